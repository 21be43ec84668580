/* emit_c_mesh.c: the degree-1 triangle header's indexed-mesh entry points (templates/c/mesh.h):
 * blocks of triangles gathered through the index array into classify_soa. */
#include "emit/emit_c_mesh.h"
#include "emit/fmt.h"
#include "emit/template.h"

/* The SSE2 gather's stores of the transposed rows r0..r3 (x, y, z, w of one vertex of four
 * triangles): clip space never reads z. */
static void put_stores(sbuf *o, const out_info *info, const char *up)
{
    int c;
    for (c = 0; c < 4; c++)
        if (c != 2 || info->space == OUT_WORLD)
            sbuf_printf(o, "                _mm_storeu_ps(soa + (k * 4 + %d) * %sMESH_LANES + l, r%d);\n",
                        c, up, c);
}

int emit_c_mesh(sbuf *o, const tp_table *t, const out_info *info, ptp_error *err)
{
    sbuf stores;
    char up[64];
    tpl_slot slots[4];
    int st;
    if (t->dom.kind != TP_TRI || t->dom.n != 1)
        return PTP_OK;
    fmt_upper(up, sizeof up, info->prefix);
    sbuf_init(&stores);
    put_stores(&stores, info, up);
    slots[0] = (tpl_slot){"PREFIX", info->prefix};
    slots[1] = (tpl_slot){"UPREFIX", up};
    slots[2] = (tpl_slot){"STORES", stores.s};
    slots[3] = (tpl_slot){"VALUE", info->space == OUT_CLIP ? "the points in clip space and eye (0, 0, alpha, 0)"
                                                         : "the points and the eye in world space"};
    st = stores.failed ? ptp_fail(err, PTP_ENOMEM, "out of memory writing the C header")
                       : tpl_fill(o, "c/mesh.h", slots, 4, err);
    sbuf_clear(&stores);
    return st;
}
