/* emit_c.c: the C target, an stb-style header: the term table, planes, values, and classify (one
 * patch, batch, SoA) as straight-line code, with the second look of --certified or --refine. */
#include "emit/emit_c.h"
#include "emit/emit_c_batch.h"
#include "emit/emit_c_cert.h"
#include "emit/emit_c_boundary.h"
#include "emit/emit_c_mesh.h"
#include "emit/emit_c_refine.h"
#include "emit/fmt.h"
#include "emit/kern.h"
#include "plan/cert.h"
#include "plan/slp.h"
#include "emit/slp_text.h"
#include "emit/template.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void emit_c_cross4_component(sbuf *o, int i, const char *cast, int ind)
{
    int p = i == 0 ? 1 : 0, q = i <= 1 ? 2 : 1, s = i == 3 ? 2 : 3, neg = i % 2;
    sbuf_printf(o, "%sa[%d] * (%sb[%d] * c[%d] - %sb[%d] * c[%d]) -\n"
                   "%*s%sb[%d] * (%sa[%d] * c[%d] - %sa[%d] * c[%d]) +\n"
                   "%*s%sc[%d] * (%sa[%d] * b[%d] - %sa[%d] * b[%d])%s",
                neg ? "-(" : "", p, cast, q, s, cast, s, q, ind, "", neg ? "  " : "", p, cast, q, s,
                cast, s, q, ind, "", neg ? "  " : "", p, cast, q, s, cast, s, q, neg ? ")" : "");
}

/* The table loop (the paper's): cross4 and planes; opens the region where gcc contracts no
 * product, which the lanes functions close. */
static void put_functions(sbuf *o, const out_info *info, const char *up)
{
    const char *px = info->prefix;
    int i;
    sbuf_printf(o,
                "/* From here through values gcc contracts no product into an FMA; one region, because gcc\n"
                " * does not inline across optimize options (cross4 into planes, the lanes into values). */\n"
                "#if defined(__GNUC__) && !defined(__clang__)\n"
                "#pragma GCC push_options\n#pragma GCC optimize(\"fp-contract=off\")\n#endif\n\n"
                "/* cross4 of Appendix A of Loop, Niessner and Eisenacher (2011): r . x = -det[a b c x].\n"
                " * Its products are never contracted into FMAs, so two equal points give exactly 0. */\n"
                "static void %scross4(float r[4], const float a[4], const float b[4], const float c[4])\n{\n"
                "#if defined(__clang__)\n#pragma STDC FP_CONTRACT OFF\n#endif\n",
                px);
    for (i = 0; i < 4; i++) {
        sbuf_printf(o, "    r[%d] = ", i);
        emit_c_cross4_component(o, i, "", 11);
        sbuf_puts(o, ";\n");
    }
    sbuf_puts(o, "}\n\n");
    sbuf_printf(o,
                "void %splanes(const float cp[][4], float t[][4])\n{\n"
                "    unsigned x, c;\n"
                "    for (x = 0; x < %sPLANES; x++)\n"
                "        t[x][0] = t[x][1] = t[x][2] = t[x][3] = 0.0f;\n"
                "    for (x = 0; x < %sTERMS; x++) {\n"
                "        float r[4];\n"
                "        %scross4(r, cp[%sterm_idx[x][1]], cp[%sterm_idx[x][2]], cp[%sterm_idx[x][3]]);\n"
                "        for (c = 0; c < 4; c++)\n"
                "            t[%sterm_idx[x][0]][c] += %sterm_wgt[x] * r[c];\n"
                "    }\n}\n\n",
                px, up, up, px, px, px, px, px, px);
}

/* Strict rule, plain or certified: lt (gt) = the lanes whose values so far are all < 0 (> 0),
 * one masked compare a plane into an AVX-512 mask register (gcc otherwise keeps every value live
 * to compare them all at the end), else 0/1 or 0/-1 masks; KCLASS: 1 where lt, 0 where gt, else
 * 2. */
