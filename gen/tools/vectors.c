/* vectors.c: the ptpgen-vectors/1 document: random integer patches, exact values and classes.
 * A splitmix64 stream draws every case; each value is summed exactly over a common denominator. */
#include "tools/vectors.h"
#include "core/i128.h"

#include <inttypes.h>
#include <stdlib.h>

enum { KIND_NEAR, KIND_FLAT, KIND_COLLAPSED, KIND_EDGE_ON, KIND_CORNER };
static const char *const kind_names[] = {"near-planar", "flat", "collapsed-edge", "edge-on",
                                         "corner-tangent"};

/* What follows the domain's numbering (tp_domain_text's conventions) in "conventions". */
static const char conventions[] =
    "t_P is the sum of "
    "weight*cross4(b_j, b_k, b_l) over the ptpgen-planes/1 terms of plane P, cross4 as in "
    "Appendix A of Loop, Niessner and Eisenacher (2011); values d_P = eye.t_P in world space and "
    "eye.z*t_P.z in clip space, exact and as the nearest double; classes 0 front, 1 back, "
    "2 silhouette: strict, back iff every d_P < 0 and front iff every d_P > 0; degenerate, back "
    "iff no d_P > 0 and front iff no d_P < 0 (all zero counts as back)";

/* An integer in [lo, hi] (the modulo bias does not matter here). */
static int draw(uint64_t *s, int lo, int hi)
{
    return lo + (int)(ptp_splitmix64(s) % (uint64_t)(hi - lo + 1));
}

/* +1 or -1. */
static int draw_sign(uint64_t *s)
{
    return draw(s, 0, 1) ? 1 : -1;
}

/* One case being drawn. */
typedef struct {
    int (*X)[3];     /* the integer 3-D points, before the weights */
    int64_t (*b)[4]; /* the homogeneous control points */
    int64_t eye[4];
    int kind;
} vcase;

/* C, U, V in [-2, 2]^3 with N = U x V != 0; clip: the plane of U and V contains the z axis
 * (edge-on) or does not (N_z != 0). */
static void draw_frame(int C[3], int U[3], int V[3], int N[3], uint64_t *s, out_space space,
                       int edge_on)
{
    int c, vertical = space == OUT_CLIP && edge_on;
    for (c = 0; c < 3; c++)
        C[c] = draw(s, -2, 2);
    do {
        for (c = 0; c < 3; c++) {
            U[c] = draw(s, -2, 2);
            V[c] = draw(s, -2, 2);
        }
        if (vertical)
            V[0] = V[1] = 0;
        N[0] = U[1] * V[2] - U[2] * V[1];
        N[1] = U[2] * V[0] - U[0] * V[2];
        N[2] = U[0] * V[1] - U[1] * V[0];
    } while ((!N[0] && !N[1] && !N[2]) || (space == OUT_CLIP && !vertical && !N[2]));
    if (vertical && draw(s, 0, 1))
        for (c = 0; c < 3; c++) {
            int x = U[c];
            U[c] = V[c];
            V[c] = x;
            N[c] = -N[c];
        }
}

/* v->X = the grid C + a_i U + b_j V plus noise in [-amp, amp]^3 per point (triangles: the
 * cells i + j <= d of the grid). */
static void draw_grid(vcase *v, const tp_table *t, uint64_t *s, const int C[3], const int U[3],
                      const int V[3], int amp)
{
    int i, j, c;
    for (i = 0; i <= t->dom.n; i++)
        for (j = 0; j <= t->dom.m; j++) {
            int *X, a = 6 * i / t->dom.n - 3, b = 6 * j / t->dom.m - 3;
            if (!tp_grid_has(t->dom.kind, t->dom.n, t->dom.m, i, j))
                continue;
            X = v->X[tp_domain_point(&t->dom, i, j)];
            for (c = 0; c < 3; c++)
                X[c] = C[c] + a * U[c] + b * V[c] + draw(s, -amp, amp);
        }
}

