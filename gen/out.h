/* out.h: the machine-readable outputs of a control-plane table: json, table, stats.
 * Each writes into an sbuf; nothing here touches files. */
#ifndef OUT_H
#define OUT_H

#include "sbuf.h"
#include "sched.h"
#include "tplane.h"

/* What every output names besides the table itself. */
typedef struct {
    const char *command; /* the normalized command line that makes this output */
    const char *prefix;  /* identifier prefix of generated names, e.g. "ptp_3x3_" */
    const sched *sched;  /* the schedule of the table's terms over a patch's threads */
} out_info;

/* The ptpgen-planes/1 JSON document of t. */
int out_json(sbuf *o, const tp_table *t, const out_info *info, ptp_error *err);
/* A C header in the paper's idx/wgt format, with exact weights in comments and an
 * integer form over one common denominator. */
int out_table(sbuf *o, const tp_table *t, const out_info *info, ptp_error *err);
/* The term count of every plane as a matrix, and the total. */
int out_stats(sbuf *o, const tp_table *t, const out_info *info, ptp_error *err);

#endif
