/* cam.h: the camera math of the renderer: look-at view, Vulkan perspective (y down, depth 0..1),
 * the clip-space eye alpha of ptpgen's kernels, and the overview camera of Figure 1. */
#ifndef RENDER_CAM_H
#define RENDER_CAM_H

/* A 4x4 matrix m[row][col] acting on column vectors: clip = m * (x, y, z, 1). */
typedef struct cam_mat {
    double m[4][4];
} cam_mat;

/* A camera: where it is, what it maps to clip space, and its clip-space eye. */
typedef struct cam_view {
    double eye[3];
    cam_mat view, proj, mvp; /* mvp = proj * view */
    double near, far;
    double alpha;            /* sign(det proj) * proj[2][3]: the kernels' eye (0, 0, alpha, 0) */
} cam_view;

/* Sets c up to look from eye at target with up vector up, vertical field of view fov_deg and
 * aspect width/height, near and far planes enclosing the sphere (center, radius) (near at
 * least far/1000 when the eye is inside it). Returns 0, or -1 when eye == target or up is
 * parallel to the view direction. */
int cam_look(cam_view *c, const double eye[3], const double target[3], const double up[3],
             double fov_deg, double aspect, const double center[3], double radius);

/* The overview camera: looks at the sphere (center, radius) from the side of c's view
 * direction (a quarter turn about up, a little behind and above), far enough to see the whole
 * sphere. */
int cam_overview(cam_view *ov, const cam_view *c, const double up[3], double aspect,
                 const double center[3], double radius);

/* out = m stored column-major as floats, the layout of a GLSL mat4. */
void cam_to_gl(float out[16], const cam_mat *m);

#endif
