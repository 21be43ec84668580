{{BANNER}}
#pragma OPENCL FP_CONTRACT OFF

{{TABLES}}{{FUNCTIONS}}kernel __attribute__((reqd_work_group_size({{BLOCK_THREADS}}, 1, 1)))
void {{PREFIX}}classify(global const float4 *cp, global uint *cls, global float *planes,
                        float4 eye, uint patch_count{{INDEXED}})
{
{{BODY}}}
