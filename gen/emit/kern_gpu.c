/* kern_gpu.c: the one GPU kernel emitter, specialized by a target's data table and syntax hooks.
 * Computes the banner, constant tables, helper functions and body, then fills the template. */
#include "plan/cert.h"
#include "emit/fmt.h"
#include "emit/kern.h"
#include "emit/template.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* s, or "" for NULL (a string field left out of a table). */
static const char *opt(const char *s)
{
    return s ? s : "";
}

/* The C family's hooks: the contracts are kern_syntax's (kern.h). */
static void c_constant(sbuf *o, const kern_target *g, const char *name, const char *type,
                       const char *value, const char *comment)
{
    (void)g, (void)type;
    if (comment)
        sbuf_printf(o, "#define %s %s /* %s */\n", name, value, comment);
    else
        sbuf_printf(o, "#define %s %s\n", name, value);
}

static void c_table_open(sbuf *o, const kern_target *g, const char *type, const char *name, long n)
{
    sbuf_printf(o, "%s %s %s[%ld] = {", g->table_qual, type, name, n);
}

static void c_shared(sbuf *o, const kern_target *g, const char *indent, const char *type,
                     const char *name, const char *count)
{
    sbuf_printf(o, "%s%s %s %s[%s];\n", indent, g->shared_qual, type, name, count);
}

static void c_function(sbuf *o, const kern_target *g, const char *ret, const char *name,
                       const kern_param *p, int n)
{
    int i;
    sbuf_printf(o, "%s%s %s(", opt(g->func_qual), ret, name);
    for (i = 0; i < n; i++)
        sbuf_printf(o, "%s%s %s", i == 0 ? "" : ", ", p[i].type, p[i].name);
    sbuf_puts(o, ")\n{\n");
}

static void c_locals(sbuf *o, const kern_target *g, const char *indent, const char *type,
                     const kern_var *v, int n, int exact)
{
    int i;
    sbuf_printf(o, "%s%s%s ", indent, exact ? opt(g->precise) : "", type);
    for (i = 0; i < n; i++)
        sbuf_printf(o, "%s%s%s%s", i == 0 ? "" : ", ", v[i].name, v[i].init ? " = " : "",
                    opt(v[i].init));
    sbuf_puts(o, ";\n");
}

static void c_select(char *out, size_t size, const char *cond, const char *t, const char *f)
{
    snprintf(out, size, "%s ? %s : %s", cond, t, f);
}

const kern_syntax kern_c_syntax = {
    .constant = c_constant,
    .table_open = c_table_open,
    .table_close = "\n};\n",
    .shared = c_shared,
    .function = c_function,
    .locals = c_locals,
    .select = c_select,
    .isnan = "isnan(%s)",
    .braces = 0,
};

/* Ends the head of a for or an if whose body, one statement, follows on the next line. */
static void put_then(sbuf *o, const kern_target *g)
{
    sbuf_puts(o, g->syntax->braces ? " {\n" : "\n");
}

/* Closes the body put_then opened, at the head's indent. */
static void put_end(sbuf *o, const kern_target *g, const char *indent)
{
    if (g->syntax->braces)
        sbuf_printf(o, "%s}\n", indent);
}

/* Declares one local variable (see kern_syntax.locals). */
static void put_local(sbuf *o, const kern_target *g, const char *type, const char *name,
                      const char *init, int assigned)
{
    kern_var v = {name, init, assigned};
    g->syntax->locals(o, g, "    ", type, &v, 1, 0);
}

/* The separator before value i of a table with per_line values to a line. */
static const char *table_sep(long i, int per_line)
{
    return i == 0 ? "\n    " : i % per_line ? ", " : ",\n    ";
}

/* Appends a constant table prefix+name of n uints, `per_line` values to a line, in hex (packed
 * fields) or decimal. */
static void put_uint_table(sbuf *o, const kern_target *g, const char *prefix, const char *name,
                           const unsigned long *v, long n, int per_line, int hex)
{
    char full[128];
    long i;
    snprintf(full, sizeof full, "%s%s", prefix, name);
    g->syntax->table_open(o, g, g->uint, full, n);
    for (i = 0; i < n; i++)
        sbuf_printf(o, hex ? "%s0x%05lxu" : "%s%luu", table_sep(i, per_line), v[i]);
    sbuf_puts(o, g->syntax->table_close);
}

/* Appends a constant float table prefix+name of n values (rounded to floats exactly, 9 digits). */
static void put_float_table(sbuf *o, const kern_target *g, const char *prefix, const char *name,
                            const float *v, int n)
{
    char full[128];
    int i;
    snprintf(full, sizeof full, "%s%s", prefix, name);
    g->syntax->table_open(o, g, g->real, full, n);
    for (i = 0; i < n; i++) {
        char lit[48];
        sprintf(lit, "%.9g", (double)v[i]);
        if (!strpbrk(lit, ".en"))
            strcat(lit, ".0");
        sbuf_printf(o, "%s%sf", table_sep(i, 6), lit);
    }
    sbuf_puts(o, g->syntax->table_close);
}

/* Declares the constant up+name = value (a uint) with its comment. */
static void put_uint_constant(sbuf *o, const kern_target *g, const char *up, const char *name,
                              long value, const char *comment)
{
    char full[128], lit[32];
    snprintf(full, sizeof full, "%s%s", up, name);
    snprintf(lit, sizeof lit, "%ldu", value);
    g->syntax->constant(o, g, full, g->uint, lit, comment);
}

/* The constants P, Q, K, L and the planes each thread owns (CSR: own_start, own_plane); v has
 * room for nplanes + P + 1 values. */
static void put_owners(sbuf *o, const tp_table *t, const out_info *info, const kern_target *g,
                       const char *up, unsigned long *v)
{
    const sched *s = info->sched;
    int P = s->threads, th, p, k = 0;
    put_uint_constant(o, g, up, "P", P, "threads per patch");
    put_uint_constant(o, g, up, "Q", s->patches, "patches per workgroup");
    put_uint_constant(o, g, up, "K", t->dom.npoints, "control points per patch");
    put_uint_constant(o, g, up, "L", t->dom.nplanes, "control planes per patch");
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
}

/* Whether the kernel has the second look: --certified on a target with double-float. */
static int second_look(const out_info *info, const kern_target *g)
{
    return info->certified && g->vec2;
}

/* Whether the second look sums its planes again from the rounds' tables (no df_table): the
 * weights' low parts and the accumulators' low parts acc2 are emitted for it. */
static int second_look_rounds(const out_info *info, const kern_target *g)
{
    return second_look(info, g) && !g->df_table;
}

/* Into hi the float of w's literal, into lo the float nearest w - hi: hi + lo is w within
 * 2^-47 |w|. */
static void weight_split(float *hi, float *lo, const rat *w)
{
    char lit[48];
    *hi = strtof(fmt_float_literal(lit, w), NULL);
    *lo = (float)(rat_get_d(w) - (double)*hi);
}

