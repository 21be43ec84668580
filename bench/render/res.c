/* res.c: the renderer's resources: the point, class and cone buffers, the colour and depth
 * targets with their render pass and framebuffer, the query pools, command buffer and fence. */
#include "render.h"

#include <string.h>

#define COLOR_FORMAT VK_FORMAT_R8G8B8A8_UNORM
#define DEPTH_FORMAT VK_FORMAT_D32_SFLOAT

/* The storage and vertex buffers; the world points get w = 1. */
static int buffers(render_gpu *g, const bez_model *m, const float *cones, char *err)
{
    const VkBufferUsageFlags sv =
        VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_VERTEX_BUFFER_BIT;
    const VkBufferUsageFlags st =
        VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;
    VkDeviceSize points = (VkDeviceSize)g->npatches * 16 * 16, classes = g->npatches * 4ull;
    float *w;
    if (vkx_buffer(&g->vk, &g->world, points, sv, err) ||
        vkx_buffer(&g->vk, &g->clip, points, sv, err) ||
        vkx_buffer(&g->vk, &g->cls, classes, st, err) ||
        vkx_buffer(&g->vk, &g->exact, classes, st, err) ||
        vkx_buffer(&g->vk, &g->cones, cones ? classes * 8 : 32,
                   VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, err) ||
        vkx_buffer(&g->vk, &g->pixels, (VkDeviceSize)g->w * g->h * 4,
                   VK_BUFFER_USAGE_TRANSFER_DST_BIT, err))
        return -1;
    w = g->world.map;
    for (size_t k = 0; k < (size_t)g->npatches * 16; k++) {
        memcpy(w + k * 4, m->pts + k * 3, 3 * sizeof *w);
        w[k * 4 + 3] = 1.0f;
    }
    if (cones)
        memcpy(g->cones.map, cones, (size_t)classes * 8);
    memset(g->cls.map, 0, (size_t)classes); /* RENDER_NONE: every patch class 0 */
    memset(g->exact.map, 0, (size_t)classes);
    return 0;
}

/* A 2-D image with its memory and view. */
static int image(render_gpu *g, VkFormat fmt, VkImageUsageFlags usage, VkImageAspectFlags aspect,
                 VkImage *img, VkDeviceMemory *mem, VkImageView *view, char *err)
{
    VkImageCreateInfo ici;
    VkImageViewCreateInfo vci;
    memset(&ici, 0, sizeof ici);
    ici.sType = VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO;
    ici.imageType = VK_IMAGE_TYPE_2D;
    ici.format = fmt;
    ici.extent.width = g->w;
    ici.extent.height = g->h;
    ici.extent.depth = 1;
    ici.mipLevels = 1;
    ici.arrayLayers = 1;
    ici.samples = VK_SAMPLE_COUNT_1_BIT;
    ici.tiling = VK_IMAGE_TILING_OPTIMAL;
    ici.usage = usage;
    ici.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    if (vkx_check(vkCreateImage(g->vk.dev, &ici, NULL, img), "vkCreateImage", err) ||
        vkx_image_memory(&g->vk, *img, mem, err))
        return -1;
    memset(&vci, 0, sizeof vci);
    vci.sType = VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO;
    vci.image = *img;
    vci.viewType = VK_IMAGE_VIEW_TYPE_2D;
    vci.format = fmt;
    vci.subresourceRange.aspectMask = aspect;
    vci.subresourceRange.levelCount = 1;
    vci.subresourceRange.layerCount = 1;
    return vkx_check(vkCreateImageView(g->vk.dev, &vci, NULL, view), "vkCreateImageView", err);
}

