/* test_sched.c: checks the thread schedules of every bidegree up to 6x6 and the argument checks.
 * Also prints, as "# " lines, the table of R, LB and efficiency of every case it checks. */
#include "check.h"
#include "plan/sched.h"
#include "core/tplane.h"

#include <stdlib.h>
#include <string.h>

#define MAXDEG 6

static const int thread_counts[] = {1, 2, 4, 8, 16, 32, 64};
#define NPS ((int)(sizeof thread_counts / sizeof thread_counts[0]))

/* One row of the printed table. */
typedef struct {
    int n, m, P, R, LB, proven, is_default;
    double eff;
} row;

/* The first property s breaks as a schedule of t (count[p] = the terms of plane p), or NULL. */
static const char *violation(const sched *s, const tp_table *t, const int *count)
{
    static char msg[256];
    int P = s->threads, N = (int)t->nterms, p, th, r, lb, maxload = 0, sum = 0, maxcount = 0;
    int *load = calloc((size_t)P, sizeof *load);
    char *seen = calloc(t->nterms, 1);
    msg[0] = 0;
    if (!load || !seen) {
        snprintf(msg, sizeof msg, "out of memory in the test");
        goto done;
    }
    if (s->nplanes != t->dom.nplanes) {
        snprintf(msg, sizeof msg, "nplanes %d, table has %d", s->nplanes, t->dom.nplanes);
        goto done;
    }
    for (p = 0; p < t->dom.nplanes; p++) {
        if (s->owner[p] < 0 || s->owner[p] >= P) {
            snprintf(msg, sizeof msg, "plane %d has owner %d", p, s->owner[p]);
            goto done;
        }
        load[s->owner[p]] += count[p];
        if (count[p] > maxcount)
            maxcount = count[p];
    }
    for (th = 0; th < P; th++) {
        if (load[th] == 0) {
            snprintf(msg, sizeof msg, "thread %d owns no plane (its padding would have none)", th);
            goto done;
        }
        if (load[th] != s->load[th]) {
            snprintf(msg, sizeof msg, "thread %d: load %d, its planes hold %d", th, s->load[th],
                     load[th]);
            goto done;
        }
        sum += load[th];
        if (load[th] > maxload)
            maxload = load[th];
    }
    lb = (N + P - 1) / P > maxcount ? (N + P - 1) / P : maxcount;
    if (sum != N || s->rounds != maxload || s->lower_bound != lb || s->rounds < lb ||
        (s->rounds == lb && !s->proven)) {
        snprintf(msg, sizeof msg,
                 "loads sum %d of %d, R %d, max load %d, LB %d (expected %d), proven %d", sum, N,
                 s->rounds, maxload, s->lower_bound, lb, s->proven);
        goto done;
    }
    for (th = 0; th < P; th++)
        for (r = 0; r < s->rounds; r++) {
            long x = s->slot[(long)r * P + th], prev = r ? s->slot[(long)(r - 1) * P + th] : -1;
            if (r >= load[th]) {
                if (x != -1) {
                    snprintf(msg, sizeof msg, "thread %d round %d: %ld instead of padding", th,
                             r, x);
                    goto done;
                }
                continue;
            }
            if (x < 0 || x >= N || seen[x]) {
                snprintf(msg, sizeof msg, "thread %d round %d: term %ld out of range or repeated",
                         th, r, x);
                goto done;
            }
            seen[x] = 1;
            if (s->owner[t->terms[x].plane] != th) {
                snprintf(msg, sizeof msg, "thread %d round %d: term %ld of plane %d of thread %d",
                         th, r, x, t->terms[x].plane, s->owner[t->terms[x].plane]);
                goto done;
            }
            if (prev >= 0 && (t->terms[prev].plane > t->terms[x].plane ||
                              (t->terms[prev].plane == t->terms[x].plane && prev > x))) {
                snprintf(msg, sizeof msg, "thread %d round %d: term %ld after term %ld", th, r, x,
                         prev);
                goto done;
            }
        }
done:
    free(load);
    free(seen);
    return msg[0] ? msg : NULL;
}

