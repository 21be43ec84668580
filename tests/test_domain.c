/* test_domain.c: the patch-domain descriptor: counts, index maps, parsing and names.
 * Every quad bidegree against the documented formulas, and the counts against tp_derive. */
#include "check.h"
#include "core/domain.h"
#include "core/tplane.h"
#include "kref.h"

#include <stdlib.h>
#include <string.h>

/* The map onto [0, count) at (i, j) of the grid (a, b) is k = i*(b+1) + j, both directions agree,
 * and every number is hit once; plane selects the plane map. Writes the first failure to why. */
static int grid_ok(char *why, size_t size, const tp_domain *d, int plane)
{
    int a = plane ? d->pu : d->n, b = plane ? d->pv : d->m, count = plane ? d->nplanes : d->npoints;
    int i, j, k, x, y, ok = count == (a + 1) * (b + 1);
    char *seen = calloc((size_t)count + 1, 1);
    if (!ok)
        snprintf(why, size, "count %d, want %d", count, (a + 1) * (b + 1));
    for (i = 0; ok && i <= a; i++)
        for (j = 0; ok && j <= b; j++) {
            k = plane ? tp_domain_plane(d, i, j) : tp_domain_point(d, i, j);
            ok = k == i * (b + 1) + j && !seen[k]++;
            if (!ok)
                snprintf(why, size, "(%d, %d) -> %d", i, j, k);
        }
    for (k = 0; ok && k < count; k++) {
        if (plane)
            tp_domain_plane_ij(&x, &y, d, k);
        else
            tp_domain_point_ij(&x, &y, d, k);
        ok = seen[k] && x >= 0 && x <= a && y >= 0 && y <= b && x * (b + 1) + y == k &&
             (!plane || tp_domain_plane_row_start(d, k) == (y == 0));
        if (!ok)
            snprintf(why, size, "%d -> (%d, %d)", k, x, y);
    }
    free(seen);
    return ok;
}

/* The first failure of domain d against the formulas, written to why; 0 when there is none. */
static int domain_bad(char *why, size_t size, const tp_domain *d, int n, int m)
{
    tp_domain t;
    if (!(d->kind == TP_QUAD && d->n == n && d->m == m && d->pu == 3 * n - 2 && d->pv == 3 * m - 2 &&
          d->npoints == (n + 1) * (m + 1) && d->nplanes == (3 * n - 1) * (3 * m - 1))) {
        snprintf(why, size, "degrees %d %d %d %d, counts %d %d", d->n, d->m, d->pu, d->pv,
                 d->npoints, d->nplanes);
        return 1;
    }
    if (!grid_ok(why, size, d, 0) || !grid_ok(why, size, d, 1))
        return 1;
    tp_domain_transpose(&t, d);
    if (!(t.n == m && t.m == n && t.pu == d->pv && t.pv == d->pu && t.npoints == d->npoints &&
          t.nplanes == d->nplanes && tp_domain_point(&t, m, 0) == m * (n + 1) &&
          tp_domain_plane(&t, 1, 0) == d->pu + 1)) {
        snprintf(why, size, "transposed: %dx%d", t.n, t.m);
        return 1;
    }
    return 0;
}

/* Every bidegree: the counts and degrees, both maps, the transposed domain. */
static void test_maps(void)
{
    char why[200] = "", w[160];
    int n, m, bad = 0;
    for (n = 1; n <= PTP_MAX_DEGREE; n++)
        for (m = 1; m <= PTP_MAX_DEGREE; m++) {
            tp_domain d;
            ptp_error err;
            int st = tp_domain_init(&d, TP_QUAD, n, m, &err);
            if (st)
                snprintf(w, sizeof w, "init: %.100s", err.msg);
            if ((st || domain_bad(w, sizeof w, &d, n, m)) && !bad++)
                snprintf(why, sizeof why, "%dx%d: %s", n, m, w);
        }
    check(!bad, "every bidegree: counts, plane degrees, point and plane maps inverse bijections "
                "equal to i*(m+1)+j and I*(pv+1)+J, rows at J = 0, transposition",
          "%d bad, first %s", bad, why);
}

