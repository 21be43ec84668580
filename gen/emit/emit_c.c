/* emit_c.c: the C target, an stb-style header: the term table, planes, values, and classify (one
 * patch, batch, SoA) as straight-line code, with the second look of --certified or --refine. */
#include "emit/emit_c.h"
#include "emit/emit_c_batch.h"
#include "emit/emit_c_cert.h"
#include "emit/emit_c_mesh.h"
#include "emit/emit_c_refine.h"
#include "emit/fmt.h"
#include "emit/kern.h"
#include "plan/cert.h"
#include "plan/slp.h"
#include "plan/slp_order.h"
#include "plan/slp_point.h"
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

/* One bracket of a term: ((G(b_j) M(k,l) - G(b_k) M(j,l)) + G(b_l) M(j,k)) for one kind, with G
 * named g0, g1, ... and the minors m0_1, ... (letters g and m chosen by the caller). */
static void put_bracket(sbuf *o, const slp_prog *p, const slp_term *x, char g, char m)
{
    const slp_pair *q = p->pairs;
    sbuf_printf(o, "((%c%d * %c%d_%d - %c%d * %c%d_%d) + %c%d * %c%d_%d)", g, x->point[0], m,
                q[x->pair[0]].k, q[x->pair[0]].l, g, x->point[1], m, q[x->pair[1]].k,
                q[x->pair[1]].l, g, x->point[2], m, q[x->pair[2]].k, q[x->pair[2]].l);
}

/* Loads point k's coordinates (world: with the eye's products a, b; clip: g = e2 w) unless
 * done[npairs + k]: where first read, or all up front (put_loads). */
static void put_point(sbuf *o, const slp_prog *p, int k, int world, const char *px,
                      unsigned char *done)
{
    if (done[p->npairs + (size_t)k])
        return;
    done[p->npairs + (size_t)k] = 1;
    if (world)
        sbuf_printf(o, "        const %svf x%d = %svload(q + %d * qs), y%d = %svload(q + %d * qs),\n"
                       "            z%d = %svload(q + %d * qs), w%d = %svload(q + %d * qs);\n"
                       "        const %svf a%d = e0 * y%d - e1 * x%d, b%d = e2 * w%d - e3 * z%d;\n",
                    px, k, px, 4 * k, k, px, 4 * k + 1, k, px, 4 * k + 2, k, px, 4 * k + 3, px, k,
                    k, k, k, k, k);
    else
        sbuf_printf(o, "        const %svf x%d = %svload(q + %d * qs), y%d = %svload(q + %d * qs),\n"
                       "            w%d = %svload(q + %d * qs), g%d = e2 * w%d;\n",
                    px, k, px, 4 * k, k, px, 4 * k + 1, k, px, 4 * k + 3, k, k);
}

/* Declares the minor pair unless done[pair], after its points. */
static void put_minor(sbuf *o, const slp_prog *p, int pair, int world, const char *px,
                      unsigned char *done)
{
    const slp_pair *q = &p->pairs[pair];
    if (done[pair])
        return;
    done[pair] = 1;
    put_point(o, p, q->k, world, px, done);
    put_point(o, p, q->l, world, px, done);
    sbuf_printf(o, "        const %svf m%d_%d = x%d * y%d - y%d * x%d;\n", px, q->k, q->l, q->k, q->l,
                q->k, q->l);
    if (world)
        sbuf_printf(o, "        const %svf n%d_%d = z%d * w%d - w%d * z%d;\n", px, q->k, q->l, q->k,
                    q->l, q->k, q->l);
}

/* The signed sum of the minors (letter m) of fused entries [a, b), positive ones first. */
static void put_minor_sum(sbuf *o, const slp_prog *p, size_t a, size_t b, char m)
{
    size_t i;
    int pass, n = 0;
    for (pass = 0; pass < 2; pass++)
        for (i = a; i < b; i++) {
            const slp_entry *x = &p->entries[i];
            const slp_pair *q = &p->pairs[x->pair];
            if (x->neg != pass)
                continue;
            sbuf_printf(o, "%s%c%d_%d", n++ ? (x->neg ? " - " : " + ") : x->neg ? "-" : "", m, q->k,
                        q->l);
        }
}

/* Appends 2^a u as a doublings, ((u + u) + (u + u)) (the compiler shares the repeats). */
static void put_doubled(sbuf *o, int a)
{
    if (a == 0) {
        sbuf_puts(o, "u");
        return;
    }
    sbuf_puts(o, "(");
    put_doubled(o, a - 1);
    sbuf_puts(o, " + ");
    put_doubled(o, a - 1);
    sbuf_puts(o, ")");
}