/* k[0] = a random corner point, k[1] and k[2] its neighbours along the two edges through it. */
static void draw_corner(int k[3], const tp_table *t, uint64_t *s)
{
    const tp_domain *d = &t->dom;
    if (d->kind == TP_TRI) {
        /* vertex c of the barycentric (i, j, k), and one step from it towards each other one */
        int c = draw(s, 0, 2), x, e[3][3] = {{0}};
        for (x = 0; x < 3; x++)
            e[x][c] = d->n - (x > 0);
        e[1][(c + 1) % 3] = e[2][(c + 2) % 3] = 1;
        for (x = 0; x < 3; x++)
            k[x] = tp_domain_point(d, e[x][0], e[x][1]);
    } else {
        int ci = draw(s, 0, 1) * d->n, cj = draw(s, 0, 1) * d->m;
        k[0] = tp_domain_point(d, ci, cj);
        k[1] = tp_domain_point(d, ci, cj + (cj ? -1 : 1));
        k[2] = tp_domain_point(d, ci + (ci ? -1 : 1), cj);
    }
}

/* Moves a random corner X_0 by noise in [-2, 2]^3 and puts the eye in its tangent plane (the
 * corner plane becomes zero): world, eye = X_0 +- (X_1 - X_0) +- (X_2 - X_0) with X_1, X_2 its
 * neighbours; clip, X_2 takes the x, y of X_0 or X_1. */
static void corner_tangent(vcase *v, const tp_table *t, out_space space, uint64_t *s)
{
    int k[3], c, k0, k1, k2;
    draw_corner(k, t, s);
    k0 = k[0];
    k1 = k[1];
    k2 = k[2];
    for (c = 0; c < 3; c++)
        v->X[k0][c] += draw(s, -2, 2);
    if (space == OUT_CLIP) {
        int from = draw(s, 0, 1) ? k1 : k0;
        v->X[k2][0] = v->X[from][0];
        v->X[k2][1] = v->X[from][1];
    } else {
        int s1 = draw_sign(s), s2 = draw_sign(s);
        for (c = 0; c < 3; c++)
            v->eye[c] = v->X[k0][c] + s1 * (v->X[k1][c] - v->X[k0][c]) +
                        s2 * (v->X[k2][c] - v->X[k0][c]);
    }
}

/* Replaces the control points of one random boundary edge by copies of its first point. */
static void collapse_edge(vcase *v, const tp_table *t, uint64_t *s)
{
    int pt[TP_EDGE_POINTS_MAX], x, c;
    int n = tp_domain_edge_points(pt, &t->dom, draw(s, 0, tp_domain_edges(&t->dom) - 1));
    for (x = 1; x < n; x++)
        for (c = 0; c < 4; c++)
            v->b[pt[x]][c] = v->b[pt[0]][c];
}

/* Draws the next case from s (see vectors.h for the distribution). */
static void draw_case(vcase *v, const tp_table *t, out_space space, uint64_t *s)
{
    int C[3], U[3], V[3], N[3], c, k, r = draw(s, 0, 19), rational = draw(s, 0, 2) == 0;
    v->kind = r < 8 ? KIND_NEAR : r < 11 ? KIND_FLAT : r < 14 ? KIND_COLLAPSED
            : r < 17 ? KIND_EDGE_ON : KIND_CORNER;
    draw_frame(C, U, V, N, s, space, v->kind == KIND_EDGE_ON);
    draw_grid(v, t, s, C, U, V,
              v->kind == KIND_NEAR || v->kind == KIND_COLLAPSED ? draw(s, 1, 2) : 0);
    if (space == OUT_CLIP) {
        v->eye[0] = v->eye[1] = v->eye[3] = 0;
        v->eye[2] = draw_sign(s);
    } else {
        int e = v->kind == KIND_EDGE_ON ? 0 : draw_sign(s) * draw(s, 1, 4);
        int lim = v->kind == KIND_EDGE_ON ? 8 : 2, a = draw(s, -lim, lim), b = draw(s, -lim, lim);
        for (c = 0; c < 3; c++)
            v->eye[c] = C[c] + e * N[c] + a * U[c] + b * V[c];
        v->eye[3] = 1;
    }
    if (v->kind == KIND_CORNER)
        corner_tangent(v, t, space, s);
    for (k = 0; k < t->dom.npoints; k++) {
        int w = rational ? draw(s, 1, VECTORS_W_MAX) : 1;
        v->b[k][0] = w * v->X[k][0];
        v->b[k][1] = w * v->X[k][1];
        v->b[k][2] = space == OUT_CLIP ? w * v->X[k][2] / 17 : w * v->X[k][2];
        v->b[k][3] = w;
    }
    if (v->kind == KIND_COLLAPSED)
        collapse_edge(v, t, s);
}

