/* host_wgpu.c: runs one WGSL compute kernel through wgpu-native (WebGPU's C API; lavapipe through
 * Vulkan in the tests) over patch sets, checking every class (and, with --planes, every plane
 * value) against the double reference of kref.
 *
 *   host_wgpu WGSL --degree N M --space clip|world --rule strict|degenerate
 *             --block-threads PQ --patches-per-block Q [--planes] [--certified]
 *             [--random SETS COUNT SEED] [--model PATH NEYES SEED]
 *             [--exact SETS COUNT SEED] --name LABEL [--bench RUNS]
 *
 * Kernel contract (bind group 0): binding 0 the control points (var<storage, read>
 * array<vec4<f32>>, point k of patch p at p*K + k), binding 1 the classes (var<storage,
 * read_write> array<u32>, one per patch), binding 2 the plane values (var<storage, read_write>
 * array<f32>, d[p*L + i]) only with --planes, binding 3 a var<uniform> struct { eye: vec4<f32>,
 * patch_count: u32 } (32 bytes). Entry point "main" with @workgroup_size(PQ) (or (PQ, 1, 1));
 * workgroup (x, y) handles the Q patches of block y * num_workgroups.x + x; the host dispatches
 * ceil(count/Q) groups as (gx, gy), gx = min(groups, 65535 or the device's limit),
 * gy = ceil(groups/gx). Invocations past patch_count write nothing.
 *
 * The bind group layout is explicit, so a kernel whose bindings differ from the contract fails at
 * pipeline creation (wgpu's validation message is the "not ok" line). Sets whose buffers would
 * exceed one storage binding (128 MiB, or the device's maxStorageBufferBindingSize) run in chunks
 * of patches, one dispatch each with patch_count = the chunk size.
 *
 * Output: "# device: ...", kref_report's lines, and one check that the kernel wrote nothing
 * past patch_count (the classes and values buffers are filled with 0xFFFFFFFF before every
 * dispatch and reach past the chunk as far as its last workgroup does; the part past the chunk
 * must come back untouched). Any setup failure is one "not ok - LABEL: reason" line. Exit status
 * 0 only when every check passed.
 *
 * --bench RUNS: after each set's checked run, its dispatch, the copy of its classes into the
 * mapped read-back buffer and the wait for the map run RUNS more times; the best is printed as
 * "# bench: patches=N runs=RUNS best_s=S patches_per_s=R". The set must fit one dispatch. */
#define _POSIX_C_SOURCE 200809L

#include "check.h"
#include "kref.h"

#include <webgpu.h>
#include <wgpu.h>

#include <errno.h>
#include <inttypes.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

/* The largest storage binding the host creates; -DHOST_MAX_BUFFER=... exercises chunking. */
#ifndef HOST_MAX_BUFFER
#define HOST_MAX_BUFFER ((uint64_t)128 << 20)
#endif
/* The largest group count along x (lowered with -DHOST_MAX_GROUPS_X=... to exercise 2-D
 * dispatches with small sets). */
#ifndef HOST_MAX_GROUPS_X
#define HOST_MAX_GROUPS_X 65535u
#endif
/* How long one dispatch (or a request) may take before the run is declared hung. */
#define HOST_TIMEOUT_MS (600.0 * 1000.0)
/* The uniform block: eye, patch_count, padding. */
#define HOST_PARAMS_BYTES 32u
/* The classes and plane values buffers are filled with this before every dispatch. */
#define HOST_UNWRITTEN 0xFFu
#define HOST_ERRSZ 512

