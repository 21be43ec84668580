/* host_alpha.c: checks the bicubic clip-space C header's alpha() on projections stored as glm and
 * DirectXMath store them: clip-space classes with that alpha equal the world-space header's.
 *
 * Built by test_kernels.sh as C and C++: cc -IDIR host_alpha.c libptptest.a, DIR holding the
 * default-named ptp_3x3.h and ptp_3x3_world.h. Usage: host_alpha MODEL.bez... */
#define PTP_3X3_IMPLEMENTATION
#define PTP_3X3_WORLD_IMPLEMENTATION
#include "ptp_3x3.h"
#include "ptp_3x3_world.h"

#include "check.h"
#ifdef __cplusplus
extern "C" {
#endif
#include "kref.h"
#ifdef __cplusplus
}
#endif

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifdef __cplusplus
#define LANGUAGE "C++"
#else
#define LANGUAGE "C"
#endif

enum { GL, VK, VK_REV, DX_LH, DX_RH, DX_REV, GL_ROWS, KINDS };
static const char *const names[KINDS] = {
    "glm::perspective (OpenGL, RH, depth -1..1)",
    "glm perspectiveRH_ZO with proj[1][1] *= -1 (Vulkan)",
    "glm perspectiveRH_ZO(far, near) with proj[1][1] *= -1 (Vulkan, reversed Z)",
    "XMMatrixPerspectiveFovLH (DirectXMath)",
    "XMMatrixPerspectiveFovRH (DirectXMath)",
    "XMMatrixPerspectiveFovLH(far, near) (DirectXMath, reversed Z)",
    "glm::perspective written row by row (ROW_MAJOR)"};

/* proj: the projection of kind as its library stores it (glm: m[c][r] at c * 4 + r; DirectXMath:
 * XMFLOAT4X4 m[r][c] at r * 4 + c for row vectors); *layout: the argument alpha() takes; *lh: the
 * view looks along +z (left-handed). */
static void projection(float proj[16], int *layout, int *lh, int kind, double n, double f)
{
    double t = tan(0.5), a = 1.5, m[4][4] = {{0}};
    int r, c;
    if (kind == VK_REV || kind == DX_REV) { /* reversed Z: near and far swapped */
        double x = n;
        n = f;
        f = x;
    }
    *lh = kind == DX_LH || kind == DX_REV;
    *layout = kind == GL_ROWS ? PTP_3X3_ROW_MAJOR : PTP_3X3_COLUMN_MAJOR;
    if (kind == GL || kind == GL_ROWS || kind == VK || kind == VK_REV) { /* glm: m[column][row] */
        m[0][0] = 1 / (a * t);
        m[1][1] = kind == GL || kind == GL_ROWS ? 1 / t : -1 / t;
        m[2][2] = kind == GL || kind == GL_ROWS ? -(f + n) / (f - n) : f / (n - f);
        m[2][3] = -1;
        m[3][2] = kind == GL || kind == GL_ROWS ? -(2 * f * n) / (f - n) : -(f * n) / (f - n);
    } else { /* DirectXMath: m[row][column], row vectors */
        double h = 1 / t, range = *lh ? f / (f - n) : f / (n - f);
        m[0][0] = h / a;
        m[1][1] = h;
        m[2][2] = range;
        m[2][3] = *lh ? 1 : -1;
        m[3][2] = *lh ? -range * n : range * n;
    }
    for (r = 0; r < 4; r++)
        for (c = 0; c < 4; c++)
            proj[kind == GL_ROWS ? c * 4 + r : r * 4 + c] = (float)m[r][c];
}

/* The set's patches in clip space: cs->cp = P V x, P(r, c) the column-vector projection. */
static void to_clip(kref_set *cs, const kref_set *ws, const float proj[16], int layout, int lh,
                    const double E[3], const double C[3])
{
    double V[16], M[16];
    size_t p;
    int r, c, k;
    kref_look_at(V, E, C, lh);
    for (r = 0; r < 4; r++)
        for (c = 0; c < 4; c++) {
            M[r * 4 + c] = 0;
            for (k = 0; k < 4; k++)
                M[r * 4 + c] += proj[layout == PTP_3X3_ROW_MAJOR ? r * 4 + k : k * 4 + r] * V[k * 4 + c];
        }
    for (p = 0; p < ws->count * 16; p++)
        for (r = 0; r < 4; r++)
            cs->cp[p][r] = (float)(M[r * 4] * ws->cp[p][0] + M[r * 4 + 1] * ws->cp[p][1] +
                                   M[r * 4 + 2] * ws->cp[p][2] + M[r * 4 + 3] * ws->cp[p][3]);
}

