/* dense_mesh.c: the degree-1 world-space header's classify_mesh and classify_clusters on a dense
 * triangle mesh (a BEZ model tessellated by bench/tess.c) from many eyes, against exact signs.
 *
 * Built around `ptpgen --domain triangle --degree 1 --target c --space world --prefix dm_` (any
 * --coordinates), included with -include and DM_IMPLEMENTATION (tests/test_mesh.sh):
 *   dense_mesh MODEL.bez N EYES SEED NAME
 * tessellates MODEL at N x N quads a patch, puts EYES eyes at 1.2 to 5 bounding radii, and
 * reports, as TAP lines, the triangles called back whose exact value is > 0 (front-facing: unsafe)
 * or 0 (edge-on), those called front whose exact value is <= 0, and the clusters of 64 called back
 * with a triangle whose exact value is > 0. Exit 1 when one is unsafe. */
#include "bezfile.h"
#include "check.h"
#include "exact.h"
#include "tess.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

/* The triangles of one cluster (classify_clusters). */
#define DM_CLUSTER 64

/* The next of a 64-bit LCG's uniforms in [0, 1). */
static double uniform(uint64_t *s)
{
    *s = *s * 6364136223846793005u + 1442695040888963407u;
    return (double)(*s >> 11) * 0x1p-53;
}

/* The exact sign of triangle t's plane seen from eye: a double evaluation where its error bound
 * decides (every difference, product and sum rounded once: 8 roundings of the monomials' sum),
 * else exact_values on the header's own term. */
static int exact_sign_of(const float (*v)[4], const uint32_t *ix, const float eye[4])
{
    const float *p0 = v[ix[0]], *p1 = v[ix[1]], *p2 = v[ix[2]];
    double a[3], b[3], e[3], n[3], m[3], d = 0, mag = 0;
    int c;
    for (c = 0; c < 3; c++) {
        a[c] = (double)p1[c] - p0[c];
        b[c] = (double)p2[c] - p0[c];
        e[c] = (double)eye[c] - p0[c];
    }
    for (c = 0; c < 3; c++) {
        int i = (c + 1) % 3, j = (c + 2) % 3;
        n[c] = a[i] * b[j] - a[j] * b[i];
        m[c] = fabs(a[i] * b[j]) + fabs(a[j] * b[i]);
        d += e[c] * n[c];
        mag += fabs(e[c]) * m[c];
    }
    if (fabs(d) > 16 * 0x1p-53 * mag)
        return (d > 0) - (d < 0);
    {
        const float b3[3][3] = {{p0[0], p0[1], p0[2]}, {p1[0], p1[1], p1[2]}, {p2[0], p2[1], p2[2]}};
        const unsigned short idx[1][4] = {{dm_term_idx[0][0], dm_term_idx[0][1], dm_term_idx[0][2],
                                           dm_term_idx[0][3]}};
        const int w[1] = {(int)dm_term_wgt[0]};
        exact_int x;
        if (exact_values(b3, 3, eye, 1, idx, w, 1, &x) != 0)
            return 2; /* cannot happen for finite data: counted as unsafe */
        return exact_sign(&x);
    }
}