static void put_strict_macros(sbuf *o, const char *px, const char *up)
{
    static const char *const rel[2][2] = {{"LT", "<"}, {"GT", ">"}};
    int i;
    sbuf_printf(o, "/* Strict: lt (gt) = the lanes whose values so far are all < 0 (> 0); KCLASS(lt, gt) = their\n"
                   " * classes: back (1) where lt, front (0) where gt, else silhouette (2). */\n"
                   "#if %sVW == 16\ntypedef __mmask16 %svk;\n", up, px);
    for (i = 0; i < 2; i++)
        sbuf_printf(o, "#define %sK%s0(v) _mm512_cmp_ps_mask((__m512)(v), _mm512_setzero_ps(), _CMP_%s_OS)\n"
                       "#define %sK%s(k, v) _mm512_mask_cmp_ps_mask(k, (__m512)(v), _mm512_setzero_ps(), _CMP_%s_OS)\n",
                    up, rel[i][0], rel[i][0], up, rel[i][0], rel[i][0]);
    sbuf_printf(o, "#define %sKCLASS(lt, gt) ((%svm)_mm512_mask_blend_epi32(lt, _mm512_maskz_mov_epi32((__mmask16)~(gt), \\\n"
                   "    _mm512_set1_epi32(2)), _mm512_set1_epi32(1)))\n#else\ntypedef %svm %svk;\n",
                up, px, px, px);
    for (i = 0; i < 2; i++)
        sbuf_printf(o, "#define %sK%s0(v) ((v) %s 0.0f)\n#define %sK%s(k, v) ((k) & ((v) %s 0.0f))\n",
                    up, rel[i][0], rel[i][1], up, rel[i][0], rel[i][1]);
    sbuf_printf(o, "#define %sKCLASS(lt, gt) (((lt) & 1) + 2 * ((((lt) | (gt)) & 1) ^ 1))\n#endif\n", up);
}

/* The lanes function's comment, attributes and head, and the eye's values (certified: E). */
static void put_lanes_head(sbuf *o, const out_info *info, const cert_bounds *cb, const char *up)
{
    const char *px = info->prefix;
    int world = info->space == OUT_WORLD;
    if (info->certified)
        emit_c_cert_macros(o, px, up);
    if (emit_c_cert_late(info))
        emit_c_cert_late_macros(o, cb, px, up);
    if (info->certified || info->rule == OUT_STRICT)
        put_strict_macros(o, px, up);
    sbuf_printf(o,
                "/* The classification of n patches in structure-of-arrays order: coordinate c of point k\n"
                " * of patch l at soa[(k * 4 + c) * stride + l]. Straight-line code from the exact table\n"
                " * (%sFLOPS per patch): each plane's value at a positive scale as the sum of its terms'\n"
                " * Laplace expansions over shared 2x2 minors. An iteration classifies %sVW patches,\n"
                " * branch-free: GNU C vectors with gcc, one patch that clang vectorizes across iterations\n"
                " * (-march=native for AVX2 or AVX-512). The last patches are padded with copies of the last\n"
                " * one. Exact planes never contract products into FMAs (equal points give exact zeros);\n"
                " * fused planes use explicit multiply-adds. With d, d[P * ds + l] = the value of plane P\n"
                " * of patch l that decides, at true scale: times a positive float per plane, which keeps\n"
                " * its sign, zero or NaN. Inlined into lanes (d NULL), values (and lanes_values). */\n"
                "#if defined(__GNUC__)\n__attribute__((always_inline))\n#endif\n"
                "static inline void %slanes_body(const float *%sRESTRICT soa, size_t stride, size_t n,\n"
                "%*sconst float eye[4], unsigned char *%sRESTRICT cls,\n"
                "%*sfloat *%sRESTRICT d, size_t ds)\n{\n"
                "#if defined(__clang__)\n#pragma STDC FP_CONTRACT OFF\n#endif\n",
                up, up, px, up, (int)strlen(px) + 31, "", up, (int)strlen(px) + 31, "", up);
    if (world && info->slp->local) /* vectors: the frame's multiply-adds take them */
        sbuf_printf(o, "    const %svf e0 = %svsplat(eye[0]), e1 = %svsplat(eye[1]),\n"
                       "        e2 = %svsplat(eye[2]), e3 = %svsplat(eye[3]);\n",
                    px, px, px, px, px);
    else if (world)
        sbuf_puts(o, "    const float e0 = eye[0], e1 = eye[1], e2 = eye[2], e3 = eye[3];\n");
    else
        sbuf_puts(o, "    const float e2 = eye[2];\n");
    if (info->certified && world && info->slp->local) /* the local eye's: in the loop */
        sbuf_printf(o, "    const float E3 = %sABSMAX(0.0f, eye[3]);\n", up);
    else if (info->certified) {
        if (world)
            sbuf_printf(o, "    const float E0 = %sABSMAX(0.0f, e0), E1 = %sABSMAX(0.0f, e1),\n"
                           "        E2 = %sABSMAX(0.0f, e2), E3 = %sABSMAX(0.0f, e3);\n"
                           "    const float E = %sABSMAX(%sABSMAX(E0, E1), %sABSMAX(E2, E3));\n",
                        up, up, up, up, up, up, up);
        else
            sbuf_printf(o, "    const float E = %sABSMAX(0.0f, e2);\n", up);
    }
}

