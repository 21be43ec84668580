/* slp_text.c: the straight-line program written through a syntax table: points, minors, the
 * bracket, fused and point forms of the planes, in slp_order's order. */
#include "emit/slp_text.h"
#include "emit/fmt.h"
#include "plan/slp_order.h"
#include "plan/slp_point.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* slp_order's registers (AVX-512 has 32 vector registers; 8 left for sums and temporaries) and
 * window (the planes it picks from): the fastest of those tried with gcc 12 and clang 14 on
 * bicubic patches (bench/README: Plane order). */
#define SLP_ORDER_CAP 24
#define SLP_ORDER_WIN 4

/* A product, a multiply-add and a sum are at most this long (a sum of a dozen minors). */
#define EXPR SLPT_EXPR

int slpt_init(slpt_writer *w, sbuf *o, const plan_slp *plan, const slpt_syntax *s, int world,
              const void *ctx, ptp_error *err)
{
    const slp_prog *p = &plan->prog;
    *w = (slpt_writer){o, p, plan, s, world, ctx, calloc(p->npairs + (size_t)p->npoints, 1)};
    if (!w->done)
        return ptp_fail(err, PTP_ENOMEM, "out of memory writing the straight-line program");
    return PTP_OK;
}

void slpt_clear(slpt_writer *w)
{
    free(w->done);
    w->done = NULL;
}

/* Writes to out (EXPR bytes, truncating) the printf format f of the arguments; returns out. */
static char *expr(char *out, const char *f, ...)
{
    va_list ap;
    va_start(ap, f);
    vsnprintf(out, EXPR, f, ap);
    va_end(ap);
    return out;
}

/* Writes to out the product of a and b in the syntax's form. */
static char *mul(char *out, const slpt_writer *w, const char *a, const char *b)
{
    return expr(out, w->s->mul, a, b);
}

/* Declares the n locals name[i] = init[i]: in one declaration two a line (multi), else one each. */
static void declare(slpt_writer *w, const char *const *name, const char *const *init, int n)
{
    const slpt_syntax *s = w->s;
    int i;
    for (i = 0; i < n; i++) {
        if (!s->multi || i == 0)
            sbuf_printf(w->o, "%s%s", s->indent, s->decl);
        else if (i % 2 == 0)
            sbuf_printf(w->o, "%s    ", s->indent);
        sbuf_printf(w->o, "%s = %s", name[i], init[i]);
        sbuf_puts(w->o, !s->multi || i + 1 == n ? ";\n" : i % 2 ? ",\n" : ", ");
    }
}

/* Writes to out the difference p q - r s of products (G or a minor). */
static void minor_expr(char *out, const slpt_writer *w, const char *p, const char *q,
                       const char *r, const char *s)
{
    char a[EXPR], b[EXPR];
    expr(out, "%s - %s", mul(a, w, p, q), mul(b, w, r, s));
}

/* The frame's names: the origin's negation, and the eye as given and as the local frame sees it. */
static const char *const origin[3] = {"ox", "oy", "oz"};
static const char *const raw_eye[3] = {"e0", "e1", "e2"}, *const local_eye[3] = {"l0", "l1", "l2"};

void slpt_input(char *out, const slpt_writer *w, int idx, int c)
{
    char x[EXPR], wk[EXPR];
    w->s->load(x, EXPR, w, idx, c);
    if (!w->plan->local || c == 3) {
        memcpy(out, x, EXPR);
        return;
    }
    w->s->load(wk, EXPR, w, idx, 3);
    expr(out, w->s->shift, origin[c], wk, x);
}

/* Writes to out row r of the uniform cubic B-spline-to-Bezier map (times 6) applied to a[0..3]:
 * (a0 + a2) + 4 a1, 4 a1 + 2 a2, 2 a1 + 4 a2, (a1 + a3) + 4 a2. */
static void bspline_row(char *out, const slpt_writer *w, int r, char a[4][EXPR])
{
    char p[EXPR], q[EXPR];
    if (r == 0 || r == 3)
        expr(out, "(%s + %s) + %s", a[r == 0 ? 0 : 1], a[r == 0 ? 2 : 3], mul(p, w, "4.0f", a[r == 0 ? 1 : 2]));
    else
        expr(out, "%s + %s", mul(p, w, r == 1 ? "4.0f" : "2.0f", a[1]), mul(q, w, r == 1 ? "2.0f" : "4.0f", a[2]));
}

/* B-spline input: declares h<c><i>_<j> (the map along u) and the Bezier points bx<k> ... (then
 * along v), coordinate by coordinate (clip space never reads z). */
