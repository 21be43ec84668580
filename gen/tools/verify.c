/* verify.c: `ptpgen verify`: a table read by verify_parse checked against tp_derive's exact one.
 * Whole-table readings (a scale, negation, u and v swapped, v-first) first, then every problem. */
#include "tools/verify.h"
#include "core/tplane.h"
#include "tools/verify_arrays.h"
#include "tools/verify_parse.h"

#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define TOL 1e-6          /* the relative tolerance of a weight that is a rounding */
#define SIMPLE_DEN 1000   /* the largest denominator of a scale that is snapped to a fraction */

/* A scale: every weight of the table is s times the expected one. */
typedef struct {
    double d;
    rat r;     /* s exactly, when exact */
    int exact;
} scale;

/* A term of the table under check, with its points sorted. */
typedef struct {
    int plane, q[3];  /* the points in increasing order */
    int flipped;      /* sorting them took an odd permutation */
    int repeated;     /* a point repeats: the term is 0 */
    verify_weight g;  /* the weight of cross4(b_q0, b_q1, b_q2): the written one, negated if flipped */
    size_t src;       /* its index in the document */
    long v[2];        /* the term of each expected table with the same plane and points, or -1 */
} gterm;

/* A reading of the whole table: expected table `which` (0: exact, 1: relabelled) times s. */
typedef struct {
    int which;
    scale s;
    size_t score; /* the terms it explains */
} reading;

/* What the report says about a term (problems first, then notes). */
enum {
    P_MISSING,
    P_EXTRA,
    P_WEIGHT,
    P_PLANE,
    P_DUP,
    P_ORDER,
    P_ARRAY, /* counted by verify_arrays, which writes its own lines */
    NPROBLEMS,
    N_ORDER_OK = NPROBLEMS,
    N_REPEATED,
    N_ZERO
};

/* One line of the report: a problem or a note on line `line` (INT_MAX for a missing term). */
typedef struct {
    int kind, line;
    size_t g;  /* the term (index into the gterms), unless P_MISSING */
    long v;    /* the expected term, for P_MISSING, P_WEIGHT, P_PLANE and P_ORDER */
    int other; /* P_DUP: the line it repeats */
} item;

/* Everything one check works on. */
typedef struct {
    const verify_doc *d;
    const tp_table *t;
    const char *name;
    tp_term *x[2];  /* [0] the exact table in the declared convention, [1] in the other one:
                       relabelled (i, j) -> (j, i), not negated */
    tp_term *owned; /* the one of them relabel allocated */
    int vfirst;     /* the declared convention is v-first */
    size_t nx;
    int vfirst_negated; /* x[1] is x[0] negated (so for every square patch): no reading of its own */
    gterm *g;
    size_t ng;
    item *it;
    size_t nit;
} ctx;

static double dabs(double a)
{
    return a < 0 ? -a : a;
}

/* a and b agree within the relative tolerance. */
static int near(double a, double b)
{
    double m = dabs(a) > dabs(b) ? dabs(a) : dabs(b);
    return dabs(a - b) <= TOL * m;
}

/* Sorts p[0..2] increasing; returns 1 when that took an odd permutation. */
static int sort3(int *p)
{
    int a, b, t, odd = 0;
    for (a = 0; a < 3; a++)
        for (b = a + 1; b < 3; b++)
            if (p[b] < p[a]) {
                t = p[a];
                p[a] = p[b];
                p[b] = t;
                odd ^= 1;
            }
    return odd;
}

/* Orders terms by plane, then points. */
static int cmp_key(int pa, const int *a, int pb, const int *b)
{
    int i;
    if (pa != pb)
        return pa < pb ? -1 : 1;
    for (i = 0; i < 3; i++)
        if (a[i] != b[i])
            return a[i] < b[i] ? -1 : 1;
    return 0;
}

static int cmp_tp(const void *pa, const void *pb)
{
    const tp_term *a = pa, *b = pb;
    int qa[3] = {a->j, a->k, a->l}, qb[3] = {b->j, b->k, b->l};
    return cmp_key(a->plane, qa, b->plane, qb);
}

static int cmp_g(const void *pa, const void *pb)
{
    const gterm *a = pa, *b = pb;
    int c = cmp_key(a->plane, a->q, b->plane, b->q);
    return c ? c : (a->src > b->src) - (a->src < b->src);
}

static int cmp_scale(const void *pa, const void *pb)
{
    const scale *a = pa, *b = pb;
    return (a->d > b->d) - (a->d < b->d);
}

static int cmp_item(const void *pa, const void *pb)
{
    const item *a = pa, *b = pb;
    if (a->line != b->line)
        return a->line < b->line ? -1 : 1;
    if (a->kind != b->kind)
        return a->kind < b->kind ? -1 : 1;
    if (a->v != b->v)
        return a->v < b->v ? -1 : 1;
    return (a->g > b->g) - (a->g < b->g);
}

