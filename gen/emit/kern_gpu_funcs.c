/* kern_gpu_funcs.c: the GPU kernel's helper functions: the term (cross4), the differences of
 * points, the collapsed edges' tests and the classification; the second look's in kern_gpu_df.c. */
#include "emit/kern_gpu.h"

#include <stdio.h>

/* Writes to d (512 bytes) det[a b c] of rows p, q, s (components "xyzw"[i]) with the target's
 * products, its lines after the first indented by 8. */
static void put_det(char *d, const kern_target *g, int p, int q, int s)
{
    static const char comp[] = "xyzw";
    const char *col = "abc";
    size_t n = 0;
    int i;
    for (i = 0; i < 3; i++) {
        /* cofactor expansion along row p: +a.p (b c), -b.p (a c), +c.p (a b) */
        char u = col[i == 0 ? 1 : 0], v = col[i == 2 ? 1 : 2], x[16], y[16], m1[48], m2[48], e[128];
        snprintf(x, sizeof x, "%c.%c", u, comp[q]);
        snprintf(y, sizeof y, "%c.%c", v, comp[s]);
        snprintf(m1, sizeof m1, g->mul, x, y);
        snprintf(x, sizeof x, "%c.%c", u, comp[s]);
        snprintf(y, sizeof y, "%c.%c", v, comp[q]);
        snprintf(m2, sizeof m2, g->mul, x, y);
        snprintf(e, sizeof e, "(%s - %s)", m1, m2);
        snprintf(x, sizeof x, "%c.%c", col[i], comp[p]);
        n += (size_t)snprintf(d + n, 512 - n, "%s", i == 0 ? "" : i == 1 ? " -\n        " : " +\n        ");
        n += (size_t)snprintf(d + n, 512 - n, g->mul, x, e); /* at most 3 * 170 bytes in all */
    }
}

/* The term: cross4's z (clip space) or eye . cross4 (world). Its products are never contracted
 * into FMAs, so a term with two equal points (a collapsed edge) is exactly zero, as the
 * degenerate rule needs. */
static void put_cross4(sbuf *o, const out_info *info, const kern_target *g)
{
    const char *v = g->vec4;
    kern_param p[4] = {{v, "a"}, {v, "b"}, {v, "c"}, {v, "e"}};
    kern_var x = {"z", NULL, 0};
    char name[128], det[512];
    if (info->space == OUT_CLIP) {
        sbuf_puts(o, "/* The z component of cross4(a, b, c): det of rows x, y, w. */\n");
        snprintf(name, sizeof name, "%scross4z", info->prefix);
        g->syntax->function(o, g, g->real, name, p, 3);
        put_det(det, g, 0, 1, 3);
        x.init = det;
        g->syntax->locals(o, g, "    ", g->real, &x, 1, 1);
        sbuf_puts(o, "    return z;\n}\n\n");
    } else {
        static const int rows[4][3] = {{1, 2, 3}, {0, 2, 3}, {0, 1, 3}, {0, 1, 2}};
        static const char *const names[4] = {"x", "y", "z", "w"};
        char e[8], m[4][32];
        int c;
        sbuf_puts(o, "/* e . cross4(a, b, c), cross4 as in Appendix A of Loop, Niessner and Eisenacher:\n"
                     " * (det yzw, -det xzw, det xyw, -det xyz) of the columns a, b, c. */\n");
        snprintf(name, sizeof name, "%seye_cross4", info->prefix);
        g->syntax->function(o, g, g->real, name, p, 4);
        for (c = 0; c < 4; c++) {
            put_det(det, g, rows[c][0], rows[c][1], rows[c][2]);
            x.name = names[c];
            x.init = det;
            g->syntax->locals(o, g, "    ", g->real, &x, 1, 1);
            snprintf(e, sizeof e, "e.%s", names[c]);
            kgpu_mul(m[c], sizeof m[c], g, e, names[c]);
        }
        sbuf_printf(o, "    return %s - %s + %s - %s;\n}\n\n", m[0], m[1], m[2], m[3]);
    }
}

/* With differences, diff(b, a): b - a from an exact local, each component rounded once and
 * crossed by no reassociation or contraction (the target's diff). */
static void put_diff(sbuf *o, const out_info *info, const kern_target *g)
{
    kern_param p[2] = {{g->vec4, "b"}, {g->vec4, "a"}};
    char name[128], e[320];
    snprintf(name, sizeof name, "%sdiff", info->prefix);
    snprintf(e, sizeof e, g->diff, "b", "a", "b", "a", "b", "a", "b", "a");
    sbuf_puts(o, "/* b - a, each component rounded once, as written (the terms' differences of points). */\n");
    g->syntax->function(o, g, g->vec4, name, p, 2);
    g->syntax->locals(o, g, "    ", g->vec4, &(kern_var){"d", e, 0}, 1, 1);
    sbuf_puts(o, "    return d;\n}\n\n");
}

/* With exact zeros, finite(a): every coordinate of a the kernel reads is finite; and same(a, b):
 * a and b are bitwise equal in those coordinates. Bits, not ==, so that no float mode bends the
 * test: a flushed subnormal never equals 0 (-0 is not +0 either, which only gives up a cull). */
