/* vulkan_cull.c: culls bicubic patches with ptpgen's GLSL kernel on Vulkan, using its host header,
 * and checks every class against the C header. Build (docs/gpu-hosts.md):
 *   ptpgen --degree 3 --target glsl -o ptp_3x3.comp --host-header ptp_3x3_host.h
 *   ptpgen --degree 3 --target c -o ptp_3x3.h
 *   glslangValidator -V ptp_3x3.comp -o ptp_3x3.spv
 *   cc -std=c11 vulkan_cull.c -lvulkan -lm && ./a.out ptp_3x3.spv */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <vulkan/vulkan.h>

#define PTP_3X3_IMPLEMENTATION
#include "ptp_3x3.h"      /* the C header: ptp_3x3_alpha, ptp_3x3_classify */
#include "ptp_3x3_host.h" /* the kernel's host header: bindings, push constants, dispatch */

#define GRID 16 /* GRID x GRID patches on a torus */
#define N (GRID * GRID)
#define CHECK(x) do { VkResult r_ = (x); if (r_ != VK_SUCCESS) { \
    fprintf(stderr, "not ok - vulkan_cull: %s failed (%d)\n", #x, (int)r_); exit(1); } } while (0)

static VkDevice dev;
static VkPhysicalDevice phys;

/* A buffer in host-visible memory (a discrete GPU would rather use device-local memory and a
 * staging copy), mapped at *map. */
static VkBuffer make_buffer(VkDeviceSize size, VkBufferUsageFlags usage, void **map)
{
    VkBufferCreateInfo bi = {.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    VkPhysicalDeviceMemoryProperties mp;
    VkMemoryRequirements req;
    VkMemoryAllocateInfo ai = {.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    VkMemoryPropertyFlags want = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
    VkDeviceMemory mem;
    VkBuffer buf;
    uint32_t t;
    bi.size = size;
    bi.usage = usage;
    CHECK(vkCreateBuffer(dev, &bi, NULL, &buf));
    vkGetBufferMemoryRequirements(dev, buf, &req);
    vkGetPhysicalDeviceMemoryProperties(phys, &mp);
    for (t = 0; t < mp.memoryTypeCount; t++)
        if (req.memoryTypeBits >> t & 1 && (mp.memoryTypes[t].propertyFlags & want) == want)
            break;
    ai.allocationSize = req.size;
    ai.memoryTypeIndex = t;
    CHECK(t < mp.memoryTypeCount ? vkAllocateMemory(dev, &ai, NULL, &mem) : VK_ERROR_FEATURE_NOT_PRESENT);
    CHECK(vkBindBufferMemory(dev, buf, mem, 0));
    CHECK(vkMapMemory(dev, mem, 0, size, 0, map));
    return buf;
}

/* The patches in clip space: a torus of GRID x GRID bicubic patches (control points on the
 * surface), seen by a camera 4 units away, tilted 0.6 rad; proj is Vulkan's perspective with
 * its y flip (column-major, clip = proj * view). */
static void make_patches(float (*cp)[4], float proj[16])
{
    const float fov = 1.0f / tanf(0.5f), zn = 0.1f, zf = 100.0f, c = cosf(0.6f), s = sinf(0.6f);
    int p, k;
    memset(proj, 0, 16 * sizeof *proj);
    proj[0] = fov;                   /* P(0,0) */
    proj[5] = -fov;                  /* P(1,1): Vulkan's y points down */
    proj[10] = zf / (zn - zf);       /* P(2,2): depth 0..1 */
    proj[14] = zn * zf / (zn - zf);  /* P(2,3) */
    proj[11] = -1.0f;                /* P(3,2) */
    for (p = 0; p < N; p++)
        for (k = 0; k < 16; k++) {
            float u = 6.2831853f * ((float)(p % GRID) + (float)(k / 4) / 3.0f) / GRID;
            float v = 6.2831853f * ((float)(p / GRID) + (float)(k % 4) / 3.0f) / GRID;
            float x = (1.0f + 0.4f * cosf(v)) * cosf(u), y = 0.4f * sinf(v);
            float z = (1.0f + 0.4f * cosf(v)) * sinf(u);
            float vx = x, vy = c * y - s * z, vz = s * y + c * z - 4.0f, *o = cp[p * 16 + k];
            int r;
            for (r = 0; r < 4; r++) /* clip = proj * (vx, vy, vz, 1) */
                o[r] = proj[r] * vx + proj[4 + r] * vy + proj[8 + r] * vz + proj[12 + r];
        }
}

static VkShaderModule load_spirv(const char *path)
{
    VkShaderModuleCreateInfo si = {.sType = VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
    VkShaderModule m;
    FILE *f = fopen(path, "rb");
    uint32_t *code = malloc(1 << 22);
    if (!f || !code) {
        fprintf(stderr, "not ok - vulkan_cull: cannot read %s\n", path);
        exit(1);
    }
    si.codeSize = fread(code, 1, 1 << 22, f) & ~(size_t)3;
    si.pCode = code;
    fclose(f);
    CHECK(vkCreateShaderModule(dev, &si, NULL, &m));
    free(code);
    return m;
}

int main(int argc, char **argv)
{
    VkApplicationInfo app = {.sType = VK_STRUCTURE_TYPE_APPLICATION_INFO};
    VkInstanceCreateInfo ii = {.sType = VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
    VkInstance inst;
    VkQueueFamilyProperties qf[16];
    float prio = 1.0f;
    VkDeviceQueueCreateInfo qi = {.sType = VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
    VkPhysicalDeviceFeatures have, feat = {0};
    VkDeviceCreateInfo di = {.sType = VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
    VkPhysicalDeviceProperties props;
    VkQueue queue;
    uint32_t n = 1, q, i, groups[3], count[3] = {0, 0, 0}, wrong = 0;
    float (*cp)[4] = malloc(sizeof(float[4]) * 16 * N), proj[16];
    uint32_t *cls;
    void *map;
    VkBuffer points, classes;
    ptp_3x3_params params = {.patch_count = N}; /* eye below */

    make_patches(cp, proj);
    params.eye[2] = ptp_3x3_alpha(proj, PTP_3X3_COLUMN_MAJOR); /* eye (0, 0, alpha, 0) */

    /* Instance, the first device, a queue family with compute. */
    app.apiVersion = VK_API_VERSION_1_0;
    ii.pApplicationInfo = &app;
    CHECK(vkCreateInstance(&ii, NULL, &inst));
    if (vkEnumeratePhysicalDevices(inst, &n, &phys) < 0 || n == 0) /* VK_INCOMPLETE: more */
        CHECK(VK_ERROR_INITIALIZATION_FAILED);
    n = 16;
    vkGetPhysicalDeviceQueueFamilyProperties(phys, &n, qf);
    for (q = 0; q < n && !(qf[q].queueFlags & VK_QUEUE_COMPUTE_BIT); q++)
        ;
    qi.queueFamilyIndex = q;
    qi.queueCount = 1;
    qi.pQueuePriorities = &prio;
    /* A renderer reads the classes in its tessellation control shader: the feature makes its
     * stage legal in the barrier below. */
    vkGetPhysicalDeviceFeatures(phys, &have);
    feat.tessellationShader = have.tessellationShader;
    di.queueCreateInfoCount = 1;
    di.pQueueCreateInfos = &qi;
    di.pEnabledFeatures = &feat;
    CHECK(vkCreateDevice(phys, &di, NULL, &dev));
    vkGetDeviceQueue(dev, q, 0, &queue);
    vkGetPhysicalDeviceProperties(phys, &props);

    /* The buffers: points read by the compute kernel; classes written by it and, in a renderer,
     * read by the tessellation control shader as a storage buffer too (so STORAGE_BUFFER serves
     * both; add VERTEX_BUFFER or INDIRECT if a later pass reads it that way). */
    points = make_buffer(sizeof(float[4]) * PTP_3X3_POINTS * N, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, &map);
    memcpy(map, cp, sizeof(float[4]) * PTP_3X3_POINTS * N);
    classes = make_buffer(sizeof(uint32_t) * N, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, &map);
    cls = map;
    memset(cls, 0xff, sizeof(uint32_t) * N);

    /* Descriptor set PTP_3X3_SET: the two storage buffers at the host header's bindings. */
    VkDescriptorSetLayoutBinding b[2] = {
        {PTP_3X3_BINDING_POINTS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_COMPUTE_BIT, NULL},
        {PTP_3X3_BINDING_CLASSES, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_COMPUTE_BIT, NULL}};
    VkDescriptorSetLayoutCreateInfo li = {VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO, NULL, 0, 2, b};
    VkDescriptorSetLayout dsl;
    CHECK(vkCreateDescriptorSetLayout(dev, &li, NULL, &dsl));
    VkPushConstantRange pc = {VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(ptp_3x3_params)};
    VkPipelineLayoutCreateInfo pli = {VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO, NULL, 0, 1, &dsl, 1, &pc};
    VkPipelineLayout layout;
    CHECK(vkCreatePipelineLayout(dev, &pli, NULL, &layout));
    VkComputePipelineCreateInfo ci = {.sType = VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
    ci.stage.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
    ci.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
    ci.stage.module = load_spirv(argc > 1 ? argv[1] : "ptp_3x3.spv");
    ci.stage.pName = PTP_3X3_ENTRY;
    ci.layout = layout;
    VkPipeline pipe;
    CHECK(vkCreateComputePipelines(dev, VK_NULL_HANDLE, 1, &ci, NULL, &pipe));

    VkDescriptorPoolSize ps = {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 2};
    VkDescriptorPoolCreateInfo pi = {VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO, NULL, 0, 1, 1, &ps};
    VkDescriptorPool pool;
    CHECK(vkCreateDescriptorPool(dev, &pi, NULL, &pool));
    VkDescriptorSetAllocateInfo ai = {VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO, NULL, pool, 1, &dsl};
    VkDescriptorSet set;
    CHECK(vkAllocateDescriptorSets(dev, &ai, &set));
    VkDescriptorBufferInfo bufs[2] = {{points, 0, VK_WHOLE_SIZE}, {classes, 0, VK_WHOLE_SIZE}};
    VkWriteDescriptorSet w[2] = {
        {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET, NULL, set, PTP_3X3_BINDING_POINTS, 0, 1,
         VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, NULL, &bufs[0], NULL},
        {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET, NULL, set, PTP_3X3_BINDING_CLASSES, 0, 1,
         VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, NULL, &bufs[1], NULL}};
    vkUpdateDescriptorSets(dev, 2, w, 0, NULL);

    /* Record: push constants, the dispatch the host header computes, the barriers. */
    VkCommandPoolCreateInfo cpi = {VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO, NULL, 0, q};
    VkCommandPool cpool;
    CHECK(vkCreateCommandPool(dev, &cpi, NULL, &cpool));
    VkCommandBufferAllocateInfo cai = {VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO, NULL, cpool,
                                       VK_COMMAND_BUFFER_LEVEL_PRIMARY, 1};
    VkCommandBuffer cmd;
    CHECK(vkAllocateCommandBuffers(dev, &cai, &cmd));
    VkCommandBufferBeginInfo bbi = {.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    CHECK(vkBeginCommandBuffer(cmd, &bbi));
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipe);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout, PTP_3X3_SET, 1, &set, 0, NULL);
    vkCmdPushConstants(cmd, layout, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof params, &params);
    ptp_3x3_dispatch(params.patch_count, props.limits.maxComputeWorkGroupCount[0], groups);
    vkCmdDispatch(cmd, groups[0], groups[1], groups[2]);
    /* Compute-shader write -> tessellation-control-shader read: what a renderer records between
     * this dispatch and the draw whose tessellation control shader reads cls[patch] (and sets
     * the tessellation levels of a culled patch to 0). */
    VkMemoryBarrier mb = {VK_STRUCTURE_TYPE_MEMORY_BARRIER, NULL, VK_ACCESS_SHADER_WRITE_BIT,
                          VK_ACCESS_SHADER_READ_BIT};
    if (feat.tessellationShader)
        vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                             VK_PIPELINE_STAGE_TESSELLATION_CONTROL_SHADER_BIT, 0, 1, &mb, 0, NULL, 0, NULL);
    /* Compute-shader write -> host read: this example reads the classes back. */
    mb.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1,
                         &mb, 0, NULL, 0, NULL);
    CHECK(vkEndCommandBuffer(cmd));
    VkSubmitInfo sub = {.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO};
    sub.commandBufferCount = 1;
    sub.pCommandBuffers = &cmd;
    VkFenceCreateInfo fi = {.sType = VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    VkFence fence;
    CHECK(vkCreateFence(dev, &fi, NULL, &fence));
    CHECK(vkQueueSubmit(queue, 1, &sub, fence));
    CHECK(vkWaitForFences(dev, 1, &fence, VK_TRUE, UINT64_MAX));

    /* Every class against the C header's on the same clip-space points. */
    for (i = 0; i < N; i++) {
        unsigned want = ptp_3x3_classify((const float(*)[4])cp + i * 16, params.eye);
        if (cls[i] != want && wrong++ < 5)
            fprintf(stderr, "patch %u: kernel %u, C header %u\n", i, cls[i], want);
        if (want < 3)
            count[want]++;
    }
    if (wrong || !count[0] || !count[1])
        printf("not ok - vulkan_cull: %u of %d classes differ from the C header's (front %u, back %u, "
               "silhouette %u)\n", wrong, N, count[0], count[1], count[2]);
    else
        printf("ok - vulkan_cull: %d patches on %s in %u x %u workgroups, every class the C header's "
               "(front %u, back %u, silhouette %u)\n", N, props.deviceName, groups[0], groups[1],
               count[0], count[1], count[2]);
    vkDestroyDevice(dev, NULL); /* (a real program destroys every object first) */
    vkDestroyInstance(inst, NULL);
    free(cp);
    return wrong || !count[0] || !count[1];
}