/* The term of x[0..n) with this plane and sorted points, or -1. */
static long find(const tp_term *x, size_t n, int plane, const int *q)
{
    size_t lo = 0, hi = n;
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        int c, qm[3] = {x[mid].j, x[mid].k, x[mid].l};
        if (!(c = cmp_key(x[mid].plane, qm, plane, q)))
            return (long)mid;
        if (c < 0)
            lo = mid + 1;
        else
            hi = mid;
    }
    return -1;
}

/* Nonzero when g is s times v: exactly when g and s are both exact, else within TOL. */
static int weight_is(const verify_weight *g, const rat *v, const scale *s)
{
    rat e;
    if (g->exact && s->exact && !rat_mul(&e, v, &s->r))
        return rat_equal(&g->r, &e);
    return near(g->d, s->d * rat_get_d(v));
}

/* The same with g negated. */
static int neg_weight_is(const verify_weight *g, const rat *v, const scale *s)
{
    verify_weight h = *g;
    h.d = -h.d;
    rat_neg(&h.r, &h.r);
    return weight_is(&h, v, s);
}

/* Makes s exact when it is within TOL of a fraction p/q with q <= SIMPLE_DEN. */
static void snap(scale *s)
{
    double a = dabs(s->d);
    long long q;
    if (s->exact || a > 1e12 || a < 1e-12)
        return;
    for (q = 1; q <= SIMPLE_DEN; q++) {
        long long p = (long long)(a * (double)q + 0.5);
        if (p >= 1 && near((double)p / (double)q, a) &&
            !rat_set_frac(&s->r, s->d < 0 ? -p : p, q)) {
            s->exact = 1;
            s->d = rat_get_d(&s->r);
            return;
        }
    }
}

/* The scale most terms agree on against x[which] (*count of them; 0 when no term has a
 * nonzero weight and a counterpart). Ratios within 2 TOL of the smallest of a window count as
 * one; the window's median is the scale, made exact when all its exact ratios agree. */
static int best_scale(scale *best, size_t *count, const ctx *c, int which, ptp_error *err)
{
    scale *r = malloc((c->ng ? c->ng : 1) * sizeof *r);
    size_t nr = 0, i, j, bi = 0;
    int agree = 0;
    if (!r)
        return ptp_fail(err, PTP_ENOMEM, "out of memory checking %s", c->name);
    for (i = 0; i < c->ng; i++) {
        const gterm *e = &c->g[i];
        const rat *w;
        if (e->v[which] < 0 || e->repeated || e->g.d == 0)
            continue;
        w = &c->x[which][e->v[which]].w;
        r[nr].d = e->g.d / rat_get_d(w);
        r[nr].exact = e->g.exact && !rat_div(&r[nr].r, &e->g.r, w);
        nr++;
    }
    qsort(r, nr, sizeof *r, cmp_scale);
    *count = 0;
    for (i = 0, j = 0; i < nr; i++) { /* j > i: each window holds its own start */
        while (j < nr && dabs(r[j].d - r[i].d) <= 2 * TOL * dabs(r[i].d))
            j++;
        if (j - i > *count) {
            *count = j - i;
            bi = i;
        }
    }
    if (*count) {
        *best = r[bi + *count / 2];
        best->exact = 0;
        for (i = bi; i < bi + *count && agree >= 0; i++)
            if (r[i].exact) {
                if (!agree)
                    best->r = r[i].r;
                agree = !agree || rat_equal(&best->r, &r[i].r) ? 1 : -1;
            }
        if (agree > 0) {
            best->exact = 1;
            best->d = rat_get_d(&best->r);
        }
        snap(best);
    }
    free(r);
    return PTP_OK;
}

/* The number of terms the reading explains. */
static size_t score(const ctx *c, int which, const scale *s)
{
    size_t i, n = 0;
    for (i = 0; i < c->ng; i++) {
        const gterm *e = &c->g[i];
        n += e->v[which] >= 0 && !e->repeated && weight_is(&e->g, &c->x[which][e->v[which]].w, s);
    }
    return n;
}

/* The reading of the whole table: the exact table as it is, unless a scale, a negation or the
 * relabelled table explains more terms than that and more than half of the exact ones. */
static int choose(reading *best, const ctx *c, ptp_error *err)
{
    int which, st;
    best->which = 0;
    rat_set_si(&best->s.r, 1);
    best->s.d = 1;
    best->s.exact = 1;
    best->score = score(c, 0, &best->s);
    for (which = 0; which < 2; which++) {
        reading r;
        size_t count = 0;
        if (which == 1 && c->vfirst_negated)
            break;
        if ((st = best_scale(&r.s, &count, c, which, err)))
            return st;
        if (!count)
            continue;
        r.which = which;
        r.score = score(c, which, &r.s);
        if (r.score > best->score && 2 * r.score > c->nx)
            *best = r;
    }
    return PTP_OK;
}

