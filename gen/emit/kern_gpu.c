/* kern_gpu.c: the one GPU kernel emitter, specialized by a target's data table.
 * Computes the banner, constant tables, helper functions and body, then fills the template. */
#include "plan/cert.h"
#include "emit/fmt.h"
#include "emit/kern.h"
#include "emit/template.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Appends a constant table: `qual type NAME[n] = { ... };`, `per_line` values to a line, in hex
 * (packed fields) or decimal. */
static void put_uint_table(sbuf *o, const kern_target *g, const char *prefix, const char *name,
                           const unsigned long *v, long n, int per_line, int hex)
{
    long i;
    sbuf_printf(o, "%s %s %s%s[%ld] = {", g->table_qual, g->uint, prefix, name, n);
    for (i = 0; i < n; i++)
        sbuf_printf(o, hex ? "%s0x%05lxu" : "%s%luu", i == 0 ? "\n    " : i % per_line ? ", " : ",\n    ",
                    v[i]);
    sbuf_puts(o, "\n};\n");
}

/* The constant tables: the owned planes of each thread (CSR), and per round the slots of the
 * P threads (packed indices and weights); padding slots name an owned plane with weight 0. */
/* Appends a constant float table NAME[n] = { ... } (values rounded to floats exactly, 9 digits). */
static void put_float_table(sbuf *o, const kern_target *g, const char *prefix, const char *name,
                            const float *v, int n)
{
    int i;
    sbuf_printf(o, "%s float %s%s[%d] = {", g->table_qual, prefix, name, n);
    for (i = 0; i < n; i++) {
        char lit[48];
        sprintf(lit, "%.9g", (double)v[i]);
        if (!strpbrk(lit, ".en"))
            strcat(lit, ".0");
        sbuf_printf(o, "%s%sf", i == 0 ? "\n    " : i % 6 ? ", " : ",\n    ", lit);
    }
    sbuf_puts(o, "\n};\n");
}

