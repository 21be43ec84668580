/* plan.h: the finished plan a straight-line writer takes: the program of a table and, certified,
 * its margins; built once before any emitter runs, so that the writers only write. */
#ifndef PLAN_H
#define PLAN_H

#include "plan/cert.h"
#include "plan/slp.h"

typedef struct {
    slp_prog prog;    /* the straight-line program (plan/slp.h) */
    cert_bounds cert; /* with certified: its margins (cert_slp); else empty */
    long flops, muls; /* per patch (slp_flops, slp_muls) in the plan's space */
} plan_slp;

/* Builds the plan of t for world (else clip) space, with the margins when certified. p is
 * uninitialized on entry and on failure (PTP_ENOMEM, PTP_EOVERFLOW: slp_build's). */
int plan_slp_build(plan_slp *p, const tp_table *t, int world, int certified, ptp_error *err);
/* Frees p's storage. */
void plan_slp_clear(plan_slp *p);

#endif