/* Appends an item; returns 1 when it is a problem, 0 for a note. */
static int add_item(ctx *c, int kind, int line, size_t g, long v, int other)
{
    item *e = &c->it[c->nit++];
    e->kind = kind;
    e->line = line;
    e->g = g;
    e->v = v;
    e->other = other;
    return kind < NPROBLEMS;
}

/* The line of table term g. */
static int line_of(const ctx *c, size_t g)
{
    return c->d->terms[c->g[g].src].line;
}

/* An expected term keyed by its points first, for finding the plane that owns some points. */
typedef struct {
    int q[3], plane;
    long v;
} pkey;

static int cmp_pkey(const void *pa, const void *pb)
{
    const pkey *a = pa, *b = pb;
    int k = cmp_key(0, a->q, 0, b->q);
    return k ? k : (a->plane > b->plane) - (a->plane < b->plane);
}

/* s is 1. */
static int is_one(const scale *s)
{
    return s->exact && s->r.num == 1 && s->r.den == 1;
}

/* s is 1 or -1. */
static int is_unit(const scale *s)
{
    return s->exact && (s->r.num == 1 || s->r.num == -1) && s->r.den == 1;
}

/* Classifies the terms extra[0..nextra) without a counterpart, in the document's order: in the
 * wrong plane when the same points with the same weight are missing from another plane, else
 * extra; then the expected terms still not covered, missing. Returns the problem count. */
static size_t classify_extra(ctx *c, const reading *r, char *covered, const size_t *extra,
                             size_t nextra, pkey *by)
{
    const tp_term *x = c->x[r->which];
    size_t i, problems = 0;
    for (i = 0; i < c->nx; i++) {
        by[i].q[0] = x[i].j;
        by[i].q[1] = x[i].k;
        by[i].q[2] = x[i].l;
        by[i].plane = x[i].plane;
        by[i].v = (long)i;
    }
    qsort(by, c->nx, sizeof *by, cmp_pkey);
    for (i = 0; i < nextra; i++) {
        const gterm *e = &c->g[extra[i]];
        size_t lo = 0, hi = c->nx;
        long found = -1;
        if (e->g.d == 0) {
            add_item(c, N_ZERO, line_of(c, extra[i]), extra[i], -1, 0);
            continue;
        }
        while (lo < hi) { /* the first term with these points */
            size_t mid = lo + (hi - lo) / 2;
            if (cmp_key(0, by[mid].q, 0, e->q) < 0)
                lo = mid + 1;
            else
                hi = mid;
        }
        for (; lo < c->nx && found < 0 && !cmp_key(0, by[lo].q, 0, e->q); lo++)
            if (!covered[by[lo].v] && weight_is(&e->g, &x[by[lo].v].w, &r->s))
                found = by[lo].v;
        if (found >= 0)
            covered[found] = 1;
        problems += add_item(c, found >= 0 ? P_PLANE : P_EXTRA, line_of(c, extra[i]), extra[i],
                             found, 0);
    }
    for (i = 0; i < c->nx; i++)
        if (!covered[i])
            problems += add_item(c, P_MISSING, INT_MAX, 0, (long)i, 0);
    return problems;
}

/* Classifies every term of the table under reading r into c->it; returns the problem count. */
static size_t classify(ctx *c, const reading *r, char *covered, size_t *extra, pkey *by)
{
    const tp_term *x = c->x[r->which];
    size_t i = 0, j, k, nextra = 0, problems = 0;
    while (i < c->ng) {
        long v = c->g[i].v[r->which];
        size_t prim = c->ng;
        int kind = -1;
        for (j = i + 1; j < c->ng && !cmp_key(c->g[j].plane, c->g[j].q, c->g[i].plane, c->g[i].q); j++)
            ;
        if (c->g[i].repeated) {
            for (k = i; k < j; k++)
                add_item(c, N_REPEATED, line_of(c, k), k, -1, 0);
            i = j;
            continue;
        }
        if (v < 0) {
            extra[nextra++] = i; /* the first; the others repeat it */
            for (k = i + 1; k < j; k++)
                problems += add_item(c, P_DUP, line_of(c, k), k, -1, line_of(c, i));
            i = j;
            continue;
        }
        for (k = i; k < j && prim == c->ng; k++)
            if (weight_is(&c->g[k].g, &x[v].w, &r->s))
                prim = k, kind = c->g[k].flipped ? N_ORDER_OK : -1;
        for (k = i; k < j && prim == c->ng; k++)
            if (c->g[k].flipped && neg_weight_is(&c->g[k].g, &x[v].w, &r->s))
                prim = k, kind = P_ORDER;
        if (prim == c->ng)
            prim = i, kind = P_WEIGHT;
        if (kind >= 0)
            problems += add_item(c, kind, line_of(c, prim), prim, v, 0);
        for (k = i; k < j; k++)
            if (k != prim)
                problems += add_item(c, P_DUP, line_of(c, k), k, v, line_of(c, prim));
        covered[v] = 1;
        i = j;
    }
    return problems + classify_extra(c, r, covered, extra, nextra, by);
}