/* With the second look, its terms in the order of own_plane: those of own_plane[n] are
 * dj, dkl, dw, dwl[dstart[n] .. dstart[n+1]-1] (points j and k | l << 16, the weight's high and
 * low parts), so that a thread re-evaluates only the planes it chose. v has room for nplanes + 1
 * + 2 nterms values. */
static int put_df_terms(sbuf *o, const tp_table *t, const out_info *info, const kern_target *g,
                        unsigned long *v, ptp_error *err)
{
    const sched *s = info->sched;
    long L = t->dom.nplanes, n = 0, th, p;
    size_t x, k = 0;
    float *w;
    for (th = 0; th < s->threads; th++) {
        for (p = 0, n = 0; p < L; p++)
            n += s->owner[p] == th;
        if (n > 32) /* the planes a thread chose are bits of one uint */
            return ptp_fail(err, PTP_ELIMIT, "--certified: thread %ld owns %ld planes, more than 32", th, n);
    }
    n = 0;
    w = malloc(2 * (t->nterms + 1) * sizeof *w);
    if (!w)
        return ptp_fail(err, PTP_ENOMEM, "out of memory writing tables");
    for (th = 0; th < s->threads; th++)
        for (p = 0; p < L; p++) {
            if (s->owner[p] != th)
                continue;
            v[n++] = (unsigned long)k;
            for (x = 0; x < t->nterms; x++) {
                const tp_term *a = &t->terms[x];
                if (a->plane != p)
                    continue;
                v[L + 1 + k] = (unsigned long)a->j;
                v[L + 1 + t->nterms + k] = (unsigned long)a->k | (unsigned long)a->l << 16;
                weight_split(&w[k], &w[t->nterms + k], &a->w);
                k++;
            }
        }
    v[n] = (unsigned long)k;
    sbuf_puts(o, "/* Second look: the terms of own_plane[n] are dw[i] * term(dj[i], dkl[i] = k | l << 16)\n"
                 " * (weight dw + dwl in double-float) for i in dstart[n] .. dstart[n+1]-1. */\n");
    put_uint_table(o, g, info->prefix, "dstart", v, L + 1, 16, 0);
    put_uint_table(o, g, info->prefix, "dj", v + L + 1, (long)k, 16, 0);
    put_uint_table(o, g, info->prefix, "dkl", v + L + 1 + t->nterms, (long)k, 8, 1);
    put_float_table(o, g, info->prefix, "dw", w, (int)k);
    put_float_table(o, g, info->prefix, "dwl", w + t->nterms, (int)k);
    sbuf_puts(o, "\n");
    free(w);
    return PTP_OK;
}

/* With the second look from the rounds, round r's weights' low parts wl (weight_split). */
static void put_weight_lo(sbuf *o, const tp_table *t, const out_info *info, const kern_target *g,
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
    put_float_table(o, g, info->prefix, name, lo, s->threads);
}

/* Round r's tables: the slots of the P threads (packed indices pj, kl and weights w); padding
 * slots name an owned plane with weight 0. One small table per field, indexed by the thread:
 * the rounds index no large constant array dynamically (lavapipe copies such an array on every
 * access; GPUs prefer small tables too). v has room for 2 P values. */
static void put_round(sbuf *o, const tp_table *t, const out_info *info, const kern_target *g,
                      int r, unsigned long *v)
{
    const sched *s = info->sched;
    int P = s->threads, th;
    char name[128], lit[48];
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
    snprintf(name, sizeof name, "%sw%d", info->prefix, r);
    g->syntax->table_open(o, g, g->real, name, P);
    for (th = 0; th < P; th++) {
        long x = s->slot[(long)r * P + th];
        rat zero;
        rat_set_si(&zero, 0);
        fmt_float_literal(lit, x >= 0 ? &t->terms[x].w : &zero);
        sbuf_printf(o, "%s%s", table_sep(th, 8), lit);
    }
    sbuf_puts(o, g->syntax->table_close);
    if (second_look_rounds(info, g))
        put_weight_lo(o, t, info, g, r);
    sbuf_puts(o, "\n");
}

/* Appends the constant <UP>QMAX<n> and the tables tau<n>_k, tau<n>_f of cb (n: "" or "2"), after
 * the comment what, which ends with "for max(E, 1) R^3 < ". Clears cb. */
static void put_bounds(sbuf *o, const out_info *info, const kern_target *g, const char *up,
                       cert_bounds *cb, const char *n, const char *what)
{
    char name[128], lit[48];
    sbuf_printf(o, "%s%sQMAX%s. */\n", what, up, n);
    snprintf(name, sizeof name, "%sQMAX%s", up, n);
    snprintf(lit, sizeof lit, "%.9gf", (double)cb->q_max);
    g->syntax->constant(o, g, name, g->real, lit, NULL);
    snprintf(name, sizeof name, "tau%s_k", n);
    put_float_table(o, g, info->prefix, name, cb->k, cb->nplanes);
    snprintf(name, sizeof name, "tau%s_f", n);
    put_float_table(o, g, info->prefix, name, cb->k2, cb->nplanes);
    sbuf_puts(o, "\n");
    cert_clear(cb);
}

/* Whether the kernel knows exact zeros: --certified under the degenerate rule, where a plane that
 * a collapsed boundary edge zeros counts as exactly 0 (both <= 0 and >= 0), as in the C header. */
static int exact_zeros(const out_info *info)
{
    return info->certified && info->rule == OUT_DEGENERATE;
}

/* Whether the terms read differences of points (the target's diff, --certified). */
static int differences(const out_info *info, const kern_target *g)
{
    return info->certified && g->diff;
}

/* With exact zeros, the table zero: per plane the boundary edges (bit e) on which every term has
 * two points, so that collapsing any of them makes the plane exactly 0. */
static int put_zero_table(sbuf *o, const tp_table *t, const out_info *info, const kern_target *g,
                          ptp_error *err)
{
    unsigned long *z = calloc((size_t)t->dom.nplanes, sizeof *z);
    size_t x;
    if (!z)
        return ptp_fail(err, PTP_ENOMEM, "out of memory writing tables");
    for (x = 0; x < t->nterms; x++) { /* sorted by plane */
        const tp_term *a = &t->terms[x];
        int k[3] = {a->j, a->k, a->l};
        unsigned long e = tp_domain_term_edges(&t->dom, k);
        z[a->plane] = x > 0 && t->terms[x - 1].plane == a->plane ? z[a->plane] & e : e;
    }
    sbuf_puts(o, "/* Degenerate rule: bit e of zero[P] where every term of plane P has two points on boundary\n"
                 " * edge e, so that the plane is exactly 0 when that edge is collapsed. */\n");
    put_uint_table(o, g, info->prefix, "zero", z, t->dom.nplanes, 16, 0);
    sbuf_puts(o, "\n");
    free(z);
    return PTP_OK;
}

