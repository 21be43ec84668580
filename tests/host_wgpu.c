/* host_wgpu.c: runs one WGSL compute kernel through wgpu-native (WebGPU's C API; lavapipe through
 * Vulkan in the tests) over patch sets, checking every class (and, with --planes, every plane
 * value) against the double reference of kref.
 *
 *   host_wgpu WGSL --degree N M --space clip|world --rule strict|degenerate
 *             --block-threads PQ --patches-per-block Q [--planes] [--certified]
 *             [--random SETS COUNT SEED] [--model PATH NEYES SEED]
 *             [--exact SETS COUNT SEED] [--exact-far SETS COUNT SEED] --name LABEL [--bench RUNS]
 *
 * Kernel contract (bind group 0): binding 0 the control points (var<storage, read>
 * array<vec4<f32>>, point k of patch p at p*K + k), binding 1 the classes (var<storage,
 * read_write> array<u32>, one per patch), binding 2 the plane values (var<storage, read_write>
 * array<f32>, d[p*L + i]) only with --planes, binding 3 a var<uniform> struct { eye: vec4<f32>,
 * patch_count: u32 } (32 bytes; the host writes zeros after patch_count, which a kernel may
 * declare as `zero: u32` to keep products out of FMA contraction: tests/README.md). Entry point
 * "main" with @workgroup_size(PQ) (or (PQ, 1, 1); literals or module-scope constants' names,
 * which the host reads from the text to check PQ against --block-threads); workgroup (x, y)
 * handles the Q patches of block y * num_workgroups.x + x; the host dispatches ceil(count/Q)
 * groups as (gx, gy), gx = min(groups, 65535 or the device's limit), gy = ceil(groups/gx).
 * Invocations past patch_count write nothing.
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
#include "host_run.h"
#include "kref.h"

#include <webgpu.h>
#include <wgpu.h>

#include <errno.h>
#include <inttypes.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

/* How long one dispatch (or a request) may take before the run is declared hung. */
#define HOST_TIMEOUT_MS (600.0 * 1000.0)
/* The uniform block: eye, patch_count, padding. */
#define HOST_PARAMS_BYTES 32u

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
        host_fail(err, "cannot open %s: %s", path, strerror(errno));
        return NULL;
    }
    if (fseek(f, 0, SEEK_END) || (len = ftell(f)) < 0 || fseek(f, 0, SEEK_SET)) {
        fclose(f);
        host_fail(err, "cannot read %s", path);
        return NULL;
    }
    s = malloc((size_t)len + 1);
    if (!s || fread(s, 1, (size_t)len, f) != (size_t)len) {
        free(s);
        fclose(f);
        host_fail(err, "cannot read %s", path);
        return NULL;
    }
    fclose(f);
    s[len] = '\0';
    return s;
}

/* The value of one @workgroup_size argument at *at: an integer literal, or the name of a
 * module-scope `const NAME = 128u;` (or `const NAME: u32 = 128u;`) of src. Moves *at past it;
 * 0 (and *v) or -1 when it is neither. */
static int wgsl_size_arg(const char *src, const char **at, unsigned long *v)
{
    const char *p = *at, *def;
    char *end;
    size_t len = 0;
    while (*p == ' ')
        p++;
    while (p[len] == '_' || (p[len] >= 'A' && p[len] <= 'Z') || (p[len] >= 'a' && p[len] <= 'z') ||
           (len && p[len] >= '0' && p[len] <= '9'))
        len++;
    if (len) { /* a constant's name: find its definition */
        for (def = strstr(src, "const "); def; def = strstr(def + 1, "const "))
            if (!strncmp(def + 6, p, len) && def[6 + len] && strchr(" :=", def[6 + len]))
                break;
        if (!def || !(def = strchr(def, '=')))
            return -1;
        *v = strtoul(def + 1, &end, 10);
        if (end == def + 1)
            return -1;
        *at = p + len;
        return 0;
    }
    *v = strtoul(p, &end, 10);
    if (end == p)
        return -1;
    for (*at = end; **at == 'u' || **at == 'i' || **at == ' '; (*at)++)
        ;
    return 0;
}

/* Checks the first @workgroup_size(...) of src: (pq), (pq, 1) or (pq, 1, 1), each an integer
 * literal or a module-scope constant's name; 0 or -1. WebGPU has no reflection, so this reads
 * the text: a size given by an override or an expression is refused here. */