/* One subpass: colour (cleared, kept for the copy to g->pixels) and depth (cleared). */
static int render_pass(render_gpu *g, char *err)
{
    VkAttachmentDescription a[2];
    VkAttachmentReference cref = {0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
    VkAttachmentReference dref = {1, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL};
    VkSubpassDescription sub;
    VkSubpassDependency dep[2];
    VkRenderPassCreateInfo rpci;
    memset(a, 0, sizeof a);
    for (int i = 0; i < 2; i++) {
        a[i].format = i ? DEPTH_FORMAT : COLOR_FORMAT;
        a[i].samples = VK_SAMPLE_COUNT_1_BIT;
        a[i].loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
        a[i].storeOp = i ? VK_ATTACHMENT_STORE_OP_DONT_CARE : VK_ATTACHMENT_STORE_OP_STORE;
        a[i].stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
        a[i].stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
        a[i].initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
        a[i].finalLayout = i ? VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL
                             : VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
    }
    memset(&sub, 0, sizeof sub);
    sub.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
    sub.colorAttachmentCount = 1;
    sub.pColorAttachments = &cref;
    sub.pDepthStencilAttachment = &dref;
    memset(dep, 0, sizeof dep);
    dep[0].srcSubpass = VK_SUBPASS_EXTERNAL; /* the previous copy out of the colour image */
    dep[0].srcStageMask = VK_PIPELINE_STAGE_TRANSFER_BIT;
    dep[0].dstStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT |
                          VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT;
    dep[0].srcAccessMask = VK_ACCESS_TRANSFER_READ_BIT;
    dep[0].dstAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT |
                           VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
    dep[1].srcSubpass = 0; /* the copy after the pass */
    dep[1].dstSubpass = VK_SUBPASS_EXTERNAL;
    dep[1].srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
    dep[1].dstStageMask = VK_PIPELINE_STAGE_TRANSFER_BIT;
    dep[1].srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
    dep[1].dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT;
    memset(&rpci, 0, sizeof rpci);
    rpci.sType = VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO;
    rpci.attachmentCount = 2;
    rpci.pAttachments = a;
    rpci.subpassCount = 1;
    rpci.pSubpasses = &sub;
    rpci.dependencyCount = 2;
    rpci.pDependencies = dep;
    return vkx_check(vkCreateRenderPass(g->vk.dev, &rpci, NULL, &g->pass), "vkCreateRenderPass",
                     err);
}

/* The colour and depth images, the render pass and the framebuffer. */
static int targets(render_gpu *g, char *err)
{
    VkImageView views[2];
    VkFramebufferCreateInfo fci;
    if (image(g, COLOR_FORMAT,
              VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
              VK_IMAGE_ASPECT_COLOR_BIT, &g->color, &g->color_mem, &g->color_view, err) ||
        image(g, DEPTH_FORMAT, VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT,
              VK_IMAGE_ASPECT_DEPTH_BIT, &g->depth, &g->depth_mem, &g->depth_view, err) ||
        render_pass(g, err))
        return -1;
    views[0] = g->color_view;
    views[1] = g->depth_view;
    memset(&fci, 0, sizeof fci);
    fci.sType = VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO;
    fci.renderPass = g->pass;
    fci.attachmentCount = 2;
    fci.pAttachments = views;
    fci.width = g->w;
    fci.height = g->h;
    fci.layers = 1;
    return vkx_check(vkCreateFramebuffer(g->vk.dev, &fci, NULL, &g->fb), "vkCreateFramebuffer",
                     err);
}

/* Four timestamps and the pipeline statistics of the draw; the command buffer and fence. */
static int queries(render_gpu *g, char *err)
{
    VkQueryPoolCreateInfo q;
    VkCommandBufferAllocateInfo cbai = {VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO, NULL,
                                        g->vk.cpool, VK_COMMAND_BUFFER_LEVEL_PRIMARY, 1};
    VkFenceCreateInfo fci = {VK_STRUCTURE_TYPE_FENCE_CREATE_INFO, NULL, 0};
    memset(&q, 0, sizeof q);
    q.sType = VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO;
    q.queryType = VK_QUERY_TYPE_TIMESTAMP;
    q.queryCount = 4;
    if (vkx_check(vkCreateQueryPool(g->vk.dev, &q, NULL, &g->ts), "vkCreateQueryPool", err))
        return -1;
    q.queryType = VK_QUERY_TYPE_PIPELINE_STATISTICS;
    q.queryCount = 1;
    q.pipelineStatistics =
        VK_QUERY_PIPELINE_STATISTIC_CLIPPING_PRIMITIVES_BIT |
        VK_QUERY_PIPELINE_STATISTIC_TESSELLATION_CONTROL_SHADER_PATCHES_BIT |
        VK_QUERY_PIPELINE_STATISTIC_TESSELLATION_EVALUATION_SHADER_INVOCATIONS_BIT;
    return vkx_check(vkCreateQueryPool(g->vk.dev, &q, NULL, &g->stats), "vkCreateQueryPool",
                     err) ||
                   vkx_check(vkAllocateCommandBuffers(g->vk.dev, &cbai, &g->cmd),
                             "vkAllocateCommandBuffers", err) ||
                   vkx_check(vkCreateFence(g->vk.dev, &fci, NULL, &g->fence), "vkCreateFence",
                             err)
               ? -1
               : 0;
}

int render_resources(render_gpu *g, const bez_model *m, const float *cones, char *err)
{
    if (m->npatches > UINT32_MAX / 16 || (VkDeviceSize)m->npatches * 256 >
                                             g->vk.props.limits.maxStorageBufferRange)
        return vkx_fail(err, "%zu patches do not fit one storage buffer of this device",
                        m->npatches);
    g->npatches = (uint32_t)m->npatches;
    return buffers(g, m, cones, err) || targets(g, err) || queries(g, err) ? -1 : 0;
}

void render_destroy(render_gpu *g)
{
    VkDevice d = g->vk.dev;
    if (d) {
        vkDeviceWaitIdle(d);
        for (int i = 0; i < RENDER_MODULES; i++)
            if (g->mod[i])
                vkDestroyShaderModule(d, g->mod[i], NULL);
        if (g->fence)
            vkDestroyFence(d, g->fence, NULL);
        if (g->ts)
            vkDestroyQueryPool(d, g->ts, NULL);
        if (g->stats)
            vkDestroyQueryPool(d, g->stats, NULL);
        vkDestroyPipeline(d, g->p_xform, NULL);
        vkDestroyPipeline(d, g->p_cull, NULL);
        vkDestroyPipeline(d, g->p_exact, NULL);
        vkDestroyPipeline(d, g->p_gfx, NULL);
        vkDestroyPipelineLayout(d, g->clayout, NULL);
        vkDestroyPipelineLayout(d, g->glayout, NULL);
        vkDestroyDescriptorPool(d, g->dpool, NULL);
        vkDestroyDescriptorSetLayout(d, g->cdsl, NULL);
        vkDestroyDescriptorSetLayout(d, g->gdsl, NULL);
        vkDestroyFramebuffer(d, g->fb, NULL);
        vkDestroyRenderPass(d, g->pass, NULL);
        vkDestroyImageView(d, g->color_view, NULL);
        vkDestroyImageView(d, g->depth_view, NULL);
        vkDestroyImage(d, g->color, NULL);
        vkDestroyImage(d, g->depth, NULL);
        vkFreeMemory(d, g->color_mem, NULL);
        vkFreeMemory(d, g->depth_mem, NULL);
        vkx_buffer_free(&g->vk, &g->world);
        vkx_buffer_free(&g->vk, &g->clip);
        vkx_buffer_free(&g->vk, &g->cls);
        vkx_buffer_free(&g->vk, &g->exact);
        vkx_buffer_free(&g->vk, &g->cones);
        vkx_buffer_free(&g->vk, &g->pixels);
    }
    vkx_close(&g->vk);
}
