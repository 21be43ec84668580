/* cert.c: per-plane constants of the certified classification, computed in double from the
 * exact weights and rounded up to float; the derivation is in README (Certified classification). */
#include "plan/cert.h"
#include "plan/slp_point.h"

#include <stdlib.h>
#include <string.h>

/* The smallest float >= x (x >= 0, finite). The rounding to float goes through a volatile
 * store: gcc 12 -O2 can keep a double's unrounded value for (double)(float)x in vectorized code. */
static float float_up(double x)
{
    volatile float rounded = (float)x;
    float f = rounded;
    if ((double)f < x) {
        uint32_t bits;
        memcpy(&bits, &f, sizeof bits);
        bits++;
        memcpy(&f, &bits, sizeof f);
    }
    return f;
}

/* Fills b from per-plane depth d (the most roundings on a path), depth-weighted mass D (the sum
 * over monomials of its roundings times |weight|, m monomials a term), weight sum S and
 * rounded-product count n (arrays of L), for float operations of relative error at most u,
 * with K and K2 widened by widen >= 1 for the float evaluation of the bound. */
static void fill_widened(cert_bounds *b, const double *d, const double *D, const double *S,
                         const double *n, int world, double eta, double u, double widen)
{
    const double m = world ? 24 : 6;
    double smax = 0;
    int i;
    for (i = 0; i < b->nplanes; i++) {
        /* gamma_k <= k u / (1 - d u) for every k <= d */
        double k = u / (1 - d[i] * u) * D[i] * widen;
        b->k[i] = float_up(k);
        /* eta per product, scaled by at most 2 (1 + R)^3 (1 + E) and the weights; doubled
         * again for the rounding of a subnormal K2 * F. */
        b->k2[i] = float_up(4 * eta * n[i] * (S[i] > 1 ? S[i] : 1) * widen);
        smax = m * S[i] > smax ? m * S[i] : smax;
        if (b->k64) {
            /* The same evaluation in double (u = 2^-53), with two more roundings for the double
             * weights; 1 + 2^-40 covers the double evaluation of the bound and of k itself. */
            const double u64 = 0x1p-53, d64 = d[i] + 2;
            b->k64[i] = d64 * u64 / (1 - d64 * u64) * m * S[i] * (1 + 0x1p-40);
            b->k2_64[i] = 4 * 0x1p-1074 * n[i] * (S[i] > 1 ? S[i] : 1) * (1 + 0x1p-40);
        }
    }
    /* Every intermediate is at most max(E, 1) R^3 m S (1 + gamma), 4/3 of that in a scale's chain
     * (2^a x on the way to (2^a - 1) x): certifying only patches with max(E, 1) R^3 <
     * 2^120 / max(m S) keeps all of them below FLT_MAX. */
    b->q_max = (float)(0x1p120 / (smax + 1));
}

/* fill_widened for a bound evaluated in at most ten roundings: (1 - u)^-10 (1.0000006 for
 * u = 2^-24), and 1 + 2^-40 for this double arithmetic. */
static void fill(cert_bounds *b, const double *d, const double *D, const double *S, const double *n,
                 int world, double eta, double u)
{
    fill_widened(b, d, D, S, n, world, eta, u, (1 + 0.0000006 * (u * 0x1p24)) * (1 + 0x1p-40));
}

static int alloc(cert_bounds *b, int nplanes, int with64, double **d, double **D, double **S,
                 double **n, ptp_error *err)
{
    memset(b, 0, sizeof *b);
    b->nplanes = nplanes;
    b->k = malloc((size_t)nplanes * sizeof *b->k);
    b->k2 = malloc((size_t)nplanes * sizeof *b->k2);
    if (with64) {
        b->k64 = malloc((size_t)nplanes * sizeof *b->k64);
        b->k2_64 = malloc((size_t)nplanes * sizeof *b->k2_64);
    }
    *d = calloc((size_t)nplanes * 4, sizeof **d);
    *D = *d ? *d + nplanes : NULL;
    *S = *d ? *d + 2 * nplanes : NULL;
    *n = *d ? *d + 3 * nplanes : NULL;
    if (b->k && b->k2 && *d && (!with64 || (b->k64 && b->k2_64)))
        return PTP_OK;
    free(*d);
    cert_clear(b);
    return ptp_fail(err, PTP_ENOMEM, "out of memory computing the certified bounds");
}