/* e . cross4(a, b, c), exactly (|result| < 2^24 within the documented bounds). */
static int64_t eye_cross4(const int64_t e[4], const int64_t a[4], const int64_t b[4],
                          const int64_t c[4])
{
#define DET3(p, q, s)                                                                  \
    (a[p] * (b[q] * c[s] - b[s] * c[q]) - b[p] * (a[q] * c[s] - a[s] * c[q]) +          \
     c[p] * (a[q] * b[s] - a[s] * b[q]))
    return e[0] * DET3(1, 2, 3) - e[1] * DET3(0, 2, 3) + e[2] * DET3(0, 1, 3) -
           e[3] * DET3(0, 1, 2);
#undef DET3
}

/* The double nearest to a (ties to even), exactly: a in normal double range. */
static double nearest_double(const rat *a)
{
    ptp_u128 n = i128_abs(a->num), d = (ptp_u128)a->den, q = n / d, r = n % d;
    int e = 0, sticky, low;
    double x;
    if (n == 0)
        return 0.0;
    while (!(q >> 54)) { /* long division until q has 55 bits */
        r <<= 1;         /* r < d < 2^127 */
        q = (q << 1) | (r >= d);
        r -= r >= d ? d : 0;
        e--;
    }
    sticky = r != 0;
    for (; q >> 55; q >>= 1, e++)
        sticky |= (int)(q & 1);
    low = (int)(q & 3); /* the 2 bits below the 53 kept */
    q >>= 2;
    e += 2;
    if (low > 2 || (low == 2 && (sticky || (q & 1))))
        q++;
    for (x = (double)(uint64_t)q; e > 0; e--)
        x *= 2;
    for (; e < 0; e++)
        x *= 0.5;
    return a->num < 0 ? -x : x;
}

/* Appends s as a JSON string. */
static void put_string(sbuf *o, const char *s)
{
    sbuf_puts(o, "\"");
    for (; *s; s++) {
        unsigned char ch = (unsigned char)*s;
        if (ch == '"' || ch == '\\')
            sbuf_printf(o, "\\%c", ch);
        else if (ch < 0x20)
            sbuf_printf(o, "\\u%04x", ch);
        else
            sbuf_printf(o, "%c", ch);
    }
    sbuf_puts(o, "\"");
}

/* The class of a case from the counts of its positive and negative values under a rule. */
static int classify(int pos, int neg, int nvalues, out_rule rule)
{
    if (rule == OUT_STRICT)
        return neg == nvalues ? PTP_BACK : pos == nvalues ? PTP_FRONT : PTP_SILHOUETTE;
    return pos == 0 ? PTP_BACK : neg == 0 ? PTP_FRONT : PTP_SILHOUETTE;
}

/* The state of one call: the table over common denominators, one case, its values. */
typedef struct {
    const tp_table *t;
    ptp_i128 *iw;  /* per term: weight * den[plane], an integer */
    ptp_i128 *den; /* per plane: the least common denominator of its weights */
    ptp_i128 *num; /* per plane: the current case's d_P * den[plane] */
    rat *val;      /* per plane: the current case's d_P */
    vcase v;
} vstate;

/* Fills st->den and st->iw from the exact weights. */
static int common_denominators(vstate *st, ptp_error *err)
{
    const tp_table *t = st->t;
    size_t x;
    int p;
    for (p = 0; p < t->dom.nplanes; p++)
        st->den[p] = 1;
    for (x = 0; x < t->nterms; x++) {
        const tp_term *w = &t->terms[x];
        ptp_i128 *D = &st->den[w->plane];
        if (rat_lcm_den(D, &w->w))
            return ptp_fail(err, PTP_EOVERFLOW, "overflow in the denominator of plane %d",
                            w->plane);
    }
    for (x = 0; x < t->nterms; x++) {
        const tp_term *w = &t->terms[x];
        if (i128_mul_ovf(&st->iw[x], w->w.num, st->den[w->plane] / w->w.den))
            return ptp_fail(err, PTP_EOVERFLOW, "overflow in a weight of plane %d", w->plane);
    }
    return PTP_OK;
}

