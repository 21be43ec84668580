/* verify_arrays.c: iwgt, owner and the schedule of a C table checked against idx, wgt and the
 * derivation, and the report's line of what was checked and what was ignored. */
#include "tools/verify_arrays.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Everything the checks share. */
typedef struct {
    sbuf *o;
    const verify_doc *d;
    const char *name;
    size_t problems;
    sbuf checked, ignored; /* ", "-separated lists for the summary line */
} chk;

/* Writes the problem "NAME:LINE: message". */
static void problem(chk *c, int line, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

static void problem(chk *c, int line, const char *fmt, ...)
{
    char msg[512];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    sbuf_printf(c->o, "%s:%d: %s\n", c->name, line, msg);
    c->problems++;
}

/* Appends s to the list l. */
static void list_add(sbuf *l, const char *s)
{
    sbuf_printf(l, "%s%s", l->len ? ", " : "", s);
}

/* The array of role k, or NULL when the document has none. */
static const verify_array *arr(const chk *c, int k)
{
    return c->d->arr[k].line ? &c->d->arr[k] : NULL;
}

/* e is an integer written as a C integer constant expression; sets *v. */
static int int_entry(long *v, const verify_term *e)
{
    if (!e->w.cint || !e->w.exact || e->w.r.den != 1 || e->w.r.num > 1000000000 ||
        e->w.r.num < -1000000000)
        return 0;
    *v = (long)e->w.r.num;
    return 1;
}

/* The weights a and b store the same value: equal when both are exact, else the same float. */
static int same_weight(const verify_weight *a, const verify_weight *b)
{
    if (a->exact && b->exact)
        return rat_equal(&a->r, &b->r);
    return (float)a->d == (float)b->d;
}

/* *q = iwgt / DENOM for the integer entry e; 0 when e is no integer. */
static int iwgt_value(rat *q, const chk *c, const verify_term *e)
{
    long v;
    return int_entry(&v, e) && !rat_set_frac(q, v, c->d->denom.v);
}

/* Checks iwgt entry x against want[x] and wgt[x]; returns 1 when it equals want[x]. */
static int check_iwgt_entry(chk *c, size_t x, const verify_term *e, const rat *want,
                            const char *known)
{
    char a[RAT_STRLEN + 32], b[RAT_STRLEN + 32], w[RAT_STRLEN];
    const verify_term *t = &c->d->terms[x];
    verify_weight q = {0, {0, 1}, 1, 0};
    if (!iwgt_value(&q.r, c, e)) {
        problem(c, e->line, "iwgt[%zu] = %s is not an integer literal of at most 10^9", x,
                verify_weight_str(a, &e->w));
        return 0;
    }
    q.d = rat_get_d(&q.r);
    if (known[x] && !rat_equal(&q.r, &want[x])) {
        problem(c, e->line, "wrong iwgt[%zu]: got %s, so iwgt/DENOM = %s, but the exact weight of "
                            "the term on line %d is %s", x, verify_weight_str(a, &e->w),
                rat_get_str(b, &q.r), t->line, rat_get_str(w, &want[x]));
        return 0;
    }
    if (!same_weight(&q, &t->w)) {
        problem(c, e->line, "iwgt[%zu] / DENOM = %s but wgt[%zu] (line %d) is %s: iwgt must be "
                            "DENOM * wgt", x, rat_get_str(b, &q.r), x, t->wline,
                verify_weight_str(a, &t->w));
        return 0;
    }
    return known[x];
}

/* iwgt == DENOM * the exact weights, and consistent with wgt; sets *exact when every entry is
 * the exact weight. */
static void check_iwgt(chk *c, int *exact, const rat *want, const char *known)
{
    const verify_array *a = arr(c, VERIFY_IWGT);
    char s[64];
    size_t x;
    int all = 1;
    *exact = 0;
    if (!a)
        return;
    if (!c->d->denom.line || c->d->denom.v < 1) {
        list_add(&c->ignored, "iwgt (no DENOM macro of 1 or more to divide it by)");
        return;
    }
    if (a->n != c->d->nterms) {
        problem(c, a->line, "the iwgt array has %zu entries but the idx array has %zu rows", a->n,
                c->d->nterms);
        return;
    }
    for (x = 0; x < a->n; x++)
        all &= check_iwgt_entry(c, x, &a->e[x], want, known);
    *exact = all && a->n;
    snprintf(s, sizeof s, "iwgt with DENOM %ld", c->d->denom.v);
    list_add(&c->checked, s);
}

/* A term's plane and points as written, and its index: the key that slots are matched by. */
typedef struct {
    int k[4];
    size_t x;
} rkey;

static void key_of(rkey *r, const verify_term *e, size_t x)
{
    r->k[0] = e->plane;
    memcpy(r->k + 1, e->p, sizeof e->p);
    r->x = x;
}

static int cmp_key4(const rkey *a, const rkey *b)
{
    int i;
    for (i = 0; i < 4; i++)
        if (a->k[i] != b->k[i])
            return a->k[i] < b->k[i] ? -1 : 1;
    return 0;
}

static int cmp_rkey(const void *pa, const void *pb)
{
    const rkey *a = pa, *b = pb;
    int k = cmp_key4(a, b);
    return k ? k : (a->x > b->x) - (a->x < b->x);
}

/* The first position in by[0..n) (sorted) with the key of e. */
static size_t lower(const rkey *by, size_t n, const rkey *e)
{
    size_t lo = 0, hi = n;
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        if (cmp_key4(&by[mid], e) < 0)
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo;
}

/* The term of slot s: an unused one with its plane, points and weight; or -1, the problem said. */
static long match_slot(chk *c, size_t s, const rkey *by, char *used)
{
    const verify_term *terms = c->d->terms, *e = &c->d->arr[VERIFY_SCHED_IDX].e[s];
    const verify_term *w = &c->d->arr[VERIFY_SCHED_WGT].e[s];
    char a[RAT_STRLEN + 32], b[RAT_STRLEN + 32];
    size_t n = c->d->nterms, k, first, twice = n;
    rkey key;
    key_of(&key, e, 0);
    for (k = first = lower(by, n, &key); k < n && !cmp_key4(&by[k], &key); k++) {
        if (!same_weight(&terms[by[k].x].w, &w->w))
            continue;
        if (!used[by[k].x]) {
            used[by[k].x] = 1;
            return (long)by[k].x;
        }
        twice = by[k].x;
    }
    if (twice < n)
        problem(c, e->line, "sched slot %zu {%d, %d, %d, %d} repeats a slot before it: the term "
                            "(line %d) is scheduled twice", s, e->plane, e->p[0], e->p[1],
                e->p[2], terms[twice].line);
    else if (first == n || cmp_key4(&by[first], &key))
        problem(c, e->line, "sched slot %zu {%d, %d, %d, %d} with weight %s is no term of the idx "
                            "array", s, e->plane, e->p[0], e->p[1], e->p[2],
                verify_weight_str(a, &w->w));
    else
        problem(c, w->line, "sched slot %zu {%d, %d, %d, %d}: weight %s, but the term (line %d) "
                            "has weight %s", s, e->plane, e->p[0], e->p[1], e->p[2],
                verify_weight_str(a, &w->w), terms[by[first].x].line,
                verify_weight_str(b, &terms[by[first].x].w));
    return -1;
}

/* Matches every slot of weight other than 0 to a term (row[s], -1 for padding or none) and
 * names the terms left out. */
static void match_slots(chk *c, long *row, rkey *by, char *used)
{
    const verify_array *si = &c->d->arr[VERIFY_SCHED_IDX], *sw = &c->d->arr[VERIFY_SCHED_WGT];
    size_t x;
    for (x = 0; x < c->d->nterms; x++)
        key_of(&by[x], &c->d->terms[x], x);
    qsort(by, c->d->nterms, sizeof *by, cmp_rkey);
    for (x = 0; x < si->n; x++)
        row[x] = sw->e[x].w.d == 0 ? -1 : match_slot(c, x, by, used);
    for (x = 0; x < c->d->nterms; x++) {
        const verify_term *t = &c->d->terms[x];
        if (!used[x] && t->w.d != 0)
            problem(c, si->line, "the term {%d, %d, %d, %d} of line %d is in no sched slot",
                    t->plane, t->p[0], t->p[1], t->p[2], t->line);
    }
}

/* sched_iwgt[s] / DENOM is the weight of slot s: its term's (row[s]), else its sched_wgt. */
static void check_sched_iwgt(chk *c, const long *row)
{
    const verify_array *a = arr(c, VERIFY_SCHED_IWGT), *sw = &c->d->arr[VERIFY_SCHED_WGT];
    char g[RAT_STRLEN + 32], h[RAT_STRLEN + 32];
    size_t s;
    if (!a)
        return;
    if (!c->d->denom.line || c->d->denom.v < 1) {
        list_add(&c->ignored, "sched_iwgt (no DENOM macro of 1 or more)");
        return;
    }
    if (a->n != sw->n) {
        problem(c, a->line, "sched_iwgt has %zu entries but sched_wgt has %zu", a->n, sw->n);
        return;
    }
    for (s = 0; s < a->n; s++) {
        verify_weight q = {0, {0, 1}, 1, 0};
        const verify_weight *want = row[s] >= 0 ? &c->d->terms[row[s]].w : &sw->e[s].w;
        int ok = iwgt_value(&q.r, c, &a->e[s]);
        q.d = rat_get_d(&q.r);
        if (!ok || !same_weight(&q, want))
            problem(c, a->e[s].line, "wrong sched_iwgt[%zu] = %s: expected DENOM %ld times the "
                                     "slot's weight %s", s, verify_weight_str(g, &a->e[s].w),
                    c->d->denom.v, verify_weight_str(h, want));
    }
}

/* The sched arrays: as long as each other, THREADS dividing them, a permutation of the terms
 * plus padding; *row (the term of each slot, -1 for padding) is left for the owner check. */
static int check_sched(chk *c, long **row, ptp_error *err)
{
    const verify_array *si = arr(c, VERIFY_SCHED_IDX), *sw = arr(c, VERIFY_SCHED_WGT);
    rkey *by;
    char *used, s[96];
    if (!si && !sw)
        return PTP_OK;
    if (!si || !sw || si->n != sw->n) {
        problem(c, si ? si->line : sw->line, !si || !sw ? "a schedule needs both sched_idx and "
                "sched_wgt" : "sched_idx and sched_wgt differ in length");
        return PTP_OK;
    }
    if (c->d->threads.line && c->d->threads.v > 0 && si->n % (size_t)c->d->threads.v)
        problem(c, si->line, "%zu slots are not whole rounds of THREADS = %ld", si->n,
                c->d->threads.v);
    *row = malloc((si->n + 1) * sizeof **row);
    by = malloc((c->d->nterms + 1) * sizeof *by);
    used = calloc(c->d->nterms + 1, 1);
    if (*row && by && used)
        match_slots(c, *row, by, used);
    free(by);
    free(used);
    if (!*row || !by || !used)
        return ptp_fail(err, PTP_ENOMEM, "out of memory checking %s", c->name);
    check_sched_iwgt(c, *row);
    snprintf(s, sizeof s, "sched_idx/sched_wgt%s (%zu slots)", arr(c, VERIFY_SCHED_IWGT) &&
             c->d->denom.line && c->d->denom.v > 0 ? "/sched_iwgt" : "", si->n);
    list_add(&c->checked, s);
    return PTP_OK;
}

/* Every slot's plane is owned by its thread, slot s running on thread s % THREADS. */
static void check_slot_owners(chk *c, const verify_array *ow, int nplanes)
{
    const verify_array *si = arr(c, VERIFY_SCHED_IDX);
    long P = c->d->threads.v, v;
    size_t s;
    for (s = 0; si && s < si->n; s++) {
        int p = si->e[s].plane;
        if (p >= nplanes)
            problem(c, si->e[s].line, "sched slot %zu names plane %d: there are %d planes", s, p,
                    nplanes);
        else if (int_entry(&v, &ow->e[p]) && v != (long)(s % (size_t)P))
            problem(c, si->e[s].line, "sched slot %zu runs on thread %zu but writes plane %d, "
                                      "which owner (line %d) gives to thread %ld", s,
                    s % (size_t)P, p, ow->e[p].line, v);
    }
}

/* owner: one thread 0..THREADS-1 per plane, the thread of every slot that writes the plane. */
static void check_owner(chk *c, int nplanes)
{
    const verify_array *a = arr(c, VERIFY_OWNER);
    long P = c->d->threads.v, v;
    size_t p;
    char s[96];
    if (!a)
        return;
    if (!c->d->threads.line || P < 1) {
        list_add(&c->ignored, "owner (no THREADS macro)");
        return;
    }
    if (a->n != (size_t)nplanes) {
        problem(c, a->line, "owner has %zu entries, not one per plane (%d)", a->n, nplanes);
        return;
    }
    for (p = 0; p < a->n; p++)
        if (!int_entry(&v, &a->e[p]) || v < 0 || v >= P)
            problem(c, a->e[p].line, "owner[%zu] is not a thread 0..%ld", p, P - 1);
    check_slot_owners(c, a, nplanes);
    snprintf(s, sizeof s, "owner (%ld threads%s)", P, arr(c, VERIFY_SCHED_IDX) ? "" :
             "; no schedule to check it against");
    list_add(&c->checked, s);
}

/* The summary: "NAME: checked: ...; ignored: ...". */
static void summary(chk *c)
{
    const verify_doc *d = c->d;
    char s[VERIFY_IGNORED_LEN + 64];
    if (d->ignored[0]) {
        snprintf(s, sizeof s, "%s (%s%s)", d->ignored, d->c_source ? "unknown array" : "JSON key",
                 strchr(d->ignored, ',') ? "s" : "");
        list_add(&c->ignored, s);
    }
    if (d->nfunctions) {
        snprintf(s, sizeof s, "%d function%s from line %d (code cannot be checked from its text: "
                              "run it on the vectors of `ptpgen vectors --format c`)", d->nfunctions,
                 d->nfunctions == 1 ? "" : "s", d->function_line);
        list_add(&c->ignored, s);
    }
    sbuf_printf(c->o, "%s: checked: %s; ignored: %s\n", c->name, c->checked.s,
                c->ignored.len ? c->ignored.s : "nothing");
}

int verify_arrays(sbuf *o, verify_arrays_result *res, const verify_doc *d, const rat *want,
                  const char *known, int nplanes, const char *name, ptp_error *err)
{
    chk c;
    long *row = NULL;
    int st;
    char s[64];
    memset(&c, 0, sizeof c);
    c.o = o;
    c.d = d;
    c.name = name;
    sbuf_init(&c.checked);
    sbuf_init(&c.ignored);
    snprintf(s, sizeof s, "%s (%zu terms)", d->c_source ? "idx, wgt" : "terms", d->nterms);
    list_add(&c.checked, s);
    check_iwgt(&c, &res->iwgt_exact, want, known);
    if (!(st = check_sched(&c, &row, err))) {
        check_owner(&c, nplanes);
        summary(&c);
        if (c.checked.failed || c.ignored.failed)
            st = ptp_fail(err, PTP_ENOMEM, "out of memory checking %s", name);
    }
    res->problems = c.problems;
    free(row);
    sbuf_clear(&c.checked);
    sbuf_clear(&c.ignored);
    return st;
}
