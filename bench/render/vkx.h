/* vkx.h: the renderer's Vulkan setup: a headless Vulkan 1.1 instance and device (a GPU first,
 * lavapipe otherwise, or the one asked for), host-visible buffers, shader modules, messages. */
#ifndef RENDER_VKX_H
#define RENDER_VKX_H

#include <vulkan/vulkan.h>

#include <stddef.h>
#include <stdint.h>

/* Every message buffer of the renderer has this size. */
#define VKX_ERRSZ 512

/* The device, its queue (graphics and compute) and a command pool. */
typedef struct vkx {
    VkInstance inst;
    VkPhysicalDevice phys;
    VkPhysicalDeviceProperties props;
    VkPhysicalDeviceMemoryProperties memprops;
    uint32_t qfam, index;    /* queue family; the device's index in the enumeration */
    uint32_t ts_valid_bits;  /* of the queue family's timestamps; 0: none */
    VkDevice dev;
    VkQueue queue;
    VkCommandPool cpool;
} vkx;

/* A host-visible, coherent, mapped buffer. */
typedef struct vkx_buf {
    VkBuffer buf;
    VkDeviceMemory mem;
    void *map;
    VkDeviceSize size;
} vkx_buf;

/* Formats a message into err (size VKX_ERRSZ); returns -1. */
int vkx_fail(char *err, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;


/* Returns -1 with "WHAT failed: RESULT" in err when r is not VK_SUCCESS, else 0. */
int vkx_check(VkResult r, const char *what, char *err);

/* Opens device index (or, for index < 0, the first discrete or integrated GPU, else the first
 * device) with a graphics+compute queue, tessellation shaders and pipeline statistics queries.
 * Returns 0, or -1 with a message (no Vulkan, no such device, a missing feature). */
int vkx_open(vkx *v, int index, char *err);

/* Destroys everything vkx_open created (waits for the device first). */
void vkx_close(vkx *v);

/* Creates a mapped host-visible coherent buffer of size bytes with usage. */
int vkx_buffer(vkx *v, vkx_buf *b, VkDeviceSize size, VkBufferUsageFlags usage, char *err);

/* Destroys b (a zeroed b is left alone). */
void vkx_buffer_free(vkx *v, vkx_buf *b);

/* Creates a device-local image memory for image (any type when none is device-local). */
int vkx_image_memory(vkx *v, VkImage image, VkDeviceMemory *mem, char *err);

/* Creates a shader module from SPIR-V words (bytes long). */
int vkx_shader(vkx *v, VkShaderModule *m, const uint32_t *code, size_t bytes, char *err);

/* The device type in words ("cpu", "integrated-gpu", ...). */
const char *vkx_type_name(VkPhysicalDeviceType t);

#endif
