/* vkx.c: instance, device choice, queue, command pool, buffers, image memory and shader modules
 * for the renderer; every failure a message, never an exit. */
#include "vkx.h"

#include "vk_result.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int vkx_fail(char *err, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(err, VKX_ERRSZ, fmt, ap);
    va_end(ap);
    return -1;
}

int vkx_check(VkResult r, const char *what, char *err)
{
    return r == VK_SUCCESS ? 0 : vkx_fail(err, "%s failed: %s (%d)", what, vk_result_name(r), (int)r);
}

const char *vkx_type_name(VkPhysicalDeviceType t)
{
    switch (t) {
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return "integrated-gpu";
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return "discrete-gpu";
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return "virtual-gpu";
    case VK_PHYSICAL_DEVICE_TYPE_CPU: return "cpu";
    default: return "other";
    }
}

/* The first queue family with graphics and compute, or UINT32_MAX. */
static uint32_t graphics_family(VkPhysicalDevice d, uint32_t *ts_bits)
{
    uint32_t n = 0, found = UINT32_MAX;
    VkQueueFamilyProperties *q;
    vkGetPhysicalDeviceQueueFamilyProperties(d, &n, NULL);
    if (!(q = malloc((n ? n : 1) * sizeof *q)))
        return UINT32_MAX;
    vkGetPhysicalDeviceQueueFamilyProperties(d, &n, q);
    for (uint32_t i = 0; i < n && found == UINT32_MAX; i++)
        if ((q[i].queueFlags & VK_QUEUE_GRAPHICS_BIT) && (q[i].queueFlags & VK_QUEUE_COMPUTE_BIT)) {
            found = i;
            *ts_bits = q[i].timestampValidBits;
        }
    free(q);
    return found;
}

/* The index of the device to use among n: index itself, or the first GPU, else 0. */
static int choose(const VkPhysicalDevice *devs, uint32_t n, int index, char *err)
{
    if (index >= 0)
        return (uint32_t)index < n ? index
                                   : vkx_fail(err, "no Vulkan device %d (there are %u)", index, n);
    for (uint32_t i = 0; i < n; i++) {
        VkPhysicalDeviceProperties p;
        vkGetPhysicalDeviceProperties(devs[i], &p);
        if (p.deviceType == VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU ||
            p.deviceType == VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU)
            return (int)i;
    }
    return 0;
}

/* Picks the physical device and its queue family, and checks its features. */
static int pick(vkx *v, int index, char *err)
{
    VkPhysicalDevice *devs;
    VkPhysicalDeviceFeatures f;
    uint32_t n = 0;
    int i;
    if (vkx_check(vkEnumeratePhysicalDevices(v->inst, &n, NULL), "vkEnumeratePhysicalDevices",
                  err))
        return -1;
    if (n == 0)
        return vkx_fail(err, "no Vulkan device");
    if (!(devs = malloc(n * sizeof *devs)))
        return vkx_fail(err, "out of memory");
    if (vkx_check(vkEnumeratePhysicalDevices(v->inst, &n, devs), "vkEnumeratePhysicalDevices",
                  err) ||
        (i = choose(devs, n, index, err)) < 0) {
        free(devs);
        return -1;
    }
    v->phys = devs[i];
    v->index = (uint32_t)i;
    free(devs);
    vkGetPhysicalDeviceProperties(v->phys, &v->props);
    vkGetPhysicalDeviceMemoryProperties(v->phys, &v->memprops);
    vkGetPhysicalDeviceFeatures(v->phys, &f);
    if ((v->qfam = graphics_family(v->phys, &v->ts_valid_bits)) == UINT32_MAX)
        return vkx_fail(err, "device %d (%s) has no graphics and compute queue", i,
                        v->props.deviceName);
    if (!f.tessellationShader || !f.pipelineStatisticsQuery || !f.vertexPipelineStoresAndAtomics)
        return vkx_fail(err, "device %d (%s) lacks tessellation shaders, pipeline statistics or "
                             "stores from the tessellation stages",
                        i, v->props.deviceName);
    return 0;
}

/* The logical device with one queue, the three features, and a command pool. */
static int make_device(vkx *v, char *err)
{
    float prio = 1.0f;
    VkDeviceQueueCreateInfo qci = {VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO, NULL, 0, v->qfam, 1,
                                   &prio};
    VkPhysicalDeviceFeatures f;
    VkDeviceCreateInfo dci;
    VkCommandPoolCreateInfo cpi = {VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO, NULL,
                                   VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT, v->qfam};
    memset(&f, 0, sizeof f);
    f.tessellationShader = VK_TRUE;
    f.pipelineStatisticsQuery = VK_TRUE;
    f.vertexPipelineStoresAndAtomics = VK_TRUE; /* ptp-tcs: the TCS writes the classes */
    memset(&dci, 0, sizeof dci);
    dci.sType = VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO;
    dci.queueCreateInfoCount = 1;
    dci.pQueueCreateInfos = &qci;
    dci.pEnabledFeatures = &f;
    if (vkx_check(vkCreateDevice(v->phys, &dci, NULL, &v->dev), "vkCreateDevice", err))
        return -1;
    vkGetDeviceQueue(v->dev, v->qfam, 0, &v->queue);
    return vkx_check(vkCreateCommandPool(v->dev, &cpi, NULL, &v->cpool), "vkCreateCommandPool",
                     err);
}

