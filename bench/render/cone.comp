/* cone.comp: the NCONE / TCONE per-eye test of bench/cones.c's cone_cull, one invocation a patch
 * (as the paper ran them). Per patch two vec4: (axis, half-angle; the half-angle < 0 for a cone
 * that never culls) and (sphere centre, radius), precomputed on the CPU by bench/cones.c.
 * Writes class 1 (culled: back-facing) or 2 (kept). */
#version 450
layout(local_size_x = 64) in;

layout(std430, set = 0, binding = 0) readonly buffer Cones { vec4 cone[]; };
layout(std430, set = 0, binding = 1) writeonly buffer Classes { uint cls[]; };
layout(push_constant) uniform Params { vec4 eye; uint patch_count; };

const float HALF_PI = 1.57079632679489662;

void main()
{
    uint p = (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * 64u +
             gl_LocalInvocationID.x;
    if (p >= patch_count)
        return;
    vec4 a = cone[2u * p], s = cone[2u * p + 1u];
    vec3 d = eye.xyz - s.xyz;
    float dist = length(d);
    uint c = 2u;
    if (a.w >= 0.0 && dist > s.w) {
        float delta = asin(s.w / dist);
        /* the angle between axis and eye direction exceeds pi/2 + alpha + delta */
        if (a.w + delta < HALF_PI && dot(a.xyz, d) / dist < -sin(a.w + delta))
            c = 1u;
    }
    cls[p] = c;
}
