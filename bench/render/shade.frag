/* shade.frag: a headlight on the normal; grey in the frame, and in the overview the colour of
 * the cull pass's decision: culled red, kept front-facing green, kept but back-facing or
 * silhouette (by the exact tangent-plane class) yellow. */
#version 450
#extension GL_GOOGLE_include_directive : require
#include "params.glsl"

layout(location = 0) in vec3 e_normal;
layout(location = 1) in vec3 e_pos;
layout(location = 2) flat in uint e_decision;
layout(location = 3) flat in uint e_exact;
layout(location = 0) out vec4 color;

void main()
{
    float ln = length(e_normal);
    vec3 n = ln > 0.0 ? e_normal / ln : vec3(0.0);
    vec3 base = vec3(0.85);
    if (mode == 1u)
        base = e_decision == 1u ? vec3(0.9, 0.2, 0.15)
               : e_exact == 0u  ? vec3(0.3, 0.8, 0.3)
                                : vec3(0.95, 0.8, 0.2);
    float d = max(dot(n, normalize(eye.xyz - e_pos)), 0.0);
    color = vec4(base * (0.2 + 0.8 * d), 1.0);
}
