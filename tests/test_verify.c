/* test_verify.c: checks `ptpgen verify` (verify_table) on generated tables and on wrong ones.
 * Every constructed mistake must get its diagnosis, and malformed input a usage error with a line. */
#include "check.h"
#include "emit/out.h"
#include "tools/verify.h"

#include <stdlib.h>
#include <string.h>
#include <time.h>

/* The longest weight text: "p.0f / q.0f". */
#define WLEN (2 * RAT_STRLEN + 16)

/* One term as a test writes it: the points in the order given, the weight as text. */
typedef struct {
    int plane, p[3];
    char w[WLEN];
} row;

typedef struct {
    row *r;
    size_t n;
} rows;

static uint64_t rng = 0x2545F4914F6CDD1Du;

/* A pseudo-random number below n (xorshift64*; fixed seed, reproducible). */
static size_t below(size_t n)
{
    rng ^= rng >> 12;
    rng ^= rng << 25;
    rng ^= rng >> 27;
    return (size_t)((rng * 2685821657736338717u) >> 33) % n;
}

/* The result of one verify_table call. */
typedef struct {
    int st, verdict;
    char *report; /* the report ("" on failure) */
    ptp_error err;
} result;

/* verify_table on text as a table of the kind (VERIFY_KIND_ANY: the document's). */
static result run_verify_kind(const char *text, size_t len, const char *name, int kind, int n,
                              int m, int convention)
{
    result r;
    sbuf o;
    sbuf_init(&o);
    r.err.msg[0] = '\0';
    r.verdict = -1;
    r.st = verify_table(&o, &r.verdict, text, len, name, kind, n, m, convention, &r.err);
    r.report = malloc(o.len + 1);
    if (r.report) {
        memcpy(r.report, o.s ? o.s : "", o.len);
        r.report[o.len] = '\0';
    }
    sbuf_clear(&o);
    return r;
}

static result run_verify_conv(const char *text, size_t len, const char *name, int n, int m,
                              int convention)
{
    return run_verify_kind(text, len, name, VERIFY_KIND_ANY, n, m, convention);
}

static result run_verify(const char *text, size_t len, const char *name, int n, int m)
{
    return run_verify_conv(text, len, name, n, m, VERIFY_U_FIRST);
}

static result verify_str(const sbuf *b, const char *name, int n, int m)
{
    return run_verify_conv(b->s ? b->s : "", b->len, name, n, m, VERIFY_U_FIRST);
}

/* The last line of a report (its verdict), for failure details. */
static const char *last_line(const char *s)
{
    const char *p = s && *s ? s + strlen(s) - 1 : "";
    while (p > s && p[-1] != '\n')
        p--;
    return p;
}

/* Renders t with out_table (target table) or out_json into b. */
static int render(sbuf *b, const tp_table *t, int table)
{
    char prefix[32], command[80], deg[16];
    sched s;
    out_info info = {0};
    ptp_error err;
    int P = sched_default_threads(t), st;
    if (sched_build(&s, t, P, sched_default_patches(P), &err))
        return 0;
    tp_domain_prefix(prefix, sizeof prefix, &t->dom);
    snprintf(command, sizeof command, "ptpgen%s --degree %s --target %s",
             t->dom.kind == TP_TRI ? " --domain triangle" : "",
             tp_domain_format(deg, sizeof deg, &t->dom), table ? "table" : "json");
    info.command = command;
    info.prefix = prefix;
    info.sched = &s;
    info.space = OUT_CLIP;
    info.rule = OUT_STRICT;
    info.planes = 0;
    sbuf_init(b);
    st = table ? out_table(b, t, &info, &err) : out_json(b, t, &info, &err);
    sched_clear(&s);
    return !st && !b->failed;
}

/* The weight w as text: "p/q", "-27.0f/7.0f" (cfrac), or the float "%.9gf" times mul. */
enum { W_FRAC, W_CFRAC, W_FLOAT };

static void weight_text(char *buf, const rat *w, int style, double mul)
{
    char num[RAT_STRLEN], den[RAT_STRLEN];
    rat n;
    if (style == W_FLOAT) {
        snprintf(buf, WLEN, "%.9gf", (double)(float)(rat_get_d(w) * mul));
        if (!strpbrk(buf, ".e"))
            snprintf(buf, WLEN, "%.1ff", (double)(float)(rat_get_d(w) * mul));
        return;
    }
    if (style == W_FRAC) {
        rat_get_str(buf, w);
        return;
    }
    n.num = w->num;
    n.den = 1;
    rat_get_str(num, &n);
    n.num = w->den;
    rat_get_str(den, &n);
    snprintf(buf, WLEN, "%s.0f / %s.0f", num, den);
}

/* The rows of t, weights in style (times mul for floats). */
static rows rows_of(const tp_table *t, int style, double mul)
{
    rows r;
    size_t x;
    r.n = t->nterms;
    r.r = malloc((t->nterms + 8) * sizeof *r.r);
    for (x = 0; r.r && x < t->nterms; x++) {
        const tp_term *e = &t->terms[x];
        r.r[x].plane = e->plane;
        r.r[x].p[0] = e->j;
        r.r[x].p[1] = e->k;
        r.r[x].p[2] = e->l;
        weight_text(r.r[x].w, &e->w, style, mul);
    }
    return r;
}

/* JSON with one term per line: term x is on line JSON_LINE0 + x. */
#define JSON_LINE0 5

/* JSON naming the degrees (n, m) of the kind (none when n is 0), with the terms r. */
static void write_json_kind(sbuf *b, const rows *r, tp_kind kind, int n, int m)
{
    size_t x;
    sbuf_init(b);
    sbuf_puts(b, "{\n  \"format\": \"ptpgen-planes/1\",\n");
    if (n && kind == TP_TRI)
        sbuf_printf(b, "  \"domain\": \"triangle\", \"degree\": %d,\n", n);
    else if (n)
        sbuf_printf(b, "  \"degree\": [%d, %d],\n", n, m);
    else
        sbuf_puts(b, "  \"comment\": \"no degree\",\n");
    sbuf_puts(b, "  \"terms\": [\n");
    for (x = 0; x < r->n; x++)
        sbuf_printf(b, "    [%d, %d, %d, %d, \"%s\"]%s\n", r->r[x].plane, r->r[x].p[0],
                    r->r[x].p[1], r->r[x].p[2], r->r[x].w, x + 1 < r->n ? "," : "");
    sbuf_puts(b, "  ]\n}\n");
}

static void write_json(sbuf *b, const rows *r, int n, int m)
{
    write_json_kind(b, r, TP_QUAD, n, m);
}

/* verify (--degree n x m; 0 0: inferred; in the convention) on r written by write_json naming
 * bidegree jn x jm, as t.json. */
static result verify_json_conv(const rows *r, int jn, int jm, int n, int m, int convention)
{
    sbuf b;
    result res;
    write_json(&b, r, jn, jm);
    res = run_verify_conv(b.s ? b.s : "", b.len, "t.json", n, m, convention);
    sbuf_clear(&b);
    return res;
}

static result verify_json(const rows *r, int jn, int jm, int n, int m)
{
    return verify_json_conv(r, jn, jm, n, m, VERIFY_U_FIRST);
}

/* verify_json in the v-first convention. */
static result verify_json_vfirst(const rows *r, int jn, int jm, int n, int m)
{
    return verify_json_conv(r, jn, jm, n, m, VERIFY_V_FIRST);
}

/* The paper's layout, rows on lines PAPER_LINE0 + x, with comments and a directive. */
#define PAPER_LINE0 4

static void write_paper(sbuf *b, const rows *r)
{
    size_t x;
    sbuf_init(b);
    sbuf_puts(b, "/* the paper's table, as someone typed it */\n#include <stdint.h>\n"
                 "uint idx[4][] = {\n");
    for (x = 0; x < r->n; x++)
        sbuf_printf(b, "    {%d, %d, %d, %d},  // term %zu\n", r->r[x].plane, r->r[x].p[0],
                    r->r[x].p[1], r->r[x].p[2], x);
    sbuf_puts(b, "};\n#define UNUSED 1\nfloat wgt[] = {\n");
    for (x = 0; x < r->n; x++)
        sbuf_printf(b, "    %s%s /* %zu */\n", r->r[x].w, x + 1 < r->n ? "," : "", x);
    sbuf_puts(b, "};\n");
}

static void shuffle(rows *r)
{
    size_t x;
    for (x = r->n; x > 1; x--) {
        size_t y = below(x);
        row t = r->r[x - 1];
        r->r[x - 1] = r->r[y];
        r->r[y] = t;
    }
}

/* The exact table t relabelled (i, j) -> (j, i) (points and planes, numbered by the domain),
 * negated when negate is set. */