static void put_bspline(slpt_writer *w)
{
    static const char xyzw[] = "xyzw";
    char a[4][EXPR], names[16][32], inits[16][EXPR];
    const char *name[16], *init[16];
    int c, i, j, k;
    for (c = 0; c < 4; c++) {
        if (c == 2 && !w->world)
            continue;
        for (i = 0; i < 4; i++) /* along u: column j of the input's 4 x 4 vertices */
            for (j = 0; j < 4; j++) {
                for (k = 0; k < 4; k++)
                    slpt_input(a[k], w, plan_input_index(w->plan, k, j), c);
                snprintf(names[i * 4 + j], sizeof names[0], "h%c%d_%d", xyzw[c], i, j);
                bspline_row(inits[i * 4 + j], w, i, a);
            }
        for (k = 0; k < 16; k++)
            name[k] = names[k], init[k] = inits[k];
        declare(w, name, init, 16);
        for (i = 0; i < 4; i++) /* along v */
            for (j = 0; j < 4; j++) {
                for (k = 0; k < 4; k++)
                    expr(a[k], "h%c%d_%d", xyzw[c], i, k);
                snprintf(names[i * 4 + j], sizeof names[0], "b%c%d", xyzw[c], i * 4 + j);
                bspline_row(inits[i * 4 + j], w, j, a);
            }
        declare(w, name, init, 16);
    }
}

/* Patch-local coordinates: declares rw, the origin's negation o from input point 0 and, in world
 * space, the local eye. */
static void put_origin(slpt_writer *w)
{
    char w0[EXPR], x0[EXPR], inits[4][EXPR], pr[EXPR];
    const char *name = "rw", *init[4];
    int c, n = w->world ? 3 : 2;
    w->s->load(w0, EXPR, w, 0, 3);
    w->s->recip0(inits[0], EXPR, w, w0);
    init[0] = inits[0];
    declare(w, &name, init, 1);
    for (c = 0; c < n; c++) {
        w->s->load(x0, EXPR, w, 0, c);
        expr(inits[c], "-(%s)", mul(pr, w, x0, "rw"));
        init[c] = inits[c];
    }
    declare(w, origin, init, n);
    if (!w->world)
        return;
    for (c = 0; c < 3; c++) {
        expr(inits[c], w->s->shift, origin[c], "e3", raw_eye[c]);
        init[c] = inits[c];
    }
    declare(w, local_eye, init, 3);
}

void slpt_frame(slpt_writer *w)
{
    if (w->plan->local)
        put_origin(w);
    if (w->plan->bspline)
        put_bspline(w);
}

void slpt_coordinate(char *out, const slpt_writer *w, int k, int c)
{
    if (w->plan->bspline)
        expr(out, "b%c%d", "xyzw"[c], k);
    else
        slpt_input(out, w, plan_input_index(w->plan, k / (w->plan->m + 1), k % (w->plan->m + 1)), c);
}

void slpt_point(slpt_writer *w, int k)
{
    static const char xyzw[] = "xyzw";
    char names[6][24], inits[6][EXPR], v[4][24];
    const char *const *e = w->plan->local ? local_eye : raw_eye, *name[6], *init[6];
    int c, n = 0;
    if (w->done[w->p->npairs + (size_t)k])
        return;
    w->done[w->p->npairs + (size_t)k] = 1;
    for (c = 0; c < 4; c++) {
        snprintf(v[c], sizeof v[c], "%c%d", xyzw[c], k);
        if (c == 2 && !w->world)
            continue; /* clip space never reads z */
        memcpy(names[n], v[c], sizeof v[c]);
        slpt_coordinate(inits[n], w, k, c);
        n++;
    }
    if (w->world) {
        snprintf(names[n], sizeof names[n], "a%d", k);
        minor_expr(inits[n++], w, e[0], v[1], e[1], v[0]);
        snprintf(names[n], sizeof names[n], "b%d", k);
        minor_expr(inits[n++], w, e[2], v[3], "e3", v[2]);
    } else {
        snprintf(names[n], sizeof names[n], "g%d", k);
        mul(inits[n++], w, "e2", v[3]);
    }
    for (c = 0; c < n; c++)
        name[c] = names[c], init[c] = inits[c];
    if (w->world) { /* the coordinates, then the eye products */
        declare(w, name, init, 4);
        declare(w, name + 4, init + 4, 2);
    } else
        declare(w, name, init, 4);
}

