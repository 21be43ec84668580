/* test_tri.c: the triangular patch tables against the mathematics, exactly.
 * cross4(B, B_u, B_v) of random integer patches at random rational (u, v) against the planes. */
#include "check.h"
#include "core/bez.h"
#include "core/tplane.h"
#include "kref.h"

#include <stdlib.h>
#include <string.h>

/* Points have integer coordinates in [-3, 3] (w in [1, 3]); (u, v, w) = (a, b, c) / N. */
#define N 6

typedef ptp_i128 vec4[4];

static uint64_t seed = 20251123;

static int rnd(int lo, int hi)
{
    return lo + (int)(ptp_splitmix64(&seed) % (uint64_t)(hi - lo + 1));
}

/* The multinomial d!/(i! j! k!), k = d - i - j. */
static ptp_i128 multinomial(int d, int i, int j)
{
    ptp_i128 c = 1;
    int x;
    for (x = 0; x < i; x++)
        c = c * (d - x) / (x + 1);
    for (x = 0; x < j; x++)
        c = c * (d - i - x) / (x + 1);
    return c;
}

static ptp_i128 ipow(int x, int e)
{
    ptp_i128 r = 1;
    while (e-- > 0)
        r *= x;
    return r;
}

/* N^d times the triangular Bernstein basis of degree d at (a, b, c) / N, cell (i, j). */
static ptp_i128 basis(int d, int i, int j, int a, int b, int c)
{
    return multinomial(d, i, j) * ipow(a, i) * ipow(b, j) * ipow(c, d - i - j);
}

/* The point b_ijk of a degree-d patch, by the documented numbering written out: the points
 * in descending lexicographic order of (i, j). */
static int point_index(int d, int i, int j)
{
    int x, y, k = 0;
    for (x = d; x >= 0; x--)
        for (y = d - x; y >= 0; y--, k++)
            if (x == i && y == j)
                return k;
    return -1;
}

/* r = cross4(a, b, c) as the cofactors of the first row of the 4x4 determinant with rows
 * (e, a, b, c): r[q] = (-1)^q times the 3x3 minor without column q (Sarrus). */
static void cross4(vec4 r, const vec4 a, const vec4 b, const vec4 c)
{
    int q, x, col[3];
    for (q = 0; q < 4; q++) {
        ptp_i128 det = 0;
        for (x = 0; x < 3; x++)
            col[x] = x < q ? x : x + 1;
        for (x = 0; x < 3; x++) {
            int p0 = col[x], p1 = col[(x + 1) % 3], p2 = col[(x + 2) % 3];
            det += a[p0] * b[p1] * c[p2] - a[p2] * b[p1] * c[p0];
        }
        r[q] = q % 2 ? -det : det;
    }
}

/* N^(3d-2) cross4(B, B_u, B_v) at (a, b, c) / N, from the definition: B_u = d sum over degree
 * d-1 of (b_{i+1,j,k} - b_{i,j,k+1}) B^{d-1}_ijk, B_v likewise with b_{i,j+1,k}. */
static void direct(vec4 T, const vec4 *p, int d, int a, int b, int c)
{
    vec4 B = {0}, Bu = {0}, Bv = {0};
    int i, j, x;
    for (i = 0; i <= d; i++)
        for (j = 0; i + j <= d; j++) {
            ptp_i128 w = basis(d, i, j, a, b, c);
            for (x = 0; x < 4; x++)
                B[x] += w * p[point_index(d, i, j)][x];
        }
    for (i = 0; i < d; i++)
        for (j = 0; i + j < d; j++) {
            ptp_i128 w = d * basis(d - 1, i, j, a, b, c);
            const ptp_i128 *lo = p[point_index(d, i, j)];
            for (x = 0; x < 4; x++) {
                Bu[x] += w * (p[point_index(d, i + 1, j)][x] - lo[x]);
                Bv[x] += w * (p[point_index(d, i, j + 1)][x] - lo[x]);
            }
        }
    cross4(T, B, Bu, Bv);
}

