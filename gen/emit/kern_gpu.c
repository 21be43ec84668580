/* kern_gpu.c: the one GPU kernel emitter, specialized by a target's data table and syntax hooks:
 * fills the template from the parts (kern_gpu_*.c), and the words and options the parts share. */
#include "emit/kern_gpu.h"
#include "emit/fmt.h"
#include "emit/template.h"

#include <stdio.h>

const char *kgpu_opt(const char *s)
{
    return s ? s : "";
}

void kgpu_then(sbuf *o, const kern_target *g)
{
    sbuf_puts(o, g->syntax->braces ? " {\n" : "\n");
}

void kgpu_end(sbuf *o, const kern_target *g, const char *indent)
{
    if (g->syntax->braces)
        sbuf_printf(o, "%s}\n", indent);
}

void kgpu_local(sbuf *o, const kern_target *g, const char *type, const char *name,
                const char *init, int assigned)
{
    kern_var v = {name, init, assigned};
    g->syntax->locals(o, g, "    ", type, &v, 1, 0);
}

int kgpu_second_look(const out_info *info, const kern_target *g)
{
    return info->certified && info->table && g->vec2;
}

int kgpu_second_look_rounds(const out_info *info, const kern_target *g)
{
    return kgpu_second_look(info, g) && !g->df_table;
}

int kgpu_exact_zeros(const out_info *info)
{
    return info->certified && info->rule == OUT_DEGENERATE && !info->bspline;
}

int kgpu_table_local(const out_info *info, const kern_target *g)
{
    return info->table && !info->absolute && (!info->certified || g->slp_cert_u > 0);
}

int kgpu_given(const out_info *info, const kern_target *g)
{
    return info->certified && kgpu_table_local(info, g) &&
           (kgpu_exact_zeros(info) || kgpu_second_look(info, g));
}

int kgpu_differences(const out_info *info, const kern_target *g)
{
    return info->certified && info->table && g->diff && !kgpu_table_local(info, g);
}

void kgpu_shear(char *out, size_t size, const out_info *info, const kern_target *g)
{
    if (info->certified && g->slp_cert_shift)
        snprintf(out, size, "%sshift(%%s, %%s, %%s)", info->prefix);
    else
        snprintf(out, size, "%s", g->slp_fma);
}

