/* tplane.c: derives the control planes of T = cross4(B, B_u, B_v) exactly. For quads B ^ B_u ^ B_v
 * has bidegree (3n-1, 3m-1), reduced twice to (3n-2, 3m-2); for triangles 3d-2, reduced to 3d-3. */
#include "core/tplane.h"
#include "core/bez.h"

#include <stdlib.h>

/* Rank-3 wedges b_j ^ b_k ^ b_l map to cross4(b_j, b_k, b_l): both are alternating and
 * trilinear, so the sorted-triple sign of form_key_wedge is the sign of cross4. */
static int extract(tp_table *t, const bez *T, ptp_error *err)
{
    size_t total = 0, n = 0, i;
    int P, I, J;
    for (P = 0; P < t->dom.nplanes; P++) {
        tp_domain_plane_ij(&I, &J, &t->dom, P);
        total += bez_at(T, I, J)->len;
    }
    t->terms = malloc((total ? total : 1) * sizeof *t->terms);
    if (!t->terms)
        return ptp_fail(err, PTP_ENOMEM, "out of memory (%zu terms)", total);
    for (P = 0; P < t->dom.nplanes; P++) {
        const form *f;
        tp_domain_plane_ij(&I, &J, &t->dom, P);
        f = bez_at(T, I, J);
        for (i = 0; i < f->len; i++, n++) {
            int idx[3];
            tp_term *x = &t->terms[n];
            form_key_unpack(idx, f->t[i].key, 3);
            x->plane = P;
            x->j = idx[0];
            x->k = idx[1];
            x->l = idx[2];
            form_get_weight(&x->w, f, i);
        }
    }
    t->nterms = n;
    return PTP_OK;
}

int tp_derive(tp_table *t, int n, int m, ptp_error *err)
{
    tp_domain d;
    int st;
    t->terms = NULL;
    t->nterms = 0;
    if ((st = tp_domain_init(&d, TP_QUAD, n, m, err)))
        return st;
    return tp_derive_domain(t, &d, err);
}

/* T = T3 with the degrees of the planes: quads reduce along u, then along v; triangles once. */
static int reduce_planes(bez *T, const bez *T3, ptp_error *err)
{
    bez Tu;
    int st;
    if (T3->kind == TP_TRI)
        return bez_reduce_tri(T, T3, err);
    if ((st = bez_reduce_u(&Tu, T3, err)))
        return st;
    st = bez_reduce_v(T, &Tu, err);
    bez_clear(&Tu);
    return st;
}

int tp_derive_domain(tp_table *t, const tp_domain *d, ptp_error *err)
{
    bez B, Bu, Bv, BBu, T3, T;
    int st;
    t->terms = NULL;
    t->nterms = 0;
    t->dom = *d;
    if ((st = bez_patch(&B, d, err)))
        return st;
    if (!(st = bez_diff_u(&Bu, &B, err))) {
        if (!(st = bez_diff_v(&Bv, &B, err))) {
            if (!(st = bez_mul(&BBu, &B, &Bu, err))) {
                if (!(st = bez_mul(&T3, &BBu, &Bv, err))) {
                    if (!(st = reduce_planes(&T, &T3, err))) {
                        st = extract(t, &T, err);
                        bez_clear(&T);
                    }
                    bez_clear(&T3);
                }
                bez_clear(&BBu);
            }
            bez_clear(&Bv);
        }
        bez_clear(&Bu);
    }
    bez_clear(&B);
    if (st)
        tp_clear(t);
    return st;
}

void tp_clear(tp_table *t)
{
    free(t->terms);
    t->terms = NULL;
    t->nterms = 0;
}

void tp_plane_counts(int *counts, const tp_table *t)
{
    size_t i;
    int p;
    for (p = 0; p < t->dom.nplanes; p++)
        counts[p] = 0;
    for (i = 0; i < t->nterms; i++)
        counts[t->terms[i].plane]++;
}

void tp_cross4(double r[4], const double a[4], const double b[4], const double c[4])
{
    /* det3 of rows p, q, s of the column vectors a, b, c. */
#define DET3(p, q, s)                                                                  \
    (a[p] * (b[q] * c[s] - b[s] * c[q]) - b[p] * (a[q] * c[s] - a[s] * c[q]) +          \
     c[p] * (a[q] * b[s] - a[s] * b[q]))
    r[0] = DET3(1, 2, 3);
    r[1] = -DET3(0, 2, 3);
    r[2] = DET3(0, 1, 3);
    r[3] = -DET3(0, 1, 2);
#undef DET3
}