/* --certified: QMAX and the bounds' factors tau_k, tau_f of every plane; with the second look,
 * QMAX2, tau2_k and tau2_f of its double-float evaluation too; with exact zeros, zero. */
static int put_cert_tables(sbuf *o, const tp_table *t, const out_info *info, const kern_target *g,
                           const char *up, ptp_error *err)
{
    cert_bounds cb;
    int st = cert_gpu(&cb, t, info->space == OUT_WORLD, g->unit_roundoff, differences(info, g), err);
    if (st)
        return st;
    put_bounds(o, info, g, up, &cb, "",
               "/* Certified: |d_P - exact| <= tau_k[P] * M + tau_f[P] * (1 + R)^3 (1 + E), M from the\n"
               " * patch's largest |coordinates| and the eye, R the largest of them, E the eye's largest\n"
               " * |component|; for max(E, 1) R^3 < ");
    if (exact_zeros(info) && (st = put_zero_table(o, t, info, g, err)))
        return st;
    if (!g->vec2)
        return PTP_OK;
    if ((st = cert_table_df(&cb, t, info->space == OUT_WORLD, err)))
        return st;
    put_bounds(o, info, g, up, &cb, "2",
               "/* Second look, in double-float from the points: |hi + lo - exact| <= tau2_k[P] * M2\n"
               " * + tau2_f[P] * (1 + R)^3 (1 + E), M2 from the largest |coordinates|, for\n"
               " * max(E, 1) R^3 < ");
    return PTP_OK;
}

/* The constants and the constant tables: the owned planes of each thread, per round the slots of
 * the P threads and, certified, the bounds. */
static int put_tables(sbuf *o, const tp_table *t, const out_info *info, const kern_target *g,
                      const char *up, ptp_error *err)
{
    int P = info->sched->threads, r, st = PTP_OK;
    size_t n = (size_t)t->dom.nplanes + (size_t)P + 2 * t->nterms + 2;
    unsigned long *v = malloc(n * sizeof *v); /* room for put_owners, put_round, put_df_terms */
    if (!v)
        return ptp_fail(err, PTP_ENOMEM, "out of memory writing tables");
    put_owners(o, t, info, g, up, v);
    for (r = 0; r < info->sched->rounds; r++)
        put_round(o, t, info, g, r, v);
    if (second_look(info, g) && g->df_table)
        st = put_df_terms(o, t, info, g, v, err);
    free(v);
    return !st && info->certified ? put_cert_tables(o, t, info, g, up, err) : st;
}

/* Writes to out (size bytes, truncating as snprintf) the product of the n factors f, left to
 * right, as the kernel writes every float product but cross4's (kern_target.product): the
 * target's function p(p(f0, f1), f2), else f0 * f1 * f2; brk follows each comma or operator:
 * " ", or a line break and indent. A factor that is a sum, or a product after the first, comes
 * from put_group. Returns out. */
static char *put_product(char *out, size_t size, const kern_target *g, const char *brk, int n,
                         const char *const *f)
{
    size_t k = 0;
    int i;
    out[0] = '\0';
    for (i = 1; g->product && i < n && k < size; i++)
        k += (size_t)snprintf(out + k, size - k, "%s(", g->product);
    for (i = 0; i < n && k < size; i++)
        k += (size_t)snprintf(out + k, size - k, "%s%s%s%s", i == 0 ? "" : g->product ? "," : " *",
                              i == 0 ? "" : brk, f[i], i > 0 && g->product ? ")" : "");
    return out;
}

/* put_product of the two factors a and b on one line. */
static char *put_mul(char *out, size_t size, const kern_target *g, const char *a, const char *b)
{
    return put_product(out, size, g, " ", 2, (const char *const[]){a, b});
}

/* Writes to out (size bytes) e, a sum or a product, as a factor of put_product: (e) between
 * operators, e as an argument of the target's product function. Returns out. */
static char *put_group(char *out, size_t size, const kern_target *g, const char *e)
{
    snprintf(out, size, g->product ? "%s" : "(%s)", e);
    return out;
}

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
            put_mul(m[c], sizeof m[c], g, e, names[c]);
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

/* Appends src with its shorthands expanded: $ is the prefix, {a*b} the target's product of the
 * operands a and b, {a*b+c} its fused multiply-add, {h;l} the double-float of the floats h, l. */
static void put_df_text(sbuf *o, const out_info *info, const kern_target *g, const char *src)
{
    while (*src) {
        const char *end = *src == '{' ? strchr(src, '}') : NULL;
        if (*src == '$') {
            sbuf_puts(o, info->prefix);
            src++;
        } else if (end) {
            char a[64], b[64], c[64] = "";
            size_t n = strcspn(src + 1, "*;"), m = strcspn(src + n + 2, "+}");
            snprintf(a, sizeof a, "%.*s", (int)n, src + 1);
            snprintf(b, sizeof b, "%.*s", (int)m, src + n + 2);
            if (src[n + 2 + m] == '+')
                snprintf(c, sizeof c, "%.*s", (int)(end - src - n - m - 3), src + n + m + 3);
            sbuf_printf(o, *c ? g->fma : src[1 + n] == '*' ? g->mul : g->vec2_make, a, b, c);
            src = end + 1;
        } else {
            sbuf_printf(o, "%c", *src++);
        }
    }
}

/* A double-float helper: its name (after the prefix), parameters and locals as a type letter
 * (f real, v the pair, 4 vec4) and a name, the locals with their initializers, and the value it
 * returns, all in put_df_text's shorthand. Every local is exact (never contracted). */
typedef struct {
    const char *name, *params[6], *locals[6], *ret;
    int fma; /* 1: only for a target with a one-rounding FMA; -1: only without; 0: always */
} df_helper;

/* The double-float operations: error-free two-sum (Knuth), fast two-sum, the two-product (with a
 * one-rounding FMA, or Dekker's on Veltkamp's split, exact for 24-bit floats), and from them (Joldes, Muller and Popescu
 * 2017) the pair times a float, times a pair, and the accurate sum; then 2x2 minors and cofactor
 * sums of the determinants. */