/* Appends v's update with the group's sum u at scale s: assigned for the plane's first group.
 * s on the adders (slp_scale_of): 2^k u as one sum of doublings; else u's doublings and all
 * factors but the last into u, the last into v. Any other s: a product, or a multiply-add. */
static void put_group_end(sbuf *o, const rat *s, int first_group, const char *up)
{
    char sv[RAT_STRLEN];
    const char *to = first_group ? "=" : "+=";
    slp_scale c;
    int i;
    rat one;
    rat_set_si(&one, 1);
    rat_get_str(sv, s);
    if (rat_equal(s, &one))
        sbuf_printf(o, "        v %s u;\n", to);
    else if (slp_scale_of(&c, s) && c.nf == 0) {
        sbuf_printf(o, "        v %s ", to);
        put_doubled(o, c.shift);
        sbuf_puts(o, ";\n");
    } else if (slp_scale_of(&c, s)) {
        for (i = 0; i < c.shift; i++)
            sbuf_puts(o, "        u = u + u;\n");
        for (i = 0; i < c.nf; i++) {
            sbuf_printf(o, i + 1 < c.nf ? "        u = " : "        v %s ", to);
            put_doubled(o, c.a[i]);
            sbuf_puts(o, c.sign[i] > 0 ? " + u;\n" : " - u;\n");
        }
    } else if (first_group)
        sbuf_printf(o, "        v = %s.0f * u;\n", sv);
    else
        sbuf_printf(o, "        v = %sVFMAS(%s.0f, u, v);\n", up, sv);
}

/* A fused plane from entries [a, ...): per group u = sum over points b of G(b) times the signed
 * sum of b's minors, with multiply-adds, then v; returns the end of the plane's entries. */
static size_t put_fused(sbuf *o, const slp_prog *p, size_t a, int world, const char *px,
                        const char *up, unsigned char *done)
{
    int plane = p->entries[a].plane, first_group = 1;
    size_t g, b, e, i;
    for (g = a; g < p->nentries && p->entries[g].plane == plane; g = e, first_group = 0) {
        e = slp_group_end(p, g);
        for (b = g; b < e; b = i) {
            int k, pt = p->entries[b].point;
            i = slp_point_end(p, b);
            for (k = (int)b; k < (int)i; k++) /* the minors declared where first used */
                put_minor(o, p, p->entries[k].pair, world, px, done);
            put_point(o, p, pt, world, px, done);
            for (k = 0; k < (world ? 2 : 1); k++) {
                char gl = world ? (k ? 'b' : 'a') : 'g', ml = world && !k ? 'n' : 'm';
                if (b == g && k == 0)
                    sbuf_printf(o, "        u = %c%d * (", gl, pt);
                else
                    sbuf_printf(o, "        u = %sVFMA(%c%d, ", up, gl, pt);
                put_minor_sum(o, p, b, i, ml);
                sbuf_puts(o, b == g && k == 0 ? ");\n" : ", u);\n");
            }
        }
        put_group_end(o, &p->s[p->entries[g].group], first_group, up);
    }
    return g;
}

/* u's update by the class of items [a, b) of kind letter m at |coef| c (slp_point.h): their
 * signed sum, times c by adds (slp_point_by_adds) or a product; assigned for the first class. */
static void put_point_class(sbuf *o, const slp_prog *p, size_t a, size_t b, char m, int first,
                            const char *up)
{
    long c = labs(p->items[a].coef);
    int adds = slp_point_by_adds(c, first), n = 0;
    size_t i;
    if (!adds && first)
        sbuf_printf(o, "        u = %ld.0f * (", c);
    else if (!adds)
        sbuf_printf(o, "        u = %sVFMAS(%ld.0f, ", up, c);
    else
        sbuf_printf(o, "        u %s %s", first ? "=" : "+=", c == 2 ? "(" : "");
    for (i = a; i < b; i++) {
        const slp_item *x = &p->items[i];
        const slp_pair *q = &p->pairs[x->pair];
        sbuf_printf(o, "%s%c%d_%d", n++ ? (x->coef < 0 ? " - " : " + ") : x->coef < 0 ? "-" : "",
                    m, q->k, q->l);
    }
    if (adds && c == 2) /* first: u = t + t */
        sbuf_puts(o, ");\n        u += u;\n");
    else
        sbuf_puts(o, adds ? ";\n" : first ? ");\n" : ", u);\n");
}