/* An independent plain search: 1 when the items w (largest first) fit P bins of capacity C,
 * 0 when they cannot, -1 when the nodes run out. Each bin load is tried once per item. */
static int fits(int *load, const int *w, int n, int P, int C, int i, long rest, long *nodes)
{
    int b, u, r;
    long room = 0;
    if (i == n)
        return 1;
    if (--*nodes < 0)
        return -1;
    for (b = 0; b < P; b++)
        if (C - load[b] >= w[n - 1])
            room += C - load[b];
    if (room < rest)
        return 0;
    for (b = 0; b < P; b++) {
        for (u = 0; u < b && load[u] != load[b]; u++)
            ;
        if (u < b || load[b] + w[i] > C)
            continue;
        load[b] += w[i];
        r = fits(load, w, n, P, C, i + 1, rest - w[i], nodes);
        load[b] -= w[i];
        if (r)
            return r;
    }
    return 0;
}

static int by_size(const void *a, const void *b)
{
    int x = *(const int *)a, y = *(const int *)b;
    return (x < y) - (x > y);
}

/* Whether t's planes fit P threads of C terms each, by the independent search. */
static int fits_plain(const tp_table *t, const int *count, int P, int C)
{
    int *w = malloc((size_t)t->dom.nplanes * sizeof *w), *load = calloc((size_t)P, sizeof *load), r;
    long nodes = 2000000;
    if (!w || !load) {
        free(w);
        free(load);
        return -1;
    }
    memcpy(w, count, (size_t)t->dom.nplanes * sizeof *w);
    qsort(w, (size_t)t->dom.nplanes, sizeof *w, by_size);
    r = fits(load, w, t->dom.nplanes, P, C, 0, (long)t->nterms, &nodes);
    free(w);
    free(load);
    return r;
}

/* Schedules t with P threads (default Q); a failure message in *why, or NULL. */
static int build_checked(sched *s, const tp_table *t, const int *count, int P, const char **why)
{
    static char msg[600];
    ptp_error err;
    int st = sched_build(s, t, P, sched_default_patches(P), &err);
    *why = NULL;
    if (st) {
        snprintf(msg, sizeof msg, "status %d: %s", st, err.msg);
        *why = msg;
        return st;
    }
    if (s->threads != P || s->patches != sched_default_patches(P))
        *why = "threads or patches not as asked";
    else
        *why = violation(s, t, count);
    return st;
}

/* Every P in thread_counts for every bidegree up to MAXDEG: valid, R == LB. */
static void check_matrix(row *rows, int *nrows)
{
    int n, m, i, gaps = 0, unproven = 0;
    for (n = 1; n <= MAXDEG; n++)
        for (m = 1; m <= MAXDEG; m++) {
            tp_table t;
            ptp_error err;
            int *count, def;
            if (tp_derive(&t, n, m, &err)) {
                check(0, "derive for the schedule tests", "%dx%d: %s", n, m, err.msg);
                continue;
            }
            count = malloc((size_t)t.dom.nplanes * sizeof *count);
            tp_plane_counts(count, &t);
            def = sched_default_threads(&t);
            for (i = 0; i < NPS; i++) {
                int P = thread_counts[i];
                sched s;
                const char *why;
                char name[96];
                row *x = &rows[*nrows];
                if (P > t.dom.nplanes)
                    continue;
                snprintf(name, sizeof name,
                         "schedule %dx%d with %d threads: valid, R == LB", n, m, P);
                if (build_checked(&s, &t, count, P, &why)) {
                    check(0, name, "%s", why);
                    continue;
                }
                x->n = n;
                x->m = m;
                x->P = P;
                x->R = s.rounds;
                x->LB = s.lower_bound;
                x->proven = s.proven;
                x->is_default = P == def;
                x->eff = (double)t.nterms / ((double)s.rounds * P);
                (*nrows)++;
                gaps += s.rounds > s.lower_bound;
                unproven += !s.proven;
                check(!why && s.rounds == s.lower_bound, name, "%s; R %d, LB %d, proven %d",
                      why ? why : "valid", s.rounds, s.lower_bound, s.proven);
                sched_clear(&s);
            }
            free(count);
            tp_clear(&t);
        }
    printf("# %d cases, %d with R > LB (%d unproven)\n", *nrows, gaps, unproven);
}

