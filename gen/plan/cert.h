/* cert.h: the constants of certified classification: per plane, a rigorous bound on the float
 * rounding error of its value, as K * E R^3 + K2 * (1 + R)^3 (1 + E) (docs/errors.md). */
#ifndef CERT_H
#define CERT_H
#include "plan/slp.h"
/* R is the largest |coordinate| a value reads, E the largest |eye component| (clip: |eye[2]|).
 * For an evaluation whose monomial i (times weight w_i) passes d_i rounded operations on its
 * path, at most d on any, the error of a plane's value is at most
 *     sum_i gamma_{d_i} |w_i monomial_i| <= u / (1 - d u) * D * M,   D = sum_i d_i |w_i|,
 * with M >= every |monomial|: E R^3, or from per-coordinate maxima (the C target, the GPU kernels),
 * plus at most eta per rounded product for underflow (2^-150 in C; 2^-126 on GPUs, which may
 * flush subnormals to zero), scaled by at most three further factors. K = u D / (1 - d u) and
 * K2 come rounded up, widened for the float evaluation of the bound (ten roundings) and for their
 * own double computation. The table loop has d_i = d for all i (D = d m S, m = 6 monomials per
 * clip term, 24 in world space, S the sum of |weights|); cert_slp and cert_gpu count d_i per
 * monomial. */
typedef struct {
    float *k, *k2; /* per plane */
    float q_max;   /* certify only patches with max(E, 1) R^3 < q_max: nothing overflows */
    double *k64, *k2_64; /* cert_table: the same for the table loop in double (else NULL) */
    int nplanes;
} cert_bounds;
/* A float evaluation's rounding model: u, the largest relative error of one operation (2^-24
 * rounding to nearest; more where an operation may round twice), and eta, the largest absolute
 * error of a rounded product that underflows (2^-150 with subnormals, 2^-126 where they may be
 * flushed to zero); and its second look: the table loop in double (C) or, df set, in
 * double-float (the GPU targets). */
typedef struct {
    double u, eta;
    int df;
} cert_model;
/* IEEE float with subnormals, every operation rounded once, a second look in double (C). */
#define CERT_MODEL_IEEE ((cert_model){0x1p-24, 0x1p-150, 0})

/* B-spline input (--basis bspline): the roundings the conversion to Bezier points adds to each
 * factor of a monomial (two sums a pass, two passes), measured against the magnitude 36
 * max |vertex coordinate|, which bounds the sum over the map's weights (36 a point) of the
 * vertices' magnitudes: every monomial has three converted factors (docs/errors.md: B-spline
 * input). */
#define CERT_BSPLINE_ROUNDINGS 4
/* The bounds of the table loop (in double, the C target's recheck): float
 * weights, (terms + 16) roundings on a path as derived in README; bspline: the points are
 * converted from B-spline vertices first (CERT_BSPLINE_ROUNDINGS a factor). PTP_ENOMEM on
 * failure. */
int cert_table(cert_bounds *b, const tp_table *t, int world, int bspline, ptp_error *err);
/* The bounds of the GPU kernels' float pass for float operations of relative error at most u:
 * each monomial at its own depth, a term's own roundings and its plane's sum in any order and
 * association, for M the largest |monomial| (clip space) or the sum over the eye's components of
 * the largest |monomial| with that component (world space) (docs/errors.md). With
 * differences, the terms read b_j, b_k - b_j, b_l - b_j, the differences computed in float (two
 * more roundings a monomial), and M from the largest coordinates and the extents (README:
 * Differences of points); local: the points (world: and the eye) sheared to patch-local
 * coordinates first, as the straight-line program's frame (CERT_FRAME_ROUNDINGS more a
 * monomial). k64 and k2_64 stay NULL. */
int cert_gpu(cert_bounds *b, const tp_table *t, int world, double u, int differences, int local,
             ptp_error *err);
/* The bounds of the GPU kernels' second look: the table loop again in double-float arithmetic
 * (hi + lo floats from error-free transformations, + - * only), each double-float operation with
 * relative error at most 2^-44, eta = 2^-126 per float operation, and q_max low enough that the
 * splitter's 4097 x never overflows (docs/errors.md). k64 and k2_64 stay NULL. */
int cert_table_df(cert_bounds *b, const tp_table *t, int world, ptp_error *err);
/* The bounds of the straight-line program p (the C target's classify), at its planes' scales:
 * each monomial's roundings d_i from the program's summation trees as emitted; local: the
 * program reads patch-local coordinates, each rounded once (twice counted, for the double
 * route without multiply-add instructions), whose magnitudes M is taken from (docs/errors.md:
 * Patch-local coordinates); bspline: the points are converted from B-spline vertices (after
 * the shift), CERT_BSPLINE_ROUNDINGS a factor, M from 36 times the vertices' magnitudes; for
 * operations of model m. */
int cert_slp(cert_bounds *b, const slp_prog *p, int world, int local, int bspline,
             const cert_model *m, ptp_error *err);
void cert_clear(cert_bounds *b);
#endif