static int wgsl_check_size(const char *src, const char *path, size_t pq, char *err)
{
    const char *at = strstr(src, "@workgroup_size(");
    unsigned long d[3] = {1, 1, 1};
    int n = 0;
    if (!at)
        return host_fail(err, "%s has no @workgroup_size", path);
    at += strlen("@workgroup_size(");
    for (;;) {
        if (wgsl_size_arg(src, &at, &d[n++]))
            return host_fail(err, "%s: an argument of @workgroup_size is neither an integer nor "
                             "a constant's name", path);
        while (*at == ' ')
            at++;
        if (*at == ')' || n == 3)
            break;
        if (*at++ != ',')
            return host_fail(err, "%s: @workgroup_size is not a list of integers and constants' "
                             "names", path);
    }
    if (d[0] != pq || d[1] != 1 || d[2] != 1)
        return host_fail(err, "%s has workgroup size (%lu, %lu, %lu), --block-threads is %zu",
                         path, d[0], d[1], d[2], pq);
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
    char error[HOST_ERRSZ]; /* the first error wgpu reported through the device's callback */
    int hung;              /* a dispatch did not finish: leave the objects to process exit */
} wgctx;

/* What one asynchronous request hands back to its callback. */
typedef struct {
    int done, ok;
    void *object; /* the adapter or device */
    char msg[HOST_ERRSZ];
} wgreq;

/* Completes request r (the userdata1 of a callback). */
static void req_done(void *r, int ok, void *object, WGPUStringView msg)
{
    wgreq *q = r;
    q->ok = ok;
    q->object = object;
    snprintf(q->msg, sizeof q->msg, "%.*s", SV(msg));
    q->done = 1;
}

static void on_adapter(WGPURequestAdapterStatus status, WGPUAdapter adapter, WGPUStringView msg,
                       void *u1, void *u2)
{
    (void)u2;
    req_done(u1, status == WGPURequestAdapterStatus_Success, adapter, msg);
}

static void on_device(WGPURequestDeviceStatus status, WGPUDevice device, WGPUStringView msg,
                      void *u1, void *u2)
{
    (void)u2;
    req_done(u1, status == WGPURequestDeviceStatus_Success, device, msg);
}

