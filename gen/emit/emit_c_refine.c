/* emit_c_refine.c: the C header's --refine K: e.T split by de Casteljau into four pieces while
 * its signs are mixed (--certified: in double, each value with a bound); per domain, one row of `kinds`. */
#include "emit/emit_c_refine.h"

#include <math.h>
#include <stdio.h>

/* The arithmetic of split_class: float values, or (--certified) <prefix>cval, a double value
 * with a bound on its error, averaged by <prefix>mid. */
typedef struct {
    const char *px;
    char type[72]; /* "float" or "<prefix>cval" */
    int certified;
} refine_num;

/* Appends the average of a and b in num's arithmetic. */
static void put_mid(sbuf *o, const refine_num *num, const char *a, const char *b)
{
    if (num->certified)
        sbuf_printf(o, "%smid(%s, %s)", num->px, a, b);
    else
        sbuf_printf(o, "0.5f * (%s + %s)", a, b);
}

/* What a domain's subdivision writes into the shared split_class. */
typedef struct {
    const char *shape;  /* "patch", "triangle" */
    const char *pieces; /* how the four pieces are cut: "quarters split at u = v = 1/2" */
    /* the control values and their numbering, for the comment: "d[I * 8 + J] (bidegree\n * 7x7)" */
    void (*values)(char *buf, size_t size, const tp_domain *d, const tp_domain_text *x);
    /* the corners: their count and the index expressions of d[] (16 bytes each) */
    int (*corners)(char (*c)[16], const tp_domain *d);
    /* functions split_class calls, before it (or nothing) */
    void (*helpers)(sbuf *o, const tp_domain *d, const refine_num *num);
    /* the declarations of split_class's locals */
    void (*locals)(sbuf *o, const tp_domain *d, const refine_num *num);
    /* the split into four pieces, each passed to the recursion (put_recurse), after the checks */
    void (*split)(sbuf *o, const tp_domain *d, const refine_num *num, const char *up);
} refine_kind;

/* Appends the recursion into piece q of the split, at indentation ind, where first is the
 * condition that this is not the first piece: every piece must agree on back or front. */
static void put_recurse(sbuf *o, int ind, const char *q, const char *later, const char *px,
                        const char *up)
{
    sbuf_printf(o,
                "%*sunsigned c = %ssplit_class(%s, levels - 1);\n"
                "%*sif (c == %sSILHOUETTE || (%s && c != cls))\n"
                "%*s    return %sSILHOUETTE;\n"
                "%*scls = c;\n",
                ind, "", px, q, ind, "", up, later, ind, "", up, ind, "");
}

static void quad_values(char *buf, size_t size, const tp_domain *d, const tp_domain_text *x)
{
    snprintf(buf, size, "d[I * %d + J] (%s\n * %s)", d->pv + 1, x->word, x->plane_degree);
}

static int quad_corners(char (*c)[16], const tp_domain *d)
{
    (void)d;
    snprintf(c[0], 16, "0");
    snprintf(c[1], 16, "V");
    snprintf(c[2], 16, "U * (V + 1)");
    snprintf(c[3], 16, "N - 1");
    return 4;
}

static void quad_helpers(sbuf *o, const tp_domain *d, const refine_num *num)
{
    (void)o;
    (void)d;
    (void)num;
}

static void quad_locals(sbuf *o, const tp_domain *d, const refine_num *num)
{
    sbuf_printf(o, "    enum { U = %d, V = %d, N = (U + 1) * (V + 1) };\n"
                   "    %s h[2][N], q[2][N], w[U > V ? U + 1 : V + 1];\n"
                   "    unsigned n = 0, p = 0, cn, cp, x, a, b, cls = 0;\n"
                   "    int i, j, k;\n",
                d->pu, d->pv, num->type);
}

