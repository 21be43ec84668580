/* slp.c: builds the straight-line program of slp.h from the exact table: per-plane integer
 * weights grouped by value, the 2x2 minors that terms share, and the planes a collapsed edge zeros. */
#include "plan/slp.h"
#include "plan/slp_cost.h"
#include "plan/slp_point.h"
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

/* The boundary edges e of d (bit e) on which every term of a plane (terms [a, b) of p) has two
 * points: collapsing any of them zeros every bracket, and the plane needs the exact form. */
static unsigned char plane_zero(const slp_prog *p, const tp_domain *d, size_t a, size_t b)
{
    unsigned z = (1u << tp_domain_edges(d)) - 1;
    size_t x;
    for (x = a; x < b; x++)
        z &= tp_domain_term_edges(d, p->terms[x].point);
    return (unsigned char)z;
}

/* Orders fused entries by group (which orders planes), point, then pair. */
static int by_entry(const void *a, const void *b)
{
    const slp_entry *x = a, *y = b;
    if (x->group != y->group)
        return (x->group > y->group) - (x->group < y->group);
    if (x->point != y->point)
        return (x->point > y->point) - (x->point < y->point);
    return (x->pair > y->pair) - (x->pair < y->pair);
}

/* Chooses each plane's form (slp_cost_forms), then lists the fused planes' entries (p->entries
 * holds 3 nterms) and the point-form planes' items (p->items holds 3 nterms). */
static int plan_forms(slp_prog *p, const tp_domain *d)
{
    size_t a, b, i, n;
    int k, st;
    for (a = 0; a < p->nterms; a = b) {
        for (b = a; b < p->nterms && p->terms[b].plane == p->terms[a].plane; b++)
            ;
        p->zero[p->terms[a].plane] = plane_zero(p, d, a, b);
    }
    if ((st = slp_cost_forms(p)) != PTP_OK)
        return st;
    for (i = 0; i < p->nterms; i++)
        for (k = 0; k < 3 && p->form[p->terms[i].plane] == SLP_FUSED; k++) {
            const slp_term *x = &p->terms[i];
            /* the bracket's middle product is subtracted */
            p->entries[p->nentries++] = (slp_entry){x->plane, x->group, x->point[k], x->pair[k],
                                                    x->neg ^ (k == 1)};
        }
    qsort(p->entries, p->nentries, sizeof *p->entries, by_entry);
    for (a = 0; a < p->nterms; a = b) {
        for (b = a; b < p->nterms && p->terms[b].plane == p->terms[a].plane; b++)
            ;
        if (p->form[p->terms[a].plane] != SLP_POINT)
            continue;
        if ((st = slp_point_build(p->items + p->nitems, &n, p, a, b)) != PTP_OK)
            return st == PTP_ENOMEM ? st : PTP_EINTERNAL;
        p->nitems += n;
    }
    return PTP_OK;
}

/* Appends plane terms t->terms[a, b) to p: its scale c_P, its terms grouped by |weight| / c_P
 * (groups in p->s), each term's minors as pairs (pair_of: the pair of two points, or -1); sc has
 * room for b - a. PTP_OK, or PTP_EOVERFLOW with err set. */
static int add_plane(slp_prog *p, int *pair_of, scaled *sc, const tp_table *t, size_t a, size_t b,
                     ptp_error *err)
{
    size_t i;
    rat c;
    if (plane_scale(&c, t->terms, a, b))
        return ptp_fail(err, PTP_EOVERFLOW, "the scale of plane %d does not fit 128 bits", t->terms[a].plane);
    p->c[t->terms[a].plane] = c;
    for (i = a; i < b; i++) {
        sc[i - a].index = i;
        if (rat_mul(&sc[i - a].s, &t->terms[i].w, &c))
            return ptp_fail(err, PTP_EOVERFLOW, "a scaled weight of plane %d does not fit", t->terms[a].plane);
        if (rat_sgn(&sc[i - a].s) < 0)
            rat_neg(&sc[i - a].s, &sc[i - a].s);
    }
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
    return PTP_OK;
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
    p->form = calloc((size_t)t->dom.nplanes, 1);
    p->zero = calloc((size_t)t->dom.nplanes, 1);
    p->entries = malloc(3 * n * sizeof *p->entries);
    p->items = malloc(3 * n * sizeof *p->items);
    if (!pair_of || !sc || !p->pairs || !p->s || !p->c || !p->terms || !p->form || !p->zero ||
        !p->entries || !p->items) {
        st = ptp_fail(err, PTP_ENOMEM, "out of memory building the straight-line program");
        goto done;
    }
    for (i = 0; i < (size_t)t->dom.npoints * (size_t)t->dom.npoints; i++)
        pair_of[i] = -1;
    for (a = 0; a < t->nterms && st == PTP_OK; a = b) {
        for (b = a; b < t->nterms && t->terms[b].plane == t->terms[a].plane; b++)
            ;
        st = add_plane(p, pair_of, sc, t, a, b, err);
    }
    if (st)
        goto done;
    if ((st = plan_forms(p, &t->dom)) != PTP_OK)
        st = ptp_fail(err, st, st == PTP_ENOMEM ? "out of memory choosing the planes' forms"
                                                : "the point form of a plane the cost model chose failed");
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
    free(p->form);
    free(p->zero);
    free(p->entries);
    free(p->items);
    memset(p, 0, sizeof *p);
}

