/* frame.c: one frame of the renderer: transform pass, cull pass, tessellated draw (timestamps
 * around the cull pass and the draw, pipeline statistics of the draw), the copy of the image;
 * or the overview, which adds the exact ptp classes and draws every patch from a second camera. */
#define _POSIX_C_SOURCE 200809L
#include "render.h"

#include <math.h>
#include <string.h>
#include <time.h>

#define FRAME_TIMEOUT_NS (600ull * 1000000000ull)

/* Dispatches enough workgroups of per items each for count items, in 2-D past the x limit. */
static void dispatch(render_gpu *g, uint32_t count, uint32_t per)
{
    uint32_t groups = (count + per - 1) / per;
    uint32_t maxx = g->vk.props.limits.maxComputeWorkGroupCount[0];
    uint32_t gx = groups < maxx ? groups : maxx;
    vkCmdDispatch(g->cmd, gx ? gx : 1, gx ? (groups + gx - 1) / gx : 1, 1);
}

/* A global barrier from the src stages' writes to the dst stages' reads. */
static void barrier(render_gpu *g, VkPipelineStageFlags src, VkAccessFlags sa,
                    VkPipelineStageFlags dst, VkAccessFlags da)
{
    VkMemoryBarrier mb = {VK_STRUCTURE_TYPE_MEMORY_BARRIER, NULL, sa, da};
    vkCmdPipelineBarrier(g->cmd, src, dst, 0, 1, &mb, 0, NULL, 0, NULL);
}

/* Runs compute pipeline p with set over count items (per a workgroup) and push constants. */
static void compute(render_gpu *g, VkPipeline p, VkDescriptorSet set, const void *push,
                    uint32_t bytes, uint32_t count, uint32_t per)
{
    vkCmdBindPipeline(g->cmd, VK_PIPELINE_BIND_POINT_COMPUTE, p);
    vkCmdBindDescriptorSets(g->cmd, VK_PIPELINE_BIND_POINT_COMPUTE, g->clayout, 0, 1, &set, 0,
                            NULL);
    vkCmdPushConstants(g->cmd, g->clayout, VK_SHADER_STAGE_COMPUTE_BIT, 0, bytes, push);
    dispatch(g, count, per);
}

/* The transform pass: every control point to clip space, visible to the cull pass and the
 * draw's vertex input afterwards. */
static void transform(render_gpu *g, const render_cam *cam)
{
    struct { float m[16]; uint32_t count, pad[3]; } xp;
    memcpy(xp.m, cam->mvp, sizeof xp.m);
    xp.count = g->npatches * 16;
    memset(xp.pad, 0, sizeof xp.pad);
    compute(g, g->p_xform, g->set_xform, &xp, sizeof xp, xp.count, 64);
    barrier(g, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_WRITE_BIT,
            VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_VERTEX_INPUT_BIT,
            VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_VERTEX_ATTRIBUTE_READ_BIT);
}

/* The cull pass between timestamps 0 and 1 (cone methods: the world eye; ptp: (0, 0, alpha,
 * 0)), then for the overview the exact ptp classes; the classes visible to the TCS. */
static void cull(render_gpu *g, const render_cam *cam, int overview)
{
    struct { float eye[4]; uint32_t count, pad[3]; } cp;
    memset(&cp, 0, sizeof cp);
    cp.count = g->npatches;
    if (g->method == RENDER_TCONE || g->method == RENDER_NCONE)
        memcpy(cp.eye, cam->eye, sizeof cp.eye);
    else
        cp.eye[2] = cam->alpha;
    vkCmdWriteTimestamp(g->cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, g->ts, 0);
    if (g->p_cull != VK_NULL_HANDLE)
        compute(g, g->p_cull, g->set_cull, &cp, sizeof cp, g->npatches, g->cull_group);
    barrier(g, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_WRITE_BIT,
            VK_PIPELINE_STAGE_TESSELLATION_CONTROL_SHADER_BIT, VK_ACCESS_SHADER_READ_BIT);
    vkCmdWriteTimestamp(g->cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, g->ts, 1);
    if (overview) {
        memset(cp.eye, 0, sizeof cp.eye);
        cp.eye[2] = cam->alpha;
        compute(g, g->p_exact, g->set_exact, &cp, sizeof cp, g->npatches, g->exact_group);
        barrier(g, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_WRITE_BIT,
                VK_PIPELINE_STAGE_TESSELLATION_CONTROL_SHADER_BIT, VK_ACCESS_SHADER_READ_BIT);
    }
}