/* Per plane of the table loop: d the rounded operations on a path (terms + 16), S the sum of
 * |weights| and n the rounded operations that may underflow, ops per term. */
static void table_sums(double *d, double *S, double *n, const tp_table *t, double ops)
{
    size_t i;
    for (i = 0; i < t->nterms; i++) {
        double w = rat_get_d(&t->terms[i].w);
        d[t->terms[i].plane] += 1;
        S[t->terms[i].plane] += (w < 0 ? -w : w) * (1 + 0x1p-50);
        n[t->terms[i].plane] += ops;
    }
    for (i = 0; i < (size_t)t->dom.nplanes; i++)
        d[i] += 16;
}

int cert_table(cert_bounds *b, const tp_table *t, int world, int bspline, ptp_error *err)
{
    double *d, *D, *S, *n;
    int st = alloc(b, t->dom.nplanes, 1, &d, &D, &S, &n, err), i;
    if (st)
        return st;
    table_sums(d, S, n, t, world ? 44 : 12);
    for (i = 0; i < b->nplanes; i++) { /* every monomial at depth d */
        d[i] += bspline ? 3 * CERT_BSPLINE_ROUNDINGS : 0;
        D[i] = d[i] * (world ? 24 : 6) * S[i];
    }
    fill(b, d, D, S, n, world, 0x1p-126, 0x1p-24); /* GPUs may flush subnormals to zero */
    free(d);
    return PTP_OK;
}

/* The roundings the patch-local frame adds to every monomial of the straight-line program and
 * of the table kernel: its shifted factors (clip x and y; world three of x, y, z and the eye's),
 * two each (one multiply-add, or a product exact in double, a double sum and its rounding to
 * float). */
#define CERT_FRAME_ROUNDINGS(world) ((world) ? 6 : 4)

static int cmp_desc(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x < y) - (x > y);
}

/* Into d[P] and D[P] for the n terms of one plane whose |weights| are a (sorted here, largest
 * first): each term's m monomials have own roundings own in all (at most own_max on one), plus
 * those of the plane's sum of n terms in whatever order and association: at most the depths
 * n - 1, n - 1, n - 2, ..., 1 of a chain, the deepest given to the heaviest (docs/errors.md). */
static void gpu_sums(double *d, double *D, double *a, size_t n, double own, double own_max, double m)
{
    size_t k;
    qsort(a, n, sizeof *a, cmp_desc);
    *d = own_max + (double)(n - 1);
    for (k = 0; k < n; k++)
        *D += (own + m * (double)(n - (k > 0 ? k : 1))) * a[k] * (1 + 0x1p-50);
}

int cert_gpu(cert_bounds *b, const tp_table *t, int world, double u, int differences, int local,
             ptp_error *err)
{
    /* A term's monomials (of one eye component in world space, where the kernel's M sums the
     * components' bounds) and their own roundings (docs/errors.md): clip space 6, 46 in all,
     * at most 8; world space 6, 64, at most 11; with differences 2 more on every monomial, in
     * patch-local coordinates the frame's (f, whose roundings may underflow too). */
    const double m = 6, f = local ? CERT_FRAME_ROUNDINGS(world) : 0,
                 own = (world ? 64 : 46) + (differences ? 2 * m : 0) + f * m,
                 own_max = (world ? 11 : 8) + (differences ? 2 : 0) + f;
    double *d, *D, *S, *n, *a = malloc((t->nterms + 1) * sizeof *a);
    int st = a ? alloc(b, t->dom.nplanes, 0, &d, &D, &S, &n, err)
               : ptp_fail(err, PTP_ENOMEM, "out of memory computing the certified bounds");
    size_t i, first = 0;
    if (st) {
        free(a);
        return st;
    }
    /* With differences: 8 more products that may underflow, at up to 4 times the scale (a
     * difference is at most 2 R), and their flush to zero */
    table_sums(d, S, n, t, (world ? 44 : 12) * (differences ? 8 : 1) + f * (world ? 4 : 1) * m);
    for (i = 0; i < t->nterms; i++) {
        double w = rat_get_d(&t->terms[i].w);
        a[i] = w < 0 ? -w : w;
        if (i + 1 == t->nterms || t->terms[i + 1].plane != t->terms[i].plane) {
            int p = t->terms[i].plane;
            gpu_sums(&d[p], &D[p], a + first, i + 1 - first, own, own_max, m);
            first = i + 1;
        }
    }
    /* GPUs may flush subnormals to zero. With differences, M from the extents takes more
     * roundings: 1 + 20 u >= (1 - u)^-19 covers M's float evaluation (the extents H + L
     * included, in any association) and the bound's. */
    if (differences) {
        fill_widened(b, d, D, S, n, world, 0x1p-126, u, (1 + 20 * u) * (1 + 0x1p-40));
        b->q_max /= 4; /* a difference is at most 2 R */
    } else {
        fill(b, d, D, S, n, world, 0x1p-126, u);
    }
    free(d);
    free(a);
    return PTP_OK;
}

