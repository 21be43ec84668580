/* sched.c: balances the terms of a tangent-plane table over the threads of a patch.
 * Planes are items and threads bins: LPT, pair repartitions, perturbation, branch and bound. */
#include "plan/sched.h"

#include <limits.h>
#include <stdint.h>
#include <stdlib.h>

/* Work caps, counted rather than timed so that the result does not depend on the machine:
 * subset-sum cells for the heuristics, bins visited for the exact search. Each costs a few
 * tens of ms at most; the cases up to 6x6 with power-of-two P need a few ms in all. */
#define HEUR_CELLS 10000000L
#define PACK_STEPS 10000000L

/* A plane and its number of terms. */
typedef struct {
    int count, plane;
} item;

/* The assignment being improved, what R it aims at, and the heuristics' scratch. */
typedef struct {
    int P, nplanes;
    int target;       /* the R sought: no lower R is possible */
    const int *count; /* count[plane] */
    int *owner, *load;
    int *from;        /* from[s] = the pair item that first reached sum s, or -1 */
    int *idx;         /* the planes of the current pair */
    int *stamp;       /* stamp[t] = the split that last changed thread t's planes */
    int splits;       /* splits so far */
    int failed_t;     /* the thread that relieve last failed on, after split failed_at */
    int failed_at;
    long cells;       /* subset-sum cells left */
    uint64_t rng;     /* xorshift64, fixed seed */
} plan;

/* The exact search: do the items fit into P bins of capacity C? */
typedef struct {
    int n, P, C;
    const item *w;    /* the items, largest first */
    const int *suf;   /* suf[i] = w[i].count + ... + w[n-1].count */
    int *load, *bin;  /* load[b]; bin[i] = the bin of item i */
    long steps;       /* bins visited left */
} pack;

/* Largest count first, then lowest plane: a total order, so qsort is deterministic. */
static int by_count(const void *a, const void *b)
{
    const item *x = a, *y = b;
    if (x->count != y->count)
        return x->count > y->count ? -1 : 1;
    return (x->plane > y->plane) - (x->plane < y->plane);
}

/* The largest load; *arg = the first thread that carries it. */
static int max_load(int *arg, const int *load, int P)
{
    int t, m = load[0];
    *arg = 0;
    for (t = 1; t < P; t++)
        if (load[t] > m) {
            m = load[t];
            *arg = t;
        }
    return m;
}

/* A pseudo-random number in 0..n-1. */
static int rand_below(plan *w, int n)
{
    w->rng ^= w->rng << 13;
    w->rng ^= w->rng >> 7;
    w->rng ^= w->rng << 17;
    return (int)(w->rng % (uint64_t)n);
}

/* Longest processing time first: each plane, largest first, to the least loaded thread. */
static void lpt(plan *w, const item *order)
{
    int i, t, b;
    for (t = 0; t < w->P; t++)
        w->load[t] = 0;
    for (i = 0; i < w->nplanes; i++) {
        for (b = 0, t = 1; t < w->P; t++)
            if (w->load[t] < w->load[b])
                b = t;
        w->owner[order[i].plane] = b;
        w->load[b] += order[i].count;
    }
}

/* Gathers the planes of threads a and b into idx and the subset sums of their counts into
 * from; returns the number of planes, or -1 (and no cells left) when the cells would not do. */
static int pair_sums(plan *w, int a, int b)
{
    int k = 0, S = w->load[a] + w->load[b], p, j, s;
    for (p = 0; p < w->nplanes; p++)
        if (w->owner[p] == a || w->owner[p] == b)
            w->idx[k++] = p;
    w->cells -= (long)k * (S + 1) + w->nplanes;
    if (w->cells < 0)
        return -1;
    w->from[0] = 0;
    for (s = 1; s <= S; s++)
        w->from[s] = -1;
    /* Downward, so from[s - c] still holds sums of the items before j. */
    for (j = 0; j < k; j++) {
        int c = w->count[w->idx[j]];
        for (s = S; s >= c && c > 0; s--)
            if (w->from[s] < 0 && w->from[s - c] >= 0)
                w->from[s] = j;
    }
    return k;
}

/* Gives thread a the pair's planes of a subset summing to s (reached in from) and b the rest. */
static void pair_split(plan *w, int a, int b, int k, int s)
{
    int j, S = w->load[a] + w->load[b];
    w->stamp[a] = w->stamp[b] = ++w->splits;
    for (j = 0; j < k; j++)
        w->owner[w->idx[j]] = b;
    w->load[a] = s;
    w->load[b] = S - s;
    for (; s > 0; s -= w->count[w->idx[j]]) {
        j = w->from[s];
        w->owner[w->idx[j]] = a;
    }
}

