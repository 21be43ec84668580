/* kern_gpu_look.c: --certified's second look in the GPU kernel: its tables (the terms again, the
 * weights' low parts) and the body that evaluates the undecided planes again in double-float. */
#include "emit/kern_gpu.h"
#include "emit/fmt.h"

#include <stdio.h>
#include <stdlib.h>

/* Into hi the float of w's literal, into lo the float nearest w - hi: hi + lo is w within
 * 2^-47 |w|. */
static void weight_split(float *hi, float *lo, const rat *w)
{
    char lit[48];
    *hi = strtof(fmt_float_literal(lit, w), NULL);
    *lo = (float)(rat_get_d(w) - (double)*hi);
}

/* The second look's term tables for the planes plane[0..L-1] in that order (v as
 * kgpu_df_terms'), after a comment that names plane n's as whose. */
static int put_df_terms(sbuf *o, const tp_table *t, const out_info *info, const kern_target *g,
                        const long *plane, const char *whose, unsigned long *v, ptp_error *err)
{
    long L = t->dom.nplanes, n;
    size_t x, k = 0;
    float *w = malloc(2 * (t->nterms + 1) * sizeof *w);
    if (!w)
        return ptp_fail(err, PTP_ENOMEM, "out of memory writing tables");
    for (n = 0; n < L; n++) {
        v[n] = (unsigned long)k;
        for (x = 0; x < t->nterms; x++) {
            const tp_term *a = &t->terms[x];
            if (a->plane != plane[n])
                continue;
            v[L + 1 + k] = (unsigned long)a->j;
            v[L + 1 + t->nterms + k] = (unsigned long)a->k | (unsigned long)a->l << 16;
            weight_split(&w[k], &w[t->nterms + k], &a->w);
            k++;
        }
    }
    v[L] = (unsigned long)k;
    sbuf_printf(o, "/* Second look: the terms of %s are dw[i] * term(dj[i], dkl[i] = k | l << 16)\n"
                   " * (weight dw + dwl in double-float) for i in dstart[n] .. dstart[n+1]-1. */\n", whose);
    kgpu_uint_table(o, g, info->prefix, "dstart", v, L + 1, 16, 0);
    kgpu_uint_table(o, g, info->prefix, "dj", v + L + 1, (long)k, 16, 0);
    kgpu_uint_table(o, g, info->prefix, "dkl", v + L + 1 + t->nterms, (long)k, 8, 1);
    kgpu_float_table(o, g, info->prefix, "dw", w, (int)k);
    kgpu_float_table(o, g, info->prefix, "dwl", w + t->nterms, (int)k);
    sbuf_puts(o, "\n");
    free(w);
    return PTP_OK;
}

int kgpu_df_terms(sbuf *o, const tp_table *t, const out_info *info, const kern_target *g,
                  unsigned long *v, ptp_error *err)
{
    const sched *s = info->sched;
    long L = t->dom.nplanes, n, th, p, mine;
    long *order = malloc((size_t)L * sizeof *order);
    int st;
    if (!order)
        return ptp_fail(err, PTP_ENOMEM, "out of memory writing tables");
    for (th = 0, n = 0; th < s->threads; th++) {
        for (p = 0, mine = 0; p < L; p++)
            if (s->owner[p] == th) {
                order[n++] = p;
                mine++;
            }
        if (mine > 32) { /* the planes a thread chose are bits of one uint */
            free(order);
            return ptp_fail(err, PTP_ELIMIT, "--certified: thread %ld owns %ld planes, more than 32", th, mine);
        }
    }
    st = put_df_terms(o, t, info, g, order, "own_plane[n]", v, err);
    free(order);
    return st;
}

int kgpu_df_plane_terms(sbuf *o, const tp_table *t, const out_info *info, const kern_target *g,
                        ptp_error *err)
{
    long L = t->dom.nplanes, p;
    unsigned long *v = malloc(((size_t)L + 1 + 2 * t->nterms) * sizeof *v);
    long *order = malloc((size_t)L * sizeof *order);
    int st;
    if (!v || !order)
        st = ptp_fail(err, PTP_ENOMEM, "out of memory writing tables");
    else {
        for (p = 0; p < L; p++)
            order[p] = p;
        st = put_df_terms(o, t, info, g, order, "plane n", v, err);
    }
    free(v);
    free(order);
    return st;
}

void kgpu_df_weight_lo(sbuf *o, const tp_table *t, const out_info *info, const kern_target *g,
                       int r)
{
    const sched *s = info->sched;
    float lo[SCHED_MAX_THREADS], hi;
    char name[32];
    int th;
    for (th = 0; th < s->threads; th++) {
        long x = s->slot[(long)r * s->threads + th];
        lo[th] = 0.0f;
        if (x >= 0)
            weight_split(&hi, &lo[th], &t->terms[x].w);
    }
    snprintf(name, sizeof name, "wl%d", r);
    kgpu_float_table(o, g, info->prefix, name, lo, s->threads);
}

