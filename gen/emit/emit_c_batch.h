/* emit_c_batch.h: the C header's classify_batch for emit_c.c: blocks of patch-major patches
 * transposed with vector shuffles into the lanes' structure-of-arrays layout, then classified. */
#ifndef EMIT_C_BATCH_H
#define EMIT_C_BATCH_H

#include "emit/out.h"

/* Appends the transposition and classify_batch of the C header of t (prefix info->prefix, upper
 * case up): the lanes, then the second look named second (or NULL) at the patches whose class
 * satisfies the test again (e.g. "== PTP_3X3_SILHOUETTE"), or under --refine without
 * --certified the refinement from the block's values. */
void emit_c_batch(sbuf *o, const tp_table *t, const out_info *info, const char *up,
                  const char *second, const char *again);

#endif
