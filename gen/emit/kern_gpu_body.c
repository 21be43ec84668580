/* kern_gpu_body.c: the GPU kernel's body: the patch's points into shared memory, the rounds'
 * accumulation, the owned planes' signs and their combination into the patch's class. */
#include "emit/kern_gpu.h"

#include <stdio.h>
#include <string.h>

void kgpu_shared(sbuf *o, const out_info *info, const kern_target *g, const char *up,
                 const char *indent)
{
    char count[160];
    snprintf(count, sizeof count, "%sQ * %sK", up, up);
    g->syntax->shared(o, g, indent, g->vec4, "pts", count);
    if (kgpu_given(info, g))
        g->syntax->shared(o, g, indent, g->vec4, "given", count);
    snprintf(count, sizeof count, "%sQ * %sL", up, up);
    g->syntax->shared(o, g, indent, g->real, "acc", count);
    if (kgpu_second_look_rounds(info, g))
        g->syntax->shared(o, g, indent, g->real, "acc2", count);
    snprintf(count, sizeof count, "%sQ * %sP", up, up);
    g->syntax->shared(o, g, indent, g->uint, "flags", count);
}

/* The coordinates the shear moves: x and y, and in world space z. */
static int sheared_coords(const out_info *info)
{
    return info->space == OUT_WORLD ? 3 : 2;
}

/* Lines at indent moving the vec4 v by the shift: v.c = oc w.w + w.c (kgpu_shear) for the sheared
 * coordinates c, w being v's value before (its own name, or the one v was copied from). */
static void put_sheared(sbuf *o, const out_info *info, const kern_target *g, const char *indent,
                        const char *v, const char *w)
{
    static const char *const c[3] = {"x", "y", "z"};
    char oc[8], wc[72], ww[72], e[224], shear[96];
    int k;
    kgpu_shear(shear, sizeof shear, info, g);
    snprintf(ww, sizeof ww, "%s.w", w);
    for (k = 0; k < sheared_coords(info); k++) {
        snprintf(oc, sizeof oc, "o%s", c[k]);
        snprintf(wc, sizeof wc, "%s.%s", w, c[k]);
        snprintf(e, sizeof e, shear, oc, ww, wc);
        sbuf_printf(o, "%s%s.%s = %s;\n", indent, v, c[k], e);
    }
}

/* Patch-local coordinates (kgpu_table_local): into the mutable locals ox, oy (world: oz) the
 * patch's shift o = -b0.xyz / b0.w (0 where b0.w = 0, or for a thread past the last patch), and in world
 * space the eye moved the same way into l. */
static void put_shift(sbuf *o, const out_info *info, const kern_target *g, const char *up)
{
    static const char *const c[3] = {"x", "y", "z"};
    kern_var v[3] = {{"ox", "0.0f", 1}, {"oy", "0.0f", 1}, {"oz", "0.0f", 1}};
    char e[160], rw[128], b0c[8], m[64];
    int k;
    g->syntax->locals(o, g, "    ", g->real, v, sheared_coords(info), 0);
    sbuf_puts(o, "    if (live) {\n");
    snprintf(e, sizeof e, "cp[pid * %sK]", up);
    g->syntax->locals(o, g, "        ", g->vec4, &(kern_var){"b0", e, 0}, 1, 0);
    g->syntax->select(rw, sizeof rw, "b0.w != 0.0f", "1.0f / b0.w", "0.0f");
    g->syntax->locals(o, g, "        ", g->real, &(kern_var){"rw", rw, 0}, 1, 0);
    for (k = 0; k < sheared_coords(info); k++) {
        snprintf(b0c, sizeof b0c, "b0.%s", c[k]);
        kgpu_mul(m, sizeof m, g, b0c, "rw");
        sbuf_printf(o, "        o%s = -%s;\n", c[k], m);
    }
    sbuf_puts(o, "    }\n");
    if (info->space != OUT_WORLD)
        return;
    g->syntax->locals(o, g, "    ", g->vec4, &(kern_var){"l", "eye", 1}, 1, 0);
    put_sheared(o, info, g, "    ", "l", "eye");
}

