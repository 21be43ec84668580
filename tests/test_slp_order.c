/* test_slp_order.c: checks slp_order's plane orders (each plane with terms exactly once, number
 * order with a window of one, a reordering with the C target's settings) and slp_scale_of. */
#include "check.h"
#include "core/tplane.h"
#include "plan/slp_order.h"

#include <math.h>
#include <stdlib.h>

/* Nonzero when order[0 .. n) holds every plane of p with terms exactly once. */
static int is_permutation(const int *order, int n, const slp_prog *p)
{
    char *seen = calloc((size_t)p->nplanes, 1), *has = calloc((size_t)p->nplanes, 1);
    int i, ok = seen && has, count = 0;
    size_t k;
    for (k = 0; ok && k < p->nterms; k++)
        has[p->terms[k].plane] = 1;
    for (i = 0; ok && i < p->nplanes; i++)
        count += has[i];
    ok = ok && n == count;
    for (i = 0; ok && i < n; i++) {
        ok = order[i] >= 0 && order[i] < p->nplanes && has[order[i]] && !seen[order[i]];
        if (ok)
            seen[order[i]] = 1;
    }
    free(seen);
    free(has);
    return ok;
}

/* The checks on one domain (kind, degree n): win 1 is number order, cap 24 win 4 a permutation
 * that differs from it for bicubic patches, and a window over every plane a permutation. */
static void check_domain(tp_kind kind, int n)
{
    tp_domain d;
    tp_table t;
    slp_prog p;
    ptp_error err;
    int *order, count = 0, moved = 0, ok, i, k;
    static const int cap[3] = {24, 24, 0}, win[3] = {1, 4, 1000000};
    if (tp_domain_init(&d, kind, n, n, &err) || tp_derive_domain(&t, &d, &err) ||
        slp_build(&p, &t, &err)) {
        check(0, "slp_order: a table and its program", "%s", err.msg);
        return;
    }
    order = malloc((size_t)p.nplanes * sizeof *order);
    for (k = 0; k < 3; k++) {
        ok = order && slp_order(order, &count, &p, cap[k], win[k], &err) == PTP_OK &&
             is_permutation(order, count, &p);
        for (i = 1, moved = 0; ok && i < count; i++)
            moved |= order[i] < order[i - 1];
        if (k == 0)
            ok = ok && !moved;
        if (k == 1 && kind == TP_QUAD && n == 3)
            ok = ok && moved;
        check(ok, k == 0   ? "slp_order: window 1 gives every plane once in number order"
                  : k == 1 ? "slp_order: cap 24, window 4 gives every plane once (bicubic: reordered)"
                           : "slp_order: a window over every plane gives every plane once",
              "%s degree %d, cap %d, window %d", kind == TP_QUAD ? "quad" : "triangle", n, cap[k],
              win[k]);
    }
    free(order);
    slp_clear(&p);
    tp_clear(&t);
}

/* s u by chain c in float, as emitted: doublings, then per factor 2^a x +- x. */
static float run_chain(const slp_scale *c, float u)
{
    float x = u;
    int i, k;
    for (k = 0; k < c->shift; k++)
        x = x + x;
    for (i = 0; i < c->nf; i++) {
        float t = x;
        for (k = 0; k < c->a[i]; k++)
            t = t + t;
        x = c->sign[i] > 0 ? t + x : t - x;
    }
    return x;
}

/* Nonzero when chain c of s computes s (2^shift times its factors) in c->adds adds, at most
 * SLP_SCALE_ADDS, and in float rounds as its nf roundings allow: exactly s u for nf = 0, the
 * correctly rounded s u for nf = 1, within 2 roundings for nf = 2, on a sweep of u (s u is exact
 * in double). */
static int chain_ok(const slp_scale *c, long s)
{
    long f = 1L << c->shift;
    int i, adds = c->shift;
    float u = -1.0f;
    for (i = 0; i < c->nf; i++) {
        f *= (1L << c->a[i]) + c->sign[i];
        adds += c->a[i] + 1;
    }
    if (f != s || adds != c->adds || adds > SLP_SCALE_ADDS || c->nf > 2)
        return 0;
    for (i = 0; i < 4096; i++, u = u * 1.0009765625f + 0x1p-13f) {
        double exact = (double)s * u, got = run_chain(c, u);
        if (c->nf <= 1 ? got != (double)(float)exact : fabs(got - exact) > 0x1p-23 * fabs(exact))
            return 0;
    }
    return 1;
}

/* slp_scale_of: the scales 2 to 10, 12 and 16 on the adders (at most SLP_SCALE_ADDS = 4 adds),
 * with the fewest adds and roundings: 3 = 2 + 1 (2 adds, 1 rounding), 9 = 8 + 1 (not 3 3), 7 =
 * 8 - 1, 12 = 4 (2 + 1); no other scale (1 needs nothing, 1/2 is no integer). */
static void check_scales(void)
{
    static const long num[] = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 27, 1};
    static const long den[] = {1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 2};
    static const int adds[] = {0, 1, 2, 2, 3, 3, 4, 3, 4, 4, 0, 4, 0, 0, 0, 4, 0, 0, 0, 0};
    static const int nf[] = {0, 0, 1, 0, 1, 1, 1, 0, 1, 1, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0};
    int i, ok = SLP_SCALE_ADDS == 4;
    for (i = 0; ok && i < (int)(sizeof num / sizeof *num); i++) {
        rat s;
        slp_scale c;
        int has = rat_set_frac(&s, num[i], den[i]) == PTP_OK && slp_scale_of(&c, &s);
        ok = has == (adds[i] > 0) && (!has || (c.adds == adds[i] && c.nf == nf[i] && chain_ok(&c, num[i])));
    }
    check(ok, "slp_scale_of: 2 to 10, 12 and 16 as doublings and one rounded add (9 = 8 + 1, 12 = 4 (2 + 1)), "
              "correctly rounded in float; 1, 11, 13 to 15, 17, 18, 27 and 1/2 not",
          "case %d", i - 1);
}

int main(void)
{
    int n;
    check_scales();
    for (n = 1; n <= 4; n++) {
        check_domain(TP_QUAD, n);
        check_domain(TP_TRI, n);
    }
    return check_exit();
}
