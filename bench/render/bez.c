/* bez.c: a BEZ model for the renderer: bench/bezfile.c's patches with their points rounded to
 * float as the GPU sees them, and their bounding sphere. */
#include "bez.h"
#include "bezfile.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The bounding sphere about the centre of the box of all points. */
static void bound(bez_model *m)
{
    double lo[3], hi[3], r2 = 0;
    size_t n = m->npatches * 16;
    for (int c = 0; c < 3; c++)
        lo[c] = hi[c] = m->pts[c];
    for (size_t k = 0; k < n; k++)
        for (int c = 0; c < 3; c++) {
            lo[c] = fmin(lo[c], m->pts[k * 3 + c]);
            hi[c] = fmax(hi[c], m->pts[k * 3 + c]);
        }
    for (int c = 0; c < 3; c++)
        m->center[c] = 0.5 * (lo[c] + hi[c]);
    for (size_t k = 0; k < n; k++) {
        double d2 = 0;
        for (int c = 0; c < 3; c++)
            d2 += (m->pts[k * 3 + c] - m->center[c]) * (m->pts[k * 3 + c] - m->center[c]);
        r2 = fmax(r2, d2);
    }
    m->radius = sqrt(r2);
}

int bez_read(bez_model *m, const char *path, char *err, size_t errsz)
{
    bez_file f;
    memset(m, 0, sizeof *m);
    if (bez_file_read(&f, path, err, errsz))
        return -1;
    m->npatches = f.npatches;
    if (!(m->pts = malloc(m->npatches * 16 * 3 * sizeof *m->pts))) {
        snprintf(err, errsz, "%s: out of memory for %zu patches", path, f.npatches);
        bez_file_free(&f);
        return -1;
    }
    for (size_t k = 0; k < m->npatches * 16; k++)
        for (int c = 0; c < 3; c++)
            m->pts[k * 3 + c] = (float)f.v[f.idx[k / 16][k % 16]][c];
    bez_file_free(&f);
    bound(m);
    return 0;
}

void bez_free(bez_model *m)
{
    free(m->pts);
    m->pts = NULL;
    m->npatches = 0;
}
