/* host_vulkan.c: runs one compiled SPIR-V compute kernel (GLSL or HLSL) over patch sets with
 * Vulkan 1.0 (lavapipe in the tests), checking every class (and, with --planes, every plane
 * value) against the double reference of kref.
 *
 *   host_vulkan SPV --degree N M --space clip|world --rule strict|degenerate
 *               --block-threads PQ --patches-per-block Q [--planes] [--groups-x-constant]
 *               [--certified] [--random SETS COUNT SEED] [--model PATH NEYES SEED]
 *               [--exact SETS COUNT SEED] [--exact-far SETS COUNT SEED] --name LABEL [--bench RUNS]
 *
 * Kernel contract: entry point "main"; std430 storage buffers in set 0: binding 0 the control
 * points (readonly vec4[], point k of patch p at p*K + k), binding 1 the classes (uint[], one per
 * patch), binding 2 the plane values (float[], d[p*L + i]) only with --planes. One 32-byte
 * push-constant range: { vec4 eye; uint patch_count; uint groups_x; 8 bytes padding }, of which
 * GLSL kernels declare eye and patch_count and HLSL kernels also groups_x (--groups-x-constant
 * says so; the host fills groups_x either way). Workgroups of PQ invocations along x, each
 * handling the Q patches of block gl_WorkGroupID.y * groups_x + gl_WorkGroupID.x; the host
 * dispatches ceil(count/Q) groups as (gx, gy), gx = min(groups, 65535), gy = ceil(groups/gx),
 * groups_x = gx. Invocations past patch_count write nothing.
 *
 * The module is checked first: a GLCompute entry point "main", its LocalSize (PQ, 1, 1), and
 * no resource outside set 0 bindings 0..1 (0..2 with --planes). Sets whose buffers would exceed
 * one storage buffer (128 MiB, lavapipe's limit, or the device's maxStorageBufferRange) run in
 * chunks of patches, one dispatch each with patch_count = the chunk size.
 *
 * Output: "# device: ...", kref_report's lines, and one check that the kernel wrote nothing
 * past patch_count (the classes and values buffers are filled with 0xFFFFFFFF before every
 * dispatch and reach past the chunk as far as its last workgroup does; the part past the chunk
 * must come back untouched; unwritten classes in the chunk are caught by kref_check). --random,
 * --model, --exact and --exact-far may each be given more than once; at least one is required.
 * Any setup failure is one "not ok - LABEL: reason" line. Exit status 0 only when every check
 * passed.
 *
 * --bench RUNS (for `make bench`): after each set's checked run, the set's dispatch (with the wait
 * for its fence) and the copy of its classes out of the mapped buffer run RUNS more times
 * (pipeline creation and the upload of the control points excluded), and the best is printed as
 * "# bench: patches=N runs=RUNS best_s=S patches_per_s=R". The set must fit one dispatch. */
#define _POSIX_C_SOURCE 200809L

#include "check.h"
#include "host_run.h"
#include "kref.h"
#include "vk_result.h"

#include <vulkan/vulkan.h>

#include <errno.h>
#include <inttypes.h>
#include <limits.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* How long one dispatch may take before the run is declared hung. */
#define HOST_FENCE_TIMEOUT_NS (600ull * 1000000000ull)
/* The push-constant block: eye, patch_count, groups_x, padding. */
#define HOST_PUSH_BYTES 32u

/* ---- errors ---- */

#define VK_TRY(call, what)                                                                     \
    do {                                                                                       \
        VkResult vk_try_r = (call);                                                            \
        if (vk_try_r != VK_SUCCESS)                                                            \
            return host_fail(err, "%s failed: %s (%d)", (what), vk_result_name(vk_try_r),      \
                             (int)vk_try_r);                                                        \
    } while (0)

/* ---- the SPIR-V module ---- */

typedef struct {
    uint32_t *words;
    size_t nwords;
} spirv;