/* Writes sign * s * v, exact where s is; with its decimal too when decimal is set and it is a
 * fraction. */
static const char *expect_str(char *buf, const rat *v, const scale *s, int sign, int decimal)
{
    rat e;
    if (s->exact && !rat_mul(&e, v, &s->r)) {
        size_t n;
        if (sign < 0)
            rat_neg(&e, &e);
        rat_get_str(buf, &e);
        n = strlen(buf);
        if (decimal && e.den != 1)
            snprintf(buf + n, RAT_STRLEN + 32 - n, " (%.9g)", rat_get_d(&e));
        return buf;
    }
    snprintf(buf, RAT_STRLEN + 32, "%.9g", sign * s->d * rat_get_d(v));
    return buf;
}

/* Writes s's magnitude: its decimal, and p/q when exact and not an integer. */
static const char *scale_str(char *buf, const scale *s)
{
    size_t n;
    rat a;
    snprintf(buf, RAT_STRLEN + 32, "%.9g", dabs(s->d));
    if (s->exact && s->r.den != 1) {
        rat_neg(&a, &s->r);
        n = strlen(buf);
        buf[n++] = ' ';
        buf[n++] = '=';
        buf[n++] = ' ';
        rat_get_str(buf + n, rat_sgn(&s->r) < 0 ? &a : &s->r);
    }
    return buf;
}

/* Writes "{P, a, b, c} is W * cross4(ba, bb, bc) = G * cross4(bq0, bq1, bq2)": term w as
 * written, and as g reads it with its points in increasing order. */
static void put_reordered(sbuf *o, const verify_term *w, const gterm *g)
{
    char got[RAT_STRLEN + 32], neg[RAT_STRLEN + 32];
    sbuf_printf(o, "{%d, %d, %d, %d} is %s * cross4(b%d, b%d, b%d) = %s * cross4(b%d, b%d, b%d)",
                w->plane, w->p[0], w->p[1], w->p[2], verify_weight_str(got, &w->w), w->p[0],
                w->p[1], w->p[2], verify_weight_str(neg, &g->g), g->q[0], g->q[1], g->q[2]);
}

/* Writes the rest of the line of a wrong weight: term w (read as g) against exact term x under
 * r's scale. */
static void report_weight(sbuf *o, const reading *r, const verify_term *w, const gterm *g,
                          const tp_term *x)
{
    char got[RAT_STRLEN + 32], want[RAT_STRLEN + 32];
    sbuf_printf(o, "wrong weight: plane %d, cross4(b%d, b%d, b%d): got %s, expected %s",
                w->plane, w->p[0], w->p[1], w->p[2], verify_weight_str(got, &w->w),
                expect_str(want, &x->w, &r->s, g->flipped ? -1 : 1, !w->w.exact));
    if (g->flipped)
        sbuf_printf(o, " (the points are not in increasing order: that is -1 times the exact "
                       "term's weight for cross4(b%d, b%d, b%d))", g->q[0], g->q[1], g->q[2]);
    if (w->wline != w->line)
        sbuf_printf(o, " (the weight is on line %d)", w->wline);
    sbuf_puts(o, "\n");
}

/* Writes one report line for item e. */
static void report_item(sbuf *o, const ctx *c, const reading *r, const item *e)
{
    char got[RAT_STRLEN + 32], want[RAT_STRLEN + 32];
    const tp_term *x = e->v >= 0 ? &c->x[r->which][e->v] : NULL;
    const gterm *g = e->kind == P_MISSING ? NULL : &c->g[e->g];
    const verify_term *w = g ? &c->d->terms[g->src] : NULL;
    if (e->kind == P_MISSING) {
        sbuf_printf(o, "%s: missing term: plane %d: %s * cross4(b%d, b%d, b%d)\n", c->name,
                    x->plane, expect_str(want, &x->w, &r->s, 1, 0), x->j, x->k, x->l);
        return;
    }
    sbuf_printf(o, "%s:%d: ", c->name, e->line);
    switch (e->kind) {
    case P_EXTRA:
        sbuf_printf(o, "extra term: {%d, %d, %d, %d} with weight %s: the exact table has no "
                       "cross4(b%d, b%d, b%d) in plane %d\n", w->plane, w->p[0], w->p[1],
                    w->p[2], verify_weight_str(got, &w->w), g->q[0], g->q[1], g->q[2], g->plane);
        break;
    case P_WEIGHT:
        report_weight(o, r, w, g, x);
        break;
    case P_PLANE:
        sbuf_printf(o, "wrong plane: %s * cross4(b%d, b%d, b%d) is in plane %d but belongs to "
                       "plane %d\n", verify_weight_str(got, &w->w), w->p[0], w->p[1], w->p[2], w->plane,
                    x->plane);
        break;
    case P_DUP:
        sbuf_printf(o, "duplicated term: plane %d, cross4(b%d, b%d, b%d) repeats line %d\n",
                    w->plane, w->p[0], w->p[1], w->p[2], e->other);
        break;
    case P_ORDER:
        sbuf_puts(o, "points not in increasing order flip the sign: ");
        put_reordered(o, w, g);
        sbuf_printf(o, ", but the exact term is %s * cross4(b%d, b%d, b%d): "
                       "write {%d, %d, %d, %d}\n",
                    expect_str(want, &x->w, &r->s, 1, 0), x->j, x->k, x->l, w->plane, g->q[0],
                    g->q[1], g->q[2]);
        break;
    case N_ORDER_OK:
        sbuf_puts(o, "note: points not in increasing order: ");
        put_reordered(o, w, g);
        sbuf_puts(o, ", the exact term\n");
        break;
    case N_REPEATED:
        sbuf_printf(o, "note: {%d, %d, %d, %d} repeats a point: cross4 with a repeated point is "
                       "0, the term adds nothing\n", w->plane, w->p[0], w->p[1], w->p[2]);
        break;
    default: /* N_ZERO */
        sbuf_printf(o, "note: {%d, %d, %d, %d} has weight 0 and adds nothing (the exact table "
                       "has no such term)\n", w->plane, w->p[0], w->p[1], w->p[2]);
        break;
    }
}

