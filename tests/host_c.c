/* host_c.c: runs an emitted C header (--target c) over patch sets and checks it with kref
 * (tests/test_kernels.sh).
 *
 * Built per header: cc -include HEADER -D<PREFIX>IMPLEMENTATION -DPFX=<prefix> -DUPFX=<PREFIX> ...
 * C and C++ alike (c++ -x c++ host_c.c -x none libptptest.a): the header is used from both. */
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

/* The comparisons over all sets, how often classify_batch or classify_soa differs from
 * classify, and how often classify is not the class of values() under the rule. */
typedef struct {
    const kref_args *o;
    kref_result classify, batch, planes;
    int paths_differ;
    size_t values_differ, patches;
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
    for (p = 0; p < s->count; p++) {
        const float(*cp)[4] = (const float(*)[4])s->cp + p * (size_t)ref->K;
        size_t x;
        int exact;
        cls[p] = FN(classify)(cp, s->eye);
        FN(values)(cp, s->eye, d + p * L);
        exact = kref_exact_class(s, p, ref->rule);
        r->values_differ += (size_t)class_not_of_values(v, cls[p], d + p * L, ref->L, ref, exact);
        if (s->exact && p % KREF_EXACT_SAMPLE)
            continue; /* kref_check reads the values of exact sets on this sample only */
        FN(planes)(cp, t);
        for (x = 0; x < L; x++)
            dp[p * L + x] = ref->space == KREF_WORLD
                                ? s->eye[0] * t[x][0] + s->eye[1] * t[x][1] +
                                      s->eye[2] * t[x][2] + s->eye[3] * t[x][3]
                                : s->eye[2] * t[x][2];
    }
    r->patches += s->count;
    FN(classify_batch)((const float(*)[4])s->cp, s->count, s->eye, batch);
    for (p = 0; p < s->count; p++)
        for (k = 0; k < (size_t)ref->K * 4; k++)
            soa[k * stride + p] = ((const float *)s->cp)[p * (size_t)ref->K * 4 + k];
    FN(classify_soa)(soa, stride, s->count, s->eye, soa_cls);
    for (p = 0; p < s->count; p++) /* the indexed patches in reverse order: patch p is the set's last - p */
        for (k = 0; k < (size_t)ref->K; k++)
            ix[p * (size_t)ref->K + k] = (uint32_t)((s->count - 1 - p) * (size_t)ref->K + k);
    FN(classify_indexed)((const float(*)[4])s->cp, ix, s->count, s->eye, idx_cls);
    for (p = 0; p < s->count; p++)
        r->paths_differ += (batch[p] != cls[p]) + (soa_cls[p] != cls[p]) +
                           (idx_cls[s->count - 1 - p] != cls[p]);
    kref_check(&r->classify, ref, s, cls, d);
    for (p = 0; p < s->count; p++)
        cls[p] = batch[p];
    kref_check(&r->batch, ref, s, cls, NULL);
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
