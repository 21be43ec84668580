/* kern_gpu_slp_cert.c: --certified straight-line functions on the GPU targets: the patch's
 * magnitudes and size guard, the collapsed edges, each plane's bound (docs/errors.md) and the
 * second look in double-float. */
#include "emit/kern_gpu.h"
#include "emit/fmt.h"

#include <stdio.h>
#include <string.h>

const char kern_precise_shift[] =
    "/* o * w + x, --certified: the product exact (Dekker's two-product on Veltkamp's split, precise:\n"
    " * as written), so that the result is rounded about once relative to itself, where the\n"
    " * language may round fma's product apart (docs/errors.md: The straight-line program on the\n"
    " * GPU). */\n"
    "float %sshift(float o, float w, float x)\n{\n"
    "    precise float p = o * w, co = 4097.0f * o, cw = 4097.0f * w;\n"
    "    precise float oh = co - (co - o), wh = cw - (cw - w);\n"
    "    precise float ol = o - oh, wl = w - wh;\n"
    "    precise float lo = ((oh * wh - p) + oh * wl + ol * wh) + ol * wl;\n"
    "    precise float s = (x + p) + lo;\n"
    "    return s;\n}\n\n";

/* Writes to out (SLPT_EXPR bytes) e as a factor: kgpu_group's, where e has an operator. */
static char *factor(char *out, const kern_target *g, const char *e)
{
    if (strpbrk(e, " +-*/"))
        return kgpu_group(out, SLPT_EXPR, g, e);
    if (snprintf(out, SLPT_EXPR, "%s", e) < 0)
        out[0] = '\0';
    return out;
}

/* Writes to out (SLPT_EXPR bytes) the product of a and b in the target's product (CUDA's is
 * never contracted); returns out. */
static char *prod(char *out, const kern_target *g, const char *a, const char *b)
{
    char x[SLPT_EXPR], y[SLPT_EXPR];
    return kgpu_mul(out, SLPT_EXPR, g, factor(x, g, a), factor(y, g, b));
}

/* Writes to out (SLPT_EXPR bytes) the larger of a and b; returns out. */
static char *larger(char *out, const kern_target *g, const char *a, const char *b)
{
    if (snprintf(out, SLPT_EXPR, "%s(%s, %s)", g->fmax, a, b) < 0)
        out[0] = '\0';
    return out;
}

/* Rc = the largest |coordinate c| of the points as the program reads them (Bezier input: the
 * command line leaves --certified B-spline and v-major input to C). */
static void put_magnitudes(slpt_writer *w, const tp_domain *d, const out_info *info,
                           const kern_target *g)
{
    char name[16], v[SLPT_EXPR];
    int world = info->space == OUT_WORLD, k, c;
    for (c = 0; c < 4; c++)
        if (world || c != 2) {
            snprintf(name, sizeof name, "R%c", "xyzw"[c]);
            kgpu_local(w->o, g, g->real, name, "0.0f", 1);
        }
    for (k = 0; k < d->npoints; k++)
        for (c = 0; c < 4; c++)
            if (world || c != 2) {
                slpt_coordinate(v, w, k, c);
                sbuf_printf(w->o, "    R%c = %s(R%c, %s(%s));\n", "xyzw"[c], g->fmax, "xyzw"[c],
                            g->fabs, v);
            }
}

/* E, R and ER3 >= every monomial's magnitude in world space: |e_i| times the other three
 * coordinates' Rc, the eye the program reads (local: l0..l2). */
static void put_world_scale(slpt_writer *w, const out_info *info, const kern_target *g)
{
    const char *l = info->slp->local ? "l" : "e";
    char e[32], name[16], a[SLPT_EXPR], b[SLPT_EXPR], c[SLPT_EXPR], d[SLPT_EXPR], s[SLPT_EXPR];
    int i;
    for (i = 0; i < 4; i++) {
        snprintf(e, sizeof e, "%s(%s%d)", g->fabs, i < 3 ? l : "e", i);
        snprintf(name, sizeof name, "E%d", i);
        kgpu_local(w->o, g, g->real, name, e, 0);
    }
    larger(s, g, larger(a, g, "E0", "E1"), larger(b, g, "E2", "E3"));
    kgpu_local(w->o, g, g->real, "E", s, 0);
    larger(s, g, larger(a, g, "Rx", "Ry"), larger(b, g, "Rz", "Rw"));
    kgpu_local(w->o, g, g->real, "R", s, 0);
    larger(c, g, prod(a, g, "E0", "Ry"), prod(b, g, "E1", "Rx"));
    prod(d, g, c, prod(a, g, "Rz", "Rw"));
    larger(c, g, prod(a, g, "E2", "Rw"), prod(b, g, "E3", "Rz"));
    prod(a, g, c, prod(b, g, "Rx", "Ry"));
    kgpu_local(w->o, g, g->real, "ER3", larger(s, g, d, a), 0);
}

int kgpu_redo_words(int L)
{
    return (L + 31) / 32;
}

