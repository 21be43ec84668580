/* mkmodel.c: writes the knot (build/models/knot.bez), a closed model of 2,880 bicubic patches for
 * the tests and benchmarks: a periodic bicubic B-spline tube around a torus knot, as Bezier; with
 * --far, the far model (build/models/far.bez): 4,096 small patches far from the origin, a section
 * of the knot subdivided and moved away, for cullrate's absolute against local coordinates. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846
#define NU 180 /* B-spline control points (and patches) along the knot */
#define NV 16  /* around the tube */
#define GU (3 * NU) /* Bezier control points along the knot, shared between patches */
#define GV (3 * NV)

/* The far model: the knot's first FS patches along the knot (all NV around: a tube section), each
 * split 4 x 4 by de Casteljau at u, v = 1/4, 1/2, 3/4, so FS * NV * 16 sub-patches. */
#define FS 16
#define FU (12 * FS + 1) /* its Bezier control points along the knot (an open section) */
#define FV (12 * NV)     /* around the tube (periodic) */

typedef struct {
    double x[3];
} vec;

static vec add(vec a, vec b, double s) /* a + s b */
{
    for (int c = 0; c < 3; c++)
        a.x[c] += s * b.x[c];
    return a;
}

static vec cross(vec a, vec b)
{
    vec r = {{a.x[1] * b.x[2] - a.x[2] * b.x[1], a.x[2] * b.x[0] - a.x[0] * b.x[2],
              a.x[0] * b.x[1] - a.x[1] * b.x[0]}};
    return r;
}

static vec unit(vec a)
{
    double n = sqrt(a.x[0] * a.x[0] + a.x[1] * a.x[1] + a.x[2] * a.x[2]);
    vec r = {{a.x[0] / n, a.x[1] / n, a.x[2] / n}};
    return r;
}

/* The surface at knot parameter t and tube angle a (both in [0, 2 pi)): the knot
 * ((2 + 0.8 cos 3t) cos 2t, (2 + 0.8 cos 3t) sin 2t, 0.8 sin 3t) plus a radius that swells and
 * ripples, along the frame (d, T x d), d the unit offset of the knot from its torus's core
 * circle (exactly normal to the knot's tangent T). */
static vec surface(double t, double a)
{
    double c2 = cos(2 * t), s2 = sin(2 * t), c3 = cos(3 * t), s3 = sin(3 * t);
    double rad = 0.42 * (1 + 0.3 * cos(5 * t) + 0.08 * cos(3 * a + 7 * t) + 0.05 * sin(2 * a));
    vec core = {{(2 + 0.8 * c3) * c2, (2 + 0.8 * c3) * s2, 0.8 * s3}};
    vec d = {{c3 * c2, c3 * s2, s3}};
    vec tg = {{-2.4 * s3 * c2 - 2 * (2 + 0.8 * c3) * s2, -2.4 * s3 * s2 + 2 * (2 + 0.8 * c3) * c2,
                2.4 * c3}};
    vec b = cross(unit(tg), d);
    return add(add(core, d, rad * cos(a)), b, rad * sin(a));
}

/* Converts n periodic uniform cubic B-spline control points p[k*stride] into the 3n Bezier
 * points q[k*stride] of its n segments (segment i: q[3i..3i+3], q[3n] = q[0]). */
static void bspline_to_bezier(const vec *p, vec *q, int n, int stride)
{
    for (int i = 0; i < n; i++) {
        vec p0 = p[i * stride], p1 = p[(i + 1) % n * stride], p2 = p[(i + 2) % n * stride];
        for (int c = 0; c < 3; c++) {
            q[3 * i * stride].x[c] = (p0.x[c] + 4 * p1.x[c] + p2.x[c]) / 6;
            q[(3 * i + 1) * stride].x[c] = (2 * p1.x[c] + p2.x[c]) / 3;
            q[(3 * i + 2) * stride].x[c] = (p1.x[c] + 2 * p2.x[c]) / 3;
        }
    }
}

