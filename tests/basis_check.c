/* basis_check.c: the C header's input forms against its default on exact data. Small-integer
 * points (and w0 a power of 2) keep every conversion and shift exact, so the headers must agree
 * bit for bit:
 *   --order v-major on the transposed points      = the default on the points;
 *   --basis bspline on B-spline vertices          = --coordinates absolute on the Bezier points
 *                                                   times 36 of the vertices moved to vertex 0,
 *                                                   with the eye moved alike (computed here);
 *   --basis bspline --order v-major, transposed   = --basis bspline;
 *   classify_indexed_boundary, random masks       = classify on the vertices extrapolated here
 *                                                   (2 p1 - p2), in both orders.
 * Built around five bicubic headers of one space and rule (tests/test_basis.sh): prefixes bz_
 * (default), vz_ (v-major), bs_ (B-spline), vs_ (B-spline, v-major), ba_ (absolute coordinates),
 * with -DWORLD for world space:
 *   basis_check COUNT SEED NAME */
#include "check.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The next of a 64-bit LCG's integers in [lo, hi]. */
static int integer(uint64_t *s, int lo, int hi)
{
    *s = *s * 6364136223846793005u + 1442695040888963407u;
    return lo + (int)((*s >> 33) % (uint64_t)(hi - lo + 1));
}

/* 6 times the uniform cubic B-spline-to-Bezier map, row r. */
static const int bspline_map[4][4] = {{1, 4, 1, 0}, {0, 4, 2, 0}, {0, 2, 4, 0}, {0, 1, 4, 1}};

/* out = in with point (i, j) moved from i * 4 + j to j * 4 + i. */
static void transpose(float out[16][4], const float in[16][4])
{
    int i, j;
    for (i = 0; i < 4; i++)
        for (j = 0; j < 4; j++)
            memcpy(out[j * 4 + i], in[i * 4 + j], sizeof out[0]);
}

/* b = the Bezier points of the B-spline vertices p times 36 (exact for small dyadic p). */
static void to_bezier(float b[16][4], const float p[16][4])
{
    int i, j, a, c, k;
    for (i = 0; i < 4; i++)
        for (j = 0; j < 4; j++)
            for (c = 0; c < 4; c++) {
                double s = 0;
                for (a = 0; a < 4; a++)
                    for (k = 0; k < 4; k++)
                        s += bspline_map[i][a] * bspline_map[j][k] * (double)p[a * 4 + k][c];
                b[i * 4 + j][c] = (float)s;
            }
}

/* q = p moved to point 0 as the headers' patch-local coordinates move it (x + o w with
 * o = -x0 / w0; clip space: x and y), and the eye l alike (world space: e + o e3); exact when
 * w0 is a power of 2. */
static void to_local(float q[16][4], float l[4], const float p[16][4], const float eye[4])
{
    int k, c, n = eye[3] != 0 ? 3 : 2;
    memcpy(q, p, sizeof(float[16][4]));
    memcpy(l, eye, sizeof(float[4]));
    for (c = 0; c < n; c++) {
        float o = -p[0][c] / p[0][3];
        for (k = 0; k < 16; k++)
            q[k][c] = p[k][c] + o * p[k][3];
        l[c] = eye[c] + o * eye[3];
    }
}

/* The vertices beyond edge bit b (v = 0, u = 1, v = 1, u = 0) of p (u-major) become 2 p1 - p2. */
static void extrapolate(float p[16][4], unsigned mask)
{
    int b, i, s, c;
    for (b = 0; b < 4; b++)
        for (i = 0; mask >> b & 1 && i < 4; i++)
            for (c = 0; c < 4; c++) {
                int k[3];
                for (s = 0; s < 3; s++) /* (i along u, j along v) of the edge's vertex i, s inward */
                    k[s] = b == 0 ? i * 4 + s : b == 1 ? (3 - s) * 4 + i : b == 2 ? i * 4 + 3 - s : s * 4 + i;
                p[k[0]][c] = 2 * p[k[1]][c] - p[k[2]][c];
            }
}

/* BATCH patches a classify_indexed_boundary call. */
#define BATCH 37

/* 1 when header A on a with eye ea and header B on b with eye eb give bitwise equal values and
 * equal classes. */
