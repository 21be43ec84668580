/* host_opencl.c: builds one emitted OpenCL C 1.2 kernel and runs it over patch sets, checking
 * every class (and, with --planes, every plane value) against the double reference of kref.
 *
 *   host_opencl KERNEL.cl --kernel NAME --degree N M --space clip|world --rule strict|degenerate
 *               --block-threads PQ --patches-per-block Q [--planes] [--certified]
 *               [--random SETS COUNT SEED] [--model PATH NEYES SEED] [--exact SETS COUNT SEED]
 *               [--exact-far SETS COUNT SEED] --name LABEL [--bench RUNS]
 *
 * Kernel contract: kernel void NAME(global const float4 *cp, global uint *cls,
 * global float *planes, float4 eye, uint patch_count) with reqd_work_group_size(PQ, 1, 1);
 * a work-group handles the Q patches of block get_group_id(1)*get_num_groups(0) + get_group_id(0).
 * The host dispatches ceil(count/Q) groups as a 1-D NDRange of groups*PQ work-items.
 *
 * Output: "# device: ..." and kref_report's lines, plus one check that the kernel wrote nothing
 * past patch_count (the output buffers are padded to whole blocks, filled with a sentinel, and
 * the padding is checked untouched; classes start as 0xFFFFFFFF, so kref_check catches unwritten
 * ones). Any setup failure is one "not ok - " line.
 * --random, --model, --exact and --exact-far may each be given more than once; at least one is
 * required.
 * Exit status 0 only when every check passed.
 *
 * --bench RUNS (for `make bench`): after each set's checked run, the set's dispatch, clFinish and
 * the read-back of its classes run RUNS more times (compilation and the upload of the control
 * points excluded), and the best is printed as "# bench: patches=N runs=RUNS best_s=S
 * patches_per_s=R". */
#define _POSIX_C_SOURCE 200809L
#define CL_TARGET_OPENCL_VERSION 120

#include "check.h"
#include "kref.h"

#include <CL/cl.h>

#include <errno.h>
#include <limits.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#define CLS_UNWRITTEN 0xFFFFFFFFu
#define PLANE_UNWRITTEN 0xFF7FFFFFu /* -FLT_MAX: far outside any reference bound */

/* Everything to release at the end. */
typedef struct {
    cl_context ctx;
    cl_command_queue queue;
    cl_program prog;
    cl_kernel kern;
    cl_mem cp_buf, cls_buf, planes_buf;
    size_t cap; /* patches the output buffers hold (whole blocks) */
    size_t cp_cap; /* patches the cp buffer holds */
    cl_uint *cls;
    float *planes;
    char *src_text;
} state;

