/* emit_glsl.c: the GLSL target: a Vulkan compute shader (#version 450, std430, push constants).
 * What is GLSL's own is this table; the kernel itself comes from kern_gpu.c and the template. */
#include "emit/kern.h"

static const kern_target glsl = {
    "glsl", "GLSL 4.50 compute shader for Vulkan", "glsl/kernel.comp", ".comp", 0,
    "uint", "vec4", "const", "", "shared", 0, "barrier();", "precise ", "%s * %s",
    "gl_LocalInvocationID.x", "gl_WorkGroupID.x", "gl_WorkGroupID.y", "gl_NumWorkGroups.x",
    "layout(std430, set = 0, binding = 2) writeonly buffer Planes { float planes[]; };\n",
    " * Bindings (set 0, std430): 0 control points (readonly vec4[]), 1 classes (uint[]), 2 values\n"
    " * d[p*L + P] (float[], with --planes). Push constants: { vec4 eye; uint patch_count; }.\n"
    " * Dispatch ceil(patch_count / Q) workgroups, in 2-D (x, y) when x would exceed the limit:\n"
    " * workgroup (x, y) handles the patches of block y * num_groups_x + x.\n",
    "abs", "max"};

int emit_glsl(sbuf *o, const tp_table *t, const out_info *info, ptp_error *err)
{
    return kern_emit_gpu(o, t, info, &glsl, err);
}
