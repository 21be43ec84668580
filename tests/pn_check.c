/* pn_check.c: checks of bench/pn.c (PN triangles), bench/tess.c (the tessellator) and the
 * triangular cases of bench/cones.c and bench/exact.c; run by test_cullrate.sh. */
#include "cones.h"
#include "exact.h"
#include "pn.h"
#include "tess.h"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-const-variable" /* the table's schedule arrays */
#include "cr_tt.h" /* ptpgen's table for cubic triangles (the Makefile's cullrate part) */
#pragma GCC diagnostic pop

#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

static int failed;

/* One check line: "ok - NAME", or "not ok - NAME: detail" (printf-style). */
static void check(int ok, const char *name, const char *detail, ...)
{
    va_list ap;
    printf("%s - %s", ok ? "ok" : "not ok", name);
    if (!ok) {
        printf(": ");
        va_start(ap, detail);
        vprintf(detail, ap);
        va_end(ap);
        failed++;
    }
    printf("\n");
}

/* A uniform double in [lo, hi) (splitmix64). */
static double rnd(double lo, double hi)
{
    static uint64_t x = 16;
    uint64_t z = (x += 0x9e3779b97f4a7c15u);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9u;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebu;
    return lo + (hi - lo) * (double)((z ^ (z >> 31)) >> 11) * 0x1p-53;
}

/* The index of cell (i, j, d - i - j) of a degree-d triangle: descending (i, j). */
static int cell(int d, int i, int j)
{
    int r = d - i;
    return r * (r + 1) / 2 + r - j;
}

