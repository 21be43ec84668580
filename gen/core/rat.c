/* rat.c: exact rational arithmetic over checked 128-bit integers.
 * Results are always canonical; overflow is reported as PTP_EOVERFLOW, never wrapped. */
#include "core/rat.h"
#include "core/i128.h"

#include <string.h>

char *i128_to_str(char *buf, ptp_i128 a)
{
    char tmp[41];
    int n = 0, i = 0;
    ptp_u128 u = i128_abs(a);
    for (; u >> 64; u /= 10)
        tmp[n++] = (char)('0' + (int)(u % 10));
    {
        uint64_t v = (uint64_t)u; /* the rest in cheap 64-bit divisions */
        do {
            tmp[n++] = (char)('0' + (int)(v % 10));
            v /= 10;
        } while (v);
    }
    if (a < 0)
        buf[i++] = '-';
    while (n)
        buf[i++] = tmp[--n];
    buf[i] = '\0';
    return buf;
}

void rat_set_si(rat *r, int64_t n)
{
    r->num = n;
    r->den = 1;
}

int rat_set_frac(rat *r, ptp_i128 num, ptp_i128 den)
{
    ptp_u128 g;
    int neg;
    if (den == 0)
        return PTP_EUSAGE;
    neg = (num < 0) != (den < 0);
    g = u128_gcd(i128_abs(num), i128_abs(den));
    if (num == 0) {
        r->num = 0;
        r->den = 1;
        return PTP_OK;
    }
    {
        rat t;
        if (i128_from_mag(&t.num, neg, i128_abs(num) / g) ||
            i128_from_mag(&t.den, 0, i128_abs(den) / g))
            return PTP_EOVERFLOW;
        *r = t;
    }
    return PTP_OK;
}

int rat_is_canonical(const rat *a)
{
    if (a->den <= 0 || a->num < -I128_MAX)
        return 0;
    if (a->num == 0)
        return a->den == 1;
    return u128_gcd(i128_abs(a->num), (ptp_u128)a->den) == 1;
}

int rat_add(rat *r, const rat *a, const rat *b)
{
    /* Knuth 4.5.1: with g = gcd(b1, b2), the sum is (a1*(b2/g) + a2*(b1/g)) / (b1/g * b2),
     * and only g can share a factor with the new numerator. */
    ptp_i128 g = (ptp_i128)u128_gcd((ptp_u128)a->den, (ptp_u128)b->den);
    ptp_i128 x, y, t, den, g2;
    rat s;
    if (i128_mul_ovf(&x, a->num, b->den / g) || i128_mul_ovf(&y, b->num, a->den / g) ||
        i128_add_ovf(&t, x, y))
        return PTP_EOVERFLOW;
    if (t == 0) {
        rat_set_si(r, 0);
        return PTP_OK;
    }
    g2 = (ptp_i128)u128_gcd(i128_abs(t), (ptp_u128)g);
    if (i128_mul_ovf(&den, a->den / g, b->den / g2))
        return PTP_EOVERFLOW;
    s.num = t / g2;
    s.den = den;
    *r = s;
    return PTP_OK;
}

int rat_sub(rat *r, const rat *a, const rat *b)
{
    rat nb;
    rat_neg(&nb, b);
    return rat_add(r, a, &nb);
}

int rat_mul(rat *r, const rat *a, const rat *b)
{
    ptp_i128 g1, g2;
    rat s;
    if (a->num == 0 || b->num == 0) {
        rat_set_si(r, 0);
        return PTP_OK;
    }
    g1 = (ptp_i128)u128_gcd(i128_abs(a->num), (ptp_u128)b->den);
    g2 = (ptp_i128)u128_gcd(i128_abs(b->num), (ptp_u128)a->den);
    if (i128_mul_ovf(&s.num, a->num / g1, b->num / g2) ||
        i128_mul_ovf(&s.den, a->den / g2, b->den / g1))
        return PTP_EOVERFLOW;
    *r = s;
    return PTP_OK;
}

int rat_div(rat *r, const rat *a, const rat *b)
{
    rat inv;
    if (b->num == 0)
        return PTP_EUSAGE;
    inv.num = b->num < 0 ? -b->den : b->den;
    inv.den = b->num < 0 ? -b->num : b->num;
    return rat_mul(r, a, &inv);
}

void rat_neg(rat *r, const rat *a)
{
    r->num = -a->num;
    r->den = a->den;
}

int rat_sgn(const rat *a)
{
    return (a->num > 0) - (a->num < 0);
}

int rat_equal(const rat *a, const rat *b)
{
    return a->num == b->num && a->den == b->den;
}

int rat_lcm_den(ptp_i128 *D, const rat *a)
{
    ptp_i128 g = (ptp_i128)u128_gcd((ptp_u128)*D, (ptp_u128)a->den), L;
    if (i128_mul_ovf(&L, *D / g, a->den))
        return PTP_EOVERFLOW;
    *D = L;
    return PTP_OK;
}

double rat_get_d(const rat *a)
{
    return (double)a->num / (double)a->den;
}

char *rat_get_str(char *buf, const rat *a)
{
    i128_to_str(buf, a->num);
    if (a->den != 1) {
        size_t n = strlen(buf);
        buf[n] = '/';
        i128_to_str(buf + n + 1, a->den);
    }
    return buf;
}

/* Parses decimal digits from *s into the magnitude *u, advancing *s; PTP_EUSAGE if there are
 * none, PTP_EOVERFLOW past 2^128 - 1. */
static int parse_mag(ptp_u128 *u, const char **s)
{
    const char *p = *s;
    *u = 0;
    for (; *p >= '0' && *p <= '9'; p++) {
        if (u128_mul_ovf(u, *u, 10) || *u + (ptp_u128)(*p - '0') < *u)
            return PTP_EOVERFLOW;
        *u += (ptp_u128)(*p - '0');
    }
    if (p == *s)
        return PTP_EUSAGE;
    *s = p;
    return PTP_OK;
}

int rat_set_str(rat *r, const char *s)
{
    ptp_u128 num, den = 1, g;
    rat t;
    int neg = *s == '-', st;
    s += neg;
    if ((st = parse_mag(&num, &s)))
        return st;
    if (*s == '/') {
        s++;
        if ((st = parse_mag(&den, &s)))
            return st;
    }
    if (*s != '\0')
        return PTP_EUSAGE;
    if (den == 0)
        return PTP_EUSAGE;
    g = u128_gcd(num, den); /* reduce before the range check: "-2^127/2" fits */
    if (i128_from_mag(&t.num, neg, num / g) || i128_from_mag(&t.den, 0, den / g))
        return PTP_EOVERFLOW;
    if (t.num == 0)
        t.den = 1;
    *r = t;
    return PTP_OK;
}
