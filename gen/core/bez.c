/* bez.c: the symbolic Bernstein polynomial operations of the derivation engine.
 * All arithmetic is exact; products accumulate integers over one denominator per cell. */
#include "core/bez.h"
#include "core/i128.h"

#include <assert.h>
#include <stdlib.h>

/* C(n, k) for 0 <= k <= n <= 3*PTP_MAX_TRI_DEGREE (exact: the running product stays below
 * C(n, k) * n). */
static ptp_i128 binom(int n, int k)
{
    ptp_i128 c = 1;
    int i;
    for (i = 0; i < k; i++)
        c = c * (n - i) / (i + 1);
    return c;
}

/* The number of coefficients of p. */
static size_t bez_count(const bez *p)
{
    return (size_t)tp_grid_count(p->kind, p->du, p->dv);
}

int bez_init(bez *p, tp_kind kind, int du, int dv, int rank, ptp_error *err)
{
    size_t n, i;
    p->kind = kind;
    p->du = du;
    p->dv = kind == TP_TRI ? du : dv;
    p->rank = rank;
    n = bez_count(p);
    p->c = malloc(n * sizeof *p->c);
    if (!p->c)
        return ptp_fail(err, PTP_ENOMEM, "out of memory (polynomial of degrees %d, %d)", du, dv);
    for (i = 0; i < n; i++)
        form_init(&p->c[i], rank);
    return PTP_OK;
}

void bez_clear(bez *p)
{
    size_t n = bez_count(p), i;
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
    int k, i, j, st;
    if ((st = bez_init(B, d->kind, d->n, d->m, 1, err)))
        return st;
    rat_set_si(&one, 1);
    for (k = 0; k < d->npoints; k++) {
        tp_domain_point_ij(&i, &j, d, k);
        if ((st = form_set_point(bez_at(B, i, j), tp_domain_point(d, i, j), &one, err))) {
            bez_clear(B);
            return st;
        }
    }
    return PTP_OK;
}

/* D = derivative along u (along_u) or v: D_IJ = d * (P_{IJ + e} - P_IJ), e the unit step in
 * that index; a triangle's step lowers K, which the (I, J) numbering leaves implicit. */