/* The loop over blocks of VW patches: the masks and sums, and the last block padded with copies
 * of the last patch. */
static void put_lanes_loop(sbuf *o, const out_info *info, const char *up)
{
    const char *px = info->prefix;
    int world = info->space == OUT_WORLD;
    int strict = info->rule == OUT_STRICT || info->certified; /* certified: strict with margins */
    char more[96] = ""; /* the masks after lt and gt: certified amb, degenerate nan */
    if (info->certified)
        snprintf(more, sizeof more, ";\n        %svm amb", px);
    else if (!strict)
        strcpy(more, ", nan");
    sbuf_printf(o, "    size_t l;\n    for (l = 0; l < n; l += %sVW) {\n"
                   "        const float *q = soa + l;\n        size_t qs = stride;\n"
                   "        %s%s lt, gt%s;\n        %svf u, v%s;\n"
                   "#if %sVW > 1\n"
                   "        float tail[%sPOINTS * 4 * %sVW];\n"
                   "        if (n - l < %sVW) {\n"
                   "            size_t i, k;\n"
                   "            for (k = 0; k < %sPOINTS * 4; k++)\n"
                   "%s"
                   "%*sfor (i = 0; i < %sVW; i++)\n"
                   "%*s    tail[k * %sVW + i] = soa[k * stride + (l + i < n ? l + i : n - 1)];\n"
                   "            q = tail;\n            qs = %sVW;\n        }\n#endif\n",
                up, px, strict ? "vk" : "vm", more, px,
                info->certified ? ", t, s" : "", up, up, up, up, up,
                world ? "" : "                if (k % 4 != 2) /* z: clip space never reads it */\n",
                world ? 16 : 20, "", up, world ? 16 : 20, "", up, up);
    if (emit_c_cert_late(info))
        sbuf_printf(o, "#if %sCLATE\n        %svf raw[%sPLANES];\n#endif\n", up, px, up);
}

/* Certified: the magnitudes and the size guard, from loads of their own (gcc keeps the points
 * where first read, and the lanes run faster), here unless CLATE puts them after the planes;
 * degenerate rule: every point's coordinates up front (slpt_point) and the collapsed edges. */
static void put_loads(slpt_writer *w, const tp_table *t, const out_info *info,
                      const cert_bounds *cb, const char *up)
{
    int k;
    if (!info->certified)
        return;
    if (emit_c_cert_late(info)) {
        sbuf_printf(w->o, "#if !%sCLATE\n", up);
        emit_c_cert_magnitudes(w, t->dom.npoints, info, cb);
        sbuf_puts(w->o, "#endif\n");
        return;
    }
    emit_c_cert_magnitudes(w, t->dom.npoints, info, cb);
    if (!emit_c_cert_zeros(info))
        return;
    for (k = 0; k < t->dom.npoints; k++)
        slpt_point(w, k);
    emit_c_cert_collapsed(w->o, &t->dom, info);
}

/* With d: d[P * ds + l] = the value v of plane P of each patch l times 1/c_P (its scale), which
 * keeps v's sign. */
static void put_value_store(sbuf *o, const slp_prog *p, int plane, const char *px)
{
    char k[48];
    sbuf_printf(o, "        if (d)\n            %svstoref(d + %d * ds + l, v", px, plane);
    if (slpt_inverse_scale(k, sizeof k, p, plane))
        sbuf_printf(o, " * %s", k);
    sbuf_puts(o, ", n - l);\n");
}