static int spv_read(spirv *s, const char *path, char *err)
{
    FILE *f = fopen(path, "rb");
    size_t cap = 1 << 16, len = 0;
    unsigned char *buf;
    s->words = NULL;
    s->nwords = 0;
    if (!f)
        return host_fail(err, "cannot open %s: %s", path, strerror(errno));
    buf = malloc(cap);
    for (;;) {
        size_t got;
        if (!buf) {
            fclose(f);
            return host_fail(err, "out of memory reading %s", path);
        }
        got = fread(buf + len, 1, cap - len, f);
        len += got;
        if (len < cap) {
            if (ferror(f)) {
                free(buf);
                fclose(f);
                return host_fail(err, "cannot read %s", path);
            }
            break;
        }
        {
            unsigned char *nb = realloc(buf, cap * 2);
            if (!nb)
                free(buf);
            buf = nb;
            cap *= 2;
        }
    }
    fclose(f);
    if (len < 20 || len % 4) {
        free(buf);
        return host_fail(err, "%s is not SPIR-V (%zu bytes)", path, len);
    }
    s->nwords = len / 4;
    s->words = malloc(len);
    if (!s->words) {
        free(buf);
        return host_fail(err, "out of memory reading %s", path);
    }
    memcpy(s->words, buf, len);
    free(buf);
    if (s->words[0] != 0x07230203u) {
        uint32_t magic = s->words[0];
        free(s->words);
        s->words = NULL;
        return host_fail(err, "%s is not SPIR-V (magic 0x%08" PRIx32 ")", path, magic);
    }
    return 0;
}

/* What the host checks in the module before creating the pipeline. */
typedef struct {
    int has_main;        /* a GLCompute entry point named "main" */
    int has_local_size;  /* an OpExecutionMode LocalSize for it */
    uint32_t local_size[3];
    int nbindings;       /* storage resources found (Binding decorations) */
    uint32_t binding[16], set[16];
} spv_info;

static int spv_scan(const spirv *s, spv_info *info, char *err)
{
    enum {
        OP_ENTRY_POINT = 15, OP_EXECUTION_MODE = 16, OP_DECORATE = 71,
        MODEL_GLCOMPUTE = 5, MODE_LOCAL_SIZE = 17, DEC_BINDING = 33, DEC_SET = 34
    };
    uint32_t main_id = 0;
    uint32_t set_ids[16], set_vals[16];
    int nsets = 0;
    memset(info, 0, sizeof *info);
    /* pass 1: entry point, bindings */
    for (size_t i = 5; i < s->nwords;) {
        uint32_t w = s->words[i], wc = w >> 16, op = w & 0xFFFFu;
        if (wc == 0 || i + wc > s->nwords)
            return host_fail(err, "malformed SPIR-V (instruction at word %zu)", i);
        if (op == OP_ENTRY_POINT && wc >= 4 && s->words[i + 1] == MODEL_GLCOMPUTE) {
            const char *name = (const char *)&s->words[i + 3];
            size_t maxlen = (wc - 3) * 4;
            if (memchr(name, '\0', maxlen) && !strcmp(name, "main")) {
                info->has_main = 1;
                main_id = s->words[i + 2];
            }
        } else if (op == OP_DECORATE && wc >= 4 && s->words[i + 2] == DEC_BINDING) {
            if (info->nbindings < 16) {
                info->binding[info->nbindings] = s->words[i + 3];
                info->set[info->nbindings] = s->words[i + 1]; /* the id for now */
                info->nbindings++;
            }
        } else if (op == OP_DECORATE && wc >= 4 && s->words[i + 2] == DEC_SET) {
            if (nsets < 16) {
                set_ids[nsets] = s->words[i + 1];
                set_vals[nsets] = s->words[i + 3];
                nsets++;
            }
        }
        i += wc;
    }
    /* resolve the descriptor set of every binding (no DescriptorSet decoration means set 0) */
    for (int b = 0; b < info->nbindings; b++) {
        uint32_t id = info->set[b];
        info->set[b] = 0;
        for (int k = 0; k < nsets; k++)
            if (set_ids[k] == id)
                info->set[b] = set_vals[k];
    }
    /* pass 2: the local size of main */
    for (size_t i = 5; info->has_main && i < s->nwords;) {
        uint32_t w = s->words[i], wc = w >> 16, op = w & 0xFFFFu;
        if (op == OP_EXECUTION_MODE && wc >= 6 && s->words[i + 1] == main_id &&
            s->words[i + 2] == MODE_LOCAL_SIZE) {
            info->has_local_size = 1;
            info->local_size[0] = s->words[i + 3];
            info->local_size[1] = s->words[i + 4];
            info->local_size[2] = s->words[i + 5];
        }
        i += wc;
    }
    return 0;
}

/* ---- Vulkan ---- */

