/* out.h: what every output is told (out_info) and the machine-readable outputs of a table: json,
 * table, stats, and the C arrays the C header shares. Each writes into an sbuf, never a file. */
#ifndef OUT_H
#define OUT_H

#include "emit/sbuf.h"
#include "plan/plan.h"
#include "plan/sched.h"
#include "core/tplane.h"

/* Clip space: control points already transformed, only z components needed; world space: the
 * full planes dotted with a homogeneous eye point. */
typedef enum { OUT_CLIP, OUT_WORLD } out_space;
/* strict: back iff all values < 0, front iff all > 0; degenerate: the paper's count rule, back
 * iff none > 0, front iff none < 0 (all zero counts as back). NaN makes a patch silhouette. */
typedef enum { OUT_STRICT, OUT_DEGENERATE } out_rule;

/* The straight-line GPU kernel's patches (invocations) per workgroup unless told otherwise: local
 * sizes of 8 to 256 ran alike on lavapipe (bench/README). */
#define OUT_SLP_GROUP 64

/* What every output names besides the table itself. */
typedef struct {
    const char *command; /* the normalized command line that makes this output */
    const char *prefix;  /* identifier prefix of generated names, e.g. "ptp_3x3_" */
    const sched *sched;  /* the schedule of the table's terms over a patch's threads */
    out_space space;
    out_rule rule;
    int planes;          /* kernels also write the per-plane values */
    int certified;       /* back or front only when every value clears its rounding bound */
    int refine;          /* C: de Casteljau levels on e.T when the values have mixed signs */
    const char *suffix;  /* the target's file suffix, ".comp" (tgt_emit_target sets it from the
                            registry): a banner names the file <prefix without its '_'><suffix> */
    int table;           /* GPU: the paper's table kernel, sched's P threads a patch (also with
                            certified; else the straight-line program, one patch an invocation) */
    int functions;       /* GPU: only the functions classify_patch and values, for any stage */
    int indexed;         /* GPU straight-line kernel: each patch's points through its indices
                            (with bspline, and its boundary mask: OpenSubdiv's phantoms) */
    int group;           /* GPU straight-line kernel: patches (invocations) per workgroup */
    int lanes;           /* OpenCL --kernel lanes: patches per work-item, a vector's width (or 0) */
    const plan_slp *slp; /* the straight-line plan (the C header, the GPU straight-line code;
                            tgt_emit_target builds it), or NULL */
    int bspline;         /* C and the straight-line GPU code: the points are a uniform bicubic
                            B-spline patch's control vertices (--basis bspline) */
    int vmajor;          /* the same: the points' rows run along v (--order v-major) */
    int absolute;        /* the code reads the coordinates as given (else patch-local: point
                            0's origin subtracted; WGSL's certified table kernel always reads
                            them as given) */
} out_info;

/* The ptpgen-planes/1 JSON document of t. */
int out_json(sbuf *o, const tp_table *t, const out_info *info, ptp_error *err);
/* A C header in the paper's idx/wgt format, with exact weights in comments and an
 * integer form over one common denominator. */
int out_table(sbuf *o, const tp_table *t, const out_info *info, ptp_error *err);
/* Writes C arrays NAMEidx[COUNT][4] = {plane, j, k, l} and NAMEwgt[COUNT] (float, the exact
 * rational in a comment) and, when itype is not NULL, NAMEiwgt[COUNT] (D * wgt, of type itype):
 * for the table's terms in order (s NULL) or the slots of schedule s, with padding rows. */
void out_c_arrays(sbuf *o, const tp_table *t, const sched *s, const char *name,
                  const char *count, const char *itype, ptp_i128 D);
/* The term count of every plane as a matrix, and the total. */
int out_stats(sbuf *o, const tp_table *t, const out_info *info, ptp_error *err);

#endif