/* Roundings on the path from a group's u at scale s to its plane's value: s u's own (none for
 * s = 1; the rounded adds of its chain, whose doublings are exact; else one product), v's update
 * (an add, or a multiply-add counted as a product and an add) unless the group is the plane's
 * first, and the adds of the later groups: group gi of groups (docs/errors.md). */
static double group_depth(const rat *s, int gi, int groups)
{
    slp_scale c;
    double own = s->den == 1 && s->num == 1 ? 0 : slp_scale_of(&c, s) ? c.nf : 1;
    return own + (gi > 0) + (groups - 1 - gi);
}

/* Fused plane P from entry a (docs/errors.md): into d[P] the most roundings on a path, into
 * D[P] the sum over its monomials of their path's roundings times |s|. Run j of a group (a point
 * b and a kind K: G_K(b) times the signed sum of b's n minors) has 2 n (world: 4 n) monomials,
 * each through a minor (2) and G (1, world 2), the n - 1 sums of the minors, the product with G
 * (a multiply-add counts as a product and a sum: two roundings where the target has no FMA),
 * the first multiply-add after it (j > 0) and the runs - 1 - j later ones of the group. */
static void fused_sums(double *d, double *D, const slp_prog *p, size_t a, int world)
{
    int plane = p->entries[a].plane, kinds = world ? 2 : 1, groups = 0, gi = 0;
    size_t g, e, b, i;
    for (g = a; g < p->nentries && p->entries[g].plane == plane; g = slp_group_end(p, g))
        groups++;
    for (g = a; g < p->nentries && p->entries[g].plane == plane; g = e, gi++) {
        const double s = rat_get_d(&p->s[p->entries[g].group]);
        double tail = group_depth(&p->s[p->entries[g].group], gi, groups);
        int runs = 0, j = 0;
        e = slp_group_end(p, g);
        for (b = g; b < e; b = slp_point_end(p, b))
            runs += kinds;
        for (b = g; b < e; b = i) {
            int k;
            i = slp_point_end(p, b);
            for (k = 0; k < kinds; k++, j++) {
                double r = (world ? 2 : 1) + 2 + (double)(i - b - 1) + 1 + (j > 0) + (runs - 1 - j);
                d[plane] = r + tail > d[plane] ? r + tail : d[plane];
                D[plane] += (r + tail) * (double)(i - b) * (world ? 4 : 2) * s * (1 + 0x1p-50);
            }
        }
    }
}

/* Exact plane P from term a (docs/errors.md): d[P] and D[P] as for fused_sums. Term q of a
 * group of L (u = t_0; u += t_1 ...) has 7 (world 8) roundings in its bracket, L - max(q, 1) in
 * the group's sum, one more, and the group's path to the plane's value. Returns the next term. */
static size_t exact_sums(double *d, double *D, const slp_prog *p, size_t a, int world)
{
    int plane = p->terms[a].plane, groups = 0, gi = 0;
    size_t g, e, i;
    for (g = a; g < p->nterms && p->terms[g].plane == plane; g = e, groups++)
        for (e = g; e < p->nterms && p->terms[e].group == p->terms[g].group; e++)
            ;
    for (g = a; g < p->nterms && p->terms[g].plane == plane; g = e, gi++) {
        const double s = rat_get_d(&p->s[p->terms[g].group]);
        for (e = g; e < p->nterms && p->terms[e].group == p->terms[g].group; e++)
            ;
        for (i = g; i < e; i++) {
            double q = (double)(i - g), r = (world ? 8 : 7) + (double)(e - g) - (q > 1 ? q : 1) + 1 +
                                            group_depth(&p->s[p->terms[g].group], gi, groups);
            d[plane] = r > d[plane] ? r : d[plane];
            D[plane] += r * (world ? 24 : 6) * s * (1 + 0x1p-50);
        }
    }
    return g;
}