/* The second look's decision: every thread of a patch combines the first look's certified flags
 * and plain flags (pf, shifted by 2) into all; again: the plain signs decide, the bounds do not. */
static void put_again(sbuf *o, const kern_target *g, const char *up)
{
    sbuf_printf(o,
                "\n    /* Second look: in a patch whose plain float signs decide but whose bounds do not,\n"
                "     * the planes whose bounds do not clear are evaluated again in double-float, against\n"
                "     * their own bound. */\n"
                "    flags[q * %sP + t] = f | (pf << 2u);\n"
                "    %s\n",
                up, g->barrier);
    kgpu_local(o, g, g->uint, "all", "0u", 1);
    sbuf_printf(o, "    for (i = 0u; i < %sP; i++)", up);
    kgpu_then(o, g);
    sbuf_printf(o, "        all |= flags[q * %sP + i];\n", up);
    kgpu_end(o, g, "    ");
    kgpu_local(o, g, "bool", "again", "live && ((all & 5u) == 1u || (all & 10u) == 2u)", 0);
    sbuf_printf(o, "    %s\n", g->barrier);
}

/* Writes to out (size bytes) the point the second look reads at index idx (an expression): as
 * given (kgpu_given), else from pts. Returns out. */
static char *look_point(char *out, size_t size, const out_info *info, const kern_target *g,
                        const char *up, const char *idx)
{
    snprintf(out, size, "%s[q * %sK + %s]", kgpu_given(info, g) ? "given" : "pts", up, idx);
    return out;
}

/* The second look from the rounds: put_accumulate's rounds in double-float into acc and acc2;
 * with split_rounds each round under a test of its weight (padding slots' is 0). */
static void put_df_accumulate(sbuf *o, const out_info *info, const kern_target *g, const char *up)
{
    const char *px = info->prefix, *fn = info->space == OUT_CLIP ? "cross4z" : "eye_cross4";
    char hi[96], lo[96], w[96], wl[96], x[256], y[256], pt[3][128];
    int r;
    look_point(pt[0], sizeof pt[0], info, g, up, "(pj >> 16)");
    look_point(pt[1], sizeof pt[1], info, g, up, "(kl & 0xffffu)");
    look_point(pt[2], sizeof pt[2], info, g, up, "(kl >> 16)");
    g->syntax->locals(o, g, "        ", g->uint, &(kern_var){"at", NULL, 1}, 1, 0);
    sbuf_printf(o, "        for (i = %sown_start[t]; i < %sown_start[t + 1u]; i++) {\n"
                   "            acc[q * %sL + %sown_plane[i]] = 0.0f;\n"
                   "            acc2[q * %sL + %sown_plane[i]] = 0.0f;\n        }\n",
                px, px, up, px, up, px);
    snprintf(x, sizeof x, g->vec2_make, "acc[at]", "acc2[at]");
    for (r = 0; r < info->sched->rounds; r++) {
        const char *in = g->split_rounds ? "            " : "        ";
        snprintf(hi, sizeof hi, "%sw%d[t]", px, r);
        snprintf(lo, sizeof lo, "%swl%d[t]", px, r);
        snprintf(y, sizeof y, g->vec2_make, hi, lo);
        snprintf(w, sizeof w, "%spj%d[t]", px, r);
        snprintf(wl, sizeof wl, "%skl%d[t]", px, r);
        if (g->split_rounds)
            sbuf_printf(o, "        if (%s != 0.0f) {\n", hi);
        sbuf_printf(o, "%spj = %s;\n%skl = %s;\n%sat = q * %sL + (pj & 0xffffu);\n"
                       "%ss = %sdf_add(%s, %sdf_mul(%s, %sdf_%s(%s,\n"
                       "%s    %s, %s%s)));\n"
                       "%sacc[at] = s.x;\n%sacc2[at] = s.y;\n",
                    in, w, in, wl, in, up, in, px, x, px, y, px, fn, pt[0], in, pt[1], pt[2],
                    info->space == OUT_CLIP ? "" : ", eye", in, in);
        if (g->split_rounds)
            sbuf_puts(o, "        }\n");
    }
}

void kgpu_df_term_sum(sbuf *o, const out_info *info, const kern_target *g, const char *in,
                      const char *start, const char *end, const char *const pt[3])
{
    const char *px = info->prefix, *fn = info->space == OUT_CLIP ? "cross4z" : "eye_cross4";
    char w[128];
    snprintf(w, sizeof w, g->vec2_make, "$dw[j]", "$dwl[j]");
    sbuf_printf(o, "%sfor (j = %s; j < %s; j++)", in, start, end);
    kgpu_then(o, g);
    sbuf_printf(o, "%s    s = %sdf_add(s, %sdf_mul(", in, px, px);
    kgpu_df_text(o, info, g, w);
    sbuf_printf(o, ", %sdf_%s(%s,\n%s        %s, %s%s)));\n", px, fn, pt[0], in, pt[1], pt[2],
                info->space == OUT_CLIP ? "" : ", eye");
    kgpu_end(o, g, in);
}

