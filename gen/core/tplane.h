/* tplane.h: the exact control-plane table of the parametric tangent plane.
 * T = cross4(B, dB/du, dB/dv) of a quad or triangular patch, as weighted cross4 triples per plane. */
#ifndef TPLANE_H
#define TPLANE_H

#include "core/domain.h"
#include "core/rat.h"

/* One weighted product: plane t_plane += w * cross4(b_j, b_k, b_l), j < k < l. */
typedef struct {
    int plane, j, k, l;
    rat w;
} tp_term;

typedef struct {
    tp_domain dom;      /* the patch: degrees, counts, point and plane numbering */
    size_t nterms;
    tp_term *terms;     /* sorted by plane, then (j, k, l) */
} tp_table;

/* Derives the table of the quad domain of bidegree (n, m), 1 <= n, m <= PTP_MAX_DEGREE.
 * Fails with PTP_EUSAGE below that and PTP_ELIMIT beyond (tp_domain_init), PTP_EOVERFLOW if
 * a weight does not fit, PTP_EINTERNAL if the degree reduction check fails. t is
 * uninitialized on entry and on failure. */
int tp_derive(tp_table *t, int n, int m, ptp_error *err);
/* The same for the domain d, of either kind (triangles: degree 3d-3, the product's 3d-2
 * reduced once with the same zero-residual check). */
int tp_derive_domain(tp_table *t, const tp_domain *d, ptp_error *err);
/* Frees t's storage. */
void tp_clear(tp_table *t);
/* counts[p] = the number of terms of plane p (counts has t->dom.nplanes entries). */
void tp_plane_counts(int *counts, const tp_table *t);
/* The cross4 of Appendix A of Loop, Niessner and Eisenacher, in double. */
void tp_cross4(double r[4], const double a[4], const double b[4], const double c[4]);

#endif