static rows relabelled(const tp_table *t, int negate)
{
    rows r = rows_of(t, W_FRAC, 1);
    tp_domain tr;
    size_t x;
    tp_domain_transpose(&tr, &t->dom);
    for (x = 0; r.r && x < r.n; x++) {
        row *e = &r.r[x];
        int q, a, b, sign = negate ? -1 : 1;
        rat w = t->terms[x].w;
        tp_domain_plane_ij(&a, &b, &t->dom, e->plane);
        e->plane = tp_domain_plane(&tr, b, a);
        for (q = 0; q < 3; q++) {
            tp_domain_point_ij(&a, &b, &t->dom, e->p[q]);
            e->p[q] = tp_domain_point(&tr, b, a);
        }
        for (a = 0; a < 3; a++)
            for (b = a + 1; b < 3; b++)
                if (e->p[b] < e->p[a]) {
                    int tmp = e->p[a];
                    e->p[a] = e->p[b];
                    e->p[b] = tmp;
                    sign = -sign;
                }
        if (sign < 0)
            rat_neg(&w, &w);
        rat_get_str(e->w, &w);
    }
    return r;
}

static int has(const result *r, const char *s)
{
    return r->report && strstr(r->report, s) != NULL;
}

/* Checks a RIGHT (or WRONG) verdict with a report containing want. */
static void expect_verdict(const char *name, result r, int verdict, const char *want)
{
    check(r.st == PTP_OK && r.verdict == verdict && has(&r, want), name,
          "status %d (%s), verdict %d, report ends \"%s\", wanted \"%s\"", r.st, r.err.msg,
          r.verdict, last_line(r.report), want);
    free(r.report);
}

/* Writes r in the paper's layout (p.h) or as a 3x3 JSON document (t.json), expects verify
 * without --degree to give verdict with want in its report, and frees r. */
static void expect_rows(const char *name, rows *r, int json, int verdict, const char *want)
{
    sbuf b;
    if (json)
        write_json(&b, r, 3, 3);
    else
        write_paper(&b, r);
    expect_verdict(name, verify_str(&b, json ? "t.json" : "p.h", 0, 0), verdict, want);
    sbuf_clear(&b);
    free(r->r);
}

/* Expects verify_json_conv of r (then freed) to give verdict with want in its report. */
static void expect_json(const char *name, rows r, int jn, int jm, int n, int m, int convention,
                        int verdict, const char *want)
{
    expect_verdict(name, verify_json_conv(&r, jn, jm, n, m, convention), verdict, want);
    free(r.r);
}

/* Checks a WRONG verdict whose report has a line starting "NAME:LINE: what". */
static void expect_line(const char *name, result r, const char *file, int line, const char *what)
{
    char want[256];
    if (line)
        snprintf(want, sizeof want, "%s:%d: %s", file, line, what);
    else
        snprintf(want, sizeof want, "%s: %s", file, what);
    check(r.st == PTP_OK && r.verdict == VERIFY_WRONG && has(&r, want), name,
          "status %d (%s), verdict %d, wanted \"%s\" in:\n%.2000s", r.st, r.err.msg, r.verdict,
          want, r.report ? r.report : "");
    free(r.report);
}

/* Checks a usage error whose message starts "FILE:LINE: " (any line when line is 0) and
 * mentions what; the report must stay empty. */
static void expect_usage(const char *name, result r, const char *file, int line, const char *what)
{
    size_t k = strlen(file);
    const char *p = r.err.msg + k + 1;
    int ok = !strncmp(r.err.msg, file, k) && r.err.msg[k] == ':' && *p >= '1' && *p <= '9';
    ok = ok && (!line || atoi(p) == line);
    while (*p >= '0' && *p <= '9')
        p++;
    check(r.st == PTP_EUSAGE && ok && *p == ':' && strstr(r.err.msg, what) && r.report &&
              !*r.report, name, "status %d, message \"%s\", wanted %s:%d: \"%s\"", r.st,
          r.err.msg, file, line, what);
    free(r.report);
}

static void test_generated(void)
{
    static const int degrees[][2] = {{1, 1}, {2, 2}, {3, 3}, {4, 4}, {1, 3}, {3, 1}, {2, 3}, {3, 2}};
    size_t d;
    for (d = 0; d < sizeof degrees / sizeof degrees[0]; d++) {
        int n = degrees[d][0], m = degrees[d][1], table;
        tp_table t;
        ptp_error err;
        if (!check(!tp_derive(&t, n, m, &err), "derive", "%s", err.msg))
            continue;
        for (table = 0; table < 2; table++) {
            char name[128];
            sbuf b;
            if (!check(render(&b, &t, table), "render", "%dx%d", n, m))
                continue;
            snprintf(name, sizeof name, "verify accepts ptpgen's own %dx%d %s (degree inferred)", n,
                     m, table ? "table" : "json");
            expect_verdict(name, verify_str(&b, "gen", 0, 0), VERIFY_RIGHT, "RIGHT: exact");
            snprintf(name, sizeof name, "verify accepts ptpgen's own %dx%d %s with --degree %dx%d", n,
                     m, table ? "table" : "json", n, m);
            expect_verdict(name, verify_str(&b, "gen", n, m), VERIFY_RIGHT, "RIGHT: exact");
            sbuf_clear(&b);
        }
        tp_clear(&t);
    }
}

/* test_bicubic_mistakes on t's rows r (exact fractions): one weight changed, two points
 * swapped in a row; r as it was after. */
static void mistakes_in_a_row(const tp_table *t, rows *r)
{
    row keep;
    char want[256], w[RAT_STRLEN];
    /* one weight changed */
    keep = r->r[10];
    strcpy(r->r[10].w, "-1/3");
    expect_line("one weight changed: wrong weight, with its line", verify_json(r, 3, 3, 0, 0),
                "t.json", JSON_LINE0 + 10, "wrong weight");
    snprintf(want, sizeof want, "got -1/3, expected %s", rat_get_str(w, &t->terms[10].w));
    expect_verdict("wrong weight: got vs expected", verify_json(r, 3, 3, 0, 0), VERIFY_WRONG,
                   want);
    r->r[10] = keep;

    /* two points swapped within a row */
    keep = r->r[1];
    r->r[1].p[1] = keep.p[2];
    r->r[1].p[2] = keep.p[1];
    expect_line("two indices swapped in a row: the order flips the sign",
                verify_json(r, 3, 3, 0, 0), "t.json", JSON_LINE0 + 1,
                "points not in increasing order flip the sign: {1, 0, 5, 1} is -27/7 * "
                "cross4(b0, b5, b1) = 27/7 * cross4(b0, b1, b5)");
    /* the same swap with the weight negated is right: a note, no problem */
    strcpy(r->r[1].w, "27/7");
    expect_verdict("swapped points with the weight negated: right, with a note",
                   verify_json(r, 3, 3, 0, 0), VERIFY_RIGHT, "note: points not in increasing");
    r->r[1] = keep;
}

/* test_bicubic_mistakes on rows r (exact fractions): a term dropped, duplicated, extra, or
 * moved to a wrong plane; r as it was after. */
static void mistakes_of_rows(rows *r)
{
    row keep;
    char want[256];
    /* a term dropped */
    keep = r->r[7];
    memmove(&r->r[7], &r->r[8], (r->n - 8) * sizeof *r->r);
    r->n--;
    snprintf(want, sizeof want, "missing term: plane %d: %s * cross4(b%d, b%d, b%d)", keep.plane,
             keep.w, keep.p[0], keep.p[1], keep.p[2]);
    expect_line("a term dropped: missing, with plane, points and exact weight",
                verify_json(r, 3, 3, 0, 0), "t.json", 0, want);
    memmove(&r->r[8], &r->r[7], (r->n - 7) * sizeof *r->r);
    r->r[7] = keep;
    r->n++;

    /* a term duplicated (the copy as the last term) */
    r->r[r->n] = r->r[20];
    r->n++;
    snprintf(want, sizeof want, "duplicated term: plane %d, cross4(b%d, b%d, b%d) repeats line %d",
             r->r[20].plane, r->r[20].p[0], r->r[20].p[1], r->r[20].p[2], JSON_LINE0 + 20);
    expect_line("a term duplicated: the line and the line it repeats",
                verify_json(r, 3, 3, 0, 0), "t.json", JSON_LINE0 + (int)r->n - 1, want);
    r->n--;

    /* an extra term */
    r->r[r->n] = r->r[0];
    r->r[r->n].p[2] = 15;
    r->n++;
    expect_line("an extra term", verify_json(r, 3, 3, 0, 0), "t.json",
                JSON_LINE0 + (int)r->n - 1, "extra term: {0, 0, 1, 15}");
    r->n--;

    /* a term moved to a plane without those points */
    keep = r->r[30];
    r->r[30].plane = 63;
    snprintf(want, sizeof want, "is in plane 63 but belongs to plane %d", keep.plane);
    expect_line("a term moved to a wrong plane", verify_json(r, 3, 3, 0, 0), "t.json",
                JSON_LINE0 + 30, "wrong plane");
    expect_verdict("wrong plane names both planes", verify_json(r, 3, 3, 0, 0), VERIFY_WRONG,
                   want);
    r->r[30] = keep;
}

/* test_bicubic_mistakes on t's tables scaled, negated and relabelled, into *r (whose rows
 * the first case scales). */