/* Point-form plane P from item a (docs/errors.md): d[P] and D[P] from slp_point_plane, which
 * follows the code as emitted. */
static void point_sums(double *d, double *D, const slp_prog *p, size_t a, int world)
{
    int P = p->items[a].plane;
    slp_point_sum s;
    slp_point_plane(&s, p->items + a, slp_point_plane_end(p->items, p->nitems, a) - a, world);
    d[P] = s.dmax;
    D[P] = s.dsum * (1 + 0x1p-50);
}

int cert_table_df(cert_bounds *b, const tp_table *t, int world, ptp_error *err)
{
    /* u2: the largest relative error of the double-float + - * and of the weights' hi + lo (at
     * most 7u^2 and 2^-47), doubled; (1 - u2)^-1 and the 2^-50 of the double sums below are in
     * float_up's widening. */
    const double u2 = 0x1p-44, widen = 1.0000006 * (1 + 0x1p-40);
    double *d, *D, *S, *n, smax = 0;
    int st = alloc(b, t->dom.nplanes, 0, &d, &D, &S, &n, err), i;
    if (st)
        return st;
    table_sums(d, S, n, t, world ? 2048 : 512); /* float operations of a term, generously */
    for (i = 0; i < b->nplanes; i++) {
        /* 6 monomials a term for each eye component, whose bounds the kernel's M sums */
        double m = world ? 24 : 6;
        b->k[i] = float_up(d[i] * u2 / (1 - d[i] * u2) * 6 * S[i] * widen);
        b->k2[i] = float_up(4 * 0x1p-126 * n[i] * (S[i] > 1 ? S[i] : 1) * widen);
        smax = m * S[i] > smax ? m * S[i] : smax;
    }
    /* Every intermediate is at most 2 (m S + 24) max(E, 1) R^3, times 4097 in the splitter. */
    b->q_max = (float)(0x1p100 / (smax + 24));
    free(d);
    return PTP_OK;
}

/* Adds the input's roundings to every monomial of each plane, h of them (the frame's, local;
 * B-spline input's, three factors' CERT_BSPLINE_ROUNDINGS): h to the depth, h times the plane's
 * mass (at most m S: every form regroups the terms' m monomials) to D, and the frame's m a term
 * (n counts 32, clip 12, a term) to the roundings that may underflow, 36 times over from
 * B-spline input (a vertex's shift reaches a point with weights summing to 36; the
 * conversion's sums and exact products never underflow). */
static void frame_sums(double *d, double *D, const double *S, double *n, int nplanes, int world,
                       int local, int bspline)
{
    const double f = local ? CERT_FRAME_ROUNDINGS(world) : 0,
                 h = f + (bspline ? 3 * CERT_BSPLINE_ROUNDINGS : 0), m = world ? 24 : 6,
                 per = world ? 32 : 12;
    int i;
    for (i = 0; i < nplanes; i++) {
        d[i] += h;
        D[i] += h * m * S[i] * (1 + 0x1p-50);
        n[i] += n[i] / per * f * m * (bspline ? 36 : 1);
    }
}

int cert_slp(cert_bounds *b, const slp_prog *p, int world, int local, int bspline,
             const cert_model *m, ptp_error *err)
{
    double *d, *D, *S, *n;
    size_t i;
    int st = alloc(b, p->nplanes, 0, &d, &D, &S, &n, err);
    if (st)
        return st;
    for (i = 0; i < p->nterms; i++) {
        const slp_term *x = &p->terms[i];
        S[x->plane] += rat_get_d(&p->s[x->group]) * (1 + 0x1p-50);
        n[x->plane] += world ? 32 : 12;
    }
    for (i = 0; i < p->nterms;)
        if (p->form[p->terms[i].plane] == SLP_BRACKET)
            i = exact_sums(d, D, p, i, world);
        else
            i++;
    for (i = 0; i < p->nentries; i = slp_plane_end(p, i))
        fused_sums(d, D, p, i, world);
    for (i = 0; i < p->nitems; i = slp_point_plane_end(p->items, p->nitems, i))
        point_sums(d, D, p, i, world);
    if (local || bspline)
        frame_sums(d, D, S, n, p->nplanes, world, local, bspline);
    fill(b, d, D, S, n, world, m->eta, m->u);
    free(d);
    return PTP_OK;
}

void cert_clear(cert_bounds *b)
{
    free(b->k);
    free(b->k2);
    free(b->k64);
    free(b->k2_64);
    memset(b, 0, sizeof *b);
}
