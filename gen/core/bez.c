/* bez.c: the symbolic Bernstein polynomial operations of the derivation engine.
 * All arithmetic is exact; products accumulate integers over one denominator per cell. */
#include "core/bez.h"
#include "core/i128.h"

#include <assert.h>
#include <stdlib.h>

/* C(n, k) for 0 <= k <= n <= 3*PTP_MAX_DEGREE (exact: the running product stays below
 * C(n, k) * n). */
static ptp_i128 binom(int n, int k)
{
    ptp_i128 c = 1;
    int i;
    for (i = 0; i < k; i++)
        c = c * (n - i) / (i + 1);
    return c;
}

int bez_init(bez *p, int du, int dv, int rank, ptp_error *err)
{
    size_t n = (size_t)(du + 1) * (size_t)(dv + 1), i;
    p->du = du;
    p->dv = dv;
    p->rank = rank;
    p->c = malloc(n * sizeof *p->c);
    if (!p->c)
        return ptp_fail(err, PTP_ENOMEM, "out of memory (polynomial of bidegree %dx%d)", du, dv);
    for (i = 0; i < n; i++)
        form_init(&p->c[i], rank);
    return PTP_OK;
}

void bez_clear(bez *p)
{
    size_t n = (size_t)(p->du + 1) * (size_t)(p->dv + 1), i;
    if (!p->c)
        return;
    for (i = 0; i < n; i++)
        form_clear(&p->c[i]);
    free(p->c);
    p->c = NULL;
}

int bez_patch(bez *B, const tp_domain *d, ptp_error *err)
{
    rat one;
    int i, j, st;
    if ((st = bez_init(B, d->n, d->m, 1, err)))
        return st;
    rat_set_si(&one, 1);
    for (i = 0; i <= d->n; i++)
        for (j = 0; j <= d->m; j++)
            if ((st = form_set_point(bez_at(B, i, j), tp_domain_point(d, i, j), &one, err))) {
                bez_clear(B);
                return st;
            }
    return PTP_OK;
}

/* D = derivative along u (along_u) or v: D_k = d * (P_{k+1} - P_k) in that index. */
static int diff(bez *D, const bez *P, int along_u, ptp_error *err)
{
    int d = along_u ? P->du : P->dv, I, J, st;
    rat pd, nd;
    if (d < 1)
        return ptp_fail(err, PTP_EINTERNAL, "derivative of a polynomial of degree 0");
    if ((st = bez_init(D, P->du - along_u, P->dv - !along_u, P->rank, err)))
        return st;
    rat_set_si(&pd, d);
    rat_set_si(&nd, -d);
    for (I = 0; I <= D->du; I++)
        for (J = 0; J <= D->dv; J++) {
            const form *hi = bez_at(P, I + along_u, J + !along_u), *lo = bez_at(P, I, J);
            if ((st = form_lincomb(bez_at(D, I, J), &pd, hi, &nd, lo, err))) {
                bez_clear(D);
                return st;
            }
        }
    return PTP_OK;
}

int bez_diff_u(bez *D, const bez *P, ptp_error *err)
{
    return diff(D, P, 1, err);
}

int bez_diff_v(bez *D, const bez *P, ptp_error *err)
{
    return diff(D, P, 0, err);
}

static int mul_overflow(ptp_error *err)
{
    return ptp_fail(err, PTP_EOVERFLOW, "exact arithmetic overflowed 128 bits in a Bernstein product");
}

/* Binomial rows of the two factors' degrees, computed once per product. */
typedef struct {
    ptp_i128 au[3 * PTP_MAX_DEGREE + 1], av[3 * PTP_MAX_DEGREE + 1];
    ptp_i128 bu[3 * PTP_MAX_DEGREE + 1], bv[3 * PTP_MAX_DEGREE + 1];
} binom_rows;

/* The factor of cell pair (ia, ja) x (ib, jb): the Bernstein numerators over both
 * denominators, in lowest terms. */
static int pair_factor(rat *f, const bez *A, const bez *B, const binom_rows *c, int ia, int ja,
                       int ib, int jb)
{
    ptp_i128 n, d;
    const form *fa = bez_at(A, ia, ja), *fb = bez_at(B, ib, jb);
    if (i128_mul_ovf(&n, c->au[ia], c->bu[ib]) || i128_mul_ovf(&n, n, c->av[ja]) ||
        i128_mul_ovf(&n, n, c->bv[jb]) || i128_mul_ovf(&d, fa->den, fb->den))
        return PTP_EOVERFLOW;
    return rat_set_frac(f, n, d);
}

