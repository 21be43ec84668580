/* plan.c: the straight-line plan of a table, built once: the program, its operation counts and,
 * certified, its margins. */
#include "plan/plan.h"

long plan_frame_muls(int k, int world)
{
    int c = world ? 3 : 2; /* the shifted coordinates of a point */
    return c + (long)c * k + (world ? 3 : 0);
}

long plan_frame_flops(int k, int world)
{
    int c = world ? 3 : 2;
    return 1 + c + 2 * ((long)c * k + (world ? 3 : 0)); /* a multiply-add counts two */
}

long plan_bspline_muls(int world)
{
    return (world ? 4 : 3) * 48L;
}

long plan_bspline_flops(int world)
{
    return (world ? 4 : 3) * 96L;
}

int plan_slp_build(plan_slp *p, const tp_table *t, int world, int form,
                   const cert_model *certified, ptp_error *err)
{
    int st = slp_build(&p->prog, t, err), local = (form & PLAN_LOCAL) != 0;
    p->cert = p->look = (cert_bounds){0};
    p->local = local;
    p->bspline = (form & PLAN_BSPLINE) != 0;
    p->vmajor = (form & PLAN_VMAJOR) != 0;
    p->n = t->dom.n;
    p->m = t->dom.m;
    if (st)
        return st;
    p->flops = slp_flops(&p->prog, world) + (local ? plan_frame_flops(t->dom.npoints, world) : 0) +
               (p->bspline ? plan_bspline_flops(world) : 0);
    p->muls = slp_muls(&p->prog, world) + (local ? plan_frame_muls(t->dom.npoints, world) : 0) +
              (p->bspline ? plan_bspline_muls(world) : 0);
    if (certified &&
        (st = cert_slp(&p->cert, &p->prog, world, local, p->bspline, certified, err)) == PTP_OK &&
        (st = certified->df ? cert_table_df(&p->look, t, world, err)
                            : cert_table(&p->look, t, world, p->bspline, err)) != PTP_OK)
        cert_clear(&p->cert);
    if (st)
        slp_clear(&p->prog);
    return st;
}

int plan_input_index(const plan_slp *p, int i, int j)
{
    return p->vmajor ? j * (p->n + 1) + i : i * (p->m + 1) + j;
}

void plan_slp_clear(plan_slp *p)
{
    cert_clear(&p->cert);
    cert_clear(&p->look);
    slp_clear(&p->prog);
}