/* Nonzero when N times the table's planes, N^(3d-3) sum_P t_P B^{3d-3}_P at (a, b, c) / N,
 * equal T exactly; or on overflow (reported in why). */
static int planes_match(char *why, size_t size, const tp_table *t, const vec4 *p, const vec4 T,
                        int a, int b, int c)
{
    rat s[4], x, y;
    int q, I, J, st = 0;
    size_t e;
    for (q = 0; q < 4; q++)
        rat_set_si(&s[q], 0);
    for (e = 0; e < t->nterms && !st; e++) {
        const tp_term *m = &t->terms[e];
        vec4 cr;
        tp_domain_plane_ij(&I, &J, &t->dom, m->plane);
        cross4(cr, p[m->j], p[m->k], p[m->l]);
        for (q = 0; q < 4 && !st; q++)
            st = rat_set_frac(&x, cr[q] * basis(t->dom.pu, I, J, a, b, c) * N, 1) ||
                 rat_mul(&y, &x, &m->w) || rat_add(&s[q], &s[q], &y);
    }
    if (st) {
        snprintf(why, size, "overflow");
        return 0;
    }
    for (q = 0; q < 4; q++)
        if (s[q].den != 1 || s[q].num != T[q]) {
            snprintf(why, size, "component %d: %g, direct %g", q, rat_get_d(&s[q]), (double)T[q]);
            return 0;
        }
    return 1;
}

/* Random patches of degree d at random (a, b, c) on and inside the triangle: every case
 * must match; returns the number of mismatches, the first in why. */
static int random_cases(char *why, size_t size, const tp_table *t, int cases)
{
    int d = t->dom.n, bad = 0, s, k, x;
    vec4 *p = malloc((size_t)t->dom.npoints * sizeof *p);
    for (s = 0; s < cases; s++) {
        int a = rnd(0, N), b = rnd(0, N - a), c = N - a - b;
        vec4 T;
        char w[120];
        for (k = 0; k < t->dom.npoints; k++) {
            for (x = 0; x < 3; x++)
                p[k][x] = rnd(-3, 3);
            p[k][3] = s % 2 ? rnd(1, 3) : 1; /* odd cases: rational patches */
        }
        direct(T, (const vec4 *)p, d, a, b, c);
        if (!planes_match(w, sizeof w, t, (const vec4 *)p, T, a, b, c) && !bad++)
            snprintf(why, size, "degree %d at (%d, %d, %d)/%d: %s", d, a, b, c, N, w);
    }
    free(p);
    return bad;
}

/* Degrees 1..5: the planes equal cross4(B, B_u, B_v) exactly; a changed weight is caught. */
static void test_exact(void)
{
    char why[200] = "";
    int d, bad = 0, caught = 0;
    for (d = 1; d <= 5; d++) {
        tp_domain dom;
        tp_table t;
        ptp_error err;
        if (tp_domain_init(&dom, TP_TRI, d, d, &err) || tp_derive_domain(&t, &dom, &err)) {
            if (!bad++)
                snprintf(why, sizeof why, "degree %d: %.100s", d, err.msg);
            continue;
        }
        bad += random_cases(why, sizeof why, &t, 40);
        rat_set_frac(&t.terms[t.nterms / 2].w, t.terms[t.nterms / 2].w.num + 1,
                     t.terms[t.nterms / 2].w.den);
        caught += random_cases(why + 100, 100, &t, 40) > 0;
        tp_clear(&t);
    }
    check(!bad, "degrees 1..5: the planes at 40 random (u, v) of random integer patches (w = 1 "
                "and rational) equal cross4(B, B_u, B_v) exactly", "%s", why);
    check(caught == 5, "the exact comparison catches one weight changed by 1/den",
          "caught in %d of 5 degrees", caught);
}