static int put_tables(sbuf *o, const tp_table *t, const out_info *info, const kern_target *g,
                      const char *up, ptp_error *err)
{
    const sched *s = info->sched;
    int P = s->threads, th, p, r, k = 0;
    int L = t->dom.nplanes;
    unsigned long *v = malloc((size_t)(2 * P > L ? 2 * P : L + P + 1) * sizeof *v);
    char lit[48];
    if (!v)
        return ptp_fail(err, PTP_ENOMEM, "out of memory writing tables");
    sbuf_printf(o, "#define %sP %du /* threads per patch */\n", up, P);
    sbuf_printf(o, "#define %sQ %du /* patches per workgroup */\n", up, s->patches);
    sbuf_printf(o, "#define %sK %du /* control points per patch */\n", up, t->dom.npoints);
    sbuf_printf(o, "#define %sL %du /* control planes per patch */\n", up, t->dom.nplanes);
    sbuf_printf(o, "/* %d rounds: the largest number of terms of one thread. */\n\n", s->rounds);
    for (th = 0; th <= P; th++) {
        v[th] = (unsigned long)k;
        for (p = 0; th < P && p < t->dom.nplanes; p++)
            k += s->owner[p] == th;
    }
    sbuf_puts(o, "/* Thread t owns the planes own_plane[own_start[t] .. own_start[t+1]-1]. */\n");
    put_uint_table(o, g, info->prefix, "own_start", v, P + 1, 16, 0);
    for (th = 0, k = 0; th < P; th++)
        for (p = 0; p < t->dom.nplanes; p++)
            if (s->owner[p] == th)
                v[k++] = (unsigned long)p;
    put_uint_table(o, g, info->prefix, "own_plane", v, t->dom.nplanes, 16, 0);
    sbuf_puts(o, "\n");
    for (r = 0; r < s->rounds; r++) {
        /* Round r: one small table per field, indexed by the thread. Unrolled, so that no
         * shader indexes a large constant array dynamically (lavapipe copies such an array
         * on every access; GPUs prefer small tables too). */
        char name[32];
        for (th = 0; th < P; th++) {
            long x = s->slot[(long)r * P + th];
            int plane = x >= 0 ? t->terms[x].plane : sched_padding_plane(s, th);
            v[th] = (unsigned long)plane | (unsigned long)(x >= 0 ? t->terms[x].j : 0) << 16;
            v[P + th] = x >= 0 ? (unsigned long)t->terms[x].k | (unsigned long)t->terms[x].l << 16 : 0;
        }
        sbuf_printf(o, "/* Round %d: thread t adds w%d[t] * term(plane | j << 16 = pj%d[t], k | l << 16 = kl%d[t]). */\n",
                    r, r, r, r);
        snprintf(name, sizeof name, "pj%d", r);
        put_uint_table(o, g, info->prefix, name, v, P, 8, 1);
        snprintf(name, sizeof name, "kl%d", r);
        put_uint_table(o, g, info->prefix, name, v + P, P, 8, 1);
        sbuf_printf(o, "%s float %sw%d[%d] = {", g->table_qual, info->prefix, r, P);
        for (th = 0; th < P; th++) {
            long x = s->slot[(long)r * P + th];
            rat zero;
            rat_set_si(&zero, 0);
            fmt_float_literal(lit, x >= 0 ? &t->terms[x].w : &zero);
            sbuf_printf(o, "%s%s", th == 0 ? "\n    " : th % 8 ? ", " : ",\n    ", lit);
        }
        sbuf_puts(o, "\n};\n\n");
    }
    free(v);
    if (info->certified) {
        cert_bounds cb;
        int st = cert_table(&cb, t, info->space == OUT_WORLD, err);
        if (st)
            return st;
        sbuf_printf(o, "/* Certified: |d_P - exact| <= tau_k[P] * E R^3 + tau_f[P] * (1 + R)^3 (1 + E), R the\n"
                       " * patch's largest |coordinate|, E the eye's; for max(E, 1) R^3 < %sQMAX. */\n"
                       "#define %sQMAX %.9gf\n",
                    up, up, (double)cb.q_max);
        put_float_table(o, g, info->prefix, "tau_k", cb.k, cb.nplanes);
        put_float_table(o, g, info->prefix, "tau_f", cb.k2, cb.nplanes);
        sbuf_puts(o, "\n");
        cert_clear(&cb);
    }
    return PTP_OK;
}

/* Appends det[a b c] of rows p, q, s (components "xyzw"[i]) with the target's products. */
static void put_det(sbuf *o, const kern_target *g, int p, int q, int s)
{
    static const char comp[] = "xyzw";
    const char *col = "abc";
    int i;
    for (i = 0; i < 3; i++) {
        /* cofactor expansion along row p: +a.p (b c), -b.p (a c), +c.p (a b) */
        char u = col[i == 0 ? 1 : 0], v = col[i == 2 ? 1 : 2], x[16], y[16], m1[48], m2[48], d[128];
        snprintf(x, sizeof x, "%c.%c", u, comp[q]);
        snprintf(y, sizeof y, "%c.%c", v, comp[s]);
        snprintf(m1, sizeof m1, g->mul, x, y);
        snprintf(x, sizeof x, "%c.%c", u, comp[s]);
        snprintf(y, sizeof y, "%c.%c", v, comp[q]);
        snprintf(m2, sizeof m2, g->mul, x, y);
        snprintf(d, sizeof d, "(%s - %s)", m1, m2);
        snprintf(x, sizeof x, "%c.%c", col[i], comp[p]);
        sbuf_puts(o, i == 0 ? "" : i == 1 ? " -\n        " : " +\n        ");
        sbuf_printf(o, g->mul, x, d);
    }
}

/* The helper functions: the term (cross4's z, or eye . cross4), the flags of one value and the
 * class of a patch's flags, per space and rule. The products are never contracted into FMAs, so
 * a term with two equal points (a collapsed edge) is exactly zero, as the degenerate rule needs. */
