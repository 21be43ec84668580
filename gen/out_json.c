/* out_json.c: the ptpgen-planes/1 JSON output.
 * One term per line, exact weights as strings, sorted by plane then triple (formatted by hand:
 * this loop is most of the time of a small run). */
#include "out.h"
#include "i128.h"

int out_json(sbuf *o, const tp_table *t, const out_info *info, ptp_error *err)
{
    char w[RAT_STRLEN];
    size_t i;
    sbuf_printf(o, "{\n  \"format\": \"ptpgen-planes/1\",\n");
    sbuf_printf(o, "  \"generator\": \"ptpgen %s\",\n  \"command\": \"%s\",\n", PTP_VERSION,
                info->command);
    sbuf_printf(o, "  \"degree\": [%d, %d],\n  \"plane_degree\": [%d, %d],\n", t->n, t->m,
                t->pu, t->pv);
    sbuf_printf(o, "  \"points\": %d,\n  \"planes\": %d,\n  \"terms\": [", t->npoints,
                t->nplanes);
    for (i = 0; i < t->nterms; i++) {
        const tp_term *x = &t->terms[i];
        const int v[4] = {x->plane, x->j, x->k, x->l};
        int c;
        sbuf_puts(o, i ? ",\n    [" : "\n    [");
        for (c = 0; c < 4; c++) {
            sbuf_puts(o, i128_to_str(w, v[c]));
            sbuf_puts(o, ", ");
        }
        sbuf_puts(o, "\"");
        sbuf_puts(o, rat_get_str(w, &x->w));
        sbuf_puts(o, "\"]");
    }
    sbuf_puts(o, "\n  ]\n}\n");
    return o->failed ? ptp_fail(err, PTP_ENOMEM, "out of memory writing json") : PTP_OK;
}
