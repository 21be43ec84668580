/* exact.h: the exact sign of e.T(u,v) for a bicubic or cubic triangular patch of float points seen
 * from a float eye, in wide integers: cullrate's arbiter for the culls its double reference calls
 * unsafe. */
#ifndef EXACT_H
#define EXACT_H

#include <stddef.h>
#include <stdint.h>

#include "cones.h" /* the domains, CONE_QUAD and CONE_TRI */

/* A signed integer of 1024 bits, two's complement in 32-bit limbs, least significant first.
 * Every value below fits for all finite float inputs (bound in exact.c). */
#define EXACT_LIMBS 32
typedef struct exact_int {
    uint32_t d[EXACT_LIMBS];
} exact_int;

/* -1, 0 or 1: the sign of *x. */
int exact_sign(const exact_int *x);

/* The control values c[P] of f(u,v) = e.T(u,v), e = (eye, 1), of the patch of the points b
 * (points of them, at most 16) and the planes' count planes (at most 64), numbered as
 * cones.h's domains, each times one positive factor common to all, from ptpgen's exact table
 * (terms rows of idx = {plane, j, k, l}, integer weights iwgt): the signs are those of the
 * exact control values of the float model. Every coordinate must be finite. Returns 0, or -1
 * for counts or an index out of range or a plane whose sum of |iwgt| is 2^32 or more (the
 * bound would not hold). */
int exact_values(const float (*b)[3], int points, const float eye[3], size_t terms,
                 const unsigned short idx[][4], const int iwgt[], int planes, exact_int *c);

/* 1 if f(u,v) > 0 exactly at some sample u = s/(n-1), v = t/(n-1), s, t = 0..n-1 (with
 * s + t <= n - 1 for a triangle), of the values c from exact_values for a patch of the domain
 * (CONE_QUAD: 64 values of bidegree 7x7, CONE_TRI: 28 of total degree 6): cone_sample's grid,
 * without rounding. Else 0; -1 for n outside 2..257 or an unknown domain. */
int exact_sample_positive(int domain, const exact_int *c, int n);

#endif