static void mistakes_of_scale(const tp_table *t, rows *r)
{
    size_t x;
    /* all weights times 1/7, exact */
    for (x = 0; x < r->n; x++) {
        rat s, v;
        rat_set_frac(&s, 1, 7);
        rat_mul(&v, &t->terms[x].w, &s);
        rat_get_str(r->r[x].w, &v);
    }
    expect_rows("all weights times 1/7: right up to the scale, named", r, 1, VERIFY_RIGHT,
                "RIGHT: correct up to a positive scale s = 0.142857143 = 1/7");

    /* all weights times 2.5, as floats, in ptpgen's table layout */
    *r = rows_of(t, W_FLOAT, 2.5);
    expect_rows("all float weights times 2.5: right up to the scale 5/2", r, 0, VERIFY_RIGHT,
                "positive scale s = 2.5 = 5/2");

    /* all negated */
    *r = rows_of(t, W_FLOAT, -1);
    expect_rows("all weights negated: wrong, the opposite orientation", r, 0, VERIFY_WRONG,
                "WRONG: all weights negated");

    /* negated and scaled */
    *r = rows_of(t, W_FLOAT, -3);
    expect_rows("all weights times -3: negated and scaled", r, 0, VERIFY_WRONG,
                "WRONG: all weights negated, and every weight scaled by 3");

    /* a square patch: u and v swapped gives the same table; v-first gives the negated one */
    *r = relabelled(t, 1);
    expect_rows("3x3 with u and v swapped is the same table (the transposition rule)", r, 1,
                VERIFY_RIGHT, "RIGHT: exact");
    *r = relabelled(t, 0);
    expect_rows("3x3 in the v-first convention: negated, and v-first named", r, 1, VERIFY_WRONG,
                "v-first index convention");
}

/* test_bicubic_mistakes on t in the paper's layout: shuffled, and with a wrong weight, into
 * *r. */
static void mistakes_in_paper_layout(const tp_table *t, rows *r)
{
    sbuf b;
    char want[256];
    /* the paper's own layout: shuffled, fractions as weights, no degree */
    *r = rows_of(t, W_CFRAC, 1);
    shuffle(r);
    write_paper(&b, r);
    expect_verdict("the paper's layout, shuffled, -27.0f / 7.0f fractions: C rounds them to floats, "
                   "so right to float precision, not exact",
                   verify_str(&b, "paper.h", 0, 0), VERIFY_RIGHT,
                   "RIGHT: right to float precision (|error| <= 1/2 ulp): the 516 terms");
    /* and a wrong weight there names the idx line and the wgt line */
    snprintf(r->r[40].w, sizeof r->r[40].w, "1.5f");
    sbuf_clear(&b);
    write_paper(&b, r);
    snprintf(want, sizeof want, "(the weight is on line %d)", PAPER_LINE0 + (int)r->n + 3 + 40);
    expect_line("paper layout: a wrong weight names its row's line", verify_str(&b, "paper.h", 0, 0),
                "paper.h", PAPER_LINE0 + 40, "wrong weight");
    expect_verdict("paper layout: a wrong weight names the weight's line too",
                   verify_str(&b, "paper.h", 0, 0), VERIFY_WRONG, want);
    sbuf_clear(&b);
}

/* The wrong variants of the bicubic table, each with its diagnosis. */
static void test_bicubic_mistakes(void)
{
    tp_table t;
    ptp_error err;
    rows r;
    if (!check(!tp_derive(&t, 3, 3, &err), "derive 3x3", "%s", err.msg))
        return;
    r = rows_of(&t, W_FRAC, 1);
    mistakes_in_a_row(&t, &r);
    mistakes_of_rows(&r);
    mistakes_of_scale(&t, &r);
    mistakes_in_paper_layout(&t, &r);
    free(r.r);
    tp_clear(&t);
}

/* u and v swapped and v-first on a non-square patch, where they differ from the exact table. */
static void test_transposed(void)
{
    tp_table t, u;
    ptp_error err;
    rows r;
    sbuf b;
    size_t x;
    if (!check(!tp_derive(&t, 2, 3, &err) && !tp_derive(&u, 3, 2, &err), "derive 2x3, 3x2", "%s",
               err.msg))
        return;
    r = relabelled(&t, 1);
    expect_verdict("2x3 with u and v swapped: wrong, the transposed patch",
                   verify_json(&r, 0, 0, 2, 3), VERIFY_WRONG,
                   "WRONG: u and v swapped: it is the exact table of bidegree 3x2");
    expect_verdict("2x3 with u and v swapped is exactly the 3x2 table",
                   verify_json(&r, 0, 0, 3, 2), VERIFY_RIGHT, "RIGHT: exact");
    free(r.r);

    expect_json("a 3x2 document checked as 2x3: u and v swapped, and a note on the degree",
                rows_of(&u, W_FRAC, 1), 3, 2, 2, 3, VERIFY_U_FIRST, VERIFY_WRONG,
                "t.json:3: note: the document names bidegree 3x2; checked as 2x3");
    expect_json("2x3 in the v-first index convention: wrong, explained", relabelled(&t, 0), 2, 3,
                0, 0, VERIFY_U_FIRST, VERIFY_WRONG,
                "WRONG: the v-first index convention: the same planes, but point (i, j) "
                "numbered j*3+i");

    r = relabelled(&t, 1);
    for (x = 0; x < r.n; x++) {
        rat w, two;
        rat_set_str(&w, r.r[x].w);
        rat_set_si(&two, 2);
        rat_mul(&w, &w, &two);
        rat_get_str(r.r[x].w, &w);
    }
    strcpy(r.r[3].w, "1");
    expect_verdict("2x3 with u and v swapped and scaled by 2, one weight wrong: both named",
                   verify_json(&r, 2, 3, 0, 0), VERIFY_WRONG,
                   "1 wrong weight) against the 200 terms of bidegree 2x3, read as the exact "
                   "table with u and v swapped and scaled by 2");
    expect_line("... and the wrong weight is against the swapped table, scaled",
                verify_json(&r, 2, 3, 0, 0), "t.json", JSON_LINE0 + 3, "wrong weight");
    free(r.r);

    r = rows_of(&t, W_CFRAC, 1);
    write_paper(&b, &r);
    expect_usage("a 2x3 paper table without --degree: ambiguous, asks for it",
                 verify_str(&b, "p.h", 0, 0), "p.h", 0, "use --degree");
    expect_verdict("... and with --degree 2x3 it is right to float precision",
                   verify_str(&b, "p.h", 2, 3), VERIFY_RIGHT, "RIGHT: right to float precision");
    sbuf_clear(&b);
    free(r.r);
    tp_clear(&t);
    tp_clear(&u);
}

static result verify_text(const char *text, int n)
{
    return run_verify(text, strlen(text), "x", n, n);
}

