/* test_vectors.c: checks the ptpgen-vectors/1 test vectors written by gen/vectors.c.
 * Determinism, values against a double evaluation, exact rounding, classes, edge cases, limits. */
#include "check.h"
#include "core/i128.h"
#include "tools/vectors.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* One case read back from a document. */
typedef struct {
    int64_t eye[4];
    int64_t (*b)[4];
    rat *val;
    double *dbl;
    int cls[2]; /* strict, degenerate */
    char kind[32];
} pcase;

/* Moves *p just past the next occurrence of key; returns 0 when there is none. */
static int seek(const char **p, const char *key)
{
    const char *q = strstr(*p, key);
    if (!q)
        return 0;
    *p = q + strlen(key);
    return 1;
}

/* The next integer at or after *p (skipping separators), moving *p past it. */
static int64_t next_int(const char **p)
{
    int64_t x = 0;
    int neg;
    *p += strcspn(*p, "-0123456789");
    neg = **p == '-';
    for (*p += neg; **p >= '0' && **p <= '9'; ++*p)
        x = 10 * x + (**p - '0');
    return neg ? -x : x;
}

/* The next number at or after *p as a double, moving *p past it. */
static double next_double(const char **p)
{
    char buf[64];
    size_t n;
    *p += strcspn(*p, "-0123456789");
    n = strspn(*p, "-+.0123456789eE");
    if (n >= sizeof buf)
        return NAN;
    memcpy(buf, *p, n);
    buf[n] = '\0';
    *p += n;
    return strtod(buf, NULL);
}

/* Reads the case that follows *p into c (storage for t's sizes); returns 0 when there is none
 * or it is malformed. */
static int parse_case(pcase *c, const char **p, const tp_table *t)
{
    char buf[RAT_STRLEN];
    int k, x;
    if (!seek(p, "{\"eye\": ["))
        return 0;
    for (x = 0; x < 4; x++)
        c->eye[x] = next_int(p);
    if (!seek(p, "\"points\": ["))
        return 0;
    for (k = 0; k < t->dom.npoints; k++)
        for (x = 0; x < 4; x++)
            c->b[k][x] = next_int(p);
    if (!seek(p, "\"values\": ["))
        return 0;
    for (k = 0; k < t->dom.nplanes; k++) {
        size_t n;
        if (!seek(p, "\"") || (n = strcspn(*p, "\"")) >= sizeof buf)
            return 0;
        memcpy(buf, *p, n);
        buf[n] = '\0';
        *p += n + 1;
        if (rat_set_str(&c->val[k], buf))
            return 0;
    }
    if (!seek(p, "\"values_double\": ["))
        return 0;
    for (k = 0; k < t->dom.nplanes; k++)
        c->dbl[k] = next_double(p);
    if (!seek(p, "\"class_strict\": "))
        return 0;
    c->cls[0] = (int)next_int(p);
    if (!seek(p, "\"class_degenerate\": "))
        return 0;
    c->cls[1] = (int)next_int(p);
    if (!seek(p, "\"kind\": \"") || strcspn(*p, "\"") >= sizeof c->kind)
        return 0;
    memcpy(c->kind, *p, strcspn(*p, "\""));
    c->kind[strcspn(*p, "\"")] = '\0';
    return 1;
}

/* Nonzero when d is the double nearest to a (ties to even), decided exactly: with
 * |d| = M 2^E, M in [2^52, 2^53), |a| must lie between the midpoints to d's neighbours. */
static int is_nearest(double d, const rat *a)
{
    int e, s;
    int64_t M;
    ptp_i128 p = a->num < 0 ? -a->num : a->num, L = p, lo, hi, two;
    if (a->num == 0 || d == 0)
        return a->num == 0 && d == 0 && !signbit(d);
    if ((d < 0) != (a->num < 0))
        return 0;
    M = (int64_t)ldexp(frexp(fabs(d), &e), 53);
    s = e - 55; /* the unit 2^s is a quarter ulp: d = 4M units */
    if (s < -120 || s > 120)
        return 0;
    two = (ptp_i128)1 << (s < 0 ? -s : s);
    if ((s < 0 && i128_mul_ovf(&L, p, two)) ||
        i128_mul_ovf(&lo, 4 * M - (M == (int64_t)1 << 52 ? 1 : 2), a->den) ||
        i128_mul_ovf(&hi, 4 * M + 2, a->den) ||
        (s > 0 && (i128_mul_ovf(&lo, lo, two) || i128_mul_ovf(&hi, hi, two))))
        return 0;
    return M % 2 == 0 ? lo <= L && L <= hi : lo < L && L < hi;
}