/* A point-form plane from item a (slp_point.h): per point and kind, u from the classes, then
 * v = G u or v = fma(G, u, v); returns the end of the plane's items. */
static size_t put_point_form(sbuf *o, const slp_prog *p, size_t a, int world, const char *px,
                             const char *up, unsigned char *done)
{
    size_t e = slp_point_plane_end(p->items, p->nitems, a), f, fe, c, ce, i;
    int k;
    for (f = a; f < e; f = fe) {
        int pt = p->items[f].point;
        fe = slp_point_factor_end(p->items, p->nitems, f);
        for (i = f; i < fe; i++) /* the minors and the point declared where first used */
            put_minor(o, p, p->items[i].pair, world, px, done);
        put_point(o, p, pt, world, px, done);
        for (k = 0; k < (world ? 2 : 1); k++) {
            char gl = world ? (k ? 'b' : 'a') : 'g', ml = world && !k ? 'n' : 'm';
            for (c = f; c < fe; c = ce) {
                ce = slp_point_class_end(p->items, p->nitems, c);
                put_point_class(o, p, c, ce, ml, c == f, up);
            }
            if (f == a && k == 0)
                sbuf_printf(o, "        v = %c%d * u;\n", gl, pt);
            else
                sbuf_printf(o, "        v = %sVFMA(%c%d, u, v);\n", up, gl, pt);
        }
    }
    return e;
}

/* The statements of term i: its group's sum u and, at the end of a group, the plane's v
 * (assigned when the group is the plane's first, first_group). */