/* The names of a few domains, as banners and tables print them. */
static void test_names(void)
{
    tp_domain d;
    tp_domain_text x;
    char buf[32];
    tp_domain_init(&d, TP_QUAD, 3, 3, NULL);
    tp_domain_text_get(&x, &d);
    check(!strcmp(x.word, "bidegree") && !strcmp(x.degree, "3x3") && !strcmp(x.name, "bidegree 3x3") &&
              !strcmp(x.plane_degree, "7x7") && !strcmp(x.plane_name, "bidegree 7x7") &&
              !strcmp(x.degrees, "3, 3") && !strcmp(x.plane_degrees, "7, 7") &&
              !strcmp(x.point_rule, "k = i*4 + j") && !strcmp(x.plane_rule, "P = I*8 + J") &&
              !strcmp(x.point_axes, "i along u") && !strcmp(x.plane_axes, "I along u") &&
              strstr(x.conventions, "i*(m+1)+j") && strstr(x.plane_rows, "row I along u"),
          "names of bidegree 3x3", "%s / %s / %s / %s / %s", x.name, x.plane_name, x.point_rule,
          x.plane_rule, x.degrees);
    tp_domain_init(&d, TP_QUAD, 2, 16, NULL);
    tp_domain_text_get(&x, &d);
    check(!strcmp(tp_domain_prefix(buf, sizeof buf, &d), "ptp_2x16_") &&
              !strcmp(x.plane_name, "bidegree 4x46") && !strcmp(x.point_rule, "k = i*17 + j") &&
              !strcmp(x.plane_rule, "P = I*47 + J") && !strcmp(x.plane_degrees, "4, 46"),
          "names and prefix of bidegree 2x16", "%s / %s / %s / %s", buf, x.plane_name,
          x.point_rule, x.plane_rule);
}

/* Format and parse are inverse for every bidegree; "N" is NxN and 'X' reads as 'x'. */
static void test_round_trip(void)
{
    char s[16], t[16], f[16], why[120] = "";
    int n, m, bad = 0;
    for (n = 1; n <= PTP_MAX_DEGREE; n++)
        for (m = 1; m <= PTP_MAX_DEGREE; m++) {
            tp_domain d, e, g, h;
            ptp_error err;
            snprintf(s, sizeof s, "%d", n);
            snprintf(t, sizeof t, "%dX%d", n, m);
            tp_domain_init(&d, TP_QUAD, n, m, NULL);
            tp_domain_format(f, sizeof f, &d);
            if (tp_domain_parse(&e, TP_QUAD, f, &err) || tp_domain_parse(&g, TP_QUAD, t, &err) ||
                tp_domain_parse(&h, TP_QUAD, s, &err) || memcmp(&e, &d, sizeof d) ||
                memcmp(&g, &d, sizeof d) || h.n != n || h.m != n || h.nplanes != (3 * n - 1) * (3 * n - 1))
                if (!bad++)
                    snprintf(why, sizeof why, "%s / %s / %s", f, t, s);
        }
    check(!bad, "format and parse round-trip for every bidegree, N alone is NxN, NXM is NxM",
          "%d bad, first %s", bad, why);
}