static void test_malformed(void)
{
    tp_table t;
    ptp_error err;
    sbuf b;
    char *big;
    size_t x, n = 10u << 20;
    double t0;
    rows r;
    if (!check(!tp_derive(&t, 2, 2, &err), "derive 2x2", "%s", err.msg))
        return;
    if (render(&b, &t, 1)) {
        result res = run_verify(b.s, b.len / 2, "x", 0, 0);
        expect_usage("a table cut in the middle: a usage error with the line", res, "x", 0, "");
        res = run_verify(b.s, (size_t)(strstr(b.s, "_idx[") - b.s) + 200, "x", 0, 0);
        expect_usage("a table cut inside its idx array", res, "x", 0, "expected");
        res = run_verify(b.s, (size_t)(strstr(b.s, "_wgt[") - b.s) + 200, "x", 0, 0);
        expect_usage("a table cut inside its wgt array", res, "x", 0, "expected");
        sbuf_clear(&b);
    }
    if (render(&b, &t, 0)) {
        expect_usage("a json cut in the middle", run_verify(b.s, b.len / 2, "x", 0, 0), "x", 0, "");
        sbuf_clear(&b);
    }
    r = rows_of(&t, W_FRAC, 1);
    r.n--;
    write_paper(&b, &r);
    r.n++;
    {
        /* one weight fewer than rows: drop the last weight line */
        char *p = strstr(b.s, "float wgt[] = {\n");
        char *q = p ? strstr(p, ",") : NULL;
        if (q) {
            char *text = malloc(b.len + 64);
            size_t k = (size_t)(q - b.s);
            memcpy(text, b.s, k);
            strcpy(text + k, "\n};\n");
            expect_usage("idx and wgt of different lengths", verify_text(text, 0), "x", 0,
                         "weights but the idx array");
            free(text);
        }
    }
    sbuf_clear(&b);
    free(r.r);

    expect_usage("a point out of range",
                 verify_text("uint idx[][4] = {{0, 0, 1, 16}};\nfloat wgt[] = {-9};\n", 3), "x", 0,
                 "point 16 out of range");
    expect_usage("a plane out of range", verify_text("[[64, 0, 1, 2, \"1\"]]", 3), "x", 0,
                 "plane 64 out of range");
    expect_usage("an index beyond any bidegree without --degree",
                 verify_text("idx[][4] = {{0, 0, 1, 2}, {1, 0, 1, 99}};\nwgt[] = {1, 2};", 0), "x", 0,
                 "cannot infer the bidegree");
    expect_usage("a negative index", verify_text("idx[][4] = {{0, -1, 1, 2}}; wgt[] = {1};", 0),
                 "x", 0, "negative index");
    expect_usage("a non-number index", verify_text("idx[][4] = {{0, a, 1, 2}}; wgt[] = {1};", 0),
                 "x", 0, "expected an index");
    expect_usage("a non-number weight", verify_text("idx[][4] = {{0, 0, 1, 2}};\nwgt[] = {x};", 0),
                 "x", 2, "expected a weight");
    expect_usage("a bad literal", verify_text("idx[][4] = {{0, 0, 1, 2}};\nwgt[] = {1.2.3};", 0),
                 "x", 2, "is not a number");
    expect_usage("a weight string that is no number", verify_text("[[0, 0, 1, 4, \"-9x\"]]", 3),
                 "x", 0, "'9x' is not a number");
    expect_usage("a weight string with more than a number",
                 verify_text("[[0, 0, 1, 4, \"-9 x\"]]", 3), "x", 0, "not a number or a fraction");
    expect_usage("a weight that is no string or number", verify_text("[[0, 0, 1, 4, true]]", 3),
                 "x", 0, "a weight must be");
    expect_usage("a division by zero", verify_text("idx[][4] = {{0, 0, 1, 2}}; wgt[] = {1/0};", 0),
                 "x", 0, "division by zero");
    expect_usage("a row of 3 indices", verify_text("idx[][4] = {{0, 0, 1}}; wgt[] = {1};", 0), "x", 0,
                 "expected ','");
    expect_usage("two idx arrays",
                 verify_text("a_idx[][4] = {{0,0,1,2}};\nb_idx[][4] = {{0,0,1,2}};\nwgt[] = {1};", 0),
                 "x", 2, "a second idx array");
    expect_usage("no wgt array", verify_text("idx[][4] = {{0,0,1,2}};", 0), "x", 0, "no wgt array");
    expect_usage("an unterminated comment", verify_text("idx[][4] = {{0,0,1,2}};\n/* ...", 0),
                 "x", 2, "unterminated comment");
    expect_usage("an empty file", run_verify("", 0, "x", 0, 0), "x", 1, "empty");
    expect_usage("only blanks", verify_text(" \n\t\n", 0), "x", 0, "empty");
    expect_usage("only comments", verify_text("// nothing\n/* here */\n", 0), "x", 0, "no table");
    expect_usage("json without terms", verify_text("{\"degree\": [3, 3]}", 0), "x", 0,
                 "no \"terms\"");
    expect_usage("json with a bad degree", verify_text("{\"degree\": [0, 3], \"terms\": []}", 0),
                 "x", 0, "degree");
    expect_usage("json with trailing text", verify_text("{\"terms\": []} x", 3), "x", 0,
                 "after the end");
    expect_usage("json with an empty table and no degree", verify_text("{\"terms\": []}", 0), "x", 0,
                 "no terms");
    expect_verdict("an empty table with --degree: every term missing", verify_text("[]", 1),
                   VERIFY_WRONG, "4 missing terms");

    /* binary garbage, fixed seed */
    big = malloc(n + 1);
    if (!check(big != NULL, "allocate 10 MB", ""))
        return;
    for (x = 0; x < 4096; x++)
        big[x] = (char)below(256);
    big[0] = 'x'; /* not JSON */
    {
        result res = run_verify(big, 4096, "x", 0, 0);
        check(res.st == PTP_EUSAGE && !strncmp(res.err.msg, "x:", 2), "binary garbage: usage error",
              "status %d: %s", res.st, res.err.msg);
        free(res.report);
        res = run_verify(big, 4096, "x", 3, 3);
        check(res.st == PTP_EUSAGE, "binary garbage with --degree: usage error", "status %d: %s",
              res.st, res.err.msg);
        free(res.report);
    }

    /* a 10 MB line: a number of 10 MB digits; then 10 MB of one JSON line; then 10 MB of '[' */
    t0 = (double)clock() / CLOCKS_PER_SEC;
    strcpy(big, "idx[][4] = {{0, 0, 1, 2}}; wgt[] = {");
    memset(big + strlen(big), '7', n - strlen(big));
    big[n] = '\0';
    expect_usage("a 10 MB number on one line", run_verify(big, n, "x", 0, 0), "x", 1,
                 "number too long");
    memset(big, ' ', n);
    memcpy(big, "{\"terms\": [", 11);
    for (x = 11; x + 20 < n; x += 20)
        memcpy(big + x, "[0, 0, 1, 2, \"-1\"], ", 20);
    expect_usage("10 MB of terms on one line, unterminated", run_verify(big, n, "x", 1, 1), "x", 1,
                 "term");
    memset(big, '[', n);
    memcpy(big, "{\"a\": ", 6);
    expect_usage("10 MB of nested '[' in JSON", run_verify(big, n, "x", 0, 0), "x", 1,
                 "nested too deeply");
    memcpy(big, "{\"terms\": [[[[", 14);
    expect_usage("nested arrays as a term", run_verify(big, n, "x", 0, 0), "x", 1, "expected");
    strcpy(big, "idx[][4] = {{0, 0, 1, 2}}; wgt[] = {");
    memset(big + strlen(big), '(', n - strlen(big));
    expect_usage("10 MB of '(' in a weight", run_verify(big, n, "x", 0, 0), "x", 1,
                 "nested too deeply");
    strcpy(big, "idx[][4] = {{0, 0, 1, 2}}; wgt[] = {");
    memset(big + strlen(big), '-', n - strlen(big));
    expect_usage("10 MB of '-' in a weight", run_verify(big, n, "x", 0, 0), "x", 1,
                 "expected a weight");
    check((double)clock() / CLOCKS_PER_SEC - t0 < 20, "the 10 MB inputs take under 20 s of CPU",
          "%.1f s", (double)clock() / CLOCKS_PER_SEC - t0);
    free(big);
    tp_clear(&t);
}

/* The 1x1 table written in many legal ways: each must read as exact. */
static void test_forms(void)
{
    static const char *const right[] = {
        /* a flat idx array, hex, octal and suffixed integers, exponents, a cast, long double */
        "static const unsigned idx[16] = {0x0, 0, 1, 2u, 1, 0, 1, 3UL, 2, 0, 02, 3, 3, 1, 2, 3};\n"
        "const double wgt[4] = {-1e0, -10e-1, 0.1e1f, (double)(1.0L)};\n",
        /* directives with continuations, comments and quotes; a use of idx in code; strings */
        "#define A \"x\\\" /* not a comment\" \\\n   continued 'q\n#if 0 /* a comment\n spanning */\n"
        "#endif\nint idx[][4] = { {0,0,1,2}, {1,0,1,3}, {2,0,2,3}, {3,1,2,3,}, }; // done\n"
        "const char *s = \"idx[] = {\", c = '{';\nfloat wgt[] = { -1, -1, +1, 1., };\n"
        "void f(float *t) { int x; for (x = 0; x < 4; x++) t[idx[x][0]] += wgt[x]; }\n",
        /* JSON: escapes in keys and strings, numbers as weights, fields to ignore */
        "{\"ter\\u006ds\": [[0,0,1,2,-1],[1,0,1,3,-1.0],[2,0,2,3,1E0],[3,1,2,3,\"1\"]],\n"
        " \"x\": {\"a\": [true, false, null, \"\\n\\t\\\"\\\\\\/\\b\\f\\r\\u00e9\"], \"b\": -1.5e-3}}",
        /* a bare terms array with weights as expressions in strings */
        "\xEF\xBB\xBF[[0, 0, 1, 2, \"-2/2\"], [1, 0, 1, 3, \"(-1)\"], [2, 0, 2, 3, \"3 * 1/3\"],"
        " [3, 1, 2, 3, \"(float)1\"]]",
    };
    static const struct {
        const char *text, *what;
        int line;
    } usage[] = {
        {"[[0, 0, 1, 2, \"-1\x01\"]]", "control character", 1},
        {"[[0, 0, 1, 2, \"\\x\"]]", "bad escape", 1},
        {"[[0, 0, 1, 2, \"\\u12\"]]", "bad \\u escape", 1},
        {"[[0, 0, 1, 2, -]]", "a bad number", 1},
        {"[[0, 0, 1, 2, 1.]]", "a bad number", 1},
        {"[[0, 0, 1, 2, 1e]]", "a bad number", 1},
        {"[[0, 0, 1.5, 2, 1]]", "must be a non-negative integer", 1},
        {"[[0, 0, 100000, 2, 1]]", "out of range", 1},
        {"[[0, 0, 1, 2, 1e999]]", "weight out of range", 1},
        {"{\"terms\": 5}", "must be an array", 1},
        {"{\"terms\": [],\n\"terms\": []}", "a second \"terms\"", 2},
        {"{\"degree\": [1, 1],\n\"degree\": [1, 1], \"terms\": []}", "a second \"degree\"", 2},
        {"{5: 1}", "expected a key string", 1},
        {"{\"a\": x, \"terms\": []}", "expected a JSON value", 1},
        {"{\"terms\": [],\n \"a\": {5: 1}}", "expected a key string", 2},
        {"{\"terms\": [] \"a\": 1}", "expected ','", 1},
        {"idx[] = {0, 0, 1, 2, {1, 0, 1, 3}}; wgt[] = {1, 1};", "mixes", 1},
        {"idx[] = {0, 0, 1, 2, 1};\nwgt[] = {1, 1};", "not a multiple of 4", 1},
        {"idx[][4] = {{0,0,1,2}}; wgt[] = {1};\nwgt[] = {1};", "a second wgt array", 2},
        {"idx[4\n", "unterminated '['", 1},
        {"idx[][4] = {{0,0,1,2}}; wgt[] = {1};\nchar *s = \"abc;\n", "unterminated string", 2},
        {"idx[][4] = {{0,0,1,100000}}; wgt[] = {1};", "out of range", 1},
        {"idx[][4] = {{0,0,1,2}};\nwgt[] = {1e999};", "weight out of range", 2},
        {"idx[][4] = {{0,0,1,2}};\nwgt[] = {(float x};", "expected ')' after the cast", 2},
        {"idx[][4] = {{0,0,1,2}};\nwgt[] = {(1};", "expected ')' to close", 2},
        {"idx[][4] = {{0,0,1,2}};\nwgt[] = {1 2};", "expected ',' or '}' in the wgt array of line 2",
         2},
        {"void f(void) {\n idx[][4] = {{0,0,1,2}}; wgt[] = {1};", "is never closed", 1},
        {"[[0, 0, 1, 2, \"1111111111111111111111111111111111111111111111111111111111111111111111"
         "1111111111111111111111111111111111111111111111111111111111111111111111111111111111111111"
         "1111111111111111111111111111111111111111111111111111111111111111111111111111111111111111"
         "1111111111111111111111111111111111111111111\"]]", "weight string too long", 1},
        {"{", "expected a key string", 1},
    };
    size_t k;
    for (k = 0; k < sizeof right / sizeof *right; k++) {
        char name[64];
        snprintf(name, sizeof name, "the 1x1 table written in legal form %zu reads as exact", k + 1);
        expect_verdict(name, verify_text(right[k], 0), VERIFY_RIGHT, "RIGHT: exact");
    }
    for (k = 0; k < sizeof usage / sizeof *usage; k++) {
        char name[128];
        snprintf(name, sizeof name, "malformed input %zu: %s", k + 1, usage[k].what);
        expect_usage(name, verify_text(usage[k].text, 0), "x", usage[k].line, usage[k].what);
    }
    {
        result r = verify_text("[]", -1);
        check(r.st == PTP_EUSAGE, "a negative degree is a usage error", "status %d", r.st);
        free(r.report);
        r = run_verify("[]", 2, "x", 3, 0);
        check(r.st == PTP_EUSAGE, "only one of n, m zero is a usage error", "status %d", r.st);
        free(r.report);
        r = verify_text("[]", PTP_MAX_DEGREE + 1);
        check(r.st == PTP_ELIMIT, "a degree beyond the limit is refused", "status %d", r.st);
        free(r.report);
    }
}

