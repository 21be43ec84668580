/* host_c.c: runs an emitted C header (--target c) over patch sets and checks it with kref
 * (tests/test_kernels.sh).
 *
 * Built per header: cc -include HEADER -D<PREFIX>IMPLEMENTATION -DPFX=<prefix> -DUPFX=<PREFIX> ...
 * C and C++ alike (c++ -x c++ host_c.c -x none libptptest.a): the header is used from both.
 * -DHOST_BSPLINE (a bicubic --basis bspline header) and -DHOST_VMAJOR (--order v-major): the
 * header reads each set's patches as the B-spline vertices whose Bezier points they are (the
 * inverse map is integral: exact for integer points) or transposed, and only its classes are
 * checked (its values are 36^3 times the Bezier points'). Patches whose vertices are not floats
 * are given silhouette (tests/test_basis.sh). */
#include "host_c.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Nonzero when class c is not the one values d (L of them, from values()) give under the rule:
 * certified, a class other than silhouette must be the rule's, or the exact class exact (-1:
 * unknown), which a second look in double can find where the floats' signs are wrong (far
 * patches). v: L doubles of scratch. */
static int class_not_of_values(double *v, unsigned c, const float *d, int L, const kref_ref *ref,
                               int exact)
{
    int x;
    for (x = 0; x < L; x++)
        v[x] = d[x]; /* exact: the signs, zeros and NaNs are the floats' */
    if (ref->certified)
        return c != MACRO(SILHOUETTE) && (int)c != kref_classify(v, L, ref->rule) &&
               (int)c != exact;
    return (int)c != kref_classify(v, L, ref->rule);
}

#if defined(HOST_BSPLINE) || defined(HOST_VMAJOR)
#define HOST_INPUT 1
#ifdef HOST_VMAJOR
#define HOST_AT(i, j) ((j) * 4 + (i))
#else
#define HOST_AT(i, j) ((i) * 4 + (j))
#endif
/* Coordinate c of vertex (a, b) as the header reads it of Bezier points cp (exact in double). */
static double input_coordinate(const float (*cp)[4], int a, int b, int c)
{
#ifdef HOST_BSPLINE
    /* 6 times the inverse of the uniform cubic B-spline-to-Bezier map (rows (1 4 1 0) / 6 ...) */
    static const int inverse_map[4][4] = {{6, -7, 2, 0}, {0, 2, -1, 0}, {0, -1, 2, 0}, {0, 2, -7, 6}};
    double v = 0;
    int i, j;
    for (i = 0; i < 4; i++)
        for (j = 0; j < 4; j++)
            v += inverse_map[a][i] * inverse_map[b][j] * (double)cp[i * 4 + j][c];
    return v;
#else
    return cp[a * 4 + b][c];
#endif
}

/* in = the 16 points of each patch of s as the header reads them: with HOST_BSPLINE the
 * B-spline vertices (times 36) of the Bezier points, with HOST_VMAJOR point (i, j) at j * 4 + i;
 * lost[p] = 1 where a vertex is not a float. Returns how many patches lost. */
static size_t input_form(float (*in)[4], unsigned char *lost, const kref_set *s)
{
    size_t p, n = 0;
    int a, b, c;
    for (p = 0; p < s->count; p++) {
        const float(*cp)[4] = (const float(*)[4])s->cp + p * 16;
        lost[p] = 0;
        for (a = 0; a < 4; a++)
            for (b = 0; b < 4; b++)
                for (c = 0; c < 4; c++) {
                    double v = input_coordinate(cp, a, b, c);
                    in[p * 16 + HOST_AT(a, b)][c] = (float)v;
                    lost[p] |= (double)(float)v != v;
                }
        n += lost[p];
    }
    return n;
}
#else
#define HOST_INPUT 0
#endif

/* The comparisons over all sets, how often classify_batch or classify_soa differs from
 * classify, and how often classify is not the class of values() under the rule. */
typedef struct {
    const kref_args *o;
    kref_result classify, batch, planes;
    int paths_differ;
    size_t values_differ, patches, lost; /* lost: patches whose input form is not floats */
} results;

/* Runs the header's functions over one set and accumulates into ctx (results); returns 0, or
 * 1 after a "not ok" line when the header's bidegree is not the reference's. */
