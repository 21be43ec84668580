/* emit_c_mesh.c: the degree-1 triangle header's indexed-mesh entry points (templates/c/mesh.h):
 * triangles gathered by index into classify_soa, or (AVX-512, AVX) into a fused register kernel. */
#include "emit/emit_c_mesh.h"
#include "emit/fmt.h"
#include "emit/template.h"

#include <stdio.h>
#include <string.h>

/* A vector width of the fused kernel: the intrinsics' family and vector type. */
typedef struct {
    const char *fam, *vec;
    int wide; /* AVX-512: compare masks; AVX: compares to all-ones floats */
} fused_isa;

/* Appends fam_mul_ps(a, b). */
static void put_mul(sbuf *o, const fused_isa *isa, const char *a, const char *b)
{
    sbuf_printf(o, "%s_mul_ps(%s, %s)", isa->fam, a, b);
}

/* Appends a * b - c * d as the fused kernel's text. */
static void put_diff(sbuf *o, const fused_isa *isa, const char *a, const char *b, const char *c,
                     const char *d)
{
    sbuf_printf(o, "%s_sub_ps(", isa->fam);
    put_mul(o, isa, a, b);
    sbuf_puts(o, ", ");
    put_mul(o, isa, c, d);
    sbuf_puts(o, ")");
}

/* Appends (a0 m1_2 - a1 m0_2) + a2 m0_1: one plane's Laplace expansion over the minors m. */
static void put_plane(sbuf *o, const fused_isa *isa, char a, char m)
{
    char x[6][8];
    snprintf(x[0], sizeof x[0], "%c0", a);
    snprintf(x[1], sizeof x[1], "%c1_2", m);
    snprintf(x[2], sizeof x[2], "%c1", a);
    snprintf(x[3], sizeof x[3], "%c0_2", m);
    snprintf(x[4], sizeof x[4], "%c2", a);
    snprintf(x[5], sizeof x[5], "%c0_1", m);
    sbuf_printf(o, "%s_add_ps(", isa->fam);
    put_diff(o, isa, x[0], x[1], x[2], x[3]);
    sbuf_puts(o, ", ");
    put_mul(o, isa, x[4], x[5]);
    sbuf_puts(o, ")");
}

/* The gather's stores for one vector width: the rows of the in-lane 4x4 transpose (one vertex of
 * the block's triangles) into the SoA rows; clip space never reads z. v names the intrinsics'
 * vector family ("_mm", "_mm256", "_mm512"): SSE2 from t0, t1 (x and y: their low and high
 * pairs) and t2, t3 (z and w), AVX and AVX-512 from mesh_rows' v[0] to v[3]. */
static void put_stores(sbuf *o, const out_info *info, const char *up, const char *v)
{
    static const char *const row[4] = {"t0, t1, 0x44", "t0, t1, 0xee", "t2, t3, 0x44", "t2, t3, 0xee"};
    int c;
    for (c = 0; c < 4; c++)
        if (c != 2 || info->space == OUT_WORLD) {
            sbuf_printf(o, "                %s_storeu_ps(soa + (k * 4 + %d) * %sMESH_LANES + l, ", v, c, up);
            if (strcmp(v, "_mm"))
                sbuf_printf(o, "v[%d]);\n", c);
            else
                sbuf_printf(o, "%s_shuffle_ps(%s));\n", v, row[c]);
        }
}

/* mesh_rows' in-lane 4x4 transpose of r[0 to 3] into the rows v[0 to 3]. */
static void put_transpose(sbuf *o, const fused_isa *isa)
{
    static const char *const row[4] = {"t0, t1, 0x44", "t0, t1, 0xee", "t2, t3, 0x44", "t2, t3, 0xee"};
    int c;
    sbuf_printf(o, "    const %s t0 = %s_unpacklo_ps(r[0], r[1]), t1 = %s_unpacklo_ps(r[2], r[3]);\n",
                isa->vec, isa->fam, isa->fam);
    sbuf_printf(o, "    const %s t2 = %s_unpackhi_ps(r[0], r[1]), t3 = %s_unpackhi_ps(r[2], r[3]);\n",
                isa->vec, isa->fam, isa->fam);
    for (c = 0; c < 4; c++)
        sbuf_printf(o, "    v[%d] = %s_shuffle_ps(%s);\n", c, isa->fam, row[c]);
}

/* The fused kernel's eye broadcasts: e0 to e3 in world space, e2 alone in clip space. */
static void put_eye(sbuf *o, const out_info *info, const fused_isa *isa)
{
    int c;
    for (c = 0; c < 4; c++)
        if (c == 2 || info->space == OUT_WORLD)
            sbuf_printf(o, "    const %s e%d = %s_set1_ps(eye[%d]);\n", isa->vec, c, isa->fam, c);
}

