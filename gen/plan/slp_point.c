/* slp_point.c: the point form of slp_point.h: its items from a plane's terms, their order, and
 * the form's operation counts and rounding sums, in the order the C target emits it. */
#include "plan/slp_point.h"

#include <stdlib.h>

/* Orders items by point, |coef|, sign (positive first), then minor. */
static int by_item(const void *a, const void *b)
{
    const slp_item *x = a, *y = b;
    long ax = labs(x->coef), ay = labs(y->coef);
    if (x->point != y->point)
        return (x->point > y->point) - (x->point < y->point);
    if (ax != ay)
        return (ax > ay) - (ax < ay);
    if ((x->coef < 0) != (y->coef < 0))
        return (x->coef < 0) - (y->coef < 0);
    return (x->pair > y->pair) - (x->pair < y->pair);
}

int slp_point_build(slp_item *out, size_t *n, const slp_prog *p, size_t a, size_t b)
{
    int P = p->terms[a].plane, k, pt;
    size_t i, np = p->npairs;
    long *c;
    *n = 0;
    if (p->zero[P])
        return 1;
    for (i = a; i < b; i++)
        if (p->s[p->terms[i].group].den != 1 || p->s[p->terms[i].group].num > 1000000)
            return 1;
    if (!(c = calloc((size_t)p->npoints * np, sizeof *c)))
        return PTP_ENOMEM;
    for (i = a; i < b; i++) { /* the bracket's middle product is subtracted */
        const slp_term *x = &p->terms[i];
        long w = (long)p->s[x->group].num * (x->neg ? -1 : 1);
        for (k = 0; k < 3; k++)
            c[(size_t)x->point[k] * np + (size_t)x->pair[k]] += k == 1 ? -w : w;
    }
    for (pt = 0; pt < p->npoints; pt++)
        for (i = 0; i < np; i++)
            if (c[(size_t)pt * np + i])
                out[(*n)++] = (slp_item){P, pt, (int)i, c[(size_t)pt * np + i]};
    free(c);
    qsort(out, *n, sizeof *out, by_item);
    return PTP_OK;
}

size_t slp_point_plane_end(const slp_item *it, size_t n, size_t a)
{
    size_t b = a;
    while (b < n && it[b].plane == it[a].plane)
        b++;
    return b;
}

size_t slp_point_factor_end(const slp_item *it, size_t n, size_t a)
{
    size_t b = a;
    while (b < n && it[b].plane == it[a].plane && it[b].point == it[a].point)
        b++;
    return b;
}

size_t slp_point_class_end(const slp_item *it, size_t n, size_t a)
{
    size_t b = slp_point_factor_end(it, n, a), e = a;
    while (e < b && labs(it[e].coef) == labs(it[a].coef))
        e++;
    return e;
}

int slp_point_by_adds(long c, int first)
{
    return c == 1 || (c == 2 && first);
}

/* A value's monomials: w the sum of their |weights|, d the sum of roundings times |weight|, m the
 * most roundings on a path. */
typedef struct {
    double w, d, m;
} node;

static double max_d(double x, double y)
{
    return x > y ? x : y;
}

/* x + y rounded. */
static node add(node x, node y)
{
    double w = x.w + y.w;
    return (node){w, x.d + y.d + w, max_d(x.m, y.m) + 1};
}

/* x y, rounded once (round 1) or as a multiply-add's product (2: its product and its sum). */
static node mul(node x, node y, int round)
{
    double w = x.w * y.w;
    return (node){w, x.d * y.w + x.w * y.d + round * w, x.m + y.m + round};
}

/* fma(x, y, z): the product's monomials through two roundings, z's through one. */
static node fma_node(node x, node y, node z)
{
    node p = mul(x, y, 2);
    return (node){p.w + z.w, p.d + z.d + z.w, max_d(p.m, z.m + 1)};
}

/* The class sum t of n items (a minor of either kind: 2 monomials through 2 roundings),
 * counting its adds into s. */
static node class_sum(slp_point_sum *s, size_t n)
{
    const node minor = {2, 4, 2};
    node t = minor;
    size_t i;
    for (i = 1; i < n; i++) {
        s->adds++;
        t = add(t, minor);
    }
    return t;
}

/* u (first: none) with the class sum t at |coef| c: by adds (slp_point_by_adds: t, or the exact
 * doubling t + t) or a product (a multiply-add after the first). */
static node class_scaled(slp_point_sum *s, node u, int first, node t, long c)
{
    node x = {(double)c, 0, 0};
    if (!slp_point_by_adds(c, first)) {
        *(first ? &s->muls : &s->fmas) += 1;
        return first ? mul(x, t, 1) : fma_node(x, t, u);
    }
    s->adds += (c == 2) + !first;
    t = (node){t.w * (double)c, t.d * (double)c, t.m};
    return first ? t : add(u, t);
}

void slp_point_plane(slp_point_sum *s, const slp_item *it, size_t n, int world)
{
    const node g = world ? (node){2, 4, 2} : (node){1, 1, 1};
    node v = {0, 0, 0};
    size_t f, fe, c, ce;
    int K, first_v = 1;
    *s = (slp_point_sum){0, 0, 0, 0, 0, 0};
    for (f = 0; f < n; f = fe) {
        fe = slp_point_factor_end(it, n, f);
        for (K = 0; K < (world ? 2 : 1); K++, first_v = 0) {
            node u = {0, 0, 0};
            for (c = f; c < fe; c = ce) {
                ce = slp_point_class_end(it, n, c);
                u = class_scaled(s, u, c == f, class_sum(s, ce - c), labs(it[c].coef));
            }
            *(first_v ? &s->muls : &s->fmas) += 1;
            v = first_v ? mul(g, u, 1) : fma_node(g, u, v);
        }
    }
    s->w = v.w;
    s->dsum = v.d;
    s->dmax = v.m;
}