static const char *cl_err(cl_int e)
{
    switch (e) {
    case CL_SUCCESS: return "CL_SUCCESS";
    case CL_DEVICE_NOT_FOUND: return "CL_DEVICE_NOT_FOUND";
    case CL_DEVICE_NOT_AVAILABLE: return "CL_DEVICE_NOT_AVAILABLE";
    case CL_COMPILER_NOT_AVAILABLE: return "CL_COMPILER_NOT_AVAILABLE";
    case CL_MEM_OBJECT_ALLOCATION_FAILURE: return "CL_MEM_OBJECT_ALLOCATION_FAILURE";
    case CL_OUT_OF_RESOURCES: return "CL_OUT_OF_RESOURCES";
    case CL_OUT_OF_HOST_MEMORY: return "CL_OUT_OF_HOST_MEMORY";
    case CL_BUILD_PROGRAM_FAILURE: return "CL_BUILD_PROGRAM_FAILURE";
    case CL_INVALID_VALUE: return "CL_INVALID_VALUE";
    case CL_INVALID_PLATFORM: return "CL_INVALID_PLATFORM";
    case CL_INVALID_DEVICE: return "CL_INVALID_DEVICE";
    case CL_INVALID_CONTEXT: return "CL_INVALID_CONTEXT";
    case CL_INVALID_COMMAND_QUEUE: return "CL_INVALID_COMMAND_QUEUE";
    case CL_INVALID_MEM_OBJECT: return "CL_INVALID_MEM_OBJECT";
    case CL_INVALID_BUILD_OPTIONS: return "CL_INVALID_BUILD_OPTIONS";
    case CL_INVALID_PROGRAM: return "CL_INVALID_PROGRAM";
    case CL_INVALID_PROGRAM_EXECUTABLE: return "CL_INVALID_PROGRAM_EXECUTABLE";
    case CL_INVALID_KERNEL_NAME: return "CL_INVALID_KERNEL_NAME";
    case CL_INVALID_KERNEL_DEFINITION: return "CL_INVALID_KERNEL_DEFINITION";
    case CL_INVALID_KERNEL: return "CL_INVALID_KERNEL";
    case CL_INVALID_ARG_INDEX: return "CL_INVALID_ARG_INDEX";
    case CL_INVALID_ARG_VALUE: return "CL_INVALID_ARG_VALUE";
    case CL_INVALID_ARG_SIZE: return "CL_INVALID_ARG_SIZE";
    case CL_INVALID_KERNEL_ARGS: return "CL_INVALID_KERNEL_ARGS";
    case CL_INVALID_WORK_DIMENSION: return "CL_INVALID_WORK_DIMENSION";
    case CL_INVALID_WORK_GROUP_SIZE: return "CL_INVALID_WORK_GROUP_SIZE";
    case CL_INVALID_WORK_ITEM_SIZE: return "CL_INVALID_WORK_ITEM_SIZE";
    case CL_INVALID_GLOBAL_OFFSET: return "CL_INVALID_GLOBAL_OFFSET";
    case CL_INVALID_BUFFER_SIZE: return "CL_INVALID_BUFFER_SIZE";
    case CL_INVALID_GLOBAL_WORK_SIZE: return "CL_INVALID_GLOBAL_WORK_SIZE";
    case CL_EXEC_STATUS_ERROR_FOR_EVENTS_IN_WAIT_LIST:
        return "CL_EXEC_STATUS_ERROR_FOR_EVENTS_IN_WAIT_LIST";
    case -1001: return "CL_PLATFORM_NOT_FOUND_KHR (no OpenCL driver installed)";
    default: return "OpenCL error";
    }
}

/* Reads a whole file into a NUL-terminated buffer; NULL on failure (errno set). */
static char *read_file(const char *path, size_t *len)
{
    FILE *f = fopen(path, "rb");
    char *buf = NULL;
    size_t cap = 0, n = 0;
    if (!f)
        return NULL;
    for (;;) {
        size_t got;
        if (cap - n < 4096) {
            char *nb = realloc(buf, cap ? 2 * cap : 65536);
            if (!nb) {
                free(buf);
                fclose(f);
                errno = ENOMEM;
                return NULL;
            }
            buf = nb;
            cap = cap ? 2 * cap : 65536;
        }
        got = fread(buf + n, 1, cap - n - 1, f);
        n += got;
        if (got == 0)
            break;
    }
    if (ferror(f)) {
        free(buf);
        fclose(f);
        errno = EIO;
        return NULL;
    }
    fclose(f);
    buf[n] = '\0';
    *len = n;
    return buf;
}

