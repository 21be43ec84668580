/* cert_look.c: `make cert-look`: how often the certified C header's float lanes leave a patch to
 * its second look in double (certify64), and how many patches it culls, with patch-local and
 * with absolute coordinates, in world and in clip space, over BEZ models.
 *
 * Built around four certified bicubic headers (Makefile: prefixes cl_wl_ world local, cl_wa_
 * world absolute, cl_cl_ clip local, cl_ca_ clip absolute), included with -include:
 *   cert_look [--eyes N] MODEL.bez...
 * The eyes (default 100) lie at 2 to 5 bounding radii around each model's box; clip space looks
 * from each at the box's centre through an OpenGL perspective (alpha > 0). */
#include "bezfile.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* A header's lanes (static in the same translation unit: class 3 where only the plain signs
 * decide, which classify_soa then hands to certify64) and classify_soa. */
typedef void (*lanes_fn)(const float *, size_t, size_t, const float *, unsigned char *);
typedef void (*soa_fn)(const float *, size_t, size_t, const float *, unsigned char *);

/* The variants in the table's order: world local, world absolute, clip local, clip absolute. */
static const lanes_fn lanes[4] = {cl_wl_lanes, cl_wa_lanes, cl_cl_lanes, cl_ca_lanes};
static const soa_fn soa[4] = {cl_wl_classify_soa, cl_wa_classify_soa, cl_cl_classify_soa,
                              cl_ca_classify_soa};

/* The next of a 64-bit LCG's uniforms in [0, 1). */
static double uniform(uint64_t *s)
{
    *s = *s * 6364136223846793005u + 1442695040888963407u;
    return (double)(*s >> 11) * 0x1p-53;
}

/* A model's patches in structure-of-arrays order (w = 1), its box's centre and radius. */
typedef struct {
    size_t n;
    float *world, *clip;
    double ctr[3], rad;
} model;

/* Reads path into *m. Returns 0, or -1 with the reason on stderr. */
static int model_read(model *m, const char *path)
{
    bez_file b;
    char err[256];
    double lo[3], hi[3];
    size_t p, k;
    int c;
    if (bez_file_read(&b, path, err, sizeof err))
        return fprintf(stderr, "cert_look: %s\n", err), -1;
    m->n = b.npatches;
    m->world = malloc(m->n * 64 * sizeof *m->world);
    m->clip = malloc(m->n * 64 * sizeof *m->clip);
    if (!m->world || !m->clip) {
        bez_file_free(&b);
        return fprintf(stderr, "cert_look: out of memory\n"), -1;
    }
    for (c = 0; c < 3; c++)
        lo[c] = hi[c] = b.v[0][c];
    for (k = 0; k < b.nverts; k++)
        for (c = 0; c < 3; c++)
            lo[c] = fmin(lo[c], b.v[k][c]), hi[c] = fmax(hi[c], b.v[k][c]);
    m->rad = 0;
    for (c = 0; c < 3; c++)
        m->ctr[c] = (lo[c] + hi[c]) / 2, m->rad += (hi[c] - lo[c]) * (hi[c] - lo[c]) / 4;
    m->rad = sqrt(m->rad);
    for (p = 0; p < m->n; p++)
        for (k = 0; k < 16; k++)
            for (c = 0; c < 4; c++)
                m->world[(k * 4 + c) * m->n + p] = c < 3 ? (float)b.v[b.idx[p][k]][c] : 1.0f;
    bez_file_free(&b);
    return 0;
}

/* Writes m's points in clip space for the eye looking at m's centre (view: right s, up u,
 * backward -f; an OpenGL perspective with near 0.1 radii, far beyond the model, focal length
 * 1.5) into m->clip, and alpha = 2 far near / (far - near) into *alpha. */