/* Several mistakes in one table: each named on its line, in line order, and the notes. */
static void test_several(void)
{
    static const char *const want[] = {
        "t.json:6: points not in increasing order flip the sign",
        "t.json:7: wrong weight: plane 1, cross4(b0, b4, b2): got 1, expected 18/7 (the points are "
        "not in increasing order: that is -1 times the exact term's weight for cross4(b0, b2, b4))",
        "t.json:9: note: {2, 0, 0, 5} repeats a point",
        "t.json:10: note: {2, 0, 3, 15} has weight 0",
        "t.json:11: wrong weight: plane 2, cross4(b1, b2, b4): got 0, expected -9/7",
        "t.json:13: wrong weight", /* the first of two different copies when neither is right */
        "t.json:14: duplicated term: plane 3, cross4(b0, b3, b5) repeats line 13",
        "t.json: missing term: plane 2: -18/7 * cross4(b0, b2, b5)",
        "t.json: missing term: plane 2: -3/7 * cross4(b0, b3, b4)",
        "t.json: missing term: plane 3: -54/35 * cross4(b0, b2, b6)",
        "t.json: WRONG: 8 problems (3 missing terms, 3 wrong weights, 1 duplicated term, 1 sign "
        "flipped by the order of the points)",
    };
    tp_table t;
    ptp_error err;
    rows r;
    result res;
    size_t k;
    const char *at;
    if (!check(!tp_derive(&t, 3, 3, &err), "derive 3x3", "%s", err.msg))
        return;
    r = rows_of(&t, W_FRAC, 1);
    r.r[1].p[1] = 5, r.r[1].p[2] = 1;             /* line 6: order flips the sign */
    r.r[2].p[1] = 4, r.r[2].p[2] = 2;             /* line 7: order flipped and weight wrong */
    strcpy(r.r[2].w, "1");
    r.r[4].p[1] = 0;                              /* line 9: a repeated point (and a missing term) */
    r.r[5].p[2] = 15;                             /* line 10: an extra term of weight 0 */
    strcpy(r.r[5].w, "0");
    strcpy(r.r[6].w, "0");                        /* line 11: a weight 0 where one belongs */
    r.r[8] = r.r[9];                              /* lines 13, 14: two copies, both wrong */
    strcpy(r.r[8].w, "5");
    strcpy(r.r[9].w, "6");
    res = verify_json(&r, 3, 3, 0, 0);
    at = res.report;
    for (k = 0; at && k < sizeof want / sizeof *want; k++)
        at = strstr(at, want[k]);
    check(res.st == PTP_OK && res.verdict == VERIFY_WRONG && at != NULL,
          "several mistakes: each named on its line, in line order, with the notes",
          "missing \"%s\" (in this order) in:\n%s", k ? want[k - 1] : want[0], res.report);
    free(res.report);
    free(r.r);
    tp_clear(&t);
}

/* Removes every occurrence of word from b's text. */
static void drop_all(sbuf *b, const char *word)
{
    size_t k = strlen(word);
    char *p;
    while ((p = strstr(b->s, word)) != NULL) {
        memmove(p, p + k, strlen(p + k) + 1);
        b->len -= k;
    }
}

/* A 2x2 table checked as 3x3: many problems, and a note that the indices fit 2x2. */
static void test_wrong_degree(void)
{
    tp_table t;
    ptp_error err;
    sbuf b;
    if (!check(!tp_derive(&t, 2, 2, &err), "derive 2x2", "%s", err.msg))
        return;
    if (render(&b, &t, 1)) {
        expect_verdict("a 2x2 table checked as 3x3 says the indices fit 2x2",
                       verify_str(&b, "t.h", 3, 3), VERIFY_WRONG,
                       "t.h: note: the indices fit bidegree 2x2, not 3x3");
        expect_verdict("... and that its name says 2x2", verify_str(&b, "t.h", 3, 3), VERIFY_WRONG,
                       "note: the array name names bidegree 2x2; checked as 3x3");
        drop_all(&b, "table_"); /* the names of earlier tables: ptp_2x2_idx */
        expect_verdict("... also from the name ptp_2x2_idx (without table_)",
                       verify_str(&b, "t.h", 3, 3), VERIFY_WRONG,
                       "note: the array name names bidegree 2x2; checked as 3x3");
        sbuf_clear(&b);
    }
    tp_clear(&t);
}

/* The line number of the line `k` lines after the first one holding decl in b, and the start
 * and end of that line; 0 when decl is not there. */
static int find_line(size_t *start, size_t *end, const sbuf *b, const char *decl, int k)
{
    const char *p = strstr(b->s, decl), *q;
    int line = 1;
    if (!p)
        return 0;
    while (p > b->s && p[-1] != '\n')
        p--;
    for (; k > 0 && (q = strchr(p, '\n')); k--)
        p = q + 1;
    for (q = b->s; q < p; q++)
        line += *q == '\n';
    *start = (size_t)(p - b->s);
    *end = (size_t)(strchr(p, '\n') - b->s);
    return line;
}

/* out = b with the line `k` lines after the one holding decl replaced by repl; returns its
 * line number (0 when decl is not there). */
static int replace_line(sbuf *out, const sbuf *b, const char *decl, int k, const char *repl)
{
    size_t start, end;
    int line = find_line(&start, &end, b, decl, k);
    sbuf_init(out);
    if (line)
        sbuf_printf(out, "%.*s%s%s", (int)start, b->s, repl, b->s + end);
    return line;
}

/* out = b with every "from" (and its upper case, for the macros) replaced by "to". */
static void rename_arrays(sbuf *out, const sbuf *b, const char *from, const char *to)
{
    char uf[32], ut[32];
    const char *p = b->s;
    size_t k, n = strlen(from);
    for (k = 0; k <= n && k < sizeof uf; k++)
        uf[k] = (char)(from[k] >= 'a' && from[k] <= 'z' ? from[k] - 32 : from[k]);
    for (k = 0; k <= strlen(to) && k < sizeof ut; k++)
        ut[k] = (char)(to[k] >= 'a' && to[k] <= 'z' ? to[k] - 32 : to[k]);
    sbuf_init(out);
    while (*p) {
        int lower = !strncmp(p, from, n), upper = !strncmp(p, uf, n);
        if (lower || upper) {
            sbuf_puts(out, lower ? to : ut);
            p += n;
        } else {
            sbuf_printf(out, "%c", *p++);
        }
    }
}