static void on_map(WGPUMapAsyncStatus status, WGPUStringView msg, void *u1, void *u2)
{
    (void)u2;
    req_done(u1, status == WGPUMapAsyncStatus_Success, NULL, msg);
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
    double deadline = host_now_ms() + HOST_TIMEOUT_MS;
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
        if (host_now_ms() > deadline) {
            v->hung = 1;
            return host_fail(err, "%s did not finish in %.0f s", what, HOST_TIMEOUT_MS / 1e3);
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
        return host_fail(err, "wgpuCreateInstance failed");

    memset(&r, 0, sizeof r);
    acb.mode = WGPUCallbackMode_AllowProcessEvents;
    acb.callback = on_adapter;
    acb.userdata1 = &r;
    wgpuInstanceRequestAdapter(v->inst, NULL, acb);
    if (wg_wait(v, &r, 1, "wgpuInstanceRequestAdapter", err))
        return -1;
    if (!r.ok || !r.object)
        return host_fail(err, "no WebGPU adapter (Vulkan): %s", r.msg);
    v->adapter = r.object;
    if (wgpuAdapterGetInfo(v->adapter, &info) != WGPUStatus_Success)
        return host_fail(err, "wgpuAdapterGetInfo failed");
    printf("# device: %.*s (%.*s, wgpu-native %u.%u.%u.%u, backend %s)\n", SV(info.device),
           SV(info.description), ver >> 24, (ver >> 16) & 0xFFu, (ver >> 8) & 0xFFu,
           ver & 0xFFu, info.backendType == WGPUBackendType_Vulkan ? "Vulkan" : "not Vulkan");
    fflush(stdout);
    wgpuAdapterInfoFreeMembers(info);

    /* ask for everything the adapter allows: buffers and dispatches as large as it has */
    v->limits.nextInChain = NULL;
    if (wgpuAdapterGetLimits(v->adapter, &v->limits) != WGPUStatus_Success)
        return host_fail(err, "wgpuAdapterGetLimits failed");
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
        return host_fail(err, "wgpuAdapterRequestDevice failed: %s", r.msg);
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
        return host_fail(err, "creating the pipeline layout: %s", v->error);
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
        return host_fail(err, "compiling %s: %s", path, v->error);
    cpd.layout = v->layout;
    cpd.compute.module = v->shader;
    cpd.compute.entryPoint = sv("main");
    v->pipe = wgpuDeviceCreateComputePipeline(v->dev, &cpd);
    if (v->error[0] || !v->pipe)
        return host_fail(err, "creating the pipeline of %s: %s", path, v->error);
    bd.usage = WGPUBufferUsage_Uniform | WGPUBufferUsage_CopyDst;
    bd.size = HOST_PARAMS_BYTES;
    v->params = wgpuDeviceCreateBuffer(v->dev, &bd);
    if (v->error[0] || !v->params)
        return host_fail(err, "creating the uniform buffer: %s", v->error);
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
        return host_fail(err, "creating buffers of %" PRIu64 ", %" PRIu64 " and %" PRIu64
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
            return host_fail(err, "mapping the read-back buffer failed: %s %s", r[i].msg, v->error);
        v->mapped[i] = wgpuBufferGetConstMappedRange(v->read[i], 0, (size_t)v->size[i]);
        if (!v->mapped[i])
            return host_fail(err, "wgpuBufferGetConstMappedRange failed: %s", v->error);
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
        return host_fail(err, "the dispatch (%" PRIu32 " x %" PRIu32 " groups): %s", gx, gy,
                         v->error);
    return wg_map(v, nb, err);
}

/* ---- the device as host_run drives it ---- */

/* The largest storage binding: maxStorageBufferBindingSize, within maxBufferSize. */
static uint64_t wg_max_binding(const wgctx *v)
{
    uint64_t b = v->limits.maxStorageBufferBindingSize;
    return b < v->limits.maxBufferSize ? b : v->limits.maxBufferSize;
}

/* host_device.alloc: buffers of cp_bytes, cls_words and val_words, their read-back copies and
 * the bind group. */
static int wg_alloc(void *ctx, uint64_t cp_bytes, uint64_t cls_words, uint64_t val_words,
                    char *err)
{
    wgctx *v = ctx;
    size_t most = (size_t)(cls_words > val_words ? cls_words : val_words) * 4;
    wg_free_buffers(v);
    v->size[0] = cp_bytes;
    v->size[1] = cls_words * 4;
    v->size[2] = val_words * 4;
    v->fill = malloc(most);
    if (!v->fill)
        return host_fail(err, "out of memory for %zu bytes", most);
    memset(v->fill, 0xFF, most);
    return wg_bind_buffers(v, err);
}

/* host_device.upload: queue writes, ordered before the next dispatch. */
static int wg_upload(void *ctx, const void *cp, size_t bytes, char *err)
{
    wgctx *v = ctx;
    wgpuQueueWriteBuffer(v->queue, v->bufs[0], 0, cp, bytes);
    for (int b = 1; b < v->nbuf; b++)
        wgpuQueueWriteBuffer(v->queue, v->bufs[b], 0, v->fill, (size_t)v->size[b]);
    return v->error[0] ? host_fail(err, "writing the buffers: %s", v->error) : 0;
}

/* host_device.run: the results are read from the mapped read-back buffers. */
static int wg_run_mapped(void *ctx, const float eye[4], uint32_t n, uint32_t gx, uint32_t gy,
                         int values, const uint32_t *out[2], char *err)
{
    wgctx *v = ctx;
    if (wg_run(v, eye, n, gx, gy, values ? 3 : 2, err))
        return -1;
    out[0] = v->mapped[1];
    out[1] = values ? v->mapped[2] : NULL;
    return 0;
}

static void wg_release(void *ctx)
{
    wg_unmap(ctx);
}

/* ---- main ---- */

int main(int argc, char **argv)
{
    kref_args o;
    char msg[HOST_ERRSZ];
    kref_ref ref;
    wgctx v;
    char *src = NULL;
    int ok = 0, rc;
    long runs;

    rc = kref_start(&o, &ref, &runs, argc, argv, "host_wgpu", KREF_NEED_FILE | KREF_NEED_BLOCK);
    if (rc)
        return rc;
    if (o.groups_x_constant) {
        check(0, o.label, "--groups-x-constant: WGSL kernels read @builtin(num_workgroups)");
        kref_clear(&ref);
        return 2;
    }
    memset(&v, 0, sizeof v);
    v.nbuf = o.planes ? 3 : 2;

#define SETUP_FAIL(...)                                                                        \
    do {                                                                                       \
        check(0, o.label, __VA_ARGS__);                                                        \
        goto done;                                                                             \
    } while (0)

    if (!(src = wgsl_read(o.file, msg)) || wgsl_check_size(src, o.file, o.pq, msg))
        SETUP_FAIL("%s", msg);
    if (wg_setup_device(&v, msg) ||
        host_check_group(&o, v.limits.maxComputeInvocationsPerWorkgroup,
                         v.limits.maxComputeWorkgroupSizeX, msg))
        SETUP_FAIL("%s", msg);
    if (wg_setup_pipeline(&v, src, o.file, msg))
        SETUP_FAIL("%s", msg);
    {
        host_device d = {&v, wg_alloc, wg_upload, wg_run_mapped, wg_release};
        /* --groups-x-constant was refused above: the kernel line names no push constants */
        ok = host_run_kernel(&d, &o, &ref, runs, wg_max_binding(&v),
                             v.limits.maxComputeWorkgroupsPerDimension,
                             v.limits.maxComputeWorkgroupsPerDimension);
    }

done:
#undef SETUP_FAIL
    fflush(stdout);
    wg_teardown(&v);
    free(src);
    kref_clear(&ref);
    return ok && !check_exit() ? 0 : 1;
}