static void put_edge_functions(sbuf *o, const out_info *info, const kern_target *g)
{
    kern_param p[2] = {{g->vec4, "a"}, {g->vec4, "b"}};
    char name[128], x[64], y[64], v[8];
    int c, f, n;
    for (f = 0; f < 2; f++) {
        snprintf(name, sizeof name, "%s%s", info->prefix, f ? "same" : "finite");
        g->syntax->function(o, g, "bool", name, p, f + 1);
        sbuf_puts(o, "    return ");
        for (c = 0, n = 0; c < 4; c++) {
            if (info->space == OUT_CLIP && c == 2)
                continue; /* clip space reads no z */
            snprintf(v, sizeof v, "a.%c", "xyzw"[c]);
            snprintf(x, sizeof x, g->bits, v);
            v[0] = 'b';
            snprintf(y, sizeof y, g->bits, v);
            if (f)
                sbuf_printf(o, "%s(%s == %s)", n++ ? " &&\n        " : "", x, y);
            else
                sbuf_printf(o, "%s((%s & 0x7f800000u) != 0x7f800000u)", n++ ? " &&\n        " : "", x);
        }
        sbuf_puts(o, ";\n}\n\n");
    }
}

/* The flags of one value and the class of a patch's flags, per rule: flags sets bit b where
 * bits[b][0] holds; class_of is the class of the first condition that holds, as selects. */
static void put_classify(sbuf *o, const out_info *info, const kern_target *g)
{
    static const char *const doc[3][2] = {
        {"Bit 0: d is not < 0; bit 1: d is not > 0 (NaN sets both).",
         "Strict rule: back iff every value < 0, front iff every value > 0."},
        {"Bit 0: d > 0; bit 1: d < 0; bit 2: d is NaN.",
         "Degenerate rule: back iff no value > 0, front iff no value < 0, NaN: silhouette."},
        {"Bit 0: d is not certainly < 0 (d >= -bound); bit 1: not certainly > 0 (NaN sets both).",
         "Certified: back iff every value is certainly < 0, front iff every value is certainly > 0."}};
    static const char *const cond[3] = {"(f & 4u) != 0u", "(f & 1u) == 0u", "(f & 2u) == 0u"};
    static const ptp_class cls[3] = {PTP_SILHOUETTE, PTP_BACK, PTP_FRONT};
    int m = info->certified ? 2 : info->rule == OUT_STRICT ? 0 : 1, i, k = 0;
    char nan[64], name[128], e[2][256], c[16];
    const char *bits[3][3][3] = {{{"d < 0.0f", "0u", "1u"}, {"d > 0.0f", "0u", "2u"}, {NULL}},
                                 {{"d > 0.0f", "1u", "0u"}, {"d < 0.0f", "2u", "0u"}, {nan, "4u", "0u"}},
                                 {{"d < -bound", "0u", "1u"}, {"d > bound", "0u", "2u"}, {NULL}}};
    kern_param p[2] = {{g->real, "d"}, {g->real, "bound"}}, pf = {g->uint, "f"};
    snprintf(nan, sizeof nan, g->syntax->isnan, "d");
    snprintf(name, sizeof name, "%sflags", info->prefix);
    sbuf_printf(o, "/* %s */\n", doc[m][0]);
    g->syntax->function(o, g, g->uint, name, p, m == 2 ? 2 : 1);
    sbuf_puts(o, "    return ");
    for (i = 0; i < 3 && bits[m][i][0]; i++) {
        g->syntax->select(e[0], sizeof e[0], bits[m][i][0], bits[m][i][1], bits[m][i][2]);
        sbuf_printf(o, "%s(%s)", i == 0 ? "" : " | ", e[0]);
    }
    snprintf(e[0], sizeof e[0], "%uu", (unsigned)PTP_SILHOUETTE); /* when no condition holds */
    for (i = 2; i >= (m == 1 ? 0 : 1); i--, k = !k) { /* NaN first, under the degenerate rule */
        snprintf(c, sizeof c, "%uu", (unsigned)cls[i]);
        g->syntax->select(e[!k], sizeof e[0], cond[i], c, e[k]);
    }
    snprintf(name, sizeof name, "%sclass_of", info->prefix);
    sbuf_printf(o, ";\n}\n\n/* %s */\n", doc[m][1]);
    g->syntax->function(o, g, g->uint, name, &pf, 1);
    sbuf_printf(o, "    return %s;\n}\n\n", e[k]);
}

void kgpu_look_functions(sbuf *o, const out_info *info, const kern_target *g)
{
    if (kgpu_exact_zeros(info))
        put_edge_functions(o, info, g);
    kgpu_df_functions(o, info, g);
    put_classify(o, info, g);
}

void kgpu_functions(sbuf *o, const out_info *info, const kern_target *g)
{
    put_cross4(o, info, g);
    if (kgpu_table_local(info, g) && info->certified && g->slp_cert_shift)
        sbuf_printf(o, g->slp_cert_shift, info->prefix);
    if (kgpu_differences(info, g))
        put_diff(o, info, g);
    if (kgpu_exact_zeros(info))
        put_edge_functions(o, info, g);
    if (kgpu_second_look(info, g))
        kgpu_df_functions(o, info, g);
    put_classify(o, info, g);
}