/* Plane P's value v into the masks (set by the first plane): plain strict lt and gt (the strict
 * macros), degenerate lt, gt and nan; certified: emit_c_cert_masks. */
static void put_masks(sbuf *o, const slp_prog *p, const cert_bounds *cb, const out_info *info,
                      const char *up, int plane, int first)
{
    const char *op = first ? "=" : "|=";
    if (info->certified)
        emit_c_cert_masks(o, p, cb, info, up, plane, first);
    else if (info->rule == OUT_STRICT)
        sbuf_printf(o, first ? "        lt = %sKLT0(v);\n        gt = %sKGT0(v); /* plane %d */\n"
                             : "        lt = %sKLT(lt, v);\n        gt = %sKGT(gt, v); /* plane %d */\n",
                    up, up, plane);
    else
        sbuf_printf(o, "        lt %s v < 0.0f;\n        gt %s v > 0.0f;\n"
                       "        nan %s v != v; /* plane %d */\n",
                    op, op, op, plane);
}

/* The lanes and certify64 compute a class arithmetically from 0/1 masks, in these numbers. */
_Static_assert(PTP_FRONT == 0 && PTP_BACK == 1 && PTP_SILHOUETTE == 2, "ptp_class's numbers");

/* The end of the lanes body: each lane's class from the masks, stored; then lanes and values,
 * which inline it. */
static void put_lanes_class(sbuf *o, const out_info *info, const char *up)
{
    const char *px = info->prefix;
    int strict = info->rule == OUT_STRICT || info->certified;
    if (info->certified)
        sbuf_puts(o, "        /* Certified: back (1) iff every value is below minus its bound, front (0) iff\n"
                     "         * every value is above its bound; 3 where only the plain signs decide (a second\n"
                     "         * look in double follows), else silhouette (2). Masks 0 or 1 first. */\n"
                     "        amb |= (s > F) == 0;\n        amb &= 1;\n");
    else if (strict)
        sbuf_puts(o, "        /* Strict: back (1) iff every value < 0, front (0) iff every value > 0, else\n"
                     "         * silhouette (2); arithmetic, not branches. */\n");
    else
        sbuf_puts(o, "        /* Degenerate: back (1) iff no value > 0, front (0) iff no value < 0, else\n"
                     "         * silhouette (2), and NaN silhouette; arithmetic, not branches. Masks 0 or 1 first. */\n"
                     "        lt &= 1;\n        gt &= 1;\n        nan &= 1;\n");
    if (info->certified)
        sbuf_printf(o, "        const %svm notlt = %sKNOT(lt), notgt = %sKNOT(gt);\n", px, up, up);
    if (strict && !info->certified)
        sbuf_printf(o, "        %svstore(cls + l, %sKCLASS(lt, gt), n - l);\n", px, up);
    else
        sbuf_printf(o, "        %svstore(cls + l, %s, n - l);\n", px,
                    info->certified ? "(1 - (notlt | amb)) + 2 * ((notlt | amb) & (notgt | amb)) + (amb & (1 - (notlt & notgt)))"
                                    : "2 * nan + (1 - nan) * ((1 - gt) + 2 * (gt & lt))");
    sbuf_printf(o, "    }\n}\n\n"
                   "/* The classes of n patches: lanes_body without values (one copy: it is large). */\n"
                   "%sNOINLINE\n"
                   "static void %slanes(const float *%sRESTRICT soa, size_t stride, size_t n, const float eye[4],\n"
                   "%*sunsigned char *%sRESTRICT cls)\n{\n"
                   "    %slanes_body(soa, stride, n, eye, cls, NULL, 0);\n}\n\n"
                   "void %svalues(const float cp[][4], const float eye[4], float d[])\n{\n"
                   "    unsigned char c;\n"
                   "    %slanes_body(cp[0], 1, 1, eye, &c, d, 1); /* one patch is the SoA layout with stride 1 */\n}\n",
                up, px, up, (int)strlen(px) + 18, "", up, px, px, px);
    if (!info->refine || info->certified) /* classify_batch's blocks: loads at constant offsets */
        sbuf_printf(o, "\n/* lanes on classify_batch's blocks (stride LANES): one more copy, whose loads need no\n"
                       " * offsets computed from the stride (gcc keeps those in spilled registers). */\n"
                       "%sNOINLINE\n"
                       "static void %slanes_block(const float *%sRESTRICT soa, size_t n, const float eye[4],\n"
                       "%*sunsigned char *%sRESTRICT cls)\n{\n"
                       "    %slanes_body(soa, %sLANES, n, eye, cls, NULL, 0);\n}\n",
                    up, px, up, (int)strlen(px) + 24, "", up, px, up);
    else /* classify_batch refines from a whole block's values */
        sbuf_printf(o, "\n/* The classes and values d[P * ds + l] of n patches (--refine: classify_batch). */\n"
                       "%sNOINLINE\n"
                       "static void %slanes_values(const float *%sRESTRICT soa, size_t stride, size_t n,\n"
                       "%*sconst float eye[4], unsigned char *%sRESTRICT cls, float *d, size_t ds)\n{\n"
                       "    %slanes_body(soa, stride, n, eye, cls, d, ds);\n}\n",
                    up, px, up, (int)strlen(px) + 25, "", up, px);
    sbuf_puts(o, "#if defined(__GNUC__) && !defined(__clang__)\n#pragma GCC pop_options\n#endif\n\n");
}

