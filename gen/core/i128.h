/* i128.h: checked 128-bit integer helpers used by the exact arithmetic.
 * Every operation reports overflow instead of wrapping; no compiler runtime helpers needed. */
#ifndef I128_H
#define I128_H

#include "core/ptp.h"

#define I128_MAX ((ptp_i128)(((ptp_u128)1 << 127) - 1))

/* |a| as an unsigned value (exact for every a). */
static inline ptp_u128 i128_abs(ptp_i128 a)
{
    return a < 0 ? (ptp_u128)0 - (ptp_u128)a : (ptp_u128)a;
}

/* *r = a * b for unsigned values; returns 1 on overflow (then *r is unspecified). */
static inline int u128_mul_ovf(ptp_u128 *r, ptp_u128 a, ptp_u128 b)
{
    const ptp_u128 lo = UINT64_MAX;
    ptp_u128 ah = a >> 64, al = a & lo, bh = b >> 64, bl = b & lo, cross;
    if (ah && bh)
        return 1;
    cross = ah * bl + bh * al; /* one of the two products is zero */
    if (cross >> 64)
        return 1;
    *r = al * bl;
    if (*r + (cross << 64) < *r)
        return 1;
    *r += cross << 64;
    return 0;
}

/* Makes a signed value of sign neg and magnitude u; returns 1 unless |result| <= I128_MAX. */
static inline int i128_from_mag(ptp_i128 *r, int neg, ptp_u128 u)
{
    if (u > (ptp_u128)I128_MAX)
        return 1;
    *r = neg ? -(ptp_i128)u : (ptp_i128)u;
    return 0;
}

/* *r = a * b; returns 1 when |a * b| > I128_MAX. */
static inline int i128_mul_ovf(ptp_i128 *r, ptp_i128 a, ptp_i128 b)
{
    ptp_u128 u;
    if (a == (int64_t)a && b == (int64_t)b) { /* |a*b| < 2^126: one 64x64->128 multiply */
        *r = (ptp_i128)(int64_t)a * (int64_t)b;
        return 0;
    }
    if (u128_mul_ovf(&u, i128_abs(a), i128_abs(b)))
        return 1;
    return i128_from_mag(r, (a < 0) != (b < 0), u);
}

/* *r = a + b; returns 1 when |a + b| > I128_MAX (a and b in range). */
static inline int i128_add_ovf(ptp_i128 *r, ptp_i128 a, ptp_i128 b)
{
    if ((b > 0 && a > I128_MAX - b) || (b < 0 && a < -I128_MAX - b))
        return 1;
    *r = a + b;
    return 0;
}

/* Greatest common divisor of |a| and |b| (gcd(0, 0) = 0), by the binary algorithm. */
static inline ptp_u128 u128_gcd(ptp_u128 a, ptp_u128 b)
{
    int shift;
    if (a == 0)
        return b;
    if (b == 0)
        return a;
    if (!(a >> 64) && !(b >> 64)) {
        uint64_t x = (uint64_t)a, y = (uint64_t)b;
        int s = __builtin_ctzll(x | y);
        x >>= __builtin_ctzll(x);
        while (y) {
            y >>= __builtin_ctzll(y);
            if (x > y) {
                uint64_t t = x;
                x = y;
                y = t;
            }
            y -= x;
        }
        return (ptp_u128)x << s;
    }
    for (shift = 0; !((a | b) & 1); shift++) {
        a >>= 1;
        b >>= 1;
    }
    while (!(a & 1))
        a >>= 1;
    while (b) {
        while (!(b & 1))
            b >>= 1;
        if (a > b) {
            ptp_u128 t = a;
            a = b;
            b = t;
        }
        b -= a;
    }
    return a << shift;
}

/* Writes a in decimal to buf (at least 41 bytes); returns buf. */
char *i128_to_str(char *buf, ptp_i128 a);

#endif
