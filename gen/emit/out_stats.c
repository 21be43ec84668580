/* out_stats.c: the human-readable term statistics.
 * The term count of every plane as the paper's matrix (section 6), the total, and the schedule. */
#include "emit/out.h"
#include "plan/slp.h"

#include <stdlib.h>

/* The number of digits of v >= 0. */
static int digits(int v)
{
    int d = 1;
    for (; v >= 10; v /= 10)
        d++;
    return d;
}

/* The per-plane values v as the plane matrix of d (tp_domain_plane_row_start), each printed
 * w wide, under the title and the layout. */
static void put_matrix(sbuf *o, const char *title, const tp_domain *d, const int *v, int w)
{
    tp_domain_text x;
    int P;
    tp_domain_text_get(&x, d);
    sbuf_printf(o, "%s (%s):\n", title, x.plane_rows);
    for (P = 0; P < d->nplanes; P++)
        sbuf_printf(o, "%s%*d", P == 0 ? "" : tp_domain_plane_row_start(d, P) ? "\n" : " ", w,
                    v[P]);
    sbuf_puts(o, "\n");
}

/* The owner map, each thread's load, R, LB and the efficiency. */
static void put_schedule(sbuf *o, const tp_table *t, const sched *s)
{
    int th, w = digits(s->threads - 1), wl = digits(s->rounds);
    sbuf_printf(o, "\nschedule: %d threads per patch, %d patches per block (%d threads per block)\n",
                s->threads, s->patches, s->threads * s->patches);
    put_matrix(o, "owning thread of each plane", &t->dom, s->owner, w);
    sbuf_printf(o, "terms per thread:\n");
    for (th = 0; th < s->threads; th++)
        sbuf_printf(o, "%s%*d", th == 0 ? "" : th % 16 ? " " : "\n", wl, s->load[th]);
    sbuf_printf(o, "\nrounds R = %d, lower bound LB = %d (%s)\n", s->rounds, s->lower_bound,
                s->rounds == s->lower_bound ? "R = LB"
                : s->proven ? "R proven optimal" : "not proven optimal");
    sbuf_printf(o, "efficiency %zu / (R * P) = %zu / %ld = %.1f%%\n", t->nterms, t->nterms,
                (long)s->rounds * s->threads, 100.0 * (double)t->nterms / ((double)s->rounds * s->threads));
}

/* The C header's straight-line program: its exact, fused and point-form planes, and the
 * operations per patch in clip and world space: all of them, those on the multiply pipes and
 * those on the adders. */
static int put_slp(sbuf *o, const tp_table *t, ptp_error *err)
{
    slp_prog p;
    size_t i, exact_terms = 0;
    int P, exact = 0, point = 0, st = slp_build(&p, t, err);
    if (st)
        return st;
    for (P = 0; P < p.nplanes; P++) {
        exact += (p.form[P] == SLP_BRACKET);
        point += (p.form[P] == SLP_POINT);
    }
    for (i = 0; i < p.nterms; i++)
        exact_terms += (p.form[p.terms[i].plane] == SLP_BRACKET);
    sbuf_printf(o, "C straight-line code: %d exact planes (%zu terms), %d fused, %d in the point form; "
                   "per patch %ld flops, %ld on the multiply pipes, %ld on the add pipes (clip space), "
                   "%ld, %ld and %ld (world space), with the patch-local frame's %ld, %ld and 0 "
                   "(world %ld, %ld and 0)\n",
                exact, exact_terms, p.nplanes - exact - point, point,
                slp_flops(&p, 0) + plan_frame_flops(p.npoints, 0),
                slp_muls(&p, 0) + plan_frame_muls(p.npoints, 0), slp_adds(&p, 0),
                slp_flops(&p, 1) + plan_frame_flops(p.npoints, 1),
                slp_muls(&p, 1) + plan_frame_muls(p.npoints, 1), slp_adds(&p, 1),
                plan_frame_flops(p.npoints, 0), plan_frame_muls(p.npoints, 0),
                plan_frame_flops(p.npoints, 1), plan_frame_muls(p.npoints, 1));
    slp_clear(&p);
    return PTP_OK;
}

int out_stats(sbuf *o, const tp_table *t, const out_info *info, ptp_error *err)
{
    int *counts = malloc((size_t)t->dom.nplanes * sizeof *counts), P, max = 0, st;
    tp_domain_text x;
    if (!counts)
        return ptp_fail(err, PTP_ENOMEM, "out of memory writing stats");
    tp_plane_counts(counts, t);
    for (P = 0; P < t->dom.nplanes; P++)
        max = counts[P] > max ? counts[P] : max;
    tp_domain_text_get(&x, &t->dom);
    sbuf_printf(o, "%s: %d points, planes of %s: %d planes, %zu terms\n", x.name, t->dom.npoints,
                x.plane_name, t->dom.nplanes, t->nterms);
    put_matrix(o, "terms per plane", &t->dom, counts, digits(max));
    sbuf_printf(o, "total %zu\n", t->nterms);
    put_schedule(o, t, info->sched);
    free(counts);
    if ((st = put_slp(o, t, err)) != PTP_OK)
        return st;
    return o->failed ? ptp_fail(err, PTP_ENOMEM, "out of memory writing stats") : PTP_OK;
}
