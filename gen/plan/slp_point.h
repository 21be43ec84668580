/* slp_point.h: the point form of a plane of slp.h's program that no collapsed edge zeros: one
 * product per point and kind, the terms' integer weights inside the sums of minors. */
#ifndef SLP_POINT_H
#define SLP_POINT_H
#include "plan/slp.h"
/* A plane at scale c_P is sum over kinds K and points b of G_K(b) L_K(b), L_K(b) the sum of
 * coef M_K over the minors b meets in the plane's terms (coef the term's signed integer weight,
 * summed where two terms give b the same minor). Items are ordered by point, then |coef| (a
 * class), positive first, then minor: the code sums a class's items in that order, scales the
 * sum by |coef| (slp_point_by_adds), adds the classes in turn into u, and multiplies G by u into
 * the plane's value: v = G u for the first point and kind, then v = fma(G, u, v). */
/* The items of plane terms [a, b) (slp_build's grouping) into out (room for 3 (b - a)), *n of
 * them; 0, or 1 when the plane is along an edge (p->zero) or a weight is not a small integer,
 * or PTP_ENOMEM. */
int slp_point_build(slp_item *out, size_t *n, const slp_prog *p, size_t a, size_t b);
/* The ends of the run at item a of it[0, n): its plane's, its point's and its class's (same
 * point and |coef|). */
size_t slp_point_plane_end(const slp_item *it, size_t n, size_t a);
size_t slp_point_factor_end(const slp_item *it, size_t n, size_t a);
size_t slp_point_class_end(const slp_item *it, size_t n, size_t a);
/* Whether the code scales a class's sum by c > 0 (the first class of its point, first) with adds:
 * for c = 1, and for c = 2 first (t + t, exact); else with a product (a multiply-add after the
 * first), which is as many instructions or fewer. */
int slp_point_by_adds(long c, int first);
/* A point-form plane's operations (products, multiply-adds, and adds or subtracts) beyond the
 * shared minors and G's, and its roundings (docs/errors.md): w the sum of |weight| of its
 * monomials (a term's 6 in clip space, 24 in world space, times |coef|), dsum the sum over them
 * of their roundings times |weight|, dmax the most on any path, where a multiply-add counts as a
 * product and a sum (targets without FMA round both). */
typedef struct {
    long muls, fmas, adds;
    double w, dsum, dmax;
} slp_point_sum;
void slp_point_plane(slp_point_sum *s, const slp_item *it, size_t n, int world);
#endif
