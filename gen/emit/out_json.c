/* out_json.c: the ptpgen-planes/1 JSON output: one term per line, exact weights as strings, sorted
 * by plane then triple (formatted by hand: this loop is most of the time of a small run). */
#include "emit/out.h"
#include "core/i128.h"

/* Appends [plane, j, k, l, "weight"]. */
static void put_term(sbuf *o, const tp_term *x)
{
    char w[RAT_STRLEN];
    const int v[4] = {x->plane, x->j, x->k, x->l};
    int c;
    sbuf_puts(o, "[");
    for (c = 0; c < 4; c++) {
        sbuf_puts(o, i128_to_str(w, v[c]));
        sbuf_puts(o, ", ");
    }
    sbuf_puts(o, "\"");
    sbuf_puts(o, rat_get_str(w, &x->w));
    sbuf_puts(o, "\"]");
}

/* Appends "name": [v_0, ..., v_{n-1}], breaking the line before each row of the planes of d
 * (d not NULL: one value per plane) or else every `row` values. */
static void put_ints(sbuf *o, const char *name, const int *v, int n, const tp_domain *d, int row)
{
    int i;
    sbuf_printf(o, "    \"%s\": [", name);
    for (i = 0; i < n; i++)
        sbuf_printf(o, "%s%d", i == 0 ? "" : (d ? tp_domain_plane_row_start(d, i) : i % row == 0)
                                                 ? ",\n      " : ", ", v[i]);
    sbuf_puts(o, "],\n");
}

static void put_schedule(sbuf *o, const tp_table *t, const sched *s)
{
    long i, nslots = (long)s->rounds * s->threads;
    sbuf_printf(o, "  \"schedule\": {\n    \"threads_per_patch\": %d,\n", s->threads);
    sbuf_printf(o, "    \"patches_per_block\": %d,\n    \"rounds\": %d,\n", s->patches, s->rounds);
    sbuf_printf(o, "    \"lower_bound\": %d,\n    \"proven_optimal\": %s,\n", s->lower_bound,
                s->proven ? "true" : "false");
    put_ints(o, "owner", s->owner, s->nplanes, &t->dom, 0);
    put_ints(o, "loads", s->load, s->threads, NULL, 16);
    sbuf_puts(o, "    \"slots\": [");
    for (i = 0; i < nslots; i++) {
        sbuf_puts(o, i ? ",\n      " : "\n      ");
        if (s->slot[i] < 0)
            sbuf_puts(o, "null");
        else
            put_term(o, &t->terms[s->slot[i]]);
    }
    sbuf_puts(o, "\n    ]\n  }\n");
}

int out_json(sbuf *o, const tp_table *t, const out_info *info, ptp_error *err)
{
    size_t i;
    tp_domain_text x;
    tp_domain_text_get(&x, &t->dom);
    sbuf_printf(o, "{\n  \"format\": \"ptpgen-planes/1\",\n");
    sbuf_printf(o, "  \"generator\": \"ptpgen %s\",\n  \"command\": \"%s\",\n", PTP_VERSION,
                info->command);
    sbuf_printf(o, "  %s,\n", x.json);
    sbuf_printf(o, "  \"points\": %d,\n  \"planes\": %d,\n", t->dom.npoints, t->dom.nplanes);
    /* The kernels' values are d_P = eye . t_P times this positive constant (true scale). */
    sbuf_puts(o, "  \"plane_scale\": \"1\",\n  \"terms\": [");
    for (i = 0; i < t->nterms; i++) {
        sbuf_puts(o, i ? ",\n    " : "\n    ");
        put_term(o, &t->terms[i]);
    }
    sbuf_puts(o, "\n  ],\n");
    put_schedule(o, t, info->sched);
    sbuf_puts(o, "}\n");
    return o->failed ? ptp_fail(err, PTP_ENOMEM, "out of memory writing json") : PTP_OK;
}
