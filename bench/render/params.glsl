/* params.glsl: the graphics push constants, shared by the tessellation and fragment shaders:
 * the overview's mvp, the eye (world) for the headlight, the tessellation factor, and the mode
 * (0 the frame: a culled patch gets factor 0; 1 the overview: every patch, coloured by class),
 * the orientation (1, or -1 where dB/dv x dB/du is the outward normal), and the clip-space eye's
 * alpha (the TCS that classifies its own patch). */
layout(push_constant) uniform Params {
    mat4 ov_mvp;
    vec4 eye;
    float tess;
    uint mode;
    float orient;
    float alpha;
};
