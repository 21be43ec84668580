/* emit_c_cert.c: the C header's --certified parts: the lanes' magnitudes, margins and collapsed
 * edges, and certify64, the second look in double at the patches float cannot certify. */
#include "emit/emit_c_cert.h"
#include "emit/emit_c.h"
#include "emit/fmt.h"

#include <stdio.h>
#include <string.h>

#include <stdlib.h>

/* Appends a constant double table NAME[n] (17 digits: each literal rounds back to its double;
 * not hex, which C++ lacks before C++17). */
static void put_double_table(sbuf *o, const char *px, const char *name, const double *v, int n)
{
    int i;
    sbuf_printf(o, "static const double %s%s[%d] = {", px, name, n);
    for (i = 0; i < n; i++)
        sbuf_printf(o, "%s%.16e", i == 0 ? "\n    " : i % 4 ? ", " : ",\n    ", v[i]);
    sbuf_puts(o, "\n};\n");
}

/* --certified, second look: the weights and each plane's bounds (the plan's look), as double
 * tables. */
static int put_tables64(sbuf *o, const tp_table *t, const out_info *info, ptp_error *err)
{
    const char *px = info->prefix;
    const cert_bounds *cb = &info->slp->look;
    double *w = malloc((t->nterms + 1) * sizeof *w);
    size_t i;
    if (!w)
        return ptp_fail(err, PTP_ENOMEM, "out of memory writing the C header");
    for (i = 0; i < t->nterms; i++)
        w[i] = rat_get_d(&t->terms[i].w);
    sbuf_puts(o, "/* --certified, second look: the weights in double, and each plane's bound in double. */\n");
    put_double_table(o, px, "wgt64", w, (int)t->nterms);
    put_double_table(o, px, "tau64_k", cb->k64, cb->nplanes);
    put_double_table(o, px, "tau64_f", cb->k2_64, cb->nplanes);
    free(w);
    return PTP_OK;
}

/* certify64's sum of the weighted terms in double, into d. */
static void put_terms64(sbuf *o, int world, const char *px, const char *up)
{
    int k;
    if (world) {
        /* cross4 in double: the products of the minors are exact, as in the table's bound */
        sbuf_puts(o, "        double r[4];\n");
        for (k = 0; k < 4; k++) {
            sbuf_printf(o, "        r[%d] = ", k);
            emit_c_cross4_component(o, k, "(double)", 15);
            sbuf_puts(o, ";\n");
        }
        sbuf_printf(o, "        d[%sterm_idx[x][0]] += %swgt64[x] * ((double)eye[0] * r[0] + (double)eye[1] * r[1] +\n"
                       "                                        (double)eye[2] * r[2] + (double)eye[3] * r[3]);\n"
                       "    }\n",
                    px, px);
    } else {
        sbuf_printf(o, "        d[%sterm_idx[x][0]] += %swgt64[x] * (", px, px);
        emit_c_cross4_component(o, 2, "(double)", 40);
        sbuf_printf(o, ");\n    }\n"
                       "    for (x = 0; x < %sPLANES; x++)\n        d[x] *= eye[2];\n",
                    up);
    }
}

int emit_c_cert_zeros(const out_info *info)
{
    return info->certified && info->rule == OUT_DEGENERATE && !info->slp->bspline;
}

int emit_c_cert_late(const out_info *info)
{
    return info->certified && !emit_c_cert_zeros(info);
}

/* The input is not u-major Bezier points: certify64 reads them through points64. */
static int converted(const out_info *info)
{
    return info->slp->bspline || info->slp->vmajor;
}

/* The input's index of point k (as the domain numbers it): k, or from v-major input
 * plan_input_index's of its (i, j). */
static int input_point(const out_info *info, const tp_domain *d, int k)
{
    int i, j;
    tp_domain_point_ij(&i, &j, d, k);
    return info->slp->vmajor ? plan_input_index(info->slp, i, j) : k;
}

/* certify64's collapsed edges (degenerate rule): each plane's edges zero[], same(), and
 * collapsed(cp): bit e where edge e's points are equal and every coordinate is finite. */
