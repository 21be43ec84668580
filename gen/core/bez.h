/* bez.h: bivariate polynomials in Bernstein form (tensor-product or triangular) over forms.
 * Builds a patch and its partial derivatives, multiplies (wedge) and degree-reduces exactly. */
#ifndef BEZ_H
#define BEZ_H

#include "core/domain.h"
#include "core/form.h"

/* Quad: sum_{I,J} B^du_I(u) B^dv_J(v) c_IJ. Triangle (du = dv = D): sum_{I+J<=D}
 * D!/(I! J! K!) u^I v^J w^K c_IJ with K = D-I-J, w = 1-u-v. Every coefficient is a form of the
 * same rank; c_IJ is c[tp_grid_index(kind, du, dv, I, J)]. */
typedef struct {
    tp_kind kind;
    int du, dv, rank;
    form *c;
} bez;

/* Initializes p as the zero polynomial of the kind, degrees (du, dv) (a triangle's degree is
 * du; dv is set to it) and the given rank. */
int bez_init(bez *p, tp_kind kind, int du, int dv, int rank, ptp_error *err);
/* Frees p's storage. */
void bez_clear(bez *p);
/* The coefficient (I, J). */
static inline form *bez_at(const bez *p, int I, int J)
{
    return &p->c[tp_grid_index(p->kind, p->du, p->dv, I, J)];
}
/* B = the symbolic patch of the domain d: coefficient (i, j) is the point b_k,
 * k = tp_domain_point(d, i, j). B must be uninitialized. */
int bez_patch(bez *B, const tp_domain *d, ptp_error *err);
/* D = dP/du or dP/dv (quad: bidegree (du-1, dv) or (du, dv-1); triangle: degree D-1, with
 * w = 1-u-v: D_IJ = D (c_{I+1,J} - c_IJ) along u, D (c_{I,J+1} - c_IJ) along v); D
 * uninitialized, the degree at least 1. */
int bez_diff_u(bez *D, const bez *P, ptp_error *err);
int bez_diff_v(bez *D, const bez *P, ptp_error *err);
/* R = A ^ B (A and B of one kind), the Bernstein product with alternating products of the
 * coefficients: B^a_I B^b_L = [c^a_I c^b_L / c^{a+b}_{I+L}] B^{a+b}_{I+L}, c the Bernstein
 * constants (quad: C(a,i) C(a',j); triangle: a!/(i! j! k!)). R uninitialized. */
int bez_mul(bez *R, const bez *A, const bez *B, ptp_error *err);
/* R = the quad P written with degree one lower in u (or v), R uninitialized. Fails with
 * PTP_EINTERNAL unless P's degree in that variable really is lower (zero residual). */
int bez_reduce_u(bez *R, const bez *P, ptp_error *err);
int bez_reduce_v(bez *R, const bez *P, ptp_error *err);
/* R = the triangle P written with total degree one lower, R uninitialized. Fails with
 * PTP_EINTERNAL unless P's degree really is lower (zero residual). */
int bez_reduce_tri(bez *R, const bez *P, ptp_error *err);

#endif