/* Draws case `index` (the next of stream s) into st->v and sums its values exactly into
 * st->val; sets its classes under both rules. */
static int compute_case(vstate *st, int cls[2], long index, out_space space, uint64_t *s,
                        ptp_error *err)
{
    const tp_table *t = st->t;
    const vcase *v = &st->v;
    int p, pos = 0, neg = 0;
    size_t x;
    draw_case(&st->v, t, space, s);
    for (p = 0; p < t->dom.nplanes; p++)
        st->num[p] = 0;
    for (x = 0; x < t->nterms; x++) {
        const tp_term *w = &t->terms[x];
        ptp_i128 y;
        if (i128_mul_ovf(&y, st->iw[x], eye_cross4(v->eye, v->b[w->j], v->b[w->k], v->b[w->l])) ||
            i128_add_ovf(&st->num[w->plane], st->num[w->plane], y))
            return ptp_fail(err, PTP_EOVERFLOW, "overflow in plane %d of case %ld", w->plane,
                            index);
    }
    for (p = 0; p < t->dom.nplanes; p++) {
        if (rat_set_frac(&st->val[p], st->num[p], st->den[p])) /* |num| <= I128_MAX, den > 0 */
            return ptp_fail(err, PTP_EINTERNAL, "bad value of plane %d of case %ld", p, index);
        pos += rat_sgn(&st->val[p]) > 0;
        neg += rat_sgn(&st->val[p]) < 0;
    }
    cls[0] = classify(pos, neg, t->dom.nplanes, OUT_STRICT);
    cls[1] = classify(pos, neg, t->dom.nplanes, OUT_DEGENERATE);
    return PTP_OK;
}

/* Appends the current case as JSON. */
static void put_case(sbuf *o, const vstate *st, const int cls[2])
{
    const tp_table *t = st->t;
    const vcase *v = &st->v;
    char buf[RAT_STRLEN];
    int p, k;
    sbuf_printf(o, "    {\"eye\": [%" PRId64 ", %" PRId64 ", %" PRId64 ", %" PRId64 "],\n",
                v->eye[0], v->eye[1], v->eye[2], v->eye[3]);
    sbuf_puts(o, "     \"points\": [");
    for (k = 0; k < t->dom.npoints; k++)
        sbuf_printf(o, "%s[%" PRId64 ", %" PRId64 ", %" PRId64 ", %" PRId64 "]", k ? ", " : "",
                    v->b[k][0], v->b[k][1], v->b[k][2], v->b[k][3]);
    sbuf_puts(o, "],\n     \"values\": [");
    for (p = 0; p < t->dom.nplanes; p++)
        sbuf_printf(o, "%s\"%s\"", p ? ", " : "", rat_get_str(buf, &st->val[p]));
    sbuf_puts(o, "],\n     \"values_double\": [");
    for (p = 0; p < t->dom.nplanes; p++)
        sbuf_printf(o, "%s%.17g", p ? ", " : "", nearest_double(&st->val[p]));
    sbuf_printf(o, "],\n     \"class_strict\": %d, \"class_degenerate\": %d, \"kind\": \"%s\"}",
                cls[0], cls[1], kind_names[v->kind]);
}

