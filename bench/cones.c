/* cones.c: NCONE and TCONE normal cones with bounding spheres, and the subdivision and sampling
 * bracket of the exact tangent-plane test, for bicubic and cubic triangular patches (cones.h). */
#include "cones.h"

#include <math.h>
#include <string.h>

/* The products of cross products are never fused into FMAs, so that a cross product of two
 * bitwise-equal vectors is exactly zero (cone_planes' collapsed edges rely on it). */
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC optimize("fp-contract=off")
#endif
#if defined(__clang__)
#pragma STDC FP_CONTRACT OFF
#endif
/* After the pragmas, so that its products are not fused either. */
#include "vec3.h"

#define PI 3.14159265358979323846

/* What differs between the domains: point and plane counts, f's degree (per axis for quads,
 * total for triangles). */
typedef struct shape {
    int points, planes, deg;
} shape;
static const shape shapes[2] = {{16, 64, 7}, {10, 28, 6}};

static const double fact[7] = {1, 1, 2, 6, 24, 120, 720};

/* The index of triangular cell (i, j, d - i - j) of degree d: descending (i, j). */
static int tri_index(int d, int i, int j)
{
    int r = d - i;
    return r * (r + 1) / 2 + r - j;
}

/* The multinomial d! / (i! j! k!), d = i + j + k <= 6. */
static double multinomial(int i, int j, int k)
{
    return fact[i + j + k] / (fact[i] * fact[j] * fact[k]);
}

/* The triangular Bernstein polynomial of degree d (<= 6) for cell (i, j) at (u, v). */
static double tri_bernstein(int d, int i, int j, double u, double v)
{
    double r = multinomial(i, j, d - i - j), w = 1 - u - v;
    int k;
    for (k = 0; k < i; k++)
        r *= u;
    for (k = 0; k < j; k++)
        r *= v;
    for (k = 0; k < d - i - j; k++)
        r *= w;
    return r;
}

/* The angle between two unit vectors, accurate near 0 and pi. */
static double angle(const double a[3], const double b[3])
{
    double x[3];
    vec3_cross(x, a, b);
    return atan2(sqrt(vec3_dot(x, x)), vec3_dot(a, b));
}

/* 1 if all n points are finite. */
static int finite_patch(const double (*b)[3], int n)
{
    int k, c;
    for (k = 0; k < n; k++)
        for (c = 0; c < 3; c++)
            if (!isfinite(b[k][c]))
                return 0;
    return 1;
}

/* The sphere about the center of the bounding box that holds the n points. */
static void sphere(const double (*b)[3], int n, cone_bound *c)
{
    double lo[3], hi[3], r2 = 0;
    int k, i;
    for (i = 0; i < 3; i++)
        lo[i] = hi[i] = b[0][i];
    for (k = 1; k < n; k++)
        for (i = 0; i < 3; i++) {
            lo[i] = fmin(lo[i], b[k][i]);
            hi[i] = fmax(hi[i], b[k][i]);
        }
    for (i = 0; i < 3; i++)
        c->center[i] = 0.5 * (lo[i] + hi[i]);
    for (k = 0; k < n; k++) {
        double d[3];
        vec3_sub(d, b[k], c->center);
        r2 = fmax(r2, vec3_dot(d, d));
    }
    c->radius = sqrt(r2);
}

/* A cone holding the directions of the n (<= 36) vectors v, zero vectors skipped: unit axis
 * and half-angle *alpha. The axis is the direction of the center of the smallest ball
 * enclosing the unit vectors, approximated by 64 Badoiu-Clarkson steps from their mean (the
 * farthest vector from the center is the one at the largest angle to the axis), keeping the
 * narrowest cone seen; any axis is valid, as alpha is the largest angle to it. Returns 0
 * when every vector is zero or the mean is zero (no cone), else 1, with alpha possibly
 * pi/2 or more. */
