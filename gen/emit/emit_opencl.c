/* emit_opencl.c: the OpenCL C 1.2 target.
 * What is OpenCL's own is this table; the kernel itself comes from kern_gpu.c and the template. */
#include "emit/kern.h"

static const kern_target opencl = {
    "opencl", "OpenCL C 1.2 kernel", "opencl/kernel.cl", ".cl", 1,
    "uint", "float4", "constant", "", "local", 1, "barrier(CLK_LOCAL_MEM_FENCE);", "", "%s * %s",
    "(uint)get_local_id(0)", "(uint)get_group_id(0)", "(uint)get_group_id(1)",
    "(uint)get_num_groups(0)", NULL,
    " * Kernel <prefix>classify(cp, cls, planes, eye, patch_count): planes receives d[p*L + P] when not\n"
    " * NULL. Work-group size exactly P*Q; ceil(patch_count / Q) work-groups, 1-D or 2-D:\n"
    " * work-group (x, y) handles the patches of block y * num_groups(0) + x.\n",
    "fabs", "fmax"};

int emit_opencl(sbuf *o, const tp_table *t, const out_info *info, ptp_error *err)
{
    return kern_emit_gpu(o, t, info, &opencl, err);
}
