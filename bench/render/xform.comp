/* xform.comp: the renderer's transform pass: every control point to clip space, clip = mvp * p,
 * one invocation a point (2-D dispatch: point = (y * groups_x + x) * 64 + local id). */
#version 450
layout(local_size_x = 64) in;

layout(std430, set = 0, binding = 0) readonly buffer World { vec4 wp[]; };
layout(std430, set = 0, binding = 1) writeonly buffer Clip { vec4 cp[]; };
layout(push_constant) uniform Params { mat4 mvp; uint count; };

void main()
{
    uint i = (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * 64u +
             gl_LocalInvocationID.x;
    if (i < count)
        cp[i] = mvp * wp[i];
}