/* Picks the first device of the first platform that has one; prints "# device: ...". */
static int pick_device(const char *label, cl_platform_id *plat, cl_device_id *dev)
{
    cl_uint np = 0, i;
    cl_platform_id *ps;
    cl_int e = clGetPlatformIDs(0, NULL, &np);
    if (e != CL_SUCCESS || np == 0) {
        check(0, label, "no OpenCL platform (clGetPlatformIDs: %s, %u platforms)", cl_err(e),
              (unsigned)np);
        return -1;
    }
    ps = malloc(np * sizeof *ps);
    if (!ps || clGetPlatformIDs(np, ps, NULL) != CL_SUCCESS) {
        free(ps);
        check(0, label, "clGetPlatformIDs failed listing %u platforms", (unsigned)np);
        return -1;
    }
    for (i = 0; i < np; i++) {
        cl_uint nd = 0;
        if (clGetDeviceIDs(ps[i], CL_DEVICE_TYPE_ALL, 1, dev, &nd) == CL_SUCCESS && nd > 0) {
            char pname[256] = "?", dname[256] = "?", dver[256] = "?";
            *plat = ps[i];
            free(ps);
            clGetPlatformInfo(*plat, CL_PLATFORM_NAME, sizeof pname - 1, pname, NULL);
            clGetDeviceInfo(*dev, CL_DEVICE_NAME, sizeof dname - 1, dname, NULL);
            clGetDeviceInfo(*dev, CL_DEVICE_VERSION, sizeof dver - 1, dver, NULL);
            pname[sizeof pname - 1] = dname[sizeof dname - 1] = dver[sizeof dver - 1] = '\0';
            printf("# device: %s / %s (%s)\n", pname, dname, dver);
            return 0;
        }
    }
    free(ps);
    check(0, label, "no OpenCL device on any of %u platforms", (unsigned)np);
    return -1;
}

/* Builds the program; on failure prints one "not ok" line and the log's first lines. */
static int build(state *st, const kref_args *o, cl_device_id dev)
{
    size_t len = 0, loglen = 0;
    const char *text;
    cl_int e;
    st->src_text = read_file(o->file, &len);
    if (!st->src_text) {
        check(0, o->label, "cannot read %s: %s", o->file, strerror(errno));
        return -1;
    }
    text = st->src_text;
    st->prog = clCreateProgramWithSource(st->ctx, 1, &text, &len, &e);
    if (e != CL_SUCCESS) {
        check(0, o->label, "clCreateProgramWithSource: %s", cl_err(e));
        return -1;
    }
    e = clBuildProgram(st->prog, 1, &dev, "-cl-std=CL1.2", NULL, NULL);
    if (e != CL_SUCCESS) {
        char *log = NULL, *line, *nl, empty[1] = "";
        int shown = 0;
        clGetProgramBuildInfo(st->prog, dev, CL_PROGRAM_BUILD_LOG, 0, NULL, &loglen);
        log = calloc(loglen + 1, 1);
        if (log && loglen)
            clGetProgramBuildInfo(st->prog, dev, CL_PROGRAM_BUILD_LOG, loglen, log, NULL);
        /* the first non-empty log line goes into the check line, the next ones as comments */
        line = log ? log : empty;
        while (*line == '\n' || *line == '\r' || *line == ' ')
            line++;
        nl = strchr(line, '\n');
        if (nl)
            *nl = '\0';
        check(0, o->label, "build of %s failed (%s): %.300s", o->file, cl_err(e),
              *line ? line : "(empty build log)");
        while (nl && shown < 20) {
            line = nl + 1;
            nl = strchr(line, '\n');
            if (nl)
                *nl = '\0';
            if (*line) {
                printf("# %.300s\n", line);
                shown++;
            }
        }
        free(log);
        return -1;
    }
    st->kern = clCreateKernel(st->prog, o->kernel_name, &e);
    if (e != CL_SUCCESS) {
        check(0, o->label, "clCreateKernel(%s) in %s: %s", o->kernel_name, o->file,
              cl_err(e));
        return -1;
    }
    return 0;
}