typedef struct {
    VkBuffer buf;
    VkDeviceMemory mem;
    void *map;
    VkDeviceSize size;
} hbuf;

typedef struct {
    VkInstance inst;
    VkPhysicalDevice phys;
    VkPhysicalDeviceProperties props;
    VkPhysicalDeviceMemoryProperties memprops;
    uint32_t qfam;
    VkDevice dev;
    VkQueue queue;
    VkShaderModule shader;
    VkDescriptorSetLayout dsl;
    VkPipelineLayout layout;
    VkPipeline pipe;
    VkDescriptorPool dpool;
    VkDescriptorSet dset;
    VkCommandPool cpool;
    VkCommandBuffer cmd;
    VkFence fence;
    int nbindings;  /* 2, or 3 with --planes */
    hbuf bufs[3];   /* control points, classes, plane values */
    int hung;     /* a dispatch did not finish: do not wait for the device when cleaning up */
} vkctx;

static int vk_setup_device(vkctx *v, char *err)
{
    VkApplicationInfo app;
    VkInstanceCreateInfo ici;
    VkPhysicalDevice *devs;
    uint32_t ndev = 0;
    VkResult r;

    memset(&app, 0, sizeof app);
    app.sType = VK_STRUCTURE_TYPE_APPLICATION_INFO;
    app.pApplicationName = "ptpgen host_vulkan";
    app.pEngineName = "ptpgen";
    app.apiVersion = VK_API_VERSION_1_0;
    memset(&ici, 0, sizeof ici);
    ici.sType = VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO;
    ici.pApplicationInfo = &app;
    VK_TRY(vkCreateInstance(&ici, NULL, &v->inst), "vkCreateInstance");

    VK_TRY(vkEnumeratePhysicalDevices(v->inst, &ndev, NULL), "vkEnumeratePhysicalDevices");
    if (ndev == 0)
        return host_fail(err, "no Vulkan device");
    devs = malloc(ndev * sizeof *devs);
    if (!devs)
        return host_fail(err, "out of memory");
    r = vkEnumeratePhysicalDevices(v->inst, &ndev, devs);
    if (r != VK_SUCCESS && r != VK_INCOMPLETE) {
        free(devs);
        return host_fail(err, "vkEnumeratePhysicalDevices failed: %s", vk_result_name(r));
    }
    for (uint32_t d = 0; d < ndev && !v->phys; d++) {
        uint32_t nq = 0;
        VkQueueFamilyProperties *qp;
        vkGetPhysicalDeviceQueueFamilyProperties(devs[d], &nq, NULL);
        qp = malloc((nq ? nq : 1) * sizeof *qp);
        if (!qp) {
            free(devs);
            return host_fail(err, "out of memory");
        }
        vkGetPhysicalDeviceQueueFamilyProperties(devs[d], &nq, qp);
        for (uint32_t q = 0; q < nq; q++)
            if ((qp[q].queueFlags & VK_QUEUE_COMPUTE_BIT) && qp[q].queueCount > 0) {
                v->phys = devs[d];
                v->qfam = q;
                break;
            }
        free(qp);
    }
    free(devs);
    if (!v->phys)
        return host_fail(err, "no Vulkan device with a compute queue (%" PRIu32 " devices)", ndev);
    vkGetPhysicalDeviceProperties(v->phys, &v->props);
    vkGetPhysicalDeviceMemoryProperties(v->phys, &v->memprops);
    printf("# device: %s (Vulkan %u.%u.%u, driver 0x%08" PRIx32 ")\n", v->props.deviceName,
           VK_VERSION_MAJOR(v->props.apiVersion), VK_VERSION_MINOR(v->props.apiVersion),
           VK_VERSION_PATCH(v->props.apiVersion), v->props.driverVersion);
    fflush(stdout);

    {
        float prio = 1.0f;
        VkDeviceQueueCreateInfo qci;
        VkDeviceCreateInfo dci;
        memset(&qci, 0, sizeof qci);
        qci.sType = VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO;
        qci.queueFamilyIndex = v->qfam;
        qci.queueCount = 1;
        qci.pQueuePriorities = &prio;
        memset(&dci, 0, sizeof dci);
        dci.sType = VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO;
        dci.queueCreateInfoCount = 1;
        dci.pQueueCreateInfos = &qci;
        VK_TRY(vkCreateDevice(v->phys, &dci, NULL, &v->dev), "vkCreateDevice");
    }
    vkGetDeviceQueue(v->dev, v->qfam, 0, &v->queue);
    return 0;
}

