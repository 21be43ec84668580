/* emit_glsl.c: the GLSL target: a Vulkan compute shader (#version 450, std430, push constants).
 * What is GLSL's own is this table; the kernel itself comes from kern_gpu.c and the template. */
#include "emit/kern.h"

/* --host-header: the push constants { vec4 eye; uint patch_count; } (std430 and std140 alike). */
static const kern_host_field host_params[] = {
    {"float", "eye", 4, 0}, {"uint32_t", "patch_count", 1, 16}, {NULL, NULL, 0, 0}};
static const kern_host_slot host_slots[] = {
    {"SET", 0, "descriptor set of the buffers", 0},
    {"BINDING_POINTS", 0, "storage buffer: the control points, vec4[] (read)", 0},
    {"BINDING_CLASSES", 1, "storage buffer: the classes, uint[] (written)", 0},
    {"BINDING_PLANES", 2, "storage buffer: the values d[p*L + P], float[] (written)", KERN_SLOT_PLANES},
    {"BINDING_INDICES", 4, "storage buffer: the indices, K a patch, uint[] (read)", KERN_SLOT_INDEXED},
    {"BINDING_BOUNDARY", 5, "storage buffer: the boundary masks, one a patch, uint[] (read)",
     KERN_SLOT_BOUNDARY},
    {NULL, 0, NULL, 0}};

const kern_target kern_glsl = {
    .name = "glsl",
    .language = "GLSL 4.50 compute shader for Vulkan",
    .template_name = "glsl/kernel.comp",
    .syntax = &kern_c_syntax,
    .uint = "uint", .real = "float", .vec4 = "vec4",
    .table_qual = "const",
    .shared_qual = "shared",
    .barrier = "barrier();",
    .precise = "precise ",
    .mul = "%s * %s",
    .local_id = "gl_LocalInvocationID.x",
    .group_x = "gl_WorkGroupID.x", .group_y = "gl_WorkGroupID.y", .groups_x = "gl_NumWorkGroups.x",
    .planes_buffer = "layout(std430, set = 0, binding = 2) writeonly buffer Planes { float planes[]; };\n",
    .interface =
        " * Bindings (set 0, std430): 0 control points (readonly vec4[]), 1 classes (uint[]), 2 values\n"
        " * d[p*L + P] (float[], with --planes). Push constants: { vec4 eye; uint patch_count; }.\n"
        " * Dispatch ceil(patch_count / Q) workgroups, in 2-D (x, y) when x would exceed the limit:\n"
        " * workgroup (x, y) handles the patches of block y * num_groups_x + x.\n",
    .indices_decl = "layout(std430, set = 0, binding = 4) readonly buffer Indices { uint point_index[]; };\n",
    .boundary_decl = "layout(std430, set = 0, binding = 5) readonly buffer Boundary { uint boundary_mask[]; };\n",
    .indices_note = " * Binding 4 the indices point_index (readonly uint[], K a patch).\n",
    .boundary_note = " * Binding 5 the boundary masks boundary_mask (readonly uint[], one a patch).\n",
    .fabs = "abs", .fmax = "max",
    .unit_roundoff = 0x1p-24, /* round to nearest */
    .diff = "%s - %s", /* in a precise local: evaluated as written */
    .bits = "floatBitsToUint(%s)",
    .vec2 = "vec2", .vec2_make = "vec2(%s, %s)",
    .slp_classify = "uint %s(vec4 cp[%d], vec4 eye)\n{",
    .slp_values = "void %s(vec4 cp[%d], vec4 eye, out float d[%d])\n{",
    /* no .slp_look: lavapipe builds the look's constant term tables in every invocation (minutes
     * of compilation, most of the run time); from a storage buffer they would cost little
     * (bench/README) */
    .slp_d = "d[%d]",
    .slp_decl = "precise float ",
    .slp_fma = "fma(%s, %s, %s)",
    .slp_cert_u = 0x1p-23 * (1 + 0x1p-20), /* Vulkan may round fma as a product and a sum */
    .slp_cert_shift = kern_precise_shift,
    .slp_ref = "%s",
    .slp_suffix = ".glsl",
    .slp_language = "GLSL 4.50 functions",
    .host_params_note =
        " * Push constants (layout(push_constant), std430 offsets, the same under std140), stage\n"
        " * VK_SHADER_STAGE_COMPUTE_BIT, range offset 0, size sizeof(params).\n",
    .host_params = host_params, .host_params_size = 20, .host_slots = host_slots,
};
