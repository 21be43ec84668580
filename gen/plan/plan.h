/* plan.h: the finished plan a straight-line writer takes: the program of a table and, certified,
 * its margins; built once before any emitter runs, so that the writers only write. */
#ifndef PLAN_H
#define PLAN_H

#include "plan/cert.h"
#include "plan/slp.h"

typedef struct {
    slp_prog prog;    /* the straight-line program (plan/slp.h) */
    cert_bounds cert; /* with certified: its margins (cert_slp); else empty */
    long flops, muls; /* per patch (slp_flops, slp_muls, and the frame's) in the plan's space */
    int local;        /* the program reads patch-local coordinates (docs/math.md: Patch-local
                         coordinates): point 0's origin subtracted, one rounding a coordinate */
} plan_slp;

/* The frame's operations per patch of k points: one reciprocal, the origin's 2 (world 3)
 * products, and one multiply-add per shifted coordinate (the eye's 3 in world space). */
long plan_frame_flops(int k, int world);
long plan_frame_muls(int k, int world);

/* Builds the plan of t for world (else clip) space, in patch-local coordinates when local, with
 * the margins when certified. p is uninitialized on entry and on failure (PTP_ENOMEM,
 * PTP_EOVERFLOW: slp_build's). */
int plan_slp_build(plan_slp *p, const tp_table *t, int world, int local, int certified,
                   ptp_error *err);
/* Frees p's storage. */
void plan_slp_clear(plan_slp *p);

#endif