/* Formats a message into err (size HOST_ERRSZ); returns -1. */
static int fail(char *err, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;
static int fail(char *err, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(err, HOST_ERRSZ, fmt, ap);
    va_end(ap);
    return -1;
}

static double now_ms(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec * 1e3 + (double)ts.tv_nsec / 1e6;
}

/* A WGPUStringView as a printf precision and pointer: ("%.*s", SV(s)). */
static int sv_len(WGPUStringView s)
{
    size_t n = !s.data ? 0 : s.length == WGPU_STRLEN ? strlen(s.data) : s.length;
    return n > 400 ? 400 : (int)n;
}
#define SV(s) sv_len(s), ((s).data ? (s).data : "")

static WGPUStringView sv(const char *s)
{
    WGPUStringView v;
    v.data = s;
    v.length = WGPU_STRLEN;
    return v;
}

/* ---- the WGSL file ---- */

/* Reads the whole file into a NUL-terminated string; NULL (message in err) on failure. */
static char *wgsl_read(const char *path, char *err)
{
    FILE *f = fopen(path, "rb");
    long len;
    char *s;
    if (!f) {
        fail(err, "cannot open %s: %s", path, strerror(errno));
        return NULL;
    }
    if (fseek(f, 0, SEEK_END) || (len = ftell(f)) < 0 || fseek(f, 0, SEEK_SET)) {
        fclose(f);
        fail(err, "cannot read %s", path);
        return NULL;
    }
    s = malloc((size_t)len + 1);
    if (!s || fread(s, 1, (size_t)len, f) != (size_t)len) {
        free(s);
        fclose(f);
        fail(err, "cannot read %s", path);
        return NULL;
    }
    fclose(f);
    s[len] = '\0';
    return s;
}

/* Checks the first @workgroup_size(...) of src: (pq), (pq, 1) or (pq, 1, 1); 0 or -1. WebGPU has
 * no reflection, so this reads the text: a kernel whose size is an override or a constant's name
 * is refused here. */
static int wgsl_check_size(const char *src, const char *path, size_t pq, char *err)
{
    const char *at = strstr(src, "@workgroup_size(");
    unsigned long d[3] = {1, 1, 1};
    int n = 0;
    char *end;
    if (!at)
        return fail(err, "%s has no @workgroup_size", path);
    at += strlen("@workgroup_size(");
    for (;;) {
        while (*at == ' ')
            at++;
        d[n++] = strtoul(at, &end, 10);
        if (end == at)
            return fail(err, "%s: @workgroup_size is not a list of integers", path);
        at = end;
        while (*at == ' ' || *at == 'u')
            at++;
        if (*at == ')' || n == 3)
            break;
        if (*at++ != ',')
            return fail(err, "%s: @workgroup_size is not a list of integers", path);
    }
    if (d[0] != pq || d[1] != 1 || d[2] != 1)
        return fail(err, "%s has workgroup size (%lu, %lu, %lu), --block-threads is %zu", path,
                    d[0], d[1], d[2], pq);
    return 0;
}

/* ---- WebGPU ---- */

typedef struct {
    WGPUInstance inst;
    WGPUAdapter adapter;
    WGPUDevice dev;
    WGPUQueue queue;
    WGPULimits limits;
    WGPUShaderModule shader;
    WGPUBindGroupLayout bgl;
    WGPUPipelineLayout layout;
    WGPUComputePipeline pipe;
    WGPUBindGroup group;
    WGPUBuffer params;     /* the uniform block */
    WGPUBuffer bufs[3];    /* control points, classes, plane values */
    WGPUBuffer read[3];    /* map-read copies of classes [1] and plane values [2] */
    uint64_t size[3];      /* bytes of bufs[i] and read[i] */
    const void *mapped[3]; /* read[i]'s contents after wg_run, until wg_unmap */
    unsigned char *fill;   /* HOST_UNWRITTEN bytes, as many as size[1] and size[2] */
    int nbuf;              /* 2, or 3 with --planes */
    size_t cap;            /* patches the control point buffer holds (0: no buffers yet) */
    char error[HOST_ERRSZ]; /* the first error wgpu reported through the device's callback */
    int hung;              /* a dispatch did not finish: leave the objects to process exit */
} wgctx;

/* What one asynchronous request hands back to its callback. */
typedef struct {
    int done, ok;
    void *object; /* the adapter or device */
    char msg[HOST_ERRSZ];
} wgreq;

static void on_adapter(WGPURequestAdapterStatus status, WGPUAdapter adapter, WGPUStringView msg,
                       void *u1, void *u2)
{
    wgreq *r = u1;
    (void)u2;
    r->ok = status == WGPURequestAdapterStatus_Success;
    r->object = adapter;
    snprintf(r->msg, sizeof r->msg, "%.*s", SV(msg));
    r->done = 1;
}

static void on_device(WGPURequestDeviceStatus status, WGPUDevice device, WGPUStringView msg,
                      void *u1, void *u2)
{
    wgreq *r = u1;
    (void)u2;
    r->ok = status == WGPURequestDeviceStatus_Success;
    r->object = device;
    snprintf(r->msg, sizeof r->msg, "%.*s", SV(msg));
    r->done = 1;
}

static void on_map(WGPUMapAsyncStatus status, WGPUStringView msg, void *u1, void *u2)
{
    wgreq *r = u1;
    (void)u2;
    r->ok = status == WGPUMapAsyncStatus_Success;
    snprintf(r->msg, sizeof r->msg, "%.*s", SV(msg));
    r->done = 1;
}

/* Keeps the first error of the device (validation, out of memory, internal). */
static void on_error(WGPUDevice const *device, WGPUErrorType type, WGPUStringView msg, void *u1,
                     void *u2)
{
    wgctx *v = u1;
    (void)device;
    (void)u2;
    if (!v->error[0])
        snprintf(v->error, sizeof v->error, "wgpu error %d: %.*s", (int)type, SV(msg));
}

/* Processes events until every one of the n requests is done or HOST_TIMEOUT_MS passes;
 * 0, or -1 (message in err) on a timeout. */
static int wg_wait(wgctx *v, wgreq *r, int n, const char *what, char *err)
{
    double deadline = now_ms() + HOST_TIMEOUT_MS;
    struct timespec nap = {0, 20000};
    for (;;) {
        int all = 1;
        if (v->dev)
            wgpuDevicePoll(v->dev, 0, NULL);
        wgpuInstanceProcessEvents(v->inst);
        for (int i = 0; i < n; i++)
            all = all && r[i].done;
        if (all)
            return 0;
        if (now_ms() > deadline) {
            v->hung = 1;
            return fail(err, "%s did not finish in %.0f s", what, HOST_TIMEOUT_MS / 1e3);
        }
        nanosleep(&nap, NULL);
    }
}

/* Creates the instance (Vulkan only), the adapter and a device with the adapter's limits;
 * prints "# device: ...". */
static int wg_setup_device(wgctx *v, char *err)
{
    WGPUInstanceExtras extras;
    WGPUInstanceDescriptor idesc = WGPU_INSTANCE_DESCRIPTOR_INIT;
    WGPURequestAdapterCallbackInfo acb = WGPU_REQUEST_ADAPTER_CALLBACK_INFO_INIT;
    WGPURequestDeviceCallbackInfo dcb = WGPU_REQUEST_DEVICE_CALLBACK_INFO_INIT;
    WGPUDeviceDescriptor ddesc = WGPU_DEVICE_DESCRIPTOR_INIT;
    WGPUAdapterInfo info = WGPU_ADAPTER_INFO_INIT;
    wgreq r;
    uint32_t ver = wgpuGetVersion();

    memset(&extras, 0, sizeof extras);
    extras.chain.sType = (WGPUSType)WGPUSType_InstanceExtras;
    extras.backends = WGPUInstanceBackend_Vulkan;
    idesc.nextInChain = &extras.chain;
    if (!(v->inst = wgpuCreateInstance(&idesc)))
        return fail(err, "wgpuCreateInstance failed");

    memset(&r, 0, sizeof r);
    acb.mode = WGPUCallbackMode_AllowProcessEvents;
    acb.callback = on_adapter;
    acb.userdata1 = &r;
    wgpuInstanceRequestAdapter(v->inst, NULL, acb);
    if (wg_wait(v, &r, 1, "wgpuInstanceRequestAdapter", err))
        return -1;
    if (!r.ok || !r.object)
        return fail(err, "no WebGPU adapter (Vulkan): %s", r.msg);
    v->adapter = r.object;
    if (wgpuAdapterGetInfo(v->adapter, &info) != WGPUStatus_Success)
        return fail(err, "wgpuAdapterGetInfo failed");
    printf("# device: %.*s (%.*s, wgpu-native %u.%u.%u.%u, backend %s)\n", SV(info.device),
           SV(info.description), ver >> 24, (ver >> 16) & 0xFFu, (ver >> 8) & 0xFFu,
           ver & 0xFFu, info.backendType == WGPUBackendType_Vulkan ? "Vulkan" : "not Vulkan");
    fflush(stdout);
    wgpuAdapterInfoFreeMembers(info);

    /* ask for everything the adapter allows: buffers and dispatches as large as it has */
    v->limits.nextInChain = NULL;
    if (wgpuAdapterGetLimits(v->adapter, &v->limits) != WGPUStatus_Success)
        return fail(err, "wgpuAdapterGetLimits failed");
    memset(&r, 0, sizeof r);
    ddesc.requiredLimits = &v->limits;
    ddesc.uncapturedErrorCallbackInfo.callback = on_error;
    ddesc.uncapturedErrorCallbackInfo.userdata1 = v;
    dcb.mode = WGPUCallbackMode_AllowProcessEvents;
    dcb.callback = on_device;
    dcb.userdata1 = &r;
    wgpuAdapterRequestDevice(v->adapter, &ddesc, dcb);
    if (wg_wait(v, &r, 1, "wgpuAdapterRequestDevice", err))
        return -1;
    if (!r.ok || !r.object)
        return fail(err, "wgpuAdapterRequestDevice failed: %s", r.msg);
    v->dev = r.object;
    v->queue = wgpuDeviceGetQueue(v->dev);
    return 0;
}

/* The explicit layout of the contract: bindings 0, 1, (2 with --planes), 3. */
static int wg_setup_layout(wgctx *v, char *err)
{
    static const WGPUBufferBindingType types[4] = {
        WGPUBufferBindingType_ReadOnlyStorage, WGPUBufferBindingType_Storage,
        WGPUBufferBindingType_Storage, WGPUBufferBindingType_Uniform};
    WGPUBindGroupLayoutEntry e[4];
    WGPUBindGroupLayoutDescriptor bgld = WGPU_BIND_GROUP_LAYOUT_DESCRIPTOR_INIT;
    WGPUPipelineLayoutDescriptor pld = WGPU_PIPELINE_LAYOUT_DESCRIPTOR_INIT;
    size_t n = 0;
    for (uint32_t b = 0; b < 4; b++) {
        WGPUBindGroupLayoutEntry init = WGPU_BIND_GROUP_LAYOUT_ENTRY_INIT;
        if (b == 2 && v->nbuf < 3)
            continue;
        e[n] = init;
        e[n].binding = b;
        e[n].visibility = WGPUShaderStage_Compute;
        e[n].buffer.type = types[b];
        n++;
    }
    bgld.entryCount = n;
    bgld.entries = e;
    v->bgl = wgpuDeviceCreateBindGroupLayout(v->dev, &bgld);
    pld.bindGroupLayoutCount = 1;
    pld.bindGroupLayouts = &v->bgl;
    v->layout = wgpuDeviceCreatePipelineLayout(v->dev, &pld);
    if (v->error[0] || !v->bgl || !v->layout)
        return fail(err, "creating the pipeline layout: %s", v->error);
    return 0;
}

/* Compiles src (WGSL) and creates the pipeline and the uniform buffer. */
static int wg_setup_pipeline(wgctx *v, const char *src, const char *path, char *err)
{
    WGPUShaderSourceWGSL wgsl = WGPU_SHADER_SOURCE_WGSL_INIT;
    WGPUShaderModuleDescriptor smd = WGPU_SHADER_MODULE_DESCRIPTOR_INIT;
    WGPUComputePipelineDescriptor cpd = WGPU_COMPUTE_PIPELINE_DESCRIPTOR_INIT;
    WGPUBufferDescriptor bd = WGPU_BUFFER_DESCRIPTOR_INIT;

    if (wg_setup_layout(v, err))
        return -1;
    wgsl.code = sv(src);
    smd.nextInChain = &wgsl.chain;
    smd.label = sv(path);
    v->shader = wgpuDeviceCreateShaderModule(v->dev, &smd);
    if (v->error[0] || !v->shader)
        return fail(err, "compiling %s: %s", path, v->error);
    cpd.layout = v->layout;
    cpd.compute.module = v->shader;
    cpd.compute.entryPoint = sv("main");
    v->pipe = wgpuDeviceCreateComputePipeline(v->dev, &cpd);
    if (v->error[0] || !v->pipe)
        return fail(err, "creating the pipeline of %s: %s", path, v->error);
    bd.usage = WGPUBufferUsage_Uniform | WGPUBufferUsage_CopyDst;
    bd.size = HOST_PARAMS_BYTES;
    v->params = wgpuDeviceCreateBuffer(v->dev, &bd);
    if (v->error[0] || !v->params)
        return fail(err, "creating the uniform buffer: %s", v->error);
    return 0;
}

static WGPUBuffer wg_buffer(wgctx *v, uint64_t size, WGPUBufferUsage usage)
{
    WGPUBufferDescriptor bd = WGPU_BUFFER_DESCRIPTOR_INIT;
    bd.usage = usage;
    bd.size = size;
    return wgpuDeviceCreateBuffer(v->dev, &bd);
}

static void wg_free_buffers(wgctx *v)
{
    for (int i = 0; i < 3; i++) {
        if (v->bufs[i])
            wgpuBufferRelease(v->bufs[i]);
        if (v->read[i])
            wgpuBufferRelease(v->read[i]);
        v->bufs[i] = v->read[i] = NULL;
        v->size[i] = 0;
    }
    if (v->group)
        wgpuBindGroupRelease(v->group);
    v->group = NULL;
    free(v->fill);
    v->fill = NULL;
    v->cap = 0;
}

/* Creates the storage buffers (size[0..nbuf-1] bytes), their read-back copies and the bind
 * group. */
static int wg_bind_buffers(wgctx *v, char *err)
{
    const WGPUBufferUsage st = WGPUBufferUsage_Storage | WGPUBufferUsage_CopyDst;
    WGPUBindGroupEntry e[4];
    WGPUBindGroupDescriptor bgd = WGPU_BIND_GROUP_DESCRIPTOR_INIT;
    size_t n = 0;
    v->bufs[0] = wg_buffer(v, v->size[0], st);
    for (int i = 1; i < v->nbuf; i++) {
        v->bufs[i] = wg_buffer(v, v->size[i], st | WGPUBufferUsage_CopySrc);
        v->read[i] = wg_buffer(v, v->size[i], WGPUBufferUsage_MapRead | WGPUBufferUsage_CopyDst);
    }
    for (uint32_t b = 0; b < 4; b++) {
        WGPUBindGroupEntry init = WGPU_BIND_GROUP_ENTRY_INIT;
        if (b == 2 && v->nbuf < 3)
            continue;
        e[n] = init;
        e[n].binding = b;
        e[n].buffer = b == 3 ? v->params : v->bufs[b];
        e[n].size = b == 3 ? HOST_PARAMS_BYTES : v->size[b];
        n++;
    }
    bgd.layout = v->bgl;
    bgd.entryCount = n;
    bgd.entries = e;
    v->group = wgpuDeviceCreateBindGroup(v->dev, &bgd);
    if (v->error[0] || !v->group)
        return fail(err, "creating buffers of %" PRIu64 ", %" PRIu64 " and %" PRIu64
                    " bytes: %s", v->size[0], v->size[1], v->size[2], v->error);
    return 0;
}

static void wg_teardown(wgctx *v)
{
    if (v->hung)
        return; /* objects in use by a queue that never finished: leave them to process exit */
    wg_free_buffers(v);
    if (v->params)
        wgpuBufferRelease(v->params);
    if (v->pipe)
        wgpuComputePipelineRelease(v->pipe);
    if (v->shader)
        wgpuShaderModuleRelease(v->shader);
    if (v->layout)
        wgpuPipelineLayoutRelease(v->layout);
    if (v->bgl)
        wgpuBindGroupLayoutRelease(v->bgl);
    if (v->queue)
        wgpuQueueRelease(v->queue);
    if (v->dev)
        wgpuDeviceRelease(v->dev);
    if (v->adapter)
        wgpuAdapterRelease(v->adapter);
    if (v->inst)
        wgpuInstanceRelease(v->inst);
    memset(v, 0, sizeof *v);
}

/* Maps the read-back buffers 1..nb-1 into v->mapped (wg_unmap releases them). */
static int wg_map(wgctx *v, int nb, char *err)
{
    wgreq r[3];
    memset(r, 0, sizeof r);
    for (int i = 1; i < nb; i++) {
        WGPUBufferMapCallbackInfo mcb = WGPU_BUFFER_MAP_CALLBACK_INFO_INIT;
        mcb.mode = WGPUCallbackMode_AllowProcessEvents;
        mcb.callback = on_map;
        mcb.userdata1 = &r[i];
        wgpuBufferMapAsync(v->read[i], WGPUMapMode_Read, 0, (size_t)v->size[i], mcb);
    }
    if (wg_wait(v, r + 1, nb - 1, "the dispatch and the read-back", err))
        return -1;
    for (int i = 1; i < nb; i++) {
        if (!r[i].ok)
            return fail(err, "mapping the read-back buffer failed: %s %s", r[i].msg, v->error);
        v->mapped[i] = wgpuBufferGetConstMappedRange(v->read[i], 0, (size_t)v->size[i]);
        if (!v->mapped[i])
            return fail(err, "wgpuBufferGetConstMappedRange failed: %s", v->error);
    }
    return 0;
}

static void wg_unmap(wgctx *v)
{
    for (int i = 1; i < 3; i++)
        if (v->mapped[i]) {
            wgpuBufferUnmap(v->read[i]);
            v->mapped[i] = NULL;
        }
}

/* Runs the kernel over patches [0, n) already in the control point buffer as gx * gy groups,
 * copies buffers 1..nb-1 (the classes; the plane values too when nb is 3) to their read-back
 * copies and maps those (v->mapped). */
static int wg_run(wgctx *v, const float eye[4], uint32_t n, uint32_t gx, uint32_t gy, int nb,
                  char *err)
{
    unsigned char params[HOST_PARAMS_BYTES];
    WGPUCommandEncoder enc;
    WGPUComputePassEncoder pass;
    WGPUCommandBuffer cmd;

    memset(params, 0, sizeof params);
    memcpy(params, eye, 16);
    memcpy(params + 16, &n, 4);
    wgpuQueueWriteBuffer(v->queue, v->params, 0, params, sizeof params);
    enc = wgpuDeviceCreateCommandEncoder(v->dev, NULL);
    pass = wgpuCommandEncoderBeginComputePass(enc, NULL);
    wgpuComputePassEncoderSetPipeline(pass, v->pipe);
    wgpuComputePassEncoderSetBindGroup(pass, 0, v->group, 0, NULL);
    wgpuComputePassEncoderDispatchWorkgroups(pass, gx, gy, 1);
    wgpuComputePassEncoderEnd(pass);
    wgpuComputePassEncoderRelease(pass);
    for (int i = 1; i < nb; i++)
        wgpuCommandEncoderCopyBufferToBuffer(enc, v->bufs[i], 0, v->read[i], 0, v->size[i]);
    cmd = wgpuCommandEncoderFinish(enc, NULL);
    wgpuQueueSubmit(v->queue, 1, &cmd);
    wgpuCommandBufferRelease(cmd);
    wgpuCommandEncoderRelease(enc);
    if (v->error[0])
        return fail(err, "the dispatch (%" PRIu32 " x %" PRIu32 " groups): %s", gx, gy, v->error);
    return wg_map(v, nb, err);
}

/* ---- running the sets ---- */

/* The dispatch of count patches: groups = ceil(count / q) laid out as gx * gy. */
static void dispatch_shape(size_t count, size_t q, uint64_t max_x, uint64_t *gx, uint64_t *gy)
{
    uint64_t groups = (count + q - 1) / q;
    *gx = groups < max_x ? groups : max_x;
    if (*gx == 0)
        *gx = 1;
    *gy = (groups + *gx - 1) / *gx;
    if (*gy == 0)
        *gy = 1;
}

/* What limits a chunk: the largest binding and dispatch. */
typedef struct {
    uint64_t max_bytes; /* of one storage binding */
    uint64_t max_x;     /* groups along x */
    size_t chunk;       /* the most patches of one dispatch */
} limits;

/* Makes the buffers hold a chunk of n patches: control points exactly; classes and plane
 * values as far as the dispatch of n patches reaches (and the binding limit allows), so that
 * writes past patch_count land in them and are seen. */
static int ensure_buffers(wgctx *v, const kref_args *o, const limits *lim, size_t K, size_t L,
                          size_t n, char *err)
{
    uint64_t gx, gy, cover, ncls, npl;
    if (n <= v->cap)
        return 0;
    wg_free_buffers(v);
    dispatch_shape(n, o->q, lim->max_x, &gx, &gy);
    cover = gx * gy * o->q;
    ncls = cover < lim->max_bytes / 4 ? cover : lim->max_bytes / 4;
    npl = cover < lim->max_bytes / (4 * L) ? cover : lim->max_bytes / (4 * L);
    v->size[0] = (uint64_t)n * K * 16;
    v->size[1] = ncls * 4;
    v->size[2] = o->planes ? npl * L * 4 : 0;
    v->fill = malloc((size_t)(v->size[1] > v->size[2] ? v->size[1] : v->size[2]));
    if (!v->fill)
        return fail(err, "out of memory for %zu patches", n);
    memset(v->fill, HOST_UNWRITTEN, (size_t)(v->size[1] > v->size[2] ? v->size[1] : v->size[2]));
    if (wg_bind_buffers(v, err))
        return -1;
    v->cap = n;
    return 0;
}

/* Tallies writes past patch_count (kref_check itself catches classes left unwritten). */
typedef struct {
    size_t bad;      /* 32-bit words written past patch_count */
    size_t guarded;  /* words past patch_count checked */
    size_t dispatches;
    double ms;       /* in dispatches, the read-back included */
    char first[300];
} tally;

/* Counts the words of mapped buffer b from word `from` on that are not HOST_UNWRITTEN. */
static void guard(tally *t, const wgctx *v, int b, size_t from, const char *set, size_t n)
{
    const uint32_t *w = v->mapped[b];
    size_t words = (size_t)(v->size[b] / 4);
    for (size_t x = from; x < words; x++, t->guarded++)
        if (w[x] != 0xFFFFFFFFu && !t->bad++)
            snprintf(t->first, sizeof t->first, "%.80s: %s %zu of a %zu-patch dispatch", set,
                     b == 1 ? "class written at patch" : "plane value written at index", x, n);
}

/* Runs one set chunk by chunk into cls (and planes) and checks it; 0 or -1 (message in err). */
static int run_set(wgctx *v, const kref_args *o, const limits *lim, const kref_ref *ref,
                   const kref_set *s, unsigned *cls, float *planes, kref_result *res, tally *t,
                   char *err)
{
    size_t K = (size_t)ref->K, L = (size_t)ref->L;
    if (s->K != ref->K)
        return fail(err, "%s: %d points per patch, the reference has %d", s->name, s->K, ref->K);
    for (size_t off = 0; off < s->count;) {
        size_t n = s->count - off < lim->chunk ? s->count - off : lim->chunk;
        uint64_t gx, gy;
        double t0;
        if (ensure_buffers(v, o, lim, K, L, n, err))
            return -1;
        dispatch_shape(n, o->q, lim->max_x, &gx, &gy);
        wgpuQueueWriteBuffer(v->queue, v->bufs[0], 0, s->cp + off * K, n * K * 16);
        for (int b = 1; b < v->nbuf; b++)
            wgpuQueueWriteBuffer(v->queue, v->bufs[b], 0, v->fill, (size_t)v->size[b]);
        t0 = now_ms();
        if (wg_run(v, s->eye, (uint32_t)n, (uint32_t)gx, (uint32_t)gy, v->nbuf, err)) {
            size_t len = strlen(err);
            snprintf(err + len, HOST_ERRSZ - len, " (%.80s, patches %zu..%zu)", s->name, off,
                     off + n - 1);
            return -1;
        }
        t->ms += now_ms() - t0;
        t->dispatches++;
        memcpy(cls + off, v->mapped[1], n * sizeof *cls);
        guard(t, v, 1, n, s->name, n);
        if (o->planes) {
            memcpy(planes + off * L, v->mapped[2], n * L * sizeof *planes);
            guard(t, v, 2, n * L, s->name, n);
        }
        wg_unmap(v);
        off += n;
    }
    kref_check(res, ref, s, cls, planes);
    return 0;
}

/* --bench: times runs repetitions of the dispatch of set s, whose control points run_set left in
 * the buffer, with the read-back of its classes into cls; prints the best as one "# bench: "
 * line. 0, or -1 (message in err). */
static int bench_set(wgctx *v, const kref_args *o, const limits *lim, const kref_set *s,
                     unsigned *cls, long runs, char *err)
{
    uint64_t gx, gy;
    double best = 0;
    if (s->count == 0)
        return 0;
    if (s->count > lim->chunk)
        return fail(err, "%s: --bench needs a set that fits one dispatch (%zu patches), it has %zu",
                    s->name, lim->chunk, s->count);
    dispatch_shape(s->count, o->q, lim->max_x, &gx, &gy);
    for (long r = 0; r < runs; r++) {
        double t0 = now_ms(), ms;
        if (wg_run(v, s->eye, (uint32_t)s->count, (uint32_t)gx, (uint32_t)gy, 2, err))
            return -1;
        memcpy(cls, v->mapped[1], s->count * sizeof *cls);
        wg_unmap(v);
        ms = now_ms() - t0;
        if (r == 0 || ms < best)
            best = ms;
    }
    printf("# bench: patches=%zu runs=%ld best_s=%.6f patches_per_s=%.0f\n", s->count, runs,
           best * 1e-3, (double)s->count / (best * 1e-3));
    return 0;
}

/* The largest chunk of patches whose buffers all fit and whose dispatch is allowed; 0 or -1. */
static int chunk_limits(limits *lim, const wgctx *v, const kref_args *o, size_t K, size_t L,
                        char *err)
{
    uint64_t per = K * 16, chunk, max_groups;
    lim->max_bytes = HOST_MAX_BUFFER;
    if (v->limits.maxStorageBufferBindingSize < lim->max_bytes)
        lim->max_bytes = v->limits.maxStorageBufferBindingSize;
    if (v->limits.maxBufferSize < lim->max_bytes)
        lim->max_bytes = v->limits.maxBufferSize;
    lim->max_x = v->limits.maxComputeWorkgroupsPerDimension;
    if (lim->max_x > HOST_MAX_GROUPS_X)
        lim->max_x = HOST_MAX_GROUPS_X;
    if (o->planes && L * 4 > per)
        per = L * 4;
    chunk = lim->max_bytes / per;
    if (chunk == 0)
        return fail(err, "one patch needs %" PRIu64 " bytes, more than a storage binding may "
                    "hold (%" PRIu64 ")", per, lim->max_bytes);
    max_groups = lim->max_x * v->limits.maxComputeWorkgroupsPerDimension;
    if (chunk > max_groups * o->q)
        chunk = max_groups * o->q;
    if (chunk > UINT32_MAX)
        chunk = UINT32_MAX;
    if (chunk >= o->q)
        chunk -= chunk % o->q; /* whole blocks in every chunk but a set's last */
    lim->chunk = (size_t)chunk;
    return 0;
}

/* ---- main ---- */

/* Runs every set of every source; 0, or -1 after a "not ok" line (or with a message in err). */
static int run_sources(wgctx *v, const kref_args *o, const limits *lim, const kref_ref *ref,
                       long runs, kref_result *res, tally *t, char *err)
{
    unsigned *cls = NULL;
    float *planes = NULL;
    size_t have = 0, total = 0, L = (size_t)ref->L;
    int nsets_total = 0, failed = 0;
    for (int si = 0; si < o->nsources && !failed; si++) {
        int nsets = (int)o->src[si].nsets;
        kref_set *sets = kref_source_sets(ref, &o->src[si], o->label);
        if (!sets) {
            failed = 1;
            err[0] = '\0';
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
                    failed = fail(err, "out of memory for %zu patches", have);
                    break;
                }
            }
            failed = run_set(v, o, lim, ref, &sets[i], cls, planes, res, t, err) != 0 ||
                     (runs && bench_set(v, o, lim, &sets[i], cls, runs, err) != 0);
            total += sets[i].count;
        }
        kref_free_sets(sets, nsets);
        nsets_total += nsets;
    }
    free(cls);
    free(planes);
    if (!failed)
        printf("# %s: %d sets, %zu patches, %zu dispatches (chunks of at most %zu patches), "
               "%.1f ms in dispatches\n",
               o->label, nsets_total, total, t->dispatches, lim->chunk, t->ms);
    return failed ? -1 : 0;
}