static const df_helper df_helpers[] = {
    {"df_two_sum", {"fa", "fb"}, {"fs=a + b", "fv=s - a", "fe=(a - (s - v)) + (b - v)"}, "{s;e}", 0},
    {"df_fast_two_sum", {"fa", "fb"}, {"fs=a + b", "fe=b - (s - a)"}, "{s;e}", 0},
    {"df_split", {"fa"}, {"fc={4097.0f*a}", "fh=c - (c - a)", "fl=a - h"}, "{h;l}", -1},
    {"df_two_prod", {"fa", "fb"},
     {"vx=$df_split(a)", "vy=$df_split(b)", "fp={a*b}",
      "fe=(({x.x*y.x} - p) + {x.x*y.y} + {x.y*y.x}) + {x.y*y.y}"}, "{p;e}", -1},
    {"df_two_prod", {"fa", "fb"}, {"fp={a*b}", "fe={a*b+-p}"}, "{p;e}", 1},
    {"df_mul_f", {"vx", "fb"}, {"vc=$df_two_prod(x.x, b)", "fl=c.y + {x.y*b}"},
     "$df_fast_two_sum(c.x, l)", 0},
    {"df_mul", {"vx", "vy"}, {"vc=$df_two_prod(x.x, y.x)", "fl=c.y + ({x.x*y.y} + {x.y*y.x})"},
     "$df_fast_two_sum(c.x, l)", 0},
    {"df_add", {"vx", "vy"},
     {"vs=$df_two_sum(x.x, y.x)", "vt=$df_two_sum(x.y, y.y)", "fh=s.y + t.x",
      "vv=$df_fast_two_sum(s.x, h)", "fl=v.y + t.y"}, "$df_fast_two_sum(v.x, l)", 0},
    {"df_sub", {"vx", "vy"}, {NULL}, "$df_add(x, {-y.x;-y.y})", 0},
    {"df_minor", {"fa", "fb", "fc", "fd"}, {NULL}, "$df_sub($df_two_prod(a, b), $df_two_prod(c, d))", 0},
    {"df_cof", {"vm0", "fa0", "vm1", "fa1", "vm2", "fa2"}, {NULL},
     "$df_add($df_sub($df_mul_f(m0, a0), $df_mul_f(m1, a1)), $df_mul_f(m2, a2))", 0},
};

/* The type a df_helper's letter names. */
static const char *df_type(const kern_target *g, char c)
{
    return c == 'f' ? g->real : c == 'v' ? g->vec2 : g->vec4;
}

/* Appends helper h's function. */
static void put_df_helper(sbuf *o, const out_info *info, const kern_target *g, const df_helper *h)
{
    kern_param p[6];
    char name[128];
    sbuf e;
    int n, i;
    for (n = 0; n < 6 && h->params[n]; n++)
        p[n] = (kern_param){df_type(g, h->params[n][0]), h->params[n] + 1};
    snprintf(name, sizeof name, "%s%s", info->prefix, h->name);
    g->syntax->function(o, g, g->vec2, name, p, n);
    for (i = 0; i < 6 && h->locals[i]; i++) {
        char var[8];
        const char *eq = strchr(h->locals[i], '=');
        snprintf(var, sizeof var, "%.*s", (int)(eq - h->locals[i] - 1), h->locals[i] + 1);
        sbuf_init(&e);
        put_df_text(&e, info, g, eq + 1);
        g->syntax->locals(o, g, "    ", df_type(g, h->locals[i][0]), &(kern_var){var, opt(e.s), 0},
                          1, 1);
        o->failed |= e.failed;
        sbuf_clear(&e);
    }
    sbuf_puts(o, "    return ");
    put_df_text(o, info, g, h->ret);
    sbuf_puts(o, ";\n}\n\n");
}

/* Writes to d (256 bytes) the double-float det[a b c] of rows p, q, s, as put_det expands it. */
static void put_df_det(char *d, int p, int q, int s)
{
    static const char comp[] = "xyzw";
    const char *u = "baa", *v = "ccb";
    size_t n = (size_t)snprintf(d, 256, "$df_cof(");
    int i;
    for (i = 0; i < 3; i++)
        n += (size_t)snprintf(d + n, 256 - n, "%s$df_minor(%c.%c, %c.%c, %c.%c, %c.%c), %c.%c",
                              i ? ",\n        " : "", u[i], comp[q], v[i], comp[s], u[i], comp[s],
                              v[i], comp[q], "abc"[i], comp[p]);
    snprintf(d + n, 256 - n, ")");
}

