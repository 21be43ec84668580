/* slp.h: the straight-line program behind the C target's classify: every plane's value up to a
 * positive factor, from shared 2x2 minors; exact brackets where a collapsed boundary needs zeros. */
#ifndef SLP_H
#define SLP_H
#include "core/tplane.h"
/* A plane's value at scale c_P > 0 (c_P makes its weights coprime integers s) is
 *     sum over the distinct s of the plane of  s * (sum over its terms of weight +-s of
 *         +-sum over kinds K of ((G_K(b_j) M_K(b_k, b_l) - G_K(b_k) M_K(b_j, b_l)) + G_K(b_l) M_K(b_j, b_k)))
 * where each bracket is the generalized Laplace expansion of -det[b_j b_k b_l e] along rows
 * {0, 1}, so every monomial of the determinant appears once. World space has two kinds:
 *     G_0(x) = e0 x1 - e1 x0 with M_0 the (z, w) minor, G_1(x) = e2 x3 - e3 x2 with the (x, y) minor;
 * clip space (e = (0, 0, e2, 0)) only kind 1 with G_1(x) = e2 x3. Two equal points in a term
 * make its bracket exactly zero in float arithmetic without contracted multiply-adds, so a plane
 * whose terms all vanish is exactly zero. That form is kept on the exact planes: those whose every
 * term has two points on one boundary edge, which a collapsed edge (all its points equal) zeros,
 * and those where the cost model (plan/slp_cost.h) finds that fusing does not pay. The other
 * planes are fused: per group, sum over its points b of G_K(b) times the signed sum of the
 * minors b meets in its terms, with multiply-adds:
 *     s * sum over b of sum over kinds K of G_K(b) * (sum of +-M_K over b's terms in the group).
 * The point form (plan/slp_point.h) takes the weights into the sums instead, one product per
 * point and kind, on planes no collapsed edge zeros. */
enum slp_form {
    SLP_BRACKET, /* the exact bracket form */
    SLP_FUSED,   /* grouped by weight, then by point */
    SLP_POINT    /* grouped by point, the weights inside (slp_point.h) */
};
typedef struct {
    int k, l; /* the minor M(b_k, b_l), k < l */
} slp_pair;
typedef struct {
    int plane, neg;  /* the bracket is subtracted when neg */
    int group;       /* terms of one plane with one s form a group, consecutive */
    int point[3];    /* j < k < l */
    int pair[3];     /* the minors (k, l), (j, l), (j, k) */
} slp_term;
/* One entry of a fused plane: point b meets minor pair in a term of the group, signed. */
typedef struct {
    int plane, group, point, pair, neg;
} slp_entry;
/* One item of a point-form plane: coef times minor pair times G(point). */
typedef struct {
    int plane, point, pair;
    long coef;
} slp_item;
typedef struct {
    int npoints, nplanes;
    size_t npairs, ngroups, nterms;
    slp_pair *pairs; /* in order of first use */
    rat *s;          /* the scale s > 0 of every group; s == 1 needs no product */
    rat *c;          /* the scale c_P > 0 of every plane: its value is c_P times the true one */
    slp_term *terms; /* by plane, then group */
    unsigned char *form;  /* per plane: its enum slp_form */
    unsigned char *zero;  /* per plane: bit e set when every term has two points on boundary
                             edge e (tp_domain_on_edge), so that collapsing e zeros the plane
                             exactly; a plane with zero nonzero is exact */
    size_t nentries;
    slp_entry *entries;   /* of the fused planes, by plane, group, point, then pair */
    size_t nitems;
    slp_item *items;      /* of the point-form planes, by plane (order: slp_point.h) */
} slp_prog;
/* Builds the program of t. p is uninitialized on entry and on failure (PTP_ENOMEM,
 * PTP_EOVERFLOW when a plane's scale does not fit). */
int slp_build(slp_prog *p, const tp_table *t, ptp_error *err);
/* Frees p's storage. */
void slp_clear(slp_prog *p);
/* A group scale s on the adders: s u = 2^shift u (exact doublings), then nf factors
 * f_i = 2^a_i + sign_i (sign_i = +-1), each x <- 2^a_i x + sign_i x: a_i exact doublings and one
 * rounded add (3 u = (u + u) + u). adds = shift + sum (a_i + 1) operations, all on the add pipes,
 * and nf roundings on every path through it. */
typedef struct {
    int shift, nf, adds;
    int a[2], sign[2];
} slp_scale;
/* The most adds that replace one product by s (slp_scale_of): the scales 2 to 10, 12 and 16.
 * Longer chains load the add pipes (which the batch path's transposes also use) past the multiply
 * pipes and lengthen the planes' chains; 4 was the fastest of 3 to 8 for bicubic classify_batch
 * on Zen 4 (bench/README: Scales on the adders). */
#define SLP_SCALE_ADDS 4
/* 1 and the cheapest chain into c (fewest adds, then fewest roundings) when s > 1 is an integer
 * with a chain of at most SLP_SCALE_ADDS adds and 2 factors; else 0 (s = 1 needs no operation,
 * another s one product, or one multiply-add into the plane's value). */
int slp_scale_of(slp_scale *c, const rat *s);
/* Floating-point operations per patch (multiplies, adds, subtracts; a multiply-add counts 2),
 * clip or world space. */
long slp_flops(const slp_prog *p, int world);
/* Operations per patch on the multiply pipes (multiplies and multiply-adds). */
long slp_muls(const slp_prog *p, int world);
/* Operations per patch on the add pipes (adds and subtracts that are no part of a multiply-add). */
long slp_adds(const slp_prog *p, int world);
/* The fused planes' runs: the end b of the run at entry a, whose entries [a, b) share entry a's
 * group (and its point; its plane). */
size_t slp_group_end(const slp_prog *p, size_t a);
size_t slp_point_end(const slp_prog *p, size_t a);
size_t slp_plane_end(const slp_prog *p, size_t a);
#endif