/* The name of the index convention, v-first or not. */
static const char *conv_name(int vfirst)
{
    return vfirst ? "v-first" : "u-first";
}

/* Writes how convention vfirst numbers the points and planes of d, a quad (for triangles the
 * other convention is the negated table, which verdict_reading names instead). */
static void numbering(sbuf *o, const tp_domain *d, int vfirst)
{
    if (vfirst)
        sbuf_printf(o, "point (i, j) numbered j*%d+i and plane (I, J) numbered J*%d+I", d->n + 1,
                    d->pu + 1);
    else
        sbuf_printf(o, "point (i, j) numbered i*%d+j and plane (I, J) numbered I*%d+J", d->m + 1,
                    d->pv + 1);
}

/* Writes what reading r is, e.g. "the exact table scaled by 2" (nothing for the exact table). */
static void reading_str(sbuf *o, const ctx *c, const reading *r)
{
    char s[RAT_STRLEN + 32];
    int neg = r->s.d < 0;
    if (r->which == 0)
        sbuf_puts(o, neg ? "the exact table negated" : "the exact table");
    else if (neg)
        sbuf_puts(o, "the exact table with u and v swapped");
    else
        sbuf_printf(o, "the exact table in the %s index convention", conv_name(!c->vfirst));
    if (!is_unit(&r->s))
        sbuf_printf(o, "%s scaled by %s", neg || r->which ? " and" : "", scale_str(s, &r->s));
}

/* Writes the verdict on a table with problems: their counts by kind. */
static void verdict_problems(sbuf *o, const ctx *c, const reading *r, const size_t *count,
                             size_t problems)
{
    static const char *const names[NPROBLEMS][2] = {
        {"missing term", "missing terms"},
        {"extra term", "extra terms"},
        {"wrong weight", "wrong weights"},
        {"wrong plane", "wrong planes"},
        {"duplicated term", "duplicated terms"},
        {"sign flipped by the order of the points", "signs flipped by the order of the points"},
        {"problem in iwgt, owner or the sched arrays",
         "problems in iwgt, owner or the sched arrays"}};
    tp_domain_text x;
    int k, first = 1;
    tp_domain_text_get(&x, &c->t->dom);
    sbuf_printf(o, "WRONG: %zu problem%s (", problems, problems == 1 ? "" : "s");
    for (k = 0; k < NPROBLEMS; k++)
        if (count[k]) {
            sbuf_printf(o, "%s%zu %s", first ? "" : ", ", count[k], names[k][count[k] != 1]);
            first = 0;
        }
    sbuf_printf(o, ") against the %zu terms of %s", c->nx, x.name);
    if (r->which || !is_one(&r->s)) {
        sbuf_puts(o, ", read as ");
        reading_str(o, c, r);
    }
    sbuf_puts(o, "\n");
}

/* How well the weights of a table read as the exact one (scale 1) carry the exact values:
 * PREC_EXACT when each is exact (or iwgt/DENOM gives it exactly), PREC_FLOAT when each is the
 * float nearest the exact weight, else PREC_TOL (within TOL), *worst the largest relative error. */
enum { PREC_EXACT, PREC_FLOAT, PREC_TOL };