/* --certified's second look: the double-float helpers and the term, as put_cross4's. */
static void put_df_functions(sbuf *o, const out_info *info, const kern_target *g)
{
    static const int rows[5][3] = {{1, 2, 3}, {0, 2, 3}, {0, 1, 3}, {0, 1, 2}, {0, 1, 3}};
    static const char *const names[4] = {"x", "y", "z", "w"};
    const char *v = g->vec4;
    kern_param p[4] = {{v, "a"}, {v, "b"}, {v, "c"}, {v, "e"}};
    int world = info->space == OUT_WORLD, c;
    char name[128], det[256];
    sbuf_puts(o, "/* Second look: double-float arithmetic (hi .x + lo .y) from error-free transformations\n"
                 " * with + - * only, none contracted into an FMA. */\n");
    for (c = 0; c < (int)(sizeof df_helpers / sizeof *df_helpers); c++)
        if (df_helpers[c].fma != (g->fma ? -1 : 1))
            put_df_helper(o, info, g, &df_helpers[c]);
    sbuf_printf(o, "/* %s, in double-float. */\n", world ? "e . cross4(a, b, c)" : "cross4z(a, b, c)");
    snprintf(name, sizeof name, "%sdf_%s", info->prefix, world ? "eye_cross4" : "cross4z");
    g->syntax->function(o, g, g->vec2, name, p, world ? 4 : 3);
    for (c = world ? 0 : 4; c < (world ? 4 : 5); c++) {
        put_df_det(det, rows[c][0], rows[c][1], rows[c][2]);
        sbuf_printf(o, "    %s %s = ", g->vec2, world ? names[c] : "z");
        put_df_text(o, info, g, det);
        sbuf_puts(o, ";\n");
    }
    if (world)
        put_df_text(o, info, g, "    return $df_sub($df_add($df_sub($df_mul_f(x, e.x), $df_mul_f(y, e.y)),\n"
                                "        $df_mul_f(z, e.z)), $df_mul_f(w, e.w));\n}\n\n");
    else
        sbuf_puts(o, "    return z;\n}\n\n");
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

/* The workgroup-shared arrays: the patches' points, the planes' accumulators (with the second
 * look from the rounds, their low parts acc2 too), the flags. */
static void put_shared(sbuf *o, const out_info *info, const kern_target *g, const char *up,
                       const char *indent)
{
    char count[160];
    snprintf(count, sizeof count, "%sQ * %sK", up, up);
    g->syntax->shared(o, g, indent, g->vec4, "pts", count);
    snprintf(count, sizeof count, "%sQ * %sL", up, up);
    g->syntax->shared(o, g, indent, g->real, "acc", count);
    if (second_look_rounds(info, g))
        g->syntax->shared(o, g, indent, g->real, "acc2", count);
    snprintf(count, sizeof count, "%sQ * %sP", up, up);
    g->syntax->shared(o, g, indent, g->uint, "flags", count);
}

/* The body's start: the thread's place (lid, q, t), its patch (pid, live), the loop variables
 * and the flags f; then the patch's control points into shared memory. */
static void put_load(sbuf *o, const kern_target *g, const char *up)
{
    char q[96], t[96], pid[256];
    kern_var v[6] = {{"lid", g->local_id, 0}, {"q", q, 0}, {"t", t, 0},
                     {"i", NULL, 1}, {"pj", NULL, 1}, {"kl", NULL, 1}};
    snprintf(q, sizeof q, "lid / %sP", up);
    snprintf(t, sizeof t, "lid %% %sP", up);
    snprintf(pid, sizeof pid, "(%s * %s + %s) * %sQ + q", g->group_y, g->groups_x, g->group_x, up);
    g->syntax->locals(o, g, "    ", g->uint, v, 6, 0);
    put_local(o, g, g->uint, "pid", pid, 0);
    put_local(o, g, g->uint, "f", "0u", 1);
    put_local(o, g, "bool", "live", "pid < patch_count", 0);
    sbuf_printf(o, "\n    /* The patch's control points into shared memory, P threads cooperating. */\n"
                   "    for (i = t; i < %sK; i += %sP)",
                up, up);
    put_then(o, g);
    sbuf_puts(o, "        if (live)");
    put_then(o, g);
    sbuf_printf(o, "            pts[q * %sK + i] = cp[pid * %sK + i];\n", up, up);
    put_end(o, g, "        ");
    put_end(o, g, "    ");
    sbuf_printf(o, "    %s\n\n", g->barrier);
}

/* The accumulation of the planes this thread owns, one round at a time; with differences, term
 * (j, k, l) reads b_j, b_k - b_j, b_l - b_j (the same determinant). */
static void put_accumulate(sbuf *o, const out_info *info, const kern_target *g, const char *up)
{
    const char *px = info->prefix, *fn = info->space == OUT_CLIP ? "cross4z" : "eye_cross4";
    char a[128], b[320], c[320], w[96], term[1024], e[1152]; /* up has at most 63 bytes */
    int r, n = (int)(strlen(px) + strlen(fn));
    sbuf_printf(o,
                "    /* Accumulate the planes this thread owns, one round at a time: no other thread\n"
                "     * touches them. */\n"
                "    for (i = %sown_start[t]; i < %sown_start[t + 1u]; i++)",
                px, px);
    put_then(o, g);
    sbuf_printf(o, "        acc[q * %sL + %sown_plane[i]] = 0.0f;\n", up, px);
    put_end(o, g, "    ");
    snprintf(a, sizeof a, "pts[q * %sK + (pj >> 16)]", up);
    if (differences(info, g)) { /* b_k - b_j and b_l - b_j */
        snprintf(b, sizeof b, "%sdiff(pts[q * %sK + (kl & 0xffffu)], %s)", px, up, a);
        snprintf(c, sizeof c, "%sdiff(pts[q * %sK + (kl >> 16)], %s)", px, up, a);
    } else {
        snprintf(b, sizeof b, "pts[q * %sK + (kl & 0xffffu)]", up);
        snprintf(c, sizeof c, "pts[q * %sK + (kl >> 16)]", up);
    }
    for (r = 0; r < info->sched->rounds; r++) {
        snprintf(w, sizeof w, "%sw%d[t]", px, r);
        snprintf(term, sizeof term, "%s%s(%s,%s%*s %s,\n        %*s %s%s)", px, fn, a,
                 differences(info, g) ? "\n        " : "", differences(info, g) ? n : 0, "", b, n, "",
                 c, info->space == OUT_CLIP ? "" : ", eye");
        put_product(e, sizeof e, g, "\n        ", 2, (const char *const[]){w, term});
        sbuf_printf(o, "    pj = %spj%d[t];\n    kl = %skl%d[t];\n"
                       "    acc[q * %sL + (pj & 0xffffu)] += %s;\n",
                    px, r, px, r, up, e);
    }
    sbuf_puts(o, "\n");
}

/* With exact zeros, col: bit e where boundary edge e of d is collapsed, its points bitwise equal
 * and every coordinate of the patch finite (fin). */
static void put_collapsed(sbuf *o, const tp_domain *d, const out_info *info, const kern_target *g,
                          const char *up)
{
    char base[96], bit[16];
    int e, k, f, i, j;
    sbuf_puts(o, "    /* Degenerate rule: bit e of col where boundary edge e is collapsed (its points bitwise\n"
                 "     * equal, every coordinate finite); the planes of zero[] with bit e are then exactly 0. */\n");
    put_local(o, g, g->uint, "col", "0u", 1);
    snprintf(base, sizeof base, "q * %sK", up);
    put_local(o, g, g->uint, "base", base, 0);
    for (e = 0; e < tp_domain_edges(d); e++) {
        sbuf cond;
        char *sel;
        sbuf_init(&cond);
        sbuf_puts(&cond, "fin");
        for (k = 0, f = -1; k < d->npoints; k++) {
            tp_domain_point_ij(&i, &j, d, k);
            if (!tp_domain_on_edge(d, e, i, j))
                continue;
            if (f < 0)
                f = k;
            else
                sbuf_printf(&cond, " &&\n        %ssame(pts[base + %du], pts[base + %du])", info->prefix, k, f);
        }
        snprintf(bit, sizeof bit, "%uu", 1u << e);
        sel = cond.failed ? NULL : malloc(strlen(cond.s) + 64);
        if (sel) {
            g->syntax->select(sel, strlen(cond.s) + 64, cond.s, bit, "0u");
            sbuf_printf(o, "    col |= %s;\n", sel);
        }
        o->failed |= !sel;
        free(sel);
        sbuf_clear(&cond);
    }
}

/* Into e (size bytes) the largest |monomial| of one coordinate and two differences over the
 * coordinates u, D the extents, as a factor (put_group): Ru0 Du1 Du2 + Du0 Ru1 Du2 + Du0 Du1 Ru2.
 * Returns e. */
static char *put_diff_monomial(char *e, size_t size, const kern_target *g, const char *u)
{
    char f[3][4], m[3][64], s[224];
    int i, k;
    for (i = 0; i < 3; i++) {
        for (k = 0; k < 3; k++)
            snprintf(f[k], sizeof f[k], "%c%c", k == i ? 'R' : 'D', u[k]);
        put_product(m[i], sizeof m[i], g, " ", 3, (const char *const[]){f[0], f[1], f[2]});
    }
    snprintf(s, sizeof s, "%s + %s + %s", m[0], m[1], m[2]);
    return put_group(e, size, g, s);
}

/* Into e (size bytes) world space's largest |monomial| with the eye's components h[0], h[1]
 * (the other two r): (|eye.h0| Rh1 + |eye.h1| Rh0) (Rr0 Rr1). Returns e. */
static char *put_eye_monomial(char *e, size_t size, const kern_target *g, const char *h,
                              const char *r)
{
    char a[32], x[2][4], m[2][64], s[160], t[2][160];
    int i;
    for (i = 0; i < 2; i++) {
        snprintf(a, sizeof a, "%s(eye.%c)", g->fabs, h[i]);
        snprintf(x[0], sizeof x[0], "R%c", h[!i]);
        put_mul(m[i], sizeof m[i], g, a, x[0]);
    }
    snprintf(s, sizeof s, "%s + %s", m[0], m[1]);
    snprintf(x[0], sizeof x[0], "R%c", r[0]);
    snprintf(x[1], sizeof x[1], "R%c", r[1]);
    put_group(t[0], sizeof t[0], g, s);
    put_group(t[1], sizeof t[1], g, put_mul(a, sizeof a, g, x[0], x[1]));
    return put_mul(e, size, g, t[0], t[1]);
}

/* Into e (1024 bytes), M from the eye and the patch's largest |coordinates| Rx, Ry, Rz, Rw: the
 * largest |monomial| (clip space); in world space the sum over the eye's components of the
 * largest |monomial| with that component (README: Certified). With diff (differences), a
 * monomial has one coordinate and two differences instead (put_diff_monomial). */
static void put_monomial_max(char *e, const out_info *info, const kern_target *g, int diff)
{
    static const char *const other[4] = {"yzw", "xzw", "xyw", "xyz"};
    char a[32], m[256], x[160];
    size_t n = 0;
    int c;
    if (info->space == OUT_CLIP) {
        if (diff)
            put_diff_monomial(m, sizeof m, g, "xyw");
        else
            put_group(m, sizeof m, g, put_product(x, sizeof x, g, " ", 3, (const char *const[]){"Rx", "Ry", "Rw"}));
        put_mul(e, 1024, g, "E", m);
    } else if (diff) {
        for (c = 0; c < 4 && n < 1024; c++) {
            snprintf(a, sizeof a, "%s(eye.%c)", g->fabs, "xyzw"[c]);
            put_diff_monomial(x, sizeof x, g, other[c]);
            n += (size_t)snprintf(e + n, 1024 - n, "%s%s", c ? " +\n        " : "", put_mul(m, sizeof m, g, a, x));
        }
    } else {
        put_eye_monomial(m, sizeof m, g, "xy", "zw");
        snprintf(e, 1024, "%s +\n        %s", m, put_eye_monomial(x, sizeof x, g, "zw", "xy"));
    }
}

/* With differences, the patch's extents over the coordinates c (n of them): step 0 declares
 * Hc = max b.c and Lc = max -b.c from the first point, step 1 (in the loop over the points a)
 * updates them, step 2 declares the extents Dc = Hc + Lc (README: Differences of points). */
static void put_extents(sbuf *o, const out_info *info, const kern_target *g, const char *up,
                        const char *c, int n, int step)
{
    char name[2][4], init[2][96];
    int k;
    for (k = 0; differences(info, g) && k < n; k++) {
        snprintf(name[0], sizeof name[0], "H%c", c[k]);
        snprintf(name[1], sizeof name[1], "L%c", c[k]);
        snprintf(init[0], sizeof init[0], "pts[q * %sK].%c", up, c[k]);
        snprintf(init[1], sizeof init[1], "-pts[q * %sK].%c", up, c[k]);
        if (step == 0)
            g->syntax->locals(o, g, "    ", g->real,
                              (kern_var[2]){{name[0], init[0], 1}, {name[1], init[1], 1}}, 2, 0);
        else if (step == 1)
            sbuf_printf(o, "        H%c = %s(H%c, a.%c);\n        L%c = %s(L%c, -a.%c);\n", c[k], g->fmax,
                        c[k], c[k], c[k], g->fmax, c[k], c[k]);
        else {
            snprintf(name[0], sizeof name[0], "D%c", c[k]);
            snprintf(init[0], sizeof init[0], "H%c + L%c", c[k], c[k]);
            put_local(o, g, g->real, name[0], init[0], 0);
        }
    }
}

/* Appends at indent the head of the test that the patch is too large for the bound (or NaN),
 * if (!(max(E, 1) * R3 < <up>qmax)), with the target's product. */
static void put_too_large(sbuf *o, const kern_target *g, const char *indent, const char *up,
                          const char *qmax)
{
    char e[32], m[64];
    snprintf(e, sizeof e, "%s(E, 1.0f)", g->fmax);
    sbuf_printf(o, "%sif (!(%s < %s%s))", indent, put_mul(m, sizeof m, g, e, "R3"), up, qmax);
}

/* --certified: the patch's largest |coordinates| Rx, Ry, (Rz,) Rw, R the largest of them, E the
 * eye's largest |component|, M the largest |monomial| (with differences, of the terms as they
 * read them), with the second look M2 that of the points, and F the underflow term's factor;
 * patches too large for the bound get flags 3 (never certified). With exact zeros, the collapsed
 * edges of d too. */
static void put_scale(sbuf *o, const tp_domain *d, const out_info *info, const kern_target *g,
                      const char *up)
{
    const char *ab = g->fabs, *mx = g->fmax, *f = g->real, *c = info->space == OUT_CLIP ? "xyw" : "xyzw";
    char e[1024], rc[4][4], r1[16], e1[16];
    kern_var r[4];
    int k, n = (int)strlen(c);
    sbuf_puts(o, "    /* Certified: the patch's largest |coordinates| and the eye's bound the errors. */\n");
    for (k = 0; k < n; k++) {
        snprintf(rc[k], sizeof rc[k], "R%c", c[k]);
        r[k] = (kern_var){rc[k], "0.0f", 1};
    }
    g->syntax->locals(o, g, "    ", f, r, n, 0);
    put_extents(o, info, g, up, c, n, 0);
    if (exact_zeros(info))
        put_local(o, g, "bool", "fin", "true", 1);
    sbuf_printf(o, "    for (i = 0u; i < %sK; i++) {\n", up);
    snprintf(e, sizeof e, "pts[q * %sK + i]", up);
    g->syntax->locals(o, g, "        ", g->vec4, &(kern_var){"a", e, 0}, 1, 0);
    for (k = 0; k < n; k++)
        sbuf_printf(o, "        R%c = %s(R%c, %s(a.%c));\n", c[k], mx, c[k], ab, c[k]);
    put_extents(o, info, g, up, c, n, 1);
    if (exact_zeros(info))
        sbuf_printf(o, "        fin = fin && %sfinite(a);\n", info->prefix);
    sbuf_puts(o, "    }\n");
    if (info->space == OUT_CLIP) {
        snprintf(e, sizeof e, "%s(%s(Rx, Ry), Rw)", mx, mx);
        put_local(o, g, f, "R", e, 0);
        snprintf(e, sizeof e, "%s(eye.z)", ab);
    } else {
        snprintf(e, sizeof e, "%s(%s(Rx, Ry), %s(Rz, Rw))", mx, mx, mx);
        put_local(o, g, f, "R", e, 0);
        snprintf(e, sizeof e, "%s(%s(%s(eye.x), %s(eye.y)), %s(%s(eye.z), %s(eye.w)))", mx, mx, ab, ab,
                 mx, ab, ab);
    }
    put_local(o, g, f, "E", e, 0);
    put_local(o, g, f, "R3", put_product(e, sizeof e, g, " ", 3, (const char *const[]){"R", "R", "R"}), 0);
    put_extents(o, info, g, up, c, n, 2);
    put_monomial_max(e, info, g, differences(info, g));
    put_local(o, g, f, "M", e, 0);
    if (second_look(info, g)) { /* M2: the second look reads the points */
        put_monomial_max(e, info, g, 0);
        put_local(o, g, f, "M2", e, 0);
    }
    put_group(r1, sizeof r1, g, "1.0f + R");
    put_group(e1, sizeof e1, g, "1.0f + E");
    put_local(o, g, f, "F", put_product(e, sizeof e, g, " ", 4, (const char *const[]){r1, r1, r1, e1}), 0);
    put_too_large(o, g, "    ", up, "QMAX");
    put_then(o, g);
    sbuf_puts(o, "        f = 3u; /* too large for the bound, or NaN: never certified */\n");
    put_end(o, g, "    ");
    if (exact_zeros(info))
        put_collapsed(o, d, info, g, up);
    if (second_look(info, g)) { /* the plain float signs' flags; the planes to look at again */
        kern_var v[3] = {{"pf", "0u", 1}, {"redo", "0u", 1}, {"fd", "0u", 1}};
        g->syntax->locals(o, g, "    ", g->uint, v, 3, 0);
    }
}

/* With exact zeros, the local keep of the plane numbered by the expression plane: 0u where a
 * collapsed edge makes it exactly 0, so that its flags certify both signs; else 3u. */
static void put_keep(sbuf *o, const out_info *info, const kern_target *g, const char *indent,
                     const char *plane)
{
    char cond[224], e[320];
    snprintf(cond, sizeof cond, "(%szero[%s] & col) == 0u", info->prefix, plane);
    g->syntax->select(e, sizeof e, cond, "3u", "0u");
    g->syntax->locals(o, g, indent, g->uint, &(kern_var){"keep", e, 0}, 1, 0);
}

/* Into x (initialized here; the caller clears it) the first look's certified flags of the
 * plane: flags(d, tau_k[plane] * M + tau_f[plane] * F) (and keep), with the target's products.
 * Returns its text. */
static const char *first_flags(sbuf *x, const out_info *info, const kern_target *g)
{
    char k[96], f[96], m[2][128];
    snprintf(k, sizeof k, "%stau_k[plane]", info->prefix);
    snprintf(f, sizeof f, "%stau_f[plane]", info->prefix);
    sbuf_init(x);
    sbuf_printf(x, "%sflags(d, %s + %s)%s", info->prefix, put_mul(m[0], sizeof m[0], g, k, "M"),
                put_mul(m[1], sizeof m[1], g, f, "F"), exact_zeros(info) ? " & keep" : "");
    return x->s ? x->s : "";
}

/* With the second look, a plane's certified flags fp and plain flags pp: into f and pf, and
 * where they differ (the bound does not clear where the plain sign decides) the plane's bit in
 * redo (its place in own_plane after own_start[t]), else fp into fd. */
static void put_split_flags(sbuf *o, const out_info *info, const kern_target *g)
{
    const char *px = info->prefix, *keep = exact_zeros(info) ? " & keep" : "";
    char e[256];
    sbuf fp;
    kern_var v[2] = {{"fp", first_flags(&fp, info, g), 0}, {"pp", NULL, 0}};
    char pp[128];
    snprintf(pp, sizeof pp, "%sflags(d, 0.0f)%s", px, keep);
    v[1].init = pp;
    g->syntax->locals(o, g, "        ", g->uint, v, 1, 0);
    g->syntax->locals(o, g, "        ", g->uint, v + 1, 1, 0);
    o->failed |= fp.failed;
    sbuf_clear(&fp);
    snprintf(e, sizeof e, "1u << (i - %sown_start[t])", px);
    g->syntax->select(pp, sizeof pp, "fp != pp", e, "0u");
    sbuf_printf(o, "        f |= fp;\n        pf |= pp;\n        redo |= %s;\n", pp);
    g->syntax->select(pp, sizeof pp, "fp != pp", "0u", "fp");
    sbuf_printf(o, "        fd |= %s;\n", pp);
}

/* The values and flags of the owned planes (and with --planes, the values written out). */
static void put_signs(sbuf *o, const out_info *info, const kern_target *g, const char *up)
{
    const char *px = info->prefix;
    char e[256], d[320];
    sbuf x;
    sbuf_printf(o,
                "    /* The values and signs of the owned planes; then one thread combines the patch's. */\n"
                "    for (i = %sown_start[t]; i < %sown_start[t + 1u]; i++) {\n",
                px, px);
    snprintf(e, sizeof e, "%sown_plane[i]", px);
    g->syntax->locals(o, g, "        ", g->uint, &(kern_var){"plane", e, 0}, 1, 0);
    snprintf(e, sizeof e, "acc[q * %sL + plane]", up);
    if (info->space == OUT_CLIP)
        put_mul(d, sizeof d, g, "eye.z", e);
    g->syntax->locals(o, g, "        ", g->real, &(kern_var){"d", info->space == OUT_CLIP ? d : e, 0}, 1, 0);
    if (info->planes) {
        sbuf_printf(o, "        if (%slive)", g->planes_buffer ? "" : "planes && ");
        put_then(o, g);
        sbuf_printf(o, "            planes[pid * %sL + plane] = d;\n", up);
        put_end(o, g, "        ");
    }
    if (exact_zeros(info))
        put_keep(o, info, g, "        ", "plane");
    if (second_look(info, g))
        put_split_flags(o, info, g);
    else if (info->certified) {
        sbuf_printf(o, "        f |= %s;\n", first_flags(&x, info, g));
        o->failed |= x.failed;
        sbuf_clear(&x);
    } else
        sbuf_printf(o, "        f |= %sflags(d);\n", px);
    sbuf_puts(o, "    }\n");
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
    put_local(o, g, g->uint, "all", "0u", 1);
    sbuf_printf(o, "    for (i = 0u; i < %sP; i++)", up);
    put_then(o, g);
    sbuf_printf(o, "        all |= flags[q * %sP + i];\n", up);
    put_end(o, g, "    ");
    put_local(o, g, "bool", "again", "live && ((all & 5u) == 1u || (all & 10u) == 2u)", 0);
    sbuf_printf(o, "    %s\n", g->barrier);
}

/* The second look from the rounds: put_accumulate's rounds in double-float into acc and acc2;
 * with split_rounds each round under a test of its weight (padding slots' is 0). */
static void put_df_accumulate(sbuf *o, const out_info *info, const kern_target *g, const char *up)
{
    const char *px = info->prefix, *fn = info->space == OUT_CLIP ? "cross4z" : "eye_cross4";
    char hi[96], lo[96], w[96], wl[96], x[256], y[256];
    int r;
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
                       "%ss = %sdf_add(%s, %sdf_mul(%s, %sdf_%s(pts[q * %sK + (pj >> 16)],\n"
                       "%s    pts[q * %sK + (kl & 0xffffu)], pts[q * %sK + (kl >> 16)]%s)));\n"
                       "%sacc[at] = s.x;\n%sacc2[at] = s.y;\n",
                    in, w, in, wl, in, up, in, px, x, px, y, px, fn, up, in, up, up,
                    info->space == OUT_CLIP ? "" : ", eye", in, in);
        if (g->split_rounds)
            sbuf_puts(o, "        }\n");
    }
}

