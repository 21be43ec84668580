/* test_tplane.c: checks the derived control-plane tables against the mathematics.
 * Count matrix, closed forms, transposition, and numeric agreement with cross4(B, B_u, B_v). */
#include "core/bez.h"
#include "check.h"
#include "core/tplane.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* The paper's section 6 matrix: terms per plane of the bicubic patch. */
static const int paper_counts[64] = {
    1, 2, 4,  5,  5,  4,  2,  1, 2, 4, 8,  10, 10, 8,  4,  2, 4, 8, 11, 17, 17, 11,
    8, 4, 5,  10, 17, 21, 21, 17, 10, 5, 5, 10, 17, 21, 21, 17, 10, 5,  4,  8,  11, 17,
    17, 11, 8, 4, 2, 4, 8, 10, 10, 8, 4, 2, 1, 2, 4, 5, 5, 4, 2, 1};

static uint64_t rng = 0x9E3779B97F4A7C15u;

/* A uniform double in [lo, hi) (xorshift64*; fixed seed, reproducible). */
static double uniform(double lo, double hi)
{
    rng ^= rng >> 12;
    rng ^= rng << 25;
    rng ^= rng >> 27;
    return lo + (hi - lo) * (double)((rng * 2685821657736338717u) >> 11) / 9007199254740992.0;
}

static double bernstein(int d, int i, double t)
{
    double c = 1;
    int k;
    for (k = 0; k < i; k++)
        c = c * (d - k) / (k + 1);
    return c * pow(t, i) * pow(1 - t, d - i);
}

/* Evaluates the patch (deriv 0), B_u (1) or B_v (2) at (u, v). */
static void eval_patch(double r[4], const double (*b)[4], int n, int m, int deriv, double u,
                       double v)
{
    int i, j, c;
    memset(r, 0, 4 * sizeof *r);
    for (i = 0; i <= n - (deriv == 1); i++)
        for (j = 0; j <= m - (deriv == 2); j++) {
            const double *p = b[i * (m + 1) + j];
            double w = bernstein(n - (deriv == 1), i, u) * bernstein(m - (deriv == 2), j, v);
            for (c = 0; c < 4; c++) {
                double x = p[c];
                if (deriv == 1)
                    x = n * (b[(i + 1) * (m + 1) + j][c] - p[c]);
                if (deriv == 2)
                    x = m * (b[i * (m + 1) + j + 1][c] - p[c]);
                r[c] += w * x;
            }
        }
}

/* Largest |error| / magnitude over 50 random (u, v) between cross4(B, B_u, B_v) and the
 * Bernstein evaluation of the planes of t applied to the points b. */
static double worst_error(const tp_table *t, const double (*b)[4])
{
    double (*pl)[4] = calloc((size_t)t->dom.nplanes, sizeof *pl);
    double (*mg)[4] = calloc((size_t)t->dom.nplanes, sizeof *mg);
    double worst = 0;
    size_t x;
    int s, c, I, J;
    for (x = 0; x < t->nterms; x++) {
        const tp_term *e = &t->terms[x];
        double cr[4], w = rat_get_d(&e->w);
        tp_cross4(cr, b[e->j], b[e->k], b[e->l]);
        for (c = 0; c < 4; c++) {
            pl[e->plane][c] += w * cr[c];
            mg[e->plane][c] += fabs(w * cr[c]);
        }
    }
    for (s = 0; s < 50; s++) {
        double u = uniform(0, 1), v = uniform(0, 1), B[4], Bu[4], Bv[4], T[4], P[4] = {0},
               M = 0;
        eval_patch(B, b, t->dom.n, t->dom.m, 0, u, v);
        eval_patch(Bu, b, t->dom.n, t->dom.m, 1, u, v);
        eval_patch(Bv, b, t->dom.n, t->dom.m, 2, u, v);
        tp_cross4(T, B, Bu, Bv);
        for (I = 0; I <= t->dom.pu; I++)
            for (J = 0; J <= t->dom.pv; J++) {
                double w = bernstein(t->dom.pu, I, u) * bernstein(t->dom.pv, J, v);
                for (c = 0; c < 4; c++) {
                    P[c] += w * pl[I * (t->dom.pv + 1) + J][c];
                    M = fmax(M, w * mg[I * (t->dom.pv + 1) + J][c]);
                }
            }
        for (c = 0; c < 4; c++)
            worst = fmax(worst, fabs(P[c] - T[c]) / (M > 0 ? M : 1));
    }
    free(pl);
    free(mg);
    return worst;
}