/* Six times the signed volume enclosed by the Bezier control net g (GU x GV, periodic), as
 * triangles: positive when the net's (u, v) order faces outward. */
static double net_volume(const vec *g)
{
    double v = 0;
    for (int i = 0; i < GU; i++)
        for (int j = 0; j < GV; j++) {
            vec a = g[i * GV + j], b = g[(i + 1) % GU * GV + j];
            vec c = g[(i + 1) % GU * GV + (j + 1) % GV], d = g[i * GV + (j + 1) % GV];
            vec n1 = cross(b, c), n2 = cross(c, d);
            for (int k = 0; k < 3; k++)
                v += a.x[k] * (n1.x[k] + n2.x[k]);
        }
    return v;
}

/* Writes the BEZ file: NU*NV patches over the GU*GV shared points of g. */
static int write_bez(FILE *f, const vec *g)
{
    fprintf(f, "%d\n", NU * NV);
    for (int i = 0; i < NU; i++)
        for (int j = 0; j < NV; j++)
            for (int k = 0; k < 16; k++)
                fprintf(f, "%d%c", (3 * i + k / 4) % GU * GV + (3 * j + k % 4) % GV + 1,
                        k == 15 ? '\n' : ',');
    fprintf(f, "%d\n", GU * GV);
    for (int k = 0; k < GU * GV; k++)
        fprintf(f, "%.9g,%.9g,%.9g\n", g[k].x[0], g[k].x[1], g[k].x[2]);
    return fflush(f) || ferror(f) ? -1 : 0;
}

/* Halves the cubic w[0..3] (integers, multiples of 8) at t = 1/2 into o[0..6] exactly. */
static void halve(const int64_t w[4], int64_t o[7])
{
    o[0] = w[0];
    o[1] = (w[0] + w[1]) / 2;
    o[2] = (w[0] + 2 * w[1] + w[2]) / 4;
    o[3] = (w[0] + 3 * w[1] + 3 * w[2] + w[3]) / 8;
    o[4] = (w[1] + 2 * w[2] + w[3]) / 4;
    o[5] = (w[2] + w[3]) / 2;
    o[6] = w[3];
}

/* Splits the cubic p[0..3] at t = 1/4, 1/2 and 3/4 into the 13 points q[0..12] of its four
 * pieces, all times 64: two halvings of the points times 8, exact in integers. */
static void split4(const int64_t p[4], int64_t q[13])
{
    int64_t w[4], h[7];
    int k, s;
    for (k = 0; k < 4; k++)
        w[k] = 8 * p[k];
    halve(w, h);
    for (s = 0; s < 2; s++) {
        for (k = 0; k < 4; k++)
            w[k] = 8 * h[3 * s + k];
        halve(w, q + 6 * s);
    }
}

/* The far model from the knot's net g: the first FS patch rows along the knot rounded to
 * multiples of 2^-20, each split 4 x 4 in exact integer arithmetic (split4 along the knot, then
 * around), so the sub-patches' points are exact multiples of 2^-32, then moved by far_offset
 * (exact in double) and rounded to float. The sub-patches' control nets span 0.047 to 0.092
 * (median 0.068), so the coordinates, about 1,100, are about 2^14 times a sub-patch's size: a
 * float's ulp there (2^-13 or 2^-14) is about 1/600 of a sub-patch. */
static const double far_offset[3] = {1100, -1100, 1100};