/* The work-group size the kernel declares must be exactly (PQ, 1, 1). */
static int check_group_size(const state *st, const kref_args *o, cl_device_id dev)
{
    size_t req[3] = {0, 0, 0}, maxwg = 0;
    cl_int e = clGetKernelWorkGroupInfo(st->kern, dev, CL_KERNEL_COMPILE_WORK_GROUP_SIZE,
                                        sizeof req, req, NULL);
    if (e != CL_SUCCESS) {
        check(0, o->label, "clGetKernelWorkGroupInfo(COMPILE_WORK_GROUP_SIZE): %s", cl_err(e));
        return -1;
    }
    if (!req[0] && !req[1] && !req[2]) {
        check(0, o->label, "kernel %s declares no reqd_work_group_size(%zu, 1, 1)",
              o->kernel_name, o->pq);
        return -1;
    }
    if (req[0] != o->pq || req[1] != 1 || req[2] != 1) {
        check(0, o->label, "kernel %s declares reqd_work_group_size(%zu, %zu, %zu), "
              "--block-threads is %zu", o->kernel_name, req[0], req[1], req[2], o->pq);
        return -1;
    }
    e = clGetKernelWorkGroupInfo(st->kern, dev, CL_KERNEL_WORK_GROUP_SIZE, sizeof maxwg, &maxwg,
                                 NULL);
    if (e == CL_SUCCESS && maxwg < o->pq) {
        check(0, o->label, "the device runs kernel %s with at most %zu work-items per group, "
              "it needs %zu", o->kernel_name, maxwg, o->pq);
        return -1;
    }
    return 0;
}

/* Makes the buffers hold count patches (cp exactly; outputs padded to whole blocks). */
static int ensure_buffers(state *st, const kref_args *o, const kref_ref *ref, size_t count)
{
    size_t blocks = (count + o->q - 1) / o->q, cap = blocks * o->q;
    size_t L = (size_t)ref->L, K = (size_t)ref->K;
    cl_int e;
    if (count > SIZE_MAX / K / sizeof(cl_float4) || cap > SIZE_MAX / L / sizeof(float)) {
        check(0, o->label, "%zu patches do not fit in memory", count);
        return -1;
    }
    if (count != st->cp_cap) {
        if (st->cp_buf)
            clReleaseMemObject(st->cp_buf);
        st->cp_buf = clCreateBuffer(st->ctx, CL_MEM_READ_ONLY, count * K * sizeof(cl_float4),
                                    NULL, &e);
        if (e != CL_SUCCESS) {
            st->cp_buf = NULL;
            st->cp_cap = 0;
            check(0, o->label, "clCreateBuffer(cp, %zu patches): %s", count, cl_err(e));
            return -1;
        }
        st->cp_cap = count;
    }
    if (cap != st->cap) {
        if (st->cls_buf)
            clReleaseMemObject(st->cls_buf);
        if (st->planes_buf)
            clReleaseMemObject(st->planes_buf);
        st->cls_buf = st->planes_buf = NULL;
        free(st->cls);
        free(st->planes);
        st->planes = NULL;
        st->cap = 0;
        st->cls = malloc(cap * sizeof *st->cls);
        if (o->planes)
            st->planes = malloc(cap * L * sizeof *st->planes);
        if (!st->cls || (o->planes && !st->planes)) {
            check(0, o->label, "out of memory for %zu patches", cap);
            return -1;
        }
        st->cls_buf = clCreateBuffer(st->ctx, CL_MEM_READ_WRITE, cap * sizeof(cl_uint), NULL,
                                     &e);
        if (e == CL_SUCCESS && o->planes)
            st->planes_buf = clCreateBuffer(st->ctx, CL_MEM_READ_WRITE,
                                            cap * L * sizeof(cl_float), NULL, &e);
        if (e != CL_SUCCESS) {
            check(0, o->label, "clCreateBuffer(outputs, %zu patches): %s", cap, cl_err(e));
            return -1;
        }
        st->cap = cap;
    }
    return 0;
}

/* Tallies writes past patch_count (kref_check itself catches classes left unwritten). */
typedef struct {
    size_t bad;
    char first[300];
} hygiene;