/* Quads: halves along u by the curve de Casteljau of every column, then each half along v. */
static void quad_split(sbuf *o, const tp_domain *d, const refine_num *num, const char *up)
{
    (void)d;
    sbuf_puts(o,
              "    for (j = 0; j <= V; j++) { /* along u: h[0] on u in [0, 1/2], h[1] on [1/2, 1] */\n"
              "        for (i = 0; i <= U; i++)\n            w[i] = d[i * (V + 1) + j];\n"
              "        for (i = 0; i <= U; i++) {\n"
              "            h[0][i * (V + 1) + j] = w[0];\n"
              "            h[1][(U - i) * (V + 1) + j] = w[U - i];\n"
              "            for (k = 0; k < U - i; k++)\n                w[k] = ");
    put_mid(o, num, "w[k]", "w[k + 1]");
    sbuf_puts(o, ";\n"
              "        }\n"
              "    }\n"
              "    for (a = 0; a < 2; a++) {\n"
              "        for (i = 0; i <= U; i++) { /* h[a] along v into q[0] and q[1] */\n"
              "            for (j = 0; j <= V; j++)\n                w[j] = h[a][i * (V + 1) + j];\n"
              "            for (j = 0; j <= V; j++) {\n"
              "                q[0][i * (V + 1) + j] = w[0];\n"
              "                q[1][i * (V + 1) + V - j] = w[V - j];\n"
              "                for (k = 0; k < V - j; k++)\n                    w[k] = ");
    put_mid(o, num, "w[k]", "w[k + 1]");
    sbuf_puts(o, ";\n"
              "            }\n"
              "        }\n"
              "        for (b = 0; b < 2; b++) {\n");
    put_recurse(o, 12, "q[b]", "a + b > 0", num->px, up);
    sbuf_puts(o, "        }\n    }\n");
}

static void tri_values(char *buf, size_t size, const tp_domain *d, const tp_domain_text *x)
{
    (void)d;
    snprintf(buf, size, "d[P] (%s %s,\n * %s)", x->word, x->plane_degree, x->plane_rule);
}

/* The planes (D,0,0), (0,D,0) and (0,0,D), numbered by the domain. */
static int tri_corners(char (*c)[16], const tp_domain *d)
{
    snprintf(c[0], 16, "%d", tp_domain_plane(d, d->pu, 0));
    snprintf(c[1], 16, "%d", tp_domain_plane(d, 0, d->pu));
    snprintf(c[2], 16, "%d", tp_domain_plane(d, 0, 0));
    return 3;
}

/* Triangles: one de Casteljau step (in place, any degree: the plane numbering puts the cells
 * (I+1, J, K), (I, J+1, K), (I, J, K+1) of cell x = r(r+1)/2 + K, r = m-I, of the degree m net
 * at x, x + r + 1, x + r + 2 of the degree m+1 net), and the blossom that gives a piece's net. */
static void tri_helpers(sbuf *o, const tp_domain *d, const refine_num *num)
{
    const char *px = num->px, *ty = num->type;
    sbuf_printf(o,
                "/* One de Casteljau step of the degree-m triangle net w (cell (I, J, K) at r(r+1)/2 + K,\n"
                " * r = m - I) at the midpoint of corners e[0] and e[1] (0: u = 1, 1: v = 1, 2: w = 1; a\n"
                " * corner when they are equal), in place: w becomes the degree m-1 net. */\n"
                "static void %ssplit_step(%s *w, int m, const unsigned char *e)\n{\n"
                "    int r, c, x = 0;\n"
                "    for (r = 0; r < m; r++)\n"
                "        for (c = 0; c <= r; c++, x++) {\n"
                "            %s a = w[x + (e[0] ? r + e[0] : 0)], b = w[x + (e[1] ? r + e[1] : 0)];\n"
                "            w[x] = e[0] == e[1] ? a : ",
                px, ty, ty);
    put_mid(o, num, "a", "b");
    sbuf_printf(o,
                ";\n"
                "        }\n"
                "}\n\n"
                "/* q = the net of d over the triangle with corners e[0], e[1], e[2] (midpoints as in\n"
                " * split_step): q at (I, J, K) is the blossom of d at (e[0]^I, e[1]^J, e[2]^K). */\n"
                "static void %ssplit_piece(%s *q, const %s *d, const unsigned char (*e)[2])\n{\n"
                "    enum { D = %d, N = (D + 1) * (D + 2) / 2 };\n"
                "    %s l[N], m[N], s[N];\n"
                "    int i, j, k, x;\n"
                "    for (x = 0; x < N; x++)\n        l[x] = d[x];\n"
                "    for (i = 0; i <= D; i++) { /* l: d stepped i times at e[0] */\n"
                "        for (x = 0; x < (D - i + 1) * (D - i + 2) / 2; x++)\n            m[x] = l[x];\n"
                "        for (j = 0; j <= D - i; j++) { /* m: l stepped j times at e[1] */\n"
                "            for (x = 0; x < (D - i - j + 1) * (D - i - j + 2) / 2; x++)\n"
                "                s[x] = m[x];\n"
                "            for (k = D - i - j; k > 0; k--)\n                %ssplit_step(s, k, e[2]);\n"
                "            q[(D - i) * (D - i + 1) / 2 + D - i - j] = s[0];\n"
                "            %ssplit_step(m, D - i - j, e[1]);\n"
                "        }\n"
                "        %ssplit_step(l, D - i, e[0]);\n"
                "    }\n"
                "}\n\n",
                px, ty, ty, d->pu, ty, px, px, px);
}