static void put_term(sbuf *o, const slp_prog *p, size_t i, int world, int first_group,
                     const char *up)
{
    const slp_term *x = &p->terms[i];
    int first = i == 0 || p->terms[i - 1].group != x->group;
    int last = i + 1 == p->nterms || p->terms[i + 1].group != x->group;
    if (first)
        sbuf_printf(o, "        u = %s", x->neg ? "-" : "");
    else
        sbuf_printf(o, "        u %s ", x->neg ? "-=" : "+=");
    if (world) {
        sbuf_puts(o, "(");
        put_bracket(o, p, x, 'a', 'n');
        sbuf_puts(o, " + ");
        put_bracket(o, p, x, 'b', 'm');
        sbuf_puts(o, ")");
    } else
        put_bracket(o, p, x, 'g', 'm');
    sbuf_puts(o, ";\n");
    if (last)
        put_group_end(o, &p->s[x->group], first_group, up);
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
    if (world)
        sbuf_puts(o, "    const float e0 = eye[0], e1 = eye[1], e2 = eye[2], e3 = eye[3];\n");
    else
        sbuf_puts(o, "    const float e2 = eye[2];\n");
    if (info->certified) {
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
 * degenerate rule: every point's coordinates up front (put_point) and the collapsed edges. */
static void put_loads(sbuf *o, const slp_prog *p, const tp_table *t, const out_info *info,
                      const cert_bounds *cb, const char *up, unsigned char *done)
{
    int k;
    if (!info->certified)
        return;
    if (emit_c_cert_late(info)) {
        sbuf_printf(o, "#if !%sCLATE\n", up);
        emit_c_cert_magnitudes(o, t->dom.npoints, info, cb);
        sbuf_puts(o, "#endif\n");
        return;
    }
    emit_c_cert_magnitudes(o, t->dom.npoints, info, cb);
    if (!emit_c_cert_zeros(info))
        return;
    for (k = 0; k < t->dom.npoints; k++)
        put_point(o, p, k, info->space == OUT_WORLD, info->prefix, done);
    emit_c_cert_collapsed(o, &t->dom, info);
}

/* With d: d[P * ds + l] = the value v of plane P of each patch l times 1/c_P (its scale), which
 * keeps v's sign. */
static void put_value_store(sbuf *o, const slp_prog *p, int plane, const char *px)
{
    char k[40];
    rat one, inv;
    rat_set_si(&one, 1);
    sbuf_printf(o, "        if (d)\n            %svstoref(d + %d * ds + l, v", px, plane);
    if (!rat_equal(&p->c[plane], &one) && !rat_div(&inv, &one, &p->c[plane]))
        sbuf_printf(o, " * %s", fmt_float_literal(k, &inv));
    sbuf_puts(o, ", n - l);\n");
}

/* The terms of exact plane from term a, in bracket form; returns the end of its terms. */
static size_t put_exact(sbuf *o, const slp_prog *p, size_t a, int world, const char *px,
                        const char *up, unsigned char *done)
{
    size_t i;
    int first_group = 1, k;
    for (i = a; i < p->nterms && p->terms[i].plane == p->terms[a].plane; i++) {
        for (k = 0; k < 3; k++)
            put_minor(o, p, p->terms[i].pair[k], world, px, done);
        for (k = 0; k < 3; k++)
            put_point(o, p, p->terms[i].point[k], world, px, done);
        if (i > a && p->terms[i - 1].group != p->terms[i].group)
            first_group = 0;
        put_term(o, p, i, world, first_group, up);
    }
    return i;
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

/* slp_order's registers (AVX-512 has 32 vector registers; 8 left for sums and temporaries) and
 * window (the planes it picks from): the fastest of those tried with gcc 12 and clang 14 on
 * bicubic patches (bench/README: Plane order). */
#define SLP_ORDER_CAP 24
#define SLP_ORDER_WIN 4

/* The straight-line program: every plane, exact or fused, in slp_order's order (consecutive
 * planes share registers), then its value into the masks (and into d). */
static int put_program(sbuf *o, const slp_prog *p, const cert_bounds *cb, const out_info *info,
                       const char *up, unsigned char *done, ptp_error *err)
{
    const char *px = info->prefix;
    int world = info->space == OUT_WORLD, n = 0, k, st;
    size_t *term = malloc(((size_t)p->nplanes + 1) * 3 * sizeof *term), *entry = term + p->nplanes,
           *item = entry + p->nplanes, i;
    int *order = malloc(((size_t)p->nplanes + 1) * sizeof *order);
    if (!term || !order) {
        st = ptp_fail(err, PTP_ENOMEM, "out of memory writing the C header");
        goto out;
    }
    for (i = p->nterms; i-- > 0;) /* each plane's first term and first fused entry */
        term[p->terms[i].plane] = i;
    for (i = p->nentries; i-- > 0;)
        entry[p->entries[i].plane] = i;
    for (i = p->nitems; i-- > 0;)
        item[p->items[i].plane] = i;
    if ((st = slp_order(order, &n, p, SLP_ORDER_CAP, SLP_ORDER_WIN, err)) != PTP_OK)
        goto out;
    for (k = 0; k < n; k++) {
        if (p->form[order[k]] == SLP_BRACKET)
            put_exact(o, p, term[order[k]], world, px, up, done);
        else if (p->form[order[k]] == SLP_FUSED)
            put_fused(o, p, entry[order[k]], world, px, up, done);
        else
            put_point_form(o, p, item[order[k]], world, px, up, done);
        put_value_store(o, p, order[k], px);
        put_masks(o, p, cb, info, up, order[k], k == 0);
    }
out:
    free(term);
    free(order);
    return st;
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

/* The straight-line kernel over n patches in structure-of-arrays order (the lanes function). */
static int put_lanes(sbuf *o, const slp_prog *p, const cert_bounds *cb, const tp_table *t,
                     const out_info *info, const char *up, ptp_error *err)
{
    unsigned char *done = calloc(p->npairs + (size_t)p->npoints, 1); /* minors, then points */
    int st;
    if (!done)
        return ptp_fail(err, PTP_ENOMEM, "out of memory writing the C header");
    put_lanes_head(o, info, cb, up);
    put_lanes_loop(o, info, up);
    put_loads(o, p, t, info, cb, up, done);
    st = put_program(o, p, cb, info, up, done, err);
    free(done);
    if (st == PTP_OK && emit_c_cert_late(info))
        emit_c_cert_late_bounds(o, t->dom.npoints, info, cb, up);
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
    slp_prog prog;
    cert_bounds cb = {0};
    int st = slp_build(&prog, t, err);
    if (st)
        return st;
    snprintf(flops, 24, "%ld", slp_flops(&prog, info->space == OUT_WORLD));
    snprintf(muls, 24, "%ld", slp_muls(&prog, info->space == OUT_WORLD));
    if (info->certified)
        st = cert_slp(&cb, &prog, info->space == OUT_WORLD, err);
    if (!st)
        st = put_lanes(o, &prog, &cb, t, info, up, err);
    if (!st)
        st = put_entries(o, t, &prog, info, up, err);
    cert_clear(&cb);
    slp_clear(&prog);
    return st;
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
    sbuf_clear(&banner);
    sbuf_clear(&tables);
    sbuf_clear(&funcs);
    sbuf_clear(&variant);
    return st;
}