/* Bad --degree arguments: PTP_EUSAGE, the argument quoted and the reason. */
static void test_rejects(void)
{
    static const struct {
        const char *arg, *why;
    } bad[] = {{"0", "at least 1"},  {"0x3", "at least 1"}, {"3x0", "at least 1"},
               {"17", "largest supported degree is 16"}, {"3x17", "largest supported degree is 16"},
               {"99999999999999999999", "largest supported degree is 16"},
               {"3x", "expected N or NxM"}, {"x3", "expected N or NxM"},
               {"3x3x3", "expected N or NxM"}, {"-1", "expected N or NxM"},
               {"", "expected N or NxM"}, {"3y3", "expected N or NxM"},
               {" 3", "expected N or NxM"}, {"3 ", "expected N or NxM"},
               {"3x3 ", "expected N or NxM"}, {"a3", "expected N or NxM"},
               {"3x3a", "expected N or NxM"}, {"+3", "expected N or NxM"},
               {"3.0", "expected N or NxM"}, {"3 x3", "expected N or NxM"}};
    char name[80], quoted[48];
    size_t i;
    for (i = 0; i < sizeof bad / sizeof *bad; i++) {
        tp_domain d;
        ptp_error err = {0, ""};
        int st = tp_domain_parse(&d, TP_QUAD, bad[i].arg, &err);
        snprintf(name, sizeof name, "--degree '%s' is refused: %s", bad[i].arg, bad[i].why);
        snprintf(quoted, sizeof quoted, "--degree '%s': ", bad[i].arg);
        check(st == PTP_EUSAGE && err.status == PTP_EUSAGE && !strncmp(err.msg, quoted, strlen(quoted)) &&
                  strstr(err.msg, bad[i].why),
              name, "status %d: %s", st, err.msg);
    }
}

/* A reference acceptor: digits, then optionally 'x' or 'X' and digits; each 1..16. */
static int accepts(int *n, int *m, const char *s)
{
    const char *p = s;
    long v[2] = {0, 0};
    int k;
    for (k = 0; k < 2; k++) {
        const char *q = p;
        for (; *p >= '0' && *p <= '9'; p++)
            v[k] = v[k] > 100 ? 101 : v[k] * 10 + (*p - '0');
        if (p == q || v[k] < 1 || v[k] > PTP_MAX_DEGREE)
            return 0;
        if (k == 0 && *p != 'x' && *p != 'X') {
            v[1] = v[0];
            break;
        }
        p += k == 0;
    }
    *n = (int)v[0];
    *m = (int)v[1];
    return *p == '\0';
}

/* Random short strings: parse accepts exactly what the reference does, with its degrees. */
static void test_random_parse(void)
{
    static const char alphabet[] = "0123456789xX y-+01236";
    uint64_t s = 20240601;
    prop p;
    int c;
    prop_init(&p, "parse agrees with a reference acceptor on 20000 random strings");
    for (c = 0; c < 20000; c++) {
        char arg[8];
        int len = (int)(ptp_splitmix64(&s) % 7), i, n = 0, m = 0, want, st;
        tp_domain d;
        ptp_error err;
        for (i = 0; i < len; i++)
            arg[i] = alphabet[ptp_splitmix64(&s) % (sizeof alphabet - 1)];
        arg[len] = '\0';
        want = accepts(&n, &m, arg);
        st = tp_domain_parse(&d, TP_QUAD, arg, &err);
        p.tried++;
        if (want ? st || d.n != n || d.m != m : st != PTP_EUSAGE)
            prop_fail(&p, "'%s': status %d, reference %s %dx%d", arg, st,
                      want ? "accepts" : "refuses", n, m);
    }
    prop_report(&p);
}

/* Init's limits, with tp_derive's messages and statuses. */
static void test_init_limits(void)
{
    tp_domain d;
    ptp_error err;
    int st = tp_domain_init(&d, TP_QUAD, 0, 2, &err);
    check(st == PTP_EUSAGE && !strcmp(err.msg, "bidegree 0x2: degrees must be at least 1"),
          "init refuses degree 0 (PTP_EUSAGE)", "status %d: %s", st, err.msg);
    st = tp_domain_init(&d, TP_QUAD, 3, PTP_MAX_DEGREE + 1, &err);
    check(st == PTP_ELIMIT && !strcmp(err.msg, "bidegree 3x17 is beyond the supported limit 16x16 "
                                               "(exact weights in 128-bit rationals)"),
          "init refuses degree 17 (PTP_ELIMIT), naming the limit", "status %d: %s", st, err.msg);
}

/* tp_derive's tables carry the domain, and their indices fill exactly [0, npoints) and
 * [0, nplanes): the largest index used is the last, which verify's inference relies on. */