static void hygiene_fail(hygiene *h, const char *set, const char *what, size_t index)
{
    if (!h->bad++)
        snprintf(h->first, sizeof h->first, "%.80s: %s %zu", set, what, index);
}

/* Marks st's classes and (with --planes) plane values unwritten and writes them and set s's
 * count patches to the device; 0, or -1 (reported). */
static int upload_set(state *st, const kref_args *o, const kref_ref *ref, const kref_set *s,
                      size_t count)
{
    size_t L = (size_t)ref->L, K = (size_t)ref->K, p, i;
    uint32_t pattern = PLANE_UNWRITTEN;
    cl_int e;
    for (p = 0; p < st->cap; p++)
        st->cls[p] = CLS_UNWRITTEN;
    if (o->planes)
        for (i = 0; i < st->cap * L; i++)
            memcpy(&st->planes[i], &pattern, sizeof pattern);
    e = clEnqueueWriteBuffer(st->queue, st->cp_buf, CL_TRUE, 0, count * K * sizeof(cl_float4),
                             s->cp, 0, NULL, NULL);
    if (e == CL_SUCCESS)
        e = clEnqueueWriteBuffer(st->queue, st->cls_buf, CL_TRUE, 0, st->cap * sizeof(cl_uint),
                                 st->cls, 0, NULL, NULL);
    if (e == CL_SUCCESS && o->planes)
        e = clEnqueueWriteBuffer(st->queue, st->planes_buf, CL_TRUE, 0,
                                 st->cap * L * sizeof(cl_float), st->planes, 0, NULL, NULL);
    if (e != CL_SUCCESS) {
        check(0, o->label, "%s: clEnqueueWriteBuffer: %s", s->name, cl_err(e));
        return -1;
    }
    return 0;
}

/* Sets the kernel's arguments for set s of count patches: the buffers (planes NULL without
 * --planes), the eye and the count; 0, or -1 (reported). */
static int set_args(state *st, const kref_args *o, const kref_set *s, size_t count)
{
    cl_uint pc = (cl_uint)count;
    cl_float4 eye;
    cl_int e;
    int i;
    for (i = 0; i < 4; i++)
        eye.s[i] = s->eye[i];
    e = clSetKernelArg(st->kern, 0, sizeof(cl_mem), &st->cp_buf);
    if (e == CL_SUCCESS)
        e = clSetKernelArg(st->kern, 1, sizeof(cl_mem), &st->cls_buf);
    if (e == CL_SUCCESS) /* a NULL value pointer passes a NULL global pointer */
        e = clSetKernelArg(st->kern, 2, sizeof(cl_mem), o->planes ? &st->planes_buf : NULL);
    if (e == CL_SUCCESS)
        e = clSetKernelArg(st->kern, 3, sizeof(cl_float4), &eye);
    if (e == CL_SUCCESS)
        e = clSetKernelArg(st->kern, 4, sizeof(cl_uint), &pc);
    if (e != CL_SUCCESS) {
        check(0, o->label, "%s: clSetKernelArg: %s", s->name, cl_err(e));
        return -1;
    }
    return 0;
}

/* Runs the kernel over groups workgroups of o->pq threads and reads back the classes and (with
 * --planes) the plane values of set s; 0, or -1 (reported). */
static int dispatch(state *st, const kref_args *o, const kref_ref *ref, const kref_set *s,
                    size_t groups)
{
    size_t gsize = groups * o->pq, lsize = o->pq, L = (size_t)ref->L;
    cl_int e = clEnqueueNDRangeKernel(st->queue, st->kern, 1, NULL, &gsize, &lsize, 0, NULL, NULL);
    if (e != CL_SUCCESS) {
        check(0, o->label, "%s: clEnqueueNDRangeKernel(%zu groups of %zu): %s", s->name,
              groups, lsize, cl_err(e));
        return -1;
    }
    e = clFinish(st->queue);
    if (e == CL_SUCCESS)
        e = clEnqueueReadBuffer(st->queue, st->cls_buf, CL_TRUE, 0, st->cap * sizeof(cl_uint),
                                st->cls, 0, NULL, NULL);
    if (e == CL_SUCCESS && o->planes)
        e = clEnqueueReadBuffer(st->queue, st->planes_buf, CL_TRUE, 0,
                                st->cap * L * sizeof(cl_float), st->planes, 0, NULL, NULL);
    if (e != CL_SUCCESS) {
        check(0, o->label, "%s: running the kernel: %s", s->name, cl_err(e));
        return -1;
    }
    return 0;
}