/* The generated table of (n, m) with everything appended. */
static int render_plus(sbuf *b, const tp_table *t, const char *more)
{
    int ok = render(b, t, 1);
    sbuf_puts(b, more);
    return ok;
}

/* iwgt, owner and the sched arrays are checked; what is not is listed (a function by the line
 * of its body's '{'). */
static void test_arrays(void)
{
    tp_table t;
    ptp_error err;
    sbuf b, c;
    char want[160];
    int line;
    if (!check(!tp_derive(&t, 2, 2, &err) && render(&b, &t, 1), "derive and render 2x2", "%s",
               err.msg))
        return;
    expect_verdict("the 2x2 table: every array checked, exact through iwgt/DENOM",
                   verify_str(&b, "t.h", 0, 0), VERIFY_RIGHT,
                   "t.h: checked: idx, wgt (76 terms), iwgt with DENOM 12, "
                   "sched_idx/sched_wgt/sched_iwgt (80 slots), owner (8 threads); ignored: nothing\n"
                   "t.h: RIGHT: exact: the 76 terms");
    line = replace_line(&c, &b, "_2x2_table_iwgt[", 1, "    5,");
    expect_line("a wrong iwgt entry, by its line", verify_str(&c, "t.h", 0, 0), "t.h", line,
                "wrong iwgt[0]: got 5, so iwgt/DENOM = 5/12, but the exact weight");
    sbuf_clear(&c);
    line = replace_line(&c, &b, "_2x2_table_sched_wgt[", 1, "    7.0f,");
    expect_line("a wrong sched_wgt entry, by its line", verify_str(&c, "t.h", 0, 0), "t.h", line,
                "sched slot 0 {");
    expect_verdict("... counted in the verdict", verify_str(&c, "t.h", 0, 0), VERIFY_WRONG,
                   "in iwgt, owner or the sched arrays) against the 76 terms");
    sbuf_clear(&c);
    line = replace_line(&c, &b, "_2x2_table_sched_wgt[", 1, "    0.0f,");
    expect_verdict("a sched_wgt entry set to 0 (padding): its term is in no slot",
                   verify_str(&c, "t.h", 0, 0), VERIFY_WRONG, "is in no sched slot");
    sbuf_clear(&c);
    line = replace_line(&c, &b, "_2x2_table_sched_iwgt[", 1, "    3,");
    expect_line("a wrong sched_iwgt entry", verify_str(&c, "t.h", 0, 0), "t.h", line,
                "wrong sched_iwgt[0] = 3");
    sbuf_clear(&c);
    line = replace_line(&c, &b, "_2x2_table_owner[", 1, "    7, 1, 5, 2, 4,");
    expect_verdict("a wrong owner: the slots of plane 0 run on another thread",
                   verify_str(&c, "t.h", 0, 0), VERIFY_WRONG, "which owner (line");
    sbuf_clear(&c);
    replace_line(&c, &b, "#define PTP_2X2_DENOM", 0, "");
    expect_verdict("no DENOM: iwgt is listed as ignored, the floats right to float precision",
                   verify_str(&c, "t.h", 0, 0), VERIFY_RIGHT,
                   "ignored: iwgt (no DENOM macro of 1 or more to divide it by), sched_iwgt (no "
                   "DENOM macro of 1 or more)\n"
                   "t.h: RIGHT: right to float precision (|error| <= 1/2 ulp)");
    sbuf_clear(&c);
    replace_line(&c, &b, "#define PTP_2X2_THREADS", 0, "");
    expect_verdict("no THREADS: owner is listed as ignored", verify_str(&c, "t.h", 0, 0),
                   VERIFY_RIGHT, "ignored: owner (no THREADS macro)");
    sbuf_clear(&c);
    snprintf(want, sizeof want, "; ignored: ptp_2x2_foo_bar (unknown array), 1 function from "
                                "line %d (code cannot be checked", find_line(&(size_t){0},
                                &(size_t){0}, &b, "#endif", 0) + 3);
    render_plus(&c, &t, "static const int ptp_2x2_foo_bar[2] = {1, 2};\n"
                        "static int f(int x)\n{\n    return -x;\n}\n");
    expect_verdict("an unknown array and a function are listed as ignored",
                   verify_str(&c, "t.h", 0, 0), VERIFY_RIGHT, want);
    expect_verdict("... and the verdict says the functions are not checked",
                   verify_str(&c, "t.h", 0, 0), VERIFY_RIGHT,
                   "(the arrays only: the code of its functions is not checked)");
    sbuf_clear(&c);
    rename_arrays(&c, &b, "ptp_2x2_", "ptp_2x2_table_");
    expect_verdict("arrays named ptp_2x2_table_idx and so on: matched by suffix, all checked",
                   verify_str(&c, "t.h", 2, 2), VERIFY_RIGHT, "t.h: checked: idx, wgt (76 terms), "
                   "iwgt with DENOM 12, sched_idx/sched_wgt/sched_iwgt (80 slots), owner (8 "
                   "threads); ignored: nothing\n");
    sbuf_clear(&c);
    sbuf_clear(&b);
    if (check(render(&b, &t, 0), "render json", "2x2"))
        expect_verdict("ptpgen's json: the terms checked, the other keys listed as ignored",
                       verify_str(&b, "t.json", 0, 0), VERIFY_RIGHT, "t.json: checked: terms (76 "
                       "terms); ignored: plane_degree, points, planes, plane_scale, schedule (JSON "
                       "keys)\n");
    sbuf_clear(&b);
    tp_clear(&t);
}

/* A schedule that runs a term twice, and one with padding that is right. */
static void test_schedule(void)
{
    static const char twice[] =
        "#define T_THREADS 2\nint t_idx[][4] = {{0, 0, 1, 2}, {1, 0, 1, 3}, {2, 0, 2, 3}, "
        "{3, 1, 2, 3}};\nfloat t_wgt[] = {-1, -1, 1, 1};\nint t_owner[4] = {0, 1, 0, 1};\n"
        "int t_sched_idx[][4] = {{0, 0, 1, 2}, {1, 0, 1, 3}, {2, 0, 2, 3}, {3, 1, 2, 3},\n"
        "{0, 0, 1, 2}, {1, 0, 0, 0}};\nfloat t_sched_wgt[] = {-1, -1, 1, 1, -1, 0};\n";
    char padded[sizeof twice];
    char *p;
    expect_line("a term scheduled twice", run_verify(twice, strlen(twice), "s.h", 0, 0), "s.h", 6,
                "sched slot 4 {0, 0, 1, 2} repeats a slot before it: the term (line 2) is "
                "scheduled twice");
    memcpy(padded, twice, sizeof twice);
    p = strstr(padded, "-1, 0};");
    memcpy(p, " 0, 0};", 7);
    expect_verdict("... and with that slot padding (weight 0, its thread's plane): right",
                   run_verify(padded, strlen(padded), "s.h", 0, 0), VERIFY_RIGHT,
                   "checked: idx, wgt (4 terms), sched_idx/sched_wgt (6 slots), owner (2 threads); "
                   "ignored: nothing\ns.h: RIGHT: exact");
}

/* Straight-line code cannot be checked from its text: verify says so and names the vectors. */
static void test_code(void)
{
    static const char code[] = "/* a classify with a flipped sign */\n#include <math.h>\n"
                               "unsigned classify(const float b[][4], const float e[4])\n{\n"
                               "    float t = -(b[0][0] * e[2]);\n    return t < 0;\n}\n";
    expect_usage("a straight-line classify (a flipped sign cannot be seen): verify says it "
                 "cannot check code", run_verify(code, strlen(code), "c.c", 0, 0), "c.c", 4,
                 "functions but no table arrays: verify checks tables (idx and wgt arrays, or "
                 "ptpgen json); straight-line code, such as ptpgen's C header, cannot be checked "
                 "from its text: run it on the test vectors of `ptpgen vectors --format c`");
}