static void put_collapsed64(sbuf *o, const slp_prog *p, const tp_domain *d, const out_info *info,
                            const char *up)
{
    const char *px = info->prefix;
    int world = info->space == OUT_WORLD, e, k, x, n, pt[TP_EDGE_POINTS_MAX];
    sbuf_printf(o, "\n/* Degenerate rule: bit e of zero[P] where every term of plane P has two points on boundary\n"
                   " * edge e, so that the plane is exactly 0 when that edge is collapsed. */\n"
                   "static const unsigned char %szero[%sPLANES] = {", px, up);
    for (k = 0; k < p->nplanes; k++)
        sbuf_printf(o, "%s%d", k == 0 ? "\n    " : k % 16 ? ", " : ",\n    ", p->zero[k]);
    sbuf_printf(o, "\n};\n\n/* 1 if a and b are equal in every coordinate the kernel reads (+0 == -0, NaN never). */\n"
                   "static unsigned %ssame(const float a[4], const float b[4])\n{\n"
                   "    return (a[0] == b[0]) & (a[1] == b[1]) & %s(a[3] == b[3]);\n}\n\n"
                   "/* Bit e where boundary edge e of cp is collapsed: its points equal, every coordinate finite. */\n"
                   "static unsigned %scollapsed(const float cp[][4])\n{\n"
                   "    unsigned x, k, fin = 1, col = 0;\n"
                   "    for (x = 0; x < %sPOINTS; x++)\n"
                   "        for (k = 0; k < 4; k++)\n"
                   "            fin &= %scp[x][k] - cp[x][k] == 0;\n",
                px, world ? "(a[2] == b[2]) & " : "", px, up, world ? "" : "k == 2 || ");
    for (e = 0; e < tp_domain_edges(d); e++) {
        sbuf_printf(o, "    col |= (");
        n = tp_domain_edge_points(pt, d, e);
        for (x = 1; x < n; x++)
            sbuf_printf(o, "%s%ssame(cp[%d], cp[%d])", x > 1 ? " & " : "", px,
                        input_point(info, d, pt[x]), input_point(info, d, pt[0]));
        sbuf_printf(o, ") << %d;\n", e);
    }
    sbuf_puts(o, "    return fin * col;\n}\n");
}

/* Appends points64(cp, in): the u-major Bezier points certify64 reads, in double, from the input
 * in: v-major points reordered; B-spline vertices converted to 36 times their Bezier points by
 * the uniform cubic map along u, then along v (exact products, two sums a pass: at most
 * CERT_BSPLINE_ROUNDINGS roundings a coordinate, cert_table's count). */
static void put_points64(sbuf *o, const out_info *info, const tp_domain *d, const char *up)
{
    const char *px = info->prefix;
    int i, j, n = 0;
    sbuf_printf(o, "\n/* certify64's u-major Bezier points%s of the input in. */\n"
                   "static void %spoints64(double cp[][4], const float in[][4])\n{\n",
                info->slp->bspline ? " (times 36, in double)" : "", px);
    if (!info->slp->bspline) {
        sbuf_printf(o, "    static const unsigned char at[%sPOINTS] = {", up);
        for (i = 0; i <= d->n; i++)
            for (j = 0; j <= d->m; j++, n++)
                sbuf_printf(o, "%s%d", n == 0 ? "" : ", ", input_point(info, d, n));
        sbuf_printf(o, "};\n    unsigned x, c;\n    for (x = 0; x < %sPOINTS; x++)\n"
                       "        for (c = 0; c < 4; c++)\n            cp[x][c] = in[at[x]][c];\n}\n", up);
        return;
    }
    sbuf_printf(o, "    static const double m[4][4] = {{1, 4, 1, 0}, {0, 4, 2, 0}, {0, 2, 4, 0}, {0, 1, 4, 1}};\n"
                   "    double h[16][4], s;\n    unsigned i, j, k, c;\n"
                   "    for (i = 0; i < 4; i++) /* along u */\n"
                   "        for (j = 0; j < 4; j++)\n            for (c = 0; c < 4; c++) {\n"
                   "                for (s = 0, k = 0; k < 4; k++)\n"
                   "                    s += m[i][k] * in[%s][c];\n"
                   "                h[i * 4 + j][c] = s;\n            }\n"
                   "    for (i = 0; i < 4; i++) /* along v */\n"
                   "        for (j = 0; j < 4; j++)\n            for (c = 0; c < 4; c++) {\n"
                   "                for (s = 0, k = 0; k < 4; k++)\n"
                   "                    s += m[j][k] * h[i * 4 + k][c];\n"
                   "                cp[i * 4 + j][c] = s;\n            }\n}\n",
                info->slp->vmajor ? "j * 4 + k" : "k * 4 + j");
}

/* Appends certify64's head through R, E, ER3 and F: R the largest |coordinate| of the points it
 * reads (from B-spline input 36 times the vertices'), E the eye's. */