/* Creates the shader module of code and the layouts: nbindings storage buffers at bindings 0..
 * nbindings-1, and HOST_PUSH_BYTES of push constants (failing if the device allows fewer). */
static int vk_setup_layouts(vkctx *v, const spirv *code, int nbindings, char *err)
{
    VkDescriptorSetLayoutBinding b[3];
    {
        VkShaderModuleCreateInfo smci;
        memset(&smci, 0, sizeof smci);
        smci.sType = VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO;
        smci.codeSize = code->nwords * 4;
        smci.pCode = code->words;
        VK_TRY(vkCreateShaderModule(v->dev, &smci, NULL, &v->shader), "vkCreateShaderModule");
    }
    {
        VkDescriptorSetLayoutCreateInfo dslci;
        memset(b, 0, sizeof b);
        for (int i = 0; i < nbindings; i++) {
            b[i].binding = (uint32_t)i;
            b[i].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
            b[i].descriptorCount = 1;
            b[i].stageFlags = VK_SHADER_STAGE_COMPUTE_BIT;
        }
        memset(&dslci, 0, sizeof dslci);
        dslci.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO;
        dslci.bindingCount = (uint32_t)nbindings;
        dslci.pBindings = b;
        VK_TRY(vkCreateDescriptorSetLayout(v->dev, &dslci, NULL, &v->dsl),
               "vkCreateDescriptorSetLayout");
    }
    {
        VkPushConstantRange pcr;
        VkPipelineLayoutCreateInfo plci;
        if (v->props.limits.maxPushConstantsSize < HOST_PUSH_BYTES)
            return host_fail(err, "device allows only %" PRIu32 " bytes of push constants",
                        v->props.limits.maxPushConstantsSize);
        pcr.stageFlags = VK_SHADER_STAGE_COMPUTE_BIT;
        pcr.offset = 0;
        pcr.size = HOST_PUSH_BYTES;
        memset(&plci, 0, sizeof plci);
        plci.sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO;
        plci.setLayoutCount = 1;
        plci.pSetLayouts = &v->dsl;
        plci.pushConstantRangeCount = 1;
        plci.pPushConstantRanges = &pcr;
        VK_TRY(vkCreatePipelineLayout(v->dev, &plci, NULL, &v->layout), "vkCreatePipelineLayout");
    }
    return 0;
}

/* Creates the compute pipeline of the shader's main on the layout (vk_setup_layouts first). */
static int vk_setup_compute(vkctx *v, char *err)
{
    VkComputePipelineCreateInfo cpci;
    memset(&cpci, 0, sizeof cpci);
    cpci.sType = VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO;
    cpci.stage.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
    cpci.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
    cpci.stage.module = v->shader;
    cpci.stage.pName = "main";
    cpci.layout = v->layout;
    VK_TRY(vkCreateComputePipelines(v->dev, VK_NULL_HANDLE, 1, &cpci, NULL, &v->pipe),
           "vkCreateComputePipelines");
    return 0;
}

/* Creates the descriptor pool for nbindings storage buffers and allocates the one set of the
 * layout from it. */
static int vk_setup_descriptors(vkctx *v, int nbindings, char *err)
{
    VkDescriptorPoolSize ps;
    VkDescriptorPoolCreateInfo dpci;
    VkDescriptorSetAllocateInfo dsai;
    ps.type = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    ps.descriptorCount = (uint32_t)nbindings;
    memset(&dpci, 0, sizeof dpci);
    dpci.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO;
    dpci.maxSets = 1;
    dpci.poolSizeCount = 1;
    dpci.pPoolSizes = &ps;
    VK_TRY(vkCreateDescriptorPool(v->dev, &dpci, NULL, &v->dpool), "vkCreateDescriptorPool");
    memset(&dsai, 0, sizeof dsai);
    dsai.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO;
    dsai.descriptorPool = v->dpool;
    dsai.descriptorSetCount = 1;
    dsai.pSetLayouts = &v->dsl;
    VK_TRY(vkAllocateDescriptorSets(v->dev, &dsai, &v->dset), "vkAllocateDescriptorSets");
    return 0;
}

/* Creates the command pool of the queue's family, its one primary command buffer and the
 * fence (unsignaled). */
