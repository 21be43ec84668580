/* render.h: the renderer's GPU state and its three jobs: resources (res.c), pipelines
 * (pipes.c) and frames (frame.c): transform, cull and tessellated draw of bicubic patches. */
#ifndef RENDER_RENDER_H
#define RENDER_RENDER_H

#include "bez.h"
#include "vkx.h"

/* The cull pass of a frame. */
typedef enum render_method {
    RENDER_NONE,     /* no cull pass: every patch is tessellated */
    RENDER_TCONE,    /* cone.comp on bench/cones.c's TCONE cones */
    RENDER_NCONE,    /* cone.comp on NCONE cones */
    RENDER_PTP,      /* ptpgen's clip-space GLSL kernel: the straight-line program */
    RENDER_PTP_CERT, /* the same with --certified (no second look in GLSL) */
    RENDER_PTP_TABLE, /* the paper's table kernel (--kernel table) */
    RENDER_PTP_TCS,  /* no cull pass: the TCS classifies its patch (--stage function) */
    RENDER_PTP_TCS_CERT /* the same with --certified */
} render_method;

/* Bytes of the compute and of the graphics push constants. */
#define RENDER_CPUSH 80u
#define RENDER_GPUSH 96u

/* Shader modules: the compute passes, the draw's stages and the TCS variants (pipes.c). */
#define RENDER_MODULES 11

/* One camera's per-draw inputs. */
typedef struct render_cam {
    float mvp[16];   /* column-major, clip = mvp * world */
    float eye[4];    /* world eye (w = 1), for the headlight and the cone test */
    float alpha;     /* the ptp kernels' clip-space eye (0, 0, alpha, 0), negated for inward */
} render_cam;

/* Everything on the GPU. Zero-initialise, then render_resources and render_pipelines. */
typedef struct render_gpu {
    vkx vk;
    uint32_t w, h, npatches;
    render_method method;
    int inward;           /* dB/dv x dB/du faces out: front faces wound the other way */
    vkx_buf world, clip, cls, exact, cones, pixels;
    VkImage color, depth;
    VkDeviceMemory color_mem, depth_mem;
    VkImageView color_view, depth_view;
    VkRenderPass pass;
    VkFramebuffer fb;
    VkDescriptorSetLayout cdsl, gdsl;
    VkPipelineLayout clayout, glayout;
    VkDescriptorPool dpool;
    VkDescriptorSet set_xform, set_cull, set_exact, set_gfx;
    VkShaderModule mod[RENDER_MODULES];
    VkPipeline p_xform, p_cull, p_exact, p_gfx;
    uint32_t cull_group;  /* patches per workgroup of p_cull; 0 for RENDER_NONE */
    uint32_t exact_group; /* patches per workgroup of p_exact */
    VkQueryPool ts, stats;
    VkCommandBuffer cmd;
    VkFence fence;
} render_gpu;

/* What one frame measured. */
typedef struct render_stats {
    double cull_ms, draw_ms;           /* GPU timestamps (-1 without them) */
    double xform_wall_ms, cull_wall_ms, draw_wall_ms; /* wall time of each submission */
    double frame_ms;                   /* wall time of the frame, recording included */
    double cull_cpu_ms, draw_cpu_ms, frame_cpu_ms; /* the process's CPU time: on lavapipe, the
                                                      work, whatever else the machine runs */
    uint64_t clip_primitives, tcs_patches, tes_invocations;
} render_stats;

/* Creates the buffers (uploading the model's points, and cones: two vec4 a patch, for the
 * cone methods, else NULL), the colour and depth images, render pass, framebuffer, queries,
 * command buffer and fence. */
int render_resources(render_gpu *g, const bez_model *m, const float *cones, char *err);

/* Creates the shader modules, layouts, descriptor sets and pipelines for g->method. */
int render_pipelines(render_gpu *g, char *err);

/* Creates g->p_gfx, the tessellated draw, from the modules mod (vertex, tessellation control,
 * tessellation evaluation, fragment); gfx.c. */
int render_gfx_pipeline(render_gpu *g, const VkShaderModule mod[4], char *err);

/* Records and runs one frame from cam with factor tess (mode 0) or the overview from ov
 * classified for cam (mode 1) as three submissions, each waited for: the transform pass, the
 * cull pass, the draw. Each is timed on the wall clock as well as by timestamps, because
 * lavapipe's timestamps around a compute dispatch mostly read the same time. Fills *s. The
 * image is then in g->pixels, the classes in g->cls (and g->exact after the overview). */
int render_frame(render_gpu *g, const render_cam *cam, const render_cam *ov, float tess,
                 int overview, render_stats *s, char *err);

/* Destroys everything in g, the device last. */
void render_destroy(render_gpu *g);

#endif
