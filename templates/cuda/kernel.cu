{{BANNER}}
{{TABLES}}{{FUNCTIONS}}extern "C" __global__ void __launch_bounds__({{BLOCK_THREADS}})
{{PREFIX}}classify(const float4 *cp, unsigned *cls, float *planes, float4 eye, unsigned patch_count{{INDEXED}})
{
{{BODY}}}
