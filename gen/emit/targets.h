/* targets.h: the registry of ptpgen's targets, the one place a target is added: its name,
 * file suffix, description, emitter, and the generation options its output depends on. */
#ifndef TARGETS_H
#define TARGETS_H

#include "emit/kern.h"

/* The generation options a target uses: an option whose bit a target lacks leaves its bytes
 * unchanged (apart from the command line a banner quotes). */
enum {
    TGT_SPACE = 1 << 0,     /* --space: C and kernels (clip z or world eye dot) */
    TGT_RULE = 1 << 1,      /* --rule: C and kernels (the classification) */
    TGT_PLANES = 1 << 2,    /* --planes: GPU kernels write every value (C has planes() always) */
    TGT_CERTIFIED = 1 << 3, /* --certified: C and kernels (rounding bounds) */
    TGT_REFINE = 1 << 4,    /* --refine K: C only (a de Casteljau loop on the CPU) */
    TGT_PREFIX = 1 << 5,    /* --prefix: targets that declare names (table, C, kernels) */
    TGT_SCHEDULE = 1 << 6,  /* --threads-per-patch, --patches-per-block: targets that write the
                               schedule (json, table, stats, GPU kernels; C: a thread a patch) */
    TGT_KERNEL = 1 << 7     /* --kernel, --stage: the GPU targets' form (straight-line or table,
                               kernel or functions) */
};
/* The number of TGT_ bits. */
#define TGT_NOPTIONS 8

/* An emitter: writes target output for table t into o (the signature of out.h and kern.h). */
typedef int (*tgt_emit)(sbuf *o, const tp_table *t, const out_info *info, ptp_error *err);

typedef struct {
    const char *name;        /* "glsl", the --target value */
    const char *suffix;      /* ending of the default file name after the prefix without its '_'
                                ("ptp_3x3" + ".comp"), "" for a report that is no file (stats) */
    const char *description; /* one line, for the usage text */
    tgt_emit emit;           /* the emitter, or NULL for a GPU kernel */
    const kern_target *gpu;  /* a GPU kernel's table for kern_emit_gpu, or NULL */
    unsigned options;        /* the TGT_ bits of the options its output depends on */
} tgt_target;

/* The targets, tgt_targets[0] the default; tgt_count of them. */
extern const tgt_target tgt_targets[];
extern const int tgt_count;

/* Writes target g's output for table t into o: its emitter, or kern_emit_gpu with its table,
 * with info's suffix set to g's. */
int tgt_emit_target(sbuf *o, const tgt_target *g, const tp_table *t, const out_info *info,
                    ptp_error *err);
/* The target called name, or NULL. */
const tgt_target *tgt_find(const char *name);
/* The option name of TGT_ bit number i (0 <= i < TGT_NOPTIONS): "space", ..., "schedule". */
const char *tgt_option_name(int i);
/* Appends the registry, one target a line: "name suffix options description", suffix "-" when
 * empty, options the comma-separated names of its bits ("-" when none). */
void tgt_write_list(sbuf *o);

#endif