static int diff(bez *D, const bez *P, int along_u, ptp_error *err)
{
    int d = along_u ? P->du : P->dv, tri = P->kind == TP_TRI, k, I, J, st;
    rat pd, nd;
    if (d < 1)
        return ptp_fail(err, PTP_EINTERNAL, "derivative of a polynomial of degree 0");
    if ((st = bez_init(D, P->kind, P->du - (along_u || tri), P->dv - !along_u, P->rank, err)))
        return st;
    rat_set_si(&pd, d);
    rat_set_si(&nd, -d);
    for (k = 0; k < (int)bez_count(D); k++) {
        const form *hi, *lo;
        tp_grid_coords(&I, &J, D->kind, D->du, D->dv, k);
        hi = bez_at(P, I + along_u, J + !along_u);
        lo = bez_at(P, I, J);
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

/* *c = the Bernstein constant of cell (I, J) of p: C(du, I) C(dv, J) for quads, the
 * multinomial D!/(I! J! K!) = C(D, I) C(D-I, J) for triangles. Nonzero on overflow. */
static int cell_const(ptp_i128 *c, const bez *p, int I, int J)
{
    if (p->kind == TP_TRI)
        return i128_mul_ovf(c, binom(p->du, I), binom(p->du - I, J));
    return i128_mul_ovf(c, binom(p->du, I), binom(p->dv, J));
}

/* The Bernstein constants of every cell of the two factors, computed once per product. */
typedef struct {
    ptp_i128 *a, *b;
} cell_consts;

/* The factor of cell pair (ia, ja) x (ib, jb): the Bernstein constants over both
 * denominators, in lowest terms. */
static int pair_factor(rat *f, const bez *A, const bez *B, const cell_consts *c, int ia, int ja,
                       int ib, int jb)
{
    ptp_i128 n, d;
    const form *fa = bez_at(A, ia, ja), *fb = bez_at(B, ib, jb);
    if (i128_mul_ovf(&n, c->a[tp_grid_index(A->kind, A->du, A->dv, ia, ja)],
                     c->b[tp_grid_index(B->kind, B->du, B->dv, ib, jb)]) ||
        i128_mul_ovf(&d, fa->den, fb->den))
        return PTP_EOVERFLOW;
    return rat_set_frac(f, n, d);
}

/* The range [*lo, *hi] of a factor index i with 0 <= i <= da and 0 <= I - i <= db. */
static void pair_range(int *lo, int *hi, int I, int da, int db)
{
    *lo = I > db ? I - db : 0;
    *hi = I < da ? I : da;
}

/* Nonzero when (ia, ja) is a cell of A and (I-ia, J-ja) one of B. */
static int pair_ok(const bez *A, const bez *B, int I, int J, int ia, int ja)
{
    return tp_grid_has(A->kind, A->du, A->dv, ia, ja) &&
           tp_grid_has(B->kind, B->du, B->dv, I - ia, J - ja);
}

/* Appends to *buf (growing it, *n used of *cap) every product of a term of fa with a term
 * of fb, scaled by s. */
static int mul_terms(form_term **buf, size_t *n, size_t *cap, const form *fa, const form *fb,
                     ptp_i128 s, ptp_error *err)
{
    size_t x, y;
    if (*n + fa->len * fb->len > *cap) {
        size_t c = *cap ? *cap : 256;
        form_term *t;
        while (c < *n + fa->len * fb->len)
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
            form_term *t = &(*buf)[*n];
            int sign = form_key_wedge(&t->key, fa->t[x].key, fa->rank, fb->t[y].key, fb->rank);
            if (!sign)
                continue;
            if (i128_mul_ovf(&t->num, sx, sign * fb->t[y].num))
                return mul_overflow(err);
            (*n)++;
        }
    }
    return PTP_OK;
}

/* Collects the products for output cell (I, J) into *buf (growing it) and sets the cell. */
static int mul_cell(bez *R, const bez *A, const bez *B, const cell_consts *c, int I, int J,
                    form_term **buf, size_t *cap, rat *factors, ptp_error *err)
{
    int ia, ja, ilo, ihi, jlo, jhi, np = 0, st;
    ptp_i128 L = 1, den;
    size_t n = 0;
    pair_range(&ilo, &ihi, I, A->du, B->du);
    pair_range(&jlo, &jhi, J, A->dv, B->dv);
    /* Pass 1: the pair factors and their common denominator L. */
    for (ia = ilo; ia <= ihi; ia++)
        for (ja = jlo; ja <= jhi; ja++) {
            rat *f = &factors[np];
            if (!pair_ok(A, B, I, J, ia, ja))
                continue;
            np++;
            if (pair_factor(f, A, B, c, ia, ja, I - ia, J - ja) || rat_lcm_den(&L, f))
                return mul_overflow(err);
        }
    /* Pass 2: every product of a term of A's cell with a term of B's cell, over L. */
    np = 0;
    for (ia = ilo; ia <= ihi; ia++)
        for (ja = jlo; ja <= jhi; ja++) {
            ptp_i128 s;
            if (!pair_ok(A, B, I, J, ia, ja))
                continue;
            if (i128_mul_ovf(&s, factors[np].num, L / factors[np].den))
                return mul_overflow(err);
            np++;
            if ((st = mul_terms(buf, &n, cap, bez_at(A, ia, ja), bez_at(B, I - ia, J - ja), s, err)))
                return st;
        }
    if (cell_const(&den, R, I, J) || i128_mul_ovf(&den, L, den))
        return mul_overflow(err);
    return form_set_terms(bez_at(R, I, J), *buf, n, den, err);
}

/* c = the Bernstein constants of every cell of A and B; PTP_ENOMEM or PTP_EOVERFLOW. */
static int consts_init(cell_consts *c, const bez *A, const bez *B, ptp_error *err)
{
    int k, I, J, ovf = 0;
    c->a = malloc(bez_count(A) * sizeof *c->a);
    c->b = malloc(bez_count(B) * sizeof *c->b);
    if (!c->a || !c->b) {
        free(c->a);
        free(c->b);
        return ptp_fail(err, PTP_ENOMEM, "out of memory (Bernstein product)");
    }
    for (k = 0; k < (int)bez_count(A) && !ovf; k++) {
        tp_grid_coords(&I, &J, A->kind, A->du, A->dv, k);
        ovf = cell_const(&c->a[k], A, I, J);
    }
    for (k = 0; k < (int)bez_count(B) && !ovf; k++) {
        tp_grid_coords(&I, &J, B->kind, B->du, B->dv, k);
        ovf = cell_const(&c->b[k], B, I, J);
    }
    if (ovf) {
        free(c->a);
        free(c->b);
        return mul_overflow(err);
    }
    return PTP_OK;
}

int bez_mul(bez *R, const bez *A, const bez *B, ptp_error *err)
{
    form_term *buf = NULL;
    size_t cap = 0;
    rat *factors;
    cell_consts c;
    int k, I, J, st;
    if (A->rank + B->rank > FORM_MAX_RANK || A->kind != B->kind)
        return ptp_fail(err, PTP_EINTERNAL, "product of rank %d (at most %d) or of two kinds",
                        A->rank + B->rank, FORM_MAX_RANK);
    if ((st = bez_init(R, A->kind, A->du + B->du, A->dv + B->dv, A->rank + B->rank, err)))
        return st;
    factors = malloc(bez_count(A) * sizeof *factors);
    if (!factors || (st = consts_init(&c, A, B, err))) {
        free(factors);
        bez_clear(R);
        return st ? st : ptp_fail(err, PTP_ENOMEM, "out of memory (Bernstein product)");
    }
    for (k = 0; k < (int)bez_count(R) && !st; k++) {
        tp_grid_coords(&I, &J, R->kind, R->du, R->dv, k);
        st = mul_cell(R, A, B, &c, I, J, &buf, &cap, factors, err);
    }
    free(buf);
    free(factors);
    free(c.a);
    free(c.b);
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
    if ((st = bez_init(R, P->kind, P->du - along_u, P->dv - !along_u, P->rank, err)))
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

/* r = (a*x + b*(y or z) + c*(w or z)) / q with y, w NULL for zero terms (z the zero form). */
static int lincomb3(form *r, int a, const form *x, int b, const form *y, int c, const form *w,
                    int q, const form *z, ptp_error *err)
{
    rat ra, rb, rc, one;
    int st;
    rat_set_frac(&ra, a, q);
    rat_set_frac(&rb, b, q);
    rat_set_frac(&rc, c, q);
    rat_set_si(&one, 1);
    if ((st = form_lincomb(r, &ra, x, &rb, y ? y : z, err)))
        return st;
    return form_lincomb(r, &one, r, &rc, w ? w : z, err);
}

/* Triangular degree reduction from e = D+1 to D. Elevation gives, for every cell (I, J, K) of
 * degree e, e c_IJ = I r_{I-1,J} + J r_{I,J-1} + K r_IJ. The cells with K > 0 give r_IJ in
 * order of increasing I + J; the cells with K = 0 are the residual, which must vanish. */
static int reduce_tri(bez *R, const bez *P, form *x, const form *z, ptp_error *err)
{
    int e = P->du, s, I, st = 0;
    for (s = 0; s <= e && !st; s++)
        for (I = 0; I <= s && !st; I++) {
            int J = s - I, K = e - s;
            const form *lu = I ? bez_at(R, I - 1, J) : NULL, *lv = J ? bez_at(R, I, J - 1) : NULL;
            if (K > 0) {
                st = lincomb3(bez_at(R, I, J), e, bez_at(P, I, J), -I, lu, -J, lv, K, z, err);
                continue;
            }
            if (!(st = lincomb3(x, 0, z, I, lu, J, lv, e, z, err)) && !form_equal(x, bez_at(P, I, J)))
                st = ptp_fail(err, PTP_EINTERNAL,
                              "degree reduction left a nonzero residual at (%d, %d, 0): the "
                              "triangular polynomial is not of degree %d", I, J, e - 1);
        }
    return st;
}

int bez_reduce_tri(bez *R, const bez *P, ptp_error *err)
{
    form x, z;
    int st;
    if (P->kind != TP_TRI || P->du < 1)
        return ptp_fail(err, PTP_EINTERNAL, "triangular degree reduction of degree %d", P->du);
    if ((st = bez_init(R, TP_TRI, P->du - 1, P->du - 1, P->rank, err)))
        return st;
    form_init(&x, P->rank);
    form_init(&z, P->rank);
    st = reduce_tri(R, P, &x, &z, err);
    form_clear(&x);
    form_clear(&z);
    if (st)
        bez_clear(R);
    return st;
}
