/* host_run.h: what the Vulkan and the WebGPU test hosts share: patch sets cut into chunks of one
 * dispatch each, the check that a kernel writes nothing past patch_count, --bench, and the loop. */
#ifndef HOST_RUN_H
#define HOST_RUN_H

#include "kref.h"

#include <stddef.h>
#include <stdint.h>

/* The size of every error message buffer err. */
#define HOST_ERRSZ 512
/* The classes and plane values buffers hold this word before every dispatch. */
#define HOST_UNWRITTEN 0xFFFFFFFFu

/* Formats a message into err (HOST_ERRSZ bytes); returns -1. */
int host_fail(char *err, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;
/* A monotonic clock in milliseconds. */
double host_now_ms(void);

/* What limits a chunk: the largest storage buffer and dispatch. */
typedef struct {
    uint64_t max_bytes; /* of one storage buffer (binding) */
    uint64_t max_x;     /* groups along x */
    size_t chunk;       /* the most patches of one dispatch */
} host_limits;

/* Fills lim for a device whose storage buffers hold at most dev_bytes and whose dispatches have
 * at most dev_x by dev_y groups (capped at 128 MiB and 65535 groups along x, lavapipe's limits;
 * compile host_run.c with -DHOST_MAX_BUFFER=... or -DHOST_MAX_GROUPS_X=... to exercise chunks and
 * 2-D dispatches with small sets): lim->chunk is the largest number of patches (whole blocks of
 * o->q) whose buffers and dispatch fit. 0, or -1 (message in err) when one patch does not fit. */
int host_chunk_limits(host_limits *lim, const kref_args *o, size_t K, size_t L,
                      uint64_t dev_bytes, uint64_t dev_x, uint64_t dev_y, char *err);
/* 0 if a workgroup of o->pq invocations fits a device of at most invocations per workgroup and
 * size_x along x; else -1 with a message in err. */
int host_check_group(const kref_args *o, uint64_t invocations, uint64_t size_x, char *err);
/* The dispatch of count patches: ceil(count / q) groups laid out as gx * gy, gx <= max_x. */
void host_dispatch_shape(uint64_t *gx, uint64_t *gy, size_t count, size_t q, uint64_t max_x);

/* A device as host_run drives it; every function returns 0, or -1 with a message in err. */
typedef struct {
    void *ctx;
    /* Replaces the buffers with ones of cp_bytes (control points), cls_words (classes) and
     * val_words (plane values; 0 without --planes) and binds them. */
    int (*alloc)(void *ctx, uint64_t cp_bytes, uint64_t cls_words, uint64_t val_words, char *err);
    /* Stores bytes of control points and fills the classes and values with HOST_UNWRITTEN. */
    int (*upload)(void *ctx, const void *cp, size_t bytes, char *err);
    /* Runs the kernel over patches [0, n) as gx * gy groups and points out[0] at the classes and,
     * with values, out[1] at the plane values (whole buffers), readable until release. */
    int (*run)(void *ctx, const float eye[4], uint32_t n, uint32_t gx, uint32_t gy, int values,
               const uint32_t *out[2], char *err);
    void (*release)(void *ctx);
} host_device;

/* Runs every set of every source of o on d, chunk by chunk, and checks it against ref; with
 * runs > 0 also times each set's dispatch RUNS times and prints "# bench: patches=N runs=RUNS
 * best_s=S patches_per_s=R". Prints "# LABEL: N sets, ..." and the check lines: that nothing was
 * written past patch_count, and kref_report's; a failure to run is one "not ok - LABEL: reason"
 * line. Returns 1 if every check passed, else 0. */
int host_run(const host_device *d, const kref_args *o, const host_limits *lim,
             const kref_ref *ref, long runs);
/* The end of a host's main once the kernel is ready on d: prints "# kernel: FILE, ..." (o's
 * options), sizes the chunks for a device whose storage buffers hold at most dev_bytes and whose
 * dispatches have at most dev_x by dev_y groups (host_chunk_limits), and runs (host_run).
 * Returns 1 if every check passed, else 0 (after a "not ok" line). */
int host_run_kernel(const host_device *d, const kref_args *o, const kref_ref *ref, long runs,
                    uint64_t dev_bytes, uint64_t dev_x, uint64_t dev_y);

#endif