static void to_clip(model *m, const float eye[3], float *alpha)
{
    double f[3], up[3] = {0, 0, 1}, s[3], u[3], dist = 0, len = 0, near, far, a;
    size_t p, k;
    int c;
    for (c = 0; c < 3; c++)
        f[c] = m->ctr[c] - eye[c], dist += f[c] * f[c];
    dist = sqrt(dist);
    for (c = 0; c < 3; c++)
        f[c] /= dist;
    if (fabs(f[2]) > 0.99)
        up[1] = 1, up[2] = 0;
    for (c = 0; c < 3; c++)
        s[c] = f[(c + 1) % 3] * up[(c + 2) % 3] - f[(c + 2) % 3] * up[(c + 1) % 3], len += s[c] * s[c];
    for (c = 0; c < 3; c++)
        s[c] /= sqrt(len);
    for (c = 0; c < 3; c++)
        u[c] = s[(c + 1) % 3] * f[(c + 2) % 3] - s[(c + 2) % 3] * f[(c + 1) % 3];
    near = 0.1 * m->rad, far = dist + 2 * m->rad, a = 2 * far * near / (far - near);
    for (p = 0; p < m->n; p++)
        for (k = 0; k < 16; k++) {
            double v[3], x = 0, y = 0, z = 0;
            for (c = 0; c < 3; c++)
                v[c] = m->world[(k * 4 + c) * m->n + p] - (double)eye[c];
            for (c = 0; c < 3; c++)
                x += s[c] * v[c], y += u[c] * v[c], z -= f[c] * v[c];
            m->clip[(k * 4 + 0) * m->n + p] = (float)(1.5 * x);
            m->clip[(k * 4 + 1) * m->n + p] = (float)(1.5 * y);
            m->clip[(k * 4 + 2) * m->n + p] = (float)(-(far + near) / (far - near) * z - a);
            m->clip[(k * 4 + 3) * m->n + p] = (float)(-z);
        }
    *alpha = (float)a;
}

int main(int argc, char **argv)
{
    static const char *const name[4] = {"world, local", "world, absolute", "clip, local",
                                         "clip, absolute"};
    int neyes = 100, i = 1, e, v;
    if (argc > 2 && strcmp(argv[1], "--eyes") == 0)
        neyes = atoi(argv[2]), i = 3;
    if (i >= argc || neyes < 1)
        return fprintf(stderr, "usage: cert_look [--eyes N] MODEL.bez...\n"), 2;
    printf("%-12s %-16s %13s %13s %9s %13s\n", "model", "variant", "patch-views", "second look",
           "share", "culled");
    for (; i < argc; i++) {
        model m;
        uint64_t seed = 7;
        size_t second[4] = {0}, culled[4] = {0}, p;
        unsigned char *cls;
        const char *base = strrchr(argv[i], '/') ? strrchr(argv[i], '/') + 1 : argv[i];
        if (model_read(&m, argv[i]) || !(cls = malloc(m.n)))
            return 1;
        for (e = 0; e < neyes; e++) {
            double dist = m.rad * (2 + 3 * uniform(&seed)), z = 2 * uniform(&seed) - 1;
            double phi = 6.283185307179586 * uniform(&seed), r = sqrt(1 - z * z);
            float eye[4] = {(float)(m.ctr[0] + dist * r * cos(phi)),
                            (float)(m.ctr[1] + dist * r * sin(phi)), (float)(m.ctr[2] + dist * z), 1};
            float clip_eye[4] = {0, 0, 0, 0};
            to_clip(&m, eye, &clip_eye[2]);
            for (v = 0; v < 4; v++) {
                const float *pts = v < 2 ? m.world : m.clip, *at = v < 2 ? eye : clip_eye;
                lanes[v](pts, m.n, m.n, at, cls);
                for (p = 0; p < m.n; p++)
                    second[v] += cls[p] == 3;
                soa[v](pts, m.n, m.n, at, cls);
                for (p = 0; p < m.n; p++)
                    culled[v] += cls[p] < 2;
            }
        }
        for (v = 0; v < 4; v++)
            printf("%-12s %-16s %13zu %13zu %8.3f%% %13zu\n", base, name[v], m.n * (size_t)neyes,
                   second[v], 100.0 * (double)second[v] / ((double)m.n * neyes), culled[v]);
        free(cls);
        free(m.world);
        free(m.clip);
    }
    return 0;
}