/* Repartitions thread t, at the maximum M, with another thread so that both end below M;
 * returns 1 when it did. Pairs unchanged since t last failed would fail again. */
static int relieve(plan *w, int t, int M)
{
    int u, k, s, again = t == w->failed_t && w->stamp[t] <= w->failed_at;
    w->cells -= w->P;
    for (u = 0; u < w->P && w->cells > 0; u++) {
        if (u == t || w->load[u] > M - 2 || (again && w->stamp[u] <= w->failed_at))
            continue;
        if ((k = pair_sums(w, t, u)) < 0)
            return 0;
        for (s = (M + w->load[u]) / 2; w->from[s] < 0; s--)
            ;
        if (M + w->load[u] - s < M) {
            pair_split(w, t, u, k, s);
            return 1;
        }
    }
    w->failed_t = t;
    w->failed_at = w->splits;
    return 0;
}

/* Relieves the most loaded thread until R reaches the target, no pair helps or the cells run
 * out; returns R. */
static int improve(plan *w)
{
    int t, M;
    while ((M = max_load(&t, w->load, w->P)) > w->target && relieve(w, t, M))
        ;
    return M;
}

/* A sideways move out of a local optimum: repartitions a random pair at random, both parts
 * at most M. The current split is one choice, so there always is one. */
static void perturb(plan *w, int M)
{
    int a = rand_below(w, w->P), b = rand_below(w, w->P - 1), k, S, s, lo, hi, n = 0;
    if (b >= a)
        b++;
    S = w->load[a] + w->load[b];
    if ((k = pair_sums(w, a, b)) < 0)
        return;
    lo = S > M ? S - M : 0;
    hi = S < M ? S : M;
    for (s = lo; s <= hi; s++)
        n += w->from[s] >= 0;
    for (n = rand_below(w, n), s = lo; w->from[s] < 0 || n-- > 0; s++)
        ;
    pair_split(w, a, b, k, s);
}

/* The first item at or after i with at most r terms (n if none). */
static int first_at_most(const pack *k, int i, int r)
{
    int hi = k->n;
    while (i < hi) {
        int mid = i + (hi - i) / 2;
        if (k->w[mid].count <= r)
            hi = mid;
        else
            i = mid + 1;
    }
    return i;
}

/* Nonzero when the room the items i.. can still use (in each bin, at most the items that
 * fit it) holds them. */
static int room_suffices(const pack *k, int i)
{
    long room = 0;
    int b;
    for (b = 0; b < k->P; b++) {
        int r = k->C - k->load[b], fit = k->suf[first_at_most(k, i, r)];
        room += fit < r ? fit : r;
    }
    return room >= k->suf[i];
}

/* Places items i.. ; v = the load item i-1's bin had before it when the two are equal in
 * size, else C. Returns 1 when all fit, 0 when they cannot, -1 when out of steps.
 * Bins of equal load are interchangeable, so one of each load is tried, fullest first. A run
 * of equal items may fill bins in decreasing order of load, so item i goes to a load at most
 * v or to v + size (item i-1's bin). An exact fit dominates: any other packing swaps into it. */
static int pack_from(pack *k, int i, int v)
{
    int c, b, u, last, r;
    if (i == k->n)
        return 1;
    if ((k->steps -= k->P) < 0)
        return -1;
    if (!room_suffices(k, i))
        return 0;
    c = k->w[i].count;
    for (last = k->C - c + 1;; k->steps -= k->P) {
        for (b = -1, u = 0; u < k->P; u++) {
            int l = k->load[u];
            if (l < last && (l <= v || l == v + c) && (b < 0 || l > k->load[b]))
                b = u;
        }
        if (b < 0)
            return 0;
        last = k->load[b];
        k->load[b] += c;
        k->bin[i] = b;
        r = pack_from(k, i + 1, i + 1 < k->n && k->w[i + 1].count == c ? last : k->C);
        k->load[b] -= c;
        if (r || last == k->C - c)
            return r;
    }
}

/* Tries capacities target..R-1 in turn until one packs or the steps run out, raising the
 * target past each capacity proved too small; a packing replaces w's assignment. Returns the
 * new R. */