/* Declares the minor pair unless done, after its points. */
static void put_minor(slpt_writer *w, int pair)
{
    const slp_pair *q = &w->p->pairs[pair];
    char name[2][32], init[2][EXPR], a[4][16];
    const char *nm, *in;
    int i;
    if (w->done[pair])
        return;
    w->done[pair] = 1;
    slpt_point(w, q->k);
    slpt_point(w, q->l);
    for (i = 0; i < (w->world ? 2 : 1); i++) {
        char c0 = i ? 'z' : 'x', c1 = i ? 'w' : 'y';
        snprintf(name[i], sizeof name[i], "%c%d_%d", i ? 'n' : 'm', q->k, q->l);
        snprintf(a[0], sizeof a[0], "%c%d", c0, q->k);
        snprintf(a[1], sizeof a[1], "%c%d", c1, q->l);
        snprintf(a[2], sizeof a[2], "%c%d", c1, q->k);
        snprintf(a[3], sizeof a[3], "%c%d", c0, q->l);
        minor_expr(init[i], w, a[0], a[1], a[2], a[3]);
        nm = name[i], in = init[i];
        declare(w, &nm, &in, 1);
    }
}

/* Writes to out the minor of pair with letter m, "m0_1". */
static char *minor_name(char *out, size_t size, const slpt_writer *w, int pair, char m)
{
    snprintf(out, size, "%c%d_%d", m, w->p->pairs[pair].k, w->p->pairs[pair].l);
    return out;
}

/* Writes to out one bracket of a term: ((G(b_j) M(k,l) - G(b_k) M(j,l)) + G(b_l) M(j,k)) for
 * one kind, G named with letter g and the minors with letter m. */
static void put_bracket(char *out, const slpt_writer *w, const slp_term *x, char g, char m)
{
    char gv[3][16], mv[3][16], pr[3][EXPR];
    int i;
    for (i = 0; i < 3; i++) {
        snprintf(gv[i], sizeof gv[i], "%c%d", g, x->point[i]);
        mul(pr[i], w, gv[i], minor_name(mv[i], sizeof mv[i], w, x->pair[i], m));
    }
    expr(out, "((%s - %s) + %s)", pr[0], pr[1], pr[2]);
}

/* Appends to s the signed sum of the minors (letter m) of fused entries [a, b), positive first. */
static void put_minor_sum(sbuf *s, const slpt_writer *w, size_t a, size_t b, char m)
{
    size_t i;
    int pass, n = 0;
    char mv[32];
    for (pass = 0; pass < 2; pass++)
        for (i = a; i < b; i++) {
            const slp_entry *x = &w->p->entries[i];
            if (x->neg != pass)
                continue;
            sbuf_printf(s, "%s%s", n++ ? (x->neg ? " - " : " + ") : x->neg ? "-" : "",
                        minor_name(mv, sizeof mv, w, x->pair, m));
        }
}

/* Appends 2^a u as a doublings, ((u + u) + (u + u)) (the compiler shares the repeats). */
static void put_doubled(sbuf *o, int a)
{
    if (a == 0) {
        sbuf_puts(o, "u");
        return;
    }
    sbuf_puts(o, "(");
    put_doubled(o, a - 1);
    sbuf_puts(o, " + ");
    put_doubled(o, a - 1);
    sbuf_puts(o, ")");
}

/* Appends v's update with the group's sum u at scale s: assigned for the plane's first group.
 * s on the adders (slp_scale_of): 2^k u as one sum of doublings; else u's doublings and all
 * factors but the last into u, the last into v. Any other s: a product, or a multiply-add. */
static void put_group_end(slpt_writer *w, const rat *s, int first_group)
{
    char sv[RAT_STRLEN], lit[RAT_STRLEN + 4], e[EXPR];
    const char *to = first_group ? "=" : "+=", *in = w->s->indent;
    slp_scale c;
    int i;
    rat one;
    rat_set_si(&one, 1);
    rat_get_str(sv, s);
    snprintf(lit, sizeof lit, "%s.0f", sv);
    if (rat_equal(s, &one))
        sbuf_printf(w->o, "%sv %s u;\n", in, to);
    else if (slp_scale_of(&c, s) && c.nf == 0) {
        sbuf_printf(w->o, "%sv %s ", in, to);
        put_doubled(w->o, c.shift);
        sbuf_puts(w->o, ";\n");
    } else if (slp_scale_of(&c, s)) {
        for (i = 0; i < c.shift; i++)
            sbuf_printf(w->o, "%su = u + u;\n", in);
        for (i = 0; i < c.nf; i++) {
            if (i + 1 < c.nf)
                sbuf_printf(w->o, "%su = ", in);
            else
                sbuf_printf(w->o, "%sv %s ", in, to);
            put_doubled(w->o, c.a[i]);
            sbuf_puts(w->o, c.sign[i] > 0 ? " + u;\n" : " - u;\n");
        }
    } else if (first_group)
        sbuf_printf(w->o, "%sv = %s;\n", in, mul(e, w, lit, "u"));
    else {
        expr(e, w->s->fmas, lit, "u", "v");
        sbuf_printf(w->o, "%sv = %s;\n", in, e);
    }
}

