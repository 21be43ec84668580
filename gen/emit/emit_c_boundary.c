/* emit_c_boundary.c: the B-spline header's boundary section (templates/c/boundary.h): the table
 * of each boundary edge's phantom vertices in the input's order. */
#include "emit/emit_c_boundary.h"
#include "emit/fmt.h"
#include "emit/template.h"
#include "plan/phantom.h"

/* Appends the phantoms table of phantom_table: per edge bit, its four {p0, p1, p2}. */
static void put_phantoms(sbuf *o, const plan_slp *p)
{
    int q[4][4][3], b, k;
    phantom_table(q, p);
    sbuf_puts(o, "{");
    for (b = 0; b < 4; b++) {
        sbuf_puts(o, b ? ",\n    {" : "\n    {");
        for (k = 0; k < 4; k++)
            sbuf_printf(o, "%s{%d, %d, %d}", k ? ", " : "", q[b][k][0], q[b][k][1], q[b][k][2]);
        sbuf_puts(o, "}");
    }
    sbuf_puts(o, "}");
}

int emit_c_boundary(sbuf *o, const out_info *info, ptp_error *err)
{
    sbuf phantoms;
    char up[64];
    tpl_slot slots[3];
    int st;
    if (!info->slp->bspline)
        return PTP_OK;
    fmt_upper(up, sizeof up, info->prefix);
    sbuf_init(&phantoms);
    put_phantoms(&phantoms, info->slp);
    slots[0] = (tpl_slot){"PREFIX", info->prefix};
    slots[1] = (tpl_slot){"UPREFIX", up};
    slots[2] = (tpl_slot){"PHANTOMS", phantoms.s};
    st = phantoms.failed ? ptp_fail(err, PTP_ENOMEM, "out of memory writing the C header")
                         : tpl_fill(o, "c/boundary.h", slots, 3, err);
    sbuf_clear(&phantoms);
    return st;
}