static int vk_setup_commands(vkctx *v, char *err)
{
    VkCommandPoolCreateInfo cpi;
    VkCommandBufferAllocateInfo cbai;
    VkFenceCreateInfo fci;
    memset(&cpi, 0, sizeof cpi);
    cpi.sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO;
    cpi.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    cpi.queueFamilyIndex = v->qfam;
    VK_TRY(vkCreateCommandPool(v->dev, &cpi, NULL, &v->cpool), "vkCreateCommandPool");
    memset(&cbai, 0, sizeof cbai);
    cbai.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO;
    cbai.commandPool = v->cpool;
    cbai.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    cbai.commandBufferCount = 1;
    VK_TRY(vkAllocateCommandBuffers(v->dev, &cbai, &v->cmd), "vkAllocateCommandBuffers");
    memset(&fci, 0, sizeof fci);
    fci.sType = VK_STRUCTURE_TYPE_FENCE_CREATE_INFO;
    VK_TRY(vkCreateFence(v->dev, &fci, NULL, &v->fence), "vkCreateFence");
    return 0;
}

/* Everything a dispatch of code needs on v's device (vk_setup_device first): the shader, its
 * layouts and pipeline for nbindings storage buffers, the descriptor set, the command buffer
 * and the fence. 0, or host_fail's -1 with the message in err. */
static int vk_setup_pipeline(vkctx *v, const spirv *code, int nbindings, char *err)
{
    if (vk_setup_layouts(v, code, nbindings, err) || vk_setup_compute(v, err) ||
        vk_setup_descriptors(v, nbindings, err) || vk_setup_commands(v, err))
        return -1;
    return 0;
}

/* Creates a host-visible, coherent, mapped storage buffer of size bytes. */
static int vk_buffer(vkctx *v, hbuf *h, VkDeviceSize size, const char *what, char *err)
{
    VkBufferCreateInfo bci;
    VkMemoryRequirements req;
    VkMemoryAllocateInfo mai;
    const VkMemoryPropertyFlags want =
        VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
    uint32_t type = UINT32_MAX;

    memset(&bci, 0, sizeof bci);
    bci.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO;
    bci.size = size;
    bci.usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
    bci.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    VK_TRY(vkCreateBuffer(v->dev, &bci, NULL, &h->buf), "vkCreateBuffer");
    vkGetBufferMemoryRequirements(v->dev, h->buf, &req);
    for (uint32_t t = 0; t < v->memprops.memoryTypeCount; t++)
        if ((req.memoryTypeBits & (1u << t)) &&
            (v->memprops.memoryTypes[t].propertyFlags & want) == want) {
            type = t;
            break;
        }
    if (type == UINT32_MAX)
        return host_fail(err, "no host-visible coherent memory for the %s buffer", what);
    memset(&mai, 0, sizeof mai);
    mai.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO;
    mai.allocationSize = req.size;
    mai.memoryTypeIndex = type;
    {
        VkResult r = vkAllocateMemory(v->dev, &mai, NULL, &h->mem);
        if (r != VK_SUCCESS)
            return host_fail(err, "vkAllocateMemory of %llu bytes for the %s buffer failed: %s",
                        (unsigned long long)req.size, what, vk_result_name(r));
    }
    VK_TRY(vkBindBufferMemory(v->dev, h->buf, h->mem, 0), "vkBindBufferMemory");
    VK_TRY(vkMapMemory(v->dev, h->mem, 0, VK_WHOLE_SIZE, 0, &h->map), "vkMapMemory");
    h->size = size;
    return 0;
}

static void vk_free_buffers(vkctx *v)
{
    for (int i = 0; i < 3; i++) {
        if (v->bufs[i].map)
            vkUnmapMemory(v->dev, v->bufs[i].mem);
        if (v->bufs[i].buf)
            vkDestroyBuffer(v->dev, v->bufs[i].buf, NULL);
        if (v->bufs[i].mem)
            vkFreeMemory(v->dev, v->bufs[i].mem, NULL);
        memset(&v->bufs[i], 0, sizeof v->bufs[i]);
    }
}