static void put_certify64_head(sbuf *o, const out_info *info, const char *up)
{
    const char *px = info->prefix, *in = converted(info) ? "in" : "cp";
    int world = info->space == OUT_WORLD;
    sbuf_printf(o,
                "\n/* The certified class of a patch whose plain float signs decide but whose bounds do not, from\n"
                " * the table loop in double: |d_P - exact| <= tau64_k[P] E R^3 + tau64_f[P] (1 + R)^3 (1 + E). */\n"
                "static unsigned %scertify64(const float %s[][4], const float eye[4]%s)\n{\n    double ",
                px, in, info->refine ? ", double d[], double b[]" : "");
    if (converted(info))
        sbuf_printf(o, "cp[%sPOINTS][4], ", up);
    if (!info->refine)
        sbuf_printf(o, "d[%sPLANES], ", up);
    sbuf_printf(o, "R = 0, E = 0, ER3, F;\n    unsigned x, k, notlt = 0, notgt = 0%s;\n",
                emit_c_cert_zeros(info) ? ", col" : "");
    if (converted(info))
        sbuf_printf(o, "    %spoints64(cp, in);\n", px);
    sbuf_printf(o,
                "    for (x = 0; x < %sPLANES; x++)\n        d[x] = 0;\n"
                "    for (x = 0; x < %sPOINTS; x++)\n"
                "        for (k = 0; k < 4; k++)\n"
                "            if (%s)\n"
                "                R = %sABSMAX(R, (double)%s[x][k]);\n%s"
                "    for (k = 0; k < 4; k++)\n"
                "        if (%s)\n"
                "            E = %sABSMAX(E, (double)eye[k]);\n"
                "    ER3 = E * (R * R * R);\n"
                "    F = (1 + R) * (1 + R) * (1 + R) * (1 + E);\n",
                up, up, world ? "1" : "k != 2", up, in,
                info->slp->bspline ? "    R *= 36; /* exact: the Bezier points are 36 times the true ones */\n" : "",
                world ? "1" : "k == 2", up);
}

int emit_c_cert_certify64(sbuf *o, const tp_table *t, const slp_prog *p, const out_info *info,
                          const char *up, ptp_error *err)
{
    const char *px = info->prefix;
    int world = info->space == OUT_WORLD, st = put_tables64(o, t, info, err);
    if (st)
        return st;
    if (emit_c_cert_zeros(info))
        put_collapsed64(o, p, &t->dom, info, up);
    if (converted(info))
        put_points64(o, info, &t->dom, up);
    put_certify64_head(o, info, up);
    sbuf_printf(o,
                "    for (x = 0; x < %sTERMS; x++) {\n"
                "        const %s *a = cp[%sterm_idx[x][1]], *b = cp[%sterm_idx[x][2]], *c = cp[%sterm_idx[x][3]];\n",
                up, converted(info) ? "double" : "float", px, px, px);
    put_terms64(o, world, px, up);
    if (emit_c_cert_zeros(info))
        sbuf_printf(o,
                    "    col = %scollapsed(%s);\n"
                    "    for (x = 0; x < %sPLANES; x++) {\n"
                    "        double bound = %stau64_k[x] * ER3 + %stau64_f[x] * F;\n"
                    "        unsigned z = (%szero[x] & col) != 0; /* exactly 0 */\n"
                    "        notlt |= ((d[x] < -bound) | z) == 0;\n"
                    "        notgt |= ((d[x] > bound) | z) == 0;\n%s"
                    "    }\n",
                    px, converted(info) ? "in" : "cp", up, px, px, px,
                    info->refine ? "        d[x] = z ? 0.0 : d[x]; /* for refined */\n"
                                   "        b[x] = z ? 0.0 : bound;\n" : "");
    else
        sbuf_printf(o,
                    "    for (x = 0; x < %sPLANES; x++) {\n"
                    "        double bound = %stau64_k[x] * ER3 + %stau64_f[x] * F;\n"
                    "        notlt |= !(d[x] < -bound);\n"
                    "        notgt |= !(d[x] > bound);\n%s"
                    "    }\n",
                    up, px, px, info->refine ? "        b[x] = bound; /* for refined */\n" : "");
    sbuf_puts(o, "    return (1u - notlt) + 2u * (notlt & notgt);\n}\n\n");
    return PTP_OK;
}