static int bound_directions(const double (*v)[3], int n, double axis[3], double *alpha)
{
    double u[36][3], c[3] = {0, 0, 0};
    int m = 0, i, it;
    for (i = 0; i < n; i++) {
        double l = sqrt(vec3_dot(v[i], v[i]));
        if (l == 0)
            continue;
        u[m][0] = v[i][0] / l;
        u[m][1] = v[i][1] / l;
        u[m][2] = v[i][2] / l;
        c[0] += u[m][0];
        c[1] += u[m][1];
        c[2] += u[m][2];
        m++;
    }
    for (i = 0; i < 3 && m > 0; i++)
        c[i] /= m;
    *alpha = PI;
    for (it = 1; it <= 64; it++) {
        double a[3], worst = -1, len = sqrt(vec3_dot(c, c));
        int far = 0;
        if (len == 0)
            return it > 1; /* no mean direction; later, the best cone so far */
        a[0] = c[0] / len;
        a[1] = c[1] / len;
        a[2] = c[2] / len;
        for (i = 0; i < m; i++) {
            double t = angle(a, u[i]);
            if (t > worst) {
                worst = t;
                far = i;
            }
        }
        if (worst < *alpha) {
            *alpha = worst;
            memcpy(axis, a, sizeof a);
        }
        for (i = 0; i < 3; i++)
            c[i] += (u[far][i] - c[i]) / (it + 1);
    }
    return 1;
}

/* A triangle's B_u and B_v (w = 1 - u - v), degree 2, cell a = (i, j, k) in tri_index order:
 * bu[a] = 3 (b_{a+e1} - b_{a+e3}), bv[a] = 3 (b_{a+e2} - b_{a+e3}). */
static void tri_derivatives(const double (*b)[3], double bu[12][3], double bv[12][3])
{
    int i, j, k;
    for (i = 0; i <= 2; i++)
        for (j = 0; i + j <= 2; j++)
            for (k = 0; k < 3; k++) {
                double base = b[tri_index(3, i, j)][k];
                bu[tri_index(2, i, j)][k] = 3 * (b[tri_index(3, i + 1, j)][k] - base);
                bv[tri_index(2, i, j)][k] = 3 * (b[tri_index(3, i, j + 1)][k] - base);
            }
}

/* The control vectors of B_u and B_v; returns their count, 12 or 6 each. For a bicubic patch
 * bu[a*4 + b] = 3 (b_{a+1,b} - b_{a,b}) (degree 2x3), bv[c*3 + d] = 3 (b_{c,d+1} - b_{c,d})
 * (degree 3x2); for a triangle, tri_derivatives. */
static int derivatives(const cone_patch *bp, double bu[12][3], double bv[12][3])
{
    const double(*b)[3] = bp->p;
    int i, j, k;
    if (bp->domain == CONE_TRI) {
        tri_derivatives(b, bu, bv);
        return 6;
    }
    for (i = 0; i < 3; i++)
        for (j = 0; j < 4; j++)
            for (k = 0; k < 3; k++)
                bu[i * 4 + j][k] = 3 * (b[(i + 1) * 4 + j][k] - b[i * 4 + j][k]);
    for (i = 0; i < 4; i++)
        for (j = 0; j < 3; j++)
            for (k = 0; k < 3; k++)
                bv[i * 3 + j][k] = 3 * (b[i * 4 + j + 1][k] - b[i * 4 + j][k]);
    return 12;
}

static const double binom[8][8] = {
    {1, 0, 0, 0, 0, 0, 0, 0},     {1, 1, 0, 0, 0, 0, 0, 0},      {1, 2, 1, 0, 0, 0, 0, 0},
    {1, 3, 3, 1, 0, 0, 0, 0},     {1, 4, 6, 4, 1, 0, 0, 0},      {1, 5, 10, 10, 5, 1, 0, 0},
    {1, 6, 15, 20, 15, 6, 1, 0},  {1, 7, 21, 35, 35, 21, 7, 1},
};

/* A triangle's 15 control vectors of N = B_u x B_v (degree 4), by the triangular Bernstein
 * product: N_g = sum over a + b = g of m(a) m(b) / m(g) Bu_a x Bv_b, m the multinomials. */
