/* pipes.c: the renderer's shader modules (SPIR-V compiled in at build time, ptpgen's kernels
 * and functions among them), descriptor sets, layouts and its four pipelines: transform, cull,
 * the exact ptp classes for the overview, and the tessellated draw (its TCS culls for ptp-tcs). */
#include "render.h"

#include <stdint.h>
#include <string.h>

#include "spv_cone.h"
#include "spv_frag.h"
#include "spv_ptp.h"
#include "spv_ptp_cert.h"
#include "spv_ptp_table.h"
#include "spv_tesc.h"
#include "spv_tesc_ptp.h"
#include "spv_tesc_ptp_cert.h"
#include "spv_tese.h"
#include "spv_vert.h"
#include "spv_xform.h"
#include "ptp_groups.h" /* RENDER_PTP_Q, RENDER_PTP_CERT_Q, RENDER_PTP_TABLE_Q: the kernels' patches
                          * per workgroup */

/* Indices of g->mod. */
enum { M_XFORM, M_CONE, M_PTP, M_PTP_CERT, M_PTP_TABLE, M_VERT, M_TESC, M_TESE, M_FRAG, M_TESC_PTP,
       M_TESC_PTP_CERT, M_COUNT };
_Static_assert(M_COUNT == RENDER_MODULES, "render_gpu's mod[] holds every shader module");

static int modules(render_gpu *g, char *err)
{
    static const struct {
        const uint32_t *code;
        size_t bytes;
    } spv[M_COUNT] = {
        {render_spv_xform, sizeof render_spv_xform},
        {render_spv_cone, sizeof render_spv_cone},
        {render_spv_ptp, sizeof render_spv_ptp},
        {render_spv_ptp_cert, sizeof render_spv_ptp_cert},
        {render_spv_ptp_table, sizeof render_spv_ptp_table},
        {render_spv_vert, sizeof render_spv_vert},
        {render_spv_tesc, sizeof render_spv_tesc},
        {render_spv_tese, sizeof render_spv_tese},
        {render_spv_frag, sizeof render_spv_frag},
        {render_spv_tesc_ptp, sizeof render_spv_tesc_ptp},
        {render_spv_tesc_ptp_cert, sizeof render_spv_tesc_ptp_cert},
    };
    for (int i = 0; i < M_COUNT; i++)
        if (vkx_shader(&g->vk, &g->mod[i], spv[i].code, spv[i].bytes, err))
            return -1;
    return 0;
}

/* A set layout of two storage buffers for stages, and a pipeline layout with push bytes. */
static int layout(render_gpu *g, VkShaderStageFlags sets, VkShaderStageFlags push, uint32_t bytes,
                  VkDescriptorSetLayout *dsl, VkPipelineLayout *pl, char *err)
{
    VkDescriptorSetLayoutBinding b[2];
    VkDescriptorSetLayoutCreateInfo dci;
    VkPushConstantRange pcr = {push, 0, bytes};
    VkPipelineLayoutCreateInfo plci;
    memset(b, 0, sizeof b);
    for (uint32_t i = 0; i < 2; i++) {
        b[i].binding = i;
        b[i].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
        b[i].descriptorCount = 1;
        b[i].stageFlags = sets;
    }
    memset(&dci, 0, sizeof dci);
    dci.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO;
    dci.bindingCount = 2;
    dci.pBindings = b;
    if (vkx_check(vkCreateDescriptorSetLayout(g->vk.dev, &dci, NULL, dsl),
                  "vkCreateDescriptorSetLayout", err))
        return -1;
    memset(&plci, 0, sizeof plci);
    plci.sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO;
    plci.setLayoutCount = 1;
    plci.pSetLayouts = dsl;
    plci.pushConstantRangeCount = 1;
    plci.pPushConstantRanges = &pcr;
    return vkx_check(vkCreatePipelineLayout(g->vk.dev, &plci, NULL, pl), "vkCreatePipelineLayout",
                     err);
}

