/* emit_c_mesh.c: the degree-1 triangle header's indexed-mesh entry points (templates/c/mesh.h):
 * blocks of triangles gathered through the index array into classify_soa. */
#include "emit/emit_c_mesh.h"
#include "emit/fmt.h"
#include "emit/template.h"

/* The gather's stores for one vector width: the rows of the in-lane 4x4 transpose (one vertex of
 * the block's triangles), from t0, t1 (x and y: their low and high pairs) and t2, t3 (z and w),
 * into the SoA rows; clip space never reads z. v names the intrinsics' vector family ("_mm",
 * "_mm256", "_mm512"). */
static void put_stores(sbuf *o, const out_info *info, const char *up, const char *v)
{
    static const char *const row[4] = {"t0, t1, 0x44", "t0, t1, 0xee", "t2, t3, 0x44", "t2, t3, 0xee"};
    int c;
    for (c = 0; c < 4; c++)
        if (c != 2 || info->space == OUT_WORLD)
            sbuf_printf(o, "                %s_storeu_ps(soa + (k * 4 + %d) * %sMESH_LANES + l, %s_shuffle_ps(%s));\n",
                        v, c, up, v, row[c]);
}

int emit_c_mesh(sbuf *o, const tp_table *t, const out_info *info, ptp_error *err)
{
    static const char *const family[3] = {"_mm", "_mm256", "_mm512"};
    static const char *const slot[3] = {"STORES4", "STORES8", "STORES16"};
    sbuf stores[3];
    char up[64];
    tpl_slot slots[6];
    int i, st;
    if (t->dom.kind != TP_TRI || t->dom.n != 1)
        return PTP_OK;
    fmt_upper(up, sizeof up, info->prefix);
    for (i = 0; i < 3; i++) {
        sbuf_init(&stores[i]);
        put_stores(&stores[i], info, up, family[i]);
        slots[3 + i] = (tpl_slot){slot[i], stores[i].s};
    }
    slots[0] = (tpl_slot){"PREFIX", info->prefix};
    slots[1] = (tpl_slot){"UPREFIX", up};
    slots[2] = (tpl_slot){"VALUE", info->space == OUT_CLIP ? "the points in clip space and eye (0, 0, alpha, 0)"
                                                         : "the points and the eye in world space"};
    st = stores[0].failed || stores[1].failed || stores[2].failed
             ? ptp_fail(err, PTP_ENOMEM, "out of memory writing the C header")
             : tpl_fill(o, "c/mesh.h", slots, 6, err);
    for (i = 0; i < 3; i++)
        sbuf_clear(&stores[i]);
    return st;
}
