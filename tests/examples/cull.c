/* cull.c: which bicubic patches to skip for one camera: clip-space points, alpha, one call.
 * Header: ptpgen --degree 3 --target c -o ptp_3x3.h */
#define PTP_3X3_IMPLEMENTATION
#include "ptp_3x3.h"

/* Classifies count patches (16 points (x, y, z, w) each, in world space) as seen through view
 * and proj (column-major 4x4, as OpenGL and glm store them) into cls; clip receives the
 * points in clip space. Returns the number of back-facing patches, which need no tessellation. */
size_t cull_patches(const float (*world)[4], size_t count, const float view[16],
                    const float proj[16], float (*clip)[4], unsigned char *cls)
{
    float mvp[16] = {0}, eye[4] = {0, 0, 0, 0};
    size_t i, culled = 0;
    for (int c = 0; c < 16; c++) /* mvp = proj * view */
        for (int k = 0; k < 4; k++)
            mvp[c] += proj[k * 4 + c % 4] * view[c / 4 * 4 + k];
    for (i = 0; i < count * PTP_3X3_POINTS; i++) /* what the vertex shader does */
        for (int r = 0; r < 4; r++)
            clip[i][r] = mvp[r] * world[i][0] + mvp[4 + r] * world[i][1] +
                         mvp[8 + r] * world[i][2] + mvp[12 + r] * world[i][3];
    eye[2] = ptp_3x3_alpha(proj, PTP_3X3_COLUMN_MAJOR); /* the eye is (0, 0, alpha, 0) */
    ptp_3x3_classify_batch((const float (*)[4])clip, count, eye, cls);
    for (i = 0; i < count; i++)
        culled += cls[i] == PTP_3X3_BACK; /* or PTP_3X3_FRONT, PTP_3X3_SILHOUETTE */
    return culled;
}