static void tri_normals(const double bu[12][3], const double bv[12][3], double n[36][3])
{
    int a1, a2, b1, b2, k;
    for (a1 = 0; a1 <= 2; a1++)
        for (a2 = 0; a1 + a2 <= 2; a2++)
            for (b1 = 0; b1 <= 2; b1++)
                for (b2 = 0; b1 + b2 <= 2; b2++) {
                    double x[3], *t = n[tri_index(4, a1 + b1, a2 + b2)];
                    double w = multinomial(a1, a2, 2 - a1 - a2) *
                               multinomial(b1, b2, 2 - b1 - b2) /
                               multinomial(a1 + b1, a2 + b2, 4 - a1 - a2 - b1 - b2);
                    vec3_cross(x, bu[tri_index(2, a1, a2)], bv[tri_index(2, b1, b2)]);
                    for (k = 0; k < 3; k++)
                        t[k] += w * x[k];
                }
}

/* The control vectors of N = B_u x B_v into n (zeroed first); returns their count, 36 or 15. */
static int normals(const cone_patch *bp, double n[36][3])
{
    double bu[12][3], bv[12][3];
    int a, bb, cc, d, k;
    derivatives(bp, bu, bv);
    memset(n, 0, 36 * sizeof *n);
    if (bp->domain == CONE_TRI) {
        tri_normals((const double(*)[3])bu, (const double(*)[3])bv, n);
        return 15;
    }
    /* N_{IJ} = sum C(2,a)C(3,c)/C(5,a+c) C(3,b)C(2,d)/C(5,b+d) Bu_{ab} x Bv_{cd}. */
    for (a = 0; a < 3; a++)
        for (bb = 0; bb < 4; bb++)
            for (cc = 0; cc < 4; cc++)
                for (d = 0; d < 3; d++) {
                    double x[3], w = binom[2][a] * binom[3][cc] / binom[5][a + cc] *
                                     binom[3][bb] * binom[2][d] / binom[5][bb + d];
                    double *t = n[(a + cc) * 6 + bb + d];
                    vec3_cross(x, bu[a * 4 + bb], bv[cc * 3 + d]);
                    for (k = 0; k < 3; k++)
                        t[k] += w * x[k];
                }
    return 36;
}

/* 1 if the patch's domain is known and its points are finite. */
static int valid_patch(const cone_patch *bp)
{
    return (bp->domain == CONE_QUAD || bp->domain == CONE_TRI) &&
           finite_patch(bp->p, shapes[bp->domain].points);
}

int cone_ncone(const cone_patch *bp, cone_bound *c)
{
    double n[36][3];
    int count;
    memset(c, 0, sizeof *c);
    if (!valid_patch(bp))
        return CONE_EINVAL;
    count = normals(bp, n);
    sphere(bp->p, shapes[bp->domain].points, c);
    c->usable = bound_directions((const double(*)[3])n, count, c->axis, &c->alpha) &&
                c->alpha < PI / 2;
    return CONE_OK;
}

int cone_tcone(const cone_patch *bp, cone_bound *c)
{
    double bu[12][3], bv[12][3], au[3], av[3], x[3], alu, alv, beta, s;
    int count;
    memset(c, 0, sizeof *c);
    if (!valid_patch(bp))
        return CONE_EINVAL;
    count = derivatives(bp, bu, bv);
    sphere(bp->p, shapes[bp->domain].points, c);
    if (!bound_directions((const double(*)[3])bu, count, au, &alu) ||
        !bound_directions((const double(*)[3])bv, count, av, &alv) || alu >= PI / 2 ||
        alv >= PI / 2)
        return CONE_OK;
    beta = angle(au, av);
    /* Tangent and bitangent never parallel nor antiparallel, so the normal turns continuously
     * and stays within alpha of the axis. The sign of cos(beta) is taken as the worse one:
     * with the signed cos(beta), sampling finds normals outside the cone for beta > pi/2. */
    if (alu + alv >= beta || alu + alv >= PI - beta)
        return CONE_OK;
    s = sqrt(sin(alu) * sin(alu) + 2 * sin(alu) * sin(alv) * fabs(cos(beta)) +
             sin(alv) * sin(alv)) /
        sin(beta);
    if (!(s < 1))
        return CONE_OK;
    vec3_cross(x, au, av);
    s = asin(s);
    beta = sqrt(vec3_dot(x, x));
    c->axis[0] = x[0] / beta;
    c->axis[1] = x[1] / beta;
    c->axis[2] = x[2] / beta;
    c->alpha = s;
    c->usable = 1;
    return CONE_OK;
}