static void vk_teardown(vkctx *v)
{
    if (v->dev) {
        if (v->hung)
            return; /* destroying objects in use is invalid; leave them to process exit */
        vkDeviceWaitIdle(v->dev);
        vk_free_buffers(v);
        if (v->fence)
            vkDestroyFence(v->dev, v->fence, NULL);
        if (v->cpool)
            vkDestroyCommandPool(v->dev, v->cpool, NULL);
        if (v->dpool)
            vkDestroyDescriptorPool(v->dev, v->dpool, NULL);
        if (v->pipe)
            vkDestroyPipeline(v->dev, v->pipe, NULL);
        if (v->layout)
            vkDestroyPipelineLayout(v->dev, v->layout, NULL);
        if (v->dsl)
            vkDestroyDescriptorSetLayout(v->dev, v->dsl, NULL);
        if (v->shader)
            vkDestroyShaderModule(v->dev, v->shader, NULL);
        vkDestroyDevice(v->dev, NULL);
    }
    if (v->inst)
        vkDestroyInstance(v->inst, NULL);
    memset(v, 0, sizeof *v);
}

/* Runs the kernel over patches [0, n) already in the control point buffer. */
static int vk_run(vkctx *v, const float eye[4], uint32_t n, uint32_t gx, uint32_t gy,
                  char *err)
{
    unsigned char push[HOST_PUSH_BYTES];
    uint32_t pc[2];
    VkCommandBufferBeginInfo cbbi;
    VkMemoryBarrier mb;
    VkSubmitInfo si;
    VkResult r;

    memset(push, 0, sizeof push);
    memcpy(push, eye, 16);
    pc[0] = n;  /* patch_count, offset 16 */
    pc[1] = gx; /* groups_x, offset 20 */
    memcpy(push + 16, pc, sizeof pc);

    VK_TRY(vkResetCommandBuffer(v->cmd, 0), "vkResetCommandBuffer");
    memset(&cbbi, 0, sizeof cbbi);
    cbbi.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO;
    cbbi.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    VK_TRY(vkBeginCommandBuffer(v->cmd, &cbbi), "vkBeginCommandBuffer");
    vkCmdBindPipeline(v->cmd, VK_PIPELINE_BIND_POINT_COMPUTE, v->pipe);
    vkCmdBindDescriptorSets(v->cmd, VK_PIPELINE_BIND_POINT_COMPUTE, v->layout, 0, 1, &v->dset,
                            0, NULL);
    vkCmdPushConstants(v->cmd, v->layout, VK_SHADER_STAGE_COMPUTE_BIT, 0, HOST_PUSH_BYTES, push);
    vkCmdDispatch(v->cmd, gx, gy, 1);
    /* make the shader's writes visible to the host reads after the fence */
    memset(&mb, 0, sizeof mb);
    mb.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER;
    mb.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
    mb.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    vkCmdPipelineBarrier(v->cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_HOST_BIT,
                         0, 1, &mb, 0, NULL, 0, NULL);
    VK_TRY(vkEndCommandBuffer(v->cmd), "vkEndCommandBuffer");

    memset(&si, 0, sizeof si);
    si.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO;
    si.commandBufferCount = 1;
    si.pCommandBuffers = &v->cmd;
    VK_TRY(vkQueueSubmit(v->queue, 1, &si, v->fence), "vkQueueSubmit");
    r = vkWaitForFences(v->dev, 1, &v->fence, VK_TRUE, HOST_FENCE_TIMEOUT_NS);
    if (r != VK_SUCCESS) {
        v->hung = 1;
        return host_fail(err, "the dispatch (%" PRIu32 " x %" PRIu32 " groups) did not finish: %s",
                    gx, gy, vk_result_name(r));
    }
    VK_TRY(vkResetFences(v->dev, 1, &v->fence), "vkResetFences");
    return 0;
}

/* ---- the device as host_run drives it ---- */

/* host_device.alloc: buffers of cp_bytes, cls_words and val_words, bound to the descriptors. */
static int vk_alloc(void *ctx, uint64_t cp_bytes, uint64_t cls_words, uint64_t val_words,
                    char *err)
{
    vkctx *v = ctx;
    VkDescriptorBufferInfo dbi[3];
    VkWriteDescriptorSet w[3];
    vk_free_buffers(v);
    if (vk_buffer(v, &v->bufs[0], cp_bytes, "control point", err) ||
        vk_buffer(v, &v->bufs[1], cls_words * 4, "class", err) ||
        (val_words && vk_buffer(v, &v->bufs[2], val_words * 4, "plane value", err)))
        return -1;
    memset(w, 0, sizeof w);
    for (int i = 0; i < v->nbindings; i++) {
        dbi[i].buffer = v->bufs[i].buf;
        dbi[i].offset = 0;
        dbi[i].range = VK_WHOLE_SIZE;
        w[i].sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
        w[i].dstSet = v->dset;
        w[i].dstBinding = (uint32_t)i;
        w[i].descriptorCount = 1;
        w[i].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
        w[i].pBufferInfo = &dbi[i];
    }
    vkUpdateDescriptorSets(v->dev, (uint32_t)v->nbindings, w, 0, NULL);
    return 0;
}

