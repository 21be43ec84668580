/* emit_hlsl.c: the HLSL target: a compute shader for Direct3D and, via glslang or DXC, Vulkan.
 * What is HLSL's own is this table; the kernel itself comes from kern_gpu.c and the template. */
#include "emit/kern.h"

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
    .planes_buffer = "[[vk::binding(2, 0)]] RWStructuredBuffer<float> planes : register(u2);\n",
    .interface =
        " * Entry point main. Resources: t0 / Vulkan binding 0 the control points (StructuredBuffer<float4>),\n"
        " * u1 / binding 1 the classes (RWStructuredBuffer<uint>), u2 / binding 2 the values d[p*L + P]\n"
        " * (with --planes); constants in b0 / Vulkan push constants: { float4 eye; uint patch_count;\n"
        " * uint groups_x; }, groups_x = the number of workgroups dispatched along x.\n"
        " * Dispatch ceil(patch_count / Q) workgroups, in 2-D (x, y) when x would exceed the limit:\n"
        " * workgroup (x, y) handles the patches of block y * groups_x + x.\n",
    .fabs = "abs", .fmax = "max",
    .unit_roundoff = 0x1p-24, /* round to nearest */
    .diff = "%s - %s", /* in a precise local: evaluated as written */
    .bits = "asuint(%s)",
    .vec2 = "float2", .vec2_make = "float2(%s, %s)",
    .split_rounds = 1,
    .slp_classify = "uint %s(float4 cp[%d], float4 eye)\n{",
    .slp_values = "void %s(float4 cp[%d], float4 eye, out float d[%d])\n{",
    .slp_d = "d[%d]",
    .slp_decl = "precise float ",
    .slp_fma = "mad(%s, %s, %s)",
    .slp_ref = "%s",
    .slp_suffix = ".hlsli",
    .slp_language = "HLSL functions (Shader Model 5 and later)",
};
