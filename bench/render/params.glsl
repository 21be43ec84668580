/* params.glsl: the graphics push constants, shared by the tessellation and fragment shaders:
 * the overview's mvp, the eye (world) for the headlight, the tessellation factor, and the mode
 * (0 the frame: a culled patch gets factor 0; 1 the overview: every patch, coloured by class). */
layout(push_constant) uniform Params {
    mat4 ov_mvp;
    vec4 eye;
    float tess;
    uint mode;
};