/* Writes to out coordinate c of point k as the fused kernel reads it: v[k][c], or the local x<k>. */
static void point_name(char *out, size_t size, int local, int k, int c)
{
    if (local)
        snprintf(out, size, "%c%d", "xyzw"[c], k);
    else
        snprintf(out, size, "v[%d][%d]", k, c);
}

/* Patch-local coordinates (slpt_frame): rw = 1 / w0 (0 where w0 is 0; NaN stays NaN, as in the
 * lanes), o = -(x0, y0[, z0]) rw, the local eye l = e + o e3 (world) and each point's x + o w, y +
 * o w[, z + o w] as one multiply-add: the lanes' VRECIP0 and VLOCAL (the fused kernel runs only
 * where VLOCAL is a multiply-add). Declares x<k> y<k> w<k> (world also z<k>, l0 l1 l2). */
static void put_frame(sbuf *o, const out_info *info, const fused_isa *isa)
{
    static const char xyz[] = "xyz";
    int world = info->space == OUT_WORLD, n = world ? 3 : 2, k, c;
    if (isa->wide)
        sbuf_puts(o, "        const __m512 rw = _mm512_maskz_div_ps(_mm512_cmp_ps_mask(v[0][3], _mm512_setzero_ps(), "
                     "_CMP_NEQ_UQ),\n            _mm512_set1_ps(1.0f), v[0][3]);\n");
    else
        sbuf_puts(o, "        const __m256 rw = _mm256_and_ps(_mm256_div_ps(_mm256_set1_ps(1.0f), v[0][3]),\n"
                     "            _mm256_cmp_ps(v[0][3], _mm256_setzero_ps(), _CMP_NEQ_UQ));\n");
    for (c = 0; c < n; c++) /* -(x0 rw): the product's sign bit flipped */
        if (isa->wide)
            sbuf_printf(o, "        const __m512 o%c = _mm512_castsi512_ps(_mm512_xor_si512(_mm512_castps_si512("
                           "_mm512_mul_ps(v[0][%d], rw)),\n            _mm512_set1_epi32(INT32_MIN)));\n",
                        xyz[c], c);
        else
            sbuf_printf(o, "        const __m256 o%c = _mm256_xor_ps(_mm256_mul_ps(v[0][%d], rw), _mm256_set1_ps(-0.0f));\n",
                        xyz[c], c);
    for (c = 0; world && c < 3; c++)
        sbuf_printf(o, "        const %s l%d = %s_fmadd_ps(o%c, e3, e%d);\n", isa->vec, c, isa->fam, xyz[c], c);
    for (k = 0; k < 3; k++) {
        for (c = 0; c < n; c++)
            sbuf_printf(o, "        const %s %c%d = %s_fmadd_ps(o%c, v[%d][3], v[%d][%d]);\n", isa->vec,
                        xyz[c], k, isa->fam, xyz[c], k, k, c);
        sbuf_printf(o, "        const %s w%d = v[%d][3];\n", isa->vec, k, k);
    }
}

/* The fused kernel's value u of the degree-1 plane from the rows v[k][0 to 3] (x, y, z, w) of its
 * three points (in patch-local coordinates x<k> ..., put_frame): the float operations of
 * classify's straight-line code for degree 1, in its order.
 * World: a_k = e0 y_k - e1 x_k, b_k = e2 w_k - e3 z_k, the minors m_ij = x_i y_j - y_i x_j and
 * n_ij = z_i w_j - w_i z_j, u = ((a0 n12 - a1 n02) + a2 n01) + ((b0 m12 - b1 m02) + b2 m01).
 * Clip: g_k = e2 w_k, u = (g0 m12 - g1 m02) + g2 m01. */
static void put_value(sbuf *o, const out_info *info, const fused_isa *isa)
{
    static const int pair[3][2] = {{1, 2}, {0, 2}, {0, 1}};
    char t[4][32];
    int k, c, world = info->space == OUT_WORLD, local = info->slp->local;
    const char *e0 = local ? "l0" : "e0", *e1 = local ? "l1" : "e1", *e2 = local ? "l2" : "e2";
    if (local)
        put_frame(o, info, isa);
    for (k = 0; k < 3; k++) {
        for (c = 0; c < 4; c++)
            point_name(t[c], sizeof t[c], local, k, c);
        if (world) {
            sbuf_printf(o, "        const %s a%d = ", isa->vec, k);
            put_diff(o, isa, e0, t[1], e1, t[0]);
            sbuf_printf(o, ", b%d = ", k);
            put_diff(o, isa, e2, t[3], "e3", t[2]);
        } else {
            sbuf_printf(o, "        const %s g%d = ", isa->vec, k);
            put_mul(o, isa, "e2", t[3]);
        }
        sbuf_puts(o, ";\n");
    }
    for (k = 0; k < 3; k++)
        for (c = 0; c < 4; c += 2)
            if (c == 0 || world) {
                int i = pair[k][0], j = pair[k][1];
                char a[32], b[32], e[32], f[32];
                point_name(a, sizeof a, local, i, c);
                point_name(b, sizeof b, local, j, c + 1);
                point_name(e, sizeof e, local, i, c + 1);
                point_name(f, sizeof f, local, j, c);
                sbuf_printf(o, "        const %s %c%d_%d = ", isa->vec, c ? 'n' : 'm', i, j);
                put_diff(o, isa, a, b, e, f);
                sbuf_puts(o, ";\n");
            }
    sbuf_puts(o, "        u = ");
    if (world) {
        sbuf_printf(o, "%s_add_ps(", isa->fam);
        put_plane(o, isa, 'a', 'n');
        sbuf_puts(o, ", ");
        put_plane(o, isa, 'b', 'm');
        sbuf_puts(o, ")");
    } else
        put_plane(o, isa, 'g', 'm');
    sbuf_puts(o, ";\n");
}

