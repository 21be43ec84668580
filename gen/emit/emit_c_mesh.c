/* emit_c_mesh.c: the degree-1 triangle header's indexed-mesh entry points (templates/c/mesh.h):
 * blocks of triangles gathered through the index array into classify_soa, or with AVX-512 into a
 * fused kernel that performs classify's float operations for degree 1 in registers. */
#include "emit/emit_c_mesh.h"
#include "emit/fmt.h"
#include "emit/template.h"

#include <string.h>

/* AVX-512 products, differences and sums of the fused kernel's source text (string literals). */
#define MUL16(a, b) "_mm512_mul_ps(" a ", " b ")"
#define SUB16(a, b) "_mm512_sub_ps(" a ", " b ")"
#define ADD16(a, b) "_mm512_add_ps(" a ", " b ")"
/* (a0 m1_2 - a1 m0_2) + a2 m0_1: one plane's Laplace expansion over the minors m. */
#define PLANE16(a, m) ADD16(SUB16(MUL16(a "0", m "1_2"), MUL16(a "1", m "0_2")), MUL16(a "2", m "0_1"))

/* The gather's stores for one vector width: the rows of the in-lane 4x4 transpose (one vertex of
 * the block's triangles) into the SoA rows; clip space never reads z. v names the intrinsics'
 * vector family ("_mm", "_mm256", "_mm512"): the narrower ones from t0, t1 (x and y: their low
 * and high pairs) and t2, t3 (z and w), AVX-512 from mesh_rows16's v[0] to v[3]. */
static void put_stores(sbuf *o, const out_info *info, const char *up, const char *v)
{
    static const char *const row[4] = {"t0, t1, 0x44", "t0, t1, 0xee", "t2, t3, 0x44", "t2, t3, 0xee"};
    int c;
    for (c = 0; c < 4; c++)
        if (c != 2 || info->space == OUT_WORLD) {
            sbuf_printf(o, "                %s_storeu_ps(soa + (k * 4 + %d) * %sMESH_LANES + l, ", v, c, up);
            if (!strcmp(v, "_mm512"))
                sbuf_printf(o, "v[%d]);\n", c);
            else
                sbuf_printf(o, "%s_shuffle_ps(%s));\n", v, row[c]);
        }
}

/* The fused AVX-512 kernel's eye broadcasts: e0 to e3 in world space, e2 alone in clip space. */
static void put_eye16(sbuf *o, const out_info *info)
{
    int c;
    for (c = 0; c < 4; c++)
        if (c == 2 || info->space == OUT_WORLD)
            sbuf_printf(o, "    const __m512 e%d = _mm512_set1_ps(eye[%d]);\n", c, c);
}

/* The fused kernel's value u of the degree-1 plane from the rows v[k][0 to 3] (x, y, z, w) of its
 * three points: the float operations of classify's straight-line code for degree 1, in its order.
 * World: a_k = e0 y_k - e1 x_k, b_k = e2 w_k - e3 z_k, the minors m_ij = x_i y_j - y_i x_j and
 * n_ij = z_i w_j - w_i z_j, u = ((a0 n12 - a1 n02) + a2 n01) + ((b0 m12 - b1 m02) + b2 m01).
 * Clip: g_k = e2 w_k, u = (g0 m12 - g1 m02) + g2 m01. */