static double dot(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static void cross(double r[3], const double a[3], const double b[3])
{
    r[0] = a[1] * b[2] - a[2] * b[1];
    r[1] = a[2] * b[0] - a[0] * b[2];
    r[2] = a[0] * b[1] - a[1] * b[0];
}

/* B, B_u and B_v of the cubic triangle b (ptpgen's order) at (u, v), w = 1 - u - v, by the
 * de Casteljau recurrence: independent of cones.c's Bernstein sums. */
static void eval(const double b[PN_POINTS][3], double u, double v, double p[3], double pu[3],
                 double pv[3])
{
    double a[10][3], w = 1 - u - v;
    int d, i, j, c;
    memcpy(a, b, sizeof a);
    for (d = 3; d > 1; d--) /* to degree 1, in place: cell(d-1, i, j) is cell(d, i+1, j) */
        for (i = d - 1; i >= 0; i--)
            for (j = 0; i + j < d; j++)
                for (c = 0; c < 3; c++)
                    a[cell(d - 1, i, j)][c] = u * a[cell(d, i + 1, j)][c] +
                                              v * a[cell(d, i, j + 1)][c] +
                                              w * a[cell(d, i, j)][c];
    for (c = 0; c < 3; c++) { /* degree 1: a[0] = b100, a[1] = b010, a[2] = b001 */
        p[c] = u * a[0][c] + v * a[1][c] + w * a[2][c];
        pu[c] = 3 * (a[0][c] - a[2][c]);
        pv[c] = 3 * (a[1][c] - a[2][c]);
    }
}

/* A random triangle and vertex normals within about 60 degrees of its face normal. */
static void random_triangle(double p[3][3], double n[3][3])
{
    double e1[3], e2[3], f[3], l;
    int k, c;
    for (k = 0; k < 3; k++)
        for (c = 0; c < 3; c++)
            p[k][c] = rnd(-1, 1);
    for (c = 0; c < 3; c++) {
        e1[c] = p[1][c] - p[0][c];
        e2[c] = p[2][c] - p[0][c];
    }
    cross(f, e1, e2);
    l = sqrt(dot(f, f));
    for (k = 0; k < 3; k++)
        for (c = 0; c < 3; c++)
            n[k][c] = f[c] / l + rnd(-0.5, 0.5);
}

static double angle(const double a[3], const double b[3])
{
    double x[3];
    cross(x, a, b);
    return atan2(sqrt(dot(x, x)), dot(a, b));
}

/* The PN triangle interpolates its corners, and B_u x B_v at each corner points along the
 * corner's normal. */
static void check_corners(void)
{
    static const double uv[3][2] = {{1, 0}, {0, 1}, {0, 0}};
    double worst_p = 0, worst_n = 0, worst_c = 0;
    int t, k, c;
    for (t = 0; t < 2000; t++) {
        double p[3][3], n[3][3], b[PN_POINTS][3];
        random_triangle(p, n);
        pn_triangle(b, (const double(*)[3])p, (const double(*)[3])n);
        for (c = 0; c < 3; c++) { /* b111 = E + (E - V) / 2 */
            double e = 0, v = (p[0][c] + p[1][c] + p[2][c]) / 3;
            for (k = 0; k < PN_POINTS; k++)
                e += k == 0 || k == 4 || k == 6 || k == 9 ? 0 : b[k][c] / 6;
            worst_c = fmax(worst_c, fabs(b[4][c] - (e + (e - v) / 2)));
        }
        for (k = 0; k < 3; k++) {
            double q[3], qu[3], qv[3], x[3], err = 0;
            eval((const double(*)[3])b, uv[k][0], uv[k][1], q, qu, qv);
            for (c = 0; c < 3; c++)
                err = fmax(err, fabs(q[c] - p[k][c]));
            worst_p = fmax(worst_p, err);
            cross(x, qu, qv);
            worst_n = fmax(worst_n, isnan(angle(x, n[k])) ? INFINITY : angle(x, n[k]));
        }
    }
    check(worst_p <= 1e-14, "pn_triangle interpolates the three corners (2000 triangles)",
          "a corner is %g off", worst_p);
    check(worst_n < 1e-6, "pn_triangle: B_u x B_v at each corner points along its normal",
          "%g rad off", worst_n);
    check(worst_c < 1e-14, "pn_triangle: the centre b111 is E + (E - V) / 2", "%g off", worst_c);
}

/* With the face normal at every corner the PN triangle is the flat triangle: point (i, j, k)
 * at (i P1 + j P2 + k P3) / 3, so all ten points lie in the plane. */
static void check_flat(void)
{
    double worst = 0;
    int t, i, j, c;
    for (t = 0; t < 2000; t++) {
        double p[3][3], n[3][3], b[PN_POINTS][3], e1[3], e2[3], f[3], err = 0;
        random_triangle(p, n);
        for (c = 0; c < 3; c++) {
            e1[c] = p[1][c] - p[0][c];
            e2[c] = p[2][c] - p[0][c];
        }
        cross(f, e1, e2);
        for (i = 0; i < 3; i++) /* every normal the face normal, scaled differently */
            for (c = 0; c < 3; c++)
                n[i][c] = f[c] * (i + 1);
        pn_triangle(b, (const double(*)[3])p, (const double(*)[3])n);
        for (i = 0; i <= 3; i++)
            for (j = 0; i + j <= 3; j++)
                for (c = 0; c < 3; c++) {
                    double want = (i * p[0][c] + j * p[1][c] + (3 - i - j) * p[2][c]) / 3;
                    err = fmax(err, fabs(b[cell(3, i, j)][c] - want));
                }
        worst = fmax(worst, err);
    }
    check(worst <= 1e-14, "pn_triangle with face normals is the flat triangle (planar points)",
          "a point is %g off", worst);
}

/* NCONE and TCONE of PN triangles hold the direction of B_u x B_v at 200 random points; the
 * bounding sphere holds the points; and cones.c's e.T agrees with this file's evaluation. */
static void check_cones(void)
{
    double worst = 0, worst_f = 0;
    int t, s, k, c, usable = 0;
    for (t = 0; t < 300; t++) {
        double p[3][3], n[3][3], eye[3];
        cone_patch b = {.domain = CONE_TRI};
        cone_bound nc, tc;
        random_triangle(p, n);
        pn_triangle(b.p, (const double(*)[3])p, (const double(*)[3])n);
        if (cone_ncone(&b, &nc) || cone_tcone(&b, &tc))
            worst = INFINITY;
        usable += nc.usable + tc.usable;
        for (c = 0; c < 3; c++)
            eye[c] = rnd(-4, 4);
        for (s = 0; s < 200; s++) {
            double u = rnd(0, 1), v = rnd(0, 1 - u), q[3], qu[3], qv[3], x[3], d[3], f;
            eval((const double(*)[3])b.p, u, v, q, qu, qv);
            cross(x, qu, qv);
            for (k = 0; k < 2; k++) {
                const cone_bound *cb = k ? &tc : &nc;
                for (c = 0; c < 3; c++)
                    d[c] = q[c] - cb->center[c];
                if (sqrt(dot(d, d)) > cb->radius * (1 + 1e-12))
                    worst = INFINITY;
                if (cb->usable && sqrt(dot(x, x)) > 1e-9)
                    worst = fmax(worst, angle(x, cb->axis) - cb->alpha);
            }
            for (c = 0; c < 3; c++)
                d[c] = eye[c] - q[c];
            f = cone_direct(&b, eye, u, v, NULL);
            worst_f = fmax(worst_f, fabs(f - dot(d, x)) / (1 + fabs(f)));
        }
    }
    check(worst < 1e-9 && usable > 100, "NCONE and TCONE of PN triangles hold every sampled normal",
          "a normal %g rad outside (or a point outside the sphere); %d usable cones", worst,
          usable);
    check(worst_f < 1e-12, "cone_direct on triangles is (E - B) . (B_u x B_v)", "off by %g",
          worst_f);
}

/* e.T's control values of a random PN triangle of float points from a random eye (floats too),
 * as doubles in c and exactly in x. Returns 0, or -1 if a table call fails. */
static int random_values(double c[64], exact_int x[64])
{
    double p[3][3], n[3][3], eye[3];
    float bf[PN_POINTS][3], ef[3];
    cone_patch b = {.domain = CONE_TRI};
    cone_tplane t;
    int k, i;
    random_triangle(p, n);
    pn_triangle(b.p, (const double(*)[3])p, (const double(*)[3])n);
    for (i = 0; i < 3; i++)
        eye[i] = ef[i] = (float)rnd(-3, 3);
    for (k = 0; k < PN_POINTS; k++)
        for (i = 0; i < 3; i++)
            b.p[k][i] = bf[k][i] = (float)b.p[k][i];
    if (cone_planes(&b, CR_TT_TERMS, cr_tt_table_idx, cr_tt_table_iwgt, CR_TT_DENOM, &t) ||
        exact_values((const float(*)[3])bf, PN_POINTS, ef, CR_TT_TERMS, cr_tt_table_idx,
                     cr_tt_table_iwgt, 28, x))
        return -1;
    cone_values(&t, eye, c);
    return 0;
}

/* 1 if cone_split to depth 6 (piece corners on the 1/64 grid) and the 257-point sampling (which
 * holds that grid) contradict each other on the triangle's values c. */
static int split_disagrees(const double c[64], int *back, int *positive)
{
    int r = cone_split(CONE_TRI, c, 6), pos;
    if (cone_sample(CONE_TRI, c, 257, &pos))
        return 1;
    *back += r == CONE_BACK;
    *positive += pos;
    return (r == CONE_BACK && pos) || (r == CONE_NOT_BACK && !pos);
}

/* Subdivision against sampling on random values: negative corners, the rest in [-1, 0.3]. */
static void check_split(void)
{
    int t, k, bad = 0, back = 0, positive = 0;
    for (t = 0; t < 3000; t++) {
        double c[64];
        for (k = 0; k < 28; k++)
            c[k] = k == 0 || k == 21 || k == 27 ? rnd(-1, 0) : rnd(-1, 0.3);
        bad += split_disagrees(c, &back, &positive);
    }
    check(!bad && back > 100 && positive > 100,
          "CVis on triangles: subdivision and sampling agree (3000 random value sets)",
          "%d disagree; %d back, %d with a positive sample", bad, back, positive);
}

/* The CVis bracket on PN triangles: subdivision and sampling agree; the 33-point sampling agrees
 * with its exact twin; the exact control values' signs are the double ones. */
static void check_cvis(void)
{
    int t, k, bad_split = 0, bad_sample = 0, bad_sign = 0, positive = 0, back = 0;
    for (t = 0; t < 400; t++) {
        double c[64], scale = 0;
        exact_int x[64];
        int pos33;
        if (random_values(c, x)) {
            bad_split = 1000;
            break;
        }
        bad_split += split_disagrees(c, &back, &positive);
        if (cone_sample(CONE_TRI, c, 33, &pos33))
            bad_sample = 1000;
        bad_sample += pos33 != exact_sample_positive(CONE_TRI, x, 33);
        for (k = 0; k < 28; k++)
            scale = fmax(scale, fabs(c[k]));
        for (k = 0; k < 28; k++)
            bad_sign += fabs(c[k]) > 1e-9 * scale && (c[k] > 0 ? 1 : -1) != exact_sign(&x[k]);
    }
    check(!bad_split && back > 20 && positive > 20,
          "CVis on triangles: subdivision and sampling agree (400 PN triangles)",
          "%d disagree; %d back, %d with a positive sample", bad_split, back, positive);
    check(!bad_sample, "exact_sample_positive on triangles matches the double sampling",
          "%d differ", bad_sample);
    check(!bad_sign, "exact_values on triangles: the signs of the double control values",
          "%d differ", bad_sign);
}

/* Two flat bicubic patches side by side (x in [0, 2], y in [0, 1], z = 0), the first with its
 * edge at x = 0 collapsed to one point when collapse is 1. */
static void flat_patches(double pts[32][3], int collapse)
{
    int p, i, j;
    for (p = 0; p < 2; p++)
        for (i = 0; i < 4; i++)
            for (j = 0; j < 4; j++) {
                double *q = pts[p * 16 + i * 4 + j];
                q[0] = p + i / 3.0;
                q[1] = collapse && p == 0 && i == 0 ? 0.5 : j / 3.0;
                q[2] = 0;
            }
}

/* The tessellator: counts, welding along the shared edge, normals (0, 0, 1) with the stand-in
 * at a collapsed edge, triangles counter-clockwise about the normal. */
static void check_tess(void)
{
    int collapse, grid;
    for (collapse = 0; collapse < 2; collapse++)
        for (grid = 1; grid <= 3; grid++) {
            double pts[32][3], worst = 0;
            tess_mesh m;
            size_t t, v;
            size_t want_v = (size_t)(2 * grid + 1) * (size_t)(grid + 1) - (size_t)(collapse * grid);
            size_t want_t = 4 * (size_t)grid * (size_t)grid - (size_t)(collapse * grid);
            flat_patches(pts, collapse);
            if (tess_bicubic(&m, (const double(*)[3])pts, 2, grid)) {
                check(0, "tess_bicubic", "failed on two flat patches");
                return;
            }
            for (v = 0; v < m.nverts; v++)
                worst = fmax(worst, fabs(m.nrm[v][2] - 1));
            for (t = 0; t < m.ntris; t++) {
                const double *a = m.pos[m.tri[t][0]], *b = m.pos[m.tri[t][1]];
                const double *c = m.pos[m.tri[t][2]];
                double area = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
                worst = fmax(worst, area > 0 ? 0 : INFINITY);
            }
            char name[100];
            snprintf(name, sizeof name, "tess_bicubic, grid %d: %s", grid,
                     collapse ? "a collapsed edge welds, drops and still has normals"
                              : "two patches weld along their edge");
            check(m.nverts == want_v && m.ntris == want_t && worst < 1e-12, name,
                  "grid %d: %zu vertices (want %zu), %zu triangles (want %zu), normal or "
                  "orientation off by %g", grid, m.nverts, want_v, m.ntris, want_t, worst);
            tess_free(&m);
        }
}

int main(void)
{
    check_corners();
    check_flat();
    check_cones();
    check_split();
    check_cvis();
    check_tess();
    return failed != 0;
}
