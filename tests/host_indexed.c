/* host_indexed.c: runs a GLSL or HLSL kernel of --kernel indexed (prefix ix_) on Vulkan
 * (lavapipe in the tests) through its host header ix_host.h, and compares every class with the
 * C header's, computed beforehand (tests/osd_check.cpp --dump, tests/indexed_bez.c):
 *
 *   host_indexed SPV DIR LABEL
 *
 * DIR holds raw little-endian arrays: vertices (float4 each), indices (uint32, IX_POINTS a
 * patch), boundary (uint32, one a patch; read where the kernel has IX_BINDING_BOUNDARY), eyes
 * (float4 each: one dispatch each) and classes (uint8, the C header's, eye-major). Prints one
 * "ok - LABEL: ..." line with the number of patch-views and of those that differ (ok: none back
 * against front, at most 1 in 1000 otherwise), or "not ok - LABEL: ..."; exit status 0 on ok.
 * Build: cc -std=c11 -I<dir of ix_host.h> tests/host_indexed.c -lvulkan. */
#include "ix_host.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <vulkan/vulkan.h>

#ifdef IX_BINDING_BOUNDARY
#define NBUF 4 /* points, classes, indices, boundary masks */
#else
#define NBUF 3
#endif

static const char *label = "host_indexed";
static VkDevice dev;
static VkPhysicalDevice phys;