static int write_far(FILE *f, const vec *g)
{
    static int64_t a[3 * FS + 1][GV + 1][3], b[FU][GV + 1][3], c[FU][FV + 1][3];
    int64_t p[4], q[13];
    int i, j, k, x;
    for (i = 0; i <= 3 * FS; i++)
        for (j = 0; j <= GV; j++)
            for (x = 0; x < 3; x++)
                a[i][j][x] = llround(ldexp(g[i * GV + j % GV].x[x], 20));
    for (j = 0; j <= GV; j++) /* along the knot: segment s of column j */
        for (x = 0; x < 3; x++)
            for (int s = 0; s < FS; s++) {
                for (k = 0; k < 4; k++)
                    p[k] = a[3 * s + k][j][x];
                split4(p, q);
                for (k = 0; k < 13; k++)
                    b[12 * s + k][j][x] = q[k];
            }
    for (i = 0; i < FU; i++) /* around the tube */
        for (x = 0; x < 3; x++)
            for (int s = 0; s < NV; s++) {
                for (k = 0; k < 4; k++)
                    p[k] = b[i][3 * s + k][x];
                split4(p, q);
                for (k = 0; k < 13; k++)
                    c[i][12 * s + k][x] = q[k];
            }
    fprintf(f, "%d\n", 16 * FS * NV);
    for (i = 0; i < 4 * FS; i++)
        for (j = 0; j < 4 * NV; j++)
            for (k = 0; k < 16; k++)
                fprintf(f, "%d%c", (3 * i + k / 4) * FV + (3 * j + k % 4) % FV + 1,
                        k == 15 ? '\n' : ',');
    fprintf(f, "%d\n", FU * FV);
    for (i = 0; i < FU; i++)
        for (j = 0; j < FV; j++) {
            char line[3][32];
            for (x = 0; x < 3; x++) {
                double d = ldexp((double)c[i][j][x], -32) + far_offset[x]; /* exact */
                float v = (float)d;
                snprintf(line[x], sizeof line[x], "%.9g", v);
                if ((float)strtod(line[x], NULL) != v || llabs(c[i][j][x]) >= INT64_C(1) << 53) {
                    fprintf(stderr, "mkmodel: %s does not read back as %.9g\n", line[x], v);
                    return -1;
                }
            }
            fprintf(f, "%s,%s,%s\n", line[0], line[1], line[2]);
        }
    return fflush(f) || ferror(f) ? -1 : 0;
}

int main(int argc, char **argv)
{
    static vec p[NU * NV], h[GU * NV], g[GU * GV];
    FILE *f = stdout;
    int far = argc > 1 && !strcmp(argv[1], "--far");
    if (far)
        argc--, argv++;
    if (argc > 2 || (argc == 2 && argv[1][0] == '-')) {
        fprintf(stderr, "usage: mkmodel [--far] [OUT.bez]   (writes the knot model, with --far the "
                        "far model; default: stdout)\n");
        return 2;
    }
    for (int i = 0; i < NU; i++) /* the B-spline control grid: samples of the surface */
        for (int j = 0; j < NV; j++)
            p[i * NV + j] = surface(2 * PI * i / NU, 2 * PI * j / NV);
    for (int j = 0; j < NV; j++) /* along the knot, then around the tube */
        bspline_to_bezier(p + j, h + j, NU, NV);
    for (int i = 0; i < GU; i++)
        bspline_to_bezier(h + i * NV, g + i * GV, NV, 1);
    if (net_volume(g) <= 0) { /* face outward: reverse the order around the tube */
        for (int i = 0; i < GU; i++)
            for (int j = 1; j < GV - j; j++) {
                vec t = g[i * GV + j];
                g[i * GV + j] = g[i * GV + GV - j];
                g[i * GV + GV - j] = t;
            }
        if (net_volume(g) <= 0) {
            fprintf(stderr, "mkmodel: the net encloses no volume\n");
            return 1;
        }
    }
    if (argc == 2 && !(f = fopen(argv[1], "w"))) {
        perror(argv[1]);
        return 1;
    }
    if ((far ? write_far(f, g) : write_bez(f, g)) || (f != stdout && fclose(f))) {
        fprintf(stderr, "mkmodel: cannot write %s\n", argc == 2 ? argv[1] : "standard output");
        return 1;
    }
    return 0;
}