int cone_cull(const cone_bound *c, const double eye[3])
{
    double d[3], dist, delta;
    if (!c->usable)
        return 0;
    vec3_sub(d, eye, c->center);
    dist = sqrt(vec3_dot(d, d));
    if (!(dist > c->radius))
        return 0;
    delta = asin(c->radius / dist);
    if (c->alpha + delta >= PI / 2)
        return 0;
    /* angle(axis, d) > pi/2 + alpha + delta, both sides in [0, pi]. */
    return vec3_dot(c->axis, d) / dist < -sin(c->alpha + delta);
}

int cone_planes(const cone_patch *bp, size_t terms, const unsigned short idx[][4],
                const int iwgt[], int denom, cone_tplane *tp)
{
    const double(*b)[3] = bp->p;
    double(*t)[4] = tp->t;
    size_t x;
    int p, k, np, nq;
    if (denom <= 0 || (bp->domain != CONE_QUAD && bp->domain != CONE_TRI))
        return CONE_EINVAL;
    np = shapes[bp->domain].points;
    nq = shapes[bp->domain].planes;
    memset(tp, 0, sizeof *tp);
    tp->domain = bp->domain;
    for (x = 0; x < terms; x++) {
        const double *bj;
        double e1[3], e2[3], n[3];
        if (idx[x][0] >= nq || idx[x][1] >= np || idx[x][2] >= np || idx[x][3] >= np)
            return CONE_EINVAL;
        bj = b[idx[x][1]];
        vec3_sub(e1, b[idx[x][2]], bj);
        vec3_sub(e2, b[idx[x][3]], bj);
        vec3_cross(n, e1, e2);
        p = idx[x][0];
        for (k = 0; k < 3; k++)
            t[p][k] += iwgt[x] * n[k];
        t[p][3] -= iwgt[x] * vec3_dot(bj, n);
    }
    for (p = 0; p < nq; p++)
        for (k = 0; k < 4; k++)
            t[p][k] /= denom;
    return CONE_OK;
}

void cone_values(const cone_tplane *tp, const double eye[3], double c[64])
{
    const double(*t)[4] = tp->t;
    int p;
    for (p = 0; p < shapes[tp->domain == CONE_TRI].planes; p++)
        c[p] = eye[0] * t[p][0] + eye[1] * t[p][1] + eye[2] * t[p][2] + t[p][3];
}

/* The Bernstein basis of degree deg (<= 7) at t. */
static void bernstein(int deg, double t, double out[8])
{
    double tp[8], sp[8];
    int i;
    tp[0] = sp[0] = 1;
    for (i = 1; i <= deg; i++) {
        tp[i] = tp[i - 1] * t;
        sp[i] = sp[i - 1] * (1 - t);
    }
    for (i = 0; i <= deg; i++)
        out[i] = binom[deg][i] * tp[i] * sp[deg - i];
}

double cone_eval(int domain, const double c[64], double u, double v)
{
    double bu[8], bv[8], f = 0;
    int i, j;
    if (domain == CONE_TRI) {
        for (i = 0; i <= 6; i++)
            for (j = 0; i + j <= 6; j++)
                f += tri_bernstein(6, i, j, u, v) * c[tri_index(6, i, j)];
        return f;
    }
    bernstein(7, u, bu);
    bernstein(7, v, bv);
    for (i = 0; i < 8; i++) {
        double row = 0;
        for (j = 0; j < 8; j++)
            row += bv[j] * c[i * 8 + j];
        f += bu[i] * row;
    }
    return f;
}

/* B, B_u and B_v of a cubic triangle at (u, v), added to p, pu and pv. */
static void tri_point(const double (*b)[3], double u, double v, double p[3], double pu[3],
                      double pv[3])
{
    double bu[12][3], bv[12][3];
    int i, j, k;
    tri_derivatives(b, bu, bv);
    for (i = 0; i <= 3; i++)
        for (j = 0; i + j <= 3; j++) {
            double w3 = tri_bernstein(3, i, j, u, v);
            double w2 = i + j <= 2 ? tri_bernstein(2, i, j, u, v) : 0;
            int a = i + j <= 2 ? tri_index(2, i, j) : 0;
            for (k = 0; k < 3; k++) {
                p[k] += w3 * b[tri_index(3, i, j)][k];
                pu[k] += w2 * bu[a][k];
                pv[k] += w2 * bv[a][k];
            }
        }
}

