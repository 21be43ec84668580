/* bez.h: bivariate polynomials in Bernstein form whose coefficients are forms.
 * Builds a patch and its partial derivatives, multiplies (wedge) and degree-reduces exactly. */
#ifndef BEZ_H
#define BEZ_H

#include "core/domain.h"
#include "core/form.h"

/* sum_{I,J} B^du_I(u) B^dv_J(v) c[I*(dv+1)+J], every coefficient a form of the same rank. */
typedef struct {
    int du, dv, rank;
    form *c;
} bez;

/* Initializes p as the zero polynomial of bidegree (du, dv) and the given rank. */
int bez_init(bez *p, int du, int dv, int rank, ptp_error *err);
/* Frees p's storage. */
void bez_clear(bez *p);
/* The coefficient (I, J). */
static inline form *bez_at(const bez *p, int I, int J)
{
    return &p->c[I * (p->dv + 1) + J];
}
/* B = the symbolic patch of the quad domain d, bidegree (n, m): coefficient (i, j) is the
 * point b_k, k = tp_domain_point(d, i, j). B must be uninitialized. */
int bez_patch(bez *B, const tp_domain *d, ptp_error *err);
/* D = dP/du (bidegree (du-1, dv)) or dP/dv (bidegree (du, dv-1)); D uninitialized, du or
 * dv at least 1. */
int bez_diff_u(bez *D, const bez *P, ptp_error *err);
int bez_diff_v(bez *D, const bez *P, ptp_error *err);
/* R = A ^ B, the Bernstein product with alternating products of the coefficients:
 * B^a_i B^b_j = C(a,i) C(b,j) / C(a+b,i+j) B^{a+b}_{i+j} in each variable. R uninitialized. */
int bez_mul(bez *R, const bez *A, const bez *B, ptp_error *err);
/* R = P written with degree one lower in u (or v), R uninitialized. Fails with
 * PTP_EINTERNAL unless P's degree in that variable really is lower (zero residual). */
int bez_reduce_u(bez *R, const bez *P, ptp_error *err);
int bez_reduce_v(bez *R, const bez *P, ptp_error *err);

#endif