/* Collects the products for output cell (I, J) into *buf (growing it) and sets the cell. */
static int mul_cell(bez *R, const bez *A, const bez *B, const binom_rows *c, int I, int J,
                    form_term **buf, size_t *cap, rat *factors, ptp_error *err)
{
    int ia, ja, ilo = I > B->du ? I - B->du : 0, jlo = J > B->dv ? J - B->dv : 0;
    int ihi = I < A->du ? I : A->du, jhi = J < A->dv ? J : A->dv, np = 0;
    ptp_i128 L = 1, den;
    size_t n = 0;
    /* Pass 1: the pair factors and their common denominator L. */
    for (ia = ilo; ia <= ihi; ia++)
        for (ja = jlo; ja <= jhi; ja++, np++) {
            rat *f = &factors[np];
            if (pair_factor(f, A, B, c, ia, ja, I - ia, J - ja) || rat_lcm_den(&L, f))
                return mul_overflow(err);
        }
    /* Pass 2: every product of a term of A's cell with a term of B's cell, over L. */
    np = 0;
    for (ia = ilo; ia <= ihi; ia++)
        for (ja = jlo; ja <= jhi; ja++, np++) {
            const form *fa = bez_at(A, ia, ja), *fb = bez_at(B, I - ia, J - ja);
            ptp_i128 s;
            size_t x, y;
            if (i128_mul_ovf(&s, factors[np].num, L / factors[np].den))
                return mul_overflow(err);
            if (n + fa->len * fb->len > *cap) {
                size_t c = *cap ? *cap : 256;
                form_term *t;
                while (c < n + fa->len * fb->len)
                    c *= 2;
                if (!(t = realloc(*buf, c * sizeof *t)))
                    return ptp_fail(err, PTP_ENOMEM, "out of memory (%zu products)", c);
                *buf = t;
                *cap = c;
            }
            for (x = 0; x < fa->len; x++) {
                ptp_i128 sx;
                if (i128_mul_ovf(&sx, s, fa->t[x].num))
                    return mul_overflow(err);
                for (y = 0; y < fb->len; y++) {
                    form_term *t = &(*buf)[n];
                    int sign = form_key_wedge(&t->key, fa->t[x].key, A->rank, fb->t[y].key, B->rank);
                    if (!sign)
                        continue;
                    if (i128_mul_ovf(&t->num, sx, sign * fb->t[y].num))
                        return mul_overflow(err);
                    n++;
                }
            }
        }
    if (i128_mul_ovf(&den, L, binom(A->du + B->du, I)) ||
        i128_mul_ovf(&den, den, binom(A->dv + B->dv, J)))
        return mul_overflow(err);
    return form_set_terms(bez_at(R, I, J), *buf, n, den, err);
}

int bez_mul(bez *R, const bez *A, const bez *B, ptp_error *err)
{
    form_term *buf = NULL;
    size_t cap = 0;
    rat *factors;
    binom_rows c;
    int I, J, st;
    if (A->rank + B->rank > FORM_MAX_RANK)
        return ptp_fail(err, PTP_EINTERNAL, "product of rank %d exceeds %d", A->rank + B->rank,
                        FORM_MAX_RANK);
    if ((st = bez_init(R, A->du + B->du, A->dv + B->dv, A->rank + B->rank, err)))
        return st;
    factors = malloc((size_t)(A->du + 1) * (size_t)(A->dv + 1) * sizeof *factors);
    if (!factors) {
        bez_clear(R);
        return ptp_fail(err, PTP_ENOMEM, "out of memory (Bernstein product)");
    }
    for (I = 0; I <= 3 * PTP_MAX_DEGREE; I++) {
        c.au[I] = I <= A->du ? binom(A->du, I) : 0;
        c.av[I] = I <= A->dv ? binom(A->dv, I) : 0;
        c.bu[I] = I <= B->du ? binom(B->du, I) : 0;
        c.bv[I] = I <= B->dv ? binom(B->dv, I) : 0;
    }
    for (I = 0; I <= R->du && !st; I++)
        for (J = 0; J <= R->dv && !st; J++)
            st = mul_cell(R, A, B, &c, I, J, &buf, &cap, factors, err);
    free(buf);
    free(factors);
    if (st)
        bez_clear(R);
    return st;
}

/* Degree reduction along u (along_u) or v. With c_0..c_d the coefficients of one line,
 * degree elevation gives c_i = (i/d) r_{i-1} + (1 - i/d) r_i, so r_0 = c_0,
 * r_i = (d c_i - i r_{i-1}) / (d - i) for 0 < i < d, and the residual c_d - r_{d-1} must vanish. */
static int reduce(bez *R, const bez *P, int along_u, ptp_error *err)
{
    int d = along_u ? P->du : P->dv, lines = along_u ? P->dv + 1 : P->du + 1, line, i, st = 0;
    if (d < 1)
        return ptp_fail(err, PTP_EINTERNAL, "degree reduction of a polynomial of degree 0");
    if ((st = bez_init(R, P->du - along_u, P->dv - !along_u, P->rank, err)))
        return st;
    for (line = 0; line < lines; line++) {
#define CELL(p, k) (along_u ? bez_at(p, k, line) : bez_at(p, line, k))
        rat zero, one, a, b;
        rat_set_si(&zero, 0);
        rat_set_si(&one, 1);
        if ((st = form_lincomb(CELL(R, 0), &one, CELL(P, 0), &zero, CELL(P, 0), err)))
            break;
        for (i = 1; i < d && !st; i++) {
            st = rat_set_frac(&a, d, d - i) | rat_set_frac(&b, -i, d - i);
            assert(st == PTP_OK); /* small integers over d - i > 0 */
            st = form_lincomb(CELL(R, i), &a, CELL(P, i), &b, CELL(R, i - 1), err);
        }
        if (!st && !form_equal(CELL(P, d), CELL(R, d - 1)))
            st = ptp_fail(err, PTP_EINTERNAL,
                            "degree reduction along %c left a nonzero residual in line %d: the "
                            "polynomial is not of degree %d",
                            along_u ? 'u' : 'v', line, d - 1);
        if (st)
            break;
#undef CELL
    }
    if (st)
        bez_clear(R);
    return st;
}

int bez_reduce_u(bez *R, const bez *P, ptp_error *err)
{
    return reduce(R, P, 1, err);
}

int bez_reduce_v(bez *R, const bez *P, ptp_error *err)
{
    return reduce(R, P, 0, err);
}
