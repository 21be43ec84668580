/* kern_gpu_cert.c: --certified in the GPU kernel: the bounds' tables, the patch's scale (its
 * largest coordinates and monomials) and each plane's certified flags. */
#include "plan/cert.h"
#include "emit/kern_gpu.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Appends the constant <UP>QMAX<n> and the tables tau<n>_k, tau<n>_f of cb (n: "" or "2"), after
 * the comment what, which ends with "for max(E, 1) R^3 < ". */
static void put_bounds(sbuf *o, const out_info *info, const kern_target *g, const char *up,
                       const cert_bounds *cb, const char *n, const char *what)
{
    char name[128], lit[48];
    sbuf_printf(o, "%s%sQMAX%s. */\n", what, up, n);
    snprintf(name, sizeof name, "%sQMAX%s", up, n);
    snprintf(lit, sizeof lit, "%.9gf", (double)cb->q_max);
    g->syntax->constant(o, g, name, g->real, lit, NULL);
    snprintf(name, sizeof name, "tau%s_k", n);
    kgpu_float_table(o, g, info->prefix, name, cb->k, cb->nplanes);
    snprintf(name, sizeof name, "tau%s_f", n);
    kgpu_float_table(o, g, info->prefix, name, cb->k2, cb->nplanes);
    sbuf_puts(o, "\n");
}

/* With exact zeros, the table zero: per plane the boundary edges (bit e) on which every term has
 * two points, so that collapsing any of them makes the plane exactly 0. */
int kgpu_zero_table(sbuf *o, const tp_table *t, const out_info *info, const kern_target *g,
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
    kgpu_uint_table(o, g, info->prefix, "zero", z, t->dom.nplanes, 16, 0);
    sbuf_puts(o, "\n");
    free(z);
    return PTP_OK;
}

void kgpu_look_bounds(sbuf *o, const out_info *info, const kern_target *g, const char *up,
                      const cert_bounds *cb)
{
    put_bounds(o, info, g, up, cb, "2",
               "/* Second look, in double-float from the points: |hi + lo - exact| <= tau2_k[P] * M2\n"
               " * + tau2_f[P] * (1 + R)^3 (1 + E), M2 from the largest |coordinates|, for\n"
               " * max(E, 1) R^3 < ");
}

int kgpu_cert_tables(sbuf *o, const tp_table *t, const out_info *info, const kern_target *g,
                     const char *up, ptp_error *err)
{
    cert_bounds cb;
    int st = cert_gpu(&cb, t, info->space == OUT_WORLD, g->unit_roundoff, kgpu_differences(info, g),
                      kgpu_table_local(info, g), err);
    if (st)
        return st;
    put_bounds(o, info, g, up, &cb, "",
               "/* Certified: |d_P - exact| <= tau_k[P] * M + tau_f[P] * (1 + R)^3 (1 + E), M from the\n"
               " * patch's largest |coordinates| and the eye, R the largest of them, E the eye's largest\n"
               " * |component|; for max(E, 1) R^3 < ");
    cert_clear(&cb);
    if (kgpu_exact_zeros(info) && (st = kgpu_zero_table(o, t, info, g, err)))
        return st;
    if (!g->vec2)
        return PTP_OK;
    if ((st = cert_table_df(&cb, t, info->space == OUT_WORLD, err)))
        return st;
    kgpu_look_bounds(o, info, g, up, &cb);
    cert_clear(&cb);
    return PTP_OK;
}

/* With exact zeros, col: bit e where boundary edge e of d is collapsed, its points bitwise equal
 * and every coordinate of the patch finite (fin); point k is pt (a format of k), which may read
 * the local base, declared from base where base is not NULL. */
