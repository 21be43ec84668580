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

int plan_slp_build(plan_slp *p, const tp_table *t, int world, int local, int certified,
                   ptp_error *err)
{
    int st = slp_build(&p->prog, t, err);
    p->cert = (cert_bounds){0};
    p->local = local;
    if (st)
        return st;
    p->flops = slp_flops(&p->prog, world) + (local ? plan_frame_flops(t->dom.npoints, world) : 0);
    p->muls = slp_muls(&p->prog, world) + (local ? plan_frame_muls(t->dom.npoints, world) : 0);
    if (certified && (st = cert_slp(&p->cert, &p->prog, world, local, err)) != PTP_OK)
        slp_clear(&p->prog);
    return st;
}

void plan_slp_clear(plan_slp *p)
{
    cert_clear(&p->cert);
    slp_clear(&p->prog);
}