/* E (the eye's largest |component|), R, ER3 >= every monomial's magnitude (clip: E Rx Ry Rw),
 * F (the underflow term with the largest K2) and clear: the patch small enough for the bound;
 * with the second look, redo instead: every plane's bit set unless the patch is small enough. */
static void put_scale(slpt_writer *w, const out_info *info, const kern_target *g)
{
    const cert_bounds *cb = &info->slp->cert;
    char s[SLPT_EXPR], a[SLPT_EXPR], b[SLPT_EXPR], k[48];
    float k2 = 0;
    int i;
    for (i = 0; i < cb->nplanes; i++)
        k2 = cb->k2[i] > k2 ? cb->k2[i] : k2;
    if (info->space == OUT_WORLD) {
        put_world_scale(w, info, g);
    } else {
        snprintf(s, sizeof s, "%s(e2)", g->fabs);
        kgpu_local(w->o, g, g->real, "E", s, 0);
        kgpu_local(w->o, g, g->real, "R", larger(s, g, larger(a, g, "Rx", "Ry"), "Rw"), 0);
        prod(s, g, "E", prod(b, g, prod(a, g, "Rx", "Ry"), "Rw"));
        kgpu_local(w->o, g, g->real, "ER3", s, 0);
    }
    kgpu_local(w->o, g, g->real, "R1", "1.0f + R", 0);
    kgpu_local(w->o, g, g->real, "R3", prod(s, g, prod(a, g, "R", "R"), "R"), 0);
    snprintf(k, sizeof k, "%.9ef", (double)k2);
    prod(b, g, prod(a, g, "R1", "R1"), "R1");
    kgpu_local(w->o, g, g->real, "F", prod(s, g, k, prod(a, g, b, "1.0f + E")), 0);
    snprintf(s, sizeof s, "%s < %.9ef", prod(a, g, larger(b, g, "E", "1.0f"), "R3"), (double)cb->q_max);
    if (!kgpu_slp_look(info, g)) {
        kgpu_local(w->o, g, "bool", "clear", s, 1);
        return;
    }
    snprintf(k, sizeof k, "%d", kgpu_redo_words(cb->nplanes));
    g->syntax->array(w->o, g, "    ", g->uint, "redo", k);
    g->syntax->select(a, sizeof a, s, "0u", "0xffffffffu");
    for (i = 0; i < kgpu_redo_words(cb->nplanes); i++)
        sbuf_printf(w->o, "    redo[%d] = %s;\n", i, a);
}

/* Appends to s "a == b" of coordinate c of input points a and b, or a's finiteness (b < 0). */
static void put_compare(sbuf *s, const char *sep, int a, int b, int c)
{
    if (b < 0)
        sbuf_printf(s, "%scp[%d].%c - cp[%d].%c == 0.0f", sep, a, "xyzw"[c], a, "xyzw"[c]);
    else
        sbuf_printf(s, "%scp[%d].%c == cp[%d].%c", sep, a, "xyzw"[c], b, "xyzw"[c]);
}

/* With exact zeros: fin (every coordinate read finite) and col<e>, boundary edge e collapsed:
 * its points equal as given (so the planes it zeros are exactly 0, docs/errors.md). */
static int put_collapsed(slpt_writer *w, const tp_domain *d, const out_info *info,
                         const kern_target *g, ptp_error *err)
{
    int world = info->space == OUT_WORLD, e, k, c, x, n, failed, p[TP_EDGE_POINTS_MAX];
    char name[16];
    sbuf s;
    sbuf_init(&s);
    for (k = 0, n = 0; k < d->npoints; k++)
        for (c = 0; c < 4; c++)
            if (world || c != 2)
                put_compare(&s, n++ ? " && " : "", k, -1, c);
    kgpu_local(w->o, g, "bool", "fin", s.s, 0);
    failed = s.failed;
    for (e = 0; e < tp_domain_edges(d); e++) {
        sbuf_clear(&s);
        sbuf_puts(&s, "fin");
        n = tp_domain_edge_points(p, d, e);
        for (x = 1; x < n; x++)
            for (c = 0; c < 4; c++)
                if (world || c != 2)
                    put_compare(&s, " && ", p[x], p[0], c);
        snprintf(name, sizeof name, "col%d", e);
        kgpu_local(w->o, g, "bool", name, s.s, 0);
        failed |= s.failed;
    }
    sbuf_clear(&s);
    return failed ? ptp_fail(err, PTP_ENOMEM, "out of memory writing the kernel") : PTP_OK;
}

int kgpu_slp_cert_head(slpt_writer *w, const tp_domain *d, const out_info *info,
                       const kern_target *g, ptp_error *err)
{
    sbuf_puts(w->o, "    /* Certified: the patch's magnitudes bound every value's rounding error. */\n");
    put_magnitudes(w, d, info, g);
    put_scale(w, info, g);
    return kgpu_exact_zeros(info) ? put_collapsed(w, d, info, g, err) : PTP_OK;
}