/* The second look's sum for own_plane[i] into s, in double-float: its terms when mine (its bit in
 * redo) is set, else none. */
static void put_df_sum(sbuf *o, const out_info *info, const kern_target *g, const char *up)
{
    const char *px = info->prefix, *fn = info->space == OUT_CLIP ? "cross4z" : "eye_cross4";
    char start[96], end[96], init[256], zero[96], w[128];
    snprintf(start, sizeof start, "%sdstart[i]", px);
    snprintf(end, sizeof end, "%sdstart[i + 1u]", px);
    g->syntax->select(init, sizeof init, "mine != 0u", start, end);
    snprintf(zero, sizeof zero, g->vec2_make, "0.0f", "0.0f");
    snprintf(w, sizeof w, g->vec2_make, "$dw[j]", "$dwl[j]");
    sbuf_printf(o, "            s = %s;\n            for (j = %s; j < %s; j++)", zero, init, end);
    put_then(o, g);
    sbuf_printf(o, "                s = %sdf_add(s, %sdf_mul(", px, px);
    put_df_text(o, info, g, w);
    sbuf_printf(o, ", %sdf_%s(pts[q * %sK + %sdj[j]],\n"
                   "                    pts[q * %sK + (%sdkl[j] & 0xffffu)], pts[q * %sK + (%sdkl[j] >> 16)]%s)));\n",
                px, fn, up, px, up, px, up, px, info->space == OUT_CLIP ? "" : ", eye");
    put_end(o, g, "            ");
}