int vkx_open(vkx *v, int index, char *err)
{
    VkApplicationInfo app;
    VkInstanceCreateInfo ici;
    memset(v, 0, sizeof *v);
    memset(&app, 0, sizeof app);
    app.sType = VK_STRUCTURE_TYPE_APPLICATION_INFO;
    app.pApplicationName = "ptpgen render";
    app.apiVersion = VK_API_VERSION_1_1;
    memset(&ici, 0, sizeof ici);
    ici.sType = VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO;
    ici.pApplicationInfo = &app;
    if (vkx_check(vkCreateInstance(&ici, NULL, &v->inst), "vkCreateInstance", err))
        return -1;
    if (pick(v, index, err))
        return -1;
    if (v->props.apiVersion < VK_API_VERSION_1_1)
        return vkx_fail(err, "device %u (%s) supports only Vulkan %u.%u", v->index,
                        v->props.deviceName, VK_VERSION_MAJOR(v->props.apiVersion),
                        VK_VERSION_MINOR(v->props.apiVersion));
    return make_device(v, err);
}

void vkx_close(vkx *v)
{
    if (v->dev) {
        vkDeviceWaitIdle(v->dev);
        if (v->cpool)
            vkDestroyCommandPool(v->dev, v->cpool, NULL);
        vkDestroyDevice(v->dev, NULL);
    }
    if (v->inst)
        vkDestroyInstance(v->inst, NULL);
    memset(v, 0, sizeof *v);
}

/* The first memory type allowed by bits with every flag of want, or UINT32_MAX. */
static uint32_t memory_type(const vkx *v, uint32_t bits, VkMemoryPropertyFlags want)
{
    for (uint32_t t = 0; t < v->memprops.memoryTypeCount; t++)
        if ((bits & (1u << t)) && (v->memprops.memoryTypes[t].propertyFlags & want) == want)
            return t;
    return UINT32_MAX;
}

/* Allocates memory of req's size from type; err names what. */
static int allocate(vkx *v, const VkMemoryRequirements *req, uint32_t type, VkDeviceMemory *mem,
                    char *err)
{
    VkMemoryAllocateInfo mai = {VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO, NULL, req->size, type};
    if (type == UINT32_MAX)
        return vkx_fail(err, "no suitable memory type");
    return vkx_check(vkAllocateMemory(v->dev, &mai, NULL, mem), "vkAllocateMemory", err);
}

int vkx_buffer(vkx *v, vkx_buf *b, VkDeviceSize size, VkBufferUsageFlags usage, char *err)
{
    const VkMemoryPropertyFlags want =
        VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
    VkBufferCreateInfo bci;
    VkMemoryRequirements req;
    memset(b, 0, sizeof *b);
    memset(&bci, 0, sizeof bci);
    bci.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO;
    bci.size = size;
    bci.usage = usage;
    bci.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    if (vkx_check(vkCreateBuffer(v->dev, &bci, NULL, &b->buf), "vkCreateBuffer", err))
        return -1;
    vkGetBufferMemoryRequirements(v->dev, b->buf, &req);
    if (allocate(v, &req, memory_type(v, req.memoryTypeBits, want), &b->mem, err) ||
        vkx_check(vkBindBufferMemory(v->dev, b->buf, b->mem, 0), "vkBindBufferMemory", err) ||
        vkx_check(vkMapMemory(v->dev, b->mem, 0, VK_WHOLE_SIZE, 0, &b->map), "vkMapMemory", err))
        return -1;
    b->size = size;
    return 0;
}

void vkx_buffer_free(vkx *v, vkx_buf *b)
{
    if (b->map)
        vkUnmapMemory(v->dev, b->mem);
    if (b->buf)
        vkDestroyBuffer(v->dev, b->buf, NULL);
    if (b->mem)
        vkFreeMemory(v->dev, b->mem, NULL);
    memset(b, 0, sizeof *b);
}

int vkx_image_memory(vkx *v, VkImage image, VkDeviceMemory *mem, char *err)
{
    VkMemoryRequirements req;
    uint32_t t;
    vkGetImageMemoryRequirements(v->dev, image, &req);
    t = memory_type(v, req.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    if (t == UINT32_MAX)
        t = memory_type(v, req.memoryTypeBits, 0);
    return allocate(v, &req, t, mem, err) ||
                   vkx_check(vkBindImageMemory(v->dev, image, *mem, 0), "vkBindImageMemory", err)
               ? -1
               : 0;
}

int vkx_shader(vkx *v, VkShaderModule *m, const uint32_t *code, size_t bytes, char *err)
{
    VkShaderModuleCreateInfo smci = {VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO, NULL, 0, bytes,
                                     code};
    return vkx_check(vkCreateShaderModule(v->dev, &smci, NULL, m), "vkCreateShaderModule", err);
}