/* The class from exact values under a rule (0 strict, 1 degenerate), written independently. */
static int expected_class(const rat *v, int n, int rule)
{
    int i, pos = 0, neg = 0;
    for (i = 0; i < n; i++) {
        pos += v[i].num > 0;
        neg += v[i].num < 0;
    }
    if (rule == 0)
        return neg == n ? 1 : pos == n ? 0 : 2;
    return pos == 0 ? 1 : neg == 0 ? 0 : 2;
}

/* Plane p of case c evaluated in double from table t: *d the value, *mag the sum of the
 * magnitudes of its terms. */
static void eval_plane(double *d, double *mag, const tp_table *t, const pcase *c, int p,
                       out_space space)
{
    size_t x;
    *d = *mag = 0;
    for (x = 0; x < t->nterms; x++) {
        const tp_term *w = &t->terms[x];
        double a[4], b[4], cc[4], r[4], y;
        int i;
        if (w->plane != p)
            continue;
        for (i = 0; i < 4; i++) {
            a[i] = (double)c->b[w->j][i];
            b[i] = (double)c->b[w->k][i];
            cc[i] = (double)c->b[w->l][i];
        }
        tp_cross4(r, a, b, cc);
        y = space == OUT_CLIP ? (double)c->eye[2] * r[2]
                              : (double)c->eye[0] * r[0] + (double)c->eye[1] * r[1] +
                                    (double)c->eye[2] * r[2] + (double)c->eye[3] * r[3];
        y *= rat_get_d(&w->w);
        *d += y;
        *mag += fabs(y);
    }
}

static const char *const kinds[] = {"near-planar", "flat", "collapsed-edge", "edge-on",
                                    "corner-tangent"};

/* Tallies over the cases of one document. */
typedef struct {
    long cases, zeros, differ, cls[2][3], kind[5];
} tally;

static int kind_index(const char *k)
{
    int i;
    for (i = 0; i < 5; i++)
        if (!strcmp(k, kinds[i]))
            return i;
    return -1;
}

/* Checks every case of doc against the table ref (the one it was made from, or not): returns
 * the number of cases that disagree with the double evaluation; the other properties go to
 * the props (NULL: not recorded) and the tally. */