int main(int argc, char **argv)
{
    kref_args o;
    char msg[HOST_ERRSZ];
    ptp_error perr;
    kref_ref ref;
    kref_result res;
    tally t;
    limits lim;
    wgctx v;
    char *src = NULL;
    int have_ref = 0, ok = 0;
    const char *bench = kref_take_bench(&argc, argv);
    long runs = 0;

    if (kref_parse_args(&o, argc, argv, "host_wgpu", KREF_NEED_FILE | KREF_NEED_BLOCK))
        return 2;
    if (bench && !(runs = kref_bench_runs(bench))) {
        check(0, o.label, "--bench takes RUNS, 1 to 1000");
        return 2;
    }
    if (o.groups_x_constant) {
        check(0, o.label, "--groups-x-constant: WGSL kernels read @builtin(num_workgroups)");
        return 2;
    }
    memset(&v, 0, sizeof v);
    memset(&res, 0, sizeof res);
    memset(&t, 0, sizeof t);
    memset(&perr, 0, sizeof perr);
    memset(&lim, 0, sizeof lim);
    v.nbuf = o.planes ? 3 : 2;

#define SETUP_FAIL(...)                                                                        \
    do {                                                                                       \
        check(0, o.label, __VA_ARGS__);                                                        \
        goto done;                                                                             \
    } while (0)

    if (kref_init(&ref, o.n, o.m, o.space, o.rule, &perr))
        SETUP_FAIL("kref_init(%dx%d): %s", o.n, o.m, perr.msg);
    have_ref = 1;
    ref.certified = o.certified;
    if (!(src = wgsl_read(o.file, msg)) || wgsl_check_size(src, o.file, o.pq, msg))
        SETUP_FAIL("%s", msg);
    if (wg_setup_device(&v, msg))
        SETUP_FAIL("%s", msg);
    if (o.pq > v.limits.maxComputeInvocationsPerWorkgroup ||
        o.pq > v.limits.maxComputeWorkgroupSizeX)
        SETUP_FAIL("--block-threads %zu exceeds the device's workgroup limit (%" PRIu32 ")",
                   o.pq, v.limits.maxComputeInvocationsPerWorkgroup);
    if (wg_setup_pipeline(&v, src, o.file, msg))
        SETUP_FAIL("%s", msg);
    printf("# kernel: %s, %dx%d, %s, %s, %zu invocations per group, %zu patches per group, %s\n",
           o.file, o.n, o.m, o.space == KREF_CLIP ? "clip" : "world",
           o.rule == KREF_STRICT ? "strict" : "degenerate", o.pq, o.q,
           o.planes ? "planes" : "no planes");
    if (chunk_limits(&lim, &v, &o, (size_t)ref.K, (size_t)ref.L, msg))
        SETUP_FAIL("%s", msg);
    if (run_sources(&v, &o, &lim, &ref, runs, &res, &t, msg)) {
        if (msg[0])
            SETUP_FAIL("%s", msg);
        goto done;
    }
    {
        char name[400];
        snprintf(name, sizeof name, "%s: nothing written past patch_count (%zu words checked)",
                 o.label, t.guarded);
        ok = check(!t.bad, name, "%zu words written, first: %s", t.bad, t.first);
        ok = kref_report(&res, o.label) && ok;
    }

done:
#undef SETUP_FAIL
    fflush(stdout);
    wg_teardown(&v);
    free(src);
    if (have_ref)
        kref_clear(&ref);
    return ok && !check_exit() ? 0 : 1;
}
