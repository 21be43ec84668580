/* patch.tesc: reads the patch's class from the cull pass (binding 0), or with PTP_TCS defined
 * classifies the patch itself (ptpgen's --stage function) and writes the class there: a
 * back-facing patch (class 1) gets every factor 0 and is discarded before evaluation; every
 * other patch the uniform factor. The overview draws every patch and passes both classes on. The patch's index
 * comes from the vertex shader (gl_VertexIndex / 16): lavapipe (Mesa 22.3) gives the TCS a
 * gl_PrimitiveID that is not the patch's index in the draw. */
#version 450
#extension GL_GOOGLE_include_directive : require
layout(vertices = 16) out;
#include "params.glsl"

#ifdef PTP_TCS
#include "ptp_3x3.glsl"
layout(std430, set = 0, binding = 0) writeonly buffer Classes { uint cls[]; };
#else
layout(std430, set = 0, binding = 0) readonly buffer Classes { uint cls[]; };
#endif
layout(std430, set = 0, binding = 1) readonly buffer Exact { uint exact[]; };

layout(location = 0) in vec4 v_clip[];
layout(location = 1) in vec3 v_world[];
layout(location = 2) flat in uint v_patch[];
layout(location = 0) out vec4 c_clip[];
layout(location = 1) out vec3 c_world[];
layout(location = 2) patch out uint c_decision;
layout(location = 3) patch out uint c_exact;

void main()
{
    c_clip[gl_InvocationID] = v_clip[gl_InvocationID];
    c_world[gl_InvocationID] = v_world[gl_InvocationID];
    if (gl_InvocationID == 0) {
#ifdef PTP_TCS
        vec4 cp[16];
        for (int k = 0; k < 16; k++)
            cp[k] = v_clip[k];
        uint c = ptp_3x3_classify_patch(cp, vec4(0.0, 0.0, alpha, 0.0));
        if (mode == 0u)
            cls[v_patch[0]] = c;
#else
        uint c = cls[v_patch[0]];
#endif
        float f = mode == 0u && c == 1u ? 0.0 : tess;
        gl_TessLevelOuter[0] = f;
        gl_TessLevelOuter[1] = f;
        gl_TessLevelOuter[2] = f;
        gl_TessLevelOuter[3] = f;
        gl_TessLevelInner[0] = f;
        gl_TessLevelInner[1] = f;
        c_decision = c;
        c_exact = mode == 1u ? exact[v_patch[0]] : 0u;
    }
}