/* host_device.upload: into the mapped memory. */
static int vk_upload(void *ctx, const void *cp, size_t bytes, char *err)
{
    vkctx *v = ctx;
    (void)err;
    memcpy(v->bufs[0].map, cp, bytes);
    for (int i = 1; i < v->nbindings; i++)
        memset(v->bufs[i].map, 0xFF, (size_t)v->bufs[i].size);
    return 0;
}

/* host_device.run: the results are read from the mapped memory. */
static int vk_run_mapped(void *ctx, const float eye[4], uint32_t n, uint32_t gx, uint32_t gy,
                         int values, const uint32_t *out[2], char *err)
{
    vkctx *v = ctx;
    if (vk_run(v, eye, n, gx, gy, err))
        return -1;
    out[0] = v->bufs[1].map;
    out[1] = values ? v->bufs[2].map : NULL;
    return 0;
}

static void vk_release(void *ctx)
{
    (void)ctx;
}

/* ---- main ---- */

int main(int argc, char **argv)
{
    kref_args o;
    char msg[HOST_ERRSZ];
    kref_ref ref;
    spirv code = {NULL, 0};
    spv_info info;
    vkctx v;
    int ok = 0, rc;
    long runs;

    rc = kref_start(&o, &ref, &runs, argc, argv, "host_vulkan", KREF_NEED_FILE | KREF_NEED_BLOCK);
    if (rc)
        return rc;
    memset(&v, 0, sizeof v);

#define SETUP_FAIL(...)                                                                        \
    do {                                                                                       \
        check(0, o.label, __VA_ARGS__);                                                        \
        goto done;                                                                             \
    } while (0)


    /* the module: an entry point main, its workgroup size, its bindings */
    if (spv_read(&code, o.file, msg) || spv_scan(&code, &info, msg))
        SETUP_FAIL("%s", msg);
    if (!info.has_main)
        SETUP_FAIL("%s has no GLCompute entry point named main", o.file);
    if (info.has_local_size && (info.local_size[0] != o.pq || info.local_size[1] != 1 ||
                                info.local_size[2] != 1))
        SETUP_FAIL("%s has workgroup size (%" PRIu32 ", %" PRIu32 ", %" PRIu32
                   "), --block-threads is %zu",
                   o.file, info.local_size[0], info.local_size[1], info.local_size[2], o.pq);
    v.nbindings = o.planes ? 3 : 2;
    for (int b = 0; b < info.nbindings; b++)
        if (info.set[b] != 0 || info.binding[b] >= (uint32_t)v.nbindings)
            SETUP_FAIL("%s uses set %" PRIu32 " binding %" PRIu32 ", the host binds set 0 "
                       "bindings 0..%d%s",
                       o.file, info.set[b], info.binding[b], v.nbindings - 1,
                       o.planes ? "" : " (binding 2 only with --planes)");

    /* the device and the pipeline */
    if (vk_setup_device(&v, msg) ||
        host_check_group(&o, v.props.limits.maxComputeWorkGroupInvocations,
                         v.props.limits.maxComputeWorkGroupSize[0], msg))
        SETUP_FAIL("%s", msg);
    if (vk_setup_pipeline(&v, &code, v.nbindings, msg))
        SETUP_FAIL("%s", msg);
    {
        host_device d = {&v, vk_alloc, vk_upload, vk_run_mapped, vk_release};
        ok = host_run_kernel(&d, &o, &ref, runs, v.props.limits.maxStorageBufferRange,
                             v.props.limits.maxComputeWorkGroupCount[0],
                             v.props.limits.maxComputeWorkGroupCount[1]);
    }

done:
#undef SETUP_FAIL
    fflush(stdout);
    vk_teardown(&v);
    free(code.words);
    kref_clear(&ref);
    return ok && !check_exit() ? 0 : 1;
}