/* The fused kernel's class words c from u: strict, back (1) iff u < 0, front (0) iff u > 0,
 * else silhouette (2); degenerate, front iff u > 0, silhouette iff u is NaN, else back. The two
 * conditions exclude each other: AVX-512 moves their classes in under compare masks, AVX adds
 * their differences from the default under all-ones compares. */
static void put_class(sbuf *o, const out_info *info, const fused_isa *isa)
{
    static const char *const pred[2][2] = {{"_CMP_LT_OQ", "_CMP_GT_OQ"}, {"_CMP_GT_OQ", "_CMP_UNORD_Q"}};
    static const int cls[2][3] = {{2, 1, 0}, {1, 0, 2}}; /* default, then under each condition */
    const int r = info->rule == OUT_STRICT ? 0 : 1;
    int i;
    if (isa->wide) {
        sbuf_printf(o, "        __m512i c = _mm512_set1_epi32(%d);\n", cls[r][0]);
        for (i = 0; i < 2; i++)
            sbuf_printf(o, "        c = _mm512_mask_mov_epi32(c, _mm512_cmp_ps_mask(u, _mm512_setzero_ps(), %s), "
                           "_mm512_set1_epi32(%d));\n", pred[r][i], cls[r][i + 1]);
        return;
    }
    sbuf_printf(o, "        const __m256i c = _mm256_cvtps_epi32(_mm256_add_ps(_mm256_add_ps(_mm256_set1_ps(%d.0f),",
                cls[r][0]);
    for (i = 0; i < 2; i++)
        sbuf_printf(o, "\n            _mm256_and_ps(_mm256_cmp_ps(u, _mm256_setzero_ps(), %s), _mm256_set1_ps(%d.0f))%s",
                    pred[r][i], cls[r][i + 1] - cls[r][0], i ? "));\n" : "),");
}

int emit_c_mesh(sbuf *o, const tp_table *t, const out_info *info, ptp_error *err)
{
    static const char *const family[3] = {"_mm", "_mm256", "_mm512"};
    static const fused_isa isa[2] = {{"_mm256", "__m256", 0}, {"_mm512", "__m512", 1}};
    static const char *const slot[9] = {"STORES4",  "STORES8", "STORES16", "EYE8",       "EYE16",
                                        "BODY8", "BODY16",  "TRANSPOSE8", "TRANSPOSE16"};
    sbuf parts[9];
    char up[64];
    tpl_slot slots[14];
    int i, st, failed = 0;
    if (t->dom.kind != TP_TRI || t->dom.n != 1)
        return PTP_OK;
    fmt_upper(up, sizeof up, info->prefix);
    for (i = 0; i < 9; i++)
        sbuf_init(&parts[i]);
    for (i = 0; i < 3; i++)
        put_stores(&parts[i], info, up, family[i]);
    for (i = 0; i < 2; i++) {
        put_eye(&parts[3 + i], info, &isa[i]);
        put_value(&parts[5 + i], info, &isa[i]);
        put_class(&parts[5 + i], info, &isa[i]);
        put_transpose(&parts[7 + i], &isa[i]);
    }
    for (i = 0; i < 9; i++) {
        failed |= parts[i].failed;
        slots[4 + i] = (tpl_slot){slot[i], parts[i].s};
    }
    slots[0] = (tpl_slot){"PREFIX", info->prefix};
    slots[1] = (tpl_slot){"UPREFIX", up};
    slots[2] = (tpl_slot){"VALUE", info->space == OUT_CLIP ? "the points in clip space and eye (0, 0, alpha, 0)"
                                                         : "the points and the eye in world space"};
    slots[3] = (tpl_slot){"FUSED", info->certified ? "0" : "1"};
    slots[13] = (tpl_slot){"LOCAL", info->slp->local ? "1" : "0"};
    st = failed ? ptp_fail(err, PTP_ENOMEM, "out of memory writing the C header")
                : tpl_fill(o, "c/mesh.h", slots, 14, err);
    for (i = 0; i < 9; i++)
        sbuf_clear(&parts[i]);
    return st;
}
