/* emit_c.c: the C target: an stb-style single header (declarations, and the implementation
 * where <PREFIX>IMPLEMENTATION is defined) with the paper's table-driven loop. */
#include "kern.h"
#include "template.h"

#include <stdio.h>
#include <string.h>

/* The implementation: cross4, planes, values, classify and classify_batch. */
static void put_functions(sbuf *o, const out_info *info, const char *up)
{
    const char *px = info->prefix;
    sbuf_printf(o,
                "/* cross4 of Appendix A of Loop, Niessner and Eisenacher (2011): r . x = -det[a b c x].\n"
                " * Its products are never contracted into FMAs, so two equal points give exactly 0. */\n"
                "#if defined(__GNUC__) && !defined(__clang__)\n"
                "#pragma GCC push_options\n#pragma GCC optimize(\"fp-contract=off\")\n#endif\n"
                "static void %scross4(float r[4], const float a[4], const float b[4], const float c[4])\n{\n"
                "#if defined(__clang__)\n#pragma STDC FP_CONTRACT OFF\n#endif\n"
                "    r[0] = a[1] * (b[2] * c[3] - b[3] * c[2]) - b[1] * (a[2] * c[3] - a[3] * c[2]) +\n"
                "           c[1] * (a[2] * b[3] - a[3] * b[2]);\n"
                "    r[1] = -(a[0] * (b[2] * c[3] - b[3] * c[2]) - b[0] * (a[2] * c[3] - a[3] * c[2]) +\n"
                "             c[0] * (a[2] * b[3] - a[3] * b[2]));\n"
                "    r[2] = a[0] * (b[1] * c[3] - b[3] * c[1]) - b[0] * (a[1] * c[3] - a[3] * c[1]) +\n"
                "           c[0] * (a[1] * b[3] - a[3] * b[1]);\n"
                "    r[3] = -(a[0] * (b[1] * c[2] - b[2] * c[1]) - b[0] * (a[1] * c[2] - a[2] * c[1]) +\n"
                "             c[0] * (a[1] * b[2] - a[2] * b[1]));\n}\n"
                "#if defined(__GNUC__) && !defined(__clang__)\n#pragma GCC pop_options\n#endif\n\n",
                px);
    sbuf_printf(o,
                "void %splanes(const float cp[][4], float t[][4])\n{\n"
                "    unsigned x, c;\n"
                "    for (x = 0; x < %sPLANES; x++)\n"
                "        t[x][0] = t[x][1] = t[x][2] = t[x][3] = 0.0f;\n"
                "    for (x = 0; x < %sTERMS; x++) {\n"
                "        float r[4];\n"
                "        %scross4(r, cp[%sidx[x][1]], cp[%sidx[x][2]], cp[%sidx[x][3]]);\n"
                "        for (c = 0; c < 4; c++)\n"
                "            t[%sidx[x][0]][c] += %swgt[x] * r[c];\n"
                "    }\n}\n\n",
                px, up, up, px, px, px, px, px, px);
    sbuf_printf(o, "void %svalues(const float cp[][4], const float eye[4], float d[])\n{\n"
                   "    unsigned x;\n"
                   "    for (x = 0; x < %sPLANES; x++)\n"
                   "        d[x] = 0.0f;\n"
                   "    for (x = 0; x < %sTERMS; x++) {\n"
                   "        float r[4];\n"
                   "        %scross4(r, cp[%sidx[x][1]], cp[%sidx[x][2]], cp[%sidx[x][3]]);\n",
                px, up, up, px, px, px, px);
    if (info->space == OUT_CLIP)
        sbuf_printf(o, "        d[%sidx[x][0]] += %swgt[x] * r[2];\n    }\n"
                       "    for (x = 0; x < %sPLANES; x++)\n        d[x] *= eye[2];\n}\n\n",
                    px, px, up);
    else
        sbuf_printf(o, "        d[%sidx[x][0]] += %swgt[x] * (eye[0] * r[0] + eye[1] * r[1] + eye[2] * r[2] + eye[3] * r[3]);\n"
                       "    }\n}\n\n",
                    px, px);
    sbuf_printf(o, "unsigned %sclassify(const float cp[][4], const float eye[4])\n{\n"
                   "    float d[%sPLANES];\n"
                   "    unsigned x, f = 0;\n"
                   "    %svalues(cp, eye, d);\n"
                   "    for (x = 0; x < %sPLANES; x++)\n",
                px, up, px, up);
    if (info->rule == OUT_STRICT)
        sbuf_printf(o, "        f |= (d[x] < 0.0f ? 0u : 1u) | (d[x] > 0.0f ? 0u : 2u); /* not < 0, not > 0 */\n"
                       "    /* Strict: back iff every value < 0, front iff every value > 0. */\n"
                       "    return !(f & 1u) ? %sBACK : !(f & 2u) ? %sFRONT : %sSILHOUETTE;\n}\n\n",
                    up, up, up);
    else
        sbuf_printf(o, "        f |= (d[x] > 0.0f ? 1u : 0u) | (d[x] < 0.0f ? 2u : 0u) | (d[x] != d[x] ? 4u : 0u);\n"
                       "    /* Degenerate: back iff no value > 0, front iff no value < 0; NaN: silhouette. */\n"
                       "    return (f & 4u) ? %sSILHOUETTE : !(f & 1u) ? %sBACK : !(f & 2u) ? %sFRONT : %sSILHOUETTE;\n}\n\n",
                    up, up, up, up);
    sbuf_printf(o, "void %sclassify_batch(const float (*cp)[4], size_t patch_count, const float eye[4],\n"
                   "                    unsigned char *cls)\n{\n"
                   "    size_t p;\n"
                   "    for (p = 0; p < patch_count; p++)\n"
                   "        cls[p] = (unsigned char)%sclassify(cp + p * %sPOINTS, eye);\n}\n",
                px, px, up);
}