#define SAME(A, B, a, ea, b, eb)                                                                \
    (A##values((const float(*)[4])(a), ea, da), B##values((const float(*)[4])(b), eb, db),     \
     !memcmp(da, db, sizeof da) &&                                                             \
         A##classify((const float(*)[4])(a), ea) == B##classify((const float(*)[4])(b), eb))

int main(int argc, char **argv)
{
    long count = argc > 1 ? atol(argv[1]) : 1000, n, bad[4] = {0};
    uint64_t seed = argc > 2 ? strtoull(argv[2], NULL, 10) : 1;
    const char *name = argc > 3 ? argv[3] : "basis";
    char label[4][256];
    static float vs[BATCH * 16][4], vt[BATCH * 16][4], ext[BATCH * 16][4];
    static uint32_t idx[BATCH * 16];
    unsigned char mask[BATCH], cs[BATCH];
    float p[16][4], t[16][4], q[16][4], b[16][4], da[64], db[64], eye[4], l[4];
    long bad_masks = 0;
    int k, c;
    for (n = 0; n < count; n++) {
        for (k = 0; k < 16; k++) /* a bumpy grid of small integers, w 1 (clip space 1 to 4) */
            for (c = 0; c < 4; c++)
                p[k][c] = c == 3 ? 1.0f : (float)(8 * (c == 0 ? k / 4 : c == 1 ? k % 4 : 0) +
                                                  integer(&seed, -6, 6));
#ifndef WORLD
        for (k = 0; k < 16; k++) {
            int w = k ? integer(&seed, 1, 4) : 1 << integer(&seed, 0, 2);
            for (c = 0; c < 4; c++)
                p[k][c] *= (float)w;
        }
        eye[0] = eye[1] = eye[3] = 0, eye[2] = (float)(integer(&seed, 0, 1) ? 1 : -1);
#else
        for (c = 0; c < 3; c++)
            eye[c] = (float)integer(&seed, -60, 60);
        eye[3] = 1;
#endif
        transpose(t, (const float(*)[4])p);
        to_local(q, l, (const float(*)[4])p, eye);
        to_bezier(b, (const float(*)[4])q);
        bad[0] += !SAME(vz_, bz_, t, eye, p, eye);
        bad[1] += !SAME(bs_, ba_, p, eye, b, l);
        bad[2] += !SAME(vs_, bs_, t, eye, p, eye);
        /* the batch's patch n % BATCH: its vertices (u-major and v-major), a mask and the
         * extrapolated copy; when the batch is full, all against this patch's eye */
        k = (int)(n % BATCH);
        memcpy(vs[k * 16], p, sizeof p);
        memcpy(vt[k * 16], t, sizeof t);
        mask[k] = (unsigned char)integer(&seed, 0, 15);
        extrapolate(p, mask[k]);
        memcpy(ext[k * 16], p, sizeof p);
        if (k == BATCH - 1) {
            unsigned char got[2][BATCH];
            for (c = 0; c < BATCH * 16; c++)
                idx[c] = (uint32_t)c;
            for (c = 0; c < BATCH; c++)
                cs[c] = (unsigned char)bs_classify((const float(*)[4])ext[c * 16], eye);
            bs_classify_indexed_boundary((const float(*)[4])vs, idx, mask, BATCH, eye, got[0]);
            vs_classify_indexed_boundary((const float(*)[4])vt, idx, mask, BATCH, eye, got[1]);
            bad_masks += memcmp(got[0], cs, BATCH) != 0 || memcmp(got[1], cs, BATCH) != 0;
        }
    }
    bad[3] = bad_masks;
    snprintf(label[0], sizeof label[0], "%s: --order v-major on transposed points = the default (%ld patches)", name, count);
    snprintf(label[1], sizeof label[1], "%s: --basis bspline = --coordinates absolute on 36 times the Bezier points in the local frame (%ld patches)", name, count);
    snprintf(label[2], sizeof label[2], "%s: --basis bspline --order v-major on transposed vertices = --basis bspline (%ld patches)", name, count);
    snprintf(label[3], sizeof label[3], "%s: classify_indexed_boundary with random masks = classify on the extrapolated vertices, both orders (%ld batches)", name, count / BATCH);
    for (k = 0; k < 4; k++)
        check(bad[k] == 0, label[k], k < 3 ? "%ld patches differ" : "%ld batches differ", bad[k]);
    return check_failed_count != 0;
}
