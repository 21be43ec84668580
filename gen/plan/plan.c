/* plan.c: the straight-line plan of a table, built once: the program, its operation counts and,
 * certified, its margins. */
#include "plan/plan.h"

int plan_slp_build(plan_slp *p, const tp_table *t, int world, int certified, ptp_error *err)
{
    int st = slp_build(&p->prog, t, err);
    p->cert = (cert_bounds){0};
    if (st)
        return st;
    p->flops = slp_flops(&p->prog, world);
    p->muls = slp_muls(&p->prog, world);
    if (certified && (st = cert_slp(&p->cert, &p->prog, world, err)) != PTP_OK)
        slp_clear(&p->prog);
    return st;
}

void plan_slp_clear(plan_slp *p)
{
    cert_clear(&p->cert);
    slp_clear(&p->prog);
}