/* Allocates *set from the pool with layout dsl and points its bindings 0 and 1 at a and b. */
static int bind_set(render_gpu *g, VkDescriptorSetLayout dsl, const vkx_buf *a, const vkx_buf *b,
                    VkDescriptorSet *set, char *err)
{
    VkDescriptorSetAllocateInfo ai = {VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO, NULL,
                                      g->dpool, 1, &dsl};
    VkDescriptorBufferInfo bi[2] = {{a->buf, 0, VK_WHOLE_SIZE}, {b->buf, 0, VK_WHOLE_SIZE}};
    VkWriteDescriptorSet w[2];
    if (vkx_check(vkAllocateDescriptorSets(g->vk.dev, &ai, set), "vkAllocateDescriptorSets", err))
        return -1;
    memset(w, 0, sizeof w);
    for (uint32_t i = 0; i < 2; i++) {
        w[i].sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
        w[i].dstSet = *set;
        w[i].dstBinding = i;
        w[i].descriptorCount = 1;
        w[i].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
        w[i].pBufferInfo = &bi[i];
    }
    vkUpdateDescriptorSets(g->vk.dev, 2, w, 0, NULL);
    return 0;
}

/* The descriptor sets: transform (world -> clip), cull (clip or cones -> classes), exact
 * (clip -> exact classes), and the draw's (classes, exact classes). */
static int sets(render_gpu *g, char *err)
{
    VkDescriptorPoolSize ps = {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 8};
    VkDescriptorPoolCreateInfo dpci = {VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO, NULL, 0, 4,
                                       1, &ps};
    int cone = g->method == RENDER_TCONE || g->method == RENDER_NCONE;
    if (vkx_check(vkCreateDescriptorPool(g->vk.dev, &dpci, NULL, &g->dpool),
                  "vkCreateDescriptorPool", err))
        return -1;
    return bind_set(g, g->cdsl, &g->world, &g->clip, &g->set_xform, err) ||
                   bind_set(g, g->cdsl, cone ? &g->cones : &g->clip, &g->cls, &g->set_cull,
                            err) ||
                   bind_set(g, g->cdsl, &g->clip, &g->exact, &g->set_exact, err) ||
                   bind_set(g, g->gdsl, &g->cls, &g->exact, &g->set_gfx, err)
               ? -1
               : 0;
}

static int compute_pipeline(render_gpu *g, VkShaderModule m, VkPipeline *p, char *err)
{
    VkComputePipelineCreateInfo ci;
    memset(&ci, 0, sizeof ci);
    ci.sType = VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO;
    ci.stage.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
    ci.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
    ci.stage.module = m;
    ci.stage.pName = "main";
    ci.layout = g->clayout;
    return vkx_check(vkCreateComputePipelines(g->vk.dev, VK_NULL_HANDLE, 1, &ci, NULL, p),
                     "vkCreateComputePipelines", err);
}

/* The compute pipelines: transform, the method's cull pass, and ptp strict for the overview. */
static int computes(render_gpu *g, char *err)
{
    static const int cull_mod[] = {-1, M_CONE, M_CONE, M_PTP, M_PTP_CERT, M_PTP_TABLE, -1, -1};
    static const uint32_t group[] = {0, 64, 64, RENDER_PTP_Q, RENDER_PTP_CERT_Q, RENDER_PTP_TABLE_Q, 0, 0};
    g->cull_group = group[g->method];
    g->exact_group = RENDER_PTP_Q;
    if (compute_pipeline(g, g->mod[M_XFORM], &g->p_xform, err) ||
        compute_pipeline(g, g->mod[M_PTP], &g->p_exact, err))
        return -1;
    return cull_mod[g->method] < 0 ? 0
                                    : compute_pipeline(g, g->mod[cull_mod[g->method]], &g->p_cull,
                                                       err);
}

int render_pipelines(render_gpu *g, char *err)
{
    const VkShaderStageFlags gstages = VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT |
                                       VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT |
                                       VK_SHADER_STAGE_FRAGMENT_BIT;
    if (modules(g, err) ||
        layout(g, VK_SHADER_STAGE_COMPUTE_BIT, VK_SHADER_STAGE_COMPUTE_BIT, RENDER_CPUSH, &g->cdsl,
               &g->clayout, err) ||
        layout(g, VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT, gstages, RENDER_GPUSH, &g->gdsl,
               &g->glayout, err) ||
        sets(g, err) || computes(g, err))
        return -1;
    int tesc = g->method == RENDER_PTP_TCS        ? M_TESC_PTP
               : g->method == RENDER_PTP_TCS_CERT ? M_TESC_PTP_CERT
                                                  : M_TESC;
    VkShaderModule gfx[4] = {g->mod[M_VERT], g->mod[tesc], g->mod[M_TESE], g->mod[M_FRAG]};
    return render_gfx_pipeline(g, gfx, err);
}
