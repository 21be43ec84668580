/* slp_order.h: the order in which the C target emits the straight-line program's planes, chosen
 * so that consecutive planes reuse the minors and points still in registers. */
#ifndef SLP_ORDER_H
#define SLP_ORDER_H
#include "plan/slp.h"
/* The values each plane reads, in the order its code reads them: minor pairs are 0 .. npairs,
 * point b is npairs + b; plane P's are val[start[P] .. start[P + 1]), each once (an exact plane
 * reads its terms' minors and points, a fused or point-form plane each point's minors, then the
 * point). */
typedef struct {
    size_t *start;
    int *val;
} slp_values;
/* Fills v from p (slp_values_clear frees it). PTP_ENOMEM on failure (v then holds nothing). */
int slp_values_build(slp_values *v, const slp_prog *p, ptp_error *err);
void slp_values_clear(slp_values *v);
/* order[0 .. *n) = every plane with terms once (order holds p->nplanes), greedily: next, of the
 * win lowest-numbered planes left, the one that reads the fewest values (minors, points) outside
 * the cap values most recently read, the lower number on ties (win 1: number order). Only the
 * order changes: no plane's value does. PTP_ENOMEM on failure. */
int slp_order(int *order, int *n, const slp_prog *p, int cap, int win, ptp_error *err);
#endif