/* What the lanes' plane_end needs: the bounds and the options. */
typedef struct {
    const cert_bounds *cb;
    const out_info *info;
    const char *up;
} lanes_ctx;

/* The lanes' loads: coordinate c of point k of the VW patches at q. */
static void lanes_load(char *out, size_t size, const slpt_writer *w, int k, int c)
{
    const lanes_ctx *x = w->ctx;
    snprintf(out, size, "%svload(q + %d * qs)", x->info->prefix, 4 * k + c);
}

/* The lanes' 1 / x, 0 where x is 0. */
static void lanes_recip0(char *out, size_t size, const slpt_writer *w, const char *x)
{
    const lanes_ctx *c = w->ctx;
    snprintf(out, size, "%sVRECIP0(%s)", c->up, x);
}

/* After each plane: its value into d, then into the masks. */
static void lanes_plane_end(slpt_writer *w, int plane, int first)
{
    const lanes_ctx *x = w->ctx;
    put_value_store(w->o, w->p, plane, x->info->prefix);
    put_masks(w->o, w->p, x->cb, x->info, x->up, plane, first);
}

/* The straight-line kernel over n patches in structure-of-arrays order (the lanes function). */
static int put_lanes(sbuf *o, const cert_bounds *cb, const tp_table *t,
                     const out_info *info, const char *up, ptp_error *err)
{
    char decl[96], fma[96], fmas[96], shift[96];
    slpt_syntax syn = {"        ", decl, 1, "%s * %s", fma, fmas, shift, lanes_recip0, lanes_load,
                       lanes_plane_end};
    lanes_ctx ctx = {cb, info, up};
    slpt_writer w;
    int st;
    snprintf(decl, sizeof decl, "const %svf ", info->prefix);
    snprintf(fma, sizeof fma, "%sVFMA(%%s, %%s, %%s)", up);
    snprintf(fmas, sizeof fmas, "%sVFMAS(%%s, %%s, %%s)", up);
    snprintf(shift, sizeof shift, "%sVLOCAL(%%s, %%s, %%s)", up);
    if ((st = slpt_init(&w, o, info->slp, &syn, info->space == OUT_WORLD, &ctx, err)))
        return st;
    put_lanes_head(o, info, cb, up);
    put_lanes_loop(o, info, up);
    slpt_frame(&w);
    put_loads(&w, t, info, cb, up);
    st = slpt_program(&w, err);
    if (st == PTP_OK && emit_c_cert_late(info))
        emit_c_cert_late_bounds(&w, t->dom.npoints, info, cb, up);
    slpt_clear(&w);
    if (st == PTP_OK)
        put_lanes_class(o, info, up);
    return st;
}

/* classify (one patch, the SoA layout with stride 1) and classify_soa (the caller's SoA array):
 * the lanes, then the second look named second (or NULL) at the patches they leave as again. */