static int exact(plan *w, pack *k, int R, long steps)
{
    int C, i, r = 0;
    k->steps = steps;
    for (C = w->target; C < R; C++) {
        k->C = C;
        for (i = 0; i < k->P; i++)
            k->load[i] = 0;
        if ((r = pack_from(k, 0, C)))
            break;
        w->target = C + 1;
    }
    if (r != 1)
        return R;
    for (i = 0; i < k->P; i++)
        w->load[i] = 0;
    for (i = 0; i < k->n; i++) {
        w->owner[k->w[i].plane] = k->bin[i];
        w->load[k->bin[i]] += k->w[i].count;
    }
    return C;
}

/* Checks P and Q against t. */
static int check_args(const tp_table *t, int P, int Q, ptp_error *err)
{
    tp_domain_text x;
    tp_domain_text_get(&x, &t->dom);
    if (P < 1 || P > SCHED_MAX_THREADS)
        return ptp_fail(err, PTP_EUSAGE,
                        "--threads-per-patch %d is out of range: it must be 1 to %d", P,
                        SCHED_MAX_THREADS);
    if (P > t->dom.nplanes)
        return ptp_fail(err, PTP_EUSAGE,
                        "--threads-per-patch %d exceeds the %d planes of %s: a thread without a "
                        "plane would idle",
                        P, t->dom.nplanes, x.name);
    if (Q < 1)
        return ptp_fail(err, PTP_EUSAGE, "--patches-per-block %d must be at least 1", Q);
    if ((long long)P * Q > SCHED_MAX_THREADS)
        return ptp_fail(err, PTP_EUSAGE,
                        "--threads-per-patch %d times --patches-per-block %d is %lld threads per "
                        "block, over the limit of %d",
                        P, Q, (long long)P * Q, SCHED_MAX_THREADS);
    if (t->nterms > INT_MAX)
        return ptp_fail(err, PTP_ELIMIT, "%s has %zu terms, over the limit of %d", x.name,
                        t->nterms, INT_MAX);
    return PTP_OK;
}

/* count[p] = the terms of plane p; fails unless t is sorted by plane. */
static int count_planes(int *count, const tp_table *t, ptp_error *err)
{
    tp_domain_text x;
    size_t i;
    int p;
    tp_domain_text_get(&x, &t->dom);
    for (p = 0; p < t->dom.nplanes; p++)
        count[p] = 0;
    for (i = 0; i < t->nterms; i++) {
        p = t->terms[i].plane;
        if (p < 0 || p >= t->dom.nplanes || (i > 0 && p < t->terms[i - 1].plane))
            return ptp_fail(err, PTP_EINTERNAL, "term %zu of %s: plane %d out of order", i,
                            x.name, p);
        count[p]++;
    }
    return PTP_OK;
}

/* Assigns the planes (w->owner, w->load) and sets s's R, LB and proven. */
static void assign(sched *s, plan *w, pack *k, item *order, int *suf, int N)
{
    int i, R;
    for (i = 0; i < w->nplanes; i++) {
        order[i].count = w->count[i];
        order[i].plane = i;
    }
    qsort(order, (size_t)w->nplanes, sizeof *order, by_count);
    w->target = (N + w->P - 1) / w->P;
    if (order[0].count > w->target)
        w->target = order[0].count;
    s->lower_bound = w->target;
    suf[w->nplanes] = 0;
    for (i = w->nplanes - 1; i >= 0; i--)
        suf[i] = suf[i + 1] + order[i].count;
    k->n = w->nplanes;
    k->P = w->P;
    k->w = order;
    k->suf = suf;
    lpt(w, order);
    R = improve(w);
    /* A short exact search settles most misses, perturbations most of the rest. */
    R = exact(w, k, R, PACK_STEPS / 10);
    while (R > w->target && w->cells > 0) {
        perturb(w, R);
        R = improve(w);
    }
    R = exact(w, k, R, PACK_STEPS);
    s->rounds = R;
    s->proven = R == w->target;
}

/* Gives each thread without a plane the smallest plane of a thread that has two or more (one
 * exists while P <= nplanes), so that padding slots can name a plane of their own thread. The
 * plane holds at most LB <= R terms, so R does not grow; planes has P entries of scratch. */