/* Integer divisions in C are errors; float weights are right to float precision, not exact. */
static void test_weights(void)
{
    static const char div[] = "int idx[][4] = {{0, 0, 1, 2}, {1, 0, 1, 3}, {2, 0, 2, 3}, "
                              "{3, 1, 2, 3}};\nfloat wgt[] = {-1, -1,\n (1)/(-3), 1};\n";
    tp_table t;
    ptp_error err;
    rows r;
    sbuf b;
    expect_usage("an integer division as a C weight: C makes it 0", run_verify(div, strlen(div),
                 "d.h", 0, 0), "d.h", 3, "integer division: C evaluates 1/-3 as 0; write "
                 "1.0f/-3 or -0.333333343f");
    if (!check(!tp_derive(&t, 3, 3, &err), "derive 3x3", "%s", err.msg))
        return;
    r = rows_of(&t, W_FRAC, 1);
    write_paper(&b, &r);
    expect_usage("the paper's layout with -27/7 weights: integer division", verify_str(&b, "p.h",
                 0, 0), "p.h", 0, "integer division: C evaluates ");
    sbuf_clear(&b);
    expect_verdict("... while \"-27/7\" in JSON is an exact fraction", verify_json(&r, 3, 3, 0, 0),
                   VERIFY_RIGHT, "RIGHT: exact");
    free(r.r);
    r = rows_of(&t, W_FLOAT, 1);
    write_paper(&b, &r);
    expect_verdict("float weights: right to float precision, not exact", verify_str(&b, "p.h", 0, 0),
                   VERIFY_RIGHT, "RIGHT: right to float precision (|error| <= 1/2 ulp): the 516 "
                   "terms of bidegree 3x3 agree");
    sbuf_clear(&b);
    snprintf(r.r[5].w, sizeof r.r[5].w, "%.9gf", rat_get_d(&t.terms[5].w) * (1 + 4e-7));
    write_paper(&b, &r);
    expect_verdict("a float weight 4e-7 off: within the tolerance, but not the nearest float",
                   verify_str(&b, "p.h", 0, 0), VERIFY_RIGHT, "RIGHT: right to a relative error "
                   "of 4e-07 (within the tolerance 1e-06, but some weights are not the float "
                   "nearest the exact one)");
    sbuf_clear(&b);
    free(r.r);
    tp_clear(&t);
}

/* --convention v-first: a v-first table passes with it and fails without it. */
static void test_convention(void)
{
    tp_table t, s;
    ptp_error err;
    rows r;
    if (!check(!tp_derive(&t, 2, 3, &err) && !tp_derive(&s, 3, 3, &err), "derive", "%s", err.msg))
        return;
    r = relabelled(&t, 0);
    expect_verdict("a 2x3 v-first table with --convention v-first: exact",
                   verify_json_vfirst(&r, 2, 3, 0, 0), VERIFY_RIGHT,
                   "RIGHT: exact: the 200 terms of bidegree 2x3 (v-first) agree");
    expect_verdict("... and without it: wrong, with the option named", verify_json(&r, 2, 3, 0, 0),
                   VERIFY_WRONG, "right only for code that numbers points v-first (check it with "
                   "--convention v-first)");
    free(r.r);
    expect_json("a u-first table with --convention v-first: wrong, the u-first convention",
                rows_of(&t, W_FRAC, 1), 2, 3, 0, 0, VERIFY_V_FIRST, VERIFY_WRONG,
                "WRONG: the u-first index convention: the same planes, but point (i, j) "
                "numbered i*4+j");
    r = relabelled(&s, 0);
    expect_verdict("a 3x3 v-first table with --convention v-first: exact",
                   verify_json_vfirst(&r, 3, 3, 0, 0), VERIFY_RIGHT, "RIGHT: exact");
    expect_verdict("... without it: negated, and v-first named with the option",
                   verify_json(&r, 3, 3, 0, 0), VERIFY_WRONG, "--convention v-first");
    free(r.r);
    tp_clear(&t);
    tp_clear(&s);
}

/* The exact table of the triangle of degree d into *t; 0 (after a "not ok") when it fails. */
static int derive_tri(tp_table *t, int d)
{
    tp_domain dom;
    ptp_error err;
    return check(!tp_domain_init(&dom, TP_TRI, d, d, &err) && !tp_derive_domain(t, &dom, &err),
                 "derive a triangle", "degree %d: %s", d, err.msg);
}

/* The wrong variants of a triangular table of degree d (its terms r, exact), each with its
 * diagnosis; those that need two terms from degree 2 on. */
static void tri_mistakes(const tp_table *t, rows *r, int d)
{
    size_t x = r->n / 2;
    row keep = r->r[x];
    char want[256], w[RAT_STRLEN], name[160];
    sbuf b;
    int n = t->dom.nplanes;
    strcpy(r->r[x].w, "-1/3");
    write_json_kind(&b, r, TP_TRI, d, d);
    snprintf(want, sizeof want, "got -1/3, expected %s", rat_get_str(w, &t->terms[x].w));
    snprintf(name, sizeof name, "triangle %d: one weight changed: wrong weight, its line and "
             "got vs expected (one term: the whole table negated and scaled)", d);
    if (r->n > 1) {
        expect_line(name, verify_str(&b, "t.json", 0, 0), "t.json", JSON_LINE0 + (int)x,
                    "wrong weight");
        expect_verdict(name, verify_str(&b, "t.json", 0, 0), VERIFY_WRONG, want);
    } else {
        expect_verdict(name, verify_str(&b, "t.json", 0, 0), VERIFY_WRONG,
                       "WRONG: all weights negated, and every weight scaled by 0.333333333 = 1/3");
    }
    sbuf_clear(&b);
    r->r[x] = keep;
    r->r[x].p[0] = keep.p[1];
    r->r[x].p[1] = keep.p[0];
    write_json_kind(&b, r, TP_TRI, d, d);
    snprintf(name, sizeof name, "triangle %d: two indices swapped in a row: the sign flips", d);
    if (r->n > 1)
        expect_line(name, verify_str(&b, "t.json", 0, 0), "t.json", JSON_LINE0 + (int)x,
                    "points not in increasing order flip the sign");
    else
        expect_verdict(name, verify_str(&b, "t.json", 0, 0), VERIFY_WRONG,
                       "WRONG: all weights negated");
    sbuf_clear(&b);
    r->r[x] = keep;
    if (n > 1) {
        r->r[x].plane = (keep.plane + 1) % n;
        write_json_kind(&b, r, TP_TRI, d, d);
        snprintf(want, sizeof want, "is in plane %d but belongs to plane %d", (keep.plane + 1) % n,
                 keep.plane);
        snprintf(name, sizeof name, "triangle %d: a term moved to a wrong plane", d);
        expect_verdict(name, verify_str(&b, "t.json", 0, 0), VERIFY_WRONG, want);
        sbuf_clear(&b);
        r->r[x] = keep;
    }
    r->r[r->n] = r->r[x];
    r->n++;
    write_json_kind(&b, r, TP_TRI, d, d);
    snprintf(want, sizeof want, "duplicated term: plane %d, cross4(b%d, b%d, b%d) repeats line %d",
             keep.plane, keep.p[0], keep.p[1], keep.p[2], JSON_LINE0 + (int)x);
    snprintf(name, sizeof name, "triangle %d: a term duplicated", d);
    expect_line(name, verify_str(&b, "t.json", 0, 0), "t.json", JSON_LINE0 + (int)r->n - 1, want);
    sbuf_clear(&b);
    r->n--;
    if (r->n < 2)
        return;
    memmove(&r->r[x], &r->r[x + 1], (r->n - x - 1) * sizeof *r->r);
    r->n--;
    write_json_kind(&b, r, TP_TRI, d, d);
    snprintf(want, sizeof want, "missing term: plane %d: %s * cross4(b%d, b%d, b%d)", keep.plane,
             keep.w, keep.p[0], keep.p[1], keep.p[2]);
    snprintf(name, sizeof name, "triangle %d: a term dropped: missing, with its exact weight", d);
    expect_line(name, verify_str(&b, "t.json", 0, 0), "t.json", 0, want);
    sbuf_clear(&b);
    memmove(&r->r[x + 1], &r->r[x], (r->n - x) * sizeof *r->r);
    r->r[x] = keep;
    r->n++;
}

/* Writes r as a triangle's JSON (t.json) or in the paper's layout (p.h) and expects verify
 * --domain triangle --degree d in convention to give verdict with want in its report. */
static void expect_tri_rows(const char *name, const rows *r, int d, int json, int convention,
                            int verdict, const char *want)
{
    sbuf b;
    if (json)
        write_json_kind(&b, r, TP_TRI, d, d);
    else
        write_paper(&b, r);
    expect_verdict(name, run_verify_kind(b.s, b.len, json ? "t.json" : "p.h", TP_TRI, d, d,
                                         convention), verdict, want);
    sbuf_clear(&b);
}

