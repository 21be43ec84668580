#version 450
#extension GL_GOOGLE_include_directive : require
// cull_patch.tesc: a tessellation control shader that culls its own bicubic patch, no compute
// pass. ptp_3x3.glsl is `ptpgen --degree 3 --target glsl --stage function -o ptp_3x3.glsl`.
layout(vertices = 16) out;
#include "ptp_3x3.glsl"
// alpha: the clip-space eye (0, 0, alpha, 0) of the projection (README: alpha).
layout(push_constant) uniform Draw { float level; float alpha; };

void main()
{
    gl_out[gl_InvocationID].gl_Position = gl_in[gl_InvocationID].gl_Position;
    if (gl_InvocationID == 0) {
        vec4 cp[16]; // the patch's clip-space control points, k = i*4 + j with i along u
        for (int k = 0; k < 16; k++)
            cp[k] = gl_in[k].gl_Position;
        // Class 1 is back-facing: factors of 0 discard the patch before evaluation.
        uint c = ptp_3x3_classify_patch(cp, vec4(0.0, 0.0, alpha, 0.0));
        float t = c == 1u ? 0.0 : level;
        gl_TessLevelOuter = float[4](t, t, t, t);
        gl_TessLevelInner = float[2](t, t);
    }
}