/* Patches per draw call at factor tess: about FRAME_DRAW_VERTICES tessellated vertices a draw
 * ((ceil(tess) + 1)^2 a patch), at least one patch. Lavapipe (Mesa 22.3) slows down far more
 * than the work grows when one draw tessellates many vertices (BigGuy at factor 16 in one draw:
 * 3.9 s; in draws of 56 patches: 0.4 s), so the patches go in draws of this size. */
#define FRAME_DRAW_VERTICES 16384u
static uint32_t draw_patches(float tess)
{
    uint32_t side = (uint32_t)ceilf(tess) + 1, n = FRAME_DRAW_VERTICES / (side * side);
    return n ? n : 1;
}

/* The render pass with the draws of every patch (statistics query around them), timestamps 2
 * and 3 around it, and the copy of the colour image into g->pixels; alpha is the classified
 * camera's (ptp-tcs). */
static void draw(render_gpu *g, const render_cam *view, float alpha, float tess, int overview)
{
    static const VkDeviceSize zero[2] = {0, 0};
    VkClearValue clear[2];
    VkRenderPassBeginInfo rb;
    VkBuffer vb[2] = {g->clip.buf, g->world.buf};
    VkBufferImageCopy copy;
    struct { float mvp[16], eye[4], tess; uint32_t mode; float orient, alpha; } gp;
    memcpy(gp.mvp, view->mvp, sizeof gp.mvp);
    memcpy(gp.eye, view->eye, sizeof gp.eye);
    gp.tess = tess;
    gp.mode = overview ? 1u : 0u;
    gp.orient = g->inward ? -1.0f : 1.0f;
    gp.alpha = alpha; /* the classified camera's, in the overview too */
    memset(clear, 0, sizeof clear);
    clear[0].color.float32[0] = clear[0].color.float32[1] = clear[0].color.float32[2] = 1.0f;
    clear[0].color.float32[3] = 1.0f;
    clear[1].depthStencil.depth = 1.0f;
    memset(&rb, 0, sizeof rb);
    rb.sType = VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO;
    rb.renderPass = g->pass;
    rb.framebuffer = g->fb;
    rb.renderArea.extent.width = g->w;
    rb.renderArea.extent.height = g->h;
    rb.clearValueCount = 2;
    rb.pClearValues = clear;
    vkCmdWriteTimestamp(g->cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, g->ts, 2);
    vkCmdBeginRenderPass(g->cmd, &rb, VK_SUBPASS_CONTENTS_INLINE);
    vkCmdBindPipeline(g->cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, g->p_gfx);
    vkCmdBindDescriptorSets(g->cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, g->glayout, 0, 1,
                            &g->set_gfx, 0, NULL);
    vkCmdPushConstants(g->cmd, g->glayout,
                       VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT |
                           VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT |
                           VK_SHADER_STAGE_FRAGMENT_BIT,
                       0, RENDER_GPUSH, &gp);
    vkCmdBindVertexBuffers(g->cmd, 0, 2, vb, zero);
    vkCmdBeginQuery(g->cmd, g->stats, 0, 0);
    for (uint32_t first = 0, per = draw_patches(tess); first < g->npatches; first += per)
        vkCmdDraw(g->cmd, 16 * (g->npatches - first < per ? g->npatches - first : per), 1,
                  16 * first, 0);
    vkCmdEndQuery(g->cmd, g->stats, 0);
    vkCmdEndRenderPass(g->cmd);
    vkCmdWriteTimestamp(g->cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, g->ts, 3);
    memset(&copy, 0, sizeof copy);
    copy.imageSubresource.aspectMask = VK_IMAGE_ASPECT_COLOR_BIT;
    copy.imageSubresource.layerCount = 1;
    copy.imageExtent.width = g->w;
    copy.imageExtent.height = g->h;
    copy.imageExtent.depth = 1;
    vkCmdCopyImageToBuffer(g->cmd, g->color, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, g->pixels.buf,
                           1, &copy);
    barrier(g, VK_PIPELINE_STAGE_TRANSFER_BIT | VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT |
                   VK_PIPELINE_STAGE_TESSELLATION_CONTROL_SHADER_BIT,
            VK_ACCESS_TRANSFER_WRITE_BIT | VK_ACCESS_SHADER_WRITE_BIT, VK_PIPELINE_STAGE_HOST_BIT,
            VK_ACCESS_HOST_READ_BIT);
}

/* Milliseconds on clock (CLOCK_MONOTONIC, or CLOCK_PROCESS_CPUTIME_ID: every thread's CPU
 * time, lavapipe's included). */
