/* emit_cuda.c: the CUDA target.
 * What is CUDA's own is this table; the kernel itself comes from kern_gpu.c and the template. */
#include "emit/kern.h"

/* --host-header: the kernel's arguments in order. */
static const kern_host_slot host_slots[] = {
    {"ARG_POINTS", 0, "const float4 *cp: the control points", 0},
    {"ARG_CLASSES", 1, "unsigned *cls: the classes", 0},
    {"ARG_PLANES", 2, "float *planes: the values d[p*L + P], or NULL", 0},
    {"ARG_EYE", 3, "float4 eye", 0},
    {"ARG_PATCH_COUNT", 4, "unsigned patch_count", 0},
    {"ARG_INDICES", 5, "const unsigned *point_index: the indices, K a patch", KERN_SLOT_INDEXED},
    {"ARG_BOUNDARY", 6, "const unsigned *boundary_mask: the boundary masks, one a patch",
     KERN_SLOT_BOUNDARY},
    {NULL, 0, NULL, 0}};

const kern_target kern_cuda = {
    .name = "cuda",
    .language = "CUDA kernel",
    .template_name = "cuda/kernel.cu",
    .named_kernel = 1,
    .syntax = &kern_c_syntax,
    .uint = "unsigned", .real = "float", .vec4 = "float4",
    .table_qual = "__constant__",
    .func_qual = "static __device__ ",
    .shared_qual = "__shared__",
    .shared_in_body = 1,
    .barrier = "__syncthreads();",
    .mul = "__fmul_rn(%s, %s)", /* not contracted into an FMA */
    .product = "__fmul_rn", /* the same function: a default nvcc build rounds as written */
    .local_id = "threadIdx.x",
    .group_x = "blockIdx.x", .group_y = "blockIdx.y", .groups_x = "gridDim.x",
    .interface =
        " * Kernel <prefix>classify(cp, cls, planes, eye, patch_count), extern \"C\": planes receives\n"
        " * d[p*L + P] when not NULL. Launch P*Q threads per block and ceil(patch_count / Q) blocks,\n"
        " * 1-D or 2-D: block (x, y) handles the patches of block y * gridDim.x + x.\n",
    .indices_decl = ",\n        const unsigned *point_index",
    .boundary_decl = ", const unsigned *boundary_mask",
    .indices_note = " * Argument 5 point_index, the indices (K a patch).\n",
    .boundary_note = " * Argument 6 boundary_mask, the boundary masks (one a patch).\n",
    .fabs = "fabsf", .fmax = "fmaxf",
    .unit_roundoff = 0x1p-24, /* round to nearest */
    /* float4 has no operators; __fsub_rn is never contracted or reassociated */
    .diff = "make_float4(__fsub_rn(%s.x, %s.x), __fsub_rn(%s.y, %s.y), __fsub_rn(%s.z, %s.z),\n"
            "        __fsub_rn(%s.w, %s.w))",
    .bits = "__float_as_uint(%s)",
    .vec2 = "float2", .vec2_make = "make_float2(%s, %s)",
    .fma = "__fmaf_rn(%s, %s, %s)", /* correctly rounded: one rounding */
    .df_table = 1,
    .slp_classify = "static __device__ inline unsigned %s(const float4 cp[%d], float4 eye)\n{",
    .slp_values = "static __device__ inline void %s(const float4 cp[%d], float4 eye, float d[%d])\n{",
    .slp_look = "static __device__ unsigned %s(const float4 cp[%d], float4 eye, unsigned c,\n"
                "                                const unsigned redo[%d])\n{",
    .slp_d = "d[%d]",
    .slp_decl = "const float ",
    .slp_fma = "__fmaf_rn(%s, %s, %s)",
    .slp_cert_u = 0x1p-24, /* __fmaf_rn rounds once */
    .slp_ref = "%s",
    .slp_suffix = ".cuh",
    .slp_language = "CUDA device functions",
    .host_params_note =
        " * Arguments of extern \"C\" __global__ <prefix>classify, in order (cuLaunchKernel's\n"
        " * kernelParams index): (const float4 *cp, unsigned *cls, float *planes, float4 eye,\n"
        " *  unsigned patch_count); planes may be NULL. Block {WORKGROUP_SIZE, 1, 1}, grid\n"
        " * {groups[0], groups[1], 1} from <prefix>dispatch.\n",
    .host_slots = host_slots,
};