static void put_functions(sbuf *o, const out_info *info, const kern_target *g)
{
    const char *f = g->func_qual, *u = g->uint, *v = g->vec4, *px = info->prefix;
    if (info->space == OUT_CLIP) {
        sbuf_printf(o, "/* The z component of cross4(a, b, c): det of rows x, y, w. */\n"
                       "%sfloat %scross4z(%s a, %s b, %s c)\n{\n    %sfloat z = ",
                    f, px, v, v, v, g->precise);
        put_det(o, g, 0, 1, 3);
        sbuf_puts(o, ";\n    return z;\n}\n\n");
    } else {
        static const int rows[4][3] = {{1, 2, 3}, {0, 2, 3}, {0, 1, 3}, {0, 1, 2}};
        int c;
        sbuf_printf(o, "/* e . cross4(a, b, c), cross4 as in Appendix A of Loop, Niessner and Eisenacher:\n"
                       " * (det yzw, -det xzw, det xyw, -det xyz) of the columns a, b, c. */\n"
                       "%sfloat %seye_cross4(%s a, %s b, %s c, %s e)\n{\n", f, px, v, v, v, v);
        for (c = 0; c < 4; c++) {
            sbuf_printf(o, "    %sfloat %c = ", g->precise, "xyzw"[c]);
            put_det(o, g, rows[c][0], rows[c][1], rows[c][2]);
            sbuf_puts(o, ";\n");
        }
        sbuf_puts(o, "    return e.x * x - e.y * y + e.z * z - e.w * w;\n}\n\n");
    }
    if (info->certified)
        sbuf_printf(o,
                    "/* Bit 0: d is not certainly < 0 (d >= -bound); bit 1: not certainly > 0 (NaN sets both). */\n"
                    "%s%s %sflags(float d, float bound)\n{\n"
                    "    return (d < -bound ? 0u : 1u) | (d > bound ? 0u : 2u);\n}\n\n"
                    "/* Certified: back iff every value is certainly < 0, front iff every value is certainly > 0. */\n"
                    "%s%s %sclass_of(%s f)\n{\n"
                    "    return (f & 1u) == 0u ? 1u : (f & 2u) == 0u ? 0u : 2u;\n}\n\n",
                    f, u, px, f, u, px, u);
    else if (info->rule == OUT_STRICT)
        sbuf_printf(o,
                    "/* Bit 0: d is not < 0; bit 1: d is not > 0 (NaN sets both). */\n"
                    "%s%s %sflags(float d)\n{\n"
                    "    return (d < 0.0f ? 0u : 1u) | (d > 0.0f ? 0u : 2u);\n}\n\n"
                    "/* Strict rule: back iff every value < 0, front iff every value > 0. */\n"
                    "%s%s %sclass_of(%s f)\n{\n"
                    "    return (f & 1u) == 0u ? 1u : (f & 2u) == 0u ? 0u : 2u;\n}\n\n",
                    f, u, px, f, u, px, u);
    else
        sbuf_printf(o,
                    "/* Bit 0: d > 0; bit 1: d < 0; bit 2: d is NaN. */\n"
                    "%s%s %sflags(float d)\n{\n"
                    "    return (d > 0.0f ? 1u : 0u) | (d < 0.0f ? 2u : 0u) | (isnan(d) ? 4u : 0u);\n}\n\n"
                    "/* Degenerate rule: back iff no value > 0, front iff no value < 0, NaN: silhouette. */\n"
                    "%s%s %sclass_of(%s f)\n{\n"
                    "    return (f & 4u) != 0u ? 2u : (f & 1u) == 0u ? 1u : (f & 2u) == 0u ? 0u : 2u;\n}\n\n",
                    f, u, px, f, u, px, u);
}

