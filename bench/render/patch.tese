/* patch.tese: evaluates the bicubic patch (point k = i*4 + j, i along u = gl_TessCoord.x): the
 * position from the clip-space points (the frame) or from the world points and the overview's
 * mvp, and the normal dB/du x dB/dv (negated for inward models) from the world points. */
#version 450
#extension GL_GOOGLE_include_directive : require
layout(quads, equal_spacing, ccw) in;
#include "params.glsl"

layout(location = 0) in vec4 c_clip[];
layout(location = 1) in vec3 c_world[];
layout(location = 2) patch in uint c_decision;
layout(location = 3) patch in uint c_exact;
layout(location = 0) out vec3 e_normal;
layout(location = 1) out vec3 e_pos;
layout(location = 2) flat out uint e_decision;
layout(location = 3) flat out uint e_exact;

/* The cubic Bernstein basis at t and its derivative. */
void basis(float t, out vec4 b, out vec4 d)
{
    float s = 1.0 - t;
    b = vec4(s * s * s, 3.0 * s * s * t, 3.0 * s * t * t, t * t * t);
    d = vec4(-3.0 * s * s, 3.0 * s * s - 6.0 * s * t, 6.0 * s * t - 3.0 * t * t, 3.0 * t * t);
}

void main()
{
    vec4 bu, du, bv, dv, clip = vec4(0.0);
    vec3 p = vec3(0.0), pu = vec3(0.0), pv = vec3(0.0);
    basis(gl_TessCoord.x, bu, du);
    basis(gl_TessCoord.y, bv, dv);
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) {
            int k = i * 4 + j;
            clip += bu[i] * bv[j] * c_clip[k];
            p += bu[i] * bv[j] * c_world[k];
            pu += du[i] * bv[j] * c_world[k];
            pv += bu[i] * dv[j] * c_world[k];
        }
    gl_Position = mode == 0u ? clip : ov_mvp * vec4(p, 1.0);
    e_normal = orient * cross(pu, pv);
    e_pos = p;
    e_decision = c_decision;
    e_exact = c_exact;
}
