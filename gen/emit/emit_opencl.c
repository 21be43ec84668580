/* emit_opencl.c: the OpenCL C 1.2 target.
 * What is OpenCL's own is this table; the kernel itself comes from kern_gpu.c and the template. */
#include "emit/kern.h"

/* --host-header: the kernel's arguments in order. */
static const kern_host_slot host_slots[] = {
    {"ARG_POINTS", 0, "global const float4 *cp: the control points", 0},
    {"ARG_CLASSES", 1, "global uint *cls: the classes", 0},
    {"ARG_PLANES", 2, "global float *planes: the values d[p*L + P], or NULL", 0},
    {"ARG_EYE", 3, "float4 eye (cl_float4)", 0},
    {"ARG_PATCH_COUNT", 4, "uint patch_count (cl_uint)", 0},
    {"ARG_INDICES", 5, "global const uint *point_index: the indices, K a patch", KERN_SLOT_INDEXED},
    {"ARG_BOUNDARY", 6, "global const uint *boundary_mask: the boundary masks, one a patch",
     KERN_SLOT_BOUNDARY},
    {NULL, 0, NULL, 0}};

/* --kernel lanes: 16 patches a work-item in float16 vectors, the points gathered lane by lane;
 * the last work-item's spare lanes repeat the last patch and are not stored. */
static const kern_lanes opencl_lanes = {
    .width = 16,
    .real = "float16",
    .flag = "int16",
    .decl = "const float16 ",
    .point = "/* A coordinate of one control point of 16 patches, patch l in lane l. */\n"
             "typedef struct {\n    float16 x, y, z, w;\n} %slanes;\n\n",
    .classify = "uint16 %s(const %slanes cp[%d], float4 eye)\n{",
    .interface =
        " * Kernel <prefix>classify(cp, cls, planes, eye, patch_count): planes is not written. Work-group\n"
        " * size exactly Q / LANES; ceil(patch_count / Q) work-groups, 1-D or 2-D: work-group (x, y)\n"
        " * handles the patches of block y * num_groups(0) + x, each work-item LANES of them.\n",
    .body = "    uint base = ((uint)get_group_id(1) * (uint)get_num_groups(0) + (uint)get_group_id(0)) * @Q +\n"
            "                (uint)get_local_id(0) * @LANES;\n"
            "    $lanes p[@K];\n"
            "    float x[@LANES], y[@LANES], z[@LANES], w[@LANES];\n"
            "    uint c[@LANES], k, l;\n"
            "    if (base >= patch_count)\n"
            "        return;\n"
            "    for (k = 0u; k < @K; k++) {\n"
            "        for (l = 0u; l < @LANES; l++) {\n"
            "            float4 q = cp[min(base + l, patch_count - 1u) * @K + k];\n"
            "            x[l] = q.x;\n"
            "            y[l] = q.y;\n"
            "            z[l] = q.z;\n"
            "            w[l] = q.w;\n"
            "        }\n"
            "        p[k].x = vload16(0, x);\n"
            "        p[k].y = vload16(0, y);\n"
            "        p[k].z = vload16(0, z);\n"
            "        p[k].w = vload16(0, w);\n"
            "    }\n"
            "    vstore16($classify_lanes(p, eye), 0, c);\n"
            "    for (l = 0u; l < @LANES && base + l < patch_count; l++)\n"
            "        cls[base + l] = c[l];\n",
};

const kern_target kern_opencl = {
    .name = "opencl",
    .language = "OpenCL C 1.2 kernel",
    .template_name = "opencl/kernel.cl",
    .named_kernel = 1,
    .syntax = &kern_c_syntax,
    .uint = "uint", .real = "float", .vec4 = "float4",
    .table_qual = "constant",
    .shared_qual = "local",
    .shared_in_body = 1,
    .barrier = "barrier(CLK_LOCAL_MEM_FENCE);",
    .mul = "%s * %s", /* not contracted: the template sets FP_CONTRACT OFF */
    .local_id = "(uint)get_local_id(0)",
    .group_x = "(uint)get_group_id(0)", .group_y = "(uint)get_group_id(1)",
    .groups_x = "(uint)get_num_groups(0)",
    .interface =
        " * Kernel <prefix>classify(cp, cls, planes, eye, patch_count): planes receives d[p*L + P] when not\n"
        " * NULL. Work-group size exactly P*Q; ceil(patch_count / Q) work-groups, 1-D or 2-D:\n"
        " * work-group (x, y) handles the patches of block y * num_groups(0) + x.\n",
    .indices_decl = ",\n                        global const uint *point_index",
    .boundary_decl = ", global const uint *boundary_mask",
    .indices_note = " * Argument 5 point_index, the indices (K a patch).\n",
    .boundary_note = " * Argument 6 boundary_mask, the boundary masks (one a patch).\n",
    .fabs = "fabs", .fmax = "fmax",
    .unit_roundoff = 0x1p-24, /* round to nearest */
    .diff = "%s - %s", /* C semantics: no reassociation; FP_CONTRACT OFF */
    .bits = "as_uint(%s)",
    .vec2 = "float2", .vec2_make = "(float2)(%s, %s)",
    .fma = "fma(%s, %s, %s)", /* correctly rounded: one rounding */
    .df_table = 1,
    .lanes = &opencl_lanes,
    .slp_classify = "uint %s(const float4 cp[%d], float4 eye)\n{",
    .slp_values = "void %s(const float4 cp[%d], float4 eye, float d[%d])\n{",
    .slp_look = "uint %s(const float4 cp[%d], float4 eye, uint c, const uint redo[%d])\n{",
    .slp_d = "d[%d]",
    .slp_decl = "const float ",
    .slp_fma = "fma(%s, %s, %s)",
    .slp_cert_u = 0x1p-24, /* fma rounds once */
    .slp_ref = "%s",
    .slp_preamble = "#pragma OPENCL FP_CONTRACT OFF\n\n",
    .slp_note = " * The points are private memory (an array the caller copies them into). The file sets\n"
                " * #pragma OPENCL FP_CONTRACT OFF: equal points give exact zeros.\n",
    .slp_suffix = ".cl",
    .slp_language = "OpenCL C 1.2 functions",
    .host_params_note =
        " * Arguments of kernel <prefix>classify, in order (clSetKernelArg index):\n"
        " * (global const float4 *cp, global uint *cls, global float *planes, float4 eye,\n"
        " *  uint patch_count); planes may be NULL. Local size {WORKGROUP_SIZE, 1, 1}, global size\n"
        " * {groups[0] * WORKGROUP_SIZE, groups[1], 1} from <prefix>dispatch.\n",
    .host_slots = host_slots,
};
