/* host_run.c: what the Vulkan and the WebGPU test hosts share: patch sets cut into chunks of one
 * dispatch each, the check that a kernel writes nothing past patch_count, --bench, and the loop. */
#define _POSIX_C_SOURCE 200809L

#include "host_run.h"

#include "check.h"

#include <inttypes.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

/* The largest storage buffer the hosts create (lavapipe's limit). */
#ifndef HOST_MAX_BUFFER
#define HOST_MAX_BUFFER ((uint64_t)128 << 20)
#endif
/* The largest group count along x of one dispatch (lavapipe's limit). */
#ifndef HOST_MAX_GROUPS_X
#define HOST_MAX_GROUPS_X 65535u
#endif

/* The state of a run: the buffers' sizes and the tally of writes past patch_count. */
typedef struct {
    size_t cap;          /* patches the buffers hold (0: none yet) */
    uint64_t cls_words, val_words;
    size_t bad;          /* 32-bit words written past patch_count */
    size_t guarded;      /* words past patch_count checked */
    size_t dispatches;
    double ms;           /* in dispatches (with the wait, and the read-back where there is one) */
    char first[300];
} host_state;

int host_fail(char *err, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(err, HOST_ERRSZ, fmt, ap);
    va_end(ap);
    return -1;
}

double host_now_ms(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec * 1e3 + (double)ts.tv_nsec / 1e6;
}

int host_check_group(const kref_args *o, uint64_t invocations, uint64_t size_x, char *err)
{
    if (o->pq > invocations || o->pq > size_x)
        return host_fail(err, "--block-threads %zu exceeds the device's workgroup limit (%" PRIu64 ")",
                         o->pq, invocations);
    return 0;
}

void host_dispatch_shape(uint64_t *gx, uint64_t *gy, size_t count, size_t q, uint64_t max_x)
{
    uint64_t groups = (count + q - 1) / q;
    *gx = groups < max_x ? groups : max_x;
    if (*gx == 0)
        *gx = 1;
    *gy = (groups + *gx - 1) / *gx;
    if (*gy == 0)
        *gy = 1;
}

int host_chunk_limits(host_limits *lim, const kref_args *o, size_t K, size_t L,
                      uint64_t dev_bytes, uint64_t dev_x, uint64_t dev_y, char *err)
{
    uint64_t per = K * 16, chunk;
    lim->max_bytes = dev_bytes < HOST_MAX_BUFFER ? dev_bytes : HOST_MAX_BUFFER;
    lim->max_x = dev_x < HOST_MAX_GROUPS_X ? dev_x : HOST_MAX_GROUPS_X;
    if (o->planes && L * 4 > per)
        per = L * 4;
    chunk = lim->max_bytes / per;
    if (chunk == 0)
        return host_fail(err, "one patch needs %llu bytes, more than a storage buffer may hold "
                         "(%llu)", (unsigned long long)per, (unsigned long long)lim->max_bytes);
    if (chunk > lim->max_x * dev_y * o->q)
        chunk = lim->max_x * dev_y * o->q;
    if (chunk > UINT32_MAX)
        chunk = UINT32_MAX;
    if (chunk >= o->q)
        chunk -= chunk % o->q; /* whole blocks in every chunk but a set's last */
    lim->chunk = (size_t)chunk;
    return 0;
}

/* Makes the buffers hold a chunk of n patches: control points exactly; classes and plane
 * values as far as the dispatch of n patches reaches (and the buffer limit allows), so that
 * writes past patch_count land in them and are seen. */
static int ensure_buffers(host_state *st, const host_device *d, const kref_args *o,
                          const host_limits *lim, size_t K, size_t L, size_t n, char *err)
{
    uint64_t gx, gy, cover, npl;
    if (n <= st->cap)
        return 0;
    host_dispatch_shape(&gx, &gy, n, o->q, lim->max_x);
    cover = gx * gy * o->q;
    st->cap = 0;
    st->cls_words = cover < lim->max_bytes / 4 ? cover : lim->max_bytes / 4;
    npl = cover < lim->max_bytes / (4 * L) ? cover : lim->max_bytes / (4 * L);
    st->val_words = o->planes ? npl * L : 0;
    if (d->alloc(d->ctx, (uint64_t)n * K * 16, st->cls_words, st->val_words, err))
        return -1;
    st->cap = n;
    return 0;
}