/* The second look's sum for own_plane[i] into s, in double-float: its terms when mine (its bit in
 * redo) is set, else none. */
static void put_df_sum(sbuf *o, const out_info *info, const kern_target *g, const char *up)
{
    const char *px = info->prefix;
    char start[96], end[96], init[256], zero[96], pt[3][320], idx[3][96];
    const char *pp[3] = {pt[0], pt[1], pt[2]};
    int k;
    snprintf(start, sizeof start, "%sdstart[i]", px);
    snprintf(end, sizeof end, "%sdstart[i + 1u]", px);
    g->syntax->select(init, sizeof init, "mine != 0u", start, end);
    snprintf(zero, sizeof zero, g->vec2_make, "0.0f", "0.0f");
    snprintf(idx[0], sizeof idx[0], "%sdj[j]", px);
    snprintf(idx[1], sizeof idx[1], "(%sdkl[j] & 0xffffu)", px);
    snprintf(idx[2], sizeof idx[2], "(%sdkl[j] >> 16)", px);
    for (k = 0; k < 3; k++)
        look_point(pt[k], sizeof pt[k], info, g, up, idx[k]);
    sbuf_printf(o, "            s = %s;\n", zero);
    kgpu_df_term_sum(o, info, g, "            ", init, end, pp);
}

char *kgpu_df_flags(char *out, size_t size, const out_info *info, const kern_target *g,
                    const char *plane)
{
    char a[96], f[8], m[3][128];
    snprintf(a, sizeof a, "%stau2_k[%s]", info->prefix, plane);
    kgpu_mul(m[0], sizeof m[0], g, a, "M2");
    snprintf(a, sizeof a, "%stau2_f[%s]", info->prefix, plane);
    snprintf(f, sizeof f, "F%s", kgpu_look_names(info, g));
    kgpu_mul(m[1], sizeof m[1], g, a, f);
    snprintf(a, sizeof a, "%s(d.y)", g->fabs);
    kgpu_mul(m[2], sizeof m[2], g, "2.0f", a);
    snprintf(out, size, "%sflags(d.x, %s + %s +\n                %s)", info->prefix, m[0], m[1], m[2]);
    return out;
}

void kgpu_df_look(sbuf *o, const out_info *info, const kern_target *g, const char *up)
{
    const char *px = info->prefix;
    char a[160], b[160], fl[512];
    kern_var j = {"j", NULL, 1}, s = {"s", NULL, 1};
    put_again(o, g, up);
    sbuf_puts(o, "    if (again) {\n");
    if (kgpu_given(info, g))
        kgpu_look_magnitudes(o, info, g, up);
    g->syntax->locals(o, g, "        ", g->vec2, &s, 1, 0);
    if (g->df_table)
        g->syntax->locals(o, g, "        ", g->uint, &j, 1, 0);
    else
        put_df_accumulate(o, info, g, up);
    sbuf_puts(o, "        f = fd;\n");
    kgpu_too_large(o, g, "        ", up, "QMAX2", kgpu_look_names(info, g));
    kgpu_then(o, g);
    sbuf_puts(o, "            f = 3u;\n");
    kgpu_end(o, g, "        ");
    sbuf_printf(o, "        for (i = %sown_start[t]; i < %sown_start[t + 1u]; i++) {\n", px, px);
    snprintf(a, sizeof a, "%sown_plane[i]", px);
    g->syntax->locals(o, g, "            ", g->uint, &(kern_var){"plane", a, 0}, 1, 0);
    snprintf(b, sizeof b, "(redo >> (i - %sown_start[t])) & 1u", px);
    g->syntax->locals(o, g, "            ", g->uint, &(kern_var){"mine", b, 0}, 1, 0);
    if (kgpu_exact_zeros(info))
        kgpu_keep(o, info, g, "            ", "plane");
    if (g->df_table) {
        put_df_sum(o, info, g, up);
    } else {
        snprintf(a, sizeof a, g->vec2_make, "acc[q * %sL + plane]", "acc2[q * %sL + plane]");
        sbuf_printf(o, "            s = ");
        sbuf_printf(o, a, up, up);
        sbuf_puts(o, ";\n");
    }
    snprintf(b, sizeof b, "%sdf_mul_f(s, eye.z)", px);
    g->syntax->locals(o, g, "            ", g->vec2,
                      &(kern_var){"d", info->space == OUT_CLIP ? b : "s", 0}, 1, 0);
    sbuf_printf(o, "            f |= %s & mine * %s;\n        }\n    }\n",
                kgpu_df_flags(fl, sizeof fl, info, g, "plane"), kgpu_exact_zeros(info) ? "keep" : "3u");
}
