/* check_cull.c: runs the README's C example (cull.c) on a BEZ model from eyes around it, and
 * checks its share of culled patches and its classes against world-space classification. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include "bezfile.h" /* bench/bezfile.c */
#define WORLD_IMPLEMENTATION
#include "world.h" /* ptpgen --degree 3 --target c --space world --prefix world_ */
#define CERT_IMPLEMENTATION
#include "cert.h" /* the same with --certified --prefix cert_ */

#define EYES 8

size_t cull_patches(const float (*world)[4], size_t count, const float view[16],
                    const float proj[16], float (*clip)[4], unsigned char *cls);

/* Reads a BEZ file of bicubic patches (bench/bezfile.c) into *pts (16 points (x, y, z, 1) a
 * patch, patch-major). Returns the patch count, or 0 after printing why on stderr. */
static size_t read_bez(const char *path, float (**pts)[4])
{
    bez_file m;
    char err[512];
    size_t n;
    if (bez_file_read(&m, path, err, sizeof err)) {
        fprintf(stderr, "check_cull: %s\n", err);
        return 0;
    }
    n = m.npatches;
    if ((*pts = malloc(n * 16 * sizeof **pts)))
        for (size_t i = 0; i < n * 16; i++)
            for (int c = 0; c < 4; c++)
                (*pts)[i][c] = c < 3 ? (float)m.v[m.idx[i / 16][i % 16]][c] : 1.0f;
    bez_file_free(&m);
    return *pts ? n : 0;
}

/* view = an OpenGL look-at matrix (column-major) from eye to center; proj = gluPerspective
 * (60 degrees, square, near and far planes at d - r and d + r for eye distance d). */
static void camera(float view[16], float proj[16], const double eye[3], const double center[3],
                   double r)
{
    double f[3], s[3], u[3], up[3] = {0, 0, 1}, d = 0, len = 0;
    for (int k = 0; k < 3; k++)
        d += (center[k] - eye[k]) * (center[k] - eye[k]);
    d = sqrt(d);
    for (int k = 0; k < 3; k++)
        f[k] = (center[k] - eye[k]) / d;
    if (fabs(f[2]) > 0.9)
        up[1] = 1, up[2] = 0;
    for (int k = 0; k < 3; k++)
        s[k] = f[(k + 1) % 3] * up[(k + 2) % 3] - f[(k + 2) % 3] * up[(k + 1) % 3];
    len = sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
    for (int k = 0; k < 3; k++)
        s[k] /= len;
    for (int k = 0; k < 3; k++)
        u[k] = s[(k + 1) % 3] * f[(k + 2) % 3] - s[(k + 2) % 3] * f[(k + 1) % 3];
    for (int k = 0; k < 16; k++)
        view[k] = proj[k] = 0;
    for (int k = 0; k < 3; k++) {
        view[k * 4 + 0] = (float)s[k];
        view[k * 4 + 1] = (float)u[k];
        view[k * 4 + 2] = (float)-f[k];
        view[12] -= (float)(s[k] * eye[k]);
        view[13] -= (float)(u[k] * eye[k]);
        view[14] += (float)(f[k] * eye[k]);
    }
    view[15] = 1;
    double n = d - r, fa = d + r, t = sqrt(3.0) /* cot 30 degrees */;
    proj[0] = proj[5] = (float)t;
    proj[10] = (float)((fa + n) / (n - fa));
    proj[11] = -1;
    proj[14] = (float)(2 * fa * n / (n - fa));
}

int main(int argc, char **argv)
{
    float (*pts)[4] = NULL, (*clip)[4], view[16], proj[16];
    size_t n = argc == 3 ? read_bez(argv[1], &pts) : 0, views = 0, culled = 0, world = 0;
    size_t decided = 0, differ = 0, differ_plain = 0;
    double lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
    double center[3], r = 0;
    if (!n) {
        fprintf(stderr, "usage: check_cull MODEL.bez NAME (a readable BEZ file of bicubic patches)\n");
        return 2;
    }
    unsigned char *cls = malloc(n), *wcls = malloc(n), *ccls = malloc(n);
    clip = malloc(n * 16 * sizeof *clip);
    for (size_t i = 0; i < n * 16; i++)
        for (int k = 0; k < 3; k++)
            lo[k] = fmin(lo[k], pts[i][k]), hi[k] = fmax(hi[k], pts[i][k]);
    for (int k = 0; k < 3; k++)
        center[k] = (lo[k] + hi[k]) / 2, r += (hi[k] - lo[k]) * (hi[k] - lo[k]) / 4;
    r = sqrt(r);
    for (int e = 0; e < EYES; e++) { /* eyes spread over a sphere at 3 radii */
        double z = 1 - (2 * e + 1) / (double)EYES, phi = 2.39996 * e, eye[3];
        eye[0] = center[0] + 3 * r * sqrt(1 - z * z) * cos(phi);
        eye[1] = center[1] + 3 * r * sqrt(1 - z * z) * sin(phi);
        eye[2] = center[2] + 3 * r * z;
        float weye[4] = {(float)eye[0], (float)eye[1], (float)eye[2], 1};
        camera(view, proj, eye, center, r);
        culled += cull_patches((const float (*)[4])pts, n, view, proj, clip, cls);
        world_classify_batch((const float (*)[4])pts, n, weye, wcls);
        cert_classify_batch((const float (*)[4])pts, n, weye, ccls);
        for (size_t p = 0; p < n; p++) {
            world += wcls[p] == WORLD_BACK;
            differ_plain += wcls[p] != cls[p];
            decided += ccls[p] != CERT_SILHOUETTE;
            differ += ccls[p] != CERT_SILHOUETTE && ccls[p] != cls[p];
        }
        views += n;
    }
    double share = 100.0 * (double)culled / (double)views;
    int bad = share < 30 || share > 60 || differ || differ_plain * 1000 > views;
    printf("%s - %s culls %.2f%% of %zu patch-views (between 30%% and 60%%); world space culls "
           "%.2f%%; classes differ from certified world space on %zu of the %zu it decides, from "
           "plain world space on %zu (at most 0.1%%)\n",
           bad ? "not ok" : "ok", argv[2], share, views, 100.0 * (double)world / (double)views,
           differ, decided, differ_plain);
    free(pts), free(clip), free(cls), free(wcls), free(ccls);
    return bad;
}