static void tri_locals(sbuf *o, const tp_domain *d, const refine_num *num)
{
    sbuf_printf(o, "    /* the pieces: the corner triangles at u = 1, v = 1, w = 1, and the middle one */\n"
                   "    static const unsigned char piece[4][3][2] = {{{0, 0}, {0, 1}, {0, 2}},\n"
                   "        {{0, 1}, {1, 1}, {1, 2}}, {{0, 2}, {1, 2}, {2, 2}}, {{1, 2}, {0, 2}, {0, 1}}};\n"
                   "    enum { N = %d };\n"
                   "    %s q[N];\n"
                   "    unsigned n = 0, p = 0, cn, cp, x, a, cls = 0;\n",
                d->nplanes, num->type);
}

static void tri_split(sbuf *o, const tp_domain *d, const refine_num *num, const char *up)
{
    (void)d;
    sbuf_printf(o, "    for (a = 0; a < 4; a++) {\n        %ssplit_piece(q, d, piece[a]);\n", num->px);
    put_recurse(o, 8, "q", "a > 0", num->px, up);
    sbuf_puts(o, "    }\n");
}

static const refine_kind kinds[] = {
    [TP_QUAD] = {"patch", "quarters split at u = v = 1/2", quad_values, quad_corners,
                 quad_helpers, quad_locals, quad_split},
    [TP_TRI] = {"triangle", "triangles split at the edge midpoints", tri_values, tri_corners,
                tri_helpers, tri_locals, tri_split},
};

/* Appends the test that value expression e is below zero (neg) or above it, by info's rule:
 * "e < 0.0f" (strict) or "e <= 0.0f"; certified, certainly so: "e.v < -e.b" or "e.v <= -e.b". */
static void put_test(sbuf *o, const refine_num *num, const out_info *info, const char *e, int neg)
{
    const char *op = neg ? (info->rule == OUT_STRICT ? "<" : "<=") : (info->rule == OUT_STRICT ? ">" : ">=");
    if (num->certified)
        sbuf_printf(o, "%s.v %s %s%s.b", e, op, neg ? "-" : "", e);
    else
        sbuf_printf(o, "%s %s 0.0f", e, op);
}

/* Appends " + " between the terms "(test)" of every corner's value d[corner]. */
static void put_corner_sum(sbuf *o, char (*c)[16], int n, const refine_num *num,
                           const out_info *info, int neg)
{
    char e[80];
    int i;
    for (i = 0; i < n; i++) {
        snprintf(e, sizeof e, "d[%s]", c[i]);
        sbuf_puts(o, i ? " + (" : "(");
        put_test(o, num, info, e, neg);
        sbuf_puts(o, ")");
    }
}

/* The shared head of split_class: the comment, the signature, the locals, the decision by the
 * signs of all values, and the corners' check. */
static void put_split_head(sbuf *o, const refine_kind *k, const tp_table *t, const out_info *info,
                           const refine_num *num, const char *up)
{
    const char *px = info->prefix, *neg = info->rule == OUT_STRICT ? "<" : "<=";
    const char *pos = info->rule == OUT_STRICT ? ">" : ">=";
    char values[160], corner[4][16], signs[160];
    tp_domain_text x;
    int nc = k->corners(corner, &t->dom);
    tp_domain_text_get(&x, &t->dom);
    k->values(values, sizeof values, &t->dom, &x);
    if (num->certified)
        snprintf(signs, sizeof signs, "back if every value is certainly %s 0\n * (v %s -b), front if every one is certainly %s 0 (v %s b)",
                 neg, neg, pos, pos);
    else
        snprintf(signs, sizeof signs, "back if all values are %s 0.0f, front if all are %s 0.0f", neg, pos);
    sbuf_printf(o,
                "/* --refine %d: the class of the scalar Bezier %s with control values %s: %s, and otherwise, while levels\n"
                " * remain and the %s corners (values of the function itself) agree, the class the four\n"
                " * %s (de Casteljau) agree on, else silhouette. */\n"
                "static unsigned %ssplit_class(const %s *d, int levels)\n{\n",
                info->refine, k->shape, values, signs, nc == 4 ? "four" : "three", k->pieces, px,
                num->type);
    k->locals(o, &t->dom, num);
    sbuf_puts(o, "    for (x = 0; x < N; x++) {\n        n += ");
    put_test(o, num, info, "d[x]", 1);
    sbuf_puts(o, ";\n        p += ");
    put_test(o, num, info, "d[x]", 0);
    sbuf_printf(o, ";\n    }\n"
                   "    if (n == N)\n        return %sBACK;\n"
                   "    if (p == N)\n        return %sFRONT;\n    cn = ",
                up, up);
    put_corner_sum(o, corner, nc, num, info, 1);
    sbuf_puts(o, ";\n    cp = ");
    put_corner_sum(o, corner, nc, num, info, 0);
    sbuf_printf(o, ";\n    if (levels == 0 || (cn != %d && cp != %d))\n"
                   "        return %sSILHOUETTE; /* the corners differ: a real sign change */\n",
                nc, nc, up);
}