static void test_derive_counts(void)
{
    char why[160] = "";
    int n, m, bad = 0;
    for (n = 1; n <= 5; n++)
        for (m = 1; m <= 5; m++) {
            tp_table t;
            tp_domain d;
            ptp_error err;
            int maxp, maxk;
            tp_domain_init(&d, TP_QUAD, n, m, NULL);
            if (tp_derive(&t, n, m, &err)) {
                if (!bad++)
                    snprintf(why, sizeof why, "%dx%d: %.100s", n, m, err.msg);
                continue;
            }
            kref_table_max(&maxp, &maxk, &t);
            if ((memcmp(&t.dom, &d, sizeof d) || maxp != d.nplanes - 1 || maxk != d.npoints - 1) &&
                !bad++)
                snprintf(why, sizeof why, "%dx%d: largest plane %d of %d, point %d of %d", n, m,
                         maxp, t.dom.nplanes, maxk, t.dom.npoints);
            tp_clear(&t);
        }
    check(!bad, "tp_derive's tables (1 <= n, m <= 5) carry the domain and use every count",
          "%s", why);
}

/* The triangle grid of degree a against the documented order, written out: (i, j) in
 * descending lexicographic order; both maps agree, rows start where i changes. */
static int tri_grid_ok(char *why, size_t size, const tp_domain *d, int plane)
{
    int a = plane ? d->pu : d->n, count = plane ? d->nplanes : d->npoints, i, j, x, y, k = 0;
    if (count != (a + 1) * (a + 2) / 2 || count != tp_grid_count(TP_TRI, a, a)) {
        snprintf(why, size, "count %d", count);
        return 0;
    }
    for (i = a; i >= 0; i--)
        for (j = a - i; j >= 0; j--, k++) {
            int got = plane ? tp_domain_plane(d, i, j) : tp_domain_point(d, i, j);
            if (plane)
                tp_domain_plane_ij(&x, &y, d, k);
            else
                tp_domain_point_ij(&x, &y, d, k);
            if (got != k || x != i || y != j || !tp_grid_has(TP_TRI, a, a, i, j) ||
                (plane && tp_domain_plane_row_start(d, k) != (j == a - i))) {
                snprintf(why, size, "(%d, %d) -> %d, %d -> (%d, %d)", i, j, got, k, x, y);
                return 0;
            }
        }
    if (tp_grid_has(TP_TRI, a, a, a, 1) || tp_grid_has(TP_TRI, a, a, -1, 0)) {
        snprintf(why, size, "cells outside the triangle");
        return 0;
    }
    return 1;
}

/* Every triangle degree: counts, plane degree 3d-3, both maps in the documented order. */
static void test_tri_maps(void)
{
    char why[160] = "", w[120];
    int n, bad = 0;
    for (n = 1; n <= PTP_MAX_TRI_DEGREE; n++) {
        tp_domain d;
        ptp_error err;
        int st = tp_domain_init(&d, TP_TRI, n, 7, &err);
        if (st)
            snprintf(w, sizeof w, "init: %.100s", err.msg);
        else if (!(d.kind == TP_TRI && d.n == n && d.m == n && d.pu == 3 * n - 3 &&
                   d.pv == 3 * n - 3))
            snprintf(w, sizeof w, "degrees %d %d %d %d", d.n, d.m, d.pu, d.pv);
        if ((st || d.pu != 3 * n - 3 || !tri_grid_ok(w, sizeof w, &d, 0) ||
             !tri_grid_ok(w, sizeof w, &d, 1)) && !bad++)
            snprintf(why, sizeof why, "degree %d: %s", n, w);
    }
    check(!bad, "every triangle degree: (d+1)(d+2)/2 points, (3d-2)(3d-1)/2 planes, both maps "
                "inverse bijections in descending (i, j) order", "%s", why);
}