static void put_classify(sbuf *o, const out_info *info, const char *up, const char *second,
                         const char *again)
{
    const char *px = info->prefix;
    sbuf_printf(o, "unsigned %sclassify(const float cp[][4], const float eye[4])\n{\n"
                   "    unsigned char c;\n"
                   "    %slanes(cp[0], 1, 1, eye, &c); /* one patch is the SoA layout with stride 1 */\n",
                px, px);
    if (second)
        sbuf_printf(o, "    if (c %s)\n        c = (unsigned char)%s%s(cp, eye);\n", again,
                    px, second);
    sbuf_puts(o, "    return c;\n}\n\n");
    sbuf_printf(o, "void %sclassify_soa(const float *soa, size_t stride, size_t patch_count,\n"
                   "                  const float eye[4], unsigned char *cls)\n{\n"
                   "    %slanes(soa, stride, patch_count, eye, cls);\n",
                px, px);
    if (second)
        sbuf_printf(o, "    size_t p;\n    unsigned k, c;\n"
                       "    for (p = 0; p < patch_count; p++)\n"
                       "        if (cls[p] %s) {\n"
                       "            float cp[%sPOINTS][4];\n"
                       "            for (k = 0; k < %sPOINTS; k++)\n"
                       "                for (c = 0; c < 4; c++)\n"
                       "                    cp[k][c] = soa[(k * 4 + c) * stride + p];\n"
                       "            cls[p] = (unsigned char)%s%s((const float (*)[4])cp, eye);\n"
                       "        }\n",
                    again, up, up, px, second);
    sbuf_puts(o, "}\n\n");
}

/* classify_batch prefetches the block that starts at least BATCH_AHEAD_MULS multiply-pipe
 * operations (per lane) ahead of the one it classifies, at most 8 blocks ahead: about a memory
 * latency of work on a fast core (bench/README: PN triangles). */
#define BATCH_AHEAD_MULS 1600

/* The blocks classify_batch prefetches ahead for program p. */
static long batch_ahead(const slp_prog *p, const out_info *info)
{
    long m = slp_muls(p, info->space == OUT_WORLD), a = (BATCH_AHEAD_MULS + m - 1) / (m > 0 ? m : 1);
    return a < 1 ? 1 : a > 8 ? 8 : a;
}

/* The second look, if any, and the three entry points on the lanes: classify (one patch),
 * classify_soa and classify_batch (patch-major). */
static int put_entries(sbuf *o, const tp_table *t, const slp_prog *p, const out_info *info,
                       const char *up, ptp_error *err)
{
    /* what silhouette patches get a second look from: refinement, or certification in double */
    const char *second = info->refine ? "refined" : info->certified ? "certify64" : NULL;
    /* the test of the classes the lanes leave for it: silhouette, 3 (certified: only the plain
     * signs decide), or both (certified refinement) */
    char again[96];
    int st;
    snprintf(again, sizeof again, "%s%s%s", info->certified ? "" : "== ", info->certified ? "" : up,
             !info->certified ? "SILHOUETTE" : info->refine ? ">= 2u" : "== 3u");
    if (info->certified && (st = emit_c_cert_certify64(o, t, p, info, up, err)) != PTP_OK)
        return st;
    if (info->refine)
        emit_c_refine(o, t, info, up);
    put_classify(o, info, up, second, again);
    sbuf_printf(o, "/* classify_batch prefetches the block AHEAD blocks on: about %d multiply-pipe operations a\n"
                   " * lane ahead (a shorter program prefetches further; bench/README: PN triangles). */\n"
                   "#define %sAHEAD %ld\n",
                BATCH_AHEAD_MULS, up, batch_ahead(p, info));
    emit_c_batch(o, t, info, up, second, again);
    return PTP_OK;
}

/* The code from the straight-line program: the lanes function, the second look and the entry
 * points; writes the program's flops and multiply-pipe operations per patch to flops and muls
 * (24 bytes each). */
static int put_code(sbuf *o, char *flops, char *muls, const tp_table *t, const out_info *info,
                    const char *up, ptp_error *err)
{
    const plan_slp *plan = info->slp;
    int st;
    snprintf(flops, 24, "%ld", plan->flops);
    snprintf(muls, 24, "%ld", plan->muls);
    st = put_lanes(o, &plan->cert, t, info, up, err);
    return st ? st : put_entries(o, t, &plan->prog, info, up, err);
}