/* --certified: the value type cval and mid, the average of two with its bound. */
static void put_cval(sbuf *o, const char *px)
{
    sbuf_printf(o,
                "/* --certified --refine: a control value v in double and a bound b on its error (exact: b = 0). */\n"
                "typedef struct {\n    double v, b;\n} %scval;\n\n"
                "/* The average of a and b: s = a.v + b.v rounds by at most u|s| (u = 2^-53), halving is\n"
                " * exact but for a subnormal (2^-1075), so the error is at most (a.b + b.b) / 2 + |s| 2^-54\n"
                " * + 2^-1075; the bound is computed in four roundings, widened by 1 + 2^-50, with 2^-1073\n"
                " * for the subnormal terms. Exact zeros (b = 0) average to an exact zero. */\n"
                "static %scval %smid(%scval a, %scval b)\n{\n"
                "    %scval r;\n"
                "    double s = a.v + b.v;\n"
                "    r.v = 0.5 * s;\n"
                "    r.b = a.v == 0 && b.v == 0 && a.b == 0 && b.b == 0\n"
                "              ? 0.0\n"
                "              : (0.5 * (a.b + b.b) + (s < 0 ? -s : s) * %.16e + %.16e) * %.16e;\n"
                "    return r;\n}\n\n",
                px, px, px, px, px, px, ldexp(1, -54), ldexp(1, -1073), 1 + ldexp(1, -50));
}

/* refined: plain, split_class of the values; certified, certify64 in double, then split_class
 * of its values and bounds if it leaves the patch silhouette. */
static void put_refined(sbuf *o, const out_info *info, const char *up)
{
    const char *px = info->prefix;
    if (!info->certified) {
        sbuf_printf(o, "/* The refined class of a patch the plane values leave silhouette. */\n"
                       "static unsigned %srefined(const float cp[][4], const float eye[4])\n{\n"
                       "    float d[%sPLANES];\n"
                       "    %svalues(cp, eye, d);\n"
                       "    return %ssplit_class(d, %d);\n}\n\n",
                    px, up, px, px, info->refine);
        return;
    }
    sbuf_printf(o, "/* The certified refined class of a patch the float bounds leave undecided: certify64's, or\n"
                   " * if it is silhouette, that of its double values with their bounds. */\n"
                   "static unsigned %srefined(const float cp[][4], const float eye[4])\n{\n"
                   "    double v[%sPLANES], b[%sPLANES];\n"
                   "    %scval d[%sPLANES];\n"
                   "    unsigned x, c = %scertify64(cp, eye, v, b);\n"
                   "    if (c != %sSILHOUETTE)\n        return c;\n"
                   "    for (x = 0; x < %sPLANES; x++) {\n"
                   "        d[x].v = v[x];\n        d[x].b = b[x];\n    }\n"
                   "    return %ssplit_class(d, %d);\n}\n\n",
                px, up, up, px, up, px, up, up, px, info->refine);
}

void emit_c_refine(sbuf *o, const tp_table *t, const out_info *info, const char *up)
{
    const refine_kind *k = &kinds[t->dom.kind];
    refine_num num;
    num.px = info->prefix;
    num.certified = info->certified;
    snprintf(num.type, sizeof num.type, "%s%s", info->certified ? info->prefix : "float",
             info->certified ? "cval" : "");
    if (info->certified)
        put_cval(o, info->prefix);
    k->helpers(o, &t->dom, &num);
    put_split_head(o, k, t, info, &num, up);
    k->split(o, &t->dom, &num, up);
    sbuf_puts(o, "    return cls;\n}\n\n");
    put_refined(o, info, up);
}
