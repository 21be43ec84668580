/* kern_gpu_slp.c: the straight-line program on the GPU targets: the functions classify_patch and
 * values for any shader stage, and the compute kernel that runs one patch an invocation on them. */
#include "emit/kern_gpu.h"
#include "emit/slp_text.h"
#include "plan/phantom.h"

#include <stdio.h>
#include <string.h>

/* What the functions' plane_end hooks read: the target, the options and the function written. */
typedef struct {
    const kern_target *g;
    const out_info *info;
    int values; /* values (else classify_patch) */
} fn_ctx;

/* Coordinate c of point k: cp[k].x. */
static void fn_load(char *out, size_t size, const slpt_writer *w, int k, int c)
{
    (void)w;
    snprintf(out, size, "cp[%d].%c", k, "xyzw"[c]);
}

/* 1 / x, 0 where x is 0, in the target's select. */
static void fn_recip0(char *out, size_t size, const slpt_writer *w, const char *x)
{
    const fn_ctx *c = w->ctx;
    char cond[160], inv[160];
    snprintf(cond, sizeof cond, "%s != 0.0f", x);
    snprintf(inv, sizeof inv, "1.0f / %s", x);
    c->g->syntax->select(out, size, cond, inv, "0.0f");
}

/* After each plane: values stores it at true scale; classify_patch folds it into the rule's
 * flags (strict lt, gt: every value so far < 0, > 0; degenerate: some value < 0, > 0, NaN). */
static void fn_plane_end(slpt_writer *w, int plane, int first)
{
    const fn_ctx *x = w->ctx;
    const kern_target *g = x->g;
    char d[32], k[48], e[160], nan[96];
    if (x->values) {
        snprintf(d, sizeof d, g->slp_d, plane);
        if (slpt_inverse_scale(k, sizeof k, w->p, plane))
            sbuf_printf(w->o, "    %s = %s;\n", d, kgpu_mul(e, sizeof e, g, "v", k));
        else
            sbuf_printf(w->o, "    %s = v;\n", d);
        return;
    }
    if (x->info->certified)
        kgpu_slp_cert_plane(w->o, w->p, x->info, g, plane);
    if (x->info->rule == OUT_STRICT) {
        if (first)
            sbuf_printf(w->o, "    lt = v < 0.0f;\n    gt = v > 0.0f; /* plane %d */\n", plane);
        else
            sbuf_printf(w->o, "    lt = lt && v < 0.0f;\n    gt = gt && v > 0.0f; /* plane %d */\n", plane);
        return;
    }
    snprintf(nan, sizeof nan, g->syntax->isnan, "v");
    if (first)
        sbuf_printf(w->o, "    lt = v < 0.0f;\n    gt = v > 0.0f;\n    nan = %s; /* plane %d */\n", nan,
                    plane);
    else
        sbuf_printf(w->o, "    lt = lt || v < 0.0f;\n    gt = gt || v > 0.0f;\n"
                          "    nan = nan || %s; /* plane %d */\n", nan, plane);
}

/* The eye's components the program reads (e2 in clip space), u and v, and the flags (with
 * --kernel lanes all vectors, so that every fma has operands of one type). */
static void put_slp_locals(sbuf *o, const out_info *info, const kern_target *g, int values)
{
    const char *real = info->lanes ? g->lanes->real : g->real;
    static const char *const comp[4] = {"eye.x", "eye.y", "eye.z", "eye.w"};
    kern_var e[4] = {{"e0", comp[0], 0}, {"e1", comp[1], 0}, {"e2", comp[2], 0}, {"e3", comp[3], 0}};
    kern_var uv[2] = {{"u", NULL, 1}, {"v", NULL, 1}};
    kern_var f[3] = {{"lt", NULL, 1}, {"gt", NULL, 1}, {"nan", NULL, 1}};
    if (info->space == OUT_WORLD)
        g->syntax->locals(o, g, "    ", real, e, 4, 1);
    else
        g->syntax->locals(o, g, "    ", real, e + 2, 1, 1);
    g->syntax->locals(o, g, "    ", real, uv, 2, 1);
    if (!values)
        g->syntax->locals(o, g, "    ", info->lanes ? g->lanes->flag : "bool", f,
                          info->rule == OUT_STRICT ? 2 : 3, 0);
}

/* The class from the flags: strict back (1) iff lt, front (0) iff gt; degenerate silhouette (2)
 * on NaN, back iff no value > 0, front iff none < 0; else silhouette; certified, silhouette
 * unless every value clears its bound or, with the second look, the L planes whose bounds do
 * not clear are certainly of the class's sign in double-float. */