/* The workgroup-shared arrays: the patches' points, the planes' accumulators, the flags. */
static void put_shared(sbuf *o, const kern_target *g, const char *up, const char *indent)
{
    sbuf_printf(o, "%s%s %s pts[%sQ * %sK];\n", indent, g->shared_qual, g->vec4, up, up);
    sbuf_printf(o, "%s%s float acc[%sQ * %sL];\n", indent, g->shared_qual, up, up);
    sbuf_printf(o, "%s%s %s flags[%sQ * %sP];\n", indent, g->shared_qual, g->uint, up, up);
}

/* The kernel body, in the syntax every GPU target shares, with the target's names. */
static void put_body(sbuf *o, const out_info *info, const kern_target *g, const char *up)
{
    const char *u = g->uint, *px = info->prefix;
    const char *fn = info->space == OUT_CLIP ? "cross4z" : "eye_cross4";
    int r;
    if (g->shared_in_body)
        put_shared(o, g, up, "    ");
    sbuf_printf(o,
                "    %s lid = %s, q = lid / %sP, t = lid %% %sP, i, pj, kl;\n"
                "    %s pid = (%s * %s + %s) * %sQ + q;\n"
                "    %s f = 0u;\n"
                "    bool live = pid < patch_count;\n\n",
                u, g->local_id, up, up, u, g->group_y, g->groups_x, g->group_x, up, u);
    sbuf_printf(o,
                "    /* The patch's control points into shared memory, P threads cooperating. */\n"
                "    for (i = t; i < %sK; i += %sP)\n"
                "        if (live)\n"
                "            pts[q * %sK + i] = cp[pid * %sK + i];\n"
                "    %s\n\n",
                up, up, up, up, g->barrier);
    sbuf_printf(o,
                "    /* Accumulate the planes this thread owns, one round at a time: no other thread\n"
                "     * touches them. */\n"
                "    for (i = %sown_start[t]; i < %sown_start[t + 1u]; i++)\n"
                "        acc[q * %sL + %sown_plane[i]] = 0.0f;\n",
                px, px, up, px);
    for (r = 0; r < info->sched->rounds; r++) {
        sbuf_printf(o, "    pj = %spj%d[t];\n    kl = %skl%d[t];\n"
                       "    acc[q * %sL + (pj & 0xffffu)] += %sw%d[t] *\n",
                    px, r, px, r, up, px, r);
        sbuf_printf(o, "        %s%s(pts[q * %sK + (pj >> 16)], pts[q * %sK + (kl & 0xffffu)],\n"
                       "        %*s pts[q * %sK + (kl >> 16)]%s);\n",
                    px, fn, up, up, (int)(strlen(px) + strlen(fn)), "", up,
                    info->space == OUT_CLIP ? "" : ", eye");
    }
    sbuf_puts(o, "\n");
    if (info->certified) {
        const char *ab = g->fabs, *mx = g->fmax;
        sbuf_printf(o, "    /* Certified: R, the patch's largest |coordinate|, and E, the eye's, bound the errors. */\n"
                       "    float R = 0.0f;\n"
                       "    for (i = 0u; i < %sK; i++) {\n"
                       "        %s a = pts[q * %sK + i];\n",
                    up, g->vec4, up);
        if (info->space == OUT_CLIP)
            sbuf_printf(o, "        R = %s(R, %s(%s(%s(a.x), %s(a.y)), %s(a.w)));\n    }\n", mx, mx, mx, ab,
                        ab, ab);
        else
            sbuf_printf(o, "        R = %s(R, %s(%s(%s(a.x), %s(a.y)), %s(%s(a.z), %s(a.w))));\n    }\n", mx,
                        mx, mx, ab, ab, mx, ab, ab);
        if (info->space == OUT_CLIP)
            sbuf_printf(o, "    float E = %s(eye.z);\n", ab);
        else
            sbuf_printf(o, "    float E = %s(%s(%s(eye.x), %s(eye.y)), %s(%s(eye.z), %s(eye.w)));\n", mx, mx,
                        ab, ab, mx, ab, ab);
        sbuf_printf(o, "    float R3 = R * R * R, ER3 = E * R3;\n"
                       "    float F = (1.0f + R) * (1.0f + R) * (1.0f + R) * (1.0f + E);\n"
                       "    if (!(%s(E, 1.0f) * R3 < %sQMAX))\n"
                       "        f = 3u; /* too large for the bound, or NaN: never certified */\n",
                    mx, up);
    }
    sbuf_printf(o,
                "    /* The values and signs of the owned planes; then one thread combines the patch's. */\n"
                "    for (i = %sown_start[t]; i < %sown_start[t + 1u]; i++) {\n"
                "        %s plane = %sown_plane[i];\n"
                "        float d = %sacc[q * %sL + plane];\n",
                px, px, u, px, info->space == OUT_CLIP ? "eye.z * " : "", up);
    if (info->planes)
        sbuf_printf(o, "        if (%slive)\n            planes[pid * %sL + plane] = d;\n",
                    g->planes_buffer ? "" : "planes && ", up);
    if (info->certified)
        sbuf_printf(o, "        f |= %sflags(d, %stau_k[plane] * ER3 + %stau_f[plane] * F);\n", px, px, px);
    else
        sbuf_printf(o, "        f |= %sflags(d);\n", px);
    sbuf_printf(o,
                "    }\n"
                "    flags[q * %sP + t] = f;\n"
                "    %s\n"
                "    if (live && t == 0u) {\n"
                "        for (i = 1u; i < %sP; i++)\n"
                "            f |= flags[q * %sP + i];\n"
                "        cls[pid] = %sclass_of(f);\n"
                "    }\n",
                up, g->barrier, up, up, px);
}