int emit_c(sbuf *o, const tp_table *t, const out_info *info, ptp_error *err)
{
    sbuf banner, tables, funcs;
    out_info plain;
    char up[64], file[96], points[16], planes[16], count[80];
    tpl_slot slots[9];
    int st;
    out_upper(up, sizeof up, info->prefix);
    kern_file_name(file, sizeof file, info->prefix, ".h");
    snprintf(points, sizeof points, "%d", t->npoints);
    snprintf(planes, sizeof planes, "%d", t->nplanes);
    snprintf(count, sizeof count, "%sTERMS", up);
    sbuf_init(&banner);
    sbuf_init(&tables);
    sbuf_init(&funcs);
    plain = *info;
    plain.sched = NULL; /* one thread per patch: no schedule */
    kern_banner(&banner, t, &plain, file, "C99 single header (stb style)",
                " * In exactly one C file, #define <PREFIX>IMPLEMENTATION before including this header.\n"
                " * Headers of several degrees (prefixes) may be included in one program.\n");
    sbuf_printf(&tables, "\n#define %sTERMS %zu\n", up, t->nterms);
    out_c_arrays(&tables, t, NULL, info->prefix, count, NULL, 0);
    put_functions(&funcs, info, up);
    slots[0] = (tpl_slot){"BANNER", banner.s};
    slots[1] = (tpl_slot){"PREFIX", info->prefix};
    slots[2] = (tpl_slot){"UPREFIX", up};
    slots[3] = (tpl_slot){"POINTS", points};
    slots[4] = (tpl_slot){"PLANES", planes};
    slots[5] = (tpl_slot){"VALUE", info->space == OUT_CLIP ? "clip space: eye[2] * t_P.z"
                                                         : "world space: eye . t_P"};
    slots[6] = (tpl_slot){"TABLES", tables.s};
    slots[7] = (tpl_slot){"FUNCTIONS", funcs.s};
    st = banner.failed || tables.failed || funcs.failed
             ? ptp_fail(err, PTP_ENOMEM, "out of memory writing the C header")
             : tpl_fill(o, "c/kernel.h", slots, 8, err);
    sbuf_clear(&banner);
    sbuf_clear(&tables);
    sbuf_clear(&funcs);
    return st;
}