static void put_slp_return(sbuf *o, const out_info *info, const kern_target *g, int L)
{
    char a[128], b[192], c[256];
    if (info->rule == OUT_STRICT) {
        g->syntax->select(a, sizeof a, "gt", "0u", "2u");
        g->syntax->select(b, sizeof b, "lt", "1u", a);
    } else {
        g->syntax->select(a, sizeof a, "lt", "2u", "0u");
        g->syntax->select(c, sizeof c, "gt", a, "1u");
        g->syntax->select(b, sizeof b, "nan", "2u", c);
    }
    if (kgpu_slp_look(info, g)) { /* the plain class; again where bounds do not clear */
        int k, n = kgpu_redo_words(L);
        kgpu_local(o, g, g->uint, "c", b, 1);
        sbuf_puts(o, "    if (c != 2u && (");
        for (k = 0; k < n; k++)
            sbuf_printf(o, "%sredo[%d]", k ? " | " : "", k);
        sbuf_puts(o, ") != 0u)");
        kgpu_then(o, g);
        sbuf_printf(o, "        c = %ssecond_look(cp, eye, c, redo);\n", info->prefix);
        kgpu_end(o, g, "    ");
        sbuf_puts(o, "    return c;\n");
        return;
    }
    if (info->certified) {
        snprintf(c, sizeof c, "(%s)", b);
        g->syntax->select(b, sizeof b, "clear", c, "2u");
    }
    sbuf_printf(o, "    return %s;\n", b);
}

/* One function: classify_patch (values 0) or values, its head, locals, program and end; with
 * --kernel lanes classify_lanes, classify_patch over vectors of patches. */
static int put_slp_function(sbuf *o, const tp_table *t, const out_info *info,
                            const kern_target *g, int values, ptp_error *err)
{
    char name[128], mul[160], fma[96], shift[96];
    slpt_syntax syn = {"    ", info->lanes ? g->lanes->decl : g->slp_decl, 0, mul, fma, fma, shift,
                       fn_recip0, fn_load, fn_plane_end};
    fn_ctx ctx = {g, info, values};
    slpt_writer w;
    int st;
    if (g->slp_mul)
        snprintf(mul, sizeof mul, g->slp_mul, info->prefix);
    else
        snprintf(mul, sizeof mul, "%s", g->mul);
    snprintf(fma, sizeof fma, "%s", g->slp_fma);
    kgpu_shear(shift, sizeof shift, info, g);
    snprintf(name, sizeof name, "%s%s", info->prefix,
             values ? "values" : info->lanes ? "classify_lanes" : "classify_patch");
    if (values)
        sbuf_printf(o, "/* d[P] = the value of plane P of the patch cp seen from eye, at true scale. */\n");
    else
        sbuf_printf(o, "/* The class of the patch cp%s seen from eye: 0 front-facing, 1 back-facing, 2 silhouette. */\n",
                    info->lanes ? " (each lane of each coordinate one patch's)" : "");
    if (info->lanes)
        sbuf_printf(o, g->lanes->classify, name, info->prefix, t->dom.npoints);
    else
        sbuf_printf(o, values ? g->slp_values : g->slp_classify, name, t->dom.npoints, t->dom.nplanes);
    sbuf_puts(o, "\n");
    put_slp_locals(o, info, g, values);
    if ((st = slpt_init(&w, o, info->slp, &syn, info->space == OUT_WORLD, &ctx, err)))
        return st;
    slpt_frame(&w);
    if (!values && info->certified)
        st = kgpu_slp_cert_head(&w, &t->dom, info, g, err);
    if (!st)
        st = slpt_program(&w, err);
    slpt_clear(&w);
    if (!values)
        put_slp_return(o, info, g, t->dom.nplanes);
    sbuf_puts(o, "}\n\n");
    return st;
}

int kgpu_slp_functions(sbuf *o, const tp_table *t, const out_info *info, const kern_target *g,
                       ptp_error *err)
{
    int st;
    if (g->slp_helpers)
        sbuf_printf(o, g->slp_helpers, info->prefix);
    if (info->certified && g->slp_cert_shift)
        sbuf_printf(o, g->slp_cert_shift, info->prefix);
    if (kgpu_slp_look(info, g) && (st = kgpu_slp_look_functions(o, t, info, g, err)))
        return st;
    st = put_slp_function(o, t, info, g, 0, err);
    return st ? st : put_slp_function(o, t, info, g, 1, err);
}

/* The constants P (1), Q, K and L of the compute kernel; with --kernel lanes LANES (patches a
 * work-item) in P's place. */
static void put_slp_constants(sbuf *o, const tp_table *t, const out_info *info,
                              const kern_target *g, const char *up)
{
    const char *what[4] = {"threads per patch", "patches per workgroup",
                           "control points per patch", "control planes per patch"};
    unsigned threads, patches;
    long v[4] = {1, 0, t->dom.npoints, t->dom.nplanes};
    char name[80], lit[32];
    int i;
    kgpu_dispatch(info, &threads, &patches); /* the workgroup the host header states */
    v[1] = (long)patches;
    if (info->lanes) {
        what[0] = "patches per work-item, one a lane";
        v[0] = info->lanes;
    }
    for (i = 0; i < 4; i++) {
        snprintf(name, sizeof name, i || !info->lanes ? "%s%c" : "%sLANES", up, "PQKL"[i]);
        snprintf(lit, sizeof lit, "%ldu", v[i]);
        g->syntax->constant(o, g, name, g->uint, lit, what[i]);
    }
    sbuf_puts(o, "\n");
}