/* Triangle names, prefix, parsing and its rejections. */
static void test_tri_names(void)
{
    static const char *const bad[] = {"3x3", "3X2", "0", "29", "", "3 "};
    tp_domain d;
    tp_domain_text x;
    ptp_error err;
    char buf[32];
    size_t i;
    int st = tp_domain_parse(&d, TP_TRI, "3", &err);
    tp_domain_text_get(&x, &d);
    check(!st && d.kind == TP_TRI && d.n == 3 && d.npoints == 10 && d.nplanes == 28 &&
              !strcmp(tp_domain_prefix(buf, sizeof buf, &d), "ptp_tri3_") &&
              !strcmp(x.name, "degree 3") && !strcmp(x.plane_name, "degree 6") &&
              !strcmp(x.degree, "3") && !strcmp(x.degrees, "3") && !strcmp(x.plane_degrees, "6") &&
              !strcmp(x.point_rule, "k = (3-i)(4-i)/2 + 3-i-j") &&
              !strcmp(x.plane_rule, "P = (6-I)(7-I)/2 + 6-I-J") &&
              !strcmp(tp_kind_name(TP_TRI), "triangle") && !strcmp(tp_kind_name(TP_QUAD), "quad"),
          "triangle degree 3: parse, counts, names, rules, prefix ptp_tri3_", "%s / %s / %s / %s",
          buf, x.name, x.point_rule, x.plane_rule);
    for (i = 0; i < sizeof bad / sizeof *bad; i++) {
        char name[80], quoted[32];
        st = tp_domain_parse(&d, TP_TRI, bad[i], &err);
        snprintf(name, sizeof name, "triangle --degree '%s' is refused", bad[i]);
        snprintf(quoted, sizeof quoted, "--degree '%s': ", bad[i]);
        check(st == PTP_EUSAGE && !strncmp(err.msg, quoted, strlen(quoted)) &&
                  (i > 1 || strstr(err.msg, "--degree for triangles takes one degree")),
              name, "status %d: %s", st, err.msg);
    }
}

/* The points on edge e of the grid written out from the documented numberings (quad k = i*(m+1)
 * + j; triangle k = (d-i)(d-i+1)/2 + (d-i-j)), in increasing order; returns their count. */
static int edge_expected(int *k, const tp_domain *d, int e)
{
    int x, count = d->kind == TP_TRI || e < 2 ? d->m + 1 : d->n + 1;
    for (x = 0; x < count; x++) {
        int i = d->kind == TP_TRI ? (e == 0 ? 0 : d->n - x) : (e == 0 ? 0 : e == 1 ? d->n : x);
        int j = d->kind == TP_TRI ? (e == 0 ? d->n - x : e == 1 ? 0 : x) : (e < 2 ? x : e == 2 ? 0 : d->m);
        k[x] = d->kind == TP_TRI ? (d->n - i) * (d->n - i + 1) / 2 + d->n - i - j : i * (d->m + 1) + j;
    }
    return count;
}

/* tp_domain_edge_points on every quad bidegree and triangle degree against edge_expected. */
static void test_edge_points(void)
{
    char why[160] = "";
    int kind, n, m, e, bad = 0;
    for (kind = 0; kind < 2; kind++)
        for (n = 1; n <= (kind ? PTP_MAX_TRI_DEGREE : PTP_MAX_DEGREE); n++)
            for (m = kind ? n : 1; m <= (kind ? n : PTP_MAX_DEGREE); m++) {
                tp_domain d;
                tp_domain_init(&d, kind ? TP_TRI : TP_QUAD, n, m, NULL);
                for (e = 0; e < tp_domain_edges(&d); e++) {
                    int got[TP_EDGE_POINTS_MAX + 1], want[TP_EDGE_POINTS_MAX + 1];
                    int c = tp_domain_edge_points(got, &d, e), w = edge_expected(want, &d, e);
                    if ((c != w || c > TP_EDGE_POINTS_MAX || memcmp(got, want, sizeof *got * (size_t)w)) &&
                        !bad++)
                        snprintf(why, sizeof why, "%s %dx%d edge %d: %d points, %d expected",
                                 kind ? "triangle" : "quad", n, m, e, c, w);
                }
            }
    check(!bad, "tp_domain_edge_points lists every edge's points in order (every degree)", "%s", why);
}

int main(void)
{
    test_maps();
    test_names();
    test_round_trip();
    test_rejects();
    test_random_parse();
    test_init_limits();
    test_derive_counts();
    test_tri_maps();
    test_tri_names();
    test_edge_points();
    return check_exit();
}
