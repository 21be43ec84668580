{{BANNER}}
/* Vulkan's bindings where the compiler targets SPIR-V (DXC -spirv: __spirv__, glslang: VULKAN);
 * FXC and DXC's DXIL read the registers. */
#if defined(__spirv__) || defined(VULKAN)
#define PTP_VK_BINDING(b) [[vk::binding(b, 0)]]
#define PTP_VK_PUSH_CONSTANT [[vk::push_constant]]
#else
#define PTP_VK_BINDING(b)
#define PTP_VK_PUSH_CONSTANT
#endif
PTP_VK_BINDING(0) StructuredBuffer<float4> cp : register(t0);
PTP_VK_BINDING(1) RWStructuredBuffer<uint> cls : register(u1);
{{PLANES_BUFFER}}{{INDEXED}}
PTP_VK_PUSH_CONSTANT cbuffer Params : register(b0)
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