/* The body's start: the thread's place (lid, q, t), its patch (pid, live), the loop variables
 * and the flags f; then the patch's control points into shared memory, in patch-local
 * coordinates where kgpu_table_local (put_shift). */
static void put_load(sbuf *o, const out_info *info, const kern_target *g, const char *up)
{
    char q[96], t[96], pid[256], e[160];
    kern_var v[6] = {{"lid", g->local_id, 0}, {"q", q, 0}, {"t", t, 0},
                     {"i", NULL, 1}, {"pj", NULL, 1}, {"kl", NULL, 1}};
    int local = kgpu_table_local(info, g);
    snprintf(q, sizeof q, "lid / %sP", up);
    snprintf(t, sizeof t, "lid %% %sP", up);
    snprintf(pid, sizeof pid, "(%s * %s + %s) * %sQ + q", g->group_y, g->groups_x, g->group_x, up);
    g->syntax->locals(o, g, "    ", g->uint, v, 6, 0);
    kgpu_local(o, g, g->uint, "pid", pid, 0);
    kgpu_local(o, g, g->uint, "f", "0u", 1);
    kgpu_local(o, g, "bool", "live", "pid < patch_count", 0);
    if (local)
        put_shift(o, info, g, up);
    sbuf_printf(o, "\n    /* The patch's control points into shared memory, P threads cooperating%s%s. */\n"
                   "    for (i = t; i < %sK; i += %sP)",
                local ? ", in\n     * patch-local coordinates (x + o w)" : "",
                kgpu_given(info, g) ? " and as given" : "", up, up);
    kgpu_then(o, g);
    if (!local) {
        sbuf_puts(o, "        if (live)");
        kgpu_then(o, g);
        sbuf_printf(o, "            pts[q * %sK + i] = cp[pid * %sK + i];\n", up, up);
        kgpu_end(o, g, "        ");
    } else {
        sbuf_puts(o, "        if (live) {\n");
        snprintf(e, sizeof e, "cp[pid * %sK + i]", up);
        g->syntax->locals(o, g, "            ", g->vec4, &(kern_var){"p", e, 1}, 1, 0);
        if (kgpu_given(info, g))
            sbuf_printf(o, "            given[q * %sK + i] = p;\n", up);
        put_sheared(o, info, g, "            ", "p", "p");
        sbuf_printf(o, "            pts[q * %sK + i] = p;\n        }\n", up);
    }
    kgpu_end(o, g, "    ");
    sbuf_printf(o, "    %s\n\n", g->barrier);
}

/* The accumulation of the planes this thread owns, one round at a time; with differences, term
 * (j, k, l) reads b_j, b_k - b_j, b_l - b_j (the same determinant). */