/* Counts the words of w[from..words-1] that are not HOST_UNWRITTEN. */
static void guard(host_state *st, const uint32_t *w, size_t from, size_t words, const char *set,
                  const char *what, size_t n)
{
    for (size_t x = from; x < words; x++, st->guarded++)
        if (w[x] != HOST_UNWRITTEN && !st->bad++)
            snprintf(st->first, sizeof st->first, "%.80s: %s %zu of a %zu-patch dispatch", set,
                     what, x, n);
}

/* Runs one set chunk by chunk into cls (and planes) and checks it; 0 or -1 (message in err). */
static int run_set(host_state *st, kref_result *res, const host_device *d, const kref_args *o,
                   const host_limits *lim, const kref_ref *ref, const kref_set *s, unsigned *cls,
                   float *planes, char *err)
{
    size_t K = (size_t)ref->K, L = (size_t)ref->L;
    if (s->K != ref->K)
        return host_fail(err, "%s: %d points per patch, the reference has %d", s->name, s->K,
                         ref->K);
    for (size_t off = 0; off < s->count;) {
        size_t n = s->count - off < lim->chunk ? s->count - off : lim->chunk;
        uint64_t gx, gy;
        const uint32_t *out[2] = {NULL, NULL};
        double t0;
        if (ensure_buffers(st, d, o, lim, K, L, n, err) ||
            d->upload(d->ctx, s->cp + off * K, n * K * 16, err))
            return -1;
        host_dispatch_shape(&gx, &gy, n, o->q, lim->max_x);
        t0 = host_now_ms();
        if (d->run(d->ctx, s->eye, (uint32_t)n, (uint32_t)gx, (uint32_t)gy, o->planes, out, err)) {
            size_t len = strlen(err);
            snprintf(err + len, HOST_ERRSZ - len, " (%.80s, patches %zu..%zu)", s->name, off,
                     off + n - 1);
            return -1;
        }
        st->ms += host_now_ms() - t0;
        st->dispatches++;
        memcpy(cls + off, out[0], n * sizeof *cls);
        guard(st, out[0], n, (size_t)st->cls_words, s->name, "class written at patch", n);
        if (o->planes) {
            memcpy(planes + off * L, out[1], n * L * sizeof *planes);
            guard(st, out[1], n * L, (size_t)st->val_words, s->name,
                  "plane value written at index", n);
        }
        d->release(d->ctx);
        off += n;
    }
    kref_check(res, ref, s, cls, planes);
    return 0;
}

/* --bench: times runs repetitions of the dispatch of set s, whose control points run_set left in
 * the buffer, and of the copy of its classes into cls; prints the best as one "# bench: " line. */
static int bench_set(const host_device *d, const kref_args *o, const host_limits *lim,
                     const kref_set *s, unsigned *cls, long runs, char *err)
{
    uint64_t gx, gy;
    double best = 0;
    if (s->count == 0)
        return 0;
    if (s->count > lim->chunk)
        return host_fail(err, "%s: --bench needs a set that fits one dispatch (%zu patches), it "
                         "has %zu", s->name, lim->chunk, s->count);
    host_dispatch_shape(&gx, &gy, s->count, o->q, lim->max_x);
    for (long r = 0; r < runs; r++) {
        const uint32_t *out[2] = {NULL, NULL};
        double t0 = host_now_ms(), ms;
        if (d->run(d->ctx, s->eye, (uint32_t)s->count, (uint32_t)gx, (uint32_t)gy, 0, out, err))
            return -1;
        memcpy(cls, out[0], s->count * sizeof *cls);
        d->release(d->ctx);
        ms = host_now_ms() - t0;
        if (r == 0 || ms < best)
            best = ms;
    }
    printf("# bench: patches=%zu runs=%ld best_s=%.6f patches_per_s=%.0f\n", s->count, runs,
           best * 1e-3, (double)s->count / (best * 1e-3));
    return 0;
}

