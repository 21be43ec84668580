/* slp_cost.c: per-plane costs of the bracket and the fused form of slp.h's straight-line
 * program, and the choice among them and the point form (slp_point.h). */
#include "plan/slp_cost.h"
#include "plan/slp_point.h"

#include <stdlib.h>

enum { LAT_MUL = 3, LAT_ADD = 3, LAT_FMA = 4 };

static long max_l(long x, long y)
{
    return x > y ? x : y;
}

/* The number of distinct points of terms [g, e): the products of the group's fused form. */
static long group_points(const slp_prog *p, size_t g, size_t e)
{
    long n = 0;
    size_t i, j;
    int k, m;
    for (i = g; i < e; i++)
        for (k = 0; k < 3; k++) {
            int seen = 0, pt = p->terms[i].point[k];
            for (j = g; j < i && !seen; j++)
                for (m = 0; m < 3; m++)
                    seen |= p->terms[j].point[m] == pt;
            n += !seen;
        }
    return n;
}

void slp_cost_plane(slp_cost *bracket, slp_cost *fused, const slp_prog *p, size_t a, size_t b)
{
    size_t g, e;
    long groups = 0, cb = 0, cf = 0;
    rat one;
    rat_set_si(&one, 1);
    *bracket = *fused = (slp_cost){0, 0, 0};
    for (g = a; g < b; g = e, groups++) {
        const rat *s = &p->s[p->terms[g].group];
        slp_scale c;
        long t, pts, dbl = slp_scale_of(&c, s) ? c.adds : 0, scale = !rat_equal(s, &one) && !dbl;
        for (e = g; e < b && p->terms[e].group == p->terms[g].group; e++)
            ;
        t = (long)(e - g);
        pts = group_points(p, g, e);
        bracket->muls += 3 * t + scale;
        bracket->ops += 6 * t - 1 + scale + dbl;
        fused->muls += pts + scale;
        fused->ops += 3 * t + scale + dbl;
        /* bracket: three products, two sums, then the terms' sums in turn; fused: the sums of a
           point's minors, then one multiply-add per point in turn; the scale s: a product, or
           dbl adds (slp_scale_of) */
        cb = max_l(cb, LAT_MUL + 2 * LAT_ADD + LAT_ADD * (t - 1) + scale * LAT_MUL + dbl * LAT_ADD);
        cf = max_l(cf, LAT_ADD * (3 * t > pts) + LAT_MUL + LAT_FMA * (pts - 1) + scale * LAT_MUL +
                    dbl * LAT_ADD);
    }
    bracket->ops += groups - 1; /* the groups' sum */
    fused->ops += groups - 1;
    bracket->chain = cb + LAT_FMA * (groups - 1);
    fused->chain = cf + LAT_FMA * (groups - 1);
}

/* The end of plane p->terms[a]'s terms. */
static size_t plane_end(const slp_prog *p, size_t a)
{
    size_t b = a;
    while (b < p->nterms && p->terms[b].plane == p->terms[a].plane)
        b++;
    return b;
}

/* The bracket or fused form of plane terms [a, b) (costs br, fu), as the header describes;
 * ops, the program's instructions in the bracket form. */
static int base_form(const slp_prog *p, size_t a, const slp_cost *br, const slp_cost *fu, long ops)
{
    return p->zero[p->terms[a].plane] || fu->ops >= br->ops ||
                   (ops <= SLP_COST_ICACHE_OPS && 2 * (br->ops - fu->ops) < 3 * (fu->chain - br->chain))
               ? SLP_BRACKET
               : SLP_FUSED;
}

/* The form of plane terms [a, b): the point form where the header says, else base (costs c);
 * items has room for 3 (b - a). */
static int point_form(int *form, slp_item *items, const slp_prog *p, size_t a, size_t b,
                      const slp_cost *c, long ops)
{
    size_t n;
    slp_point_sum pt;
    int st = ops <= SLP_COST_ICACHE_OPS ? slp_point_build(items, &n, p, a, b) : 1;
    if (st)
        return st == PTP_ENOMEM ? st : PTP_OK;
    slp_point_plane(&pt, items, n, 0);
    if (pt.muls + pt.fmas < c->muls && pt.muls + pt.fmas + pt.adds <= c->ops)
        *form = SLP_POINT;
    return PTP_OK;
}

int slp_cost_forms(slp_prog *p)
{
    long ops = 3L * (long)p->npairs + p->npoints; /* the minors and G's */
    size_t a, b;
    slp_cost br, fu;
    slp_item *items = malloc((3 * p->nterms + 1) * sizeof *items);
    int st = items ? PTP_OK : PTP_ENOMEM;
    for (a = 0; a < p->nterms; a = plane_end(p, a)) {
        slp_cost_plane(&br, &fu, p, a, plane_end(p, a));
        ops += br.ops;
    }
    for (a = 0; a < p->nterms && !st; a = b) {
        int form;
        b = plane_end(p, a);
        slp_cost_plane(&br, &fu, p, a, b);
        form = base_form(p, a, &br, &fu, ops);
        st = point_form(&form, items, p, a, b, form == SLP_BRACKET ? &br : &fu, ops);
        p->form[p->terms[a].plane] = (unsigned char)form;
    }
    free(items);
    return st;
}
