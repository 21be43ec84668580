{{BANNER}}
#version 450

layout(local_size_x = {{BLOCK_THREADS}}) in;

layout(std430, set = 0, binding = 0) readonly buffer ControlPoints { vec4 cp[]; };
layout(std430, set = 0, binding = 1) writeonly buffer Classes { uint cls[]; };
{{PLANES_BUFFER}}{{INDEXED}}layout(push_constant) uniform Params { vec4 eye; uint patch_count; };

{{TABLES}}{{SHARED}}
{{FUNCTIONS}}void main()
{
{{BODY}}}
