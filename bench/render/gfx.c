/* gfx.c: the tessellated draw's pipeline: patch lists of 16 control points (clip and world
 * vertex buffers), depth test, back-face culling, a fixed viewport of the whole target. */
#include "render.h"

#include <string.h>

/* The triangles the tessellator emits for layout(quads, ccw) are clockwise in framebuffer
 * coordinates where dB/du x dB/dv faces the eye (Vulkan's tessellation domain origin is upper
 * left); the other way round for inward models. */
#define RENDER_FRONT_FACE(inward)                                                              \
    ((inward) ? VK_FRONT_FACE_COUNTER_CLOCKWISE : VK_FRONT_FACE_CLOCKWISE)

/* The vertex input: binding 0 the clip-space points, binding 1 the world points, one vec4 each. */
static void vertex_input(VkPipelineVertexInputStateCreateInfo *vi,
                         VkVertexInputBindingDescription b[2],
                         VkVertexInputAttributeDescription a[2])
{
    for (uint32_t i = 0; i < 2; i++) {
        b[i].binding = i;
        b[i].stride = 16;
        b[i].inputRate = VK_VERTEX_INPUT_RATE_VERTEX;
        a[i].location = i;
        a[i].binding = i;
        a[i].format = VK_FORMAT_R32G32B32A32_SFLOAT;
        a[i].offset = 0;
    }
    memset(vi, 0, sizeof *vi);
    vi->sType = VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO;
    vi->vertexBindingDescriptionCount = 2;
    vi->pVertexBindingDescriptions = b;
    vi->vertexAttributeDescriptionCount = 2;
    vi->pVertexAttributeDescriptions = a;
}

/* The fixed-function state of the draw. */
typedef struct gfx_state {
    VkPipelineVertexInputStateCreateInfo vi;
    VkVertexInputBindingDescription vb[2];
    VkVertexInputAttributeDescription va[2];
    VkPipelineInputAssemblyStateCreateInfo ia;
    VkPipelineTessellationStateCreateInfo ts;
    VkViewport viewport;
    VkRect2D scissor;
    VkPipelineViewportStateCreateInfo vp;
    VkPipelineRasterizationStateCreateInfo rs;
    VkPipelineMultisampleStateCreateInfo ms;
    VkPipelineDepthStencilStateCreateInfo ds;
    VkPipelineColorBlendAttachmentState cba;
    VkPipelineColorBlendStateCreateInfo cb;
} gfx_state;

static void fixed_state(gfx_state *s, uint32_t w, uint32_t h, int inward)
{
    memset(s, 0, sizeof *s);
    vertex_input(&s->vi, s->vb, s->va);
    s->ia.sType = VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO;
    s->ia.topology = VK_PRIMITIVE_TOPOLOGY_PATCH_LIST;
    s->ts.sType = VK_STRUCTURE_TYPE_PIPELINE_TESSELLATION_STATE_CREATE_INFO;
    s->ts.patchControlPoints = 16;
    s->viewport.width = (float)w;
    s->viewport.height = (float)h;
    s->viewport.maxDepth = 1.0f;
    s->scissor.extent.width = w;
    s->scissor.extent.height = h;
    s->vp.sType = VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO;
    s->vp.viewportCount = 1;
    s->vp.pViewports = &s->viewport;
    s->vp.scissorCount = 1;
    s->vp.pScissors = &s->scissor;
    s->rs.sType = VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO;
    s->rs.polygonMode = VK_POLYGON_MODE_FILL;
    s->rs.cullMode = VK_CULL_MODE_BACK_BIT;
    s->rs.frontFace = RENDER_FRONT_FACE(inward);
    s->rs.lineWidth = 1.0f;
    s->ms.sType = VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO;
    s->ms.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
    s->ds.sType = VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO;
    s->ds.depthTestEnable = VK_TRUE;
    s->ds.depthWriteEnable = VK_TRUE;
    s->ds.depthCompareOp = VK_COMPARE_OP_LESS;
    s->cba.colorWriteMask = VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT |
                            VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT;
    s->cb.sType = VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO;
    s->cb.attachmentCount = 1;
    s->cb.pAttachments = &s->cba;
}

int render_gfx_pipeline(render_gpu *g, const VkShaderModule mod[4], char *err)
{
    static const VkShaderStageFlagBits stage[4] = {
        VK_SHADER_STAGE_VERTEX_BIT, VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT,
        VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT, VK_SHADER_STAGE_FRAGMENT_BIT};
    VkPipelineShaderStageCreateInfo st[4];
    VkGraphicsPipelineCreateInfo ci;
    gfx_state s;
    fixed_state(&s, g->w, g->h, g->inward);
    memset(st, 0, sizeof st);
    for (int i = 0; i < 4; i++) {
        st[i].sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
        st[i].stage = stage[i];
        st[i].module = mod[i];
        st[i].pName = "main";
    }
    memset(&ci, 0, sizeof ci);
    ci.sType = VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO;
    ci.stageCount = 4;
    ci.pStages = st;
    ci.pVertexInputState = &s.vi;
    ci.pInputAssemblyState = &s.ia;
    ci.pTessellationState = &s.ts;
    ci.pViewportState = &s.vp;
    ci.pRasterizationState = &s.rs;
    ci.pMultisampleState = &s.ms;
    ci.pDepthStencilState = &s.ds;
    ci.pColorBlendState = &s.cb;
    ci.layout = g->glayout;
    ci.renderPass = g->pass;
    return vkx_check(vkCreateGraphicsPipelines(g->vk.dev, VK_NULL_HANDLE, 1, &ci, NULL, &g->p_gfx),
                     "vkCreateGraphicsPipelines", err);
}