static long verify(tally *ty, prop *bounds, prop *exact, prop *round, prop *cls, prop *kind,
                   const char *doc, const tp_table *ref, out_space space)
{
    pcase c;
    char buf[RAT_STRLEN];
    const char *p = doc;
    long bad_eval = 0;
    c.b = malloc((size_t)ref->dom.npoints * sizeof *c.b);
    c.val = malloc((size_t)ref->dom.nplanes * sizeof *c.val);
    c.dbl = malloc((size_t)ref->dom.nplanes * sizeof *c.dbl);
    memset(ty, 0, sizeof *ty);
    while (c.b && c.val && c.dbl && parse_case(&c, &p, ref)) {
        int k, x, ok = 1, zeros = 0, ki = kind_index(c.kind);
        const int P[4] = {0, ref->dom.pv, ref->dom.pu * (ref->dom.pv + 1), ref->dom.nplanes - 1};
        ty->cases++;
        for (k = 0; k < ref->dom.npoints; k++) {
            const int64_t *b = c.b[k];
            ok &= llabs(b[0]) <= VECTORS_XYZ_MAX && llabs(b[1]) <= VECTORS_XYZ_MAX;
            ok &= b[3] >= 1 && b[3] <= VECTORS_W_MAX;
            ok &= space == OUT_CLIP ? llabs(b[2]) < b[3] : llabs(b[2]) <= VECTORS_XYZ_MAX;
        }
        if (space == OUT_CLIP)
            ok &= !c.eye[0] && !c.eye[1] && llabs(c.eye[2]) == 1 && !c.eye[3];
        else
            for (x = 0; x < 4; x++)
                ok &= x == 3 ? c.eye[3] == 1 : llabs(c.eye[x]) <= VECTORS_EYE_MAX;
        bounds->tried++;
        if (!ok)
            prop_fail(bounds, "case %ld: a point or the eye out of bounds", ty->cases - 1);
        for (k = 0, ok = 1; k < ref->dom.nplanes; k++) {
            double d, mag, want = rat_get_d(&c.val[k]);
            eval_plane(&d, &mag, ref, &c, k, space);
            if (fabs(d - want) > 1e-9 * mag || (mag == 0 && want != 0)) {
                if (ok && exact)
                    prop_fail(exact, "case %ld plane %d: exact %.17g, double evaluation %.17g",
                              ty->cases - 1, k, want, d);
                ok = 0;
            }
            if (!is_nearest(c.dbl[k], &c.val[k]))
                prop_fail(round, "case %ld plane %d: %.17g is not the double nearest to %s",
                          ty->cases - 1, k, c.dbl[k], rat_get_str(buf, &c.val[k]));
            zeros += c.val[k].num == 0;
        }
        bad_eval += !ok;
        if (exact)
            exact->tried++;
        round->tried++;
        for (x = 0; x < 2; x++) {
            int want = expected_class(c.val, ref->dom.nplanes, x);
            cls->tried++;
            if (c.cls[x] != want)
                prop_fail(cls, "case %ld: %s class %d, the signs say %d", ty->cases - 1,
                          x ? "degenerate" : "strict", c.cls[x], want);
            ty->cls[x][want]++;
        }
        /* What each kind promises: edge-on all zero, collapsed-edge and corner-tangent some. */
        kind->tried++;
        if (ki < 0 || (ki == 3 && zeros != ref->dom.nplanes) || (ki == 2 && zeros == 0) ||
            (ki == 4 && c.val[P[0]].num && c.val[P[1]].num && c.val[P[2]].num && c.val[P[3]].num))
            prop_fail(kind, "case %ld: kind %s with %d zero values", ty->cases - 1, c.kind, zeros);
        else
            ty->kind[ki]++;
        ty->zeros += zeros;
        ty->differ += c.cls[0] != c.cls[1];
    }
    free(c.b);
    free(c.val);
    free(c.dbl);
    return bad_eval;
}

/* FNV-1a of the cases of `ptpgen vectors --degree 3x3 --count 10 --seed 7 --space clip`. */
#define PINNED 0x7EB357A7E2CCEC8Au

/* FNV-1a of s. */
static uint64_t fnv(const char *s)
{
    uint64_t h = 0xCBF29CE484222325u;
    for (; *s; s++)
        h = (h ^ (unsigned char)*s) * 0x100000001B3u;
    return h;
}

/* The vectors of t as a string (caller frees), or NULL with the status in *status. */
static char *vectors(const tp_table *t, long count, uint64_t seed, out_space space, int *status)
{
    sbuf b;
    ptp_error err;
    sbuf_init(&b);
    if ((*status = vectors_write(&b, t, count, seed, space, VECTORS_JSON, "ptpgen vectors test", &err))) {
        sbuf_clear(&b);
        return NULL;
    }
    return b.s;
}

