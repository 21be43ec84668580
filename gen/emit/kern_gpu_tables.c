/* kern_gpu_tables.c: the GPU kernel's constants and constant tables: the planes each thread
 * owns and, per round, the slots of the P threads; the certified and second look tables aside. */
#include "emit/kern_gpu.h"
#include "emit/fmt.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The separator before value i of a table with per_line values to a line. */
static const char *table_sep(long i, int per_line)
{
    return i == 0 ? "\n    " : i % per_line ? ", " : ",\n    ";
}

void kgpu_uint_table(sbuf *o, const kern_target *g, const char *prefix, const char *name,
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

void kgpu_float_table(sbuf *o, const kern_target *g, const char *prefix, const char *name,
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
    unsigned threads, patches;
    kgpu_dispatch(info, &threads, &patches); /* the workgroup the host header states */
    put_uint_constant(o, g, up, "P", P, "threads per patch");
    put_uint_constant(o, g, up, "Q", (long)patches, "patches per workgroup");
    put_uint_constant(o, g, up, "K", t->dom.npoints, "control points per patch");
    put_uint_constant(o, g, up, "L", t->dom.nplanes, "control planes per patch");
    sbuf_printf(o, "/* %d rounds: the largest number of terms of one thread. */\n\n", s->rounds);
    for (th = 0; th <= P; th++) {
        v[th] = (unsigned long)k;
        for (p = 0; th < P && p < t->dom.nplanes; p++)
            k += s->owner[p] == th;
    }
    sbuf_puts(o, "/* Thread t owns the planes own_plane[own_start[t] .. own_start[t+1]-1]. */\n");
    kgpu_uint_table(o, g, info->prefix, "own_start", v, P + 1, 16, 0);
    for (th = 0, k = 0; th < P; th++)
        for (p = 0; p < t->dom.nplanes; p++)
            if (s->owner[p] == th)
                v[k++] = (unsigned long)p;
    kgpu_uint_table(o, g, info->prefix, "own_plane", v, t->dom.nplanes, 16, 0);
    sbuf_puts(o, "\n");
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
    kgpu_uint_table(o, g, info->prefix, name, v, P, 8, 1);
    snprintf(name, sizeof name, "kl%d", r);
    kgpu_uint_table(o, g, info->prefix, name, v + P, P, 8, 1);
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
    if (kgpu_second_look_rounds(info, g))
        kgpu_df_weight_lo(o, t, info, g, r);
    sbuf_puts(o, "\n");
}

int kgpu_tables(sbuf *o, const tp_table *t, const out_info *info, const kern_target *g,
                const char *up, ptp_error *err)
{
    int P = info->sched->threads, r, st = PTP_OK;
    size_t n = (size_t)t->dom.nplanes + (size_t)P + 2 * t->nterms + 2;
    unsigned long *v = malloc(n * sizeof *v); /* room for put_owners, put_round, kgpu_df_terms */
    if (!v)
        return ptp_fail(err, PTP_ENOMEM, "out of memory writing tables");
    put_owners(o, t, info, g, up, v);
    for (r = 0; r < info->sched->rounds; r++)
        put_round(o, t, info, g, r, v);
    if (kgpu_second_look(info, g) && g->df_table)
        st = kgpu_df_terms(o, t, info, g, v, err);
    free(v);
    return !st && info->certified ? kgpu_cert_tables(o, t, info, g, up, err) : st;
}
