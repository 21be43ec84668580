/* patch.vert: passes each control point through, in clip space (the transform pass's output)
 * and in world space (for the normal and the overview), with its patch's index. */
#version 450
layout(location = 0) in vec4 clip;
layout(location = 1) in vec4 world;
layout(location = 0) out vec4 v_clip;
layout(location = 1) out vec3 v_world;
layout(location = 2) flat out uint v_patch;

void main()
{
    v_clip = clip;
    v_world = world.xyz;
    v_patch = uint(gl_VertexIndex) / 16u; /* draws start at vertex 0, 16 a patch */
}