/* Runs every set of every source (host_run); 0, or -1 (message in err, maybe empty). */
static int run_sources(host_state *st, kref_result *res, const host_device *d,
                       const kref_args *o, const host_limits *lim, const kref_ref *ref,
                       long runs, char *err)
{
    unsigned *cls = NULL;
    float *planes = NULL;
    size_t have = 0, total = 0, L = (size_t)ref->L;
    int nsets_total = 0, failed = 0;
    err[0] = '\0';
    for (int si = 0; si < o->nsources && !failed; si++) {
        int nsets = (int)o->src[si].nsets;
        kref_set *sets = kref_source_sets(ref, &o->src[si], o->label);
        if (!sets) {
            failed = 1;
            break;
        }
        for (int i = 0; i < nsets && !failed; i++) {
            if (sets[i].count > have) {
                free(cls);
                free(planes);
                have = sets[i].count;
                cls = malloc(have * sizeof *cls);
                planes = o->planes ? malloc(have * L * sizeof *planes) : NULL;
                if (!cls || (o->planes && !planes)) {
                    failed = host_fail(err, "out of memory for %zu patches", have);
                    break;
                }
            }
            failed = run_set(st, res, d, o, lim, ref, &sets[i], cls, planes, err) != 0 ||
                     (runs && bench_set(d, o, lim, &sets[i], cls, runs, err) != 0);
            total += sets[i].count;
        }
        kref_free_sets(sets, nsets);
        nsets_total += nsets;
    }
    free(cls);
    free(planes);
    if (failed)
        return -1;
    printf("# %s: %d sets, %zu patches, %zu dispatches (chunks of at most %zu patches), "
           "%.1f ms in dispatches\n",
           o->label, nsets_total, total, st->dispatches, lim->chunk, st->ms);
    return 0;
}

/* The check lines of a run; 1 if all passed. */
static int report(const host_state *st, const kref_result *res, const char *label)
{
    char name[400];
    int ok;
    snprintf(name, sizeof name, "%s: nothing written past patch_count (%zu words checked)", label,
             st->guarded);
    ok = check(!st->bad, name, "%zu words written, first: %s", st->bad, st->first);
    return kref_report(res, label) && ok;
}

int host_run(const host_device *d, const kref_args *o, const host_limits *lim,
             const kref_ref *ref, long runs)
{
    host_state st;
    kref_result res;
    char err[HOST_ERRSZ];
    memset(&st, 0, sizeof st);
    memset(&res, 0, sizeof res);
    if (run_sources(&st, &res, d, o, lim, ref, runs, err))
        return err[0] ? check(0, o->label, "%s", err) : 0;
    return report(&st, &res, o->label);
}

int host_run_kernel(const host_device *d, const kref_args *o, const kref_ref *ref, long runs,
                    uint64_t dev_bytes, uint64_t dev_x, uint64_t dev_y)
{
    host_limits lim;
    char err[HOST_ERRSZ], deg[32];
    kref_degree_name(deg, sizeof deg, &ref->t.dom);
    printf("# kernel: %s, %s, %s, %s, %zu invocations per group, %zu patches per group, "
           "%s%s\n",
           o->file, deg, o->space == KREF_CLIP ? "clip" : "world",
           o->rule == KREF_STRICT ? "strict" : "degenerate", o->pq, o->q,
           o->planes ? "planes" : "no planes",
           o->groups_x_constant ? ", groups_x read from the push constants" : "");
    /* the largest chunk of patches whose buffers all fit and whose dispatch is allowed */
    if (host_chunk_limits(&lim, o, (size_t)ref->K, (size_t)ref->L, dev_bytes, dev_x, dev_y, err))
        return check(0, o->label, "%s", err);
    return host_run(d, o, &lim, ref, runs);
}