/* B, B_u and B_v of a bicubic patch at (u, v), added to p, pu and pv. */
static void quad_point(const double (*b)[3], double u, double v, double p[3], double pu[3],
                       double pv[3])
{
    double du[8], dv[8], cu[8], cv[8];
    int i, j, k;
    bernstein(3, u, cu);
    bernstein(3, v, cv);
    bernstein(2, u, du);
    bernstein(2, v, dv);
    for (i = 0; i < 4; i++)
        for (j = 0; j < 4; j++)
            for (k = 0; k < 3; k++) {
                p[k] += cu[i] * cv[j] * b[i * 4 + j][k];
                if (i < 3)
                    pu[k] += 3 * du[i] * cv[j] * (b[(i + 1) * 4 + j][k] - b[i * 4 + j][k]);
                if (j < 3)
                    pv[k] += 3 * cu[i] * dv[j] * (b[i * 4 + j + 1][k] - b[i * 4 + j][k]);
            }
}

double cone_direct(const cone_patch *bp, const double eye[3], double u, double v, double *sine)
{
    double p[3] = {0, 0, 0}, pu[3] = {0, 0, 0}, pv[3] = {0, 0, 0}, d[3], n[3], f;
    if (bp->domain == CONE_TRI)
        tri_point(bp->p, u, v, p, pu, pv);
    else
        quad_point(bp->p, u, v, p, pu, pv);
    vec3_sub(d, eye, p);
    vec3_cross(n, pu, pv);
    f = vec3_dot(d, n);
    if (sine) {
        double den = sqrt(vec3_dot(d, d)) * sqrt(vec3_dot(n, n));
        *sine = den > 0 ? f / den : 0;
    }
    return f;
}

/* Splits the 8 values x[0], x[s], ..., x[7s] at t = 1/2 into lo and hi (same stride). */
static void halve(const double *x, int s, double *lo, double *hi)
{
    double w[8];
    int r, i;
    for (i = 0; i < 8; i++)
        w[i] = x[i * s];
    lo[0] = w[0];
    hi[7 * s] = w[7];
    for (r = 1; r < 8; r++) {
        for (i = 0; i < 8 - r; i++)
            w[i] = 0.5 * (w[i] + w[i + 1]);
        lo[r * s] = w[0];
        hi[(7 - r) * s] = w[7 - r];
    }
}

/* The value at cell (i, j) of the blossom of the degree-6 triangular values c at i copies of
 * q[0], j of q[1] and the rest q[2] (barycentric (u, v, w) points): the control value (i, j)
 * of f over the triangle q[0] q[1] q[2]. */
static double blossom(const double c[28], const double q[3][3], int i, int j)
{
    double a[28], b[28];
    int d, r, s;
    memcpy(a, c, sizeof a);
    for (d = 6; d > 0; d--) { /* one de Casteljau step: degree d to d - 1 */
        const double *x = q[6 - d < i ? 0 : 6 - d < i + j ? 1 : 2];
        for (r = 0; r < d; r++)
            for (s = 0; r + s < d; s++)
                b[tri_index(d - 1, r, s)] = x[0] * a[tri_index(d, r + 1, s)] +
                                            x[1] * a[tri_index(d, r, s + 1)] +
                                            x[2] * a[tri_index(d, r, s)];
        memcpy(a, b, sizeof a);
    }
    return a[0];
}

/* The 4 sub-triangles of a triangle's values c at its edge midpoints into q. */
static void tri_quarter(const double c[28], double q[4][64])
{
    static const double corner[4][3][3] = {
        {{1, 0, 0}, {0.5, 0.5, 0}, {0.5, 0, 0.5}},
        {{0.5, 0.5, 0}, {0, 1, 0}, {0, 0.5, 0.5}},
        {{0.5, 0, 0.5}, {0, 0.5, 0.5}, {0, 0, 1}},
        {{0, 0.5, 0.5}, {0.5, 0, 0.5}, {0.5, 0.5, 0}},
    };
    int h, i, j;
    for (h = 0; h < 4; h++)
        for (i = 0; i <= 6; i++)
            for (j = 0; i + j <= 6; j++)
                q[h][tri_index(6, i, j)] = blossom(c, corner[h], i, j);
}