static int precision(double *worst, const ctx *c, const reading *r, int iwgt_exact)
{
    int prec = PREC_EXACT;
    size_t i;
    *worst = 0;
    for (i = 0; i < c->ng && !iwgt_exact; i++) {
        const gterm *e = &c->g[i];
        double want, err;
        if (e->v[r->which] < 0 || e->repeated || e->g.exact)
            continue;
        want = rat_get_d(&c->x[r->which][e->v[r->which]].w);
        err = dabs(e->g.d - want) / dabs(want);
        *worst = err > *worst ? err : *worst;
        if ((float)e->g.d != (float)want)
            prec = PREC_TOL;
        else if (prec == PREC_EXACT)
            prec = PREC_FLOAT;
    }
    return prec;
}

/* Writes the verdict on the exact table up to a positive scale. */
static void verdict_right(sbuf *o, const ctx *c, const reading *r, int iwgt_exact)
{
    char s[RAT_STRLEN + 32], conv[32] = "";
    tp_domain_text x;
    double worst;
    tp_domain_text_get(&x, &c->t->dom);
    if (c->vfirst)
        snprintf(conv, sizeof conv, " (v-first)");
    if (!is_one(&r->s)) {
        sbuf_printf(o, "RIGHT: correct up to a positive scale s = %s: every weight is s times the "
                       "exact one, so every sign, and so the classification, is unchanged (%zu "
                       "terms, %s%s)\n", scale_str(s, &r->s), c->nx, x.name, conv);
        return;
    }
    switch (precision(&worst, c, r, iwgt_exact)) {
    case PREC_EXACT: sbuf_puts(o, "RIGHT: exact"); break;
    case PREC_FLOAT: sbuf_puts(o, "RIGHT: right to float precision (|error| <= 1/2 ulp)"); break;
    default:
        sbuf_printf(o, "RIGHT: right to a relative error of %.2g (within the tolerance %g, but some "
                       "weights are not the float nearest the exact one)", worst, TOL);
    }
    sbuf_printf(o, ": the %zu terms of %s%s agree with the derivation%s\n", c->nx, x.name, conv,
                c->d->nfunctions ? " (the arrays only: the code of its functions is not checked)"
                                 : "");
}

/* Writes the verdict on a table that reads as a whole as another one. */
static void verdict_reading(sbuf *o, const ctx *c, const reading *r)
{
    const tp_table *t = c->t;
    char s[RAT_STRLEN + 32];
    int neg = r->s.d < 0;
    tp_domain tr;
    tp_domain_text x, xt;
    tp_domain_transpose(&tr, &t->dom);
    tp_domain_text_get(&x, &t->dom);
    tp_domain_text_get(&xt, &tr);
    if (r->which == 0)
        sbuf_puts(o, "WRONG: all weights negated");
    else if (neg)
        sbuf_puts(o, "WRONG: u and v swapped");
    else
        sbuf_printf(o, "WRONG: the %s index convention", conv_name(!c->vfirst));
    if (!is_unit(&r->s))
        sbuf_printf(o, ", and every weight scaled by %s", scale_str(s, &r->s));
    if (r->which == 0) {
        sbuf_puts(o, ": the table of the opposite orientation, which takes front-facing patches "
                     "for back-facing ones");
        if (c->vfirst_negated)
            sbuf_printf(o, "; for a %s that is also the exact table in the %s index "
                           "convention, right only for code that numbers points %s (check it "
                           "with --convention %s)",
                        t->dom.kind == TP_TRI ? "triangle" : "square patch",
                        conv_name(!c->vfirst), conv_name(!c->vfirst), conv_name(!c->vfirst));
    } else if (neg) {
        sbuf_printf(o, ": it is%s the exact table of %s, the transposed patch (i along v), which "
                       "for a %s patch has the opposite orientation",
                    is_unit(&r->s) ? "" : ", up to the scale,", xt.name, x.degree);
    } else {
        sbuf_puts(o, ": the same planes, but ");
        numbering(o, &t->dom, !c->vfirst);
        sbuf_printf(o, ": right only for code that numbers points %s (check it with --convention "
                       "%s); the %s convention checked numbers ", conv_name(!c->vfirst),
                    conv_name(!c->vfirst), conv_name(c->vfirst));
        numbering(o, &t->dom, c->vfirst);
    }
    sbuf_printf(o, " (%zu terms, %s)\n", c->nx, x.name);
}

/* Writes the verdict line. */
static void report_verdict(sbuf *o, int *verdict, const ctx *c, const reading *r,
                           const size_t *count, size_t problems, int iwgt_exact)
{
    sbuf_printf(o, "%s: ", c->name);
    if (problems) {
        verdict_problems(o, c, r, count, problems);
    } else if (r->which == 0 && r->s.d > 0) {
        *verdict = VERIFY_RIGHT;
        verdict_right(o, c, r, iwgt_exact);
    } else {
        verdict_reading(o, c, r);
    }
}

/* The number in tr, d transposed, of point x of d (of plane x, if plane). */
static int swap_uv(const tp_domain *d, const tp_domain *tr, int x, int plane)
{
    int a, b;
    if (plane) {
        tp_domain_plane_ij(&a, &b, d, x);
        return tp_domain_plane(tr, b, a);
    }
    tp_domain_point_ij(&a, &b, d, x);
    return tp_domain_point(tr, b, a);
}

