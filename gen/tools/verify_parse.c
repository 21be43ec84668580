/* verify_parse.c: reads a control-plane table for `ptpgen verify`: C arrays or ptpgen's JSON.
 * Its own small C lexer and JSON reader: linear time, bounded depth, the line of every term. */
#include "tools/verify_parse.h"
#include "core/domain.h"
#include "core/i128.h"

#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAX_DEPTH 64          /* JSON nesting, and parentheses and casts in one weight */
#define MAX_LITERAL 400       /* characters of one number that is read */
#define MAX_WEIGHT_STRING 256 /* characters of one JSON weight string */
#define EXACT_FLOAT_LIMIT 16777216.0 /* 2^24: a float literal this large may be a rounding */

/* The reading position in a text. */
typedef struct {
    const char *s;
    size_t len, pos;
    int line;
    int bol; /* only blanks and comments since the line began: '#' starts a directive */
    const char *name;
    ptp_error *err;
    verify_doc *doc; /* C source: where directives and arrays go; NULL in JSON */
} rd;

enum { T_END, T_ID, T_NUM, T_STR, T_PUNCT };

/* A C token: s[at..at+len) on line `line`. */
typedef struct {
    int kind;
    size_t at, len;
    int line;
} tok;

/* A growable array of n elements of `size` bytes. */
typedef struct {
    void *v;
    size_t n, cap;
} vec;