void emit_c_cert_macros(sbuf *o, const char *px, const char *up)
{
    /* the 512-bit minimum in its masked form: the plain one reads an undefined vector, which
     * g++ 12 reports as maybe uninitialized */
    static const char *const with[3][3] = {
        {"16", "", "_mm512_mask_min_epi32((__m512i)(a), (__mmask16)-1, (__m512i)(a), (__m512i)(b))"},
        {"8", " && defined(__AVX2__)", "_mm256_min_epi32((__m256i)(a), (__m256i)(b))"},
        {"4", " && defined(__SSE4_1__)", "_mm_min_epi32((__m128i)(a), (__m128i)(b))"}};
    int i;
    sbuf_printf(o, "/* Certified: |x| lane by lane (NaN stays NaN), and the lesser of a and b: vectors by their\n"
                   " * bits as signed integers, which order floats >= +0 as floats and put the others below. */\n"
                   "#if %sVW > 1\n#define %sVABS(x) ((%svf)((%svm)(x) & 0x7fffffff))\n",
                up, up, px, px);
    for (i = 0; i < 3; i++)
        sbuf_printf(o, "#%s %sVW == %s%s\n#include <immintrin.h>\n#define %sVMIN(a, b) ((%svf)%s)\n",
                    i ? "elif" : "if", up, with[i][0], with[i][1], up, px, with[i][2]);
    sbuf_printf(o, "#else\n#define %sVMIN(a, b) ((%svf)(((%svm)(a) & ((%svm)(a) < (%svm)(b))) | ((%svm)(b) & ((%svm)(a) >= (%svm)(b)))))\n"
                   "#endif\n#else\n#define %sVABS(x) ((x) < 0.0f ? -(x) : (x))\n#define %sVMIN(a, b) ((a) < (b) ? (a) : (b))\n#endif\n",
                up, px, px, px, px, px, px, px, up, up);
    sbuf_printf(o, "/* Certified: KC(c) = the lanes of a 0/-1 mask c as the strict masks hold them, KNOT(k) = 1\n"
                   " * where mask k is clear and 0 where it is set. */\n"
                   "#if %sVW == 16\n#define %sKC(c) _mm512_test_epi32_mask((__m512i)(c), (__m512i)(c))\n"
                   "#define %sKNOT(k) ((%svm)_mm512_maskz_mov_epi32((__mmask16)~(k), _mm512_set1_epi32(1)))\n"
                   "#else\n#define %sKC(c) (c)\n#define %sKNOT(k) (((k) & 1) ^ 1)\n#endif\n",
                up, up, up, px, up, up);
}

void emit_c_cert_late_macros(sbuf *o, const cert_bounds *cb, const char *px, const char *up)
{
    int k;
    sbuf_printf(o, "/* Certified: cert_k[P] = -K_P, the bound of plane P's value over ER3. CMIN(P, x): s = the\n"
                   " * least of s and |x| - K_P ER3. CBOUND(P) bounds the value v of plane P: with vectors (gcc,\n"
                   " * CLATE) the lanes keep v in raw[P] and bound the values in a loop after the planes, which\n"
                   " * keeps the straight-line code as small as the plain one (its size decides its speed); one\n"
                   " * patch a lane (clang vectorizes the loop), at once. */\n"
                   "static const float %scert_k[%d] = {",
                px, cb->nplanes);
    for (k = 0; k < cb->nplanes; k++)
        sbuf_printf(o, "%s%.8ef", k == 0 ? "\n    " : k % 4 ? ", " : ",\n    ", -(double)cb->k[k]);
    sbuf_printf(o, "\n};\n#define %sCMIN(P, x) (t = %sVFMAS(%scert_k[P], ER3, %sVABS(x)), s = %sVMIN(s, t))\n"
                   "#if %sVW > 1\n#define %sCLATE 1\n#define %sCBOUND(P) (raw[P] = v)\n#else\n"
                   "#define %sCLATE 0\n#define %sCBOUND(P) %sCMIN(P, v)\n#endif\n",
                up, up, px, up, up, up, up, up, up, up, up);
}

void emit_c_cert_late_bounds(const slpt_writer *w, int npoints, const out_info *info,
                             const cert_bounds *cb, const char *up)
{
    sbuf *o = w->o;
    sbuf_printf(o, "#if %sCLATE\n"
                   "        __asm__(\"\" : \"+r\"(q)); /* the magnitudes load the points again: not kept live */\n",
                up);
    emit_c_cert_magnitudes(w, npoints, info, cb);
    sbuf_printf(o, "        {\n            size_t P;\n            for (P = 0; P < %sPLANES; P++)\n"
                   "                %sCMIN(P, raw[P]);\n        }\n#endif\n",
                up, up);
}

