#version 450
// cull.tesc: a tessellation control shader for bicubic patches that skips back-facing ones.
// cls[] holds the classes ptpgen's kernel wrote, one per patch: 0 front, 1 back, 2 silhouette.
layout(vertices = 16) out;
layout(location = 0) in vec4 cp_in[];
layout(location = 0) out vec4 cp_out[];
layout(std430, set = 0, binding = 1) readonly buffer Classes { uint cls[]; };
layout(push_constant) uniform Draw { uint first_patch; float level; };

void main()
{
    cp_out[gl_InvocationID] = cp_in[gl_InvocationID];
    // Tessellation factors of 0 discard the patch: nothing of it is tessellated or shaded.
    float t = cls[first_patch + gl_PrimitiveID] == 1u ? 0.0 : level;
    gl_TessLevelOuter = float[4](t, t, t, t);
    gl_TessLevelInner = float[2](t, t);
}