/* Appends "u = G * (sum)" (the first product of a plane's group) or "u = fma(G, sum, u)". */
static void put_update(slpt_writer *w, const char *gv, sbuf *sum, int first)
{
    char e[EXPR], par[EXPR];
    if (first) {
        expr(par, "(%s)", sum->s);
        mul(e, w, gv, par);
    } else
        expr(e, w->s->fma, gv, sum->s, "u");
    sbuf_printf(w->o, "%su = %s;\n", w->s->indent, e);
}

/* A fused plane from entries [a, ...): per group u = sum over points b of G(b) times the signed
 * sum of b's minors, with multiply-adds, then v; returns the end of the plane's entries. */
static size_t put_fused(slpt_writer *w, size_t a)
{
    const slp_prog *p = w->p;
    int plane = p->entries[a].plane, first_group = 1;
    size_t g, b, e, i;
    for (g = a; g < p->nentries && p->entries[g].plane == plane; g = e, first_group = 0) {
        e = slp_group_end(p, g);
        for (b = g; b < e; b = i) {
            int k, pt = p->entries[b].point;
            i = slp_point_end(p, b);
            for (k = (int)b; k < (int)i; k++) /* the minors declared where first used */
                put_minor(w, p->entries[k].pair);
            slpt_point(w, pt);
            for (k = 0; k < (w->world ? 2 : 1); k++) {
                char gv[16], ml = w->world && !k ? 'n' : 'm';
                sbuf sum;
                snprintf(gv, sizeof gv, "%c%d", w->world ? (k ? 'b' : 'a') : 'g', pt);
                sbuf_init(&sum);
                put_minor_sum(&sum, w, b, i, ml);
                put_update(w, gv, &sum, b == g && k == 0);
                sbuf_clear(&sum);
            }
        }
        put_group_end(w, &p->s[p->entries[g].group], first_group);
    }
    return g;
}

/* u's update by the class of items [a, b) of kind letter m at |coef| c (slp_point.h): their
 * signed sum, times c by adds (slp_point_by_adds) or a product; assigned for the first class. */
static void put_point_class(slpt_writer *w, size_t a, size_t b, char m, int first)
{
    const slp_prog *p = w->p;
    long c = labs(p->items[a].coef);
    int adds = slp_point_by_adds(c, first), n = 0;
    char lit[32], e[EXPR], par[EXPR], mv[32];
    const char *in = w->s->indent;
    size_t i;
    sbuf sum;
    sbuf_init(&sum);
    for (i = a; i < b; i++) {
        const slp_item *x = &p->items[i];
        sbuf_printf(&sum, "%s%s", n++ ? (x->coef < 0 ? " - " : " + ") : x->coef < 0 ? "-" : "",
                    minor_name(mv, sizeof mv, w, x->pair, m));
    }
    snprintf(lit, sizeof lit, "%ld.0f", c);
    if (!adds && first) {
        expr(par, "(%s)", sum.s);
        sbuf_printf(w->o, "%su = %s;\n", in, mul(e, w, lit, par));
    } else if (!adds) {
        expr(e, w->s->fmas, lit, sum.s, "u");
        sbuf_printf(w->o, "%su = %s;\n", in, e);
    } else if (c == 2) /* first: u = t + t */
        sbuf_printf(w->o, "%su %s (%s);\n%su += u;\n", in, first ? "=" : "+=", sum.s, in);
    else
        sbuf_printf(w->o, "%su %s %s;\n", in, first ? "=" : "+=", sum.s);
    sbuf_clear(&sum);
}

/* A point-form plane from item a (slp_point.h): per point and kind, u from the classes, then
 * v = G u or v = fma(G, u, v); returns the end of the plane's items. */