/* Fails with PTP_EUSAGE and "NAME:LINE: message". */
static int fail_at(const rd *r, int line, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

static int fail_at(const rd *r, int line, const char *fmt, ...)
{
    char msg[400];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    return ptp_fail(r->err, PTP_EUSAGE, "%s:%d: %s", r->name, line, msg);
}

/* Appends a zeroed element to a (elements of size bytes); *at points at it. */
static int vec_push(vec *a, size_t size, void **at, const rd *r)
{
    if (a->n == a->cap) {
        size_t cap = a->cap ? a->cap * 2 : 256;
        void *v;
        if (cap > SIZE_MAX / size || !(v = realloc(a->v, cap * size)))
            return ptp_fail(r->err, PTP_ENOMEM, "out of memory reading %s", r->name);
        a->v = v;
        a->cap = cap;
    }
    *at = (char *)a->v + a->n++ * size;
    memset(*at, 0, size);
    return PTP_OK;
}

/* The byte at i, or -1 past the end. */
static int at(const rd *r, size_t i)
{
    return i < r->len ? (unsigned char)r->s[i] : -1;
}

static void newline(rd *r)
{
    if (r->line < INT_MAX)
        r->line++;
}

/* Writes a printable excerpt of s[0..n) (at most 24 characters) to buf (32 bytes). */
static const char *excerpt(char *buf, const char *s, size_t n)
{
    size_t i;
    if (n == 0)
        return strcpy(buf, "end of input");
    for (i = 0; i < n && i < 24; i++)
        buf[i] = s[i] >= 0x20 && s[i] < 0x7f ? s[i] : '?';
    buf[i] = '\0';
    return buf;
}

static const char *tok_text(char *buf, const rd *r, const tok *t)
{
    return excerpt(buf, r->s + t->at, t->kind == T_END ? 0 : t->len);
}

/* ---- numbers ---- */

static int digit_value(int c)
{
    if (c >= '0' && c <= '9')
        return c - '0';
    if (c >= 'a' && c <= 'f')
        return c - 'a' + 10;
    if (c >= 'A' && c <= 'F')
        return c - 'A' + 10;
    return 99;
}

static int is_digit(int c)
{
    return c >= '0' && c <= '9';
}

/* Nonzero when c is one of the characters of set (never for NUL or -1). */
static int in_set(int c, const char *set)
{
    return c > 0 && strchr(set, c) != NULL;
}

/* u = u * base + v, with overflow sticky in *ovf. */
static void acc(ptp_u128 *u, int *ovf, unsigned base, unsigned v)
{
    if (*ovf || u128_mul_ovf(u, *u, base) || *u + v < *u)
        *ovf = 1;
    else
        *u += v;
}

/* Sets w from the decimal floating literal s[0..n) (digits [. digits] [e[+-]digits] [fFlL],
 * with '.' or an exponent; at most MAX_LITERAL characters); returns 0, or 1 when s is no such
 * literal. Exact when every digit from the point position (after the exponent) on is 0 and the
 * value is below EXACT_FLOAT_LIMIT. */
static int float_literal(verify_weight *w, const char *s, size_t n)
{
    ptp_u128 u = 0;
    int ovf = 0, point = 0, ndig = 0, any = 0;
    long e = 0, pp;
    size_t i, k;
    char copy[MAX_LITERAL + 1];
    for (i = 0; i < n && (is_digit(s[i]) || (s[i] == '.' && !point)); i++) {
        point |= s[i] == '.';
        any |= is_digit(s[i]);
    }
    if (!any)
        return 1;
    if (i < n && (s[i] == 'e' || s[i] == 'E')) {
        int neg = 0;
        size_t e0;
        i++;
        if (i < n && (s[i] == '+' || s[i] == '-'))
            neg = s[i++] == '-';
        for (e0 = i; i < n && is_digit(s[i]); i++)
            if (e < 1000000)
                e = e * 10 + (s[i] - '0');
        if (i == e0)
            return 1;
        e = neg ? -e : e;
        point = 1;
    }
    if (i < n && in_set(s[i], "fFlL"))
        i++;
    if (i != n || !point)
        return 1;
    memcpy(copy, s, n);
    copy[n] = '\0';
    w->d = strtod(copy, NULL);
    for (k = 0; k < n && s[k] != '.' && is_digit(s[k]); k++)
        ;
    pp = (long)k + e; /* the point position, after the exponent */
    w->exact = 1;
    for (k = 0; k < n && (is_digit(s[k]) || s[k] == '.'); k++) {
        if (s[k] == '.')
            continue;
        if (ndig++ < pp)
            acc(&u, &ovf, 10, (unsigned)(s[k] - '0'));
        else if (s[k] != '0')
            w->exact = 0;
    }
    for (; ndig < pp && u && !ovf; ndig++)
        acc(&u, &ovf, 10, 0);
    if (ovf || (double)u >= EXACT_FLOAT_LIMIT)
        w->exact = 0;
    if (w->exact)
        w->r.num = (ptp_i128)u;
    return 0;
}

/* Reads the literal s[0..n): a C integer literal (decimal, octal or hex, u/l suffixes; *integer
 * set) or a decimal floating literal (an optional f/l suffix). Returns 0, 1 when s is not such a
 * literal, 2 when it is longer than MAX_LITERAL. */
static int number(verify_weight *w, int *integer, const char *s, size_t n)
{
    ptp_u128 u = 0;
    int ovf = 0, base = 10;
    size_t i = 0, d0, k;
    double d = 0;
    w->r.num = 0;
    w->r.den = 1;
    if (n > MAX_LITERAL)
        return 2;
    if (n >= 2 && s[0] == '0' && (s[1] == 'x' || s[1] == 'X'))
        base = 16, i = 2;
    else if (n >= 1 && s[0] == '0')
        base = 8;
    d0 = i;
    for (; i < n && digit_value(s[i]) < base; i++) {
        acc(&u, &ovf, (unsigned)base, (unsigned)digit_value(s[i]));
        d = d * base + digit_value(s[i]);
    }
    for (k = i; k < n && k - i < 3 && in_set(s[k], "uUlL"); k++)
        ;
    *integer = i > d0 && k == n;
    if (!*integer)
        return float_literal(w, s, n);
    w->d = d;
    w->exact = !ovf && !i128_from_mag(&w->r.num, 0, u);
    return 0;
}

/* ---- the C lexer ---- */

/* Skips the block comment at pos ("/" "*"). */
static int skip_comment(rd *r)
{
    int line = r->line;
    for (r->pos += 2; r->pos < r->len; r->pos++) {
        if (r->s[r->pos] == '*' && at(r, r->pos + 1) == '/') {
            r->pos += 2;
            return PTP_OK;
        }
        if (r->s[r->pos] == '\n')
            newline(r);
    }
    return fail_at(r, line, "unterminated comment");
}

/* Skips the string or character literal at pos; one left open at the end of the line is an
 * error, except in a directive (where it ends there). */
static int skip_quoted(rd *r, int in_directive)
{
    int q = r->s[r->pos], line = r->line;
    for (r->pos++; r->pos < r->len; r->pos++) {
        int c = r->s[r->pos];
        if (c == '\n')
            break;
        if (c == '\\' && r->pos + 1 < r->len) {
            if (r->s[++r->pos] == '\n')
                newline(r);
        } else if (c == q) {
            r->pos++;
            return PTP_OK;
        }
    }
    return in_directive ? PTP_OK : fail_at(r, line, "unterminated %s literal",
                                           q == '"' ? "string" : "character");
}

/* Skips the preprocessor directive at pos ('#'), with its continuation lines and comments. */
static int skip_directive(rd *r)
{
    int c, st;
    while ((c = at(r, r->pos)) >= 0 && c != '\n') {
        int c1 = at(r, r->pos + 1);
        if (c == '\\' && (c1 == '\n' || (c1 == '\r' && at(r, r->pos + 2) == '\n'))) {
            r->pos += c1 == '\n' ? 2 : 3;
            newline(r);
        } else if (c == '/' && c1 == '*') {
            if ((st = skip_comment(r)))
                return st;
        } else if (c == '/' && c1 == '/') {
            while ((c = at(r, r->pos)) >= 0 && c != '\n')
                r->pos++;
        } else if (c == '"' || c == '\'') {
            if ((st = skip_quoted(r, 1)))
                return st;
        } else {
            r->pos++;
        }
    }
    return PTP_OK;
}

static int is_ident(int c, int first)
{
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_' || (!first && is_digit(c));
}

/* s[0..n) is suffix or ends in "_" suffix. */
static int named(const char *s, size_t n, const char *suffix)
{
    size_t k = strlen(suffix);
    return n >= k && !memcmp(s + n - k, suffix, k) && (n == k || s[n - k - 1] == '_');
}

/* Records `#define NAME INTEGER` at pos ('#' opening a directive) when NAME ends in DENOM or
 * THREADS; reads nothing past the line. */
static void read_define(verify_doc *d, const rd *r)
{
    size_t p = r->pos + 1, n0, n1, v0;
    verify_macro *m;
    verify_weight w;
    int integer;
    while (in_set(at(r, p), " \t"))
        p++;
    if (r->len - p < 7 || memcmp(r->s + p, "define", 6) || !in_set(at(r, p + 6), " \t"))
        return;
    for (p += 6; in_set(at(r, p), " \t"); p++)
        ;
    for (n0 = p; is_ident(at(r, p), p == n0); p++)
        ;
    for (n1 = p; in_set(at(r, p), " \t"); p++)
        ;
    for (v0 = p; is_ident(at(r, p), 0); p++)
        ;
    m = named(r->s + n0, n1 - n0, "DENOM") ? &d->denom
        : named(r->s + n0, n1 - n0, "THREADS") ? &d->threads : NULL;
    if (!m || m->line || (at(r, p) >= 0 && !in_set(at(r, p), " \t\r\n/")) ||
        number(&w, &integer, r->s + v0, p - v0) || !integer || !w.exact || w.r.num > 1000000000)
        return;
    m->v = (long)w.r.num;
    m->line = r->line;
}

/* Reads the next token into t, past blanks, comments and preprocessor directives. */
static int lex(rd *r, tok *t)
{
    int c, st;
    for (;;) {
        c = at(r, r->pos);
        if (c == '\n') {
            newline(r);
            r->pos++;
            r->bol = 1;
        } else if (c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v') {
            r->pos++;
        } else if (c == '/' && at(r, r->pos + 1) == '*') {
            if ((st = skip_comment(r)))
                return st;
        } else if (c == '/' && at(r, r->pos + 1) == '/') {
            while ((c = at(r, r->pos)) >= 0 && c != '\n')
                r->pos++;
        } else if (c == '#' && r->bol) {
            if (r->doc)
                read_define(r->doc, r);
            if ((st = skip_directive(r)))
                return st;
        } else {
            break;
        }
    }
    r->bol = 0;
    t->at = r->pos;
    t->line = r->line;
    if (c < 0) {
        t->kind = T_END;
    } else if (is_ident(c, 1)) {
        t->kind = T_ID;
        while (is_ident(at(r, r->pos), 0))
            r->pos++;
    } else if (is_digit(c) || (c == '.' && is_digit(at(r, r->pos + 1)))) {
        t->kind = T_NUM; /* a preprocessing number */
        for (r->pos++; (c = at(r, r->pos)) >= 0; r->pos++) {
            if (in_set(c, "eEpP") && (at(r, r->pos + 1) == '+' || at(r, r->pos + 1) == '-'))
                r->pos++;
            else if (!is_ident(c, 0) && c != '.')
                break;
        }
    } else if (c == '"' || c == '\'') {
        t->kind = T_STR;
        if ((st = skip_quoted(r, 0)))
            return st;
    } else {
        t->kind = T_PUNCT;
        r->pos++;
    }
    t->len = r->pos - t->at;
    return PTP_OK;
}

static int is_punct(const rd *r, const tok *t, char c)
{
    return t->kind == T_PUNCT && r->s[t->at] == c;
}

static int is_word(const rd *r, const tok *t, const char *w)
{
    return t->kind == T_ID && t->len == strlen(w) && !memcmp(r->s + t->at, w, t->len);
}

/* Fails unless t is the punctuator c; then reads the next token. */
static int expect(rd *r, tok *t, char c, const char *context)
{
    char buf[32];
    if (!is_punct(r, t, c))
        return fail_at(r, t->line, "expected '%c' %s, found '%s'", c, context, tok_text(buf, r, t));
    return lex(r, t);
}

/* ---- weights: a number, or signs, casts, parentheses, '*' and '/' over numbers ---- */

static int weight_expr(rd *r, tok *t, verify_weight *w, int depth);

static void weight_neg(verify_weight *w)
{
    w->d = -w->d;
    rat_neg(&w->r, &w->r);
}

/* A unary weight: signs, then (float) or (double) and a unary, (expr), or a number. */
static int weight_unary(rd *r, tok *t, verify_weight *w, int depth)
{
    int neg = 0, st, integer;
    char buf[32];
    while (is_punct(r, t, '-') || is_punct(r, t, '+')) {
        neg ^= is_punct(r, t, '-');
        if ((st = lex(r, t)))
            return st;
    }
    if (is_punct(r, t, '(')) {
        int line = t->line;
        if (depth >= MAX_DEPTH)
            return fail_at(r, line, "weight nested too deeply");
        if ((st = lex(r, t)))
            return st;
        if (is_word(r, t, "float") || is_word(r, t, "double")) {
            if ((st = lex(r, t)) || (st = expect(r, t, ')', "after the cast")) ||
                (st = weight_unary(r, t, w, depth + 1)))
                return st;
            w->cint = 0;
        } else if ((st = weight_expr(r, t, w, depth + 1)) ||
                   (st = expect(r, t, ')', "to close the '('"))) {
            return st;
        }
    } else if (t->kind == T_NUM) {
        switch (number(w, &integer, r->s + t->at, t->len)) {
        case 0:
            break;
        case 2:
            return fail_at(r, t->line, "number too long (over %d characters)", MAX_LITERAL);
        default:
            return fail_at(r, t->line, "'%s' is not a number", tok_text(buf, r, t));
        }
        w->cint = integer;
        if ((st = lex(r, t)))
            return st;
    } else {
        return fail_at(r, t->line, "expected a weight (a number or a fraction), found '%s'",
                       tok_text(buf, r, t));
    }
    if (neg)
        weight_neg(w);
    return PTP_OK;
}

/* C evaluates a / b of two integer constant expressions as an integer division. */
static int int_division(const rd *r, int line, const verify_weight *a, const verify_weight *b)
{
    char q[RAT_STRLEN] = "an integer";
    rat t = {0, 1};
    if (a->exact && b->exact) {
        t.num = a->r.num / b->r.num;
        rat_get_str(q, &t);
    }
    return fail_at(r, line, "integer division: C evaluates %.0f/%.0f as %s; write %.0f.0f/%.0f "
                            "or %.9gf", a->d, b->d, q, a->d, b->d, (double)(float)(a->d / b->d));
}

/* In C, a product or quotient is computed in float: exact only when it is an integer below
 * 2^24 in magnitude. */
static int c_exact(const rat *q)
{
    return q->den == 1 && q->num < (ptp_i128)EXACT_FLOAT_LIMIT &&
           q->num > -(ptp_i128)EXACT_FLOAT_LIMIT;
}

/* Unaries joined by '*' and '/', exact while every operand is (and in C while c_exact). */
static int weight_expr(rd *r, tok *t, verify_weight *w, int depth)
{
    int st = weight_unary(r, t, w, depth);
    while (!st && (is_punct(r, t, '*') || is_punct(r, t, '/'))) {
        int div = is_punct(r, t, '/'), line = t->line;
        verify_weight b;
        rat q;
        if ((st = lex(r, t)) || (st = weight_unary(r, t, &b, depth)))
            return st;
        if (div && b.d == 0)
            return fail_at(r, line, "division by zero in a weight");
        if (div && r->doc && w->cint && b.cint)
            return int_division(r, line, w, &b);
        w->d = div ? w->d / b.d : w->d * b.d;
        w->exact = w->exact && b.exact && !(div ? rat_div(&q, &w->r, &b.r) : rat_mul(&q, &w->r, &b.r));
        w->exact = w->exact && (!r->doc || c_exact(&q));
        w->cint = !div && w->cint && b.cint;
        if (w->exact)
            w->r = q;
    }
    return st;
}

/* Reads one whole weight at t; it must be finite. */
static int weight(rd *r, tok *t, verify_weight *w)
{
    int line = t->line, st = weight_expr(r, t, w, 0);
    if (!st && !isfinite(w->d))
        return fail_at(r, line, "weight out of range");
    return st;
}

/* ---- the C arrays ---- */

/* What an array is, by its name: one of d->arr's (VERIFY_IWGT...), idx, wgt, or unknown. */
enum { ROLE_IDX = VERIFY_NARRAYS, ROLE_WGT, ROLE_NONE };

/* The role of the array named t: longest suffixes first, so *_sched_idx is not idx. */
static int role_of(const rd *r, const tok *t)
{
    static const struct {
        const char *suffix;
        int role;
    } names[] = {{"sched_iwgt", VERIFY_SCHED_IWGT}, {"sched_idx", VERIFY_SCHED_IDX},
                 {"sched_wgt", VERIFY_SCHED_WGT},   {"iwgt", VERIFY_IWGT},
                 {"owner", VERIFY_OWNER},           {"idx", ROLE_IDX},
                 {"wgt", ROLE_WGT}};
    size_t k;
    for (k = 0; k < sizeof names / sizeof names[0]; k++)
        if (named(r->s + t->at, t->len, names[k].suffix))
            return names[k].role;
    return ROLE_NONE;
}

/* The largest degree any kind supports. */
#define MAX_ANY_DEGREE (PTP_MAX_TRI_DEGREE > PTP_MAX_DEGREE ? PTP_MAX_TRI_DEGREE : PTP_MAX_DEGREE)

/* The degrees in an idx array name like ptp_2x3_idx or ptp_2x3_table_idx (digits 'x' digits),
 * or ptp_tri3_idx ("tri" digits: a triangle), before "_idx" or "_table_idx", after '_' or at
 * the start, into d as a hint. */
static void name_degree(verify_doc *d, const char *s, size_t n, int line)
{
    size_t k = n >= 10 && !memcmp(s + n - 10, "_table_idx", 10) ? n - 10 : n - 4; /* s[k]: '_' */
    int v[2] = {0, 0}, which, scale, tri = 0;
    if (n < 4)
        return;
    for (which = 1; which >= 0 && !tri; which--) {
        for (scale = 1; k > 0 && is_digit(s[k - 1]) && scale <= 1000; k--, scale *= 10)
            v[which] += (s[k - 1] - '0') * scale;
        if (scale == 1 || v[which] < 1 || v[which] > MAX_ANY_DEGREE)
            return;
        if (which == 1 && k >= 3 && !memcmp(s + k - 3, "tri", 3))
            tri = 1, k -= 3, v[0] = v[1];
        else if (which == 1 && (k == 0 || s[--k] != 'x'))
            return;
    }
    if ((k > 0 && s[k - 1] != '_') || v[0] > (tri ? PTP_MAX_TRI_DEGREE : PTP_MAX_DEGREE) ||
        v[1] > (tri ? PTP_MAX_TRI_DEGREE : PTP_MAX_DEGREE))
        return;
    d->n = v[0];
    d->m = v[1];
    d->degree_line = d->kind_line = line;
    d->degree_named = d->kind_named = 2;
    d->kind = tri ? TP_TRI : TP_QUAD;
}

/* Skips [ ... ] (nested) at t, and reads the token after it. */
static int skip_brackets(rd *r, tok *t)
{
    int depth = 1, line = t->line, st;
    while (!(st = lex(r, t)) && t->kind != T_END) {
        depth += is_punct(r, t, '[') - is_punct(r, t, ']');
        if (depth == 0)
            return lex(r, t);
    }
    return st ? st : fail_at(r, line, "unterminated '['");
}

/* Reads the index at t (a non-negative integer literal) and the token after it. */
static int read_index(rd *r, tok *t, int *v)
{
    verify_weight w;
    int integer = 0;
    char buf[32];
    if (is_punct(r, t, '-'))
        return fail_at(r, t->line, "negative index");
    if (t->kind != T_NUM || number(&w, &integer, r->s + t->at, t->len) || !integer)
        return fail_at(r, t->line, "expected an index (a non-negative integer), found '%s'",
                       tok_text(buf, r, t));
    if (!w.exact || w.r.num > VERIFY_MAX_INDEX)
        return fail_at(r, t->line, "index %s out of range", tok_text(buf, r, t));
    *v = (int)w.r.num;
    return lex(r, t);
}

/* After an element at t: ',' (read past it) or the closing '}' of the array of `line`. */
static int next_element(rd *r, tok *t, const char *what, int line)
{
    char buf[32];
    if (is_punct(r, t, ','))
        return lex(r, t);
    if (is_punct(r, t, '}'))
        return PTP_OK;
    return fail_at(r, t->line, "expected ',' or '}' in the %s array of line %d, found '%s'", what,
                   line, tok_text(buf, r, t));
}

/* Reads the idx initializer at t ('{'): rows {plane, j, k, l}, or a flat list of indices in
 * groups of four; appends them to rows (verify_term). */
static int read_rows(rd *r, tok *t, vec *rows, int line)
{
    int st, flat = -1, nflat = 0, v[4];
    verify_term *e = NULL;
    if ((st = lex(r, t)))
        return st;
    while (!is_punct(r, t, '}')) {
        int q, row = is_punct(r, t, '{'), rline = t->line;
        if (flat == row)
            return fail_at(r, t->line, "the idx array mixes rows {plane, j, k, l} and plain indices");
        flat = !row;
        if (row) {
            if ((st = lex(r, t)))
                return st;
            for (q = 0; q < 4; q++)
                if ((st = read_index(r, t, &v[q])) ||
                    (q < 3 && (st = expect(r, t, ',', "between the 4 indices of a row"))))
                    return st;
            if (is_punct(r, t, ',') && (st = lex(r, t)))
                return st;
            if ((st = expect(r, t, '}', "after the 4 indices {plane, j, k, l} of a row")))
                return st;
        } else {
            if (nflat == 0 && (st = vec_push(rows, sizeof *e, (void **)&e, r)))
                return st;
            if (nflat == 0)
                e->line = rline;
            if ((st = read_index(r, t, nflat == 0 ? &e->plane : &e->p[nflat - 1])))
                return st;
            nflat = (nflat + 1) % 4;
        }
        if (row) {
            if ((st = vec_push(rows, sizeof *e, (void **)&e, r)))
                return st;
            e->line = rline;
            e->plane = v[0];
            for (q = 0; q < 3; q++)
                e->p[q] = v[q + 1];
        }
        if ((st = next_element(r, t, "idx", line)))
            return st;
    }
    if (nflat)
        return fail_at(r, t->line, "the idx array of line %d holds a number of indices that is "
                                   "not a multiple of 4", line);
    return lex(r, t);
}

/* Reads the initializer at t ('{') of a list of weights or numbers, appending to wgts
 * (verify_term: w, and line = wline); what names the array in messages. */
static int read_weights(rd *r, tok *t, vec *wgts, int line, const char *what)
{
    int st;
    verify_term *e = NULL;
    if ((st = lex(r, t)))
        return st;
    while (!is_punct(r, t, '}')) {
        if ((st = vec_push(wgts, sizeof *e, (void **)&e, r)))
            return st;
        e->line = e->wline = t->line;
        if ((st = weight(r, t, &e->w)) || (st = next_element(r, t, what, line)))
            return st;
    }
    return lex(r, t);
}

/* The arrays of C source as read, by role (VERIFY_IWGT..ROLE_WGT). */
typedef struct {
    vec v[ROLE_NONE];
    int line[ROLE_NONE]; /* the line declaring each, 0 while unseen */
} c_arrays;

static const char *const role_names[ROLE_NONE] = {"iwgt", "owner", "sched_idx", "sched_wgt",
                                                  "sched_iwgt", "idx", "wgt"};

/* Appends the name of an array verify does not know to d->ignored. */
static void note_ignored(verify_doc *d, const char *s, size_t n)
{
    size_t k = strlen(d->ignored);
    if (k + n + 8 >= sizeof d->ignored) {
        if (k + 5 < sizeof d->ignored && !strstr(d->ignored, "..."))
            strcpy(d->ignored + k, k ? ", ..." : "...");
        return;
    }
    snprintf(d->ignored + k, sizeof d->ignored - k, "%s%.*s", k ? ", " : "", (int)n, s);
}

/* Reads the initializer at t ('{') of the array `name` of this role (ROLE_NONE: skipped, its
 * name noted in d->ignored). */
static int define_array(verify_doc *d, rd *r, tok *t, const tok *name, int role, c_arrays *a)
{
    if (role == ROLE_NONE) {
        note_ignored(d, r->s + name->at, name->len);
        return PTP_OK; /* the braces are skipped as any others */
    }
    if (a->line[role])
        return fail_at(r, name->line, "a second %s array (the first is on line %d): verify "
                                      "reads one table", role_names[role], a->line[role]);
    a->line[role] = name->line;
    if (role == ROLE_IDX)
        name_degree(d, r->s + name->at, name->len, name->line);
    if (role == ROLE_IDX || role == VERIFY_SCHED_IDX)
        return read_rows(r, t, &a->v[role], name->line);
    return read_weights(r, t, &a->v[role], name->line, role_names[role]);
}

/* Moves the arrays read into d, or fails when the table is not there or does not add up. */
static int finish_c(verify_doc *d, rd *r, c_arrays *a)
{
    size_t x, k;
    vec *rows = &a->v[ROLE_IDX], *wgts = &a->v[ROLE_WGT];
    if (!a->line[ROLE_IDX] && d->nfunctions)
        return fail_at(r, d->function_line, "functions but no table arrays: verify checks "
                       "tables (idx and wgt arrays, or ptpgen json); straight-line code, such as "
                       "ptpgen's C header, cannot be checked from its text: run it on the test "
                       "vectors of `ptpgen vectors --format c` instead");
    if (!a->line[ROLE_IDX])
        return fail_at(r, 1, "no table: expected C arrays idx[][4] = {{plane, j, k, l}, ...} and "
                             "wgt[] (or names ending in _idx, _wgt), or a ptpgen JSON document");
    if (!a->line[ROLE_WGT])
        return fail_at(r, a->line[ROLE_IDX], "the idx array has no wgt array (named wgt or "
                                             "ending in _wgt)");
    if (rows->n != wgts->n)
        return fail_at(r, a->line[ROLE_WGT], "the wgt array has %zu weights but the idx array "
                       "(line %d) has %zu rows", wgts->n, a->line[ROLE_IDX], rows->n);
    d->terms = rows->v;
    d->nterms = rows->n;
    rows->v = NULL;
    for (x = 0; x < d->nterms; x++) {
        const verify_term *w = (const verify_term *)wgts->v + x;
        d->terms[x].w = w->w;
        d->terms[x].wline = w->line;
    }
    for (k = 0; k < VERIFY_NARRAYS; k++) {
        d->arr[k].e = a->v[k].v;
        d->arr[k].n = a->v[k].n;
        d->arr[k].line = a->line[k];
        a->v[k].v = NULL;
    }
    return PTP_OK;
}

/* Reads C source: the one idx and the one wgt array declared with an initializer, the other
 * arrays of c_arrays, the DENOM and THREADS macros; notes unknown arrays and functions. */
static int parse_c(verify_doc *d, rd *r)
{
    c_arrays a;
    int st, open_line = 0, after_paren = 0, k;
    size_t depth = 0; /* braces open outside the arrays, the first from open_line */
    tok t, name;
    memset(&a, 0, sizeof a);
    d->c_source = 1;
    r->doc = d;
    st = lex(r, &t);
    while (!st && t.kind != T_END) {
        int role;
        if (t.kind != T_ID) {
            if (is_punct(r, &t, '{') && !depth && after_paren && !d->nfunctions++)
                d->function_line = t.line;
            if (is_punct(r, &t, '{') && !depth++)
                open_line = t.line;
            depth -= depth && is_punct(r, &t, '}');
            after_paren = is_punct(r, &t, ')');
            st = lex(r, &t);
            continue;
        }
        after_paren = 0;
        name = t;
        if ((st = lex(r, &t)) || !is_punct(r, &t, '['))
            continue;
        role = role_of(r, &name);
        while (!st && is_punct(r, &t, '['))
            st = skip_brackets(r, &t);
        if (st || !is_punct(r, &t, '=') || (st = lex(r, &t)) || !is_punct(r, &t, '{'))
            continue; /* a use like idx[x][0], not a definition */
        st = define_array(d, r, &t, &name, role, &a);
    }
    if (!st && depth)
        st = fail_at(r, open_line, "the '{' of this line is never closed: is the file cut short?");
    if (!st)
        st = finish_c(d, r, &a);
    for (k = 0; k < ROLE_NONE; k++)
        free(a.v[k].v);
    return st;
}

/* ---- JSON ---- */

static void json_ws(rd *r)
{
    int c;
    while ((c = at(r, r->pos)) == ' ' || c == '\t' || c == '\r' || c == '\n') {
        if (c == '\n')
            newline(r);
        r->pos++;
    }
}

/* Reads past the character c (after blanks), or fails naming the context. */
static int json_expect(rd *r, char c, const char *context)
{
    char buf[32];
    json_ws(r);
    if (at(r, r->pos) != c)
        return fail_at(r, r->line, "expected '%c' %s, found '%s'", c, context,
                       excerpt(buf, r->s + r->pos, r->pos < r->len ? 1 : 0));
    r->pos++;
    return PTP_OK;
}

/* Steps over the opening bracket at pos and the white space after it; 1 when close follows (the
 * container is empty: close is consumed too), else 0. */
static int json_open(rd *r, char close)
{
    r->pos++;
    json_ws(r);
    if (at(r, r->pos) != close)
        return 0;
    r->pos++;
    return 1;
}

/* After an element: consumes close (*done = 1) or a ',' (*done = 0); anything else fails, the
 * message naming context. */
static int json_next(rd *r, char close, const char *context, int *done)
{
    json_ws(r);
    *done = at(r, r->pos) == close;
    if (!*done)
        return json_expect(r, ',', context);
    r->pos++;
    return PTP_OK;
}

/* Reads the string at pos ('"'), decoding into buf (cap bytes, NUL-terminated, truncated;
 * escapes of non-ASCII characters decode to 0xFF); *n is the full decoded length. */
static int json_string(rd *r, char *buf, size_t cap, size_t *n)
{
    int line = r->line, c, k;
    *n = 0;
    for (r->pos++; (c = at(r, r->pos)) != '"'; r->pos++) {
        if (c < 0)
            return fail_at(r, line, "unterminated string");
        if (c < 0x20)
            return fail_at(r, r->line, "a control character in a string");
        if (c == '\\') {
            c = at(r, ++r->pos);
            if (c == 'u') {
                int u = 0;
                for (k = 1; k <= 4; k++) {
                    int v = digit_value(at(r, r->pos + (size_t)k));
                    if (v > 15)
                        return fail_at(r, r->line, "a bad \\u escape in a string");
                    u = u * 16 + v;
                }
                r->pos += 4;
                c = u < 0x80 ? u : 0xFF;
            } else if (in_set(c, "\"\\/bfnrt")) {
                c = c == 'b' ? '\b' : c == 'f' ? '\f' : c == 'n' ? '\n' : c == 'r' ? '\r' : c == 't' ? '\t' : c;
            } else {
                return fail_at(r, r->line, "a bad escape in a string");
            }
        }
        if (*n + 1 < cap)
            buf[*n] = (char)c;
        ++*n;
    }
    r->pos++;
    buf[*n < cap ? *n : cap - 1] = '\0';
    return PTP_OK;
}

/* Reads the number at pos (JSON grammar): sets *start, *len and *integer (no fraction, no
 * exponent, no sign). */
static int json_number(rd *r, size_t *start, size_t *len, int *integer)
{
    size_t p = r->pos;
    *start = p;
    *integer = 1;
    if (at(r, p) == '-')
        p++, *integer = 0;
    if (at(r, p) == '0')
        p++;
    else if (is_digit(at(r, p)))
        while (is_digit(at(r, p)))
            p++;
    else
        return fail_at(r, r->line, "a bad number");
    if (at(r, p) == '.') {
        if (!is_digit(at(r, ++p)))
            return fail_at(r, r->line, "a bad number");
        while (is_digit(at(r, p)))
            p++;
        *integer = 0;
    }
    if (at(r, p) == 'e' || at(r, p) == 'E') {
        p++;
        if (at(r, p) == '+' || at(r, p) == '-')
            p++;
        if (!is_digit(at(r, p)))
            return fail_at(r, r->line, "a bad number");
        while (is_digit(at(r, p)))
            p++;
        *integer = 0;
    }
    *len = p - *start;
    r->pos = p;
    return PTP_OK;
}

/* Reads a non-negative integer no larger than max, named what. */
static int json_int(rd *r, int *v, int max, const char *what)
{
    size_t start, len;
    int integer, st, dummy;
    verify_weight w;
    char buf[32];
    json_ws(r);
    if (!is_digit(at(r, r->pos)) && at(r, r->pos) != '-')
        return fail_at(r, r->line, "expected %s, found '%s'", what,
                       excerpt(buf, r->s + r->pos, r->pos < r->len ? 1 : 0));
    if ((st = json_number(r, &start, &len, &integer)))
        return st;
    if (!integer)
        return fail_at(r, r->line, "%s must be a non-negative integer, not %s", what,
                       excerpt(buf, r->s + start, len));
    if (number(&w, &dummy, r->s + start, len) == 2 || !w.exact || w.r.num > max)
        return fail_at(r, r->line, "%s %s out of range", what, excerpt(buf, r->s + start, len));
    *v = (int)w.r.num;
    return PTP_OK;
}

/* Skips any JSON value at pos. */
static int json_skip(rd *r, int depth)
{
    static const char *const words[] = {"true", "false", "null"};
    int c, st, k, integer;
    size_t start, len, n;
    char buf[32];
    json_ws(r);
    c = at(r, r->pos);
    if (depth > MAX_DEPTH)
        return fail_at(r, r->line, "JSON nested too deeply (over %d levels)", MAX_DEPTH);
    if (c == '"')
        return json_string(r, buf, sizeof buf, &n);
    if (c == '-' || is_digit(c))
        return json_number(r, &start, &len, &integer);
    if (c == '[' || c == '{') {
        char close = c == '[' ? ']' : '}';
        int done;
        if (json_open(r, close))
            return PTP_OK;
        for (;;) {
            if (close == '}') {
                json_ws(r);
                if (at(r, r->pos) != '"')
                    return fail_at(r, r->line, "expected a key string in an object");
                if ((st = json_string(r, buf, sizeof buf, &n)) ||
                    (st = json_expect(r, ':', "after a key")))
                    return st;
            }
            if ((st = json_skip(r, depth + 1)) ||
                (st = json_next(r, close,
                                close == ']' ? "or ']' in an array" : "or '}' in an object",
                                &done)) ||
                done)
                return st;
        }
    }
    for (k = 0; k < 3; k++)
        if (r->len - r->pos >= strlen(words[k]) && !memcmp(r->s + r->pos, words[k], strlen(words[k]))) {
            r->pos += strlen(words[k]);
            return PTP_OK;
        }
    return fail_at(r, r->line, "expected a JSON value, found '%s'",
                   excerpt(buf, r->s + r->pos, r->pos < r->len ? 1 : 0));
}

/* Reads a weight: a string "p/q", "p" (or any weight the C arrays take), or a number. */
static int json_weight(rd *r, verify_weight *w)
{
    char buf[MAX_WEIGHT_STRING + 1], ex[32];
    size_t n, start, len;
    int st, integer;
    json_ws(r);
    if (at(r, r->pos) == '"') {
        int line = r->line;
        rd sub;
        tok t;
        if ((st = json_string(r, buf, sizeof buf, &n)))
            return st;
        if (n > MAX_WEIGHT_STRING)
            return fail_at(r, line, "weight string too long");
        sub = *r;
        sub.s = buf;
        sub.len = n;
        sub.pos = 0;
        sub.line = line;
        sub.bol = 0;
        if ((st = lex(&sub, &t)) || (st = weight(&sub, &t, w)))
            return st;
        if (t.kind != T_END)
            return fail_at(r, line, "weight \"%s\" is not a number or a fraction p/q",
                           excerpt(ex, buf, n));
        return PTP_OK;
    }
    if (at(r, r->pos) != '-' && !is_digit(at(r, r->pos)))
        return fail_at(r, r->line, "a weight must be a string \"p/q\" or a number, found '%s'",
                       excerpt(ex, r->s + r->pos, r->pos < r->len ? 1 : 0));
    if ((st = json_number(r, &start, &len, &integer)))
        return st;
    n = r->s[start] == '-';
    if (number(w, &integer, r->s + start + n, len - n))
        return fail_at(r, r->line, "number too long (over %d characters)", MAX_LITERAL);
    if (!isfinite(w->d))
        return fail_at(r, r->line, "weight out of range");
    if (n)
        weight_neg(w);
    return PTP_OK;
}

/* Reads the terms array at pos ('['): [plane, j, k, l, weight] each. */
static int json_terms(rd *r, vec *terms)
{
    static const char *const what[] = {"the plane", "point j", "point k", "point l"};
    int st, q, v[4], done;
    verify_term *e = NULL;
    if (json_open(r, ']'))
        return PTP_OK;
    for (;;) {
        int line;
        json_ws(r);
        line = r->line;
        if (at(r, r->pos) != '[')
            return fail_at(r, line, "a term must be an array [plane, j, k, l, weight]");
        r->pos++;
        for (q = 0; q < 4; q++)
            if ((st = json_int(r, &v[q], VERIFY_MAX_INDEX, what[q])) ||
                (st = json_expect(r, ',', "in a term [plane, j, k, l, weight]")))
                return st;
        if ((st = vec_push(terms, sizeof *e, (void **)&e, r)) || (st = json_weight(r, &e->w)) ||
            (st = json_expect(r, ']', "closing a term [plane, j, k, l, weight]")))
            return st;
        e->line = e->wline = line;
        e->plane = v[0];
        for (q = 0; q < 3; q++)
            e->p[q] = v[q + 1];
        if ((st = json_next(r, ']', "or ']' after a term", &done)) || done)
            return st;
    }
}

/* Reads the value of "degree" ([n, m], or one number d for a triangle) into d. */
static int json_degree(verify_doc *d, rd *r)
{
    int st;
    d->degree_line = r->line;
    d->degree_named = 1;
    if (at(r, r->pos) != '[') {
        d->degree_one = 1;
        if (!(st = json_int(r, &d->n, PTP_MAX_TRI_DEGREE, "the degree")) && d->n < 1)
            st = fail_at(r, d->degree_line, "\"degree\" must be at least 1");
        d->m = d->n;
        return st;
    }
    if (!(st = json_expect(r, '[', "opening \"degree\": [n, m]")) &&
        !(st = json_int(r, &d->n, PTP_MAX_DEGREE, "the degree n")) &&
        !(st = json_expect(r, ',', "in \"degree\": [n, m]")) &&
        !(st = json_int(r, &d->m, PTP_MAX_DEGREE, "the degree m")) &&
        !(st = json_expect(r, ']', "closing \"degree\": [n, m]")) && (d->n < 1 || d->m < 1))
        st = fail_at(r, d->degree_line, "\"degree\" must be [n, m] with 1 <= n, m <= %d",
                     PTP_MAX_DEGREE);
    return st;
}

/* Reads the value of "domain" ("quad" or "triangle") into d; the key was on line kline. */
static int json_domain(verify_doc *d, rd *r, int kline)
{
    char v[16];
    size_t n;
    int st = json_string(r, v, sizeof v, &n);
    if (st)
        return st;
    if (strcmp(v, tp_kind_name(TP_QUAD)) && strcmp(v, tp_kind_name(TP_TRI)))
        return fail_at(r, kline, "\"domain\": \"%s\": expected \"%s\" or \"%s\"", v,
                       tp_kind_name(TP_QUAD), tp_kind_name(TP_TRI));
    d->kind = strcmp(v, tp_kind_name(TP_TRI)) ? TP_QUAD : TP_TRI;
    d->kind_named = 1;
    d->kind_line = kline;
    return PTP_OK;
}

/* Fails when the "degree" does not take the form of the "domain": one number for a triangle,
 * [n, m] for a quad. */
static int json_degree_form(const verify_doc *d, rd *r)
{
    if (d->degree_named != 1 || d->degree_one == (d->kind == TP_TRI))
        return PTP_OK;
    if (d->kind == TP_TRI)
        return fail_at(r, d->degree_line, "\"degree\" of a triangle (\"domain\": \"triangle\", "
                                          "line %d) is one number d, not [n, m]", d->kind_line);
    return fail_at(r, d->degree_line, "\"degree\": %d, one number, is a triangle's degree: say "
                                      "\"domain\": \"triangle\" (a quad's is [n, m])", d->n);
}

/* Reads one member "key": value of the document object at pos ('"'); seen[0], seen[1] and
 * seen[2] count the "terms", "degree" and "domain" members so far. Other keys are skipped and noted in d. */
static int json_member(verify_doc *d, rd *r, vec *terms, int *seen)
{
    int st, kline = r->line;
    char key[16];
    size_t n;
    if (at(r, r->pos) != '"')
        return fail_at(r, kline, "expected a key string in the object");
    if ((st = json_string(r, key, sizeof key, &n)) || (st = json_expect(r, ':', "after a key")))
        return st;
    json_ws(r);
    if (n == 5 && !strcmp(key, "terms")) {
        if (seen[0]++)
            return fail_at(r, kline, "a second \"terms\"");
        if (at(r, r->pos) != '[')
            return fail_at(r, r->line, "\"terms\" must be an array");
        return json_terms(r, terms);
    }
    if (n == 6 && !strcmp(key, "degree"))
        return seen[1]++ ? fail_at(r, kline, "a second \"degree\"") : json_degree(d, r);
    if (n == 6 && !strcmp(key, "domain")) /* ptpgen's json names the domain only for triangles */
        return seen[2]++ ? fail_at(r, kline, "a second \"domain\"") : json_domain(d, r, kline);
    if (strcmp(key, "format") && strcmp(key, "generator") && strcmp(key, "command"))
        note_ignored(d, key, strlen(key));
    return json_skip(r, 1);
}

/* Reads the document object at pos ('{'). */
static int json_object(verify_doc *d, rd *r, vec *terms, int *seen)
{
    int st, done;
    if (json_open(r, '}'))
        return PTP_OK;
    for (;;) {
        json_ws(r);
        if ((st = json_member(d, r, terms, seen)) ||
            (st = json_next(r, '}', "or '}' in the object", &done)) || done)
            return st;
    }
}

/* Reads a JSON document: an object with "terms" (and maybe "degree"), or the terms array. */
static int parse_json(verify_doc *d, rd *r)
{
    vec terms = {NULL, 0, 0};
    int st, seen[3] = {0, 0, 0}, line;
    json_ws(r);
    line = r->line;
    if (at(r, r->pos) == '[') {
        seen[0] = 1;
        st = json_terms(r, &terms);
    } else if (at(r, r->pos) != '{') {
        st = fail_at(r, line, "expected a JSON document");
    } else {
        st = json_object(d, r, &terms, seen);
    }
    if (!st && !seen[0])
        st = fail_at(r, line, "the JSON document has no \"terms\" array");
    if (!st)
        st = json_degree_form(d, r);
    if (!st) {
        json_ws(r);
        if (r->pos < r->len)
            st = fail_at(r, r->line, "text after the end of the JSON document");
    }
    d->terms = terms.v;
    d->nterms = terms.n;
    return st;
}

/* ---- the document ---- */

int verify_parse(verify_doc *d, const char *text, size_t len, const char *name, ptp_error *err)
{
    rd r;
    size_t p;
    int st;
    memset(d, 0, sizeof *d);
    r.s = text;
    r.len = len;
    r.pos = len >= 3 && !memcmp(text, "\xEF\xBB\xBF", 3) ? 3 : 0; /* a UTF-8 byte order mark */
    r.line = 1;
    r.bol = 1;
    r.name = name;
    r.err = err;
    r.doc = NULL;
    for (p = r.pos; p < len && in_set(text[p], " \t\r\n\f\v"); p++)
        ;
    if (p == len)
        return fail_at(&r, 1, "empty: no table");
    st = text[p] == '{' || text[p] == '[' ? parse_json(d, &r) : parse_c(d, &r);
    if (st)
        verify_doc_clear(d);
    return st;
}

const char *verify_weight_str(char *buf, const verify_weight *w)
{
    if (w->exact)
        return rat_get_str(buf, &w->r);
    snprintf(buf, RAT_STRLEN + 32, "%.9g", w->d);
    return buf;
}

void verify_doc_clear(verify_doc *d)
{
    int k;
    for (k = 0; k < VERIFY_NARRAYS; k++) {
        free(d->arr[k].e);
        d->arr[k].e = NULL;
        d->arr[k].n = 0;
    }
    free(d->terms);
    d->terms = NULL;
    d->nterms = 0;
}

int verify_doc_fit(int *a, int *b, const verify_doc *d, tp_kind kind)
{
    int planes = 0, points = 0, q, max = kind == TP_TRI ? PTP_MAX_TRI_DEGREE : PTP_MAX_DEGREE;
    tp_domain dom;
    size_t x;
    for (x = 0; x < d->nterms; x++) {
        const verify_term *e = &d->terms[x];
        planes = e->plane + 1 > planes ? e->plane + 1 : planes;
        for (q = 0; q < 3; q++)
            points = e->p[q] + 1 > points ? e->p[q] + 1 : points;
    }
    for (*a = 1; *a <= max; ++*a)
        for (*b = *a; *b <= (kind == TP_TRI ? *a : max); ++*b)
            if (!tp_domain_init(&dom, kind, *a, *b, NULL) && dom.npoints == points &&
                dom.nplanes == planes)
                return 1;
    return 0;
}

const char *verify_degree_name(char *buf, tp_kind kind, int a, int b)
{
    tp_domain dom = {kind, a, b, 0, 0, 0, 0};
    tp_domain_text x;
    tp_domain_text_get(&x, &dom);
    snprintf(buf, 32, "%s", x.name);
    return buf;
}

/* The kind to check d as: kind0 when not negative (PTP_EUSAGE when d names another), else the
 * one d names, else quad unless only a triangle's numbers of points and planes fit its indices. */
static int doc_kind(tp_kind *kind, const verify_doc *d, int kind0, rd *r)
{
    int a, b;
    *kind = kind0 >= 0 ? (tp_kind)kind0 : d->kind;
    if (kind0 < 0 && !d->kind_named && !verify_doc_fit(&a, &b, d, TP_QUAD) &&
        verify_doc_fit(&a, &b, d, TP_TRI))
        *kind = TP_TRI;
    if (kind0 >= 0 && d->kind_named && d->kind != *kind)
        return fail_at(r, d->kind_line, "the %s names --domain %s, not %s", d->kind_named == 1 ?
                       "document" : "array name", tp_kind_name(d->kind), tp_kind_name(*kind));
    return PTP_OK;
}

/* Sets *n, *m to the degrees of the kind to check d against (verify_doc_domain's rules). */
static int doc_degree(int *n, int *m, const verify_doc *d, tp_kind kind, int n0, int m0, rd *r)
{
    int a, b, fit = verify_doc_fit(&a, &b, d, kind), line = d->nterms ? d->terms[0].line : 1;
    const char *w = kind == TP_TRI ? "degree" : "bidegree", *arg = kind == TP_TRI ? "N" : "NxM";
    char named[32], fits[32];
    if (kind == TP_TRI && n0 != m0)
        return fail_at(r, line, "--degree %dx%d: a triangle has one degree; use --degree N", n0, m0);
    if (n0 || m0 || d->degree_named == 1 ||
        (d->degree_named == 2 && (!fit || (a == d->n && b == d->m) || (a == d->m && b == d->n)))) {
        *n = n0 || m0 ? n0 : d->n;
        *m = n0 || m0 ? m0 : d->m;
        return PTP_OK;
    }
    if (d->degree_named == 2)
        return fail_at(r, d->degree_line, "the array name says %s but the indices fit %s; use "
                       "--degree %s", verify_degree_name(named, kind, d->n, d->m),
                       verify_degree_name(fits, kind, a, b) + strlen(w) + 1, arg);
    if (!d->nterms)
        return fail_at(r, line, "the table has no terms, so no %s: use --degree %s", w, arg);
    if (!fit)
        return fail_at(r, line, "cannot infer the %s: no %s 1..%d has the numbers of planes and "
                                "points the indices use; use --degree %s", w, w,
                       kind == TP_TRI ? PTP_MAX_TRI_DEGREE : PTP_MAX_DEGREE, arg);
    if (a != b && verify_doc_fit(n, m, d, TP_TRI))
        return fail_at(r, line, "the indices fit bidegree %dx%d and %dx%d, and the triangle of "
                                "degree %d: use --degree NxM, or --domain triangle, to say which",
                       a, b, b, a, *n);
    if (a != b)
        return fail_at(r, line, "the indices fit bidegree %dx%d and %dx%d: use --degree NxM to "
                                "say which", a, b, b, a);
    *n = *m = a;
    return PTP_OK;
}

int verify_doc_domain(tp_domain *dom, const verify_doc *d, int kind0, int n0, int m0,
                      const char *name, ptp_error *err)
{
    rd r = {NULL, 0, 0, 0, 0, NULL, NULL, NULL};
    tp_kind kind;
    int n = 0, m = 0, st;
    r.name = name;
    r.err = err;
    if ((st = doc_kind(&kind, d, kind0, &r)) || (st = doc_degree(&n, &m, d, kind, n0, m0, &r)))
        return st;
    return tp_domain_init(dom, kind, n, m, err);
}