/* --kernel indexed --basis bspline: the phantoms of the edges whose bits the patch's mask sets,
 * p0 = 2 p1 - p2 per component, bit 0 to 3 in turn as the C header's extrapolate. */
static void put_phantoms(sbuf *o, const out_info *info, const kern_target *g)
{
    int q[4][4][3], b, k, c;
    char p1[32], e[96];
    phantom_table(q, info->slp);
    kgpu_local(o, g, g->uint, "mask", "boundary_mask[pid]", 0);
    for (b = 0; b < 4; b++) {
        sbuf_printf(o, "    if ((mask & %uu) != 0u) {\n", 1u << b);
        for (k = 0; k < 4; k++)
            for (c = 0; c < 4; c++) {
                snprintf(p1, sizeof p1, "p[%d].%c", q[b][k][1], "xyzw"[c]);
                sbuf_printf(o, "        p[%d].%c = %s - p[%d].%c;\n", q[b][k][0], "xyzw"[c],
                            kgpu_mul(e, sizeof e, g, "2.0f", p1), q[b][k][2], "xyzw"[c]);
            }
        sbuf_puts(o, "    }\n");
    }
}

/* Copies patch pid's K points into p: from cp[pid*K + n], or (--kernel indexed) from
 * cp[point_index[pid*K + n]] with, for B-spline input, the boundary's phantoms. */
static void put_gather(sbuf *o, const tp_domain *dom, const out_info *info,
                       const kern_target *g, const char *k)
{
    int n;
    for (n = 0; n < dom->npoints; n++) /* unrolled: PoCL keeps a loop's array in memory */
        if (info->indexed)
            sbuf_printf(o, "    p[%d] = cp[point_index[pid * %s + %du]];\n", n, k, n);
        else
            sbuf_printf(o, "    p[%d] = cp[pid * %s + %du];\n", n, k, n);
    if (info->indexed && info->bspline)
        put_phantoms(o, info, g);
}

void kgpu_slp_body(sbuf *o, const tp_domain *dom, const out_info *info, const kern_target *g,
                   const char *up)
{
    const char *px = info->prefix, *in = g->planes_buffer ? "    " : "        ";
    char pid[256], arg[64], k[80], l[80];
    kern_var i = {"i", NULL, 1};
    snprintf(pid, sizeof pid, "(%s * %s + %s) * %sQ + %s", g->group_y, g->groups_x, g->group_x, up,
             g->local_id);
    snprintf(k, sizeof k, "%sK", up);
    snprintf(l, sizeof l, "%sL", up);
    kgpu_local(o, g, g->uint, "pid", pid, 0);
    if (info->planes)
        g->syntax->locals(o, g, "    ", g->uint, &i, 1, 0);
    g->syntax->array(o, g, "    ", g->vec4, "p", k);
    sbuf_puts(o, "    if (pid >= patch_count)");
    kgpu_then(o, g);
    sbuf_puts(o, "        return;\n");
    kgpu_end(o, g, "    ");
    put_gather(o, dom, info, g, k);
    sbuf_printf(o, "    cls[pid] = %sclassify_patch(p, eye%s);\n", px, kgpu_opt(g->slp_zero));
    if (!info->planes)
        return;
    g->syntax->array(o, g, "    ", g->real, "d", l);
    snprintf(arg, sizeof arg, g->slp_ref, "d");
    sbuf_printf(o, "    %svalues(p, eye%s, %s);\n", px, kgpu_opt(g->slp_zero), arg);
    if (!g->planes_buffer) { /* a kernel parameter that may be null */
        sbuf_puts(o, "    if (planes)");
        kgpu_then(o, g);
    }
    sbuf_printf(o, "%sfor (i = 0u; i < %s; i++)", in, l);
    kgpu_then(o, g);
    sbuf_printf(o, "%s    planes[pid * %s + i] = d[i];\n", in, l);
    kgpu_end(o, g, in);
    if (!g->planes_buffer)
        kgpu_end(o, g, "    ");
}

int kgpu_slp_kernel_parts(sbuf *tables, sbuf *funcs, const tp_table *t, const out_info *info,
                          const kern_target *g, const char *up, ptp_error *err)
{
    put_slp_constants(tables, t, info, g, up);
    if (!info->lanes)
        return kgpu_slp_functions(funcs, t, info, g, err);
    sbuf_printf(funcs, g->lanes->point, info->prefix);
    return put_slp_function(funcs, t, info, g, 0, err);
}

void kgpu_lanes_body(sbuf *o, const out_info *info, const kern_target *g, const char *up)
{
    const char *s;
    for (s = g->lanes->body; *s; s++)
        if (*s == '$')
            sbuf_puts(o, info->prefix);
        else if (*s == '@')
            sbuf_puts(o, up);
        else
            sbuf_printf(o, "%c", *s);
}