static void put_collapsed(sbuf *o, const tp_domain *d, const out_info *info, const kern_target *g,
                          const char *pt, const char *base)
{
    char bit[16], a[64], b[64];
    int e, x, n, k[TP_EDGE_POINTS_MAX];
    sbuf_puts(o, "    /* Degenerate rule: bit e of col where boundary edge e is collapsed (its points bitwise\n"
                 "     * equal, every coordinate finite); the planes of zero[] with bit e are then exactly 0. */\n");
    kgpu_local(o, g, g->uint, "col", "0u", 1);
    if (base)
        kgpu_local(o, g, g->uint, "base", base, 0);
    for (e = 0; e < tp_domain_edges(d); e++) {
        sbuf cond;
        char *sel;
        sbuf_init(&cond);
        sbuf_puts(&cond, "fin");
        n = tp_domain_edge_points(k, d, e);
        for (x = 1; x < n; x++) {
            snprintf(a, sizeof a, pt, k[x]);
            snprintf(b, sizeof b, pt, k[0]);
            sbuf_printf(&cond, " &&\n        %ssame(%s, %s)", info->prefix, a, b);
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
 * coordinates u, D the extents, as a factor (kgpu_group): Ru0 Du1 Du2 + Du0 Ru1 Du2 + Du0 Du1 Ru2.
 * Returns e. */
static char *put_diff_monomial(char *e, size_t size, const kern_target *g, const char *u)
{
    char f[3][4], m[3][64], s[224];
    int i, k;
    for (i = 0; i < 3; i++) {
        for (k = 0; k < 3; k++)
            snprintf(f[k], sizeof f[k], "%c%c", k == i ? 'R' : 'D', u[k]);
        kgpu_product(m[i], sizeof m[i], g, " ", 3, (const char *const[]){f[0], f[1], f[2]});
    }
    snprintf(s, sizeof s, "%s + %s + %s", m[0], m[1], m[2]);
    return kgpu_group(e, size, g, s);
}

/* The names of one set of magnitudes: the eye they read (eye, or l in patch-local coordinates),
 * the suffix s of Rc, R, E, R3 and F ("", or "_o" for the second look's points as given) and
 * the indent in of their declarations (their loop's body one level deeper). */
typedef struct {
    const char *eye, *s, *in;
} mag_names;

/* Into e (size bytes) world space's largest |monomial| with the eye's components h[0], h[1]
 * (the other two r): (|eye.h0| Rh1 + |eye.h1| Rh0) (Rr0 Rr1), names from n. Returns e. */
static char *put_eye_monomial(char *e, size_t size, const kern_target *g, const char *h,
                              const char *r, const mag_names *n)
{
    char a[32], x[2][8], m[2][64], s[160], t[2][160];
    int i;
    for (i = 0; i < 2; i++) {
        snprintf(a, sizeof a, "%s(%s.%c)", g->fabs, n->eye, h[i]);
        snprintf(x[0], sizeof x[0], "R%c%s", h[!i], n->s);
        kgpu_mul(m[i], sizeof m[i], g, a, x[0]);
    }
    snprintf(s, sizeof s, "%s + %s", m[0], m[1]);
    snprintf(x[0], sizeof x[0], "R%c%s", r[0], n->s);
    snprintf(x[1], sizeof x[1], "R%c%s", r[1], n->s);
    kgpu_group(t[0], sizeof t[0], g, s);
    kgpu_group(t[1], sizeof t[1], g, kgpu_mul(a, sizeof a, g, x[0], x[1]));
    return kgpu_mul(e, size, g, t[0], t[1]);
}

/* Into e (1024 bytes), M from the eye and the patch's largest |coordinates| Rx, Ry, Rz, Rw
 * (names from n): the largest |monomial| (clip space); in world space the sum over the eye's
 * components of the largest |monomial| with that component (docs/errors.md). With diff
 * (differences), a monomial has one coordinate and two differences instead (put_diff_monomial). */
static void put_monomial_max(char *e, const out_info *info, const kern_target *g, int diff,
                             const mag_names *n)
{
    static const char *const other[4] = {"yzw", "xzw", "xyw", "xyz"};
    char a[32], m[256], x[160], r[3][8], big[8];
    size_t k = 0;
    int c;
    if (info->space == OUT_CLIP) {
        for (c = 0; c < 3; c++)
            snprintf(r[c], sizeof r[c], "R%c%s", "xyw"[c], n->s);
        if (diff)
            put_diff_monomial(m, sizeof m, g, "xyw");
        else
            kgpu_group(m, sizeof m, g, kgpu_product(x, sizeof x, g, " ", 3, (const char *const[]){r[0], r[1], r[2]}));
        snprintf(big, sizeof big, "E%s", n->s);
        kgpu_mul(e, 1024, g, big, m);
    } else if (diff) {
        for (c = 0; c < 4 && k < 1024; c++) {
            snprintf(a, sizeof a, "%s(%s.%c)", g->fabs, n->eye, "xyzw"[c]);
            put_diff_monomial(x, sizeof x, g, other[c]);
            k += (size_t)snprintf(e + k, 1024 - k, "%s%s", c ? " +\n        " : "", kgpu_mul(m, sizeof m, g, a, x));
        }
    } else {
        put_eye_monomial(m, sizeof m, g, "xy", "zw", n);
        snprintf(e, 1024, "%s +\n        %s", m, put_eye_monomial(x, sizeof x, g, "zw", "xy", n));
    }
}

/* With differences, the patch's extents over the coordinates c (n of them): step 0 declares
 * Hc = max b.c and Lc = max -b.c from the first point, step 1 (in the loop over the points a)
 * updates them, step 2 declares the extents Dc = Hc + Lc (docs/errors.md: differences). */
static void put_extents(sbuf *o, const out_info *info, const kern_target *g, const char *up,
                        const char *c, int n, int step)
{
    char name[2][4], init[2][96];
    int k;
    for (k = 0; kgpu_differences(info, g) && k < n; k++) {
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
            kgpu_local(o, g, g->real, name[0], init[0], 0);
        }
    }
}

void kgpu_too_large(sbuf *o, const kern_target *g, const char *indent, const char *up,
                    const char *qmax, const char *s)
{
    char e[32], m[64], r3[8];
    snprintf(e, sizeof e, "%s(E%s, 1.0f)", g->fmax, s);
    snprintf(r3, sizeof r3, "R3%s", s);
    sbuf_printf(o, "%sif (!(%s < %s%s))", indent, kgpu_mul(m, sizeof m, g, e, r3), up, qmax);
}

/* The patch's largest |coordinates| Rc over the coordinates c (n of them) of the points point
 * (an expression of i) for i below count (names from m), with differences its extents
 * (put_extents' steps 0 and 1), with exact zeros (of the terms' points, suffix "") fin: every
 * coordinate is finite. */
static void put_patch_max(sbuf *o, const out_info *info, const kern_target *g, const char *up,
                          const char *c, int n, const char *point, const char *count,
                          const mag_names *m)
{
    int fin = kgpu_exact_zeros(info) && !*m->s, k;
    char rc[4][8], in2[32];
    kern_var r[4];
    snprintf(in2, sizeof in2, "%s    ", m->in);
    for (k = 0; k < n; k++) {
        snprintf(rc[k], sizeof rc[k], "R%c%s", c[k], m->s);
        r[k] = (kern_var){rc[k], "0.0f", 1};
    }
    g->syntax->locals(o, g, m->in, g->real, r, n, 0);
    if (!*m->s)
        put_extents(o, info, g, up, c, n, 0);
    if (fin)
        kgpu_local(o, g, "bool", "fin", "true", 1);
    sbuf_printf(o, "%sfor (i = 0u; i < %s; i++) {\n", m->in, count);
    g->syntax->locals(o, g, in2, g->vec4, &(kern_var){"a", point, 0}, 1, 0);
    for (k = 0; k < n; k++)
        sbuf_printf(o, "%s%s = %s(%s, %s(a.%c));\n", in2, rc[k], g->fmax, rc[k], g->fabs, c[k]);
    if (!*m->s)
        put_extents(o, info, g, up, c, n, 1);
    if (fin)
        sbuf_printf(o, "%sfin = fin && %sfinite(a);\n", in2, info->prefix);
    sbuf_printf(o, "%s}\n", m->in);
}

/* Declares at m's indent the float name+suffix = init. */
static void put_named(sbuf *o, const kern_target *g, const mag_names *m, const char *name,
                      const char *init)
{
    char n[8];
    snprintf(n, sizeof n, "%s%s", name, m->s);
    g->syntax->locals(o, g, m->in, g->real, &(kern_var){n, init, 0}, 1, 0);
}

/* The magnitudes of the points point (an expression of i, i below count), names from m:
 * put_patch_max's, R the largest of them, E the eye's largest |component| and R3 = R^3. */
static void put_magnitudes(sbuf *o, const out_info *info, const kern_target *g, const char *up,
                           const char *point, const char *count, const mag_names *m)
{
    const char *ab = g->fabs, *mx = g->fmax, *c = info->space == OUT_CLIP ? "xyw" : "xyzw",
               *s = m->s, *v = m->eye;
    char e[320], name[8];
    if (*s)
        sbuf_printf(o, "%s/* The largest |coordinates| of the points as given and the eye's bound the\n"
                       "%s * second look's errors. */\n", m->in, m->in);
    else
        sbuf_printf(o, "%s/* Certified: the patch's largest |coordinates| and the eye's bound the "
                       "errors. */\n", m->in);
    put_patch_max(o, info, g, up, c, (int)strlen(c), point, count, m);
    if (info->space == OUT_CLIP) {
        snprintf(e, sizeof e, "%s(%s(Rx%s, Ry%s), Rw%s)", mx, mx, s, s, s);
        put_named(o, g, m, "R", e);
        snprintf(e, sizeof e, "%s(%s.z)", ab, v);
    } else {
        snprintf(e, sizeof e, "%s(%s(Rx%s, Ry%s), %s(Rz%s, Rw%s))", mx, mx, s, s, mx, s, s);
        put_named(o, g, m, "R", e);
        snprintf(e, sizeof e, "%s(%s(%s(%s.x), %s(%s.y)), %s(%s(%s.z), %s(%s.w)))", mx, mx, ab, v, ab,
                 v, mx, ab, v, ab, v);
    }
    put_named(o, g, m, "E", e);
    snprintf(name, sizeof name, "R%s", s);
    kgpu_product(e, sizeof e, g, " ", 3, (const char *const[]){name, name, name});
    put_named(o, g, m, "R3", e);
}

/* The second look's magnitudes of the points point (an expression of i, i below count), names
 * from m: put_magnitudes' and M2, the largest |monomial| of the points themselves. */
static void put_look_magnitudes(sbuf *o, const out_info *info, const kern_target *g,
                                const char *up, const char *point, const char *count,
                                const mag_names *m)
{
    char e[1024];
    put_magnitudes(o, info, g, up, point, count, m);
    put_monomial_max(e, info, g, 0, m);
    g->syntax->locals(o, g, m->in, g->real, &(kern_var){"M2", e, 0}, 1, 0);
}

/* F (names from m), the underflow term's factor (1 + R)^3 (1 + E) of m's magnitudes. */
static void put_underflow(sbuf *o, const kern_target *g, const mag_names *m)
{
    char e[256], r1[16], e1[16];
    snprintf(e, sizeof e, "1.0f + R%s", m->s);
    kgpu_group(r1, sizeof r1, g, e);
    snprintf(e, sizeof e, "1.0f + E%s", m->s);
    kgpu_group(e1, sizeof e1, g, e);
    kgpu_product(e, sizeof e, g, " ", 4, (const char *const[]){r1, r1, r1, e1});
    put_named(o, g, m, "F", e);
}

/* F; then, for a patch too large for the bound <up>qmax (or NaN), the statement then. */
static void put_guard(sbuf *o, const kern_target *g, const char *up, const char *qmax,
                      const char *then)
{
    put_underflow(o, g, &(mag_names){"eye", "", "    "});
    kgpu_too_large(o, g, "    ", up, qmax, "");
    kgpu_then(o, g);
    sbuf_printf(o, "        %s /* too large for the bound, or NaN: never certified */\n", then);
    kgpu_end(o, g, "    ");
}

const char *kgpu_look_names(const out_info *info, const kern_target *g)
{
    return kgpu_given(info, g) ? "_o" : "";
}

void kgpu_look_magnitudes(sbuf *o, const out_info *info, const kern_target *g, const char *up)
{
    mag_names m = {"eye", "_o", "        "};
    char pt[96], count[80];
    snprintf(pt, sizeof pt, "given[q * %sK + i]", up);
    snprintf(count, sizeof count, "%sK", up);
    put_look_magnitudes(o, info, g, up, pt, count, &m);
    put_underflow(o, g, &m);
}

void kgpu_cert_scale(sbuf *o, const tp_domain *d, const out_info *info, const kern_target *g,
                     const char *up)
{
    const char *c = info->space == OUT_CLIP ? "xyw" : "xyzw";
    mag_names m = {kgpu_table_local(info, g) && info->space == OUT_WORLD ? "l" : "eye", "", "    "};
    char e[1024], pt[96], count[80];
    snprintf(pt, sizeof pt, "pts[q * %sK + i]", up);
    snprintf(count, sizeof count, "%sK", up);
    put_magnitudes(o, info, g, up, pt, count, &m);
    put_extents(o, info, g, up, c, (int)strlen(c), 2);
    put_monomial_max(e, info, g, kgpu_differences(info, g), &m);
    kgpu_local(o, g, g->real, "M", e, 0);
    if (kgpu_second_look(info, g) && !kgpu_given(info, g)) { /* M2: the look reads the points */
        put_monomial_max(e, info, g, 0, &m);
        kgpu_local(o, g, g->real, "M2", e, 0);
    }
    put_guard(o, g, up, "QMAX", "f = 3u;");
    if (kgpu_exact_zeros(info)) { /* as given: a shear may round distinct points equal */
        snprintf(e, sizeof e, "q * %sK", up);
        put_collapsed(o, d, info, g,
                      kgpu_given(info, g) ? "given[base + %du]" : "pts[base + %du]", e);
    }
    if (kgpu_second_look(info, g)) { /* the plain float signs' flags; the planes to look at again */
        kern_var v[3] = {{"pf", "0u", 1}, {"redo", "0u", 1}, {"fd", "0u", 1}};
        g->syntax->locals(o, g, "    ", g->uint, v, 3, 0);
    }
}

void kgpu_cert_look_scale(sbuf *o, const tp_domain *d, const out_info *info, const kern_target *g,
                          const char *up)
{
    mag_names m = {"eye", "", "    "};
    char count[16];
    snprintf(count, sizeof count, "%du", d->npoints);
    put_look_magnitudes(o, info, g, up, "cp[i]", count, &m);
    put_guard(o, g, up, "QMAX2", "return 2u;");
    if (kgpu_exact_zeros(info))
        put_collapsed(o, d, info, g, "cp[%d]", NULL);
}

void kgpu_keep(sbuf *o, const out_info *info, const kern_target *g, const char *indent,
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
    sbuf_printf(x, "%sflags(d, %s + %s)%s", info->prefix, kgpu_mul(m[0], sizeof m[0], g, k, "M"),
                kgpu_mul(m[1], sizeof m[1], g, f, "F"), kgpu_exact_zeros(info) ? " & keep" : "");
    return x->s ? x->s : "";
}

/* With the second look, a plane's certified flags fp and plain flags pp: into f and pf, and
 * where they differ (the bound does not clear where the plain sign decides) the plane's bit in
 * redo (its place in own_plane after own_start[t]), else fp into fd. */
static void put_split_flags(sbuf *o, const out_info *info, const kern_target *g)
{
    const char *px = info->prefix, *keep = kgpu_exact_zeros(info) ? " & keep" : "";
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

void kgpu_cert_flags(sbuf *o, const out_info *info, const kern_target *g)
{
    sbuf x;
    if (kgpu_exact_zeros(info))
        kgpu_keep(o, info, g, "        ", "plane");
    if (kgpu_second_look(info, g)) {
        put_split_flags(o, info, g);
        return;
    }
    sbuf_printf(o, "        f |= %s;\n", first_flags(&x, info, g));
    o->failed |= x.failed;
    sbuf_clear(&x);
}
