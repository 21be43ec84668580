/* verify.h: `ptpgen verify`: checks someone else's control-plane table against the derivation.
 * Reads the paper's C arrays (idx, wgt) or ptpgen's JSON and names every problem by its line. */
#ifndef VERIFY_H
#define VERIFY_H

#include "core/ptp.h"
#include "emit/sbuf.h"

#include <stddef.h>

/* The verdict on a table. */
enum { VERIFY_RIGHT = 0, VERIFY_WRONG = 1 };

/* The index convention a table is checked in: u-first (ptpgen's: point (i, j) numbered
 * i*(m+1)+j, plane (I, J) numbered I*(3m-1)+J; triangles by the domain's rule) or v-first
 * (point (i, j) numbered as u-first numbers (j, i): j*(n+1)+i, J*(3n-1)+I for quads). */
enum { VERIFY_U_FIRST = 0, VERIFY_V_FIRST = 1 };

/* The kind argument of verify_table that takes the domain from the document. */
#define VERIFY_KIND_ANY (-1)

/* Checks the table in text[0..len) (named `name` in messages, e.g. the file path) against the
 * exact table of the domain of the kind (TP_QUAD, TP_TRI, or VERIFY_KIND_ANY: the one the
 * document names, a json's "domain" or an idx array's name like ptp_tri3_table_idx, else quad)
 * and the degrees (n, m) (a triangle's: n = m = d), in the index convention `convention`;
 * n = m = 0 infers them (the json's "degree", or from the number of points and planes when that
 * is unambiguous, e.g. a square table; otherwise PTP_EUSAGE asking for --degree). Besides idx
 * and wgt, a C table's iwgt (with DENOM), owner (with THREADS) and sched_idx/sched_wgt/sched_iwgt
 * arrays are checked (verify_arrays.h). Appends the report to out: one line per problem
 * "NAME:LINE: message", a line "NAME: checked: ...; ignored: ...", then a one-line verdict. Sets
 * *verdict to VERIFY_RIGHT (exact, right to float precision, or right up to a global positive
 * scale, which the report names) or VERIFY_WRONG. Returns PTP_OK, or PTP_EUSAGE when text cannot
 * be read as a table (err says why, with the line) or names a kind other than the one given,
 * PTP_ENOMEM. Never crashes or hangs on any input. Also: PTP_EUSAGE for a negative n or m or
 * only one of them 0, PTP_ELIMIT beyond the kind's limit (PTP_MAX_DEGREE, PTP_MAX_TRI_DEGREE),
 * and tp_derive's status should the derivation fail. text need not end in a NUL and may hold
 * any bytes; on failure nothing is appended to out (PTP_ENOMEM may leave it marked failed); name
 * NULL reads "(input)". */
int verify_table(sbuf *out, int *verdict, const char *text, size_t len, const char *name,
                 int kind, int n, int m, int convention, ptp_error *err);

#endif
