/* out_stats.c: the human-readable term statistics.
 * The term count of every plane as the paper's matrix (section 6), and the total. */
#include "out.h"

#include <stdlib.h>

int out_stats(sbuf *o, const tp_table *t, const out_info *info, ptp_error *err)
{
    int *counts = malloc((size_t)t->nplanes * sizeof *counts), I, J, width = 1, max = 0;
    (void)info;
    if (!counts)
        return ptp_fail(err, PTP_ENOMEM, "out of memory writing stats");
    tp_plane_counts(counts, t);
    for (I = 0; I < t->nplanes; I++)
        max = counts[I] > max ? counts[I] : max;
    for (; max >= 10; max /= 10)
        width++;
    sbuf_printf(o, "bidegree %dx%d: %d points, planes of bidegree %dx%d: %d planes, %zu terms\n",
                t->n, t->m, t->npoints, t->pu, t->pv, t->nplanes, t->nterms);
    sbuf_printf(o, "terms per plane (row I along u, column J along v):\n");
    for (I = 0; I <= t->pu; I++) {
        for (J = 0; J <= t->pv; J++)
            sbuf_printf(o, "%s%*d", J ? " " : "", width, counts[I * (t->pv + 1) + J]);
        sbuf_puts(o, "\n");
    }
    sbuf_printf(o, "total %zu\n", t->nterms);
    free(counts);
    return o->failed ? ptp_fail(err, PTP_ENOMEM, "out of memory writing stats") : PTP_OK;
}
