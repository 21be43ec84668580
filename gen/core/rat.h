/* rat.h: exact rationals in 128-bit integers with one canonical form.
 * Canonical: lowest terms, den > 0, zero is 0/1, num != -2^127; every overflow is reported. */
#ifndef RAT_H
#define RAT_H

#include "core/ptp.h"

typedef struct {
    ptp_i128 num;
    ptp_i128 den;
} rat;

/* Longest string rat_get_str writes, with the terminating NUL. */
#define RAT_STRLEN 84

/* r = n (n may be any int64). */
void rat_set_si(rat *r, int64_t n);
/* r = num/den in canonical form; PTP_EUSAGE when den == 0, PTP_EOVERFLOW when num or den
 * is -2^127 and cannot be negated. r is unchanged on failure. */
int rat_set_frac(rat *r, ptp_i128 num, ptp_i128 den);
/* Nonzero when a is in canonical form. */
int rat_is_canonical(const rat *a);
/* r = a + b, a - b, a * b, a / b. Aliasing of r with a or b is allowed. On failure
 * (PTP_EOVERFLOW; PTP_EUSAGE for division by zero) r is unchanged. Overflow is reported
 * when an intermediate product exceeds 127 bits, rarely even though the reduced result
 * would fit: an answer is never wrong, at worst refused. */
int rat_add(rat *r, const rat *a, const rat *b);
int rat_sub(rat *r, const rat *a, const rat *b);
int rat_mul(rat *r, const rat *a, const rat *b);
int rat_div(rat *r, const rat *a, const rat *b);
/* r = -a (never overflows for canonical a). */
void rat_neg(rat *r, const rat *a);
/* -1, 0 or 1: the sign of a. */
int rat_sgn(const rat *a);
/* Nonzero when a == b (both canonical). */
int rat_equal(const rat *a, const rat *b);
/* *D = lcm(*D, den of a), for *D > 0: the common denominator of a running set of weights;
 * PTP_EOVERFLOW (*D unchanged) when it does not fit 127 bits. */
int rat_lcm_den(ptp_i128 *D, const rat *a);
/* Nearest double (correct to within one rounding of each of num and den). */
double rat_get_d(const rat *a);
/* Writes "p" or "p/q" to buf (RAT_STRLEN bytes); returns buf. */
char *rat_get_str(char *buf, const rat *a);
/* Parses "p" or "p/q" (optional '-' on p, decimal digits) into canonical form;
 * PTP_EUSAGE when s is not of that form, PTP_EOVERFLOW when it does not fit. */
int rat_set_str(rat *r, const char *s);

#endif