static size_t put_point_form(slpt_writer *w, size_t a)
{
    const slp_prog *p = w->p;
    size_t e = slp_point_plane_end(p->items, p->nitems, a), f, fe, c, ce, i;
    int k;
    for (f = a; f < e; f = fe) {
        int pt = p->items[f].point;
        fe = slp_point_factor_end(p->items, p->nitems, f);
        for (i = f; i < fe; i++) /* the minors and the point declared where first used */
            put_minor(w, p->items[i].pair);
        slpt_point(w, pt);
        for (k = 0; k < (w->world ? 2 : 1); k++) {
            char gv[16], ml = w->world && !k ? 'n' : 'm', ex[EXPR];
            snprintf(gv, sizeof gv, "%c%d", w->world ? (k ? 'b' : 'a') : 'g', pt);
            for (c = f; c < fe; c = ce) {
                ce = slp_point_class_end(p->items, p->nitems, c);
                put_point_class(w, c, ce, ml, c == f);
            }
            if (f == a && k == 0)
                mul(ex, w, gv, "u");
            else
                expr(ex, w->s->fma, gv, "u", "v");
            sbuf_printf(w->o, "%sv = %s;\n", w->s->indent, ex);
        }
    }
    return e;
}

/* The statements of term i: its group's sum u and, at the end of a group, the plane's v
 * (assigned when the group is the plane's first, first_group). */
static void put_term(slpt_writer *w, size_t i, int first_group)
{
    const slp_prog *p = w->p;
    const slp_term *x = &p->terms[i];
    int first = i == 0 || p->terms[i - 1].group != x->group;
    int last = i + 1 == p->nterms || p->terms[i + 1].group != x->group;
    char b0[EXPR], b1[EXPR];
    if (first)
        sbuf_printf(w->o, "%su = %s", w->s->indent, x->neg ? "-" : "");
    else
        sbuf_printf(w->o, "%su %s ", w->s->indent, x->neg ? "-=" : "+=");
    if (w->world) {
        put_bracket(b0, w, x, 'a', 'n');
        put_bracket(b1, w, x, 'b', 'm');
        sbuf_printf(w->o, "(%s + %s)", b0, b1);
    } else {
        put_bracket(b0, w, x, 'g', 'm');
        sbuf_puts(w->o, b0);
    }
    sbuf_puts(w->o, ";\n");
    if (last)
        put_group_end(w, &p->s[x->group], first_group);
}

/* The terms of exact plane from term a, in bracket form; returns the end of its terms. */
static size_t put_exact(slpt_writer *w, size_t a)
{
    const slp_prog *p = w->p;
    size_t i;
    int first_group = 1, k;
    for (i = a; i < p->nterms && p->terms[i].plane == p->terms[a].plane; i++) {
        for (k = 0; k < 3; k++)
            put_minor(w, p->terms[i].pair[k]);
        for (k = 0; k < 3; k++)
            slpt_point(w, p->terms[i].point[k]);
        if (i > a && p->terms[i - 1].group != p->terms[i].group)
            first_group = 0;
        put_term(w, i, first_group);
    }
    return i;
}

int slpt_program(slpt_writer *w, ptp_error *err)
{
    const slp_prog *p = w->p;
    int n = 0, k, st;
    size_t *term = malloc(((size_t)p->nplanes + 1) * 3 * sizeof *term), *entry = term + p->nplanes,
           *item = entry + p->nplanes, i;
    int *order = malloc(((size_t)p->nplanes + 1) * sizeof *order);
    if (!term || !order) {
        st = ptp_fail(err, PTP_ENOMEM, "out of memory writing the straight-line program");
        goto out;
    }
    for (i = p->nterms; i-- > 0;) /* each plane's first term, fused entry and point item */
        term[p->terms[i].plane] = i;
    for (i = p->nentries; i-- > 0;)
        entry[p->entries[i].plane] = i;
    for (i = p->nitems; i-- > 0;)
        item[p->items[i].plane] = i;
    if ((st = slp_order(order, &n, p, SLP_ORDER_CAP, SLP_ORDER_WIN, err)) != PTP_OK)
        goto out;
    for (k = 0; k < n; k++) {
        if (p->form[order[k]] == SLP_BRACKET)
            put_exact(w, term[order[k]]);
        else if (p->form[order[k]] == SLP_FUSED)
            put_fused(w, entry[order[k]]);
        else
            put_point_form(w, item[order[k]]);
        w->s->plane_end(w, order[k], k == 0);
    }
out:
    free(term);
    free(order);
    return st;
}

int slpt_inverse_scale(char *out, size_t size, const slp_prog *p, int plane)
{
    char k[48];
    rat one, inv;
    rat_set_si(&one, 1);
    if (rat_equal(&p->c[plane], &one) || rat_div(&inv, &one, &p->c[plane]))
        return 0;
    snprintf(out, size, "%s", fmt_float_literal(k, &inv));
    return 1;
}
