/* form.h: sparse linear combinations of alternating products of control points.
 * A rank-r form is sum_k (num_k / den) b_{j1} ^ ... ^ b_{jr}; the canonical form is FLINT's fmpq_poly's. */
#ifndef FORM_H
#define FORM_H

#include "core/ptp.h"
#include "core/rat.h"

/* The largest rank and point index a key can hold. */
#define FORM_MAX_RANK 3
#define FORM_MAX_POINT 0xFFFF

/* A product's point indices j1 < j2 < ... < jr packed 16 bits each, j1 highest, so that
 * numeric order of keys is lexicographic order of the index tuples. */
typedef uint64_t form_key;

typedef struct {
    form_key key;
    ptp_i128 num;
} form_term;

/* Canonical: keys strictly increasing, each key's indices strictly increasing, every num
 * nonzero, den > 0 and gcd(den, all nums) = 1; the zero form has len 0 and den 1. */
typedef struct {
    int rank;
    size_t len, cap;
    form_term *t;
    ptp_i128 den;
} form;

/* Initializes f as the zero form of the given rank (1..FORM_MAX_RANK). */
void form_init(form *f, int rank);
/* Frees f's storage; f must be initialized again before further use. */
void form_clear(form *f);
/* Nonzero when f is canonical. */
int form_is_canonical(const form *f);
/* The key of the single point j (rank 1). */
form_key form_key_point(int j);
/* Unpacks a rank-r key into idx[0..r-1]. */
void form_key_unpack(int *idx, form_key key, int rank);
/* The alternating product of keys a (rank ra) and b (rank rb): stores the sorted key in
 * *r and returns the sign of the sorting permutation, or 0 when an index repeats. */
int form_key_wedge(form_key *r, form_key a, int ra, form_key b, int rb);
/* r = w * b_j (rank 1). */
int form_set_point(form *r, int j, const rat *w, ptp_error *err);
/* r = a*x + b*y, x and y of r's rank; r may alias x or y. */
int form_lincomb(form *r, const rat *a, const form *x, const rat *b, const form *y,
                 ptp_error *err);
/* Sets r (whose rank is kept) to sum_i (terms[i].num / den) * key_i: sorts terms in place,
 * adds equal keys, drops zeros and reduces to canonical form. den must be positive. On
 * failure r is the zero form. */
int form_set_terms(form *r, form_term *terms, size_t n, ptp_i128 den, ptp_error *err);
/* Nonzero when x == y (both canonical). */
int form_equal(const form *x, const form *y);
/* w = the exact weight of term i of f. */
void form_get_weight(rat *w, const form *f, size_t i);

#endif