static void cover_threads(sched *s, const item *order, int *planes)
{
    int th, i, p, from;
    for (th = 0; th < s->threads; th++)
        planes[th] = 0;
    for (p = 0; p < s->nplanes; p++)
        planes[s->owner[p]]++;
    for (th = 0; th < s->threads; th++) {
        if (planes[th])
            continue;
        for (i = s->nplanes - 1; planes[s->owner[order[i].plane]] < 2; i--)
            ;
        p = order[i].plane;
        from = s->owner[p];
        planes[from]--;
        planes[th]++;
        s->load[from] -= order[i].count;
        s->load[th] += order[i].count;
        s->owner[p] = th;
    }
}

/* Lays out each thread's terms round-major; fill has P entries. */
static void fill_slots(sched *s, const tp_table *t, int *fill)
{
    long i, n = (long)s->rounds * s->threads;
    int th;
    for (i = 0; i < n; i++)
        s->slot[i] = -1;
    for (th = 0; th < s->threads; th++)
        fill[th] = 0;
    for (i = 0; i < (long)t->nterms; i++) {
        th = s->owner[t->terms[i].plane];
        s->slot[(long)fill[th]++ * s->threads + th] = i;
    }
}

int sched_build(sched *s, const tp_table *t, int P, int Q, ptp_error *err)
{
    plan w;
    pack k;
    item *order = NULL;
    int *scratch = NULL, st, N, np = t->dom.nplanes;
    s->owner = s->load = NULL;
    s->slot = NULL;
    if ((st = check_args(t, P, Q, err)))
        return st;
    N = (int)t->nterms;
    s->threads = P;
    s->patches = Q;
    s->nplanes = np;
    /* scratch: count, idx, bin, suf (np or np + 1 each), the bins' loads, stamp (P each), from
     * (N + 1) */
    scratch = calloc((size_t)4 * np + 1 + 2 * (size_t)P + N + 1, sizeof *scratch);
    order = malloc((size_t)np * sizeof *order);
    s->owner = malloc((size_t)np * sizeof *s->owner);
    s->load = malloc((size_t)P * sizeof *s->load);
    if (!scratch || !order || !s->owner || !s->load) {
        st = ptp_fail(err, PTP_ENOMEM, "out of memory scheduling %d planes", np);
        goto done;
    }
    if ((st = count_planes(scratch, t, err)))
        goto done;
    w.P = P;
    w.nplanes = np;
    w.count = scratch;
    w.owner = s->owner;
    w.load = s->load;
    w.idx = scratch + np;
    w.stamp = scratch + 4 * np + 1 + P;
    w.from = scratch + 4 * np + 1 + 2 * P;
    w.splits = 0;
    w.failed_t = -1;
    w.failed_at = 0;
    w.cells = HEUR_CELLS;
    w.rng = 0x9E3779B97F4A7C15u;
    k.bin = scratch + 2 * np;
    k.load = scratch + 4 * np + 1;
    assign(s, &w, &k, order, scratch + 3 * np, N);
    cover_threads(s, order, k.load);
    s->slot = malloc(((size_t)s->rounds * P + 1) * sizeof *s->slot);
    if (!s->slot) {
        st = ptp_fail(err, PTP_ENOMEM, "out of memory for %d rounds of %d threads", s->rounds, P);
        goto done;
    }
    fill_slots(s, t, k.load);
done:
    free(order);
    free(scratch);
    if (st)
        sched_clear(s);
    return st;
}

void sched_clear(sched *s)
{
    free(s->owner);
    free(s->load);
    free(s->slot);
    s->owner = s->load = NULL;
    s->slot = NULL;
}

int sched_padding_plane(const sched *s, int th)
{
    int p = 0;
    while (s->owner[p] != th)
        p++;
    return p;
}

int sched_default_threads(const tp_table *t)
{
    long long N = (long long)t->nterms, lb, run = 0, largest = 0;
    size_t i;
    int P, best = 1;
    /* t is sorted by plane, so a plane's terms are one run. */
    for (i = 0; i < t->nterms; i++) {
        run = i > 0 && t->terms[i].plane == t->terms[i - 1].plane ? run + 1 : 1;
        if (run > largest)
            largest = run;
    }
    for (P = 2; P <= 64 && P <= t->dom.nplanes; P *= 2) {
        lb = (N + P - 1) / P;
        if (lb < largest)
            lb = largest;
        if (100 * N >= 95 * P * lb)
            best = P;
    }
    return best;
}

int sched_default_patches(int P)
{
    return P >= 1 && P < SCHED_BLOCK_THREADS ? SCHED_BLOCK_THREADS / P : 1;
}