/* Reports into h every class or plane value the kernel wrote past set s's count patches. */
static void check_past_count(const state *st, const kref_args *o, const kref_ref *ref,
                             const kref_set *s, size_t count, hygiene *h)
{
    size_t L = (size_t)ref->L, p, i;
    uint32_t pattern = PLANE_UNWRITTEN;
    for (p = count; p < st->cap; p++)
        if (st->cls[p] != CLS_UNWRITTEN)
            hygiene_fail(h, s->name, "class written past patch_count at patch", p);
    if (o->planes)
        for (i = count * L; i < st->cap * L; i++)
            if (memcmp(&st->planes[i], &pattern, sizeof pattern))
                hygiene_fail(h, s->name, "plane written past patch_count at index", i);
}

/* Runs one set; 0 on success, -1 on an OpenCL failure (reported). */
static int run_set(state *st, const kref_args *o, const kref_ref *ref, const kref_set *s,
                   kref_result *res, hygiene *h)
{
    size_t count = s->count, groups = (count + o->q - 1) / o->q;
    if (count > UINT32_MAX || groups > SIZE_MAX / o->pq) {
        check(0, o->label, "%s: %zu patches do not fit a uint patch_count", s->name, count);
        return -1;
    }
    if (count == 0)
        return 0;
    if (s->K != ref->K) {
        check(0, o->label, "%s: %d points per patch, the reference has %d", s->name, s->K,
              ref->K);
        return -1;
    }
    if (ensure_buffers(st, o, ref, count) || upload_set(st, o, ref, s, count) ||
        set_args(st, o, s, count) || dispatch(st, o, ref, s, groups))
        return -1;
    check_past_count(st, o, ref, s, count, h);
    kref_check(res, ref, s, st->cls, o->planes ? st->planes : NULL);
    return 0;
}

static double now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

/* --bench: times runs repetitions of the dispatch of set s (its control points and the kernel
 * arguments are still in place from run_set), clFinish and the read-back of its classes, and
 * prints the best as one "# bench: " line; 0, or -1 on an OpenCL failure (reported). */
static int bench_set(state *st, const kref_args *o, const kref_set *s, long runs)
{
    size_t groups = (s->count + o->q - 1) / o->q, gsize = groups * o->pq, lsize = o->pq;
    double best = 0;
    long r;
    if (s->count == 0)
        return 0;
    for (r = 0; r < runs; r++) {
        double t0 = now_s(), secs;
        cl_int e = clEnqueueNDRangeKernel(st->queue, st->kern, 1, NULL, &gsize, &lsize, 0, NULL,
                                          NULL);
        if (e == CL_SUCCESS)
            e = clFinish(st->queue);
        if (e == CL_SUCCESS)
            e = clEnqueueReadBuffer(st->queue, st->cls_buf, CL_TRUE, 0,
                                    s->count * sizeof(cl_uint), st->cls, 0, NULL, NULL);
        if (e != CL_SUCCESS) {
            check(0, o->label, "%s: --bench: %s", s->name, cl_err(e));
            return -1;
        }
        secs = now_s() - t0;
        if (r == 0 || secs < best)
            best = secs;
    }
    printf("# bench: patches=%zu runs=%ld best_s=%.6f patches_per_s=%.0f\n", s->count, runs, best,
           (double)s->count / best);
    return 0;
}

