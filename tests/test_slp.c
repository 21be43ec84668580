/* test_slp.c: the straight-line program's forms: exact where a collapsed edge needs zeros, the
 * cost model's choice elsewhere, and the operation counts of what is chosen. */
#include "check.h"
#include "core/tplane.h"
#include "plan/slp_cost.h"
#include "plan/slp_point.h"

#include <math.h>
#include <stdlib.h>

/* The multiply-pipe operations of p's minors and G's, clip space (as slp_muls counts them). */
static long shared_muls(const slp_prog *p)
{
    return 2L * (long)p->npairs + p->npoints;
}

/* The multiply-pipe operations of point-form plane P of p (clip space). */
static long point_muls(const slp_prog *p, int P)
{
    size_t a = 0, b;
    slp_point_sum s = {0, 0, 0, 0, 0, 0};
    while (a < p->nitems && p->items[a].plane != P)
        a++;
    b = slp_point_plane_end(p->items, p->nitems, a);
    slp_point_plane(&s, p->items + a, b - a, 0);
    return s.muls + s.fmas;
}

/* Plane P of p (point form, items [a, b)) in float as the C target evaluates it (clip space, a
 * multiply-add as fmaf), at points x, y, w and eye e2. */
static float point_value(const slp_prog *p, size_t a, size_t b, const float (*q)[3], float e2)
{
    size_t f, fe, c, ce, i;
    float v = 0;
    for (f = a; f < b; f = fe) {
        float u = 0, G = e2 * q[p->items[f].point][2];
        fe = slp_point_factor_end(p->items, b, f);
        for (c = f; c < fe; c = ce) {
            long k = labs(p->items[c].coef);
            float t = 0;
            ce = slp_point_class_end(p->items, b, c);
            for (i = c; i < ce; i++) {
                const slp_item *y = &p->items[i];
                const slp_pair *r = &p->pairs[y->pair];
                float mv = q[r->k][0] * q[r->l][1] - q[r->k][1] * q[r->l][0];
                t = i == c ? (y->coef < 0 ? -mv : mv) : y->coef < 0 ? t - mv : t + mv;
            }
            if (!slp_point_by_adds(k, c == f))
                u = c == f ? (float)k * t : fmaf((float)k, t, u);
            else
                u = c == f ? (k == 2 ? t + t : t) : u + t;
        }
        v = f == a ? G * u : fmaf(G, u, v);
    }
    return v;
}

/* Checks p's point-form planes: none is along an edge, and on random points each is within
 * 2^-12 of the double value of the table's terms (relative to their magnitudes); returns the
 * number of point-form planes. */
static int count_point(prop *pr, const slp_prog *p, const tp_table *t, int n, int m)
{
    float q[64][3];
    size_t a, b, i;
    int planes = 0, round, k;
    for (a = 0; a < p->nitems; a = b, planes++) {
        int P = p->items[a].plane;
        b = slp_point_plane_end(p->items, p->nitems, a);
        if (p->zero[P])
            prop_fail(pr, "%dx%d plane %d: along an edge, but in the point form", n, m, P);
        for (round = 0; round < 20; round++) {
            double want = 0, mag = 0;
            float got;
            for (k = 0; k < p->npoints; k++)
                for (i = 0; i < 3; i++)
                    q[k][i] = (float)(rand() % 2001 - 1000) / 256.0f;
            got = point_value(p, a, b, (const float(*)[3])q, 1.5f);
            for (i = 0; i < t->nterms; i++) {
                const tp_term *x = &t->terms[i];
                const float *r0 = q[x->j], *r1 = q[x->k], *r2 = q[x->l];
                double d = (double)r0[0] * ((double)r1[1] * r2[2] - (double)r1[2] * r2[1]) -
                           (double)r0[1] * ((double)r1[0] * r2[2] - (double)r1[2] * r2[0]) +
                           (double)r0[2] * ((double)r1[0] * r2[1] - (double)r1[1] * r2[0]);
                if (x->plane != P)
                    continue;
                want += 1.5 * rat_get_d(&x->w) * rat_get_d(&p->c[P]) * d;
                mag += fabs(1.5 * rat_get_d(&x->w) * rat_get_d(&p->c[P])) * 6 * 64;
            }
            if (fabs(got - want) > 0x1p-12 * (mag + 1))
                prop_fail(pr, "%dx%d plane %d: the point form gives %.9g, the terms %.9g", n, m, P,
                          (double)got, want);
        }
    }
    return planes;
}

/* Checks the forms of one domain's program; counts its fused planes into *fused and its
 * point-form planes into *point. */