/* Adds to differ the patches whose clip and world classes differ where neither reference value is
 * within its float bound of zero, to amb those within it, and to count[] the world classes. */
static void compare(size_t *differ, size_t *amb, size_t count[3], const kref_ref *world,
                    const kref_ref *clip, const kref_set *ws, const kref_set *cs)
{
    double dw[64], bw[64], dc[64], bc[64];
    size_t p;
    for (p = 0; p < ws->count; p++) {
        unsigned w = ptp_3x3_world_classify((const float(*)[4])ws->cp + p * 16, ws->eye);
        unsigned c = ptp_3x3_classify((const float(*)[4])cs->cp + p * 16, cs->eye);
        int i, a = 0;
        count[w]++;
        if (w == c)
            continue;
        kref_values(world, ws, p, dw, bw);
        kref_values(clip, cs, p, dc, bc);
        for (i = 0; i < 64; i++)
            a |= fabs(dw[i]) <= bw[i] || fabs(dc[i]) <= bc[i];
        *amb += a;
        *differ += !a;
    }
}

int main(int argc, char **argv)
{
    kref_ref world, clip;
    ptp_error err;
    int kind, i, e;
    if (kref_init(&world, TP_QUAD, 3, 3, KREF_WORLD, KREF_STRICT, &err) ||
        kref_init(&clip, TP_QUAD, 3, 3, KREF_CLIP, KREF_STRICT, &err))
        return !check(0, "alpha: reference", "%s", err.msg);
    for (kind = 0; kind < KINDS; kind++) {
        size_t differ = 0, amb = 0, flipped = 0, flip_amb = 0, count[3] = {0}, fc[3] = {0};
        char label[300];
        for (i = 1; i < argc; i++) {
            kref_set *sets = kref_model_sets(&world, argv[i], 3, (uint64_t)(kind + 1), &err);
            if (!sets)
                return !check(0, "alpha: model", "%s", err.msg);
            for (e = 0; e < 3; e++) {
                kref_set *ws = &sets[e], cs = *ws;
                double E[3], C[3] = {0, 0, 0}, dist = 0;
                float proj[16];
                int layout, lh, c;
                size_t p;
                for (p = 0; p < ws->count * 16; p++)
                    for (c = 0; c < 3; c++)
                        C[c] += ws->cp[p][c] / (double)(ws->count * 16);
                for (c = 0; c < 3; c++) {
                    E[c] = ws->eye[c];
                    dist += (E[c] - C[c]) * (E[c] - C[c]);
                }
                projection(proj, &layout, &lh, kind, 0.05 * sqrt(dist), 4 * sqrt(dist));
                cs.cp = (float(*)[4])malloc(ws->count * 16 * sizeof *cs.cp);
                to_clip(&cs, ws, proj, layout, lh, E, C);
                cs.eye[0] = cs.eye[1] = cs.eye[3] = 0;
                cs.eye[2] = ptp_3x3_alpha(proj, layout);
                compare(&differ, &amb, count, &world, &clip, ws, &cs);
                cs.eye[2] = -cs.eye[2]; /* the other orientation must differ: the check can fail */
                compare(&flipped, &flip_amb, fc, &world, &clip, ws, &cs);
                free(cs.cp);
            }
            kref_free_sets(sets, 3);
        }
        snprintf(label, sizeof label, "alpha (%s): %s: clip space with alpha() classifies %zu patches "
                 "as world space does (%zu ambiguous within the float bound)", LANGUAGE, names[kind],
                 count[0] + count[1] + count[2], amb);
        check(differ == 0 && count[0] && count[1] && flipped > 0, label,
              "%zu differ (front %zu, back %zu, silhouette %zu); with -alpha %zu differ", differ,
              count[0], count[1], count[2], flipped);
    }
    kref_clear(&world);
    kref_clear(&clip);
    return check_exit();
}