static void put_value16(sbuf *o, const out_info *info)
{
    static const int pair[3][2] = {{1, 2}, {0, 2}, {0, 1}};
    int k, world = info->space == OUT_WORLD;
    for (k = 0; k < 3; k++)
        if (world)
            sbuf_printf(o, "        const __m512 a%d = " SUB16(MUL16("e0", "v[%d][1]"), MUL16("e1", "v[%d][0]"))
                           ", b%d = " SUB16(MUL16("e2", "v[%d][3]"), MUL16("e3", "v[%d][2]")) ";\n",
                        k, k, k, k, k, k);
        else
            sbuf_printf(o, "        const __m512 g%d = _mm512_mul_ps(e2, v[%d][3]);\n", k, k);
    for (k = 0; k < 3; k++) {
        int i = pair[k][0], j = pair[k][1];
        sbuf_printf(o, "        const __m512 m%d_%d = " SUB16(MUL16("v[%d][0]", "v[%d][1]"), MUL16("v[%d][1]", "v[%d][0]")) ";\n",
                    i, j, i, j, i, j);
        if (world)
            sbuf_printf(o, "        const __m512 n%d_%d = " SUB16(MUL16("v[%d][2]", "v[%d][3]"), MUL16("v[%d][3]", "v[%d][2]")) ";\n",
                        i, j, i, j, i, j);
    }
    if (world)
        sbuf_printf(o, "        u = _mm512_add_ps(%s, %s);\n", PLANE16("a", "n"), PLANE16("b", "m"));
    else
        sbuf_printf(o, "        u = %s;\n", PLANE16("g", "m"));
}

/* The fused kernel's class words c from u: strict, back (1) iff u < 0, front (0) iff u > 0,
 * else silhouette (2); degenerate, front iff u > 0, silhouette iff u is NaN, else back. */
static void put_class16(sbuf *o, const out_info *info)
{
    const int strict = info->rule == OUT_STRICT;
    sbuf_printf(o, "        c = _mm512_set1_epi32(%d);\n", strict ? 2 : 1);
    if (strict)
        sbuf_printf(o, "        c = _mm512_mask_mov_epi32(c, _mm512_cmp_ps_mask(u, _mm512_setzero_ps(), _CMP_LT_OQ), _mm512_set1_epi32(1));\n");
    sbuf_printf(o, "        c = _mm512_mask_mov_epi32(c, _mm512_cmp_ps_mask(u, _mm512_setzero_ps(), _CMP_GT_OQ), _mm512_setzero_si512());\n");
    if (!strict)
        sbuf_printf(o, "        c = _mm512_mask_mov_epi32(c, _mm512_cmp_ps_mask(u, u, _CMP_UNORD_Q), _mm512_set1_epi32(2));\n");
}

int emit_c_mesh(sbuf *o, const tp_table *t, const out_info *info, ptp_error *err)
{
    static const char *const family[3] = {"_mm", "_mm256", "_mm512"};
    static const char *const slot[6] = {"STORES4", "STORES8", "STORES16", "EYE16", "VALUE16", "CLASS16"};
    sbuf parts[6];
    char up[64];
    tpl_slot slots[10];
    int i, st, failed = 0;
    if (t->dom.kind != TP_TRI || t->dom.n != 1)
        return PTP_OK;
    fmt_upper(up, sizeof up, info->prefix);
    for (i = 0; i < 6; i++)
        sbuf_init(&parts[i]);
    for (i = 0; i < 3; i++)
        put_stores(&parts[i], info, up, family[i]);
    put_eye16(&parts[3], info);
    put_value16(&parts[4], info);
    put_class16(&parts[5], info);
    for (i = 0; i < 6; i++) {
        failed |= parts[i].failed;
        slots[4 + i] = (tpl_slot){slot[i], parts[i].s};
    }
    slots[0] = (tpl_slot){"PREFIX", info->prefix};
    slots[1] = (tpl_slot){"UPREFIX", up};
    slots[2] = (tpl_slot){"VALUE", info->space == OUT_CLIP ? "the points in clip space and eye (0, 0, alpha, 0)"
                                                         : "the points and the eye in world space"};
    slots[3] = (tpl_slot){"FUSED", info->certified ? "0" : "1"};
    st = failed ? ptp_fail(err, PTP_ENOMEM, "out of memory writing the C header")
                : tpl_fill(o, "c/mesh.h", slots, 10, err);
    for (i = 0; i < 6; i++)
        sbuf_clear(&parts[i]);
    return st;
}
