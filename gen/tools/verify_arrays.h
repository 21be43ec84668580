/* verify_arrays.h: the arrays of a C table besides idx and wgt (iwgt, owner, sched_*), checked
 * against idx, wgt and the derivation, for verify.c. */
#ifndef VERIFY_ARRAYS_H
#define VERIFY_ARRAYS_H

#include "emit/sbuf.h"
#include "tools/verify_parse.h"

/* What verify_arrays found. */
typedef struct {
    size_t problems;  /* the problem lines it wrote */
    int iwgt_exact;   /* iwgt with DENOM was checked and gives every weight exactly */
} verify_arrays_result;

/* Checks d's arrays besides idx and wgt: iwgt[x] == DENOM * want[x] (want[x]: the exact weight
 * of term x as written, known where known[x]) and consistent with wgt[x]; sched_idx/sched_wgt
 * (and sched_iwgt) a permutation of the terms plus padding slots of weight 0, THREADS dividing
 * the slots; owner (nplanes entries) naming the thread of every slot's plane. Appends a line
 * "NAME:LINE: ..." per problem to o, then "NAME: checked: ...; ignored: ..." (what was checked,
 * and what could not be: unknown arrays, arrays missing what they need, functions). Returns
 * PTP_OK or PTP_ENOMEM. */
int verify_arrays(sbuf *o, verify_arrays_result *res, const verify_doc *d, const rat *want,
                  const char *known, int nplanes, const char *name, ptp_error *err);

#endif