static void release(state *st)
{
    if (st->cp_buf)
        clReleaseMemObject(st->cp_buf);
    if (st->cls_buf)
        clReleaseMemObject(st->cls_buf);
    if (st->planes_buf)
        clReleaseMemObject(st->planes_buf);
    if (st->kern)
        clReleaseKernel(st->kern);
    if (st->prog)
        clReleaseProgram(st->prog);
    if (st->queue)
        clReleaseCommandQueue(st->queue);
    if (st->ctx)
        clReleaseContext(st->ctx);
    free(st->cls);
    free(st->planes);
    free(st->src_text);
}

/* What every set of a run shares: kref_each_set's context. */
typedef struct {
    state *st;
    const kref_args *o;
    kref_result *res;
    hygiene *h;
    long runs; /* --bench RUNS, or 0 */
} run;

/* Runs and checks one set (ctx: a run), and times it under --bench; 0 on success. */
static int each_set(void *ctx, const kref_ref *ref, const kref_set *s)
{
    const run *r = ctx;
    return run_set(r->st, r->o, ref, s, r->res, r->h) != 0 ||
           (r->runs && bench_set(r->st, r->o, s, r->runs) != 0);
}

int main(int argc, char **argv)
{
    kref_args o;
    state st;
    kref_ref ref;
    kref_result res;
    hygiene h;
    cl_platform_id plat;
    cl_device_id dev;
    cl_int e;
    int ok = 0, have_ref = 0, nsets_total = 0;
    long runs;
    run r;
    char deg[32];

    if (kref_parse_bench_args(&o, &runs, argc, argv, "host_opencl",
                              KREF_NEED_FILE | KREF_NEED_KERNEL | KREF_NEED_BLOCK))
        return 2;
    memset(&st, 0, sizeof st);
    memset(&res, 0, sizeof res);
    memset(&h, 0, sizeof h);

    if (kref_init_args(&ref, &o))
        goto done;
    have_ref = 1;
    if (pick_device(o.label, &plat, &dev))
        goto done;
    {
        cl_context_properties props[3] = {CL_CONTEXT_PLATFORM, (cl_context_properties)plat, 0};
        st.ctx = clCreateContext(props, 1, &dev, NULL, NULL, &e);
        if (e != CL_SUCCESS) {
            st.ctx = NULL;
            check(0, o.label, "clCreateContext: %s", cl_err(e));
            goto done;
        }
    }
    st.queue = clCreateCommandQueue(st.ctx, dev, 0, &e);
    if (e != CL_SUCCESS) {
        st.queue = NULL;
        check(0, o.label, "clCreateCommandQueue: %s", cl_err(e));
        goto done;
    }
    if (build(&st, &o, dev) || check_group_size(&st, &o, dev))
        goto done;
    kref_degree_name(deg, sizeof deg, &ref.t.dom);
    printf("# kernel: %s in %s, %s, %s, %s, %zu work-items per group, %zu patches per group%s\n",
           o.kernel_name, o.file, deg, o.space == KREF_CLIP ? "clip" : "world",
           o.rule == KREF_STRICT ? "strict" : "degenerate", o.pq, o.q,
           o.planes ? ", planes" : "");

    r.st = &st;
    r.o = &o;
    r.res = &res;
    r.h = &h;
    r.runs = runs;
    if (kref_each_set(&ref, &o, each_set, &r, &nsets_total))
        goto done;

    {
        char name[400];
        snprintf(name, sizeof name, "%s: nothing written past patch_count "
                 "(%d sets)", o.label, nsets_total);
        ok = check(!h.bad, name, "%zu violations, first: %s", h.bad, h.first);
        ok = kref_report(&res, o.label) && ok;
    }

done:
    release(&st);
    if (have_ref)
        kref_clear(&ref);
    fflush(stdout);
    return ok && !check_exit() ? 0 : 1;
}