/* The macros that record the header's variant (the options it was generated with). */
static void put_variant(sbuf *o, const tp_table *t, const out_info *info, const char *up)
{
    if (t->dom.kind == TP_TRI)
        sbuf_printf(o, "#define %sDOMAIN_TRIANGLE 1\n#define %sDEGREE %d\n", up, up, t->dom.n);
    else
        sbuf_printf(o, "#define %sDOMAIN_QUAD 1\n#define %sDEGREE_U %d\n#define %sDEGREE_V %d\n",
                    up, up, t->dom.n, up, t->dom.m);
    sbuf_printf(o, "#define %sSPACE_%s 1\n#define %sRULE_%s 1\n#define %sCERTIFIED %d\n"
                   "#define %sREFINE %d\n",
                up, info->space == OUT_WORLD ? "WORLD" : "CLIP", up,
                info->rule == OUT_DEGENERATE ? "DEGENERATE" : "STRICT", up, info->certified != 0,
                up, info->refine);
}

int emit_c(sbuf *o, const tp_table *t, const out_info *info, ptp_error *err)
{
    sbuf banner, tables, funcs, variant;
    out_info plain;
    char up[64], file[96], points[16], planes[16], count[80], flops[24], muls[24], name[80];
    tpl_slot slots[11];
    int st;
    fmt_upper(up, sizeof up, info->prefix);
    fmt_file_name(file, sizeof file, info->prefix, info->suffix);
    snprintf(points, sizeof points, "%d", t->dom.npoints);
    snprintf(planes, sizeof planes, "%d", t->dom.nplanes);
    snprintf(count, sizeof count, "%sTERMS", up);
    sbuf_init(&banner);
    sbuf_init(&tables);
    sbuf_init(&funcs);
    sbuf_init(&variant);
    put_variant(&variant, t, info, up);
    plain = *info;
    plain.sched = NULL; /* one thread per patch: no schedule */
    fmt_banner(&banner, t, &plain, file, "C99 single header (stb style)",
                " * In exactly one C or C++ file, #define <PREFIX>IMPLEMENTATION before including this header.\n"
                " * C99 or later, or C++11 or later; -ffast-math breaks it and is refused (#error).\n"
                " * Headers of several degrees (prefixes) may be included in one program.\n");
    sbuf_printf(&tables, "\n#define %sTERMS %zu\n", up, t->nterms);
    /* <prefix>term_idx and term_wgt: not the table target's names, so both headers go together */
    snprintf(name, sizeof name, "%sterm_", info->prefix);
    out_c_arrays(&tables, t, NULL, name, count, NULL, 0);
    put_functions(&funcs, info, up);
    st = put_code(&funcs, flops, muls, t, info, up, err);
    if (st) {
        sbuf_clear(&banner);
        sbuf_clear(&tables);
        sbuf_clear(&funcs);
        sbuf_clear(&variant);
        return st;
    }
    slots[0] = (tpl_slot){"BANNER", banner.s};
    slots[1] = (tpl_slot){"PREFIX", info->prefix};
    slots[2] = (tpl_slot){"UPREFIX", up};
    slots[3] = (tpl_slot){"POINTS", points};
    slots[4] = (tpl_slot){"PLANES", planes};
    slots[5] = (tpl_slot){"VALUE", info->space == OUT_CLIP ? "clip space: eye[2] * t_P.z"
                                                         : "world space: eye . t_P"};
    slots[6] = (tpl_slot){"TABLES", tables.s};
    slots[7] = (tpl_slot){"FUNCTIONS", funcs.s};
    slots[8] = (tpl_slot){"FLOPS", flops};
    slots[9] = (tpl_slot){"VARIANT", variant.s};
    slots[10] = (tpl_slot){"MULS", muls};
    st = banner.failed || tables.failed || funcs.failed || variant.failed
             ? ptp_fail(err, PTP_ENOMEM, "out of memory writing the C header")
             : tpl_fill(o, "c/kernel.h", slots, 11, err);
    st = st ? st : emit_c_mesh(o, t, info, err); /* the degree-1 triangle's mesh entry points */
    st = st ? st : emit_c_boundary(o, info, err); /* B-spline input's boundary masks */
    sbuf_clear(&banner);
    sbuf_clear(&tables);
    sbuf_clear(&funcs);
    sbuf_clear(&variant);
    return st;
}