/* Whole-table readings of a triangle of degree d: scaled, negated, u and v swapped, v-first. */
static void tri_readings(const tp_table *t, int d)
{
    rows r[4];
    char name[4][160], want[160];
    int k;
    r[0] = rows_of(t, W_FLOAT, 2.5);
    r[1] = rows_of(t, W_FLOAT, -1);
    r[2] = relabelled(t, 1);
    r[3] = relabelled(t, 0);
    snprintf(name[0], sizeof name[0], "triangle %d: the paper's layout, float weights times 2.5: "
             "right up to the scale", d);
    snprintf(name[1], sizeof name[1], "triangle %d: all weights negated: the opposite "
             "orientation", d);
    snprintf(name[2], sizeof name[2], "triangle %d with u and v swapped (and the sign of the "
             "swap): the same table", d);
    snprintf(name[3], sizeof name[3], "triangle %d in the v-first convention: exact with "
             "--convention v-first, wrong without", d);
    snprintf(want, sizeof want, "RIGHT: exact: the %zu terms of degree %d (v-first) agree",
             t->nterms, d);
    expect_tri_rows(name[0], &r[0], d, 0, VERIFY_U_FIRST, VERIFY_RIGHT, "positive scale s = 2.5 = 5/2");
    expect_tri_rows(name[1], &r[1], d, 0, VERIFY_U_FIRST, VERIFY_WRONG, "WRONG: all weights "
                    "negated: the table of the opposite orientation, which takes front-facing "
                    "patches for back-facing ones; for a triangle that is also the exact table in "
                    "the v-first index convention");
    expect_tri_rows(name[2], &r[2], d, 1, VERIFY_U_FIRST, VERIFY_RIGHT, "RIGHT: exact");
    expect_tri_rows(name[3], &r[3], d, 1, VERIFY_V_FIRST, VERIFY_RIGHT, want);
    expect_tri_rows(name[3], &r[3], d, 1, VERIFY_U_FIRST, VERIFY_WRONG, "--convention v-first");
    free(r[3].r);
    r[3] = rows_of(t, W_FRAC, 1);
    snprintf(name[3], sizeof name[3], "triangle %d, u-first, checked v-first: negated, the "
             "u-first convention named", d);
    expect_tri_rows(name[3], &r[3], d, 1, VERIFY_V_FIRST, VERIFY_WRONG, "for a triangle that is "
                    "also the exact table in the u-first index convention");
    for (k = 0; k < 4; k++)
        free(r[k].r);
}

/* The arrays of ptpgen's table of the triangle of degree 3, each broken once. */
static void tri_arrays(const tp_table *t)
{
    sbuf b, c;
    int line;
    if (!check(render(&b, t, 1), "render the degree 3 triangle table", "failed"))
        return;
    line = replace_line(&c, &b, "_tri3_table_iwgt[", 1, "    5,");
    expect_line("triangle 3: a wrong iwgt entry, by its line", verify_str(&c, "t.h", 0, 0), "t.h",
                line, "wrong iwgt[0]: got 5");
    sbuf_clear(&c);
    line = replace_line(&c, &b, "_tri3_table_sched_wgt[", 1, "    7.0f,");
    expect_line("triangle 3: a wrong sched_wgt entry, by its line", verify_str(&c, "t.h", 0, 0),
                "t.h", line, "sched slot 0 {");
    sbuf_clear(&c);
    line = replace_line(&c, &b, "_tri3_table_sched_idx[", 1, "    {0, 0, 1, 3},");
    expect_line("triangle 3: a wrong sched_idx row, by its line", verify_str(&c, "t.h", 0, 0),
                "t.h", line, "sched slot 0 {0, 0, 1, 3}");
    sbuf_clear(&c);
    line = replace_line(&c, &b, "_tri3_table_owner[", 1, "    1,");
    expect_verdict("triangle 3: a wrong owner: the slots of plane 0 run on another thread",
                   verify_str(&c, "t.h", 0, 0), VERIFY_WRONG, "which owner (line");
    sbuf_clear(&c);
    rename_arrays(&c, &b, "ptp_tri3_table_", "t_");
    expect_verdict("triangle 3: arrays named without the degree: a triangle inferred from the sizes",
                   verify_str(&c, "t.h", 0, 0), VERIFY_RIGHT, "RIGHT: exact: the 105 terms of "
                   "degree 3 agree");
    sbuf_clear(&c);
    expect_usage("triangle 3: a triangular table with --domain quad is refused",
                 run_verify_kind(b.s, b.len, "t.h", TP_QUAD, 0, 0, VERIFY_U_FIRST), "t.h", 0,
                 "the array name names --domain triangle, not quad");
    sbuf_clear(&b);
}

/* A degree 2 table checked as degree 3: the notes on the name and the sizes; without its name,
 * the sizes it shares with bidegree 1x2. */
static void tri_wrong_degree(const tp_table *t)
{
    sbuf b, c;
    if (!check(render(&b, t, 1), "render the degree 2 triangle table", "failed"))
        return;
    expect_verdict("triangle 2 checked as 3: the indices fit degree 2",
                   run_verify_kind(b.s, b.len, "t.h", TP_TRI, 3, 3, VERIFY_U_FIRST), VERIFY_WRONG,
                   "t.h: note: the indices fit degree 2, not 3");
    expect_verdict("... and its name says degree 2",
                   run_verify_kind(b.s, b.len, "t.h", VERIFY_KIND_ANY, 3, 3, VERIFY_U_FIRST),
                   VERIFY_WRONG, "note: the array name names degree 2; checked as 3");
    rename_arrays(&c, &b, "ptp_tri2_table_", "t_");
    expect_usage("triangle 2 without a name: its sizes are also those of bidegree 1x2, so verify "
                 "asks", verify_str(&c, "t.h", 0, 0), "t.h", 0, "the indices fit bidegree 1x2 and "
                 "2x1, and the triangle of degree 2: use --degree NxM, or --domain triangle");
    expect_verdict("... and with --domain triangle it is right",
                   run_verify_kind(c.s, c.len, "t.h", TP_TRI, 0, 0, VERIFY_U_FIRST), VERIFY_RIGHT,
                   "RIGHT: exact: the 17 terms of degree 2");
    sbuf_clear(&c);
    sbuf_clear(&b);
}

/* The form of a triangle's json: "domain" and one "degree" number; the mismatches refused. */
static void tri_json_forms(void)
{
    static const char list[] = "{\"domain\": \"triangle\", \"degree\": [1, 1],\n"
                               "\"terms\": [[0, 0, 1, 2, \"1\"]]}\n";
    static const char one[] = "{\"degree\": 1,\n\"terms\": [[0, 0, 1, 2, \"1\"]]}\n";
    static const char other[] = "{\n\"domain\": \"hexagon\", \"terms\": []}\n";
    static const char right[] = "{\"domain\": \"triangle\", \"degree\": 1,\n"
                                "\"terms\": [[0, 0, 1, 2, \"1\"]]}\n";
    expect_usage("a triangle json with \"degree\": [n, m] is refused",
                 run_verify(list, strlen(list), "t.json", 0, 0), "t.json", 1, "is one number d");
    expect_usage("a json with one \"degree\" number but no triangle domain is refused",
                 run_verify(one, strlen(one), "t.json", 0, 0), "t.json", 1,
                 "one number, is a triangle's degree");
    expect_usage("\"domain\": \"hexagon\" is refused", run_verify(other, strlen(other), "t.json",
                 0, 0), "t.json", 2, "expected \"quad\" or \"triangle\"");
    expect_verdict("the degree 1 triangle json by hand: exact", run_verify(right, strlen(right),
                   "t.json", 0, 0), VERIFY_RIGHT, "RIGHT: exact: the 1 terms of degree 1");
    expect_usage("... checked with --domain quad: refused, the domain named",
                 run_verify_kind(right, strlen(right), "t.json", TP_QUAD, 0, 0, VERIFY_U_FIRST),
                 "t.json", 1, "the document names --domain triangle, not quad");
    expect_usage("... checked as a triangle of degree 1x2: refused",
                 run_verify_kind(right, strlen(right), "t.json", TP_TRI, 1, 2, VERIFY_U_FIRST),
                 "t.json", 0, "a triangle has one degree");
}

/* Triangles of degree 1 to 3: ptpgen's own tables right (degree given or inferred), every
 * wrong variant the quads have diagnosed. */
static void test_triangles(void)
{
    tp_table t[3];
    int d, table;
    for (d = 1; d <= 3; d++) {
        char name[160];
        rows r;
        sbuf b;
        if (!derive_tri(&t[d - 1], d))
            return;
        for (table = 0; table < 2; table++) {
            if (!check(render(&b, &t[d - 1], table), "render", "triangle %d", d))
                continue;
            snprintf(name, sizeof name, "verify accepts ptpgen's own triangle %d %s (inferred)", d,
                     table ? "table" : "json");
            expect_verdict(name, verify_str(&b, "gen", 0, 0), VERIFY_RIGHT, "RIGHT: exact");
            snprintf(name, sizeof name, "verify accepts ptpgen's own triangle %d %s as --domain "
                     "triangle --degree %d", d, table ? "table" : "json", d);
            expect_verdict(name, run_verify_kind(b.s, b.len, "gen", TP_TRI, d, d, VERIFY_U_FIRST),
                           VERIFY_RIGHT, "RIGHT: exact");
            sbuf_clear(&b);
        }
        r = rows_of(&t[d - 1], W_FRAC, 1);
        r.r = realloc(r.r, (r.n + 8) * sizeof *r.r);
        tri_mistakes(&t[d - 1], &r, d);
        free(r.r);
        tri_readings(&t[d - 1], d);
    }
    tri_arrays(&t[2]);
    tri_wrong_degree(&t[1]);
    tri_json_forms();
    for (d = 0; d < 3; d++)
        tp_clear(&t[d]);
}

int main(void)
{
    test_generated();
    test_bicubic_mistakes();
    test_transposed();
    test_malformed();
    test_forms();
    test_several();
    test_wrong_degree();
    test_arrays();
    test_schedule();
    test_code();
    test_weights();
    test_convention();
    test_triangles();
    return check_exit();
}