/* Builds c->x[1], the exact table relabelled (i, j) -> (j, i) without negation, sorted. */
static int relabel(ctx *c, ptp_error *err)
{
    tp_domain tr;
    size_t i;
    if (!(c->x[1] = c->owned = malloc((c->nx ? c->nx : 1) * sizeof *c->x[1])))
        return ptp_fail(err, PTP_ENOMEM, "out of memory checking %s", c->name);
    c->vfirst_negated = 1;
    tp_domain_transpose(&tr, &c->t->dom);
    for (i = 0; i < c->nx; i++) {
        tp_term *e = &c->x[1][i];
        int p[3], q;
        *e = c->x[0][i];
        p[0] = e->j;
        p[1] = e->k;
        p[2] = e->l;
        e->plane = swap_uv(&c->t->dom, &tr, e->plane, 1);
        for (q = 0; q < 3; q++)
            p[q] = swap_uv(&c->t->dom, &tr, p[q], 0);
        if (sort3(p))
            rat_neg(&e->w, &e->w);
        e->j = p[0];
        e->k = p[1];
        e->l = p[2];
    }
    qsort(c->x[1], c->nx, sizeof *c->x[1], cmp_tp);
    for (i = 0; i < c->nx && c->vfirst_negated; i++) {
        rat w;
        rat_neg(&w, &c->x[0][i].w);
        c->vfirst_negated = !cmp_tp(&c->x[0][i], &c->x[1][i]) && rat_equal(&w, &c->x[1][i].w);
    }
    if (c->vfirst) {
        c->x[1] = c->x[0];
        c->x[0] = c->owned;
    }
    return PTP_OK;
}

/* Fills c->g from the document's terms, sorted, with their counterparts in c->x. */
static void load_terms(ctx *c)
{
    size_t i;
    for (i = 0; i < c->ng; i++) {
        gterm *e = &c->g[i];
        const verify_term *w = &c->d->terms[i];
        memcpy(e->q, w->p, sizeof e->q);
        e->plane = w->plane;
        e->flipped = sort3(e->q);
        e->repeated = e->q[0] == e->q[1] || e->q[1] == e->q[2];
        e->g = w->w;
        if (e->flipped) {
            e->g.d = -e->g.d;
            rat_neg(&e->g.r, &e->g.r);
        }
        e->src = i;
        e->v[0] = find(c->x[0], c->nx, e->plane, e->q);
        e->v[1] = c->vfirst_negated ? -1 : find(c->x[1], c->nx, e->plane, e->q);
    }
    qsort(c->g, c->ng, sizeof *c->g, cmp_g);
}

/* Runs verify_arrays with the exact weight of every term as written under reading r. */
static int check_arrays(sbuf *o, verify_arrays_result *res, const ctx *c, const reading *r,
                        ptp_error *err)
{
    rat *want = malloc((c->ng + 1) * sizeof *want);
    char *known = calloc(c->ng + 1, 1);
    size_t i;
    int st;
    for (i = 0; want && known && i < c->ng; i++) {
        const gterm *e = &c->g[i];
        long v = e->v[r->which];
        rat *w = &want[e->src];
        if (v < 0 || e->repeated || !r->s.exact || rat_mul(w, &c->x[r->which][v].w, &r->s.r))
            continue;
        if (e->flipped)
            rat_neg(w, w);
        known[e->src] = 1;
    }
    st = want && known ? verify_arrays(o, res, c->d, want, known, c->t->dom.nplanes, c->name, err)
                       : ptp_fail(err, PTP_ENOMEM, "out of memory checking %s", c->name);
    free(want);
    free(known);
    return st;
}

/* Writes the report on c under reading r with its problem count to rep. */
static int write_report(sbuf *rep, int *verdict, ctx *c, const reading *r, size_t problems,
                        ptp_error *err)
{
    const verify_doc *d = c->d;
    const tp_domain *dom = &c->t->dom;
    size_t i, count[NPROBLEMS] = {0};
    verify_arrays_result ares;
    char deg[16], named[32];
    int a, b, st;
    qsort(c->it, c->nit, sizeof *c->it, cmp_item);
    if (d->degree_named && (d->n != dom->n || d->m != dom->m))
        sbuf_printf(rep, "%s:%d: note: the %s names %s; checked as %s\n", c->name,
                    d->degree_line, d->degree_named == 1 ? "document" : "array name",
                    verify_degree_name(named, dom->kind, d->n, d->m),
                    tp_domain_format(deg, sizeof deg, dom));
    for (i = 0; i < c->nit; i++) {
        report_item(rep, c, r, &c->it[i]);
        if (c->it[i].kind < NPROBLEMS)
            count[c->it[i].kind]++;
    }
    if ((st = check_arrays(rep, &ares, c, r, err)))
        return st;
    count[P_ARRAY] = ares.problems;
    problems += ares.problems;
    if (problems && verify_doc_fit(&a, &b, d, dom->kind) &&
        !((a == dom->n && b == dom->m) || (a == dom->m && b == dom->n)))
        sbuf_printf(rep, "%s: note: the indices fit %s, not %s\n", c->name,
                    verify_degree_name(named, dom->kind, a, b), tp_domain_format(deg, sizeof deg, dom));
    report_verdict(rep, verdict, c, r, count, problems, ares.iwgt_exact);
    return PTP_OK;
}