/* The second look for the patches put_again chose: f again, from fd and the planes of redo in
 * double-float against the bounds tau2 (plus twice the low part, for comparing the high part
 * alone). */
static void put_second_look(sbuf *o, const out_info *info, const kern_target *g, const char *up)
{
    const char *px = info->prefix;
    char a[160], b[160], m[3][128];
    kern_var j = {"j", NULL, 1}, s = {"s", NULL, 1};
    put_again(o, g, up);
    sbuf_puts(o, "    if (again) {\n");
    g->syntax->locals(o, g, "        ", g->vec2, &s, 1, 0);
    if (g->df_table)
        g->syntax->locals(o, g, "        ", g->uint, &j, 1, 0);
    else
        put_df_accumulate(o, info, g, up);
    sbuf_puts(o, "        f = fd;\n");
    put_too_large(o, g, "        ", up, "QMAX2");
    put_then(o, g);
    sbuf_puts(o, "            f = 3u;\n");
    put_end(o, g, "        ");
    sbuf_printf(o, "        for (i = %sown_start[t]; i < %sown_start[t + 1u]; i++) {\n", px, px);
    snprintf(a, sizeof a, "%sown_plane[i]", px);
    g->syntax->locals(o, g, "            ", g->uint, &(kern_var){"plane", a, 0}, 1, 0);
    snprintf(b, sizeof b, "(redo >> (i - %sown_start[t])) & 1u", px);
    g->syntax->locals(o, g, "            ", g->uint, &(kern_var){"mine", b, 0}, 1, 0);
    if (exact_zeros(info))
        put_keep(o, info, g, "            ", "plane");
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
    snprintf(a, sizeof a, "%stau2_k[plane]", px);
    put_mul(m[0], sizeof m[0], g, a, "M2");
    snprintf(a, sizeof a, "%stau2_f[plane]", px);
    put_mul(m[1], sizeof m[1], g, a, "F");
    snprintf(a, sizeof a, "%s(d.y)", g->fabs);
    put_mul(m[2], sizeof m[2], g, "2.0f", a);
    sbuf_printf(o, "            f |= %sflags(d.x, %s + %s +\n                %s) & mine * %s;\n        }\n    }\n",
                px, m[0], m[1], m[2], exact_zeros(info) ? "keep" : "3u");
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
    put_then(o, g);
    sbuf_printf(o, "            f |= flags[q * %sP + i];\n", up);
    put_end(o, g, "        ");
    sbuf_printf(o, "        cls[pid] = %sclass_of(f);\n"
                   "    }\n",
                info->prefix);
}

