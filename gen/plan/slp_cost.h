/* slp_cost.h: the cost model that chooses the form of each plane no collapsed edge forces into
 * the exact bracket form: fused only where its multiply-adds save enough for their chains. */
#ifndef SLP_COST_H
#define SLP_COST_H
#include "plan/slp.h"
/* One plane's straight-line code in one form, clip space (world space doubles both forms):
 * muls, its operations on the multiply pipes; ops, its vector instructions (a multiply-add is
 * one); chain, the latency in cycles of its longest serial chain from the minors and G's to its
 * value (products and sums 3, multiply-adds 4, as on Zen 4 and most cores with FMA). */
typedef struct {
    long muls, ops, chain;
} slp_cost;
/* The costs of the plane whose terms are p->terms[a, b) (grouped, as slp_build leaves them) in
 * the bracket form and in the fused form. */
void slp_cost_plane(slp_cost *bracket, slp_cost *fused, const slp_prog *p, size_t a, size_t b);
/* A program of at most this many vector operations (all planes in the bracket form, with the
 * minors and G's) fits a 32 KB instruction cache (about 10 bytes an AVX-512 instruction, and the
 * spills' loads and stores); a larger one is bound by instruction fetch. */
#define SLP_COST_ICACHE_OPS 2048
/* Sets p->form from p->zero (set for every plane). Between the bracket and the fused form: a
 * zero plane keeps the bracket form; another is fused where fusing saves instructions and, when
 * the program fits the instruction cache (so that latency, not fetch, bounds it), saves at least
 * 3 instructions for every 2 cycles it adds to the plane's chain (a core issues about 2 vector
 * floating-point instructions a cycle, and the fused chains are not all exposed). In a program
 * that fits the instruction cache, the point form (plan/slp_point.h) replaces that choice on a
 * plane no collapsed edge zeros where it needs fewer multiply-pipe operations and no more
 * instructions (in the larger bicubic program it was slower: more spills). PTP_ENOMEM on
 * failure. */
int slp_cost_forms(slp_prog *p);
#endif