static void put_accumulate(sbuf *o, const out_info *info, const kern_target *g, const char *up)
{
    const char *px = info->prefix, *fn = info->space == OUT_CLIP ? "cross4z" : "eye_cross4";
    const char *eye = info->space == OUT_CLIP ? "" : kgpu_table_local(info, g) ? ", l" : ", eye";
    char a[128], b[320], c[320], w[96], term[1024], e[1152]; /* up has at most 63 bytes */
    int r, n = (int)(strlen(px) + strlen(fn));
    sbuf_printf(o,
                "    /* Accumulate the planes this thread owns, one round at a time: no other thread\n"
                "     * touches them. */\n"
                "    for (i = %sown_start[t]; i < %sown_start[t + 1u]; i++)",
                px, px);
    kgpu_then(o, g);
    sbuf_printf(o, "        acc[q * %sL + %sown_plane[i]] = 0.0f;\n", up, px);
    kgpu_end(o, g, "    ");
    snprintf(a, sizeof a, "pts[q * %sK + (pj >> 16)]", up);
    if (kgpu_differences(info, g)) { /* b_k - b_j and b_l - b_j */
        snprintf(b, sizeof b, "%sdiff(pts[q * %sK + (kl & 0xffffu)], %s)", px, up, a);
        snprintf(c, sizeof c, "%sdiff(pts[q * %sK + (kl >> 16)], %s)", px, up, a);
    } else {
        snprintf(b, sizeof b, "pts[q * %sK + (kl & 0xffffu)]", up);
        snprintf(c, sizeof c, "pts[q * %sK + (kl >> 16)]", up);
    }
    if (kgpu_differences(info, g)) /* one argument a line: the differences are long */
        snprintf(term, sizeof term, "%s%s(%s,\n        %*s %s,\n        %*s %s%s)", px, fn, a, n,
                 "", b, n, "", c, eye);
    else
        snprintf(term, sizeof term, "%s%s(%s, %s,\n        %*s %s%s)", px, fn, a, b, n, "", c,
                 eye);
    for (r = 0; r < info->sched->rounds; r++) {
        snprintf(w, sizeof w, "%sw%d[t]", px, r);
        kgpu_product(e, sizeof e, g, "\n        ", 2, (const char *const[]){w, term});
        sbuf_printf(o, "    pj = %spj%d[t];\n    kl = %skl%d[t];\n"
                       "    acc[q * %sL + (pj & 0xffffu)] += %s;\n",
                    px, r, px, r, up, e);
    }
    sbuf_puts(o, "\n");
}

/* The values and flags of the owned planes (and with --planes, the values written out). */
static void put_signs(sbuf *o, const out_info *info, const kern_target *g, const char *up)
{
    const char *px = info->prefix;
    char e[256], d[320];
    sbuf_printf(o,
                "    /* The values and signs of the owned planes; then one thread combines the patch's. */\n"
                "    for (i = %sown_start[t]; i < %sown_start[t + 1u]; i++) {\n",
                px, px);
    snprintf(e, sizeof e, "%sown_plane[i]", px);
    g->syntax->locals(o, g, "        ", g->uint, &(kern_var){"plane", e, 0}, 1, 0);
    snprintf(e, sizeof e, "acc[q * %sL + plane]", up);
    if (info->space == OUT_CLIP)
        kgpu_mul(d, sizeof d, g, "eye.z", e);
    g->syntax->locals(o, g, "        ", g->real, &(kern_var){"d", info->space == OUT_CLIP ? d : e, 0}, 1, 0);
    if (info->planes) {
        sbuf_printf(o, "        if (%slive)", g->planes_buffer ? "" : "planes && ");
        kgpu_then(o, g);
        sbuf_printf(o, "            planes[pid * %sL + plane] = d;\n", up);
        kgpu_end(o, g, "        ");
    }
    if (info->certified)
        kgpu_cert_flags(o, info, g);
    else
        sbuf_printf(o, "        f |= %sflags(d);\n", px);
    sbuf_puts(o, "    }\n");
}

/* The end: the threads' flags through shared memory, and thread 0 of a patch writes its class. */
static void put_combine(sbuf *o, const out_info *info, const kern_target *g, const char *up)
{
    sbuf_printf(o,
                "    flags[q * %sP + t] = f;\n"
                "    %s\n"
                "    if (live && t == 0u) {\n"
                "        for (i = 1u; i < %sP; i++)",
                up, g->barrier, up);
    kgpu_then(o, g);
    sbuf_printf(o, "            f |= flags[q * %sP + i];\n", up);
    kgpu_end(o, g, "        ");
    sbuf_printf(o, "        cls[pid] = %sclass_of(f);\n"
                   "    }\n",
                info->prefix);
}

void kgpu_body(sbuf *o, const tp_domain *d, const out_info *info, const kern_target *g,
               const char *up)
{
    if (g->shared_in_body)
        kgpu_shared(o, info, g, up, "    ");
    put_load(o, info, g, up);
    put_accumulate(o, info, g, up);
    if (info->certified)
        kgpu_cert_scale(o, d, info, g, up);
    put_signs(o, info, g, up);
    if (kgpu_second_look(info, g))
        kgpu_df_look(o, info, g, up);
    put_combine(o, info, g, up);
}