/* The kernel body, with the target's names and syntax. */
static void put_body(sbuf *o, const tp_domain *d, const out_info *info, const kern_target *g,
                     const char *up)
{
    if (g->shared_in_body)
        put_shared(o, info, g, up, "    ");
    put_load(o, g, up);
    put_accumulate(o, info, g, up);
    if (info->certified)
        put_scale(o, d, info, g, up);
    put_signs(o, info, g, up);
    if (second_look(info, g))
        put_second_look(o, info, g, up);
    put_combine(o, info, g, up);
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
    fmt_file_name(file, sizeof file, info->prefix, info->suffix);
    snprintf(threads, sizeof threads, "%d", info->sched->threads * info->sched->patches);
    sbuf_init(&banner);
    sbuf_init(&tables);
    sbuf_init(&funcs);
    sbuf_init(&shared);
    sbuf_init(&body);
    fmt_banner(&banner, t, info, file, g->language, g->interface);
    st = put_tables(&tables, t, info, g, up, err);
    put_cross4(&funcs, info, g);
    if (differences(info, g))
        put_diff(&funcs, info, g);
    if (exact_zeros(info))
        put_edge_functions(&funcs, info, g);
    if (second_look(info, g))
        put_df_functions(&funcs, info, g);
    put_classify(&funcs, info, g);
    put_body(&body, &t->dom, info, g, up);
    slots[n++] = (tpl_slot){"BANNER", banner.s};
    if (g->named_kernel)
        slots[n++] = (tpl_slot){"PREFIX", info->prefix};
    slots[n++] = (tpl_slot){"BLOCK_THREADS", threads};
    slots[n++] = (tpl_slot){"TABLES", tables.s};
    slots[n++] = (tpl_slot){"FUNCTIONS", funcs.s};
    slots[n++] = (tpl_slot){"BODY", body.s};
    if (!g->shared_in_body) {
        put_shared(&shared, info, g, up, "");
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
