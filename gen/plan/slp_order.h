/* slp_order.h: the order in which the C target emits the straight-line program's planes, chosen
 * so that consecutive planes reuse the minors and points still in registers. */
#ifndef SLP_ORDER_H
#define SLP_ORDER_H
#include "plan/slp.h"
/* order[0 .. *n) = every plane with terms once (order holds p->nplanes), greedily: next, of the
 * win lowest-numbered planes left, the one that reads the fewest values (minors, points) outside
 * the cap values most recently read, the lower number on ties (win 1: number order). Only the
 * order changes: no plane's value does. PTP_ENOMEM on failure. */
int slp_order(int *order, int *n, const slp_prog *p, int cap, int win, ptp_error *err);
#endif
