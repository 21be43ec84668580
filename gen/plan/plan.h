/* plan.h: the finished plan a straight-line writer takes: the program of a table and, certified,
 * its margins; built once before any emitter runs, so that the writers only write. */
#ifndef PLAN_H
#define PLAN_H

#include "plan/cert.h"
#include "plan/slp.h"

typedef struct {
    slp_prog prog;    /* the straight-line program (plan/slp.h) */
    cert_bounds cert; /* with certified: its margins (cert_slp); else empty */
    cert_bounds look; /* with certified: the second look's, the table loop in double
                         (cert_table) or, the model's df, in double-float (cert_table_df) */
    long flops, muls; /* per patch (slp_flops, slp_muls, and the frame's) in the plan's space */
    int local;        /* the program reads patch-local coordinates (docs/math.md: Patch-local
                         coordinates): point 0's origin subtracted, one rounding a coordinate */
    int bspline;      /* the input is a uniform bicubic B-spline patch's 16 control vertices,
                         converted to the Bezier points (times 36) before the program */
    int vmajor;       /* the input's rows run along v: point (i, j) at j (n + 1) + i */
    int n, m;         /* the bidegree (quads), for the input's numbering */
} plan_slp;

/* What the program reads (plan_slp_build's form): bits of these. */
enum { PLAN_LOCAL = 1, PLAN_BSPLINE = 2, PLAN_VMAJOR = 4 };

/* The frame's operations per patch of k points: one reciprocal, the origin's 2 (world 3)
 * products, and one multiply-add per shifted coordinate (the eye's 3 in world space). */
long plan_frame_flops(int k, int world);
long plan_frame_muls(int k, int world);
/* The B-spline conversion's operations per patch (bicubic): per coordinate read (clip 3, world
 * 4), two passes of 24 exact products by 2 or 4 and 24 sums. */
long plan_bspline_flops(int world);
long plan_bspline_muls(int world);

/* Builds the plan of t for world (else clip) space, reading the input form (PLAN_ bits), with
 * the margins of the program (for the rounding model certified) and of the second look when
 * certified is not NULL. p is uninitialized on entry
 * and on failure (PTP_ENOMEM, PTP_EOVERFLOW: slp_build's). */
int plan_slp_build(plan_slp *p, const tp_table *t, int world, int form,
                   const cert_model *certified, ptp_error *err);
/* Frees p's storage. */
void plan_slp_clear(plan_slp *p);
/* The input's index of point (i, j) of a quad plan's (n + 1) x (m + 1) grid, i along u:
 * i (m + 1) + j, or from v-major input j (n + 1) + i. */
int plan_input_index(const plan_slp *p, int i, int j);

#endif
