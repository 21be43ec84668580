/* emit_cuda.c: the CUDA target.
 * What is CUDA's own is this table; the kernel itself comes from kern_gpu.c and the template. */
#include "emit/kern.h"

static const kern_target cuda = {
    "cuda", "CUDA kernel", "cuda/kernel.cu", ".cu", 1,
    "unsigned", "float4", "__constant__", "static __device__ ", "__shared__", 1, "__syncthreads();", "", "__fmul_rn(%s, %s)",
    "threadIdx.x", "blockIdx.x", "blockIdx.y", "gridDim.x", NULL,
    " * Kernel <prefix>classify(cp, cls, planes, eye, patch_count), extern \"C\": planes receives\n"
    " * d[p*L + P] when not NULL. Launch P*Q threads per block and ceil(patch_count / Q) blocks,\n"
    " * 1-D or 2-D: block (x, y) handles the patches of block y * gridDim.x + x.\n",
    "fabsf", "fmaxf"};

int emit_cuda(sbuf *o, const tp_table *t, const out_info *info, ptp_error *err)
{
    return kern_emit_gpu(o, t, info, &cuda, err);
}
