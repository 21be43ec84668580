/* test_slp.c: the straight-line program's forms: exact where a collapsed edge needs zeros, the
 * cost model's choice elsewhere, and the operation counts of what is chosen. */
#include "check.h"
#include "core/tplane.h"
#include "plan/slp_cost.h"

/* The multiply-pipe operations of p's minors and G's, clip space (as slp_muls counts them). */
static long shared_muls(const slp_prog *p)
{
    return 2L * (long)p->npairs + p->npoints;
}

/* Checks the forms of one domain's program; counts its fused planes into *fused. */
static void check_domain(prop *pr, int *fused, tp_kind kind, int n, int m)
{
    tp_domain dom;
    tp_table t;
    slp_prog p;
    ptp_error err;
    size_t a, b;
    long muls;
    *fused = -1;
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
        int P = p.terms[a].plane;
        slp_cost br, fu;
        for (b = a; b < p.nterms && p.terms[b].plane == P; b++)
            ;
        slp_cost_plane(&br, &fu, &p, a, b);
        muls += p.exact[P] ? br.muls : fu.muls;
        *fused += !p.exact[P];
        if (p.zero[P] && !p.exact[P])
            prop_fail(pr, "%dx%d plane %d: a collapsed edge zeros it, but it is fused", n, m, P);
        if (!p.exact[P] && fu.ops >= br.ops)
            prop_fail(pr, "%dx%d plane %d: fused without saving instructions", n, m, P);
        if (fu.ops >= br.ops || fu.chain <= br.chain || fu.muls > br.muls)
            prop_fail(pr, "%dx%d plane %d: fusing should save instructions for a longer chain "
                          "(ops %ld -> %ld, chain %ld -> %ld, muls %ld -> %ld)", n, m, P, br.ops,
                      fu.ops, br.chain, fu.chain, br.muls, fu.muls);
    }
    if (muls != slp_muls(&p, 0))
        prop_fail(pr, "%dx%d: the chosen forms have %ld multiply-pipe operations, slp_muls %ld",
                  n, m, muls, slp_muls(&p, 0));
    slp_clear(&p);
    tp_clear(&t);
}

int main(void)
{
    static const int quad[][2] = {{1, 1}, {2, 2}, {2, 3}, {3, 3}, {4, 4}, {3, 1}};
    int i, fused, tri3 = -1, bicubic = -1;
    prop pr;
    prop_init(&pr, "slp forms: collapsed-edge planes exact, fused planes save instructions, "
                   "slp_muls counts the chosen forms");
    for (i = 0; i < (int)(sizeof quad / sizeof *quad); i++) {
        check_domain(&pr, &fused, TP_QUAD, quad[i][0], quad[i][1]);
        if (quad[i][0] == 3 && quad[i][1] == 3)
            bicubic = fused;
    }
    for (i = 1; i <= 4; i++) {
        check_domain(&pr, &fused, TP_TRI, i, i);
        if (i == 3)
            tri3 = fused;
    }
    prop_report(&pr);
    check(tri3 == 0, "slp cost: the cubic triangle (a small program, latency bound) keeps every plane in the bracket form",
          "%d fused planes", tri3);
    check(bicubic == 36, "slp cost: the bicubic program (past the instruction cache) fuses every plane that saves instructions",
          "%d fused planes, not 36", bicubic);
    return check_failed_count != 0;
}
