/* cam.c: look-at and Vulkan perspective matrices in double, the determinant that gives the
 * clip-space alpha (README, "Which alpha"), and the overview camera. */
#include "cam.h"

#include "vec3.h"

#include <math.h>
#include <string.h>

#define CAM_PI 3.14159265358979323846

/* Scales a to unit length; 0, or -1 for a (near) zero vector. */
static int unit3(double a[3])
{
    double l = sqrt(vec3_dot(a, a));
    if (!(l > 1e-300))
        return -1;
    for (int i = 0; i < 3; i++)
        a[i] /= l;
    return 0;
}

static void mat_mul(cam_mat *r, const cam_mat *a, const cam_mat *b)
{
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) {
            double s = 0;
            for (int k = 0; k < 4; k++)
                s += a->m[i][k] * b->m[k][j];
            r->m[i][j] = s;
        }
}

/* The determinant of a. */
static double det4(const cam_mat *a)
{
    double det = 0;
    for (int c = 0; c < 4; c++) { /* Laplace along row 0, 3x3 minors by the rule of Sarrus */
        int k[3], n = 0;
        double minor;
        for (int j = 0; j < 4; j++)
            if (j != c)
                k[n++] = j;
        minor = a->m[1][k[0]] * (a->m[2][k[1]] * a->m[3][k[2]] - a->m[2][k[2]] * a->m[3][k[1]]) -
                a->m[1][k[1]] * (a->m[2][k[0]] * a->m[3][k[2]] - a->m[2][k[2]] * a->m[3][k[0]]) +
                a->m[1][k[2]] * (a->m[2][k[0]] * a->m[3][k[1]] - a->m[2][k[1]] * a->m[3][k[0]]);
        det += (c % 2 ? -1 : 1) * a->m[0][c] * minor;
    }
    return det;
}

/* The right-handed view: camera at eye looking down -z, y up. */
static int view_matrix(cam_mat *v, const double eye[3], const double target[3],
                       const double up[3])
{
    double f[3], s[3], u[3];
    vec3_sub(f, target, eye);
    if (unit3(f))
        return -1;
    vec3_cross(s, f, up);
    if (unit3(s))
        return -1;
    vec3_cross(u, s, f);
    memset(v, 0, sizeof *v);
    for (int i = 0; i < 3; i++) {
        v->m[0][i] = s[i];
        v->m[1][i] = u[i];
        v->m[2][i] = -f[i];
    }
    v->m[0][3] = -vec3_dot(s, eye);
    v->m[1][3] = -vec3_dot(u, eye);
    v->m[2][3] = vec3_dot(f, eye);
    v->m[3][3] = 1;
    return 0;
}

/* Vulkan's perspective: x right, y down (so m[1][1] < 0), depth near -> 0, far -> 1. */
static void proj_matrix(cam_mat *p, double fov_deg, double aspect, double n, double f)
{
    double t = 1 / tan(fov_deg * CAM_PI / 360);
    memset(p, 0, sizeof *p);
    p->m[0][0] = t / aspect;
    p->m[1][1] = -t;
    p->m[2][2] = f / (n - f);
    p->m[2][3] = n * f / (n - f);
    p->m[3][2] = -1;
}

int cam_look(cam_view *c, const double eye[3], const double target[3], const double up[3],
             double fov_deg, double aspect, const double center[3], double radius)
{
    double d[3], dist, det;
    memset(c, 0, sizeof *c);
    if (view_matrix(&c->view, eye, target, up))
        return -1;
    vec3_sub(d, eye, center);
    dist = sqrt(vec3_dot(d, d));
    c->far = dist + 1.01 * radius;
    c->near = dist - 1.01 * radius;
    if (c->near < c->far / 1000)
        c->near = c->far / 1000;
    proj_matrix(&c->proj, fov_deg, aspect, c->near, c->far);
    mat_mul(&c->mvp, &c->proj, &c->view);
    memcpy(c->eye, eye, sizeof c->eye);
    det = det4(&c->proj);
    c->alpha = (det > 0 ? 1 : -1) * c->proj.m[2][3];
    return 0;
}

int cam_overview(cam_view *ov, const cam_view *c, const double up[3], double aspect,
                 const double center[3], double radius)
{
    const double fov = 40;
    double d[3], side[3], eye[3], dist = 1.1 * radius / sin(fov * CAM_PI / 360);
    double u[3] = {up[0], up[1], up[2]};
    vec3_sub(d, c->eye, center);
    if (unit3(d) || unit3(u))
        return -1;
    vec3_cross(side, u, d);
    if (unit3(side))
        memcpy(side, d, sizeof side);
    for (int i = 0; i < 3; i++)
        eye[i] = 0.8 * side[i] - 0.3 * d[i] + 0.35 * u[i];
    if (unit3(eye))
        return -1;
    if (aspect < 1)
        dist /= aspect; /* the horizontal field of view is the narrower one */
    for (int i = 0; i < 3; i++)
        eye[i] = center[i] + dist * eye[i];
    return cam_look(ov, eye, center, up, fov, aspect, center, radius);
}

void cam_to_gl(float out[16], const cam_mat *m)
{
    for (int c = 0; c < 4; c++)
        for (int r = 0; r < 4; r++)
            out[c * 4 + r] = (float)m->m[r][c];
}