void kgpu_slp_cert_plane(sbuf *o, const slp_prog *p, const out_info *info, const kern_target *g,
                         int plane)
{
    unsigned zero = kgpu_exact_zeros(info) ? p->zero[plane] : 0;
    char k[32], t[128], bound[192];
    int e;
    snprintf(k, sizeof k, "%.9ef", -(double)info->slp->cert.k[plane]);
    snprintf(t, sizeof t, "%s(v)", g->fabs);
    snprintf(bound, sizeof bound, g->slp_fma, k, "ER3", t);
    if (kgpu_slp_look(info, g)) /* C's ?: in every target that has the second look */
        sbuf_printf(o, "    redo[%d] |= (", plane >> 5);
    else
        sbuf_puts(o, "    clear = clear && (");
    for (e = 0; e < 8; e++)
        if (zero >> e & 1)
            sbuf_printf(o, "col%d || ", e);
    if (kgpu_slp_look(info, g))
        sbuf_printf(o, "%s > F) ? 0u : %uu;\n", bound, 1u << (plane & 31));
    else
        sbuf_printf(o, "%s > F);\n", bound);
}

int kgpu_slp_look(const out_info *info, const kern_target *g)
{
    return info->certified && !info->table && g->slp_look;
}

/* The second look's loop over the planes of redo: each one's terms in double-float into s, its
 * value d (clip space: times eye.z), its certified flags into f; silhouette once both flags are
 * set. */
static void put_look_planes(sbuf *o, const tp_domain *d, const out_info *info, const kern_target *g)
{
    const char *px = info->prefix;
    char zero[96], e[160], fl[512], start[96], end[96], pt[3][256];
    const char *pp[3] = {pt[0], pt[1], pt[2]};
    kern_var s = {"s", zero, 1};
    snprintf(zero, sizeof zero, g->vec2_make, "0.0f", "0.0f");
    snprintf(start, sizeof start, "%sdstart[i]", px);
    snprintf(end, sizeof end, "%sdstart[i + 1u]", px);
    snprintf(pt[0], sizeof pt[0], "cp[%sdj[j]]", px);
    snprintf(pt[1], sizeof pt[1], "cp[%sdkl[j] & 0xffffu]", px);
    snprintf(pt[2], sizeof pt[2], "cp[%sdkl[j] >> 16]", px);
    sbuf_printf(o, "    for (i = 0u; i < %du; i++) {\n"
                   "        if (((redo[i >> 5u] >> (i & 31u)) & 1u) == 0u)\n"
                   "            continue;\n", d->nplanes);
    if (kgpu_exact_zeros(info))
        kgpu_keep(o, info, g, "        ", "i");
    g->syntax->locals(o, g, "        ", g->vec2, &s, 1, 0);
    kgpu_df_term_sum(o, info, g, "        ", start, end, pp);
    snprintf(e, sizeof e, "%sdf_mul_f(s, eye.z)", px);
    g->syntax->locals(o, g, "        ", g->vec2,
                      &(kern_var){"d", info->space == OUT_CLIP ? e : "s", 0}, 1, 0);
    sbuf_printf(o, "        f |= %s%s;\n        if (f == 3u)", kgpu_df_flags(fl, sizeof fl, info, g, "i"),
                kgpu_exact_zeros(info) ? " & keep" : "");
    kgpu_then(o, g);
    sbuf_puts(o, "            break; /* silhouette */\n");
    kgpu_end(o, g, "        ");
    sbuf_puts(o, "    }\n");
}

int kgpu_slp_look_functions(sbuf *o, const tp_table *t, const out_info *info,
                            const kern_target *g, ptp_error *err)
{
    /* the planes not in redo cleared their bounds with c's sign: f starts not certainly of the
     * other sign */
    kern_var v[3] = {{"i", NULL, 1}, {"j", NULL, 1}, {"f", "1u + c", 1}};
    char up[64], name[128];
    int st;
    fmt_upper(up, sizeof up, info->prefix);
    if ((st = kgpu_df_plane_terms(o, t, info, g, err)))
        return st;
    if (kgpu_exact_zeros(info) && (st = kgpu_zero_table(o, t, info, g, err)))
        return st;
    kgpu_look_bounds(o, info, g, up, &info->slp->look);
    kgpu_look_functions(o, info, g);
    snprintf(name, sizeof name, "%ssecond_look", info->prefix);
    sbuf_puts(o, "/* classify_patch's second look: c (back 1 or front 0) where the planes of redo (bit P % 32\n"
                 " * of redo[P / 32]) are certainly of its sign in double-float, each against its own bound,\n"
                 " * else silhouette (2). The other planes' float bounds cleared with c's sign. */\n");
    sbuf_printf(o, g->slp_look, name, t->dom.npoints, kgpu_redo_words(t->dom.nplanes));
    sbuf_puts(o, "\n");
    g->syntax->locals(o, g, "    ", g->uint, v, 3, 0);
    kgpu_cert_look_scale(o, &t->dom, info, g, up);
    put_look_planes(o, &t->dom, info, g);
    sbuf_printf(o, "    return %sclass_of(f);\n}\n\n", info->prefix);
    return PTP_OK;
}