/* The checks of one bidegree and space on 200 cases. */
static void check_degree(int n, int m, out_space space)
{
    const char *sp = space == OUT_CLIP ? "clip" : "world";
    tp_table t;
    ptp_error err;
    prop bounds, exact, round, cls, kind;
    tally ty;
    char *doc, head[200], name[100];
    int st, i;
    const unsigned seed = 1000u * (unsigned)n + 10u * (unsigned)m + (unsigned)space;
    snprintf(name, sizeof name, "vectors %dx%d %s: 200 cases written", n, m, sp);
    if (!check(!tp_derive(&t, n, m, &err), name, "%s", err.msg))
        return;
    doc = vectors(&t, 200, seed, space, &st);
    if (!check(doc != NULL, name, "status %d", st)) {
        tp_clear(&t);
        return;
    }
    snprintf(head, sizeof head,
             "\"degree\": [%d, %d],\n  \"space\": \"%s\",\n  \"seed\": %u,\n  \"points\": %d,\n"
             "  \"planes\": %d,\n",
             n, m, sp, seed, t.dom.npoints, t.dom.nplanes);
    snprintf(name, sizeof name, "vectors %dx%d %s: header", n, m, sp);
    check(!strncmp(doc, "{\n  \"format\": \"ptpgen-vectors/1\",\n", 34) && strstr(doc, head),
          name, "want %s", head);
    prop_init(&bounds, "vectors %dx%d %s: points and eye within the documented bounds", n, m, sp);
    prop_init(&exact, "vectors %dx%d %s: exact values agree with the double evaluation of the "
                      "table (1e-9 of the terms' magnitude)", n, m, sp);
    prop_init(&round, "vectors %dx%d %s: values_double are the exact values rounded to nearest",
              n, m, sp);
    prop_init(&cls, "vectors %dx%d %s: classes follow the signs under both rules", n, m, sp);
    prop_init(&kind, "vectors %dx%d %s: edge-on all zero, collapsed-edge and corner-tangent "
                     "with zeros", n, m, sp);
    verify(&ty, &bounds, &exact, &round, &cls, &kind, doc, &t, space);
    snprintf(name, sizeof name, "vectors %dx%d %s: 200 cases read back", n, m, sp);
    check(ty.cases == 200, name, "%ld cases", ty.cases);
    prop_report(&bounds);
    prop_report(&exact);
    prop_report(&round);
    prop_report(&cls);
    prop_report(&kind);
    snprintf(name, sizeof name, "vectors %dx%d %s: exact zeros, strict and degenerate differ",
             n, m, sp);
    check(ty.zeros > 0 && ty.differ > 0, name, "%ld zero values, %ld cases differ", ty.zeros,
          ty.differ);
    for (i = 0, st = 1; i < 3; i++)
        st &= ty.cls[0][i] >= 10 && ty.cls[1][i] >= 10;
    snprintf(name, sizeof name, "vectors %dx%d %s: every class at least 10 times under each rule",
             n, m, sp);
    check(st, name, "strict front/back/silhouette %ld/%ld/%ld, degenerate %ld/%ld/%ld",
          ty.cls[0][0], ty.cls[0][1], ty.cls[0][2], ty.cls[1][0], ty.cls[1][1], ty.cls[1][2]);
    for (i = 0, st = 1; i < 5; i++)
        st &= ty.kind[i] >= 10;
    snprintf(name, sizeof name, "vectors %dx%d %s: every kind at least 10 times", n, m, sp);
    check(st, name, "kinds %ld/%ld/%ld/%ld/%ld", ty.kind[0], ty.kind[1], ty.kind[2],
          ty.kind[3], ty.kind[4]);
    free(doc);
    tp_clear(&t);
}

/* Same seed, same bytes; other seeds differ; the first cases do not depend on the count; the
 * cases of one seed are pinned (the same on every compiler and platform). */
static void check_determinism(void)
{
    tp_table t;
    ptp_error err;
    int st;
    char *a, *b, *c, *d;
    const char *tail = "\n  ]\n}\n";
    if (!check(!tp_derive(&t, 3, 3, &err), "derive 3x3", "%s", err.msg))
        return;
    a = vectors(&t, 100, 7, OUT_CLIP, &st);
    b = vectors(&t, 100, 7, OUT_CLIP, &st);
    c = vectors(&t, 100, 8, OUT_CLIP, &st);
    d = vectors(&t, 10, 7, OUT_CLIP, &st);
    if (check(a && b && c && d, "vectors 3x3", "status %d", st)) {
        size_t n = strlen(d) - strlen(tail);
        check(!strcmp(a, b), "vectors: the same seed gives the same bytes", "");
        check(strcmp(strstr(a, "\"cases\""), strstr(c, "\"cases\"")) != 0,
              "vectors: another seed gives other cases", "");
        check(!strcmp(d + n, tail) && !strncmp(a, d, n) && a[n] == ',',
              "vectors: the first 10 cases do not depend on the count", "");
        check(fnv(strstr(d, "\"cases\"")) == PINNED, "vectors: the cases of seed 7 are pinned",
              "FNV-1a of the 10 cases is 0x%016llx",
              (unsigned long long)fnv(strstr(d, "\"cases\"")));
    }
    free(a);
    free(b);
    free(c);
    free(d);
    tp_clear(&t);
}

