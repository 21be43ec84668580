{{BANNER}}
[[vk::binding(0, 0)]] StructuredBuffer<float4> cp : register(t0);
[[vk::binding(1, 0)]] RWStructuredBuffer<uint> cls : register(u1);
{{PLANES_BUFFER}}
[[vk::push_constant]] cbuffer Params : register(b0)
{
    float4 eye;
    uint patch_count;
    uint groups_x;
};

{{TABLES}}{{SHARED}}
{{FUNCTIONS}}[numthreads({{BLOCK_THREADS}}, 1, 1)]
void main(uint3 lid3 : SV_GroupThreadID, uint3 gid : SV_GroupID)
{
{{BODY}}}