/* Checks document d against the exact table t (in convention vfirst) and appends the report
 * to o. */
static int check(sbuf *o, int *verdict, const verify_doc *d, const tp_table *t, int vfirst,
                 const char *name, ptp_error *err)
{
    ctx c;
    reading r;
    char *covered = NULL;
    size_t *extra = NULL;
    pkey *by = NULL;
    int st;
    sbuf rep;
    memset(&c, 0, sizeof c);
    c.d = d;
    c.t = t;
    c.name = name;
    c.vfirst = vfirst;
    c.x[0] = t->terms;
    c.nx = t->nterms;
    c.ng = d->nterms;
    sbuf_init(&rep);
    if ((st = relabel(&c, err)))
        return st;
    c.g = malloc((c.ng ? c.ng : 1) * sizeof *c.g);
    c.it = malloc((c.ng + c.nx + 1) * sizeof *c.it);
    covered = calloc(c.nx + 1, 1);
    extra = malloc((c.ng + 1) * sizeof *extra);
    by = malloc((c.nx + 1) * sizeof *by);
    if (!c.g || !c.it || !covered || !extra || !by) {
        st = ptp_fail(err, PTP_ENOMEM, "out of memory checking %s", name);
    } else {
        load_terms(&c);
        if (!(st = choose(&r, &c, err)))
            st = write_report(&rep, verdict, &c, &r, classify(&c, &r, covered, extra, by), err);
    }
    if (!st && (rep.failed || (sbuf_puts(o, rep.s), o->failed)))
        st = ptp_fail(err, PTP_ENOMEM, "out of memory writing the report on %s", name);
    if (st)
        *verdict = VERIFY_WRONG;
    sbuf_clear(&rep);
    free(c.owned);
    free(c.g);
    free(c.it);
    free(covered);
    free(extra);
    free(by);
    return st;
}

/* PTP_EUSAGE with the line of the first term whose index is out of range for the domain. */
static int check_range(const verify_doc *d, const tp_domain *dom, const char *name,
                       ptp_error *err)
{
    int planes = dom->nplanes, points = dom->npoints, q;
    tp_domain_text t;
    size_t x;
    tp_domain_text_get(&t, dom);
    for (x = 0; x < d->nterms; x++) {
        const verify_term *e = &d->terms[x];
        if (e->plane >= planes)
            return ptp_fail(err, PTP_EUSAGE, "%s:%d: plane %d out of range: %s has %d planes "
                                             "(0..%d)", name, e->line, e->plane, t.name, planes,
                            planes - 1);
        for (q = 0; q < 3; q++)
            if (e->p[q] >= points)
                return ptp_fail(err, PTP_EUSAGE, "%s:%d: point %d out of range: %s has %d "
                                                 "points (0..%d)", name, e->line, e->p[q], t.name,
                                points, points - 1);
    }
    return PTP_OK;
}

int verify_table(sbuf *out, int *verdict, const char *text, size_t len, const char *name,
                 int kind, int n, int m, int convention, ptp_error *err)
{
    verify_doc d;
    tp_domain dom;
    tp_table t;
    int st, max = kind == TP_TRI ? PTP_MAX_TRI_DEGREE : PTP_MAX_DEGREE;
    char deg[32];
    *verdict = VERIFY_WRONG;
    name = name ? name : "(input)";
    if (n < 0 || m < 0 || (n == 0) != (m == 0))
        return ptp_fail(err, PTP_EUSAGE, "%s: bad %s", name,
                        verify_degree_name(deg, kind == TP_TRI ? TP_TRI : TP_QUAD, n, m));
    if (n > max || m > max)
        return ptp_fail(err, PTP_ELIMIT, "%s: the largest supported degree is %d",
                        verify_degree_name(deg, kind == TP_TRI ? TP_TRI : TP_QUAD, n, m), max);
    if ((st = verify_parse(&d, text, len, name, err)))
        return st;
    if (!(st = verify_doc_domain(&dom, &d, kind, n, m, name, err)) &&
        !(st = check_range(&d, &dom, name, err)) && !(st = tp_derive_domain(&t, &dom, err))) {
        st = check(out, verdict, &d, &t, convention == VERIFY_V_FIRST, name, err);
        tp_clear(&t);
    }
    verify_doc_clear(&d);
    return st;
}