size_t slp_group_end(const slp_prog *p, size_t a)
{
    size_t b = a;
    while (b < p->nentries && p->entries[b].group == p->entries[a].group)
        b++;
    return b;
}

size_t slp_point_end(const slp_prog *p, size_t a)
{
    size_t b = a;
    while (b < p->nentries && p->entries[b].group == p->entries[a].group &&
           p->entries[b].point == p->entries[a].point)
        b++;
    return b;
}

size_t slp_plane_end(const slp_prog *p, size_t a)
{
    size_t b = a;
    while (b < p->nentries && p->entries[b].plane == p->entries[a].plane)
        b++;
    return b;
}

/* Sets c's chain of factors 2^a[i] + sign[i], i < nf, after shift doublings, if it computes
 * t 2^shift (t odd) in fewer adds than c has; 1 when it does. */
static int try_chain(slp_scale *c, ptp_i128 t, int shift, int nf, const int *a, const int *sign)
{
    ptp_i128 f = 1;
    int i, adds = shift;
    for (i = 0; i < nf; i++) {
        f *= ((ptp_i128)1 << a[i]) + sign[i];
        adds += a[i] + 1;
    }
    if (f != t || adds >= c->adds)
        return 0;
    *c = (slp_scale){shift, nf, adds, {a[0], nf > 1 ? a[1] : 0}, {sign[0], nf > 1 ? sign[1] : 0}};
    return 1;
}

int slp_scale_of(slp_scale *c, const rat *s)
{
    /* the factors 2^a + sign, a <= 4: 3, 5, 7, 9, 15, 17 (3 as 2 + 1), chains of up to 6 adds */
    static const int fa[] = {1, 2, 3, 3, 4, 4}, fs[] = {1, 1, -1, 1, -1, 1};
    const int nfac = (int)(sizeof fa / sizeof *fa);
    ptp_i128 t;
    int shift = 0, i, j;
    if (s->den != 1 || s->num <= 1)
        return 0;
    for (t = s->num; t % 2 == 0; t /= 2)
        shift++;
    c->adds = SLP_SCALE_ADDS + 1;
    try_chain(c, t, shift, 0, fa, fs);
    for (i = 0; i < nfac; i++) /* one factor, then two: fewer roundings first */
        try_chain(c, t, shift, 1, &fa[i], &fs[i]);
    for (i = 0; i < nfac; i++)
        for (j = i; j < nfac; j++) {
            const int a[2] = {fa[i], fa[j]}, sign[2] = {fs[i], fs[j]};
            try_chain(c, t, shift, 2, a, sign);
        }
    return c->adds <= SLP_SCALE_ADDS;
}

/* Operation counts of the program: multiplies, multiply-adds and adds (or subtracts). */
static void count_ops(long *mul, long *fma, long *add, const slp_prog *p, int world)
{
    int kinds = world ? 2 : 1;
    size_t i, a, b;
    *mul = (long)p->npairs * 2 * kinds + (world ? 4L : 1L) * p->npoints; /* minors, G */
    *fma = 0;
    *add = (long)p->npairs * kinds + (world ? 2L * p->npoints : 0);
    for (i = 0; i < p->nterms; i++) {
        const slp_term *x = &p->terms[i];
        int first = i == 0 || p->terms[i - 1].group != x->group;
        if (p->form[x->plane] != SLP_BRACKET)
            continue;
        *mul += 3 * kinds;
        *add += 3 * kinds - first; /* the brackets, the kinds' sum, the group's sum */
    }
    for (a = 0; a < p->nentries; a = b) { /* fused: one product per point and kind */
        int first = a == 0 || p->entries[a - 1].group != p->entries[a].group;
        b = slp_point_end(p, a);
        *mul += first;
        *fma += kinds - first;
        *add += (long)(b - a - 1) * kinds;
    }
    for (i = 0; i < p->nterms; i++) { /* each group's v (+)= s u: adds, a product or an FMA */
        const slp_term *x = &p->terms[i];
        const rat *s = &p->s[x->group];
        int first = i == 0 || p->terms[i - 1].plane != x->plane;
        slp_scale c;
        if ((i > 0 && p->terms[i - 1].group == x->group) || p->form[x->plane] == SLP_POINT)
            continue;
        if (slp_scale_of(&c, s))
            *add += c.adds + !first;
        else if (s->den == 1 && s->num == 1)
            *add += !first;
        else if (first)
            *mul += 1;
        else
            *fma += 1;
    }
    for (a = 0; a < p->nitems; a = b) { /* the point form */
        slp_point_sum s;
        b = slp_point_plane_end(p->items, p->nitems, a);
        slp_point_plane(&s, p->items + a, b - a, world);
        *mul += s.muls;
        *fma += s.fmas;
        *add += s.adds;
    }
}

long slp_flops(const slp_prog *p, int world)
{
    long mul, fma, add;
    count_ops(&mul, &fma, &add, p, world);
    return mul + 2 * fma + add;
}

long slp_muls(const slp_prog *p, int world)
{
    long mul, fma, add;
    count_ops(&mul, &fma, &add, p, world);
    return mul + fma;
}

long slp_adds(const slp_prog *p, int world)
{
    long mul, fma, add;
    count_ops(&mul, &fma, &add, p, world);
    return add;
}