int main(int argc, char **argv)
{
    bez_file m;
    tess_mesh t;
    char err[256];
    size_t p, k, front_back = 0, zero_back = 0, back_front = 0, cluster_bad = 0, calls[3] = {0};
    uint64_t seed;
    int n, neyes, e, c;
    if (argc != 6)
        return fprintf(stderr, "usage: dense_mesh MODEL.bez N EYES SEED NAME\n"), 2;
    n = atoi(argv[2]), neyes = atoi(argv[3]), seed = strtoull(argv[4], NULL, 10);
    if (bez_file_read(&m, argv[1], err, sizeof err))
        return fprintf(stderr, "dense_mesh: %s\n", err), 2;
    double (*pts)[3] = malloc(m.npatches * 16 * sizeof *pts), lo[3], hi[3], ctr[3], rad = 0;
    for (p = 0; p < m.npatches; p++)
        for (k = 0; k < 16; k++)
            for (c = 0; c < 3; c++)
                pts[p * 16 + k][c] = m.v[m.idx[p][k]][c];
    if (!pts || tess_bicubic(&t, (const double (*)[3])pts, m.npatches, n) != 0)
        return fprintf(stderr, "dense_mesh: cannot tessellate %s at %d\n", argv[1], n), 2;
    float (*v)[4] = malloc(t.nverts * sizeof *v);
    unsigned char *cls = malloc(t.ntris), *ccls = malloc(t.ntris / DM_CLUSTER + 1);
    for (c = 0; c < 3; c++)
        lo[c] = hi[c] = t.pos[0][c];
    for (k = 0; k < t.nverts; k++)
        for (c = 0; c < 4; c++) {
            v[k][c] = c < 3 ? (float)t.pos[k][c] : 1.0f;
            if (c < 3)
                lo[c] = fmin(lo[c], t.pos[k][c]), hi[c] = fmax(hi[c], t.pos[k][c]);
        }
    for (c = 0; c < 3; c++)
        ctr[c] = (lo[c] + hi[c]) / 2, rad += (hi[c] - lo[c]) * (hi[c] - lo[c]) / 4;
    rad = sqrt(rad);
    for (e = 0; e < neyes; e++) {
        double dist = rad * (1.2 + 3.8 * uniform(&seed)), z = 2 * uniform(&seed) - 1;
        double phi = 6.283185307179586 * uniform(&seed), r = sqrt(1 - z * z);
        const float eye[4] = {(float)(ctr[0] + dist * r * cos(phi)), (float)(ctr[1] + dist * r * sin(phi)),
                              (float)(ctr[2] + dist * z), 1.0f};
        size_t nc = (t.ntris + DM_CLUSTER - 1) / DM_CLUSTER;
        dm_classify_mesh((const float (*)[4])v, &t.tri[0][0], t.ntris, eye, cls);
        dm_classify_clusters((const float (*)[4])v, &t.tri[0][0], t.ntris, DM_CLUSTER, eye, ccls);
        for (k = 0; k < t.ntris; k++) {
            calls[cls[k] < 3 ? cls[k] : 2]++;
            if (cls[k] == DM_BACK || cls[k] == DM_FRONT) {
                int s = exact_sign_of((const float (*)[4])v, t.tri[k], eye);
                if (cls[k] == DM_BACK)
                    front_back += s > 0, zero_back += s == 0;
                else
                    back_front += s <= 0;
                if (cls[k] == DM_BACK && s > 0 && ccls[k / DM_CLUSTER] == DM_BACK)
                    cluster_bad++;
            }
        }
        for (k = 0; k < nc; k++) /* a back cluster has only back triangles */
            if (ccls[k] == DM_BACK)
                for (p = k * DM_CLUSTER; p < t.ntris && p < (k + 1) * DM_CLUSTER; p++)
                    cluster_bad += cls[p] != DM_BACK;
    }
    printf("# %s: %zu triangles (%s at %d x %d a patch), %d eyes: front %zu, back %zu, silhouette %zu\n",
           argv[5], t.ntris, argv[1], n, n, neyes, calls[0], calls[1], calls[2]);
    printf("# %s: called back with an exact value > 0: %zu (in a back cluster: %zu), = 0: %zu; called "
           "front with one <= 0: %zu\n", argv[5], front_back, cluster_bad, zero_back, back_front);
    check(front_back == 0 && cluster_bad == 0, argv[5], "%zu front-facing triangles called back, %zu "
          "in back clusters", front_back, cluster_bad);
    free(pts);
    free(v);
    free(cls);
    free(ccls);
    tess_free(&t);
    bez_file_free(&m);
    return front_back || cluster_bad;
}