/* Writes to out (size bytes) the load of coordinate c of point k of the lanes' patches (the
 * masks compare the points as given, each comparison cast to the mask type). */
static void put_load(char *out, size_t size, const char *px, int k, int c)
{
    snprintf(out, size, "%svload(q + %d * qs)", px, 4 * k + c);
}

void emit_c_cert_collapsed(sbuf *o, const tp_domain *d, const out_info *info)
{
    const char *px = info->prefix;
    int world = info->space == OUT_WORLD, e, k, c, x, n, pt[TP_EDGE_POINTS_MAX];
    char a[128], b[128];
    sbuf_printf(o, "        /* Certified, degenerate rule: c<e> where boundary edge e is collapsed (its points\n"
                   "         * equal as given, every coordinate finite); the planes it zeros are then exactly 0. */\n"
                   "        const %svm fin =", px);
    for (k = 0; k < d->npoints; k++)
        for (c = 0; c < 4; c++)
            if (world || c != 2) {
                put_load(a, sizeof a, px, k, c);
                sbuf_printf(o, "%s(%svm)(%s - %s == 0.0f)",
                            c ? " & " : k ? " &\n            " : "\n            ", px, a, a);
            }
    sbuf_puts(o, ";\n");
    for (e = 0; e < tp_domain_edges(d); e++) {
        sbuf_printf(o, "        const %svm c%d = fin", px, e);
        n = tp_domain_edge_points(pt, d, e);
        for (x = 1; x < n; x++) {
            sbuf_puts(o, " &\n            ");
            for (c = 0; c < 4; c++)
                if (world || c != 2) {
                    put_load(a, sizeof a, px, input_point(info, d, pt[x]), c);
                    put_load(b, sizeof b, px, input_point(info, d, pt[0]), c);
                    sbuf_printf(o, "%s(%svm)(%s == %s)", c ? " & " : "", px, a, b);
                }
        }
        sbuf_puts(o, ";\n");
    }
}

/* Appends the magnitude update Rc = max(Rc, |coordinate c of point k|) (declared for k = 0), of
 * the coordinate as the program reads it (slpt_coordinate), or from B-spline input of vertex k
 * as read (slpt_input: the conversion's magnitudes come from the vertices). */
static void put_magnitude(const slpt_writer *w, const out_info *info, int k, int c)
{
    static const char crd[] = "xyzw";
    const char *px = info->prefix;
    char v[SLPT_EXPR];
    if (info->slp->bspline)
        slpt_input(v, w, k, c);
    else
        slpt_coordinate(v, w, k, c);
    if (k == 0)
        sbuf_printf(w->o, "        %svf R%c = %svabsmax(%s, %s);\n", px, crd[c], px, v, v);
    else
        sbuf_printf(w->o, "        R%c = %svabsmax(R%c, %s);\n", crd[c], px, crd[c], v);
}

/* B-spline input: each Rc times 36 (the map's weights of a point, the Bezier points being 36
 * times the true ones), rounded up: 36.0001 clears the product's rounding. */
static void put_bspline_magnitudes(const slpt_writer *w, int world)
{
    int c;
    sbuf_puts(w->o, "        /* B-spline input: a point's magnitude is at most 36 times its vertices'. */\n");
    for (c = 0; c < 4; c++)
        if (world || c != 2)
            sbuf_printf(w->o, "        R%c = R%c * 36.0001f;\n", "xyzw"[c], "xyzw"[c]);
}

