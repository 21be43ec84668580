/* vec3.h: the products of 3-vectors in double that bench/cones.c and the renderer's camera
 * (bench/render/cam.c) share; static inline, so each file's floating-point pragmas apply. */
#ifndef VEC3_H
#define VEC3_H

/* r = a - b. */
static inline void vec3_sub(double r[3], const double a[3], const double b[3])
{
    r[0] = a[0] - b[0];
    r[1] = a[1] - b[1];
    r[2] = a[2] - b[2];
}

/* r = a x b (r distinct from a and b). */
static inline void vec3_cross(double r[3], const double a[3], const double b[3])
{
    r[0] = a[1] * b[2] - a[2] * b[1];
    r[1] = a[2] * b[0] - a[0] * b[2];
    r[2] = a[0] * b[1] - a[1] * b[0];
}

/* a . b. */
static inline double vec3_dot(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

#endif