/* Appends the whole JSON document; out is restored by the caller on failure. */
static int put_document(sbuf *out, vstate *st, long count, uint64_t seed, out_space space,
                        const char *command, ptp_error *err)
{
    const tp_table *t = st->t;
    tp_domain_text x;
    uint64_t s = seed;
    long c;
    int status, cls[2];
    sbuf_printf(out, "{\n  \"format\": \"ptpgen-vectors/1\",\n  \"generator\": \"ptpgen %s\",\n",
                PTP_VERSION);
    sbuf_puts(out, "  \"command\": ");
    put_string(out, command);
    tp_domain_text_get(&x, &t->dom);
    if (t->dom.kind == TP_QUAD)
        sbuf_printf(out, ",\n  \"degree\": [%s],\n", x.degrees);
    else
        sbuf_printf(out, ",\n  \"domain\": \"%s\",\n  \"degree\": %s,\n",
                    tp_kind_name(t->dom.kind), x.degrees);
    sbuf_printf(out, "  \"space\": \"%s\",\n", space == OUT_CLIP ? "clip" : "world");
    sbuf_printf(out, "  \"seed\": %" PRIu64 ",\n  \"points\": %d,\n  \"planes\": %d,\n", seed,
                t->dom.npoints, t->dom.nplanes);
    sbuf_printf(out, "  \"conventions\": \"%s; %s\",\n  \"cases\": [", x.conventions, conventions);
    for (c = 0; c < count; c++) {
        if ((status = compute_case(st, cls, c, space, &s, err)))
            return status;
        sbuf_puts(out, c ? ",\n" : "\n");
        put_case(out, st, cls);
    }
    sbuf_puts(out, count ? "\n  ]\n}\n" : "]\n}\n");
    return out->failed ? ptp_fail(err, PTP_ENOMEM, "out of memory writing test vectors") : PTP_OK;
}

/* The arrays of the C include, in order. */
enum { C_POINTS, C_EYE, C_VALUES, C_STRICT, C_DEGENERATE, C_NARRAYS };

/* Appends s to a C comment at column *col: control characters as blanks, no comment end, a
 * new comment line at a blank past column 90. */
static void put_comment(sbuf *o, int *col, const char *s)
{
    for (; *s; s++, ++*col) {
        if (*s == ' ' && *col > 90) {
            sbuf_puts(o, "\n *");
            *col = 2;
        }
        sbuf_printf(o, "%c%s", (unsigned char)*s < 0x20 ? ' ' : *s, s[0] == '*' && s[1] == '/'
                                                                        ? " " : "");
    }
}

/* Appends the head of the C include: its comment, guard and macros. */
static void put_c_head(sbuf *out, const tp_table *t, long count, uint64_t seed, out_space space,
                       const char *command)
{
    tp_domain_text x;
    int col = 0; /* the command goes on one line, however long */
    tp_domain_text_get(&x, &t->dom);
    sbuf_printf(out, "/* ptpgen test vectors (ptpgen-vectors/1 as a C include), %s.\n"
                     " * Generated by ptpgen %s: ", x.name, PTP_VERSION);
    put_comment(out, &col, command);
    sbuf_printf(out, "\n * Generated file, do not edit. Seed %" PRIu64 ", %s space.\n *\n"
                     " * Case c: control points ptp_vectors_points[c][k] (x, y, z, w), eye\n"
                     " * ptp_vectors_eye[c], the exact values d_P as the nearest doubles\n"
                     " * ptp_vectors_values[c][P], and the classes ptp_vectors_class_strict[c] and\n"
                     " * ptp_vectors_class_degenerate[c]. Every coordinate is a small integer, exact\n"
                     " * in float. Conventions: ", seed, space == OUT_CLIP ? "clip" : "world");
    col = 25;
    put_comment(out, &col, x.conventions);
    put_comment(out, &col, "; ");
    put_comment(out, &col, conventions);
    sbuf_printf(out, ".\n */\n#ifndef PTP_VECTORS_H\n#define PTP_VECTORS_H\n\n"
                     "#define PTP_VECTORS_COUNT %ld /* cases */\n"
                     "#define PTP_VECTORS_K %d     /* control points per case */\n"
                     "#define PTP_VECTORS_L %d     /* plane values per case */\n"
                     "#define PTP_VECTORS_CLIP %d  /* 1: clip space, 0: world space */\n",
                count, t->dom.npoints, t->dom.nplanes, space == OUT_CLIP);
}

