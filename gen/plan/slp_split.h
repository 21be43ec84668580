/* slp_split.h: cuts the C target's ordered straight-line program into pieces whose code fits the
 * instruction cache, so that the lanes run each piece over a block of patches in turn. */
#ifndef SLP_SPLIT_H
#define SLP_SPLIT_H
#include "plan/slp.h"
/* The most vector operations a piece should have (its planes, a load of each minor and G it
 * reads, the sign masks): about 16 KB of AVX-512 code, half the 32 KB instruction cache that the
 * bicubic program's 38 KB loop overflowed (bench/README: Loop fission). */
#define SLP_SPLIT_OPS 1280
/* A piece's vector operations per patch: the planes order[a, b) in world or clip space, a load
 * of each minor and G they read (world space: of each kind), and each plane's masks; -1 when out
 * of memory. */
long slp_split_ops(const slp_prog *p, const int *order, int a, int b, int world);
/* cut[0 .. *npieces] = the starts of the pieces of order[0, n) (slp_order's), cut[0] = 0 and
 * cut[*npieces] = n (cut has room for n + 1): one piece when the whole program (slp_ops, and
 * the masks) has at most SLP_SPLIT_OPS; else the fewest pieces of at most SLP_SPLIT_OPS each (a
 * plane with more alone), then the least cap on a piece that keeps them that few, each cut, of
 * those within 7/8 of the most a piece can take, where the planes before it share the fewest
 * values with those after it. PTP_ENOMEM on failure. */
int slp_split(int *cut, int *npieces, const slp_prog *p, const int *order, int n, int world,
              ptp_error *err);
#endif