/* Every P from 1 to nplanes for the bidegrees of at most 40 planes: valid, and every
 * R > LB checked against the independent search (a proven R must admit no packing at R-1). */
static void check_every_p(void)
{
    int n, m, P, gaps = 0, verified = 0, unverified = 0;
    for (n = 1; n <= MAXDEG; n++)
        for (m = 1; m <= MAXDEG; m++) {
            tp_table t;
            ptp_error err;
            int *count;
            char name[96], bad[256] = "";
            if (tp_derive(&t, n, m, &err)) {
                check(0, "derive for the schedule tests", "%dx%d: %s", n, m, err.msg);
                continue;
            }
            if (t.dom.nplanes > 40) {
                tp_clear(&t);
                continue;
            }
            count = malloc((size_t)t.dom.nplanes * sizeof *count);
            tp_plane_counts(count, &t);
            for (P = 1; P <= t.dom.nplanes && !bad[0]; P++) {
                sched s;
                const char *why;
                int r;
                if (build_checked(&s, &t, count, P, &why)) {
                    snprintf(bad, sizeof bad, "P=%d: %s", P, why);
                    break;
                }
                if (why)
                    snprintf(bad, sizeof bad, "P=%d: %s", P, why);
                else if (s.rounds > s.lower_bound) {
                    gaps++;
                    r = fits_plain(&t, count, P, s.rounds - 1);
                    if (r == 1 && s.proven)
                        snprintf(bad, sizeof bad, "P=%d: R %d claimed optimal, but %d fits", P,
                                 s.rounds, s.rounds - 1);
                    verified += r == 0;
                    unverified += r != 0;
                    printf("# %dx%d P=%d: R %d > LB %d, proven %d, independent search at R-1: %s\n",
                           n, m, P, s.rounds, s.lower_bound, s.proven,
                           r == 0 ? "no packing" : r == 1 ? "packs" : "out of nodes");
                }
                sched_clear(&s);
            }
            snprintf(name, sizeof name, "schedule %dx%d with every P from 1 to %d", n, m,
                     t.dom.nplanes);
            check(!bad[0], name, "%s", bad);
            free(count);
            tp_clear(&t);
        }
    printf("# every P, bidegrees of at most 40 planes: %d with R > LB, %d verified optimal, %d "
           "unverified\n",
           gaps, verified, unverified);
}

/* sched_build(t, P, Q) must fail with PTP_EUSAGE and a one-line message containing needle. */
static void check_usage(const tp_table *t, int P, int Q, const char *needle)
{
    sched s;
    ptp_error err;
    char name[128];
    int st;
    err.status = PTP_OK;
    err.msg[0] = 0;
    st = sched_build(&s, t, P, Q, &err);
    if (!st)
        sched_clear(&s);
    snprintf(name, sizeof name, "%dx%d with P=%d, Q=%d is refused", t->dom.n, t->dom.m, P, Q);
    check(st == PTP_EUSAGE && err.status == PTP_EUSAGE && strstr(err.msg, needle) &&
              !strchr(err.msg, '\n') && strncmp(err.msg, "ptpgen:", 7) != 0,
          name, "status %d, message \"%s\" (wanted \"%s\")", st, err.msg, needle);
}