/* The overflow bound of vectors.h for every bidegree up to 6x6: 2^24 * D_P * sum |weight| <
 * 2^51; and every one of them writes its vectors. */
static void check_limits(void)
{
    prop bound, runs;
    int n, m;
    prop_init(&bound, "vectors: 2^24 * common denominator * sum |weight| < 2^51 for every plane "
                      "up to 6x6");
    prop_init(&runs, "vectors: every bidegree up to 6x6 writes 20 cases in both spaces");
    for (n = 1; n <= 6; n++)
        for (m = 1; m <= 6; m++) {
            tp_table t;
            ptp_error err;
            int p, sp, st;
            if (tp_derive(&t, n, m, &err)) {
                prop_fail(&bound, "%dx%d: %s", n, m, err.msg);
                continue;
            }
            for (p = 0; p < t.dom.nplanes; p++) {
                ptp_i128 D = 1;
                double sum = 0;
                size_t x;
                for (x = 0; x < t.nterms; x++)
                    if (t.terms[x].plane == p) {
                        if (rat_lcm_den(&D, &t.terms[x].w))
                            prop_fail(&bound, "%dx%d plane %d: lcm overflow", n, m, p);
                        sum += fabs(rat_get_d(&t.terms[x].w));
                    }
                bound.tried++;
                if (ldexp(sum * (double)D, 24) >= ldexp(1, 51))
                    prop_fail(&bound, "%dx%d plane %d: %g", n, m, p,
                              ldexp(sum * (double)D, 24));
            }
            for (sp = 0; sp < 2; sp++) {
                char *doc = vectors(&t, 20, (uint64_t)(n * 7 + m), sp ? OUT_WORLD : OUT_CLIP, &st);
                const char *q = doc;
                long cases = 0;
                while (doc && seek(&q, "{\"eye\""))
                    cases++;
                runs.tried++;
                if (cases != 20)
                    prop_fail(&runs, "%dx%d %s: status %d, %ld cases", n, m,
                              sp ? "world" : "clip", st, cases);
                free(doc);
            }
            tp_clear(&t);
        }
    prop_report(&bound);
    prop_report(&runs);
}

/* A table with one weight changed by 0.1% must fail the double-evaluation check, so that the
 * check has teeth. */
static void check_mutation(void)
{
    tp_table t, bad;
    ptp_error err;
    prop bounds, round, cls, kind;
    tally ty;
    rat r;
    char *doc;
    int st;
    if (!check(!tp_derive(&t, 3, 3, &err) && !tp_derive(&bad, 3, 3, &err), "derive 3x3", "%s",
               err.msg))
        return;
    rat_set_frac(&r, 1001, 1000);
    rat_mul(&bad.terms[0].w, &bad.terms[0].w, &r);
    doc = vectors(&bad, 50, 3, OUT_WORLD, &st);
    prop_init(&bounds, "mutation: bounds");
    prop_init(&round, "mutation: rounding");
    prop_init(&cls, "mutation: classes");
    prop_init(&kind, "mutation: kinds");
    check(doc && verify(&ty, &bounds, NULL, &round, &cls, &kind, doc, &t, OUT_WORLD) > 0 &&
              verify(&ty, &bounds, NULL, &round, &cls, &kind, doc, &bad, OUT_WORLD) == 0,
          "vectors: a table with one weight off by 0.1% fails the double evaluation", "");
    free(doc);
    tp_clear(&t);
    tp_clear(&bad);
}

