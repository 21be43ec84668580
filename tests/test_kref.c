/* test_kref.c: checks the clip-space eye convention the kernels document, with the reference.
 * alpha = sign(det Proj) * Proj[2][3] must give the world-space classes: GL, D3D, reversed Z, y flip. */
#include "check.h"
#include "kref.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static uint64_t rng = 12345;

static double uniform(double lo, double hi)
{
    rng = rng * 6364136223846793005u + 1442695040888963407u;
    return lo + (hi - lo) * (double)(rng >> 11) / 9007199254740992.0;
}

/* Projections: 0 OpenGL, 1 Direct3D (z to [0, 1]), 2 Direct3D reversed Z, 3 OpenGL with y
 * negated (Vulkan's clip space with an OpenGL-style matrix). */
static void projection(double P[16], int kind, double n, double f)
{
    memset(P, 0, 16 * sizeof *P);
    P[0] = P[5] = 1.5;
    if (kind == 3)
        P[5] = -1.5;
    if (kind == 0 || kind == 3) {
        P[10] = -(f + n) / (f - n);
        P[11] = -2 * f * n / (f - n);
        P[14] = -1;
    } else {
        P[10] = kind == 1 ? f / (f - n) : -n / (f - n);
        P[11] = kind == 1 ? -f * n / (f - n) : f * n / (f - n);
        P[14] = 1;
    }
}

int main(void)
{
    static const char *const names[] = {"OpenGL", "Direct3D", "Direct3D reversed Z",
                                         "OpenGL-style with Vulkan's y flip"};
    kref_ref world, clip;
    ptp_error err;
    int kind, e, k, c;
    if (kref_init(&world, TP_QUAD, 3, 3, KREF_WORLD, KREF_STRICT, &err) ||
        kref_init(&clip, TP_QUAD, 3, 3, KREF_CLIP, KREF_STRICT, &err))
        return 1;
    for (kind = 0; kind < 4; kind++) {
        size_t compared = 0, differ = 0, w_count[3] = {0};
        int sign_ok = 1;
        for (e = 0; e < 40; e++) {
            kref_set *ws = kref_random_sets(&world, 1, 500, (uint64_t)(1000 * kind + e));
            kref_set cs = *ws;
            double E[3], C[3] = {0, 0, 0}, V[16], P[16], M[16], det, alpha;
            double dw[64], bw[64], dc[64], bc[64];
            size_t p;
            int i, j;
            for (c = 0; c < 3; c++)
                E[c] = uniform(-1, 1) * 8 + (c == 2 ? 12 : 0);
            kref_look_at(V, E, C, kind == 1 || kind == 2);
            projection(P, kind, 1.0, 40.0);
            for (i = 0; i < 4; i++)
                for (j = 0; j < 4; j++) {
                    M[i * 4 + j] = 0;
                    for (k = 0; k < 4; k++)
                        M[i * 4 + j] += P[i * 4 + k] * V[k * 4 + j];
                }
            det = -P[0] * P[5] * P[11] * P[14]; /* det of the projection */
            alpha = det > 0 ? P[11] : -P[11];
            sign_ok &= kind == 0 ? alpha > 0 : alpha < 0; /* as the README's table says */
            for (c = 0; c < 3; c++)
                ws->eye[c] = (float)E[c];
            ws->eye[3] = 1;
            cs.cp = malloc(ws->count * 16 * sizeof *cs.cp);
            for (p = 0; p < ws->count * 16; p++) {
                double x[4];
                for (c = 0; c < 4; c++)
                    x[c] = ws->cp[p][c];
                for (c = 0; c < 4; c++)
                    cs.cp[p][c] = (float)(M[c * 4] * x[0] + M[c * 4 + 1] * x[1] + M[c * 4 + 2] * x[2] +
                                          M[c * 4 + 3] * x[3]);
            }
            cs.eye[0] = cs.eye[1] = cs.eye[3] = 0;
            cs.eye[2] = (float)alpha;
            for (p = 0; p < ws->count; p++) {
                int amb = 0, cw, cc;
                kref_values(&world, ws, p, dw, bw);
                kref_values(&clip, &cs, p, dc, bc);
                for (i = 0; i < 64; i++)
                    amb |= fabs(dw[i]) <= bw[i] || fabs(dc[i]) <= bc[i];
                if (amb)
                    continue;
                cw = kref_classify(dw, 64, KREF_STRICT);
                cc = kref_classify(dc, 64, KREF_STRICT);
                compared++;
                w_count[cw]++;
                differ += cw != cc;
            }
            free(cs.cp);
            kref_free_sets(ws, 1);
        }
        {
            char label[200];
            snprintf(label, sizeof label, "%s projection: clip space with alpha = sign(det P) P[2][3] "
                     "(%s) classifies %zu patches as world space does", names[kind],
                     kind == 0 ? "> 0" : "< 0", compared);
            check(sign_ok && differ == 0 && w_count[0] && w_count[1] && w_count[2], label,
                  "%zu differ (front %zu, back %zu, silhouette %zu)%s", differ, w_count[0], w_count[1],
                  w_count[2], sign_ok ? "" : "; alpha has the other sign");
        }
    }
    kref_clear(&world);
    kref_clear(&clip);
    return check_exit();
}