static int run_set(void *ctx, const kref_ref *ref, const kref_set *s)
{
    results *r = (results *)ctx;
    size_t p, L = (size_t)ref->L;
    if (ref->K != MACRO(POINTS) || ref->L != MACRO(PLANES))
        return !check(0, r->o->label, "the header's bidegree differs from --degree");
    unsigned *cls = (unsigned *)malloc(s->count * sizeof *cls);
    unsigned char *batch = (unsigned char *)malloc(s->count);
    unsigned char *soa_cls = (unsigned char *)malloc(s->count);
    unsigned char *idx_cls = (unsigned char *)malloc(s->count);
    uint32_t *ix = (uint32_t *)calloc(s->count * (size_t)ref->K, sizeof *ix);
    /* the SoA copy, at a stride that is not the count (nor a power of two); zeroed, as gcc
     * cannot see the copy below fill what classify_soa reads */
    size_t stride = s->count + 3, k;
    float *soa = (float *)calloc((size_t)ref->K * 4 * stride, sizeof *soa);
    float *d = (float *)malloc(s->count * L * sizeof *d);
    float *dp = (float *)malloc(s->count * L * sizeof *dp);
    float(*t)[4] = (float(*)[4])malloc(L * sizeof *t);
    double *v = (double *)malloc(L * sizeof *v);
    float(*in)[4] = (float(*)[4])s->cp; /* the points as the header reads them */
    unsigned char *lost = NULL;
#if HOST_INPUT
    in = (float(*)[4])malloc(s->count * 16 * sizeof *in);
    lost = (unsigned char *)malloc(s->count);
    r->lost += input_form(in, lost, s);
#endif
    for (p = 0; p < s->count; p++) {
        const float(*cp)[4] = (const float(*)[4])in + p * (size_t)ref->K;
        size_t x;
        int exact;
        cls[p] = FN(classify)(cp, s->eye);
        FN(values)(cp, s->eye, d + p * L);
        exact = kref_exact_class(s, p, ref->rule);
        r->values_differ += (size_t)class_not_of_values(v, cls[p], d + p * L, ref->L, ref, exact);
        if (HOST_INPUT || (s->exact && p % KREF_EXACT_SAMPLE))
            continue; /* kref_check reads the values of exact sets on this sample only */
        FN(planes)(cp, t);
        for (x = 0; x < L; x++)
            dp[p * L + x] = ref->space == KREF_WORLD
                                ? s->eye[0] * t[x][0] + s->eye[1] * t[x][1] +
                                      s->eye[2] * t[x][2] + s->eye[3] * t[x][3]
                                : s->eye[2] * t[x][2];
    }
    r->patches += s->count;
    FN(classify_batch)((const float(*)[4])in, s->count, s->eye, batch);
    for (p = 0; p < s->count; p++)
        for (k = 0; k < (size_t)ref->K * 4; k++)
            soa[k * stride + p] = ((const float *)in)[p * (size_t)ref->K * 4 + k];
    FN(classify_soa)(soa, stride, s->count, s->eye, soa_cls);
    for (p = 0; p < s->count; p++) /* the indexed patches in reverse order: patch p is the set's last - p */
        for (k = 0; k < (size_t)ref->K; k++)
            ix[p * (size_t)ref->K + k] = (uint32_t)((s->count - 1 - p) * (size_t)ref->K + k);
    FN(classify_indexed)((const float(*)[4])in, ix, s->count, s->eye, idx_cls);
    for (p = 0; p < s->count; p++) {
        r->paths_differ += (batch[p] != cls[p]) + (soa_cls[p] != cls[p]) +
                           (idx_cls[s->count - 1 - p] != cls[p]);
        if (lost && lost[p]) /* not the set's patch: given up */
            cls[p] = batch[p] = MACRO(SILHOUETTE);
    }
    kref_check(&r->classify, ref, s, cls, HOST_INPUT ? NULL : d);
    for (p = 0; p < s->count; p++)
        cls[p] = batch[p];
    kref_check(&r->batch, ref, s, cls, NULL);
    if (!HOST_INPUT)
        kref_check(&r->planes, ref, s, cls, dp);
    free(cls);
    free(batch);
    free(soa_cls);
    free(idx_cls);
    free(ix);
    free(soa);
    free(d);
    free(dp);
    free(t);
    free(v);
    if (lost) {
        free(in);
        free(lost);
    }
    return 0;
}

/* Before the sets: run_set's labels are o's. */
static int ready(void *ctx, const kref_args *o, const kref_ref *ref)
{
    (void)ref;
    ((results *)ctx)->o = o;
    return 0;
}

/* The check lines of all sets; 1 if they all passed. */
static int report(void *ctx, const kref_args *o, const kref_ref *ref)
{
    const results *r = (const results *)ctx;
    char label[200];
    int ok = host_report(&r->classify, o, "classify and values");
    (void)ref;
    ok &= host_report(&r->batch, o, "classify_batch");
    snprintf(label, sizeof label, "%s classify_batch, classify_soa and classify_indexed equal classify on every patch",
             o->label);
    ok &= check(r->paths_differ == 0, label, "they differ %d times", r->paths_differ);
    snprintf(label, sizeof label, "%s classify is the class of values() under the rule on all %zu patches%s",
             o->label, r->patches, o->certified ? " (certified: or silhouette)" : "");
    ok &= check(r->values_differ == 0, label, "it is not on %zu", r->values_differ);
    if (HOST_INPUT) { /* classes only; most patches must be the set's */
        snprintf(label, sizeof label, "%s the input form of %zu of %zu patches is exact in floats",
                 o->label, r->patches - r->lost, r->patches);
        return ok & check(r->lost * 10 <= r->patches, label, "too few");
    }
    return ok & host_report(&r->planes, o, "planes (dotted with the eye)");
}

int main(int argc, char **argv)
{
    static const kref_host host = {"host_c", ready, run_set, report};
    results r;
    int st;
    memset(&r, 0, sizeof r);
    st = kref_host_main(&host, &r, argc, argv);
    return st ? st : check_exit();
}