/* The plain triangle: one plane, t_0 = cross4(b0, b1, b2) (B_u = b0 - b2, B_v = b1 - b2 and
 * B ^ (b0 - b2) ^ (b1 - b2) = (u + v + w) b0 ^ b1 ^ b2). */
static void test_degree1(void)
{
    tp_domain dom;
    tp_table t;
    ptp_error err;
    int ok = !tp_domain_init(&dom, TP_TRI, 1, 1, &err) && !tp_derive_domain(&t, &dom, &err);
    ok = ok && t.dom.npoints == 3 && t.dom.nplanes == 1 && t.nterms == 1 && t.terms[0].plane == 0 &&
         t.terms[0].j == 0 && t.terms[0].k == 1 && t.terms[0].l == 2 && t.terms[0].w.num == 1 &&
         t.terms[0].w.den == 1;
    check(ok, "degree 1: one plane, one term, t_0 = +1 cross4(b0, b1, b2)", "%s",
          ok ? "" : err.msg);
    if (ok)
        tp_clear(&t);
}

/* Terms per degree, planes per degree, and the largest plane and point used. */
static void test_counts(void)
{
    static const size_t terms[] = {0, 1, 17, 105, 407, 1216, 3036};
    char why[160] = "";
    int d, bad = 0;
    for (d = 1; d <= 6; d++) {
        tp_domain dom;
        tp_table t;
        ptp_error err;
        int maxp, maxk;
        if (tp_domain_init(&dom, TP_TRI, d, d, &err) || tp_derive_domain(&t, &dom, &err)) {
            if (!bad++)
                snprintf(why, sizeof why, "degree %d: %.100s", d, err.msg);
            continue;
        }
        kref_table_max(&maxp, &maxk, &t);
        if ((t.nterms != terms[d] || maxp != (3 * d - 1) * (3 * d - 2) / 2 - 1 ||
             maxk != (d + 1) * (d + 2) / 2 - 1) && !bad++)
            snprintf(why, sizeof why, "degree %d: %zu terms, largest plane %d, point %d", d,
                     t.nterms, maxp, maxk);
        tp_clear(&t);
    }
    check(!bad, "degrees 1..6: 1, 17, 105, 407, 1216, 3036 terms over all (3d-2)(3d-1)/2 planes "
                "and (d+1)(d+2)/2 points", "%s", why);
}

/* Beyond the limit: PTP_ELIMIT with the limit named. The reduction fails loudly on a
 * polynomial whose degree does not drop, and on a quad. */
static void test_limits(void)
{
    tp_domain dom;
    ptp_error err;
    char lim[16];
    bez B, R;
    int st = tp_domain_init(&dom, TP_TRI, PTP_MAX_TRI_DEGREE + 1, 0, &err);
    snprintf(lim, sizeof lim, "limit %d ", PTP_MAX_TRI_DEGREE);
    check(st == PTP_ELIMIT && strstr(err.msg, lim), "a degree beyond PTP_MAX_TRI_DEGREE is refused",
          "status %d: %s", st, err.msg);
    tp_domain_init(&dom, TP_TRI, 3, 3, &err);
    bez_patch(&B, &dom, &err);
    st = bez_reduce_tri(&R, &B, &err);
    check(st == PTP_EINTERNAL && strstr(err.msg, "residual"),
          "triangular degree reduction of a patch of full degree fails with a residual error",
          "status %d: %s", st, err.msg);
    if (st == PTP_OK)
        bez_clear(&R);
    bez_clear(&B);
    tp_domain_init(&dom, TP_QUAD, 2, 2, &err);
    bez_patch(&B, &dom, &err);
    st = bez_reduce_tri(&R, &B, &err);
    check(st == PTP_EINTERNAL, "triangular degree reduction refuses a quad", "status %d", st);
    if (st == PTP_OK)
        bez_clear(&R);
    bez_clear(&B);
}

int main(void)
{
    test_degree1();
    test_exact();
    test_counts();
    test_limits();
    return check_exit();
}
