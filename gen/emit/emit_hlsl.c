/* emit_hlsl.c: the HLSL target: a compute shader for Direct3D and, via glslang or DXC, Vulkan.
 * What is HLSL's own is this table; the kernel itself comes from kern_gpu.c and the template. */
#include "emit/kern.h"

/* --host-header: the cbuffer Params in b0 (Vulkan: push constants), padded to 16 bytes. */
static const kern_host_field host_params[] = {
    {"float", "eye", 4, 0}, {"uint32_t", "patch_count", 1, 16}, {"uint32_t", "groups_x", 1, 20},
    {"uint32_t", "pad", 2, 24}, {NULL, NULL, 0, 0}};
static const kern_host_slot host_slots[] = {
    {"REGISTER_POINTS", 0, "t0: StructuredBuffer<float4>, the control points (SRV)", 0},
    {"REGISTER_CLASSES", 1, "u1: RWStructuredBuffer<uint>, the classes (UAV)", 0},
    {"REGISTER_PLANES", 2, "u2: RWStructuredBuffer<float>, the values d[p*L + P] (UAV)", KERN_SLOT_PLANES},
    {"REGISTER_INDICES", 4, "t4: StructuredBuffer<uint>, the indices, K a patch (SRV)", KERN_SLOT_INDEXED},
    {"REGISTER_BOUNDARY", 5, "t5: StructuredBuffer<uint>, the boundary masks, one a patch (SRV)",
     KERN_SLOT_BOUNDARY},
    {"REGISTER_PARAMS", 0, "b0: cbuffer Params (CBV or root constants)", 0},
    {"ROOT_CONSTANTS", 6, "32-bit root constants the kernel reads (eye, patch_count, groups_x)", 0},
    {"SET", 0, "Vulkan: descriptor set of the buffers", 0},
    {"BINDING_POINTS", 0, "Vulkan: storage buffer binding of the control points", 0},
    {"BINDING_CLASSES", 1, "Vulkan: storage buffer binding of the classes", 0},
    {"BINDING_PLANES", 2, "Vulkan: storage buffer binding of the values", KERN_SLOT_PLANES},
    {"BINDING_INDICES", 4, "Vulkan: storage buffer binding of the indices", KERN_SLOT_INDEXED},
    {"BINDING_BOUNDARY", 5, "Vulkan: storage buffer binding of the boundary masks", KERN_SLOT_BOUNDARY},
    {NULL, 0, NULL, 0}};

const kern_target kern_hlsl = {
    .name = "hlsl",
    .language = "HLSL compute shader (Direct3D 11/12; Vulkan via glslangValidator -D or DXC)",
    .template_name = "hlsl/kernel.hlsl",
    .syntax = &kern_c_syntax,
    .uint = "uint", .real = "float", .vec4 = "float4",
    .table_qual = "static const",
    .shared_qual = "groupshared",
    .barrier = "GroupMemoryBarrierWithGroupSync();",
    .precise = "precise ",
    .mul = "%s * %s",
    .local_id = "lid3.x",
    .group_x = "gid.x", .group_y = "gid.y", .groups_x = "groups_x",
    .planes_buffer = "PTP_VK_BINDING(2) RWStructuredBuffer<float> planes : register(u2);\n",
    .interface =
        " * Entry point main. Resources: t0 / Vulkan binding 0 the control points (StructuredBuffer<float4>),\n"
        " * u1 / binding 1 the classes (RWStructuredBuffer<uint>), u2 / binding 2 the values d[p*L + P]\n"
        " * (with --planes); constants in b0 / Vulkan push constants: { float4 eye; uint patch_count;\n"
        " * uint groups_x; }, groups_x = the number of workgroups dispatched along x.\n"
        " * Dispatch ceil(patch_count / Q) workgroups, in 2-D (x, y) when x would exceed the limit:\n"
        " * workgroup (x, y) handles the patches of block y * groups_x + x.\n",
    .indices_decl = "PTP_VK_BINDING(4) StructuredBuffer<uint> point_index : register(t4);\n",
    .boundary_decl = "PTP_VK_BINDING(5) StructuredBuffer<uint> boundary_mask : register(t5);\n",
    .indices_note = " * t4 / binding 4 the indices point_index (StructuredBuffer<uint>, K a patch).\n",
    .boundary_note = " * t5 / binding 5 the boundary masks boundary_mask (StructuredBuffer<uint>, one a patch).\n",
    .fabs = "abs", .fmax = "max",
    .unit_roundoff = 0x1p-24, /* round to nearest */
    .diff = "%s - %s", /* in a precise local: evaluated as written */
    .bits = "asuint(%s)",
    .vec2 = "float2", .vec2_make = "float2(%s, %s)",
    .split_rounds = 1,
    .slp_classify = "uint %s(float4 cp[%d], float4 eye)\n{",
    .slp_values = "void %s(float4 cp[%d], float4 eye, out float d[%d])\n{",
    /* no .slp_look: as GLSL's (the same runtime in the tests) */
    .slp_d = "d[%d]",
    .slp_decl = "precise float ",
    .slp_fma = "mad(%s, %s, %s)",
    .slp_cert_u = 0x1p-23 * (1 + 0x1p-20), /* precise mad: a product and a sum */
    .slp_cert_shift = kern_precise_shift,
    .slp_ref = "%s",
    .slp_suffix = ".hlsli",
    .slp_language = "HLSL functions (Shader Model 5 and later)",
    .host_params_note =
        " * cbuffer Params : register(b0) (Vulkan: [[vk::push_constant]]), packed in 16-byte rows;\n"
        " * a constant buffer is sizeof(params) = 32 bytes (pad = 0), root constants the first\n"
        " * ROOT_CONSTANTS 32-bit values. groups_x = groups[0] of <prefix>dispatch.\n",
    .host_params = host_params, .host_params_size = 32, .host_slots = host_slots,
};