static void check_domain(prop *pr, int *fused, int *point, tp_kind kind, int n, int m,
                         long *muls_out)
{
    tp_domain dom;
    tp_table t;
    slp_prog p;
    ptp_error err;
    size_t a, b;
    long muls;
    *fused = *point = -1;
    pr->tried++;
    if (tp_domain_init(&dom, kind, n, m, &err) || tp_derive_domain(&t, &dom, &err)) {
        prop_fail(pr, "%s %dx%d: %s", kind == TP_TRI ? "triangle" : "quad", n, m, err.msg);
        return;
    }
    if (slp_build(&p, &t, &err)) {
        prop_fail(pr, "%dx%d: %s", n, m, err.msg);
        tp_clear(&t);
        return;
    }
    muls = shared_muls(&p);
    *fused = 0;
    for (a = 0; a < p.nterms; a = b) {
        int P = p.terms[a].plane, f = p.form[P];
        slp_cost br, fu;
        for (b = a; b < p.nterms && p.terms[b].plane == P; b++)
            ;
        slp_cost_plane(&br, &fu, &p, a, b);
        muls += f == SLP_BRACKET ? br.muls : f == SLP_FUSED ? fu.muls : point_muls(&p, P);
        *fused += f == SLP_FUSED;
        if (p.zero[P] && f == SLP_FUSED)
            prop_fail(pr, "%dx%d plane %d: a collapsed edge zeros it, but it is fused", n, m, P);
        if (f == SLP_FUSED && fu.ops >= br.ops)
            prop_fail(pr, "%dx%d plane %d: fused without saving instructions", n, m, P);
        if (fu.ops >= br.ops || fu.chain <= br.chain || fu.muls > br.muls)
            prop_fail(pr, "%dx%d plane %d: fusing should save instructions for a longer chain "
                          "(ops %ld -> %ld, chain %ld -> %ld, muls %ld -> %ld)", n, m, P, br.ops,
                      fu.ops, br.chain, fu.chain, br.muls, fu.muls);
    }
    *point = count_point(pr, &p, &t, n, m);
    if (muls_out)
        *muls_out = slp_muls(&p, 0);
    if (muls != slp_muls(&p, 0))
        prop_fail(pr, "%dx%d: the chosen forms have %ld multiply-pipe operations, slp_muls %ld",
                  n, m, muls, slp_muls(&p, 0));
    slp_clear(&p);
    tp_clear(&t);
}

/* slp_point_plane's counts and roundings on two small planes, derived by hand (clip space):
 * v = g0 m1_2 (monomials e2 w0 x1 y2, e2 w0 y1 x2: g 1 rounding, the minor's product and
 * difference 2, the product 1); then v = fma(g1, 3 (m0_2 + m0_3), v). */
static void check_point_sums(void)
{
    const slp_item one[] = {{0, 0, 0, 1}};
    const slp_item two[] = {{0, 0, 0, 1}, {0, 1, 1, 3}, {0, 1, 2, 3}};
    slp_point_sum s;
    slp_point_plane(&s, one, 1, 0);
    check(s.muls == 1 && s.fmas == 0 && s.adds == 0 && s.w == 2 && s.dsum == 8 && s.dmax == 4,
          "slp_point: G M is one product, 2 monomials through 4 roundings",
          "muls %ld fmas %ld adds %ld w %g dsum %g dmax %g", s.muls, s.fmas, s.adds, s.w, s.dsum, s.dmax);
    /* the second point: g1 (1 monomial, depth 1) times 3 (m0_2 + m0_3) (4 monomials at depth 3,
       times 3 by a product: 12 at depth 4); the fma's product adds 2: 12 at 1 + 4 + 2 = 7; the
       first point's 2 monomials 1 more: 5 */
    slp_point_plane(&s, two, 3, 0);
    check(s.muls == 2 && s.fmas == 1 && s.adds == 1 && s.w == 14 && s.dsum == 12 * 7 + 2 * 5 && s.dmax == 7,
          "slp_point: a point's class of weight 3 by a product, the points by a multiply-add",
          "muls %ld fmas %ld adds %ld w %g dsum %g dmax %g", s.muls, s.fmas, s.adds, s.w, s.dsum, s.dmax);
}

int main(void)
{
    static const int quad[][2] = {{1, 1}, {2, 2}, {2, 3}, {3, 3}, {4, 4}, {3, 1}};
    int i, fused, point, tri3 = -1, tri3_point = -1, bicubic = -1, bicubic_point = -1;
    long tri3_muls = 0;
    prop pr;
    srand(7);
    prop_init(&pr, "slp forms: collapsed-edge planes exact, fused planes save instructions, "
                   "point-form planes off the edges and accurate, slp_muls counts the chosen forms");
    for (i = 0; i < (int)(sizeof quad / sizeof *quad); i++) {
        check_domain(&pr, &fused, &point, TP_QUAD, quad[i][0], quad[i][1], NULL);
        if (quad[i][0] == 3 && quad[i][1] == 3) {
            bicubic = fused;
            bicubic_point = point;
        }
    }
    for (i = 1; i <= 4; i++) {
        check_domain(&pr, &fused, &point, TP_TRI, i, i, i == 3 ? &tri3_muls : NULL);
        if (i == 3) {
            tri3 = fused;
            tri3_point = point;
        }
    }
    prop_report(&pr);
    check_point_sums();
    check(tri3 == 0 && tri3_point == 6 && tri3_muls == 403,
          "slp cost: the cubic triangle (a small program) takes the point form where it saves "
          "multiply-pipe operations and instructions (6 of its 10 interior planes, 403 "
          "multiply-pipe operations, from 415 in the bracket form)", "%d fused, %d point-form planes, %ld operations",
          tri3, tri3_point, tri3_muls);
    check(bicubic == 36 && bicubic_point == 0,
          "slp cost: the bicubic program (past the instruction cache) fuses every plane that saves "
          "instructions", "%d fused planes, not 36; %d point-form", bicubic, bicubic_point);
    return check_failed_count != 0;
}