/* The 4 quarters of a square's values c, halving u and v, into q. */
static void quad_quarter(const double c[64], double q[4][64])
{
    double half[2][64];
    int h, k;
    for (k = 0; k < 8; k++) /* u (the first index): column k */
        halve(c + k, 8, half[0] + k, half[1] + k);
    for (h = 0; h < 2; h++)
        for (k = 0; k < 8; k++) /* v: row k */
            halve(half[h] + 8 * k, 1, q[2 * h] + 8 * k, q[2 * h + 1] + 8 * k);
}

static int split_rec(int domain, const double c[64], int depth)
{
    static const int corners[2][3] = {{0, 7, 56}, {0, 21, 27}}; /* and c[63] for quads */
    double q[4][64];
    int p, h, r;
    for (p = 0; p < shapes[domain].planes && !(c[p] > 0); p++)
        ;
    if (p == shapes[domain].planes)
        return CONE_BACK;
    for (h = 0; h < 3; h++)
        if (c[corners[domain][h]] > 0)
            return CONE_NOT_BACK;
    if (domain == CONE_QUAD && c[63] > 0)
        return CONE_NOT_BACK;
    if (depth == 0)
        return CONE_UNDECIDED;
    if (domain == CONE_TRI)
        tri_quarter(c, q);
    else
        quad_quarter(c, q);
    for (h = 0; h < 4; h++)
        if ((r = split_rec(domain, q[h], depth - 1)) != CONE_BACK)
            return r;
    return CONE_BACK;
}

int cone_split(int domain, const double c[64], int depth)
{
    if (depth < 0 || depth > 12 || (domain != CONE_QUAD && domain != CONE_TRI))
        return CONE_EINVAL;
    return split_rec(domain, c, depth);
}

/* cone_sample for a triangle: the grid points with s + t <= n - 1. */
static int tri_sample(const double c[28], int n, int *positive)
{
    int s, t, i, j, k;
    for (s = 0; s < n; s++)
        for (t = 0; s + t < n; t++) {
            double pw[3][7], f = 0;
            double x[3] = {(double)s / (n - 1), (double)t / (n - 1),
                           (double)(n - 1 - s - t) / (n - 1)};
            for (k = 0; k < 3; k++)
                for (pw[k][0] = 1, i = 1; i <= 6; i++)
                    pw[k][i] = pw[k][i - 1] * x[k];
            for (i = 0; i <= 6; i++)
                for (j = 0; i + j <= 6; j++)
                    f += multinomial(i, j, 6 - i - j) * pw[0][i] * pw[1][j] * pw[2][6 - i - j] *
                         c[tri_index(6, i, j)];
            if (f > 0) {
                *positive = 1;
                return CONE_OK;
            }
        }
    return CONE_OK;
}

int cone_sample(int domain, const double c[64], int n, int *positive)
{
    double bv[257][8];
    int s, t, i, j;
    *positive = 0;
    if (n < 2 || n > 257 || (domain != CONE_QUAD && domain != CONE_TRI))
        return CONE_EINVAL;
    if (domain == CONE_TRI)
        return tri_sample(c, n, positive);
    for (t = 0; t < n; t++)
        bernstein(7, (double)t / (n - 1), bv[t]);
    for (s = 0; s < n; s++) {
        double g[8] = {0, 0, 0, 0, 0, 0, 0, 0};
        for (i = 0; i < 8; i++)
            for (j = 0; j < 8; j++)
                g[j] += bv[s][i] * c[i * 8 + j]; /* u = s/(n-1), the same basis */
        for (t = 0; t < n; t++) {
            double f = 0;
            for (j = 0; j < 8; j++)
                f += bv[t][j] * g[j];
            if (f > 0) {
                *positive = 1;
                return CONE_OK;
            }
        }
    }
    return CONE_OK;
}