int kern_emit_gpu(sbuf *o, const tp_table *t, const out_info *info, const kern_target *g,
                  ptp_error *err)
{
    sbuf banner, tables, funcs, shared, body;
    char up[64], file[96], threads[16];
    tpl_slot slots[9];
    size_t n = 0;
    int st;
    fmt_upper(up, sizeof up, info->prefix);
    fmt_file_name(file, sizeof file, info->prefix, g->file_ext);
    snprintf(threads, sizeof threads, "%d", info->sched->threads * info->sched->patches);
    sbuf_init(&banner);
    sbuf_init(&tables);
    sbuf_init(&funcs);
    sbuf_init(&shared);
    sbuf_init(&body);
    fmt_banner(&banner, t, info, file, g->language, g->interface);
    st = put_tables(&tables, t, info, g, up, err);
    put_functions(&funcs, info, g);
    put_body(&body, info, g, up);
    slots[n++] = (tpl_slot){"BANNER", banner.s};
    if (g->named_kernel)
        slots[n++] = (tpl_slot){"PREFIX", info->prefix};
    slots[n++] = (tpl_slot){"BLOCK_THREADS", threads};
    slots[n++] = (tpl_slot){"TABLES", tables.s};
    slots[n++] = (tpl_slot){"FUNCTIONS", funcs.s};
    slots[n++] = (tpl_slot){"BODY", body.s};
    if (!g->shared_in_body) {
        put_shared(&shared, g, up, "");
        slots[n++] = (tpl_slot){"SHARED", shared.s};
    }
    if (g->planes_buffer)
        slots[n++] = (tpl_slot){"PLANES_BUFFER", info->planes ? g->planes_buffer : ""};
    if (banner.failed || tables.failed || funcs.failed || shared.failed || body.failed)
        st = st ? st : ptp_fail(err, PTP_ENOMEM, "out of memory writing the kernel");
    if (!st)
        st = tpl_fill(o, g->template_name, slots, n, err);
    sbuf_clear(&banner);
    sbuf_clear(&tables);
    sbuf_clear(&funcs);
    sbuf_clear(&shared);
    sbuf_clear(&body);
    return st;
}