char *kgpu_product(char *out, size_t size, const kern_target *g, const char *brk, int n,
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

char *kgpu_mul(char *out, size_t size, const kern_target *g, const char *a, const char *b)
{
    return kgpu_product(out, size, g, " ", 2, (const char *const[]){a, b});
}

char *kgpu_group(char *out, size_t size, const kern_target *g, const char *e)
{
    snprintf(out, size, g->product ? "%s" : "(%s)", e);
    return out;
}

int kgpu_table_kernel(const out_info *info)
{
    return info->table;
}

void kgpu_dispatch(const out_info *info, unsigned *threads, unsigned *patches)
{
    if (kgpu_table_kernel(info)) {
        *patches = (unsigned)info->sched->patches;
        *threads = (unsigned)info->sched->threads * *patches;
    } else {
        *patches = (unsigned)info->group;
        *threads = *patches / (unsigned)(info->lanes ? info->lanes : 1);
    }
}

/* A kernel's parts, each written into its own buffer before the template is filled. */
typedef struct {
    sbuf banner, tables, shared, funcs, body;
    sbuf indexed; /* --kernel indexed: the declarations of its buffers (the slot INDEXED) */
} kernel_parts;

/* Fills g's template with the parts p and the workgroup of kgpu_dispatch. */
static int fill_kernel(sbuf *o, const kernel_parts *p, const out_info *info, const kern_target *g,
                       ptp_error *err)
{
    char threads[16];
    tpl_slot slots[9];
    size_t n = 0;
    unsigned nthreads, npatches;
    kgpu_dispatch(info, &nthreads, &npatches);
    snprintf(threads, sizeof threads, "%u", nthreads);
    slots[n++] = (tpl_slot){"BANNER", p->banner.s};
    if (g->named_kernel)
        slots[n++] = (tpl_slot){"PREFIX", info->prefix};
    slots[n++] = (tpl_slot){"BLOCK_THREADS", threads};
    slots[n++] = (tpl_slot){"TABLES", p->tables.s};
    slots[n++] = (tpl_slot){"FUNCTIONS", p->funcs.s};
    slots[n++] = (tpl_slot){"BODY", p->body.s};
    if (!g->shared_in_body)
        slots[n++] = (tpl_slot){"SHARED", p->shared.s ? p->shared.s : ""};
    if (g->planes_buffer)
        slots[n++] = (tpl_slot){"PLANES_BUFFER", info->planes ? g->planes_buffer : ""};
    slots[n++] = (tpl_slot){"INDEXED", p->indexed.s ? p->indexed.s : ""};
    if (p->banner.failed || p->tables.failed || p->shared.failed || p->funcs.failed ||
        p->body.failed || p->indexed.failed)
        return ptp_fail(err, PTP_ENOMEM, "out of memory writing the kernel");
    return tpl_fill(o, g->template_name, slots, n, err);
}

/* --kernel indexed: the banner's interface, g's with the notes on its buffers; else nothing. */
static void put_interface(sbuf *o, const out_info *info, const kern_target *g)
{
    if (!info->indexed)
        return;
    sbuf_printf(o, "%s * --kernel indexed: point k of patch p is cp[point_index[p*K + k]], cp the vertices.\n%s",
                g->interface, g->indices_note);
    if (info->bspline)
        sbuf_printf(o, "%s * A mask's bits (1 v = 0, 2 u = 1, 4 v = 1, 8 u = 0: Far::PatchParam::GetBoundary())\n"
                       " * name the edges whose phantoms are extrapolated, p0 = 2 p1 - p2, as C's extrapolate.\n",
                    g->boundary_note);
}

/* --kernel indexed: the declarations of its buffers; else nothing. */
static void put_indexed(sbuf *o, const out_info *info, const kern_target *g)
{
    if (!info->indexed)
        return;
    sbuf_printf(o, "%s%s", g->indices_decl, info->bspline ? g->boundary_decl : "");
}

/* The kernel: the paper's table kernel (P threads a patch over the schedule's rounds, shared
 * memory) or the straight-line kernel (one patch an invocation calling classify_patch). */
static int emit_kernel(sbuf *o, const tp_table *t, const out_info *info, const kern_target *g,
                       const char *up, const char *file, ptp_error *err)
{
    int table = kgpu_table_kernel(info), st;
    out_info in = *info;
    kernel_parts p;
    sbuf iface; /* --kernel indexed: the banner's interface */
    sbuf_init(&iface);
    sbuf_init(&p.banner);
    sbuf_init(&p.tables);
    sbuf_init(&p.shared);
    sbuf_init(&p.funcs);
    sbuf_init(&p.body);
    sbuf_init(&p.indexed);
    if (!table)
        in.sched = NULL; /* the banner states the straight-line dispatch */
    put_interface(&iface, info, g);
    fmt_banner(&p.banner, t, &in, file, g->language,
               iface.s ? iface.s : info->lanes ? g->lanes->interface : g->interface);
    p.banner.failed |= iface.failed; /* fill_kernel reports it */
    sbuf_clear(&iface);
    put_indexed(&p.indexed, info, g);
    if (table) {
        st = kgpu_tables(&p.tables, t, info, g, up, err);
        kgpu_functions(&p.funcs, info, g);
        kgpu_body(&p.body, &t->dom, info, g, up);
        if (!g->shared_in_body)
            kgpu_shared(&p.shared, info, g, up, "");
    } else {
        st = kgpu_slp_kernel_parts(&p.tables, &p.funcs, t, info, g, up, err);
        if (info->lanes)
            kgpu_lanes_body(&p.body, info, g, up);
        else
            kgpu_slp_body(&p.body, &t->dom, info, g, up);
    }
    if (!st)
        st = fill_kernel(o, &p, table ? info : &in, g, err);
    sbuf_clear(&p.banner);
    sbuf_clear(&p.tables);
    sbuf_clear(&p.shared);
    sbuf_clear(&p.funcs);
    sbuf_clear(&p.body);
    sbuf_clear(&p.indexed);
    return st;
}

/* --stage function: the banner, the target's preamble and the functions alone. */
static int emit_functions(sbuf *o, const tp_table *t, const out_info *info, const kern_target *g,
                          const char *file, ptp_error *err)
{
    out_info in = *info;
    sbuf note;
    int st;
    in.sched = NULL;
    in.group = 0; /* no workgroup */
    sbuf_init(&note);
    sbuf_printf(&note, " * Functions for any shader stage (compute, tessellation control or hull, mesh, task):\n"
                       " * %sclassify_patch(cp, eye%s) returns the class of the patch cp[0..K-1];\n"
                       " * %svalues(cp, eye%s, d) writes the value d[P] of each plane.\n%s",
                info->prefix, g->slp_zero ? ", zero" : "", info->prefix, g->slp_zero ? ", zero" : "",
                kgpu_opt(g->slp_note));
    fmt_banner(o, t, &in, file, g->slp_language, note.s);
    sbuf_puts(o, kgpu_opt(g->slp_preamble));
    st = kgpu_slp_functions(o, t, info, g, err);
    if (note.failed)
        st = st ? st : ptp_fail(err, PTP_ENOMEM, "out of memory writing the functions");
    sbuf_clear(&note);
    return st;
}

int kern_emit_gpu(sbuf *o, const tp_table *t, const out_info *info, const kern_target *g,
                  ptp_error *err)
{
    char up[64], file[96];
    fmt_upper(up, sizeof up, info->prefix);
    fmt_file_name(file, sizeof file, info->prefix, info->functions ? g->slp_suffix : info->suffix);
    if (info->functions)
        return emit_functions(o, t, info, g, file, err);
    return emit_kernel(o, t, info, g, up, file, err);
}