static void test_bicubic(void)
{
    tp_table t;
    ptp_error err;
    int counts[64], same;
    char w[RAT_STRLEN];
    if (!check(tp_derive(&t, 3, 3, &err) == PTP_OK, "bicubic: derives", "%s", err.msg))
        return;
    tp_plane_counts(counts, &t);
    same = memcmp(counts, paper_counts, sizeof counts) == 0;
    check(t.nterms == 516, "bicubic: 516 terms", "got %zu", t.nterms);
    check(same, "bicubic: terms per plane equal the paper's matrix", "they differ");
    check(t.terms[0].plane == 0 && t.terms[0].j == 0 && t.terms[0].k == 1 && t.terms[0].l == 4 &&
              strcmp(rat_get_str(w, &t.terms[0].w), "-9") == 0 && t.terms[1].plane == 1,
          "bicubic: plane 0 is -9 cross4(b0, b1, b4)", "first term %d:(%d,%d,%d) %s",
          t.terms[0].plane, t.terms[0].j, t.terms[0].k, t.terms[0].l,
          rat_get_str(w, &t.terms[0].w));
    tp_clear(&t);
}

/* Properties every table must have: sorted, unique, canonical weights, j < k < l, and the
 * corner plane t_0 = T(0,0) = cross4(b0, n(b_{m+1} - b0), m(b1 - b0)) = -nm cross4(b0, b1, b_{m+1}). */
static int table_is_wellformed(const tp_table *t, char *why)
{
    size_t x;
    for (x = 0; x < t->nterms; x++) {
        const tp_term *e = &t->terms[x], *p = x ? e - 1 : NULL;
        if (!rat_is_canonical(&e->w) || e->w.num == 0 || !(e->j < e->k && e->k < e->l) ||
            e->l >= t->dom.npoints || e->plane < 0 || e->plane >= t->dom.nplanes) {
            sprintf(why, "term %zu malformed", x);
            return 0;
        }
        if (p && (p->plane > e->plane ||
                  (p->plane == e->plane &&
                   (p->j > e->j || (p->j == e->j && (p->k > e->k || (p->k == e->k && p->l >= e->l))))))) {
            sprintf(why, "terms %zu and %zu out of order or repeated", x - 1, x);
            return 0;
        }
    }
    if (t->nterms < 1 || t->terms[0].plane != 0 || t->terms[0].j != 0 || t->terms[0].k != 1 ||
        t->terms[0].l != t->dom.m + 1 || t->terms[0].w.num != -(ptp_i128)(t->dom.n * t->dom.m) ||
        t->terms[0].w.den != 1 || (t->nterms > 1 && t->terms[1].plane == 0)) {
        sprintf(why, "plane 0 is not -nm cross4(b0, b1, b_{m+1})");
        return 0;
    }
    return 1;
}

static void test_random_patches(void)
{
    int n, m, p, k, c, bad_form = 0, bad_num = 0, bad_rat = 0, cases = 0;
    double worst = 0;
    char why[128] = "", first[640] = "";
    for (n = 1; n <= 6; n++)
        for (m = 1; m <= 6; m++) {
            tp_table t;
            ptp_error err;
            if (tp_derive(&t, n, m, &err)) {
                snprintf(first, sizeof first, "%dx%d: %s", n, m, err.msg);
                bad_form++;
                continue;
            }
            if (!table_is_wellformed(&t, why)) {
                if (!bad_form++)
                    snprintf(first, sizeof first, "%dx%d: %s", n, m, why);
            }
            for (p = 0; p < 4; p++, cases++) {
                double(*b)[4] = malloc((size_t)t.dom.npoints * sizeof *b), e;
                for (k = 0; k < t.dom.npoints; k++) {
                    for (c = 0; c < 3; c++)
                        b[k][c] = uniform(-1, 1);
                    b[k][3] = p < 2 ? 1.0 : uniform(0.25, 4); /* p >= 2: rational patches */
                }
                e = worst_error(&t, (const double(*)[4])b);
                worst = fmax(worst, e);
                if (e > 1e-12 && !bad_num++)
                    snprintf(first, sizeof first, "%dx%d patch %d: error %.3g", n, m, p, e);
                if (p == 3) {
                    /* The comparison must catch a wrong table: change one weight by 0.1%. */
                    rat *w = &t.terms[t.nterms / 2].w;
                    rat f, g;
                    rat_set_frac(&f, 1001, 1000);
                    rat_mul(&g, w, &f);
                    *w = g;
                    if (worst_error(&t, (const double(*)[4])b) <= 1e-12)
                        bad_rat++;
                }
                free(b);
            }
            tp_clear(&t);
        }
    check(bad_form == 0, "every bidegree 1..6 x 1..6 derives a well-formed table (sorted, "
                         "unique, canonical, plane 0 = -nm cross4(b0, b1, b_{m+1}))", "%s", first);
    check(bad_num == 0, "random patches 1..6 x 1..6 (w = 1 and rational): planes agree with "
                        "cross4(B, Bu, Bv) at 50 points within 1e-12", "%s", first);
    check(bad_rat == 0, "the numeric comparison rejects a table with one weight off by 0.1%",
          "%d of 36 perturbed tables passed", bad_rat);
    printf("# %d random patches, worst relative error %.3g\n", cases, worst);
}

