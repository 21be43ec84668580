/* targets.c: the registry of ptpgen's targets, the one place a target is added.
 * Options per target follow what each emitter reads from out_info. */
#include "emit/targets.h"

#include <string.h>

#define KERNEL \
    (TGT_SPACE | TGT_RULE | TGT_PLANES | TGT_CERTIFIED | TGT_PREFIX | TGT_SCHEDULE | TGT_KERNEL)

const tgt_target tgt_targets[] = {
    {"json", ".json", "the exact terms and schedule, ptpgen-planes/1", out_json, NULL, TGT_SCHEDULE},
    {"table", "_table.h", "a C header in the paper's idx/wgt format", out_table, NULL,
     TGT_PREFIX | TGT_SCHEDULE},
    {"stats", "", "the term count of every plane and the schedule", out_stats, NULL, TGT_SCHEDULE},
    {"c", ".h", "a C99 single header (stb style)", emit_c, NULL,
     TGT_SPACE | TGT_RULE | TGT_CERTIFIED | TGT_REFINE | TGT_PREFIX},
    {"glsl", ".comp", "a compute kernel", NULL, &kern_glsl, KERNEL},
    {"hlsl", ".hlsl", "a compute kernel", NULL, &kern_hlsl, KERNEL},
    {"opencl", ".cl", "a compute kernel", NULL, &kern_opencl, KERNEL},
    {"cuda", ".cu", "a compute kernel", NULL, &kern_cuda, KERNEL},
    {"wgsl", ".wgsl", "a compute kernel", NULL, &kern_wgsl, KERNEL},
};
const int tgt_count = (int)(sizeof tgt_targets / sizeof *tgt_targets);

static const char *const option_names[] = {"space",  "rule",   "planes",  "certified",
                                           "refine", "prefix", "schedule", "kernel"};
_Static_assert(sizeof option_names / sizeof *option_names == TGT_NOPTIONS,
               "one name per TGT_ bit");

int tgt_emit_target(sbuf *o, const tgt_target *g, const tp_table *t, const out_info *info,
                    ptp_error *err)
{
    out_info in = *info;
    plan_slp plan;
    /* the straight-line program's rounding: the GPU target's (flushed subnormals), else IEEE's */
    const cert_model model = g->gpu ? (cert_model){g->gpu->slp_cert_u, 0x1p-126, 1} : CERT_MODEL_IEEE;
    int st;
    in.suffix = g->suffix;
    if (!(g->options & TGT_SPACE)) /* no straight-line code */
        return g->emit(o, t, &in, err);
    if ((st = plan_slp_build(&plan, t, info->space == OUT_WORLD,
                             (info->absolute ? 0 : PLAN_LOCAL) | (info->bspline ? PLAN_BSPLINE : 0) |
                                 (info->vmajor ? PLAN_VMAJOR : 0),
                             info->certified && !(g->gpu && info->table) ? &model : NULL, err)))
        return st;
    in.slp = &plan;
    st = g->gpu ? kern_emit_gpu(o, t, &in, g->gpu, err) : g->emit(o, t, &in, err);
    plan_slp_clear(&plan);
    return st;
}

const tgt_target *tgt_find(const char *name)
{
    int i;
    for (i = 0; i < tgt_count; i++)
        if (strcmp(tgt_targets[i].name, name) == 0)
            return &tgt_targets[i];
    return NULL;
}

const char *tgt_option_name(int i)
{
    return option_names[i];
}

void tgt_write_list(sbuf *o)
{
    int i, k;
    for (i = 0; i < tgt_count; i++) {
        const tgt_target *g = &tgt_targets[i];
        const char *sep = " ";
        sbuf_printf(o, "%s %s", g->name, g->suffix[0] ? g->suffix : "-");
        for (k = 0; k < TGT_NOPTIONS; k++)
            if (g->options >> k & 1) {
                sbuf_printf(o, "%s%s", sep, option_names[k]);
                sep = ",";
            }
        sbuf_printf(o, "%s %s\n", g->options ? "" : " -", g->description);
    }
}
