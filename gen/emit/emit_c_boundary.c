/* emit_c_boundary.c: the B-spline header's boundary section (templates/c/boundary.h): the table
 * of each boundary edge's phantom vertices in the input's order. */
#include "emit/emit_c_boundary.h"
#include "emit/fmt.h"
#include "emit/template.h"

/* Appends the phantoms table: for edge bit b (v = 0, u = 1, v = 1, u = 0) the vertices (i, j)
 * of that edge (i along u) with the two inward, as input indices {p0, p1, p2}. */
static void put_phantoms(sbuf *o, int vmajor)
{
    /* per edge: the first vertex (i, j), the step along the edge, the step inward */
    static const int edge[4][6] = {{0, 0, 1, 0, 0, 1}, {3, 0, 0, 1, -1, 0},
                                   {0, 3, 1, 0, 0, -1}, {0, 0, 0, 1, 1, 0}};
    int b, k, s;
    sbuf_puts(o, "{");
    for (b = 0; b < 4; b++) {
        const int *e = edge[b];
        sbuf_puts(o, b ? ",\n    {" : "\n    {");
        for (k = 0; k < 4; k++) {
            sbuf_puts(o, k ? ", {" : "{");
            for (s = 0; s < 3; s++) {
                int i = e[0] + k * e[2] + s * e[4], j = e[1] + k * e[3] + s * e[5];
                sbuf_printf(o, "%s%d", s ? ", " : "", vmajor ? j * 4 + i : i * 4 + j);
            }
            sbuf_puts(o, "}");
        }
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
    put_phantoms(&phantoms, info->slp->vmajor);
    slots[0] = (tpl_slot){"PREFIX", info->prefix};
    slots[1] = (tpl_slot){"UPREFIX", up};
    slots[2] = (tpl_slot){"PHANTOMS", phantoms.s};
    st = phantoms.failed ? ptp_fail(err, PTP_ENOMEM, "out of memory writing the C header")
                         : tpl_fill(o, "c/boundary.h", slots, 3, err);
    sbuf_clear(&phantoms);
    return st;
}