static void check_bicubic(void)
{
    tp_table t;
    ptp_error err;
    sched a, b;
    int ok;
    if (tp_derive(&t, 3, 3, &err)) {
        check(0, "derive bicubic", "%s", err.msg);
        return;
    }
    ok = !sched_build(&a, &t, 16, 8, &err);
    check(ok && a.rounds == 33 && a.proven, "bicubic with 16 threads takes 33 rounds",
          "R %d, proven %d", ok ? a.rounds : -1, ok ? a.proven : -1);
    if (ok && !sched_build(&b, &t, 16, 8, &err)) {
        check(!memcmp(a.owner, b.owner, 64 * sizeof *a.owner) &&
                  !memcmp(a.slot, b.slot, 33 * 16 * sizeof *a.slot),
              "bicubic schedule is deterministic", "two builds differ");
        sched_clear(&b);
    }
    if (ok)
        sched_clear(&a);
    check(sched_default_threads(&t) == 16 && sched_default_patches(16) == 8,
          "bicubic defaults to 16 threads, 8 patches", "P %d, Q %d", sched_default_threads(&t),
          sched_default_patches(16));
    check(sched_default_patches(1) == 128 && sched_default_patches(64) == 2 &&
              sched_default_patches(128) == 1 && sched_default_patches(1024) == 1,
          "default patches make 128 threads, at least 1 patch", "");
    check_usage(&t, 0, 1, "1 to 1024");
    check_usage(&t, -3, 1, "1 to 1024");
    check_usage(&t, 1025, 1, "1 to 1024");
    check_usage(&t, 65, 1, "exceeds the 64 planes of bidegree 3x3");
    check_usage(&t, 100, 1, "--threads-per-patch 100 exceeds the 64 planes of bidegree 3x3");
    check_usage(&t, 16, 0, "--patches-per-block 0");
    check_usage(&t, 16, -1, "--patches-per-block -1");
    check_usage(&t, 16, 65, "limit of 1024");
    check_usage(&t, 64, 17, "limit of 1024");
    tp_clear(&t);
}

/* The 6x6 case with 64 threads runs the perturbation search: it must be repeatable too. */
static void check_deterministic(void)
{
    tp_table t;
    ptp_error err;
    sched a, b;
    int ok = 0;
    if (tp_derive(&t, 6, 6, &err)) {
        check(0, "derive 6x6", "%s", err.msg);
        return;
    }
    if (!sched_build(&a, &t, 64, 2, &err)) {
        if (!sched_build(&b, &t, 64, 2, &err)) {
            ok = a.rounds == b.rounds &&
                 !memcmp(a.owner, b.owner, (size_t)t.dom.nplanes * sizeof *a.owner) &&
                 !memcmp(a.slot, b.slot, (size_t)a.rounds * 64 * sizeof *a.slot);
            sched_clear(&b);
        }
        sched_clear(&a);
    }
    check(ok, "6x6 schedule with 64 threads is deterministic", "two builds differ");
    tp_clear(&t);
}

/* Prints the table of the matrix and checks the default P of every bidegree. */
static void print_table(const row *rows, int nrows)
{
    int i, bad = 0;
    printf("# bidegree  P      R     LB  efficiency  (* = default P)\n");
    for (i = 0; i < nrows; i++) {
        const row *x = &rows[i];
        printf("# %dx%d %5d %6d %6d  %.3f%s\n", x->n, x->m, x->P, x->R, x->LB, x->eff,
               x->is_default ? " *" : "");
        if (x->is_default && x->eff < 0.95)
            bad++;
    }
    check(!bad, "every default P keeps at least 95% of thread-rounds busy", "%d below", bad);
}

int main(void)
{
    static row rows[MAXDEG * MAXDEG * NPS];
    int nrows = 0;
    check_bicubic();
    check_deterministic();
    check_matrix(rows, &nrows);
    check_every_p();
    print_table(rows, nrows);
    return check_exit();
}
