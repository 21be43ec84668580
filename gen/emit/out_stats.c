/* out_stats.c: the human-readable term statistics.
 * The term count of every plane as the paper's matrix (section 6), the total, and the schedule. */
#include "emit/out.h"

#include <stdlib.h>

/* The number of digits of v >= 0. */
static int digits(int v)
{
    int d = 1;
    for (; v >= 10; v /= 10)
        d++;
    return d;
}

/* The owner map, each thread's load, R, LB and the efficiency. */
static void put_schedule(sbuf *o, const tp_table *t, const sched *s)
{
    int I, J, th, w = digits(s->threads - 1), wl = digits(s->rounds);
    sbuf_printf(o, "\nschedule: %d threads per patch, %d patches per block (%d threads per block)\n",
                s->threads, s->patches, s->threads * s->patches);
    sbuf_printf(o, "owning thread of each plane (row I along u, column J along v):\n");
    for (I = 0; I <= t->dom.pu; I++) {
        for (J = 0; J <= t->dom.pv; J++)
            sbuf_printf(o, "%s%*d", J ? " " : "", w, s->owner[I * (t->dom.pv + 1) + J]);
        sbuf_puts(o, "\n");
    }
    sbuf_printf(o, "terms per thread:\n");
    for (th = 0; th < s->threads; th++)
        sbuf_printf(o, "%s%*d", th == 0 ? "" : th % 16 ? " " : "\n", wl, s->load[th]);
    sbuf_printf(o, "\nrounds R = %d, lower bound LB = %d (%s)\n", s->rounds, s->lower_bound,
                s->rounds == s->lower_bound ? "R = LB"
                : s->proven ? "R proven optimal" : "not proven optimal");
    sbuf_printf(o, "efficiency %zu / (R * P) = %zu / %ld = %.1f%%\n", t->nterms, t->nterms,
                (long)s->rounds * s->threads, 100.0 * (double)t->nterms / ((double)s->rounds * s->threads));
}

int out_stats(sbuf *o, const tp_table *t, const out_info *info, ptp_error *err)
{
    int *counts = malloc((size_t)t->dom.nplanes * sizeof *counts), I, J, width = 1, max = 0;
    if (!counts)
        return ptp_fail(err, PTP_ENOMEM, "out of memory writing stats");
    tp_plane_counts(counts, t);
    for (I = 0; I < t->dom.nplanes; I++)
        max = counts[I] > max ? counts[I] : max;
    for (; max >= 10; max /= 10)
        width++;
    sbuf_printf(o, "bidegree %dx%d: %d points, planes of bidegree %dx%d: %d planes, %zu terms\n",
                t->dom.n, t->dom.m, t->dom.npoints, t->dom.pu, t->dom.pv, t->dom.nplanes, t->nterms);
    sbuf_printf(o, "terms per plane (row I along u, column J along v):\n");
    for (I = 0; I <= t->dom.pu; I++) {
        for (J = 0; J <= t->dom.pv; J++)
            sbuf_printf(o, "%s%*d", J ? " " : "", width, counts[I * (t->dom.pv + 1) + J]);
        sbuf_puts(o, "\n");
    }
    sbuf_printf(o, "total %zu\n", t->nterms);
    put_schedule(o, t, info->sched);
    free(counts);
    return o->failed ? ptp_fail(err, PTP_ENOMEM, "out of memory writing stats") : PTP_OK;
}