/* Appends the element of array `which` of the current case. */
static void put_c_element(sbuf *o, const vstate *st, const int cls[2], int which)
{
    const tp_table *t = st->t;
    const vcase *v = &st->v;
    int k;
    if (which == C_POINTS) {
        sbuf_puts(o, "    {");
        for (k = 0; k < t->dom.npoints; k++)
            sbuf_printf(o, "%s{%" PRId64 ", %" PRId64 ", %" PRId64 ", %" PRId64 "}",
                        k ? ", " : "", v->b[k][0], v->b[k][1], v->b[k][2], v->b[k][3]);
        sbuf_puts(o, "},\n");
    } else if (which == C_EYE) {
        sbuf_printf(o, "    {%" PRId64 ", %" PRId64 ", %" PRId64 ", %" PRId64 "},\n",
                    v->eye[0], v->eye[1], v->eye[2], v->eye[3]);
    } else if (which == C_VALUES) {
        sbuf_puts(o, "    {");
        for (k = 0; k < t->dom.nplanes; k++)
            sbuf_printf(o, "%s%.17g", k ? ", " : "", nearest_double(&st->val[k]));
        sbuf_puts(o, "},\n");
    } else {
        sbuf_printf(o, "    %d, /* %s */\n", cls[which - C_STRICT], kind_names[v->kind]);
    }
}

/* Appends the C include: each array draws the cases again from the seed. */
static int put_c(sbuf *out, vstate *st, long count, uint64_t seed, out_space space,
                 const char *command, ptp_error *err)
{
    static const char *const decl[C_NARRAYS] = {
        "float ptp_vectors_points[PTP_VECTORS_COUNT][PTP_VECTORS_K][4]",
        "float ptp_vectors_eye[PTP_VECTORS_COUNT][4]",
        "double ptp_vectors_values[PTP_VECTORS_COUNT][PTP_VECTORS_L]",
        "unsigned char ptp_vectors_class_strict[PTP_VECTORS_COUNT]",
        "unsigned char ptp_vectors_class_degenerate[PTP_VECTORS_COUNT]"};
    int which, status, cls[2];
    long c;
    if (count < 1)
        return ptp_fail(err, PTP_EUSAGE, "a C include of test vectors needs at least one case");
    put_c_head(out, st->t, count, seed, space, command);
    for (which = 0; which < C_NARRAYS; which++) {
        uint64_t s = seed;
        sbuf_printf(out, "\nstatic const %s = {\n", decl[which]);
        for (c = 0; c < count; c++) {
            if ((status = compute_case(st, cls, c, space, &s, err)))
                return status;
            put_c_element(out, st, cls, which);
        }
        sbuf_puts(out, "};\n");
    }
    sbuf_puts(out, "\n#endif\n");
    return out->failed ? ptp_fail(err, PTP_ENOMEM, "out of memory writing test vectors") : PTP_OK;
}

int vectors_write(sbuf *out, const tp_table *t, long count, uint64_t seed, out_space space,
                  int format, const char *command, ptp_error *err)
{
    const size_t len = out->len;
    const int failed = out->failed;
    vstate st;
    int status;
    if (count < 0)
        return ptp_fail(err, PTP_EUSAGE, "the count of test vectors must not be negative");
    if (count > VECTORS_MAX_COUNT)
        return ptp_fail(err, PTP_ELIMIT, "at most %ld test vectors (asked for %ld)",
                        VECTORS_MAX_COUNT, count);
    st.t = t;
    st.iw = malloc(t->nterms * sizeof *st.iw);
    st.den = malloc((size_t)t->dom.nplanes * sizeof *st.den);
    st.num = malloc((size_t)t->dom.nplanes * sizeof *st.num);
    st.val = malloc((size_t)t->dom.nplanes * sizeof *st.val);
    st.v.X = malloc((size_t)t->dom.npoints * sizeof *st.v.X);
    st.v.b = malloc((size_t)t->dom.npoints * sizeof *st.v.b);
    if (!st.iw || !st.den || !st.num || !st.val || !st.v.X || !st.v.b)
        status = ptp_fail(err, PTP_ENOMEM, "out of memory writing test vectors");
    else if (!(status = common_denominators(&st, err)))
        status = format == VECTORS_C ? put_c(out, &st, count, seed, space, command, err)
                                     : put_document(out, &st, count, seed, space, command, err);
    free(st.iw);
    free(st.den);
    free(st.num);
    free(st.val);
    free(st.v.X);
    free(st.v.b);
    if (status && out->s) {
        out->len = len;
        out->s[len] = '\0';
        out->failed = failed;
    }
    return status;
}