#define CHECK(x) do { VkResult r_ = (x); if (r_ != VK_SUCCESS) { \
    printf("not ok - %s: %s failed (%d)\n", label, #x, (int)r_); exit(1); } } while (0)

/* The file DIR/name (dir NULL: name), whole, in a new buffer of *size bytes (a multiple of
 * unit); exits if not. */
static void *read_file(const char *dir, const char *name, size_t unit, size_t *size)
{
    char path[1024];
    FILE *f;
    void *b;
    long n;
    snprintf(path, sizeof path, "%s%s%s", dir ? dir : "", dir ? "/" : "", name);
    f = fopen(path, "rb");
    if (!f || fseek(f, 0, SEEK_END) || (n = ftell(f)) <= 0 || (size_t)n % unit || fseek(f, 0, SEEK_SET) ||
        !(b = malloc((size_t)n)) || fread(b, 1, (size_t)n, f) != (size_t)n) {
        printf("not ok - %s: cannot read %s (or it is empty, or not whole records)\n", label, path);
        exit(1);
    }
    fclose(f);
    *size = (size_t)n;
    return b;
}

/* A host-visible, coherent storage buffer of size bytes, mapped at *map. */
static VkBuffer make_buffer(VkDeviceSize size, void **map)
{
    VkBufferCreateInfo bi = {.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    VkMemoryAllocateInfo ai = {.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    VkMemoryPropertyFlags want = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
    VkPhysicalDeviceMemoryProperties mp;
    VkMemoryRequirements req;
    VkDeviceMemory mem;
    VkBuffer buf;
    uint32_t t;
    bi.size = size;
    bi.usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
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

/* The instance, the first device and a queue family with compute (its index to *family). */
static VkQueue open_device(uint32_t *family, char name[256])
{
    VkApplicationInfo app = {.sType = VK_STRUCTURE_TYPE_APPLICATION_INFO};
    VkInstanceCreateInfo ii = {.sType = VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
    VkDeviceQueueCreateInfo qi = {.sType = VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
    VkDeviceCreateInfo di = {.sType = VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
    VkQueueFamilyProperties qf[16];
    VkPhysicalDeviceProperties props;
    VkInstance inst;
    VkQueue queue;
    float prio = 1.0f;
    uint32_t n = 1, q;
    app.apiVersion = VK_API_VERSION_1_0;
    ii.pApplicationInfo = &app;
    CHECK(vkCreateInstance(&ii, NULL, &inst));
    if (vkEnumeratePhysicalDevices(inst, &n, &phys) < 0 || n == 0)
        CHECK(VK_ERROR_INITIALIZATION_FAILED);
    n = 16;
    vkGetPhysicalDeviceQueueFamilyProperties(phys, &n, qf);
    for (q = 0; q < n && !(qf[q].queueFlags & VK_QUEUE_COMPUTE_BIT); q++)
        ;
    qi.queueFamilyIndex = q;
    qi.queueCount = 1;
    qi.pQueuePriorities = &prio;
    di.queueCreateInfoCount = 1;
    di.pQueueCreateInfos = &qi;
    CHECK(vkCreateDevice(phys, &di, NULL, &dev));
    vkGetDeviceQueue(dev, q, 0, &queue);
    vkGetPhysicalDeviceProperties(phys, &props);
    snprintf(name, 256, "%s", props.deviceName);
    *family = q;
    return queue;
}

/* The compute pipeline of the SPIR-V file spv over one set of NBUF storage buffers at the host
 * header's bindings, with its push constants; the set, written with bufs, to *set. */
static VkPipeline make_pipeline(const char *spv, const VkBuffer *bufs, VkPipelineLayout *layout,
                                VkDescriptorSet *set)
{
    static const uint32_t binding[NBUF] = {IX_BINDING_POINTS, IX_BINDING_CLASSES, IX_BINDING_INDICES
#ifdef IX_BINDING_BOUNDARY
                                           , IX_BINDING_BOUNDARY
#endif
    };
    VkDescriptorSetLayoutBinding b[NBUF];
    VkDescriptorBufferInfo info[NBUF];
    VkWriteDescriptorSet w[NBUF];
    VkDescriptorSetLayoutCreateInfo li = {VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO, NULL, 0, NBUF, b};
    VkDescriptorSetLayout dsl;
    VkPushConstantRange pc = {VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(ix_params)};
    VkPipelineLayoutCreateInfo pli = {VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO, NULL, 0, 1, &dsl, 1, &pc};
    VkShaderModuleCreateInfo si = {.sType = VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
    VkComputePipelineCreateInfo ci = {.sType = VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
    VkDescriptorPoolSize ps = {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, NBUF};
    VkDescriptorPoolCreateInfo pi = {VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO, NULL, 0, 1, 1, &ps};
    VkDescriptorSetAllocateInfo ai = {VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO, NULL, VK_NULL_HANDLE, 1, &dsl};
    VkPipeline pipe;
    size_t size;
    int k;
    for (k = 0; k < NBUF; k++) {
        b[k] = (VkDescriptorSetLayoutBinding){binding[k], VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1,
                                              VK_SHADER_STAGE_COMPUTE_BIT, NULL};
        info[k] = (VkDescriptorBufferInfo){bufs[k], 0, VK_WHOLE_SIZE};
    }
    CHECK(vkCreateDescriptorSetLayout(dev, &li, NULL, &dsl));
    CHECK(vkCreatePipelineLayout(dev, &pli, NULL, layout));
    si.pCode = read_file(NULL, spv, 4, &size);
    si.codeSize = size;
    ci.stage.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
    ci.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
    CHECK(vkCreateShaderModule(dev, &si, NULL, &ci.stage.module));
    ci.stage.pName = IX_ENTRY;
    ci.layout = *layout;
    CHECK(vkCreateComputePipelines(dev, VK_NULL_HANDLE, 1, &ci, NULL, &pipe));
    CHECK(vkCreateDescriptorPool(dev, &pi, NULL, &ai.descriptorPool));
    CHECK(vkAllocateDescriptorSets(dev, &ai, set));
    for (k = 0; k < NBUF; k++)
        w[k] = (VkWriteDescriptorSet){VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET, NULL, *set, binding[k], 0, 1,
                                      VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, NULL, &info[k], NULL};
    vkUpdateDescriptorSets(dev, NBUF, w, 0, NULL);
    return pipe;
}

/* One dispatch of params->patch_count patches, waited for. */
static void run(VkQueue queue, VkCommandBuffer cmd, VkPipeline pipe, VkPipelineLayout layout,
                VkDescriptorSet set, ix_params *params)
{
    VkCommandBufferBeginInfo bbi = {.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    VkMemoryBarrier mb = {VK_STRUCTURE_TYPE_MEMORY_BARRIER, NULL, VK_ACCESS_SHADER_WRITE_BIT,
                          VK_ACCESS_HOST_READ_BIT};
    VkSubmitInfo sub = {.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO};
    VkFenceCreateInfo fi = {.sType = VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    VkFence fence;
    uint32_t groups[3];
    CHECK(vkBeginCommandBuffer(cmd, &bbi));
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipe);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout, IX_SET, 1, &set, 0, NULL);
    ix_dispatch(params->patch_count, 0, groups);
#ifdef IX_ROOT_CONSTANTS /* HLSL: the kernel reads groups_x */
    params->groups_x = groups[0];
#endif
    vkCmdPushConstants(cmd, layout, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof *params, params);
    vkCmdDispatch(cmd, groups[0], groups[1], groups[2]);
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1,
                         &mb, 0, NULL, 0, NULL);
    CHECK(vkEndCommandBuffer(cmd));
    sub.commandBufferCount = 1;
    sub.pCommandBuffers = &cmd;
    CHECK(vkCreateFence(dev, &fi, NULL, &fence));
    CHECK(vkQueueSubmit(queue, 1, &sub, fence));
    CHECK(vkWaitForFences(dev, 1, &fence, VK_TRUE, UINT64_MAX));
    vkDestroyFence(dev, fence, NULL);
}

int main(int argc, char **argv)
{
    size_t nv, ni, ne, nc, np, e, p, views = 0, differ = 0, flips = 0, back = 0;
    void *map[NBUF];
    VkBuffer bufs[NBUF];
    VkPipelineLayout layout;
    VkDescriptorSet set;
    VkCommandPool cpool;
    VkCommandBuffer cmd;
    uint32_t family, *cls;
    char name[256];
    if (argc != 4) {
        fprintf(stderr, "usage: host_indexed SPV DIR LABEL\n");
        return 2;
    }
    label = argv[3];
    const char *dir = argv[2];
    float (*v)[4] = read_file(dir, "vertices", 16, &nv);
    uint32_t *idx = read_file(dir, "indices", 4 * IX_POINTS, &ni);
    float (*eyes)[4] = read_file(dir, "eyes", 16, &ne);
    unsigned char *ref = read_file(dir, "classes", 1, &nc);
    np = ni / (4 * IX_POINTS), ne /= 16;
    if (nc != np * ne) {
        printf("not ok - %s: %zu classes for %zu patches and %zu eyes\n", label, nc, np, ne);
        return 1;
    }
    VkQueue queue = open_device(&family, name);
    bufs[0] = make_buffer(nv, &map[0]);
    memcpy(map[0], v, nv);
    bufs[1] = make_buffer(4 * np, &map[1]);
    cls = map[1];
    bufs[2] = make_buffer(ni, &map[2]);
    memcpy(map[2], idx, ni);
#ifdef IX_BINDING_BOUNDARY
    size_t nb;
    void *boundary = read_file(dir, "boundary", 4, &nb);
    if (nb != 4 * np) {
        printf("not ok - %s: %zu boundary masks for %zu patches\n", label, nb / 4, np);
        return 1;
    }
    bufs[3] = make_buffer(nb, &map[3]);
    memcpy(map[3], boundary, nb);
#endif
    VkPipeline pipe = make_pipeline(argv[1], bufs, &layout, &set);
    VkCommandPoolCreateInfo cpi = {VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO, NULL,
                                   VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT, family};
    CHECK(vkCreateCommandPool(dev, &cpi, NULL, &cpool));
    VkCommandBufferAllocateInfo cai = {VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO, NULL, cpool,
                                       VK_COMMAND_BUFFER_LEVEL_PRIMARY, 1};
    CHECK(vkAllocateCommandBuffers(dev, &cai, &cmd));
    for (e = 0; e < ne; e++) {
        ix_params params;
        memset(&params, 0, sizeof params);
        memcpy(params.eye, eyes[e], sizeof params.eye);
        params.patch_count = (uint32_t)np;
        memset(cls, 0xff, 4 * np);
        run(queue, cmd, pipe, layout, set, &params);
        for (p = 0; p < np; p++) {
            unsigned want = ref[e * np + p], got = cls[p];
            views++;
            back += want == 1;
            differ += got != want;
            flips += got != want && (got > 2 || got + want == 1); /* back against front, or unwritten */
        }
    }
    int good = flips == 0 && differ * 1000 <= views && back > 0;
    printf("%s - %s: %zu patch-views (%zu patches, %zu eyes) on %s, %zu differ from the C header's, "
           "%zu back against front\n", good ? "ok" : "not ok", label, views, np, ne, name, differ, flips);
    return !good;
}