/* is_nearest itself: right on exact doubles, halfway cases and thirds, wrong one ulp off. */
static void check_rounding(void)
{
    static const long long nd[][2] = {{1, 3}, {-2, 3}, {10, 1}, {-7, 1024}, {1, 10}};
    rat r;
    int i, ok = 1;
    for (i = 0; i < 5; i++) {
        double d = (double)nd[i][0] / (double)nd[i][1]; /* correctly rounded: both exact */
        rat_set_frac(&r, nd[i][0], nd[i][1]);
        ok &= is_nearest(d, &r) && !is_nearest(nextafter(d, 1e300), &r) &&
              !is_nearest(nextafter(d, -1e300), &r);
    }
    rat_set_frac(&r, ((ptp_i128)1 << 53) + 1, 1); /* halfway: to the even 2^53 */
    ok &= is_nearest(9007199254740992.0, &r) && !is_nearest(9007199254740994.0, &r);
    rat_set_frac(&r, ((ptp_i128)1 << 53) + 3, 1); /* halfway: to the even 2^53 + 4 */
    ok &= is_nearest(9007199254740996.0, &r) && !is_nearest(9007199254740994.0, &r);
    rat_set_frac(&r, ((ptp_i128)1 << 54) - 1, 2); /* 2^53 - 1/2: halfway below a power of 2 */
    ok &= is_nearest(9007199254740992.0, &r) && !is_nearest(9007199254740991.0, &r);
    check(ok, "vectors: the rounding check accepts nearest doubles and rejects neighbours", "");
}

/* Bad counts, the empty document and the escaping of the command. */
static void check_errors(void)
{
    tp_table t;
    ptp_error err;
    sbuf b;
    int st;
    if (!check(!tp_derive(&t, 2, 2, &err), "derive 2x2", "%s", err.msg))
        return;
    sbuf_init(&b);
    sbuf_puts(&b, "keep");
    err.msg[0] = '\0';
    st = vectors_write(&b, &t, -1, 1, OUT_CLIP, VECTORS_JSON, "x", &err);
    check(st == PTP_EUSAGE && err.status == PTP_EUSAGE && err.msg[0] && !strcmp(b.s, "keep"),
          "vectors: a negative count is a usage error and writes nothing", "status %d, '%s'", st,
          err.msg);
    err.msg[0] = '\0';
    st = vectors_write(&b, &t, VECTORS_MAX_COUNT + 1, 1, OUT_WORLD, VECTORS_JSON, "x", &err);
    check(st == PTP_ELIMIT && err.msg[0] && !strcmp(b.s, "keep"),
          "vectors: a count beyond VECTORS_MAX_COUNT is refused and writes nothing",
          "status %d, '%s'", st, err.msg);
    st = vectors_write(&b, &t, 0, 1, OUT_WORLD, VECTORS_JSON, "say \"hi\"\\\n", &err);
    check(!st && strstr(b.s, "\"command\": \"say \\\"hi\\\"\\\\\\u000a\",") &&
              strstr(b.s, "\"cases\": []\n}\n") && !strncmp(b.s, "keep{\n", 6),
          "vectors: count 0 appends an empty document, the command escaped", "%s",
          b.s ? b.s : "");
    sbuf_clear(&b);
    tp_clear(&t);
}

/* The stream every case is drawn from is splitmix64: its published first outputs from seed 0. */
static void check_stream(void)
{
    uint64_t s = 0, a = ptp_splitmix64(&s), b = ptp_splitmix64(&s);
    check(a == 0xE220A8397B1DCDAFu && b == 0x6E789E6AA1B965F4u,
          "vectors: ptp_splitmix64 gives splitmix64's known outputs from seed 0", "%016llx %016llx",
          (unsigned long long)a, (unsigned long long)b);
}

int main(void)
{
    static const int degrees[][2] = {{1, 1}, {2, 2}, {3, 3}, {2, 3}};
    int i;
    for (i = 0; i < 4; i++) {
        check_degree(degrees[i][0], degrees[i][1], OUT_CLIP);
        check_degree(degrees[i][0], degrees[i][1], OUT_WORLD);
    }
    check_determinism();
    check_mutation();
    check_rounding();
    check_limits();
    check_errors();
    check_stream();
    return check_exit();
}
