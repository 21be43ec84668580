/* exact.h: the exact sign of e.T(u,v) for a bicubic patch of float points seen from a float eye,
 * in wide integers: cullrate's arbiter for the culls its double reference calls unsafe. */
#ifndef EXACT_H
#define EXACT_H

#include <stddef.h>
#include <stdint.h>

/* A signed integer of 1024 bits, two's complement in 32-bit limbs, least significant first.
 * Every value below fits for all finite float inputs (bound in exact.c). */
#define EXACT_LIMBS 32
typedef struct exact_int {
    uint32_t d[EXACT_LIMBS];
} exact_int;

/* -1, 0 or 1: the sign of *x. */
int exact_sign(const exact_int *x);

/* The 64 control values c[P] (P = I*8 + J, I along u) of f(u,v) = e.T(u,v), e = (eye, 1), of
 * the patch b (point k = i*4 + j, i along u), each times one positive factor common to all 64,
 * from ptpgen's exact table (terms rows of idx = {plane, j, k, l}, integer weights iwgt): the
 * signs are those of the exact control values of the float model. Every coordinate must be
 * finite. Returns 0, or -1 for an index out of range or a plane whose sum of |iwgt| is 2^32 or
 * more (the bound would not hold). */
int exact_values(const float b[16][3], const float eye[3], size_t terms,
                 const unsigned short idx[][4], const int iwgt[], exact_int c[64]);

/* 1 if f(u,v) > 0 exactly at some sample u = s/(n-1), v = t/(n-1), s, t = 0..n-1, of the
 * values c from exact_values (cone_sample's grid, without rounding), else 0; -1 for n outside
 * 2..257. */
int exact_sample_positive(const exact_int c[64], int n);

#endif
