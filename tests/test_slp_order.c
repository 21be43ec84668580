/* test_slp_order.c: checks slp_order's plane orders (each plane with terms exactly once, number
 * order with a window of one, a reordering with the C target's settings) and slp_doublings. */
#include "check.h"
#include "core/tplane.h"
#include "plan/slp_order.h"

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

/* slp_doublings: k for the scales 2, 4 and 8 only. */
static void check_doublings(void)
{
    static const long num[7] = {1, 2, 3, 4, 8, 16, 1}, den[7] = {1, 1, 1, 1, 1, 1, 2};
    static const int want[7] = {0, 1, 0, 2, 3, 0, 0};
    int i, ok = 1;
    for (i = 0; i < 7; i++) {
        rat s;
        ok = ok && rat_set_frac(&s, num[i], den[i]) == PTP_OK && slp_doublings(&s) == want[i];
    }
    check(ok, "slp_doublings: 2, 4 and 8 are 1, 2 and 3 doublings; 1, 3, 16 and 1/2 none",
          "case %d", i);
}

int main(void)
{
    int n;
    check_doublings();
    for (n = 1; n <= 4; n++) {
        check_domain(TP_QUAD, n);
        check_domain(TP_TRI, n);
    }
    return check_exit();
}
