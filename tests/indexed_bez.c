/* indexed_bez.c: writes what tests/host_indexed.c reads for a BEZ model: its vertices (w = 1),
 * its patches' indices, eyes around it and the C header's classify_indexed classes from each.
 * Built with bz.h, a bicubic world-space C header of prefix bz_, and bench/bezfile.c:
 *
 *   indexed_bez MODEL.bez NEYES SEED DIR */
#define BZ_IMPLEMENTATION
#include "bz.h"
#include "bezfile.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

/* Writes n bytes of b to DIR/name; 0, or 1 with a "not ok" line. */
static int put(const char *dir, const char *name, const void *b, size_t n)
{
    char path[1024];
    FILE *f;
    snprintf(path, sizeof path, "%s/%s", dir, name);
    f = fopen(path, "wb");
    if (f && fwrite(b, 1, n, f) == n && fclose(f) == 0)
        return 0;
    printf("not ok - indexed_bez: cannot write %s\n", path);
    return 1;
}

/* A uniform double in [0, 1) from the LCG *s. */
static double next(unsigned long long *s)
{
    *s = *s * 6364136223846793005ull + 1442695040888963407ull;
    return (double)(*s >> 11) / 9007199254740992.0;
}

int main(int argc, char **argv)
{
    bez_file m;
    char err[512];
    size_t k, c, ne = argc == 5 ? strtoul(argv[2], NULL, 10) : 0;
    unsigned long long s = argc == 5 ? strtoull(argv[3], NULL, 10) : 0;
    double lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL}, r = 0;
    if (ne == 0 || bez_file_read(&m, argv[1], err, sizeof err)) {
        printf("not ok - indexed_bez: %s\n", ne ? err : "usage: indexed_bez MODEL.bez NEYES SEED DIR");
        return 1;
    }
    float (*v)[4] = malloc(sizeof *v * m.nverts), (*eyes)[4] = malloc(sizeof *eyes * ne);
    uint32_t *idx = malloc(sizeof *idx * 16 * m.npatches);
    unsigned char *cls = malloc(m.npatches * ne);
    if (!v || !eyes || !idx || !cls)
        return 1;
    for (k = 0; k < m.nverts; k++)
        for (c = 0; c < 4; c++) {
            v[k][c] = c < 3 ? (float)m.v[k][c] : 1.0f;
            lo[c % 3] = fmin(lo[c % 3], m.v[k][c % 3]), hi[c % 3] = fmax(hi[c % 3], m.v[k][c % 3]);
        }
    for (k = 0; k < 16 * m.npatches; k++)
        idx[k] = (uint32_t)m.idx[k / 16][k % 16];
    for (c = 0; c < 3; c++)
        r += (hi[c] - lo[c]) * (hi[c] - lo[c]);
    for (k = 0; k < ne; k++) { /* around the box's center, 0.6 to 3 of its diagonals away */
        double z = 2 * next(&s) - 1, phi = 6.283185307179586 * next(&s), d = sqrt(r) * (0.6 + 2.4 * next(&s));
        eyes[k][0] = (float)((lo[0] + hi[0]) / 2 + d * sqrt(1 - z * z) * cos(phi));
        eyes[k][1] = (float)((lo[1] + hi[1]) / 2 + d * sqrt(1 - z * z) * sin(phi));
        eyes[k][2] = (float)((lo[2] + hi[2]) / 2 + d * z);
        eyes[k][3] = 1.0f;
        bz_classify_indexed((const float(*)[4])v, idx, m.npatches, eyes[k], cls + k * m.npatches);
    }
    return put(argv[4], "vertices", v, sizeof *v * m.nverts) || put(argv[4], "indices", idx, 64 * m.npatches) ||
           put(argv[4], "eyes", eyes, sizeof *eyes * ne) || put(argv[4], "classes", cls, m.npatches * ne);
}
