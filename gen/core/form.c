/* form.c: canonical sparse forms over alternating products of points.
 * Terms share one denominator; every operation ends in form_canonicalize. */
#include "core/form.h"
#include "core/i128.h"

#include <assert.h>
#include <stdlib.h>
#include <string.h>

void form_init(form *f, int rank)
{
    f->rank = rank;
    f->len = f->cap = 0;
    f->t = NULL;
    f->den = 1;
}

void form_clear(form *f)
{
    free(f->t);
    f->t = NULL;
    f->len = f->cap = 0;
    f->den = 1;
}

static int key_is_sorted(form_key key, int rank)
{
    int idx[FORM_MAX_RANK], i;
    form_key_unpack(idx, key, rank);
    for (i = 1; i < rank; i++)
        if (idx[i - 1] >= idx[i])
            return 0;
    return (key >> (16 * rank)) == 0; /* rank <= 3: the shift is at most 48 */
}

int form_is_canonical(const form *f)
{
    ptp_u128 g;
    size_t i;
    if (f->rank < 1 || f->rank > FORM_MAX_RANK || f->den <= 0)
        return 0;
    if (f->len == 0)
        return f->den == 1;
    g = (ptp_u128)f->den;
    for (i = 0; i < f->len; i++) {
        if (f->t[i].num == 0 || f->t[i].num < -I128_MAX || !key_is_sorted(f->t[i].key, f->rank))
            return 0;
        if (i && f->t[i - 1].key >= f->t[i].key)
            return 0;
        g = u128_gcd(g, i128_abs(f->t[i].num));
    }
    return g == 1;
}

form_key form_key_point(int j)
{
    return (form_key)j;
}

void form_key_unpack(int *idx, form_key key, int rank)
{
    int i;
    for (i = rank - 1; i >= 0; i--) {
        idx[i] = (int)(key & FORM_MAX_POINT);
        key >>= 16;
    }
}

int form_key_wedge(form_key *r, form_key a, int ra, form_key b, int rb)
{
    int x[FORM_MAX_RANK], y[FORM_MAX_RANK], i = 0, j = 0, sign = 1;
    form_key k = 0;
    if (ra == 2 && rb == 1) { /* the hot case of B ^ B_u ^ B_v: place b among (a0, a1) */
        form_key a0 = a >> 16, a1 = a & FORM_MAX_POINT;
        if (b == a0 || b == a1)
            return 0;
        if (b > a1) {
            *r = a << 16 | b;
            return 1;
        }
        if (b > a0) {
            *r = a0 << 32 | b << 16 | a1;
            return -1;
        }
        *r = b << 32 | a;
        return 1;
    }
    form_key_unpack(x, a, ra);
    form_key_unpack(y, b, rb);
    /* Merge; each y element placed before remaining x elements crosses them all. */
    while (i < ra || j < rb) {
        int v;
        if (j == rb || (i < ra && x[i] < y[j])) {
            v = x[i++];
        } else {
            if (i < ra && x[i] == y[j])
                return 0;
            if ((ra - i) & 1)
                sign = -sign;
            v = y[j++];
        }
        k = (k << 16) | (form_key)v;
    }
    *r = k;
    return sign;
}

static int reserve(form *f, size_t n, ptp_error *err)
{
    form_term *t;
    size_t cap;
    if (n <= f->cap)
        return PTP_OK;
    cap = f->cap ? f->cap : 4;
    while (cap < n)
        cap *= 2;
    t = realloc(f->t, cap * sizeof *t);
    if (!t)
        return ptp_fail(err, PTP_ENOMEM, "out of memory (form of %zu terms)", n);
    f->t = t;
    f->cap = cap;
    return PTP_OK;
}

/* Divides den and every num by their gcd. */
static void canonicalize(form *f)
{
    ptp_u128 g = (ptp_u128)f->den;
    size_t i;
    if (f->len == 0) {
        f->den = 1;
        return;
    }
    for (i = 0; i < f->len && g != 1; i++)
        g = u128_gcd(g, i128_abs(f->t[i].num));
    if (g == 1)
        return;
    for (i = 0; i < f->len; i++)
        f->t[i].num /= (ptp_i128)g;
    f->den /= (ptp_i128)g;
}

int form_set_point(form *r, int j, const rat *w, ptp_error *err)
{
    int st;
    r->len = 0;
    r->den = 1;
    if (r->rank != 1 || j < 0 || j > FORM_MAX_POINT)
        return ptp_fail(err, PTP_EINTERNAL, "form_set_point: bad point %d", j);
    if (w->num == 0)
        return PTP_OK;
    if ((st = reserve(r, 1, err)))
        return st;
    r->t[0].key = form_key_point(j);
    r->t[0].num = w->num;
    r->den = w->den;
    r->len = 1;
    return PTP_OK;
}

static int overflow(ptp_error *err, const char *what)
{
    return ptp_fail(err, PTP_EOVERFLOW, "exact arithmetic overflowed 128 bits in %s", what);
}

