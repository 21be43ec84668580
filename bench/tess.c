/* tess.c: bicubic patches to a welded triangle mesh with exact normals (tess.h), by evaluating each
 * patch on a grid and merging equal vertices through a hash table. */
#include "tess.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* The cubic Bernstein basis and its derivative at t. */
static void basis(double t, double b[4], double d[4])
{
    double s = 1 - t;
    b[0] = s * s * s;
    b[1] = 3 * t * s * s;
    b[2] = 3 * t * t * s;
    b[3] = t * t * t;
    d[0] = -3 * s * s;
    d[1] = 3 * s * s - 6 * t * s;
    d[2] = 6 * t * s - 3 * t * t;
    d[3] = 3 * t * t;
}

/* B(u, v) and N = B_u x B_v of the patch b. */
static void evaluate(const double (*b)[3], double u, double v, double p[3], double n[3])
{
    double bu[4], du[4], bv[4], dv[4], pu[3] = {0, 0, 0}, pv[3] = {0, 0, 0};
    int i, j, k;
    basis(u, bu, du);
    basis(v, bv, dv);
    for (k = 0; k < 3; k++)
        p[k] = 0;
    for (i = 0; i < 4; i++)
        for (j = 0; j < 4; j++)
            for (k = 0; k < 3; k++) {
                p[k] += bu[i] * bv[j] * b[i * 4 + j][k];
                pu[k] += du[i] * bv[j] * b[i * 4 + j][k];
                pv[k] += bu[i] * dv[j] * b[i * 4 + j][k];
            }
    n[0] = pu[1] * pv[2] - pu[2] * pv[1];
    n[1] = pu[2] * pv[0] - pu[0] * pv[2];
    n[2] = pu[0] * pv[1] - pu[1] * pv[0];
}

/* The unit normal of the patch b at (u, v), or at the point a hundredth of the way towards the
 * centre where B_u x B_v is zero there; (0, 0, 0) if that is zero too. Stores B(u, v) in p. */
static void unit_normal(const double (*b)[3], double u, double v, double p[3], double n[3])
{
    double q[3], len;
    int k;
    evaluate(b, u, v, p, n);
    len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (!(len > 0)) {
        evaluate(b, u + (0.5 - u) / 100, v + (0.5 - v) / 100, q, n);
        len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    }
    for (k = 0; k < 3; k++)
        n[k] = len > 0 && isfinite(len) ? n[k] / len : 0;
}

/* A hash of a position rounded to float. */
static size_t hash(const float f[3])
{
    uint32_t w[3];
    uint64_t h = 0x9e3779b97f4a7c15u;
    int k;
    memcpy(w, f, sizeof w);
    for (k = 0; k < 3; k++)
        h = (h ^ w[k]) * 0xff51afd7ed558ccdu;
    return (size_t)(h ^ (h >> 29));
}

/* The vertex at position p (welded by its float rounding) in m, added if new, with the unit
 * normal n summed into its normal. table (size mask + 1) maps hashes to vertex index + 1. */
static uint32_t weld(tess_mesh *m, uint32_t *table, size_t mask, const double p[3],
                     const double n[3])
{
    float f[3] = {(float)p[0], (float)p[1], (float)p[2]};
    size_t h = hash(f) & mask;
    int k;
    for (;; h = (h + 1) & mask) {
        uint32_t v = table[h];
        if (!v)
            break;
        if ((float)m->pos[v - 1][0] == f[0] && (float)m->pos[v - 1][1] == f[1] &&
            (float)m->pos[v - 1][2] == f[2]) {
            for (k = 0; k < 3; k++)
                m->nrm[v - 1][k] += n[k];
            return v - 1;
        }
    }
    table[h] = (uint32_t)++m->nverts;
    for (k = 0; k < 3; k++) {
        m->pos[m->nverts - 1][k] = p[k];
        m->nrm[m->nverts - 1][k] = n[k];
    }
    return (uint32_t)(m->nverts - 1);
}

/* Normalizes every vertex normal of m (a zero sum stays zero). */
static void normalize(tess_mesh *m)
{
    size_t v;
    int k;
    for (v = 0; v < m->nverts; v++) {
        double *n = m->nrm[v], len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        for (k = 0; k < 3; k++)
            n[k] = len > 0 ? n[k] / len : 0;
    }
}

/* Adds triangle a b c to m unless two of its corners are one vertex. */
static void add_triangle(tess_mesh *m, uint32_t a, uint32_t b, uint32_t c)
{
    if (a == b || b == c || c == a)
        return;
    m->tri[m->ntris][0] = a;
    m->tri[m->ntris][1] = b;
    m->tri[m->ntris++][2] = c;
}

/* Adds patch b's (n+1)^2 grid vertices and up to 2 n^2 triangles to m. */
static void add_patch(tess_mesh *m, uint32_t *table, size_t mask, const double (*b)[3], int n)
{
    uint32_t id[65][65];
    int i, j;
    for (i = 0; i <= n; i++)
        for (j = 0; j <= n; j++) {
            double p[3], nv[3];
            unit_normal(b, (double)i / n, (double)j / n, p, nv);
            id[i][j] = weld(m, table, mask, p, nv);
        }
    for (i = 0; i < n; i++)
        for (j = 0; j < n; j++) {
            add_triangle(m, id[i][j], id[i + 1][j], id[i][j + 1]);
            add_triangle(m, id[i + 1][j + 1], id[i][j + 1], id[i + 1][j]);
        }
}

int tess_bicubic(tess_mesh *m, const double (*pts)[3], size_t npatches, int n)
{
    size_t maxv = npatches * (size_t)(n + 1) * (size_t)(n + 1), size = 1, p;
    uint32_t *table;
    memset(m, 0, sizeof *m);
    if (n < 1 || n > 64 || maxv >= UINT32_MAX / 4)
        return -1;
    while (size < 2 * maxv)
        size *= 2;
    table = calloc(size, sizeof *table);
    m->pos = malloc(maxv * sizeof *m->pos);
    m->nrm = malloc(maxv * sizeof *m->nrm);
    m->tri = malloc(2 * npatches * (size_t)n * (size_t)n * sizeof *m->tri);
    if (!table || !m->pos || !m->nrm || !m->tri) {
        free(table);
        tess_free(m);
        return -3;
    }
    for (p = 0; p < npatches; p++)
        add_patch(m, table, size - 1, pts + p * 16, n);
    normalize(m);
    free(table);
    return 0;
}

void tess_free(tess_mesh *m)
{
    free(m->pos);
    free(m->nrm);
    free(m->tri);
    memset(m, 0, sizeof *m);
}
