/* exact.c: exact control values and samples of e.T(u,v) for float patches and eyes (exact.h), in
 * 1024-bit two's complement integers; no rounding anywhere, so the signs are the true ones. */
#include "exact.h"

#include <limits.h>
#include <string.h>

/* Why 1024 bits hold every value, for any finite floats. Each float is below 2^128 and is
 * m 2^e with m an integer and e >= -149; scaled by 2^-q, q the smallest e, a coordinate is an
 * integer below 2^277 and a difference D = B - E one below 2^278. A term's det(D_j, D_k, D_l)
 * is below 6 (2^278)^3 < 2^837; a control value, the sum of iwgt det over a plane with sum |iwgt| <
 * 2^32, below 2^869. A sample is sum c_IJ a_I(s) a_J(t) with a_I(s) = C(7,I) s^I (N-s)^(7-I),
 * whose sum over I is N^7 <= 2^56 (N <= 256): the partial sums stay below 2^925 and the
 * sample below 2^981, inside the signed range 2^1023. A triangle's sample is
 * sum c_ijk 6!/(i! j! k!) s^i t^j (N-s-t)^k, whose weights sum to N^6: below 2^917. */

static int x_negative(const exact_int *x)
{
    return (int)(x->d[EXACT_LIMBS - 1] >> 31);
}

int exact_sign(const exact_int *x)
{
    int i;
    if (x_negative(x))
        return -1;
    for (i = 0; i < EXACT_LIMBS; i++)
        if (x->d[i])
            return 1;
    return 0;
}

/* r = -a. */
static void x_neg(exact_int *r, const exact_int *a)
{
    uint64_t carry = 1;
    int i;
    for (i = 0; i < EXACT_LIMBS; i++) {
        uint64_t v = (uint64_t)(uint32_t)~a->d[i] + carry;
        r->d[i] = (uint32_t)v;
        carry = v >> 32;
    }
}

/* r = a + b, or a - b when sub is 1. */
static void x_add(exact_int *r, const exact_int *a, const exact_int *b, int sub)
{
    uint64_t carry = (uint64_t)sub;
    int i;
    for (i = 0; i < EXACT_LIMBS; i++) {
        uint64_t v = (uint64_t)a->d[i] + (sub ? (uint32_t)~b->d[i] : b->d[i]) + carry;
        r->d[i] = (uint32_t)v;
        carry = v >> 32;
    }
}

/* r = a * b (r may be a or b), by the magnitudes' nonzero limbs. */
static void x_mul(exact_int *r, const exact_int *a, const exact_int *b)
{
    exact_int ma, mb, t;
    int neg = x_negative(a) ^ x_negative(b), la = EXACT_LIMBS, lb = EXACT_LIMBS, i, j;
    if (x_negative(a))
        x_neg(&ma, a);
    else
        ma = *a;
    if (x_negative(b))
        x_neg(&mb, b);
    else
        mb = *b;
    while (la && !ma.d[la - 1])
        la--;
    while (lb && !mb.d[lb - 1])
        lb--;
    memset(&t, 0, sizeof t);
    for (i = 0; i < la; i++) {
        uint64_t carry = 0;
        for (j = 0; j < lb && i + j < EXACT_LIMBS; j++) {
            uint64_t v = (uint64_t)ma.d[i] * mb.d[j] + t.d[i + j] + carry;
            t.d[i + j] = (uint32_t)v;
            carry = v >> 32;
        }
        if (i + j < EXACT_LIMBS)
            t.d[i + j] = (uint32_t)carry;
    }
    if (neg)
        x_neg(r, &t);
    else
        *r = t;
}

/* x = m 2^shift (m >= 0, shift <= 960), negated when neg is 1. */
static void x_set(exact_int *x, uint64_t m, int shift, int neg)
{
    int limb = shift / 32;
    uint64_t lo = m << (shift % 32), hi = shift % 32 ? m >> (64 - shift % 32) : 0;
    memset(x, 0, sizeof *x);
    x->d[limb] = (uint32_t)lo;
    if (limb + 1 < EXACT_LIMBS)
        x->d[limb + 1] = (uint32_t)(lo >> 32);
    if (limb + 2 < EXACT_LIMBS)
        x->d[limb + 2] = (uint32_t)hi;
    if (neg)
        x_neg(x, x);
}

/* The finite float f as ±*m 2^*e with *m odd (or 0, with *e = INT_MAX); returns the sign bit. */
static int split(float f, uint32_t *m, int *e)
{
    uint32_t u;
    int be;
    memcpy(&u, &f, sizeof u);
    be = (int)(u >> 23 & 0xff);
    *m = (u & 0x7fffffu) | (be ? 0x800000u : 0);
    *e = (be ? be : 1) - 150;
    if (!*m)
        *e = INT_MAX;
    while (*m && !(*m & 1)) {
        *m >>= 1;
        ++*e;
    }
    return (int)(u >> 31);
}

/* The n (<= 16) points minus the eye, as integers times a common 2^q (q omitted: a positive
 * factor). */
static void differences(const float (*b)[3], int n, const float eye[3], exact_int d[16][3])
{
    uint32_t m[17][3];
    int e[17][3], neg[17][3], q = INT_MAX, k, c;
    exact_int ex;
    for (k = 0; k <= n; k++)
        for (c = 0; c < 3; c++) {
            neg[k][c] = split(k < n ? b[k][c] : eye[c], &m[k][c], &e[k][c]);
            q = e[k][c] < q ? e[k][c] : q;
        }
    for (c = 0; c < 3; c++) {
        x_set(&ex, m[n][c], m[n][c] ? e[n][c] - q : 0, neg[n][c]);
        for (k = 0; k < n; k++) {
            x_set(&d[k][c], m[k][c], m[k][c] ? e[k][c] - q : 0, neg[k][c]);
            x_add(&d[k][c], &d[k][c], &ex, 1);
        }
    }
}

