/* slp.c: builds the straight-line program of slp.h from the exact table: per-plane integer
 * weights grouped by value, and the 2x2 minors that terms share. */
#include "plan/slp.h"
#include "core/i128.h"

#include <stdlib.h>
#include <string.h>

/* Index of the minor (k, l) in p->pairs, appended on first use; pair_of is an npoints^2 map. */
static int pair_index(slp_prog *p, int *pair_of, int k, int l)
{
    int *x = &pair_of[k * p->npoints + l];
    if (*x < 0) {
        p->pairs[p->npairs] = (slp_pair){k, l};
        *x = (int)p->npairs++;
    }
    return *x;
}

/* c = the positive scale that makes the weights of terms [a, b) coprime integers:
 * lcm of the denominators over gcd of the numerators. */
static int plane_scale(rat *c, const tp_term *terms, size_t a, size_t b)
{
    ptp_i128 D = 1, G = 0;
    size_t i;
    for (i = a; i < b; i++)
        if (rat_lcm_den(&D, &terms[i].w))
            return PTP_EOVERFLOW;
    for (i = a; i < b; i++) {
        ptp_i128 w;
        if (i128_mul_ovf(&w, terms[i].w.num, D / terms[i].w.den))
            return PTP_EOVERFLOW;
        G = (ptp_i128)u128_gcd((ptp_u128)G, i128_abs(w));
    }
    return rat_set_frac(c, D, G ? G : 1);
}

/* One term before grouping: its scaled weight and its place in the table. */
typedef struct {
    rat s;
    size_t index;
} scaled;

/* Orders the terms of a plane by |s| (then table order), so that equal scales are adjacent. */
static int by_scale(const void *a, const void *b)
{
    const scaled *x = a, *y = b;
    rat d;
    if (rat_sub(&d, &x->s, &y->s) == PTP_OK && rat_sgn(&d))
        return rat_sgn(&d);
    return (x->index > y->index) - (x->index < y->index);
}

int slp_build(slp_prog *p, const tp_table *t, ptp_error *err)
{
    size_t a, b, i, n = t->nterms + 1;
    int *pair_of = malloc((size_t)t->dom.npoints * (size_t)t->dom.npoints * sizeof *pair_of);
    scaled *sc = malloc(n * sizeof *sc);
    int st = PTP_OK;
    memset(p, 0, sizeof *p);
    p->npoints = t->dom.npoints;
    p->nplanes = t->dom.nplanes;
    p->pairs = malloc(3 * n * sizeof *p->pairs);
    p->s = malloc(n * sizeof *p->s);
    p->c = calloc((size_t)t->dom.nplanes, sizeof *p->c);
    p->terms = malloc(n * sizeof *p->terms);
    if (!pair_of || !sc || !p->pairs || !p->s || !p->c || !p->terms) {
        st = ptp_fail(err, PTP_ENOMEM, "out of memory building the straight-line program");
        goto done;
    }
    for (i = 0; i < (size_t)t->dom.npoints * (size_t)t->dom.npoints; i++)
        pair_of[i] = -1;
    for (a = 0; a < t->nterms; a = b) {
        rat c;
        for (b = a; b < t->nterms && t->terms[b].plane == t->terms[a].plane; b++)
            ;
        if (plane_scale(&c, t->terms, a, b)) {
            st = ptp_fail(err, PTP_EOVERFLOW, "the scale of plane %d does not fit 128 bits",
                          t->terms[a].plane);
            goto done;
        }
        p->c[t->terms[a].plane] = c;
        for (i = a; i < b; i++) {
            sc[i - a].index = i;
            if (rat_mul(&sc[i - a].s, &t->terms[i].w, &c)) {
                st = ptp_fail(err, PTP_EOVERFLOW, "a scaled weight of plane %d does not fit",
                              t->terms[a].plane);
                goto done;
            }
        }
        for (i = 0; i < b - a; i++)
            if (rat_sgn(&sc[i].s) < 0)
                rat_neg(&sc[i].s, &sc[i].s);
        qsort(sc, b - a, sizeof *sc, by_scale);
        for (i = 0; i < b - a; i++) {
            const tp_term *x = &t->terms[sc[i].index];
            slp_term *y = &p->terms[p->nterms++];
            if (i == 0 || !rat_equal(&sc[i].s, &sc[i - 1].s))
                p->s[p->ngroups++] = sc[i].s;
            y->plane = x->plane;
            y->neg = rat_sgn(&x->w) < 0;
            y->group = (int)p->ngroups - 1;
            y->point[0] = x->j;
            y->point[1] = x->k;
            y->point[2] = x->l;
            y->pair[0] = pair_index(p, pair_of, x->k, x->l);
            y->pair[1] = pair_index(p, pair_of, x->j, x->l);
            y->pair[2] = pair_index(p, pair_of, x->j, x->k);
        }
    }
done:
    free(pair_of);
    free(sc);
    if (st)
        slp_clear(p);
    return st;
}

void slp_clear(slp_prog *p)
{
    free(p->pairs);
    free(p->s);
    free(p->c);
    free(p->terms);
    memset(p, 0, sizeof *p);
}

long slp_flops(const slp_prog *p, int world)
{
    int kinds = world ? 2 : 1;
    long f = world ? 6L * p->npoints : 0; /* G_0 and G_1 of every point */
    size_t i;
    rat one;
    rat_set_si(&one, 1);
    for (i = 0; i < p->ngroups; i++)
        f += !rat_equal(&p->s[i], &one);             /* s * the group's sum */
    f += (long)p->npairs * 3 * kinds;                /* the minors */
    f += (long)p->nterms * (6 * kinds - 1);          /* the brackets */
    f += (long)p->nterms - p->nplanes;               /* the sums */
    if (!world)
        f += p->npoints;                             /* G = e2 w */
    return f;
}