int form_lincomb(form *r, const rat *a, const form *x, const rat *b, const form *y,
                 ptp_error *err)
{
    /* r = (ca * X + cb * Y) / L with fa = a/den(x), fb = b/den(y), L = lcm of their dens. */
    rat dx, dy, fa, fb;
    ptp_i128 L, ca, cb;
    form out;
    size_t i = 0, j = 0;
    int st = rat_set_frac(&dx, 1, x->den) | rat_set_frac(&dy, 1, y->den);
    assert(st == PTP_OK); /* canonical forms have 0 < den <= I128_MAX */
    if (rat_mul(&fa, a, &dx) || rat_mul(&fb, b, &dy))
        return overflow(err, "a linear combination of forms");
    L = fa.den;
    if (rat_lcm_den(&L, &fb) || i128_mul_ovf(&ca, fa.num, L / fa.den) ||
        i128_mul_ovf(&cb, fb.num, L / fb.den))
        return overflow(err, "a linear combination of forms");
    form_init(&out, r->rank);
    if ((st = reserve(&out, x->len + y->len, err)))
        return st;
    while (i < x->len || j < y->len) {
        form_term t;
        ptp_i128 p = 0, q = 0;
        if (j == y->len || (i < x->len && x->t[i].key < y->t[j].key)) {
            t.key = x->t[i].key;
            st = i128_mul_ovf(&t.num, ca, x->t[i++].num);
        } else if (i == x->len || y->t[j].key < x->t[i].key) {
            t.key = y->t[j].key;
            st = i128_mul_ovf(&t.num, cb, y->t[j++].num);
        } else {
            t.key = x->t[i].key;
            st = i128_mul_ovf(&p, ca, x->t[i++].num) || i128_mul_ovf(&q, cb, y->t[j++].num) ||
                 i128_add_ovf(&t.num, p, q);
        }
        if (st) {
            form_clear(&out);
            return overflow(err, "a linear combination of forms");
        }
        if (t.num)
            out.t[out.len++] = t;
    }
    out.den = L;
    canonicalize(&out);
    form_clear(r);
    *r = out;
    return PTP_OK;
}

/* Sorts terms by key: insertion sort when short, else a stable LSD radix sort on the key
 * bytes that differ between keys, through scratch space of n terms. */
static int sort_terms(form_term *terms, size_t n, ptp_error *err)
{
    form_term *a = terms, *b;
    form_key all_or = 0, all_and = ~(form_key)0;
    size_t i;
    int byte;
    if (n <= 32) {
        for (i = 1; i < n; i++) {
            form_term x = terms[i];
            size_t j = i;
            for (; j > 0 && terms[j - 1].key > x.key; j--)
                terms[j] = terms[j - 1];
            terms[j] = x;
        }
        return PTP_OK;
    }
    if (!(b = malloc(n * sizeof *b)))
        return ptp_fail(err, PTP_ENOMEM, "out of memory (sorting %zu terms)", n);
    for (i = 0; i < n; i++) {
        all_or |= terms[i].key;
        all_and &= terms[i].key;
    }
    for (byte = 0; byte < 8; byte++) {
        size_t cnt[256] = {0}, sum = 0, c;
        int shift = 8 * byte;
        form_term *t;
        if ((((all_or ^ all_and) >> shift) & 0xFF) == 0)
            continue; /* every key has the same byte here */
        for (i = 0; i < n; i++)
            cnt[(a[i].key >> shift) & 0xFF]++;
        for (c = 0; c < 256; c++) {
            size_t k = cnt[c];
            cnt[c] = sum;
            sum += k;
        }
        for (i = 0; i < n; i++)
            b[cnt[(a[i].key >> shift) & 0xFF]++] = a[i];
        t = a;
        a = b;
        b = t;
    }
    if (a != terms) {
        memcpy(terms, a, n * sizeof *terms);
        b = a;
    }
    free(b);
    return PTP_OK;
}

int form_set_terms(form *r, form_term *terms, size_t n, ptp_i128 den, ptp_error *err)
{
    size_t i, k = 0;
    int st;
    if (den <= 0)
        return ptp_fail(err, PTP_EINTERNAL, "form_set_terms: denominator not positive");
    if ((st = sort_terms(terms, n, err)))
        return st;
    r->len = 0;
    if ((st = reserve(r, n, err)))
        return st;
    for (i = 0; i < n; i++) {
        if (k && r->t[k - 1].key == terms[i].key) {
            if (i128_add_ovf(&r->t[k - 1].num, r->t[k - 1].num, terms[i].num)) {
                r->len = 0;
                r->den = 1;
                return overflow(err, "a sum of products");
            }
        } else {
            if (k && r->t[k - 1].num == 0)
                k--;
            r->t[k++] = terms[i];
        }
    }
    if (k && r->t[k - 1].num == 0)
        k--;
    r->len = k;
    r->den = den;
    canonicalize(r);
    return PTP_OK;
}

int form_equal(const form *x, const form *y)
{
    size_t i;
    if (x->rank != y->rank || x->len != y->len || x->den != y->den)
        return 0;
    for (i = 0; i < x->len; i++)
        if (x->t[i].key != y->t[i].key || x->t[i].num != y->t[i].num)
            return 0;
    return 1;
}

void form_get_weight(rat *w, const form *f, size_t i)
{
    int st = rat_set_frac(w, f->t[i].num, f->den);
    assert(st == PTP_OK); /* canonical: den > 0 and num != -2^127 */
    (void)st;
}
