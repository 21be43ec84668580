/* float_widen.h: a float model kept in doubles, without trusting the compiler to round: gcc 12.2
 * at -O2 folds (double)(float)x into x when it vectorizes such copies (tests/test_float_rounding.c). */
#ifndef FLOAT_WIDEN_H
#define FLOAT_WIDEN_H

#include <math.h>
#include <stdint.h>
#include <string.h>

/* The float *f as a double (exact). f is read through a volatile lvalue, so the compiler
 * cannot forward the double a float store was rounded from and drop the rounding: store the
 * rounded value in float storage first, then widen it with this. */
static inline double float_widen(const volatile float *f)
{
    return *f;
}

/* The finite float f as a double, decoded from its bits with integer arithmetic and ldexp: no
 * float -> double conversion that an optimizer could fold, so checks can rely on it. */
static inline double float_value(float f)
{
    uint32_t u;
    int e;
    double v;
    memcpy(&u, &f, sizeof u);
    e = (int)(u >> 23 & 0xff);
    v = ldexp((double)(int32_t)((u & 0x7fffffu) | (e ? 0x800000u : 0)), (e ? e : 1) - 150);
    return u >> 31 ? -v : v;
}

/* 1 if d[i * ds] equals f[i * fs] bit for bit (as float_value) for every i < n, else 0. */
static inline int float_same(const double *d, size_t ds, const float *f, size_t fs, size_t n)
{
    size_t i;
    for (i = 0; i < n; i++) {
        double v = float_value(f[i * fs]);
        if (memcmp(&v, &d[i * ds], sizeof v))
            return 0;
    }
    return 1;
}

#endif
