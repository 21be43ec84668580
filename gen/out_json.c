/* out_json.c: the ptpgen-planes/1 JSON output.
 * One term per line, exact weights as strings, sorted by plane then triple. */
#include "out.h"

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
        sbuf_printf(o, "%s\n    [%d, %d, %d, %d, \"%s\"]", i ? "," : "", x->plane, x->j, x->k,
                    x->l, rat_get_str(w, &x->w));
    }
    sbuf_puts(o, "\n  ]\n}\n");
    return o->failed ? ptp_fail(err, PTP_ENOMEM, "out of memory writing json") : PTP_OK;
}
