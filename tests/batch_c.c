/* batch_c.c: classify_batch's transposition check: classify_batch and classify_soa against
 * classify, on near-planar patches (front and back, so that a misplaced coordinate shows). */
/* tests/test_cli.sh builds it with -include HEADER -D<PREFIX>IMPLEMENTATION -DPFX=<prefix>
 * -DUPFX=<PREFIX>, quads or triangles; counts 1 to 297 cover whole tiles, partial blocks and
 * tails. It prints "ok N patches (front F, back B)" or "FAIL M of N differ", exiting 1 on a
 * difference. */
#include <stdio.h>
#include <stdlib.h>

#define CAT2(a, b) a##b
#define CAT(a, b) CAT2(a, b)
#define FN(name) CAT(PFX, name)
#define NP CAT(UPFX, POINTS)

/* A uniform float in [-1, 1) from the state s. */
static float uni(unsigned long long *s)
{
    *s = *s * 6364136223846793005ull + 1442695040888963407ull;
    return (float)((*s >> 40) % 2001) / 1000.0f - 1.0f;
}

/* (u, v) of point k: the quad grid (d points a side) or the triangle's points of degree e in
 * descending (i, j) order, at (i / e, j / e). */
static void domain_point(unsigned k, float *u, float *v)
{
    unsigned d = 1, e = 0, i, j, n = 0;
    while ((d + 1) * (d + 1) <= NP)
        d++;
    if (d * d == NP) {
        *u = (float)(k / d) / (float)(d - 1);
        *v = (float)(k % d) / (float)(d - 1);
        return;
    }
    while ((e + 1) * (e + 2) / 2 < NP)
        e++;
    for (i = e + 1; i-- > 0;)
        for (j = e - i + 1; j-- > 0;)
            if (n++ == k)
                *u = (float)i / (float)e, *v = (float)j / (float)e;
}

/* count patches into cp: each a random affine image of the domain at depth w about 2 (clip
 * space, z = w / 2), jittered by 0.001; every seventh by 0.5 (silhouette). */
static void make_patches(float (*cp)[4], size_t count, unsigned long long *s)
{
    size_t p;
    unsigned k, c;
    for (p = 0; p < count; p++) {
        float a[6];
        for (c = 0; c < 6; c++)
            a[c] = uni(s);
        for (k = 0; k < NP; k++) {
            float u = 0.0f, v = 0.0f, w = 2.0f + 0.1f * a[0], *q = cp[p * NP + k];
            domain_point(k, &u, &v);
            q[0] = (a[0] * u + a[1] * v + 0.1f * a[4]) * w;
            q[1] = (a[2] * u + a[3] * v + 0.1f * a[5]) * w;
            q[2] = 0.5f * w;
            q[3] = w;
            for (c = 0; c < 4; c++)
                q[c] += (p % 7 == 0 ? 0.5f : 0.001f) * uni(s);
        }
    }
}

int main(void)
{
    const float eye[4] = {0.0f, 0.0f, 1.0f, 0.0f};
    unsigned long long s = 12345;
    size_t count, p, bad = 0, total = 0, cls[3] = {0, 0, 0};
    for (count = 1; count < 300; count += 37) {
        float (*cp)[4] = (float (*)[4])malloc(count * NP * sizeof *cp);
        float *soa = (float *)malloc(count * NP * 4 * sizeof *soa);
        unsigned char *a = (unsigned char *)malloc(count), *b = (unsigned char *)malloc(count);
        unsigned k, c;
        if (!cp || !soa || !a || !b)
            return 2;
        make_patches(cp, count, &s);
        for (p = 0; p < count; p++)
            for (k = 0; k < NP; k++)
                for (c = 0; c < 4; c++)
                    soa[(k * 4 + c) * count + p] = cp[p * NP + k][c];
        FN(classify_batch)((const float (*)[4])cp, count, eye, a);
        FN(classify_soa)(soa, count, count, eye, b);
        for (p = 0; p < count; p++) {
            unsigned one = FN(classify)((const float (*)[4])(cp + p * NP), eye);
            bad += a[p] != one || b[p] != one;
            cls[one < 3 ? one : 2]++;
            total++;
        }
        free(cp);
        free(soa);
        free(a);
        free(b);
    }
    if (bad)
        printf("FAIL %zu of %zu differ\n", bad, total);
    else
        printf("ok %zu patches (front %zu, back %zu)\n", total, cls[0], cls[1]);
    return bad != 0;
}