void emit_c_cert_magnitudes(const slpt_writer *w, int npoints, const out_info *info,
                            const cert_bounds *cb)
{
    sbuf *o = w->o;
    const char *px = info->prefix;
    int world = info->space == OUT_WORLD, local = info->slp->local, k, c;
    char up[64];
    float k2 = 0;
    fmt_upper(up, sizeof up, px);
    sbuf_printf(o, "        /* Certified: Rc, the largest |coordinate c|%s, bound every value's rounding error. */\n",
                local ? " in patch-local coordinates" : "");
    for (k = 0; k < npoints; k++)
        for (c = 0; c < 4; c++)
            if (world || c != 2)
                put_magnitude(w, info, k, c);
    if (info->slp->bspline)
        put_bspline_magnitudes(w, world);
    if (world && local) /* the local eye's magnitudes, lane by lane */
        sbuf_printf(o, "        const %svf E0 = %sVABS(l0), E1 = %sVABS(l1), E2 = %sVABS(l2);\n"
                       "        const %svf E = %svabsmax(%svabsmax(%svabsmax(E0, E1), E2), E0 * 0.0f + E3);\n",
                    px, up, up, up, px, px, px, px);
    if (world)
        sbuf_printf(o, "        const %svf R = %svabsmax(%svabsmax(Rx, Ry), %svabsmax(Rz, Rw)), R3 = R * R * R;\n"
                       "        const %svf ER3 = %svabsmax(%svabsmax(E0 * Ry, E1 * Rx) * (Rz * Rw),\n"
                       "                                   %svabsmax(E2 * Rw, E3 * Rz) * (Rx * Ry));\n",
                    px, px, px, px, px, px, px, px);
    else
        sbuf_printf(o, "        const %svf R = %svabsmax(%svabsmax(Rx, Ry), Rw), R3 = R * R * R;\n"
                       "        const %svf ER3 = E * (Rx * Ry * Rw);\n",
                    px, px, px, px);
    for (k = 0; k < cb->nplanes; k++)
        k2 = cb->k2[k] > k2 ? cb->k2[k] : k2;
    sbuf_printf(o, "        /* F: the underflow term of every plane's bound, with the largest K2. */\n"
                   "        const %svf F = %.8ef * ((1.0f + R) * (1.0f + R) * (1.0f + R) * (1.0f + E));\n"
                   "        /* Patches too large for the bound (or NaN) are never certified. */\n",
                px, (double)k2);
    if (world && local) /* E lane by lane: max(E, 1) through vabsmax */
        sbuf_printf(o, "        amb = (%svabsmax(E, R * 0.0f + 1.0f) * R3 < %.8ef) == 0;\n", px,
                    (double)cb->q_max);
    else
        sbuf_printf(o, "        amb = ((E > 1.0f ? E : 1.0f) * R3 < %.8ef) == 0;\n", (double)cb->q_max);
    sbuf_puts(o, "        s = F * 0.0f + 3.40282347e+38f; /* the least t of the planes so far */\n");
}

/* Appends "c0 | c2", the masks of the collapsed edges in bits zero (not 0). */
static void put_edges(sbuf *o, unsigned zero)
{
    int e, any = 0;
    for (e = 0; e < 8; e++)
        if (zero >> e & 1)
            sbuf_printf(o, any++ ? " | c%d" : "c%d", e);
}

/* Appends "((cond) | c0 | c2)" with the masks of the collapsed edges in bits zero (not 0). */
static void put_cond(sbuf *o, const char *cond, unsigned zero)
{
    sbuf_printf(o, "((%s) | ", cond);
    put_edges(o, zero);
    sbuf_puts(o, ")");
}

void emit_c_cert_masks(sbuf *o, const slp_prog *p, const cert_bounds *cb, const out_info *info,
                       const char *up, int plane, int first)
{
    static const char *const mask[2][2] = {{"lt", "LT"}, {"gt", "GT"}};
    unsigned zero = emit_c_cert_zeros(info) ? p->zero[plane] : 0;
    int i;
    for (i = 0; i < 2; i++) {
        if (first)
            sbuf_printf(o, "        %s = %sK%s0(v)", mask[i][0], up, mask[i][1]);
        else if (zero)
            sbuf_printf(o, "        %s &= %sK%s0(v)", mask[i][0], up, mask[i][1]);
        else
            sbuf_printf(o, "        %s = %sK%s(%s, v)", mask[i][0], up, mask[i][1], mask[i][0]);
        if (zero) {
            sbuf_printf(o, " | %sKC(", up);
            put_edges(o, zero);
            sbuf_puts(o, ")");
        }
        sbuf_puts(o, i ? ";" : ";\n");
    }
    sbuf_printf(o, " /* plane %d */\n", plane);
    if (emit_c_cert_late(info)) {
        sbuf_printf(o, "        %sCBOUND(%d);\n", up, plane);
        return;
    }
    sbuf_printf(o, "        t = %sVFMAS(%.8ef, ER3, %sVABS(v)); /* minus the bound of plane %d */\n",
                up, -(double)cb->k[plane], up, plane);
    if (!zero) {
        sbuf_printf(o, "        s = %sVMIN(s, t);\n", up);
        return;
    }
    sbuf_puts(o, "        amb |= ");
    put_cond(o, "t > F", zero);
    sbuf_puts(o, " == 0;\n");
}