static double clock_ms(clockid_t clock)
{
    struct timespec ts;
    clock_gettime(clock, &ts);
    return (double)ts.tv_sec * 1e3 + (double)ts.tv_nsec / 1e6;
}

/* Reads the timestamps and statistics of the frame just run into *s. */
static int results(render_gpu *g, render_stats *s, char *err)
{
    uint64_t t[4], st[3], mask;
    const VkQueryResultFlags f = VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT;
    if (vkx_check(vkGetQueryPoolResults(g->vk.dev, g->stats, 0, 1, sizeof st, st, sizeof st, f),
                  "vkGetQueryPoolResults", err))
        return -1;
    s->clip_primitives = st[0]; /* in the order of the bits */
    s->tcs_patches = st[1];
    s->tes_invocations = st[2];
    s->cull_ms = s->draw_ms = -1;
    if (!g->vk.ts_valid_bits)
        return 0;
    if (vkx_check(vkGetQueryPoolResults(g->vk.dev, g->ts, 0, 4, sizeof t, t, sizeof *t, f),
                  "vkGetQueryPoolResults", err))
        return -1;
    mask = g->vk.ts_valid_bits >= 64 ? ~0ull : (1ull << g->vk.ts_valid_bits) - 1;
    s->cull_ms = (double)((t[1] - t[0]) & mask) * g->vk.props.limits.timestampPeriod * 1e-6;
    s->draw_ms = (double)((t[3] - t[2]) & mask) * g->vk.props.limits.timestampPeriod * 1e-6;
    return 0;
}

/* Starts recording g->cmd. */
static int begin(render_gpu *g, char *err)
{
    VkCommandBufferBeginInfo bi = {VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO, NULL,
                                   VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT, NULL};
    return vkx_check(vkResetCommandBuffer(g->cmd, 0), "vkResetCommandBuffer", err) ||
                   vkx_check(vkBeginCommandBuffer(g->cmd, &bi), "vkBeginCommandBuffer", err)
               ? -1
               : 0;
}

/* Ends g->cmd, submits it, waits for it; *ms and *cpu = the wall and CPU time of submission
 * and wait. */
static int submit(render_gpu *g, double *ms, double *cpu, char *err)
{
    VkSubmitInfo si;
    double t0, c0;
    if (vkx_check(vkEndCommandBuffer(g->cmd), "vkEndCommandBuffer", err))
        return -1;
    memset(&si, 0, sizeof si);
    si.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO;
    si.commandBufferCount = 1;
    si.pCommandBuffers = &g->cmd;
    t0 = clock_ms(CLOCK_MONOTONIC);
    c0 = clock_ms(CLOCK_PROCESS_CPUTIME_ID);
    if (vkx_check(vkQueueSubmit(g->vk.queue, 1, &si, g->fence), "vkQueueSubmit", err) ||
        vkx_check(vkWaitForFences(g->vk.dev, 1, &g->fence, VK_TRUE, FRAME_TIMEOUT_NS),
                  "waiting for the frame (vkWaitForFences)", err))
        return -1;
    *ms = clock_ms(CLOCK_MONOTONIC) - t0;
    *cpu = clock_ms(CLOCK_PROCESS_CPUTIME_ID) - c0;
    return vkx_check(vkResetFences(g->vk.dev, 1, &g->fence), "vkResetFences", err);
}

int render_frame(render_gpu *g, const render_cam *cam, const render_cam *ov, float tess,
                 int overview, render_stats *s, char *err)
{
    double t0 = clock_ms(CLOCK_MONOTONIC), c0 = clock_ms(CLOCK_PROCESS_CPUTIME_ID), xform_cpu;
    if (begin(g, err))
        return -1;
    vkCmdResetQueryPool(g->cmd, g->ts, 0, 4);
    vkCmdResetQueryPool(g->cmd, g->stats, 0, 1);
    transform(g, cam);
    if (submit(g, &s->xform_wall_ms, &xform_cpu, err) || begin(g, err))
        return -1;
    cull(g, cam, overview);
    if (submit(g, &s->cull_wall_ms, &s->cull_cpu_ms, err) || begin(g, err))
        return -1;
    draw(g, overview ? ov : cam, cam->alpha, tess, overview);
    if (submit(g, &s->draw_wall_ms, &s->draw_cpu_ms, err))
        return -1;
    s->frame_ms = clock_ms(CLOCK_MONOTONIC) - t0;
    s->frame_cpu_ms = clock_ms(CLOCK_PROCESS_CPUTIME_ID) - c0;
    return results(g, s, err);
}