/* det(a, b, c) = a . (b x c). */
static void det3(exact_int *r, const exact_int *a, const exact_int *b, const exact_int *c)
{
    exact_int x, y, s;
    int i;
    memset(r, 0, sizeof *r);
    for (i = 0; i < 3; i++) {
        x_mul(&x, &b[(i + 1) % 3], &c[(i + 2) % 3]);
        x_mul(&y, &b[(i + 2) % 3], &c[(i + 1) % 3]);
        x_add(&s, &x, &y, 1);
        x_mul(&s, &s, &a[i]);
        x_add(r, r, &s, 0);
    }
}

int exact_values(const float (*b)[3], int points, const float eye[3], size_t terms,
                 const unsigned short idx[][4], const int iwgt[], int planes, exact_int *c)
{
    uint64_t wsum[64] = {0};
    exact_int d[16][3], t, w;
    size_t x;
    int p;
    if (points < 1 || points > 16 || planes < 1 || planes > 64)
        return -1;
    for (x = 0; x < terms; x++) {
        if (idx[x][0] >= planes || idx[x][1] >= points || idx[x][2] >= points ||
            idx[x][3] >= points)
            return -1;
        wsum[idx[x][0]] += (uint64_t)(iwgt[x] < 0 ? -(int64_t)iwgt[x] : iwgt[x]);
    }
    for (p = 0; p < planes; p++)
        if (wsum[p] >> 32)
            return -1;
    differences(b, points, eye, d);
    memset(c, 0, (size_t)planes * sizeof *c);
    /* e . cross4(b_j, b_k, b_l) = n . (E - b_j), n = (b_k - b_j) x (b_l - b_j), which is
     * -det(D_j, D_k, D_l) for D = b - E. */
    for (x = 0; x < terms; x++) {
        det3(&t, d[idx[x][1]], d[idx[x][2]], d[idx[x][3]]);
        x_set(&w, (uint64_t)(iwgt[x] < 0 ? -(int64_t)iwgt[x] : iwgt[x]), 0, iwgt[x] < 0);
        x_mul(&t, &t, &w);
        x_add(&c[idx[x][0]], &c[idx[x][0]], &t, 1);
    }
    return 0;
}

/* 1 if f > 0 exactly at some point of a triangle's sample grid: f N^6 at (s, t) is
 * sum c_ijk 6!/(i! j! k!) s^i t^j r^k, r = N - s - t, N = n - 1. */
static int tri_sample_positive(const exact_int c[28], int n)
{
    static const uint64_t fact[7] = {1, 1, 2, 6, 24, 120, 720};
    exact_int f, x, w;
    int s, t, i, j, e;
    for (s = 0; s < n; s++)
        for (t = 0; s + t < n; t++) {
            memset(&f, 0, sizeof f);
            for (i = 0; i <= 6; i++)
                for (j = 0; i + j <= 6; j++) { /* cell (i, j): c[r(r+1)/2 + r - j], r = 6 - i */
                    int l = 6 - i - j;
                    uint64_t a = fact[6] / (fact[i] * fact[j] * fact[l]);
                    for (e = 0; e < 6; e++)
                        a *= (uint64_t)(e < i ? s : e < i + j ? t : n - 1 - s - t);
                    x_set(&w, a, 0, 0);
                    x_mul(&x, &c[(6 - i) * (7 - i) / 2 + 6 - i - j], &w);
                    x_add(&f, &f, &x, 0);
                }
            if (exact_sign(&f) > 0)
                return 1;
        }
    return 0;
}

int exact_sample_positive(int domain, const exact_int *c, int n)
{
    uint64_t a[257][8];
    static const uint64_t binom7[8] = {1, 7, 21, 35, 35, 21, 7, 1};
    exact_int g[8], f, x, w;
    int s, t, i, j, p, planes = domain == CONE_TRI ? 28 : 64;
    if (n < 2 || n > 257 || (domain != CONE_QUAD && domain != CONE_TRI))
        return -1;
    for (p = 0; p < planes && exact_sign(&c[p]) <= 0; p++)
        ;
    if (p == planes) /* f is a convex combination of the control values */
        return 0;
    if (domain == CONE_TRI)
        return tri_sample_positive(c, n);
    for (s = 0; s < n; s++) /* a[s][i] = C(7,i) s^i (N-s)^(7-i), u = s/N times N^7 */
        for (i = 0; i < 8; i++) {
            a[s][i] = binom7[i];
            for (j = 0; j < 7; j++)
                a[s][i] *= (uint64_t)(j < i ? s : n - 1 - s);
        }
    for (s = 0; s < n; s++) {
        for (j = 0; j < 8; j++) {
            memset(&g[j], 0, sizeof g[j]);
            for (i = 0; i < 8; i++) {
                x_set(&w, a[s][i], 0, 0);
                x_mul(&x, &c[i * 8 + j], &w);
                x_add(&g[j], &g[j], &x, 0);
            }
        }
        for (t = 0; t < n; t++) {
            memset(&f, 0, sizeof f);
            for (j = 0; j < 8; j++) {
                x_set(&w, a[t][j], 0, 0);
                x_mul(&x, &g[j], &w);
                x_add(&f, &f, &x, 0);
            }
            if (exact_sign(&f) > 0)
                return 1;
        }
    }
    return 0;
}