static int cmp_term(const void *pa, const void *pb)
{
    const tp_term *a = pa, *b = pb;
    if (a->plane != b->plane)
        return a->plane < b->plane ? -1 : 1;
    if (a->j != b->j)
        return a->j < b->j ? -1 : 1;
    if (a->k != b->k)
        return a->k < b->k ? -1 : 1;
    return (a->l > b->l) - (a->l < b->l);
}

/* Maps table (n, m) to (m, n): plane (I,J) -> (J,I), point (i,j) -> (j,i), weight negated
 * (swapping B_u and B_v flips cross4), then the triple re-sorted with its sign. */
static void transpose(tp_table *t)
{
    size_t x;
    for (x = 0; x < t->nterms; x++) {
        tp_term *e = &t->terms[x];
        int p[3] = {e->j, e->k, e->l}, a, b, sign = -1, tmp;
        e->plane = (e->plane % (t->dom.pv + 1)) * (t->dom.pu + 1) + e->plane / (t->dom.pv + 1);
        for (a = 0; a < 3; a++)
            p[a] = (p[a] % (t->dom.m + 1)) * (t->dom.n + 1) + p[a] / (t->dom.m + 1);
        for (a = 0; a < 3; a++)
            for (b = a + 1; b < 3; b++)
                if (p[b] < p[a]) {
                    tmp = p[a];
                    p[a] = p[b];
                    p[b] = tmp;
                    sign = -sign;
                }
        e->j = p[0];
        e->k = p[1];
        e->l = p[2];
        if (sign < 0)
            rat_neg(&e->w, &e->w);
    }
    qsort(t->terms, t->nterms, sizeof *t->terms, cmp_term);
}

static void test_transpose(void)
{
    int n, m, bad = 0;
    char first[64] = "";
    for (n = 1; n <= 6; n++)
        for (m = 1; m <= 6; m++) {
            tp_table a, b;
            ptp_error err;
            size_t x;
            int same;
            if (tp_derive(&a, n, m, &err) || tp_derive(&b, m, n, &err)) {
                bad++;
                continue;
            }
            transpose(&a);
            same = a.nterms == b.nterms;
            for (x = 0; same && x < a.nterms; x++)
                same = cmp_term(&a.terms[x], &b.terms[x]) == 0 && rat_equal(&a.terms[x].w, &b.terms[x].w);
            if (!same && !bad++)
                snprintf(first, sizeof first, "%dx%d vs %dx%d", n, m, m, n);
            tp_clear(&a);
            tp_clear(&b);
        }
    check(bad == 0, "tables (n,m) and (m,n) correspond under transposition with all weights "
                    "negated (1 <= n, m <= 6)", "%s", first);
}

static void test_limits(void)
{
    tp_table t;
    tp_domain d;
    ptp_error err;
    bez B, R;
    int st;
    check(tp_derive(&t, PTP_MAX_DEGREE + 1, 2, &err) == PTP_ELIMIT && strstr(err.msg, "16"),
          "a degree beyond the limit is refused, naming the limit", "%s", err.msg);
    check(tp_derive(&t, 0, 2, &err) == PTP_EUSAGE, "degree 0 is refused", "%s", err.msg);
    /* The reduction check must fail loudly on a polynomial whose degree does not drop. */
    tp_domain_init(&d, TP_QUAD, 3, 2, &err);
    bez_patch(&B, &d, &err);
    st = bez_reduce_u(&R, &B, &err);
    check(st == PTP_EINTERNAL && strstr(err.msg, "residual"),
          "degree reduction of a patch of full degree fails with a residual error", "status %d: %s",
          st, err.msg);
    if (st == PTP_OK)
        bez_clear(&R);
    st = bez_reduce_v(&R, &B, &err);
    check(st == PTP_EINTERNAL, "the same along v", "status %d", st);
    bez_clear(&B);
}

int main(void)
{
    test_bicubic();
    test_random_patches();
    test_transpose();
    test_limits();
    return check_exit();
}
