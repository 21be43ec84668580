/* kref.c: test data and the double-precision reference for executing emitted kernels
 * (tests/kref.h).
 *
 * The bound on a float32 evaluation is (terms + 16) * 2^-24 times the sum of |monomials|; exact
 * zeros (a plane along a boundary edge collapsed to one point) have bound 0. */
#include "kref.h"
#include "check.h"
#include "core/i128.h"
#include "bezfile.h"

#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define M_PI_6 0.52359877559829887308 /* 30 degrees: half the field of view */

/* Prints the usage failure as one "not ok" line; returns 2. */
static int usage(const char *host, const char *label, const char *detail)
{
    check(0, label ? label : host,
          "%s; usage: %s [FILE] [--kernel NAME] --degree N M --space clip|world "
          "--rule strict|degenerate [--block-threads PQ --patches-per-block Q] [--planes] "
          "[--groups-x-constant] [--certified] (--random SETS COUNT SEED | "
          "--model PATH NEYES SEED | --exact SETS COUNT SEED | --exact-far SETS COUNT SEED)... "
          "[--eye-radius R] --name LABEL",
          detail, host);
    return 2;
}

/* Parses a decimal integer in [lo, hi] into *out; 0 on success. */
static int parse_ull(const char *s, unsigned long long lo, unsigned long long hi,
                     unsigned long long *out)
{
    char *end;
    unsigned long long v;
    if (!s || *s < '0' || *s > '9')
        return -1;
    errno = 0;
    v = strtoull(s, &end, 10);
    if (errno || *end || v < lo || v > hi)
        return -1;
    *out = v;
    return 0;
}

/* The value of an option with two choices: 0 when s is first, 1 when it is second, else -1. */
static int choice(const char *s, const char *first, const char *second)
{
    return !strcmp(s, first) ? 0 : !strcmp(s, second) ? 1 : -1;
}

/* What kref_parse_args has read besides o: which required options, and the eye radius. */
typedef struct {
    int degree, space, rule, radius;
} parse_seen;

/* parse_valued for the options that take one positive integer (--block-threads,
 * --patches-per-block and --eye-radius), with its contract. */
static int parse_sizes(kref_args *o, parse_seen *seen, char **argv, int *i, int left,
                       const char *host)
{
    const char *s = argv[*i];
    unsigned long long a;
    if (left < 1)
        return -1;
    if (!strcmp(s, "--block-threads")) {
        if (parse_ull(argv[++*i], 1, 1u << 20, &a))
            return usage(host, o->label, "--block-threads takes a positive integer");
        o->pq = (size_t)a;
    } else if (!strcmp(s, "--patches-per-block")) {
        if (parse_ull(argv[++*i], 1, 1u << 20, &a))
            return usage(host, o->label, "--patches-per-block takes a positive integer");
        o->q = (size_t)a;
    } else if (!strcmp(s, "--eye-radius")) {
        if (parse_ull(argv[++*i], 1, 1000, &a))
            return usage(host, o->label, "--eye-radius takes R, 1..1000 bounding radii");
        seen->radius = (int)a;
    } else
        return -1;
    return 0;
}

/* Parses the option argv[*i] if it is one of those taking values and left >= the count it
 * takes (left values follow it), advancing *i past them: 0, usage's 2 for a bad value, or -1
 * when it is none of them (or lacks values). */
static int parse_valued(kref_args *o, parse_seen *seen, char **argv, int *i, int left,
                        const char *host)
{
    const char *s = argv[*i];
    unsigned long long a, b;
    int k;
    if (!strcmp(s, "--name") && left >= 1) {
        o->label = argv[++*i];
    } else if (!strcmp(s, "--kernel") && left >= 1) {
        o->kernel_name = argv[++*i];
    } else if (!strcmp(s, "--degree") && left >= 2) {
        if (parse_ull(argv[*i + 1], 1, PTP_MAX_DEGREE, &a) ||
            parse_ull(argv[*i + 2], 1, PTP_MAX_DEGREE, &b))
            return usage(host, o->label, "--degree takes N M, each 1..16");
        o->n = (int)a;
        o->m = (int)b;
        seen->degree = 1;
        *i += 2;
    } else if (!strcmp(s, "--domain") && left >= 1) {
        if ((k = choice(argv[++*i], "quad", "triangle")) < 0)
            return usage(host, o->label, "--domain is quad or triangle");
        o->kind = k ? TP_TRI : TP_QUAD;
    } else if (!strcmp(s, "--space") && left >= 1) {
        if ((k = choice(argv[++*i], "clip", "world")) < 0)
            return usage(host, o->label, "--space is clip or world");
        o->space = k ? KREF_WORLD : KREF_CLIP;
        seen->space = 1;
    } else if (!strcmp(s, "--rule") && left >= 1) {
        if ((k = choice(argv[++*i], "strict", "degenerate")) < 0)
            return usage(host, o->label, "--rule is strict or degenerate");
        o->rule = k ? KREF_DEGENERATE : KREF_STRICT;
        seen->rule = 1;
    } else
        return parse_sizes(o, seen, argv, i, left, host);
    return 0;
}

/* Parses --random, --model, --exact or --exact-far s with its three values v[0..2] into a new
 * source of o; 0, or usage's 2. */
static int parse_source(kref_args *o, const char *s, char **v, const char *host)
{
    unsigned long long a, b, c;
    kref_source *sr;
    if (o->nsources == KREF_MAX_SOURCES)
        return usage(host, o->label, "too many --random, --model and --exact(-far) options");
    sr = &o->src[o->nsources++];
    sr->kind = !strcmp(s, "--model")       ? KREF_SRC_MODEL
               : !strcmp(s, "--exact")     ? KREF_SRC_EXACT
               : !strcmp(s, "--exact-far") ? KREF_SRC_EXACT_FAR
                                           : KREF_SRC_RANDOM;
    if (sr->kind == KREF_SRC_MODEL) {
        sr->path = v[0];
        if (parse_ull(v[1], 1, INT_MAX, &a) || parse_ull(v[2], 0, UINT64_MAX, &c))
            return usage(host, o->label, "--model takes PATH NEYES SEED");
        sr->nsets = (long)a;
    } else {
        if (parse_ull(v[0], 1, INT_MAX, &a) || parse_ull(v[1], 1, UINT32_MAX, &b) ||
            parse_ull(v[2], 0, UINT64_MAX, &c))
            return usage(host, o->label, sr->kind == KREF_SRC_RANDOM
                                             ? "--random takes SETS COUNT SEED (COUNT >= 1)"
                                             : "--exact(-far) takes SETS COUNT SEED (COUNT >= 1)");
        sr->nsets = (long)a;
        sr->count = (size_t)b;
    }
    sr->seed = (uint64_t)c;
    return 0;
}

/* Parses the argument argv[*i] (an option, its values, or the file), advancing *i past its
 * values; 0, or usage's 2. */
static int parse_arg(kref_args *o, parse_seen *seen, int argc, char **argv, int *i,
                     const char *host)
{
    const char *s = argv[*i];
    int left = argc - *i - 1, st = parse_valued(o, seen, argv, i, left, host);
    char msg[200];
    if (st >= 0)
        return st;
    if (!strcmp(s, "--planes")) {
        o->planes = 1;
    } else if (!strcmp(s, "--groups-x-constant")) {
        o->groups_x_constant = 1;
    } else if (!strcmp(s, "--certified")) {
        o->certified = 1;
    } else if (!strcmp(s, "--local-bound")) {
        o->local_bound = 1;
    } else if ((!strcmp(s, "--random") || !strcmp(s, "--model") || !strcmp(s, "--exact") ||
                !strcmp(s, "--exact-far")) && left >= 3) {
        st = parse_source(o, s, argv + *i + 1, host);
        *i += 3;
        return st;
    } else if (s[0] == '-' && s[1] == '-') {
        snprintf(msg, sizeof msg, "unknown option or missing values: %.100s", s);
        return usage(host, o->label, msg);
    } else if (!o->file) {
        o->file = s;
    } else {
        snprintf(msg, sizeof msg, "unexpected argument %.100s", s);
        return usage(host, o->label, msg);
    }
    return 0;
}

/* Checks that o and seen have everything need asks for and gives every source the eye radius;
 * 0, or usage's 2. */
static int parse_check(kref_args *o, const parse_seen *seen, const char *host, unsigned need)
{
    int i;
    if (!o->label)
        return usage(host, NULL, "--name LABEL is required");
    if (!seen->degree || !seen->space || !seen->rule || (need & KREF_NEED_FILE && !o->file) ||
        (need & KREF_NEED_KERNEL && !o->kernel_name) || (need & KREF_NEED_BLOCK && (!o->pq || !o->q)))
        return usage(host, o->label, "a required argument is missing");
    if (o->q && o->pq % o->q && o->q % o->pq)
        return usage(host, o->label, "--block-threads PQ must be a multiple of --patches-per-block Q "
                                     "or divide it (OpenCL's --kernel lanes)");
    if (!o->nsources)
        return usage(host, o->label, "give at least one --random, --model or --exact(-far)");
    for (i = 0; i < o->nsources; i++)
        o->src[i].radius = seen->radius;
    return 0;
}

int kref_parse_args(kref_args *o, int argc, char **argv, const char *host, unsigned need)
{
    parse_seen seen = {0, 0, 0, 0};
    int i, st;
    memset(o, 0, sizeof *o);
    /* the label first, so that every usage failure carries it */
    for (i = 1; i + 1 < argc; i++)
        if (!strcmp(argv[i], "--name"))
            o->label = argv[i + 1];
    for (i = 1; i < argc; i++)
        if ((st = parse_arg(o, &seen, argc, argv, &i, host)) != 0)
            return st;
    return parse_check(o, &seen, host, need);
}

kref_set *kref_source_sets(const kref_ref *r, const kref_source *src, const char *label)
{
    ptp_error err;
    kref_set *sets;
    if (src->kind == KREF_SRC_MODEL) {
        if (!(sets = kref_model_sets_at(r, src->path, (int)src->nsets, src->seed, src->radius, &err)))
            check(0, label, "model %s: %s", src->path, err.msg);
    } else if (src->kind == KREF_SRC_EXACT || src->kind == KREF_SRC_EXACT_FAR) {
        if (!(sets = kref_exact_sets(r, (int)src->nsets, src->count, src->seed,
                                     src->kind == KREF_SRC_EXACT_FAR, &err)))
            check(0, label, "%ld exact sets of %zu patches: %s", src->nsets, src->count, err.msg);
    } else if (!(sets = kref_random_sets(r, (int)src->nsets, src->count, src->seed))) {
        check(0, label, "%ld random sets of %zu patches: out of memory", src->nsets, src->count);
    }
    return sets;
}

int kref_each_set(const kref_ref *r, const kref_args *a, kref_set_fn fn, void *ctx, int *nsets)
{
    int si, i, st = 0;
    if (nsets)
        *nsets = 0;
    for (si = 0; si < a->nsources && !st; si++) {
        int n = (int)a->src[si].nsets;
        kref_set *sets = kref_source_sets(r, &a->src[si], a->label);
        if (!sets)
            return -1;
        for (i = 0; i < n && !st; i++)
            st = fn(ctx, r, &sets[i]);
        kref_free_sets(sets, n);
        if (nsets)
            *nsets += n;
    }
    return st;
}

/* r->den (the lcm of each plane's denominators) and r->wint (den * w per term), or both NULL
 * when a scale overflows 128 bits or a plane's sum of |den * w| reaches 2^47 (exact sets are
 * then refused: exact_values relies on it); PTP_ENOMEM on failure. */
static int integer_weights(kref_ref *r, ptp_error *err)
{
    size_t x;
    int ovf = 0;
    ptp_i128 sum = 0;
    r->den = malloc((size_t)r->L * sizeof *r->den);
    r->wint = malloc((r->t.nterms ? r->t.nterms : 1) * sizeof *r->wint);
    if (!r->den || !r->wint) {
        free(r->den);
        free(r->wint);
        r->den = NULL;
        r->wint = NULL;
        return ptp_fail(err, PTP_ENOMEM, "out of memory");
    }
    for (x = 0; x < (size_t)r->L; x++)
        r->den[x] = 1;
    for (x = 0; x < r->t.nterms && !ovf; x++) { /* den = lcm(den, w.den) */
        const tp_term *e = &r->t.terms[x];
        ovf = rat_lcm_den(&r->den[e->plane], &e->w);
    }
    for (x = 0; x < r->t.nterms && !ovf; x++) {
        const tp_term *e = &r->t.terms[x];
        ptp_i128 w = 0;
        if (x && e->plane != r->t.terms[x - 1].plane)
            sum = 0;
        ovf = i128_mul_ovf(&w, e->w.num, r->den[e->plane] / e->w.den) ||
              (sum += w < 0 ? -w : w) >= (ptp_i128)1 << 47;
        if (!ovf)
            r->wint[x] = (int64_t)w;
    }
    if (ovf) {
        free(r->den);
        free(r->wint);
        r->den = NULL;
        r->wint = NULL;
    }
    return PTP_OK;
}

/* r->edge: the planes a collapsed boundary edge zeros exactly, those whose every term has two
 * points on that edge (the contract's exact zeros); PTP_ENOMEM on failure. */
static int edge_planes(kref_ref *r, ptp_error *err)
{
    int P, e, c;
    size_t x, a = 0, b;
    r->edge = calloc((size_t)r->L, 1);
    if (!r->edge)
        return ptp_fail(err, PTP_ENOMEM, "out of memory");
    for (P = 0; P < r->L; P++, a = b) {
        for (b = a; b < r->t.nterms && r->t.terms[b].plane == P; b++)
            ;
        for (e = 0; e < tp_domain_edges(&r->t.dom) && !r->edge[P]; e++) {
            for (x = a; x < b; x++) {
                const int pt[3] = {r->t.terms[x].j, r->t.terms[x].k, r->t.terms[x].l};
                int i, j, on = 0;
                for (c = 0; c < 3; c++) {
                    tp_domain_point_ij(&i, &j, &r->t.dom, pt[c]);
                    on += tp_domain_on_edge(&r->t.dom, e, i, j) != 0;
                }
                if (on < 2)
                    break;
            }
            r->edge[P] = x == b;
        }
    }
    return PTP_OK;
}

int kref_init(kref_ref *r, tp_kind kind, int n, int m, kref_space space, kref_rule rule,
              ptp_error *err)
{
    tp_domain d;
    int st = tp_domain_init(&d, kind, n, m, err);
    if (st || (st = tp_derive_domain(&r->t, &d, err)))
        return st;
    r->K = r->t.dom.npoints;
    r->L = r->t.dom.nplanes;
    r->space = space;
    r->rule = rule;
    r->certified = 0;
    r->local_bound = 0;
    r->edge = NULL;
    if ((st = integer_weights(r, err)) || (st = edge_planes(r, err))) {
        free(r->wint);
        free(r->den);
        tp_clear(&r->t);
    }
    return st;
}

int kref_init_args(kref_ref *r, const kref_args *a)
{
    ptp_error err;
    if (kref_init(r, a->kind, a->n, a->m, a->space, a->rule, &err))
        return !check(0, a->label, "kref_init(%dx%d): %s", a->n, a->m, err.msg);
    r->certified = a->certified;
    r->local_bound = a->local_bound;
    return 0;
}

void kref_clear(kref_ref *r)
{
    tp_clear(&r->t);
    free(r->wint);
    free(r->den);
    free(r->edge);
    r->wint = NULL;
    r->den = NULL;
    r->edge = NULL;
}

void kref_table_max(int *maxp, int *maxk, const tp_table *t)
{
    size_t x;
    *maxp = *maxk = -1;
    for (x = 0; x < t->nterms; x++) {
        *maxp = t->terms[x].plane > *maxp ? t->terms[x].plane : *maxp;
        *maxk = t->terms[x].l > *maxk ? t->terms[x].l : *maxk;
    }
}

/* The point that collapsing edge e (0..3, taken modulo the domain's edges) copies onto point
 * k: the first point on the edge, or -1 when k is not on it. */
static int edge_first(const tp_domain *d, int e, int k)
{
    int pt[TP_EDGE_POINTS_MAX], x, n = tp_domain_edge_points(pt, d, e % tp_domain_edges(d));
    for (x = 0; x < n; x++)
        if (pt[x] == k)
            return pt[0];
    return -1;
}

int kref_exact_class(const kref_set *s, size_t p, kref_rule rule)
{
    return !s->exact ? -1 : rule == KREF_STRICT ? s->exact[p] & 3 : s->exact[p] >> 2;
}

void kref_degree_name(char *buf, size_t size, const tp_domain *d)
{
    char p[32]; /* the default prefix, "ptp_tri3_": the name between "ptp_" and "_" */
    size_t n = strlen(tp_domain_prefix(p, sizeof p, d));
    snprintf(buf, size, "%.*s", (int)(n - 5), p + 4);
}

/* A uniform double in [lo, hi) from the stream *s. */
static double uniform(uint64_t *s, double lo, double hi)
{
    return lo + (hi - lo) * (double)(ptp_splitmix64(s) >> 11) / 9007199254740992.0;
}

static kref_set *alloc_sets(int nsets, size_t count, int K)
{
    kref_set *sets = calloc((size_t)nsets, sizeof *sets);
    int i;
    if (!sets)
        return NULL;
    for (i = 0; i < nsets; i++) {
        sets[i].count = count;
        sets[i].K = K;
        if (!(sets[i].cp = malloc(count * (size_t)K * sizeof *sets[i].cp))) {
            kref_free_sets(sets, nsets);
            return NULL;
        }
    }
    return sets;
}

void kref_free_sets(kref_set *sets, int nsets)
{
    int i;
    if (!sets)
        return;
    for (i = 0; i < nsets; i++) {
        free(sets[i].cp);
        free(sets[i].exact);
    }
    free(sets);
}

kref_set *kref_random_sets(const kref_ref *r, int nsets, size_t count, uint64_t seed)
{
    static const double noise[] = {0, 0.003, 0.03, 0.1, 0.3, 1.0};
    kref_set *sets = alloc_sets(nsets, count, r->K);
    int n = r->t.dom.n, m = r->t.dom.m, i, j, k, c, s, first;
    size_t p;
    char deg[16];
    if (!sets)
        return NULL;
    kref_degree_name(deg, sizeof deg, &r->t.dom);
    for (s = 0; s < nsets; s++) {
        kref_set *set = &sets[s];
        uint64_t rng = seed * 1000003u + (uint64_t)s;
        snprintf(set->name, sizeof set->name, "random %s #%d", deg, s);
        if (r->space == KREF_WORLD) {
            for (c = 0; c < 3; c++)
                set->eye[c] = (float)uniform(&rng, -4, 4);
            set->eye[3] = 1;
        } else {
            set->eye[0] = set->eye[1] = set->eye[3] = 0;
            set->eye[2] = (float)(uniform(&rng, 0, 1) < 0.5 ? -uniform(&rng, 0.5, 2) : uniform(&rng, 0.5, 2));
        }
        for (p = 0; p < count; p++) {
            /* A random parallelogram frame, bent by noise of a random size; a third rational. */
            double o[3], a[3], b[3], amp = noise[(int)uniform(&rng, 0, 6)];
            int rational = uniform(&rng, 0, 3) < 1, collapse = (int)uniform(&rng, 0, 16);
            for (c = 0; c < 3; c++) {
                o[c] = uniform(&rng, -1, 1);
                a[c] = uniform(&rng, -1, 1);
                b[c] = uniform(&rng, -1, 1);
            }
            for (i = 0; i <= n; i++)
                for (j = 0; j <= m; j++) {
                    float *pt;
                    if (!tp_grid_has(r->t.dom.kind, n, m, i, j))
                        continue;
                    pt = set->cp[p * (size_t)r->K + (size_t)tp_domain_point(&r->t.dom, i, j)];
                    double w = rational ? uniform(&rng, 0.5, 2) : 1.0, x[3];
                    for (c = 0; c < 3; c++)
                        x[c] = o[c] + a[c] * i / n + b[c] * j / m + amp * uniform(&rng, -1, 1);
                    if (r->space == KREF_CLIP)
                        x[2] = 0.5 * x[2]; /* keep clip z inside the w range */
                    for (c = 0; c < 3; c++)
                        pt[c] = (float)(w * x[c]);
                    pt[3] = (float)(w * (r->space == KREF_CLIP ? uniform(&rng, 1.5, 2.5) : 1.0));
                }
            /* A quarter collapse one edge (edge_first) to a point, like the Utah teapot's lid:
             * that edge's planes are then exactly zero. */
            for (k = 0; collapse < 4 && k < r->K; k++)
                if ((first = edge_first(&r->t.dom, collapse, k)) >= 0)
                    memcpy(set->cp[p * (size_t)r->K + (size_t)k],
                           set->cp[p * (size_t)r->K + (size_t)first], sizeof *set->cp);
        }
    }
    return sets;
}

/* ---- exact sets (--exact): integer data on the edge between the classes ---- */

/* Eye-relative coordinates of exact sets stay within EXACT_MAX, those of far sets within
 * EXACT_FAR_MAX; exact_values accepts points and eye-relative coordinates up to EXACT_LIMIT (a
 * point fits a float exactly, cross products stay below 2^49 and determinants below 2^75, in
 * 128 bits) and clip space's alpha up to EXACT_ALPHA. */
#define EXACT_MAX ((int64_t)1 << 18)
#define EXACT_FAR_MAX ((int64_t)1 << 23)
#define EXACT_LIMIT ((int64_t)1 << 24)
#define EXACT_ALPHA ((int64_t)1 << 4)
#define KREF_MAXK ((PTP_MAX_TRI_DEGREE + 1) * (PTP_MAX_TRI_DEGREE + 2) / 2 > \
                   (PTP_MAX_DEGREE + 1) * (PTP_MAX_DEGREE + 1)                  \
               ? (PTP_MAX_TRI_DEGREE + 1) * (PTP_MAX_TRI_DEGREE + 2) / 2        \
               : (PTP_MAX_DEGREE + 1) * (PTP_MAX_DEGREE + 1))

/* --exact cycles through the first EX_KINDS kinds; --exact-far makes EX_FAR only. */
enum { EX_RANDOM, EX_COLLAPSED, EX_PLANAR, EX_TANGENT, EX_NEAR, EX_KINDS, EX_FAR = EX_KINDS };
static const char *const exact_kind[EX_KINDS + 1] = {"random", "collapsed edge", "planar",
                                                     "tangent corner", "near-planar",
                                                     "far tangent corner"};

/* A uniform integer in [lo, hi] from the stream *s (hi - lo < 2^62; the modulo bias is
 * negligible for test data). */
static int64_t irand(uint64_t *s, int64_t lo, int64_t hi)
{
    return lo + (int64_t)(ptp_splitmix64(s) % (uint64_t)(hi - lo + 1));
}

/* Returns g = gcd(|a|, |b|) and sets *x, *y to integers with a x + b y = g (extended Euclid;
 * |a|, |b| < 2^62). */
static int64_t egcd(int64_t a, int64_t b, int64_t *x, int64_t *y)
{
    int64_t x0 = 1, y0 = 0, x1 = 0, y1 = 1, q, t;
    while (b) {
        q = a / b;
        t = a - q * b, a = b, b = t;
        t = x0 - q * x1, x0 = x1, x1 = t;
        t = y0 - q * y1, y0 = y1, y1 = t;
    }
    *x = a < 0 ? -x0 : x0;
    *y = a < 0 ? -y0 : y0;
    return a < 0 ? -a : a;
}

/* a . b, exactly (components below 2^62). */
static ptp_i128 dot3(const int64_t a[3], const int64_t b[3])
{
    return (ptp_i128)a[0] * b[0] + (ptp_i128)a[1] * b[1] + (ptp_i128)a[2] * b[2];
}

/* Subtracts from a the integer multiple mu b nearest to its projection on b,
 * mu = round(a.b / b.b) (b != 0; components below 2^49, so that |mu b| <= |a| fits). */
static void reduce_by(int64_t a[3], const int64_t b[3])
{
    ptp_i128 num = dot3(a, b), den = dot3(b, b), mu = num / den, rem = num % den;
    int c;
    if (2 * rem > den)
        mu++;
    else if (2 * rem < -den)
        mu--;
    for (c = 0; c < 3; c++)
        a[c] -= (int64_t)mu * b[c];
}

/* A plane through the eye: a random primitive integer normal n with |n_c| <= 2^bits, a
 * Lagrange-reduced basis a, b of the integer points on it, and a short d with n.d = 1, so that
 * c d + i a + j b lies on n.x = c. Returns 0, or -1 when a, b or d has a component beyond
 * 2^13 (a skewed lattice: the caller draws again). */
static int plane_frame(uint64_t *rng, int bits, int64_t n[3], int64_t a[3], int64_t b[3],
                       int64_t d[3])
{
    int64_t g, p, q, r, t, lim = (int64_t)1 << 13;
    int c, it;
    do {
        for (c = 0; c < 3; c++)
            n[c] = irand(rng, -((int64_t)1 << bits), (int64_t)1 << bits);
        g = egcd(n[0], n[1], &p, &q);
    } while (egcd(g, n[2], &r, &t) != 1);
    if (g == 0) { /* n = (0, 0, +-1) */
        int64_t a0[3] = {1, 0, 0}, b0[3] = {0, 1, 0}, d0[3] = {0, 0, n[2]};
        memcpy(a, a0, sizeof a0);
        memcpy(b, b0, sizeof b0);
        memcpy(d, d0, sizeof d0);
        return 0;
    }
    /* n.a = 0, n.b = n2 (p n0 + q n1 - g) = 0, a x b = n: a basis; n.d = r g + t n2 = 1 */
    a[0] = n[1] / g, a[1] = -n[0] / g, a[2] = 0;
    b[0] = p * n[2], b[1] = q * n[2], b[2] = -g;
    d[0] = r * p, d[1] = r * q, d[2] = t;
    for (;;) { /* Lagrange: |a| <= |b| and |a.b| <= |a|^2 / 2 */
        int64_t tmp[3];
        if (dot3(a, a) > dot3(b, b)) {
            memcpy(tmp, a, sizeof tmp);
            memcpy(a, b, sizeof tmp);
            memcpy(b, tmp, sizeof tmp);
        }
        memcpy(tmp, b, sizeof tmp);
        reduce_by(b, a);
        if (!memcmp(tmp, b, sizeof tmp))
            break;
    }
    for (it = 0; it < 8; it++) { /* shorten d modulo the lattice (n.d stays 1) */
        reduce_by(d, a);
        reduce_by(d, b);
    }
    for (c = 0; c < 3; c++)
        if (llabs(a[c]) > lim || llabs(b[c]) > lim || llabs(d[c]) > lim)
            return -1;
    return 0;
}

/* One patch under construction: eye-relative points v and (world space) their w. */
typedef struct {
    const tp_domain *dom;
    int n, m, K, world;
    int64_t v[KREF_MAXK][3];
    int64_t w[KREF_MAXK];
} ipatch;

/* Kind 0: coordinates in [-2^bits, 2^bits]; clip space: the third (w) in 1..4. */
static void exact_random(ipatch *pt, uint64_t *rng, int bits)
{
    int64_t a = (int64_t)1 << bits;
    int k, c;
    for (k = 0; k < pt->K; k++)
        for (c = 0; c < 3; c++)
            pt->v[k][c] = !pt->world && c == 2 ? irand(rng, 1, 4) : irand(rng, -a, a);
}

/* Moves each coordinate by +-1 with probability 1/q. */
static void jiggle(ipatch *pt, uint64_t *rng, int q)
{
    int k, c;
    for (k = 0; k < pt->K; k++)
        for (c = 0; c < 3; c++)
            if (irand(rng, 0, q - 1) == 0)
                pt->v[k][c] += irand(rng, 0, 1) ? 1 : -1;
}

/* The point that cell (i, j) of the construction goes to when its corner (0, 0) is mirrored
 * to corner c (0..3): quads mirror i (c & 1) and j (c & 2); triangles rotate the barycentric
 * indices (i, j, k) c % 3 times. */
static int corner_cell(const tp_domain *d, int c, int i, int j)
{
    int k = d->n - i - j;
    if (d->kind == TP_TRI)
        return c % 3 == 0 ? tp_domain_point(d, i, j)
               : c % 3 == 1 ? tp_domain_point(d, j, k) : tp_domain_point(d, k, i);
    return tp_domain_point(d, c & 1 ? d->n - i : i, c & 2 ? d->m - j : j);
}

/* The far tangent corner's steps k along u + v: up to about EXACT_FAR_MAX over the largest
 * |u_c| + |v_c|, so that the patch lies far from the eye against its extent (at least 2). */
static int64_t far_steps(uint64_t *rng, const int64_t u[3], const int64_t v[3])
{
    int64_t m = 1, k;
    int c;
    for (c = 0; c < 3; c++)
        if (llabs(u[c]) + llabs(v[c]) > m)
            m = llabs(u[c]) + llabs(v[c]);
    k = (EXACT_FAR_MAX - 64 * m) / m;
    return k < 4 ? 2 : irand(rng, k / 2, k);
}

/* Kinds 2 to 4 and EX_FAR on a plane frame of the given bits; returns -1 when plane_frame
 * does. */
static int exact_lattice(ipatch *pt, uint64_t *rng, int kind, int bits)
{
    int64_t n[3], a[3], b[3], d[3], u[3], v[3], o[3], e[3] = {0, 0, 0};
    int64_t s1 = irand(rng, 1, 2), s2 = irand(rng, 1, 2), off = 0, k0, k1, hc = 0;
    int i, j, c, axis = 0, corner = 0;
    if (plane_frame(rng, bits, n, a, b, d))
        return -1;
    for (c = 0; c < 3; c++) {
        u[c] = s1 * a[c];
        v[c] = s2 * b[c];
    }
    k0 = irand(rng, -4, 4);
    k1 = irand(rng, -4, 4);
    if (kind == EX_TANGENT || kind == EX_FAR) {
        /* The corner (0, 0) at o = off d + k (u + v): o, o + u and o + v lie on n.x = off, 0
         * or one unit from the eye, and the convex bump h e (zero at those three points, e
         * along n's largest component) bends the rest away, so that the corner value is 0
         * or tiny and the others are large and of one sign. The corner is mirrored to any of
         * the four. EX_FAR: the same with k far along the plane (far_steps), so that the
         * points' magnitudes dwarf their differences. */
        off = irand(rng, -1, 1);
        k0 = k1 = kind == EX_FAR ? far_steps(rng, u, v) : irand(rng, 2, 6);
        for (c = 0; c < 3; c++)
            if (llabs(n[c]) > llabs(n[axis]))
                axis = c;
        e[axis] = irand(rng, 0, 1) ? 1 : -1;
        hc = (int64_t)1 << irand(rng, 0, kind == EX_FAR ? 0 : 4);
        corner = (int)irand(rng, 0, 3);
    } else if (kind == EX_NEAR) {
        /* on n.x = off: through the eye, one unit from it, or further */
        static const int64_t offs[] = {0, 0, 1, -1, 2, -3};
        off = irand(rng, 0, 7);
        off = off < 6 ? offs[off] : irand(rng, -((int64_t)1 << bits), (int64_t)1 << bits);
    }
    for (c = 0; c < 3; c++)
        o[c] = off * d[c] + k0 * u[c] + k1 * v[c];
    for (i = 0; i <= pt->n; i++)
        for (j = 0; j <= pt->m; j++) {
            int64_t *q, h, ja, jb;
            if (!tp_grid_has(pt->dom->kind, pt->n, pt->m, i, j))
                continue;
            /* point (i, j) of the construction goes to the point of corner_cell */
            q = pt->v[corner_cell(pt->dom, corner, i, j)];
            h = hc * (i * (i - 1) + j * (j - 1) + i * j);
            ja = kind == EX_PLANAR ? irand(rng, -1, 1) : 0; /* in-plane jitter */
            jb = kind == EX_PLANAR ? irand(rng, -1, 1) : 0;
            for (c = 0; c < 3; c++)
                q[c] = o[c] + i * u[c] + j * v[c] + h * e[c] + ja * a[c] + jb * b[c];
        }
    if (kind == EX_NEAR)
        jiggle(pt, rng, 4);
    else if ((kind == EX_TANGENT || kind == EX_FAR) && irand(rng, 0, 3) == 0) /* a quarter: */
        for (i = (int)irand(rng, 1, 3); i > 0; i--) /* 1 to 3 moved by 1 */
            pt->v[irand(rng, 0, pt->K - 1)][irand(rng, 0, 2)] += irand(rng, 0, 1) ? 1 : -1;
    return 0;
}

/* Collapses edge `edge` (edge_first) to its first point. */
static void collapse_edge(ipatch *pt, int edge)
{
    int k, first;
    for (k = 0; k < pt->K; k++)
        if ((first = edge_first(pt->dom, edge, k)) >= 0) {
            memcpy(pt->v[k], pt->v[first], sizeof pt->v[k]);
            pt->w[k] = pt->w[first];
        }
}

/* One patch of the given kind and level (0..3: the magnitude); the coordinates stay within
 * EXACT_MAX, EX_FAR's within EXACT_FAR_MAX (a frame that would pass it is drawn again, with
 * fewer bits each time). */
static void exact_patch(ipatch *pt, uint64_t *rng, int kind, int level)
{
    static const int rbits[4] = {2, 4, 8, 12}, lbits[4] = {6, 12, 18, 24};
    static const int fbits[4] = {9, 10, 11, 12}; /* EX_FAR's normals */
    int bits = kind == EX_FAR ? fbits[level] : lbits[level], k, c, ok;
    int64_t cap = kind == EX_FAR ? EXACT_FAR_MAX : EXACT_MAX;
    for (k = 0; k < pt->K; k++) /* world space: w = 1, or 2..4 for a quarter */
        pt->w[k] = pt->world && irand(rng, 0, 3) == 0 ? irand(rng, 2, 4) : 1;
    do {
        int base = kind == EX_COLLAPSED ? (irand(rng, 0, 1) ? EX_NEAR : EX_RANDOM) : kind;
        if (base == EX_RANDOM)
            exact_random(pt, rng, rbits[level]);
        ok = base == EX_RANDOM || !exact_lattice(pt, rng, base, bits);
        for (k = 0; ok && k < pt->K; k++)
            for (c = 0; c < 3; c++)
                ok &= llabs(pt->v[k][c]) <= cap;
        if (!ok && bits > 4)
            bits--;
    } while (!ok);
    if (kind == EX_COLLAPSED)
        collapse_edge(pt, (int)irand(rng, 0, 3));
}

/* *out = f when f is an integer of magnitude <= lim (<= 2^24, so exact in float); else -1. */
static int float_int(float f, int64_t lim, int64_t *out)
{
    if (!(fabsf(f) <= (float)lim) || (float)(int64_t)f != f)
        return -1;
    *out = (int64_t)f;
    return 0;
}

/* The exact values of patch p of an exact set s, each times its plane's r->den: v[i] =
 * den_i * d_i. cr is scratch for K * K cross products. Returns 0, or -1 when r->wint is NULL or
 * a coordinate or the eye is not an integer of the range kref_exact_sets makes.
 * No sum overflows: |det| < 2^75 for coordinates within EXACT_LIMIT, a plane's sum of |wint|
 * is below 2^47 (integer_weights) and |scale| <= EXACT_ALPHA, so |v| < 2^126. */
static int exact_values(const kref_ref *r, const kref_set *s, size_t p, int64_t (*cr)[3],
                        ptp_i128 *v)
{
    const float(*b)[4] = (const float(*)[4])s->cp + p * (size_t)r->K;
    int64_t q[KREF_MAXK][3], e[4], x[4];
    ptp_i128 scale;
    size_t t;
    int i, k, l, c;
    if (!r->wint)
        return -1;
    for (c = 0; c < 4; c++)
        if (float_int(s->eye[c], EXACT_LIMIT, &e[c]))
            return -1;
    /* world: the eye is (e, 1) and value_t = e . cross4 = -det[b_j b_k b_l e] = -det3 of the
     * eye-relative points b - b.w e; clip: the eye is (0, 0, alpha, 0) and value_t = alpha
     * times det3 of the points' (x, y, w) (tests/kref.c cross4_mag: t.z = +det(x, y, w)) */
    if (r->space == KREF_WORLD ? e[3] != 1 : e[0] || e[1] || e[3] || llabs(e[2]) > EXACT_ALPHA)
        return -1;
    scale = r->space == KREF_WORLD ? -1 : e[2];
    for (k = 0; k < r->K; k++) {
        for (c = 0; c < 4; c++)
            if (float_int(b[k][c], EXACT_LIMIT, &x[c]))
                return -1;
        for (c = 0; c < 3; c++) {
            q[k][c] = r->space == KREF_WORLD ? x[c] - x[3] * e[c] : x[c == 2 ? 3 : c];
            if (llabs(q[k][c]) > EXACT_LIMIT)
                return -1;
        }
    }
    for (k = 0; k < r->K; k++) /* cr[k K + l] = q_k x q_l for k < l */
        for (l = k + 1; l < r->K; l++) {
            int64_t *o = cr[k * r->K + l];
            o[0] = q[k][1] * q[l][2] - q[k][2] * q[l][1];
            o[1] = q[k][2] * q[l][0] - q[k][0] * q[l][2];
            o[2] = q[k][0] * q[l][1] - q[k][1] * q[l][0];
        }
    for (i = 0, t = 0; i < r->L; i++) { /* the terms are sorted by plane */
        ptp_i128 sum = 0;
        for (; t < r->t.nterms && r->t.terms[t].plane == i; t++) {
            const tp_term *te = &r->t.terms[t];
            const int64_t *a = q[te->j], *bc = cr[te->k * r->K + te->l];
            sum += (ptp_i128)r->wint[t] * ((ptp_i128)a[0] * bc[0] + (ptp_i128)a[1] * bc[1] +
                                           (ptp_i128)a[2] * bc[2]);
        }
        v[i] = sum * scale;
    }
    return 0;
}

/* The class of exact values v[0..L-1] under rule. */
static int exact_class(const ptp_i128 *v, int L, kref_rule rule)
{
    int i, lt = 0, gt = 0, all_lt = 1, all_gt = 1;
    for (i = 0; i < L; i++) {
        lt |= v[i] < 0;
        gt |= v[i] > 0;
        all_lt &= v[i] < 0;
        all_gt &= v[i] > 0;
    }
    if (rule == KREF_STRICT)
        return all_lt ? KREF_BACK : all_gt ? KREF_FRONT : KREF_SILHOUETTE;
    return !gt ? KREF_BACK : !lt ? KREF_FRONT : KREF_SILHOUETTE;
}

/* Set s's eye: world, three coordinates drawn from rng within +-2^(2, 6, 10 or 16 by s) and
 * w = 1; clip, (0, 0, alpha, 0) with alpha 1, -1, 2 or 3 by s. */
static void exact_eye(kref_set *set, int s, int world, uint64_t *rng)
{
    static const int ebits[4] = {2, 6, 10, 16};
    static const float alphas[4] = {1, -1, 2, 3};
    int64_t eb = (int64_t)1 << ebits[s / 2 % 4];
    int c;
    if (world) {
        for (c = 0; c < 3; c++)
            set->eye[c] = (float)irand(rng, -eb, eb);
        set->eye[3] = 1;
    } else {
        set->eye[0] = set->eye[1] = set->eye[3] = 0;
        set->eye[2] = alphas[s % 4];
    }
}

/* Stores pt's points as patch p of set, in float: world, v + w eye (and w); clip, (x, y, w/2,
 * w) from v = (x, y, w). */
static void exact_store(kref_set *set, size_t p, const ipatch *pt)
{
    int k, c;
    for (k = 0; k < pt->K; k++) {
        float *q = set->cp[p * (size_t)pt->K + (size_t)k];
        const int64_t *v = pt->v[k];
        if (pt->world) {
            for (c = 0; c < 3; c++)
                q[c] = (float)(v[c] + pt->w[k] * (int64_t)set->eye[c]);
            q[3] = (float)pt->w[k];
        } else {
            q[0] = (float)v[0];
            q[1] = (float)v[1];
            q[2] = (float)(v[2] / 2);
            q[3] = (float)v[2];
        }
    }
}

/* Fills set s of kref_exact_sets (count patches, seed, far; deg names the degree) with pt, cr
 * and ev as scratch: its name, eye, patches and exact classes. 0, or -1 with err set. */
static int exact_fill(const kref_ref *r, kref_set *set, int s, size_t count, uint64_t seed,
                      int far, const char *deg, ipatch *pt, int64_t (*cr)[3], ptp_i128 *ev,
                      ptp_error *err)
{
    uint64_t rng = seed * 1000033u + (uint64_t)s;
    int kind = far ? EX_FAR : s % EX_KINDS, level = far ? s % 4 : s / EX_KINDS % 4;
    size_t p;
    snprintf(set->name, sizeof set->name, "exact %s #%d (%s)", deg, s, exact_kind[kind]);
    exact_eye(set, s, pt->world, &rng);
    for (p = 0; p < count; p++) {
        exact_patch(pt, &rng, kind, level);
        exact_store(set, p, pt);
        if (exact_values(r, set, p, cr, ev)) { /* the construction keeps in range */
            ptp_fail(err, PTP_EINTERNAL, "%s patch %zu is outside the exact range", set->name, p);
            return -1;
        }
        set->exact[p] = (unsigned char)(exact_class(ev, r->L, KREF_STRICT) +
                                        4 * exact_class(ev, r->L, KREF_DEGENERATE));
    }
    return 0;
}

kref_set *kref_exact_sets(const kref_ref *r, int nsets, size_t count, uint64_t seed, int far,
                          ptp_error *err)
{
    kref_set *sets;
    ipatch *pt;
    ptp_i128 *ev;
    int64_t(*cr)[3];
    int s;
    char deg[16];
    kref_degree_name(deg, sizeof deg, &r->t.dom);
    if (!r->wint) {
        ptp_fail(err, PTP_ELIMIT, "the %s weights are too large for exact evaluation", deg);
        return NULL;
    }
    sets = alloc_sets(nsets, count, r->K);
    pt = malloc(sizeof *pt);
    ev = malloc((size_t)r->L * sizeof *ev);
    cr = malloc((size_t)r->K * (size_t)r->K * sizeof *cr);
    for (s = 0; sets && s < nsets; s++)
        if (!(sets[s].exact = malloc(count ? count : 1))) {
            kref_free_sets(sets, nsets);
            sets = NULL;
        }
    if (!sets || !pt || !ev || !cr) {
        kref_free_sets(sets, nsets);
        free(pt);
        free(ev);
        free(cr);
        ptp_fail(err, PTP_ENOMEM, "out of memory");
        return NULL;
    }
    pt->dom = &r->t.dom;
    pt->n = r->t.dom.n;
    pt->m = r->t.dom.m;
    pt->K = r->K;
    pt->world = r->space == KREF_WORLD;
    for (s = 0; sets && s < nsets; s++)
        if (exact_fill(r, &sets[s], s, count, seed, far, deg, pt, cr, ev, err)) {
            kref_free_sets(sets, nsets);
            sets = NULL;
        }
    free(pt);
    free(ev);
    free(cr);
    return sets;
}

int kref_exact_signs(const kref_ref *r, const kref_set *s, size_t p, signed char *sign,
                     double *x)
{
    ptp_i128 *ev = malloc((size_t)r->L * sizeof *ev);
    int64_t(*cr)[3] = malloc((size_t)r->K * (size_t)r->K * sizeof *cr);
    int i, st = !ev || !cr || exact_values(r, s, p, cr, ev) ? -1 : 0;
    for (i = 0; !st && i < r->L; i++) {
        sign[i] = (signed char)((ev[i] > 0) - (ev[i] < 0));
        x[i] = (double)ev[i] / (double)r->den[i];
    }
    free(ev);
    free(cr);
    return st;
}

/* Reads a BEZ model with bench/bezfile.c; its one-line message (file, line, what was expected)
 * becomes err's. */
static int read_model(bez_file *mo, const char *path, ptp_error *err)
{
    char msg[512];
    if (bez_file_read(mo, path, msg, sizeof msg))
        return ptp_fail(err, PTP_EIO, "%s", msg);
    return PTP_OK;
}

/* r = A * B for 4x4 row-major matrices. */
static void mat_mul(double r[16], const double A[16], const double B[16])
{
    int i, j, k;
    for (i = 0; i < 4; i++)
        for (j = 0; j < 4; j++) {
            r[i * 4 + j] = 0;
            for (k = 0; k < 4; k++)
                r[i * 4 + j] += A[i * 4 + k] * B[k * 4 + j];
        }
}

void kref_look_at(double V[16], const double E[3], const double C[3], int d3d)
{
    double f[3], up[3] = {0, 1, 0}, s[3], u[3], d = 0, len;
    int c;
    for (c = 0; c < 3; c++)
        d += (C[c] - E[c]) * (C[c] - E[c]);
    for (c = 0; c < 3; c++)
        f[c] = (C[c] - E[c]) / sqrt(d);
    if (fabs(f[1]) > 0.9) {
        up[0] = 1;
        up[1] = 0;
    }
    s[0] = f[1] * up[2] - f[2] * up[1]; /* s = f x up, u = s x f */
    s[1] = f[2] * up[0] - f[0] * up[2];
    s[2] = f[0] * up[1] - f[1] * up[0];
    len = sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
    for (c = 0; c < 3; c++)
        s[c] /= len;
    u[0] = s[1] * f[2] - s[2] * f[1];
    u[1] = s[2] * f[0] - s[0] * f[2];
    u[2] = s[0] * f[1] - s[1] * f[0];
    for (c = 0; c < 3; c++) {
        V[c] = d3d ? -s[c] : s[c]; /* x = -s keeps the rotation proper with z = +f */
        V[4 + c] = u[c];
        V[8 + c] = d3d ? f[c] : -f[c];
        V[12 + c] = 0;
    }
    for (c = 0; c < 3; c++)
        V[c * 4 + 3] = -(V[c * 4] * E[0] + V[c * 4 + 1] * E[1] + V[c * 4 + 2] * E[2]);
    V[15] = 1;
}

/* An OpenGL camera at E looking at C: M = Proj * View. The eye maps to (0, 0, Proj[2][3], 0),
 * but cross4 of transformed points is det(M) M^-T cross4, so the clip-space eye that keeps the
 * world-space classes is (0, 0, sign(det Proj) * Proj[2][3], 0) = (0, 0, -Proj[3][2] * |.|, 0). */
static void camera(double M[16], double *alpha, const double E[3], const double C[3], double R)
{
    double V[16], P[16] = {0}, d = 0, n, far;
    int c;
    for (c = 0; c < 3; c++)
        d += (C[c] - E[c]) * (C[c] - E[c]);
    d = sqrt(d);
    kref_look_at(V, E, C, 0);
    n = 0.5 * (d - R);
    far = d + 2 * R;
    P[0] = P[5] = 1 / tan(M_PI_6);
    P[10] = -(far + n) / (far - n);
    P[11] = -2 * far * n / (far - n);
    P[14] = -1;
    mat_mul(M, P, V);
    *alpha = copysign(fabs(P[11]), -P[0] * P[5] * P[14]); /* det P = -P00 P11 P23 P32 */
}

kref_set *kref_model_sets(const kref_ref *r, const char *path, int neyes, uint64_t seed,
                          ptp_error *err)
{
    return kref_model_sets_at(r, path, neyes, seed, 0, err);
}

kref_set *kref_model_sets_at(const kref_ref *r, const char *path, int neyes, uint64_t seed,
                             int radius, ptp_error *err)
{
    bez_file mo;
    kref_set *sets;
    double C[3] = {0, 0, 0}, R = 0;
    const char *base = strrchr(path, '/') ? strrchr(path, '/') + 1 : path;
    int e, p, k, c, nverts;
    if (r->t.dom.kind != TP_QUAD || r->t.dom.n != 3 || r->t.dom.m != 3) {
        ptp_fail(err, PTP_EUSAGE, "models are bicubic: use bidegree 3x3");
        return NULL;
    }
    if (read_model(&mo, path, err))
        return NULL;
    nverts = (int)mo.nverts;
    if (!(sets = alloc_sets(neyes, (size_t)mo.npatches, 16))) {
        ptp_fail(err, PTP_ENOMEM, "out of memory");
        goto done;
    }
    for (k = 0; k < nverts; k++)
        for (c = 0; c < 3; c++)
            C[c] += mo.v[k][c] / nverts;
    for (k = 0; k < nverts; k++) {
        double d2 = 0;
        for (c = 0; c < 3; c++)
            d2 += (mo.v[k][c] - C[c]) * (mo.v[k][c] - C[c]);
        R = fmax(R, sqrt(d2));
    }
    for (e = 0; e < neyes; e++) {
        kref_set *s = &sets[e];
        uint64_t rng = seed * 7919u + (uint64_t)e;
        double dir[3], len = 0, dist = uniform(&rng, 2, 5) * R, E[3], M[16], alpha;
        do { /* uniform on the sphere: a normalized Gaussian-free rejection sample */
            len = 0;
            for (c = 0; c < 3; c++) {
                dir[c] = uniform(&rng, -1, 1);
                len += dir[c] * dir[c];
            }
        } while (len > 1 || len < 1e-4);
        if (radius)
            dist = radius * R;
        for (c = 0; c < 3; c++)
            E[c] = C[c] + dist * dir[c] / sqrt(len);
        snprintf(s->name, sizeof s->name, "%.*s eye %d", 40, base, e);
        camera(M, &alpha, E, C, R);
        for (p = 0; p < (int)mo.npatches; p++)
            for (k = 0; k < 16; k++) {
                const double *v = mo.v[mo.idx[p][k]];
                float *pt = s->cp[(size_t)p * 16 + (size_t)k];
                for (c = 0; c < 4; c++)
                    pt[c] = r->space == KREF_WORLD
                                ? (float)(c < 3 ? v[c] : 1.0)
                                : (float)(M[c * 4] * v[0] + M[c * 4 + 1] * v[1] + M[c * 4 + 2] * v[2] + M[c * 4 + 3]);
            }
        if (r->space == KREF_WORLD) {
            for (c = 0; c < 3; c++)
                s->eye[c] = (float)E[c];
            s->eye[3] = 1;
        } else {
            s->eye[0] = s->eye[1] = s->eye[3] = 0;
            s->eye[2] = (float)alpha;
        }
    }
done:
    bez_file_free(&mo);
    return sets;
}

/* cross4 of Appendix A in double, and the sum of |monomials| of each component. With two equal
 * points and exact set, it is exactly zero (t = mag = 0; returns 1, else 0): the kernels evaluate the planes a
 * collapsed edge zeros (kref_ref.edge) without contracted multiply-adds, so that their terms with
 * two equal points are exactly zero too and such a plane has bound 0. */
static int cross4_mag(double t[4], double mag[4], const float *a, const float *b, const float *c,
                      int exact)
{
    static const int rows[4][3] = {{1, 2, 3}, {0, 2, 3}, {0, 1, 3}, {0, 1, 2}};
    int o;
    if (exact && (!memcmp(a, b, 4 * sizeof *a) || !memcmp(a, c, 4 * sizeof *a) ||
                  !memcmp(b, c, 4 * sizeof *b))) {
        for (o = 0; o < 4; o++)
            t[o] = mag[o] = 0;
        return 1;
    }
    for (o = 0; o < 4; o++) {
        int p = rows[o][0], q = rows[o][1], s = rows[o][2];
        double m1 = (double)a[p] * b[q] * c[s], m2 = (double)a[p] * b[s] * c[q];
        double m3 = (double)b[p] * a[q] * c[s], m4 = (double)b[p] * a[s] * c[q];
        double m5 = (double)c[p] * a[q] * b[s], m6 = (double)c[p] * a[s] * b[q];
        double det = (m1 - m2) - (m3 - m4) + (m5 - m6);
        t[o] = (o & 1) ? -det : det;
        mag[o] = fabs(m1) + fabs(m2) + fabs(m3) + fabs(m4) + fabs(m5) + fabs(m6);
    }
    return 0;
}

/* Patch-local coordinates as the straight-line kernels compute them (ptpgen --coordinates local):
 * o = -(x0, y0, z0) / w0 (0 where w0 is 0), x' = x + o w. Into mag the points' widened
 * magnitudes |x'| + 2^-16 |o w| (and w's |w|), which cover a kernel whose reciprocal or origin
 * rounds differently and a shift rounded twice; into eye's the eye's (world: l = e + o e3). */
static void local_magnitudes(float (*mag)[4], float eye[4], const float (*b)[4], int K,
                             const float e[4])
{
    float rw = b[0][3] != 0.0f ? 1.0f / b[0][3] : 0.0f, o[3];
    int k, c;
    for (c = 0; c < 3; c++)
        o[c] = -(b[0][c] * rw);
    for (k = 0; k < K; k++) {
        for (c = 0; c < 3; c++)
            mag[k][c] = fabsf(fmaf(o[c], b[k][3], b[k][c])) + ldexpf(fabsf(o[c] * b[k][3]), -16);
        mag[k][3] = fabsf(b[k][3]);
    }
    for (c = 0; c < 3; c++)
        eye[c] = fabsf(fmaf(o[c], e[3], e[c])) + ldexpf(fabsf(o[c] * e[3]), -16);
    eye[3] = fabsf(e[3]);
}

/* The bound, with u = 2^-24: a cross4 component rounds its three-factor monomials, two
 * differences and two sums (5u relative to the sum of |monomials|), the float weight and its
 * product add 2u, the eye's products and sums at most 5u (world space), and summing a plane's
 * terms in any order (count - 1)u: (count + 12)u in all, taken as (count + 16)u. A kernel in
 * patch-local coordinates rounds every coordinate once more, at most 2^-16 of the shift from the
 * reference's (local_magnitudes): (count + 24)u over the local points' monomials. The bound is
 * the larger of the two, so that it holds for both formulations (--coordinates absolute and the
 * certified table kernel read the points as given), or with r->local_bound the local one alone. */
void kref_values(const kref_ref *r, const kref_set *s, size_t p, double *d, double *bound)
{
    const float(*b)[4] = (const float(*)[4])s->cp + p * (size_t)r->K;
    float(*lm)[4] = malloc((size_t)r->K * sizeof *lm), le[4];
    double *lb = calloc((size_t)r->L, sizeof *lb);
    size_t x;
    int i, count = 0;
    if (!lm || !lb) {
        fprintf(stderr, "kref: out of memory\n");
        exit(1);
    }
    local_magnitudes(lm, le, b, r->K, s->eye);
    for (i = 0; i < r->L; i++)
        d[i] = bound[i] = 0;
    for (x = 0; x < r->t.nterms; x++) {
        const tp_term *e = &r->t.terms[x];
        double t[4], mag[4], lt[4], lmag[4], w = rat_get_d(&e->w), v = 0, mg = 0, lg = 0;
        int c, zero;
        zero = cross4_mag(t, mag, b[e->j], b[e->k], b[e->l], r->edge[e->plane]);
        cross4_mag(lt, lmag, lm[e->j], lm[e->k], lm[e->l], 0);
        for (c = 0; c < 4; c++)
            if (r->space == KREF_WORLD || c == 2) {
                v += s->eye[c] * t[c];
                mg += fabs(s->eye[c]) * mag[c];
                lg += (double)le[c] * lmag[c];
            }
        d[e->plane] += w * v;
        bound[e->plane] += fabs(w) * mg;
        lb[e->plane] += zero ? 0 : fabs(w) * lg; /* two equal points stay equal */
    }
    for (i = 0, x = 0; i < r->L; i++) {
        for (count = 0; x < r->t.nterms && r->t.terms[x].plane == i; x++)
            count++;
        bound[i] = r->local_bound ? lb[i] * (count + 24) * ldexp(1, -24)
                                  : fmax(bound[i] * (count + 16), lb[i] * (count + 24)) * ldexp(1, -24);
    }
    free(lm);
    free(lb);
}

int kref_classify(const double *d, int L, kref_rule rule)
{
    int i, gt = 0, lt = 0, notgt = 0, notlt = 0, nan = 0;
    for (i = 0; i < L; i++) {
        gt |= d[i] > 0;
        lt |= d[i] < 0;
        notgt |= !(d[i] > 0);
        notlt |= !(d[i] < 0);
        nan |= d[i] != d[i];
    }
    if (rule == KREF_STRICT)
        return !notlt ? KREF_BACK : !notgt ? KREF_FRONT : KREF_SILHOUETTE;
    return nan ? KREF_SILHOUETTE : !gt ? KREF_BACK : !lt ? KREF_FRONT : KREF_SILHOUETTE;
}

/* Compares the kernel's class cls of patch p of the exact set s with its exact class (s->exact)
 * under r->rule (a certified kernel too: under the degenerate rule it may call back a patch with
 * exactly zero values), and describes the first unsafe one with its exact values (ev, and cr for
 * exact_values, are scratch). */
static void check_exact(kref_result *res, const kref_ref *r, const kref_set *s, size_t p,
                        unsigned cls, int64_t (*cr)[3], ptp_i128 *ev)
{
    static const char *const names[] = {"front", "back", "silhouette"};
    int strict = r->rule == KREF_STRICT, i, n, first;
    int cl[2] = {kref_exact_class(s, p, KREF_STRICT), kref_exact_class(s, p, KREF_DEGENERATE)};
    int want = cl[strict ? 0 : 1];
    size_t len;
    res->exact++;
    res->exact_counts[0][cl[0]]++;
    res->exact_counts[1][cl[1]]++;
    res->exact_certain += want != KREF_SILHOUETTE;
    res->exact_given_up += cls == KREF_SILHOUETTE && want != KREF_SILHOUETTE;
    if ((cls != KREF_BACK && cls != KREF_FRONT) || (int)cls == want)
        return;
    first = res->unsafe_back + res->unsafe_front == 0;
    if (cls == KREF_BACK)
        res->unsafe_back++;
    else
        res->unsafe_front++;
    if (!first)
        return;
    /* the first unsafe class: the planes that contradict it (up to three) */
    len = (size_t)snprintf(res->first_unsafe, sizeof res->first_unsafe,
                           "%s patch %zu: kernel %s, exact class %s (%s rule); exact values "
                           "(times the plane's scale)", s->name, p, names[cls], names[want],
                           strict ? "strict" : "degenerate");
    if (exact_values(r, s, p, cr, ev)) /* kref_exact_sets computed them once */
        return;
    for (i = 0, n = 0; i < r->L && n < 3 && len < sizeof res->first_unsafe; i++)
        if (cls == KREF_BACK ? ev[i] >= 0 : ev[i] <= 0) {
            char num[48], den[48];
            len += (size_t)snprintf(res->first_unsafe + len, sizeof res->first_unsafe - len,
                                    "%s plane %d = %s (scale %s)", n++ ? "," : ":", i,
                                    i128_to_str(num, ev[i]), i128_to_str(den, r->den[i]));
        }
    if (r->certified) { /* a certified kernel's unsafe class is a generator bug: the patch */
        const float(*b)[4] = (const float(*)[4])s->cp + p * (size_t)r->K;
        int k;
        printf("# %s patch %zu: eye %.0f %.0f %.0f %.0f; points (x y z w):", s->name, p,
               s->eye[0], s->eye[1], s->eye[2], s->eye[3]);
        for (k = 0; k < r->K; k++)
            printf("%s %.0f %.0f %.0f %.0f", k ? "," : "", b[k][0], b[k][1], b[k][2], b[k][3]);
        printf("\n");
    }
}

/* Compares the exact values of a sampled patch p of the exact set s (into ev; cr is scratch)
 * with the double reference d, within 2^-20 of its float bound (far above the double rounding,
 * far below any real disagreement), and its class with the exact class kref_exact_sets stored. */
static void compare_exact(kref_result *res, const kref_ref *r, const kref_set *s, size_t p,
                          const double *d, const double *bound, int64_t (*cr)[3], ptp_i128 *ev)
{
    int i;
    res->exact_compared++;
    if (exact_values(r, s, p, cr, ev) ||
        s->exact[p] != exact_class(ev, r->L, KREF_STRICT) +
                           4 * exact_class(ev, r->L, KREF_DEGENERATE)) {
        if (!res->exact_bad++)
            snprintf(res->first_exact, sizeof res->first_exact,
                     "%s patch %zu: the exact values cannot be computed again, or their classes "
                     "changed", s->name, p);
        return;
    }
    for (i = 0; i < r->L; i++) {
        double x = (double)ev[i] / (double)r->den[i];
        if (!(fabs(x - d[i]) <= ldexp(bound[i], -20))) {
            if (!res->exact_bad++)
                snprintf(res->first_exact, sizeof res->first_exact,
                         "%s patch %zu plane %d: exact %.17g, double reference %.17g", s->name,
                         p, i, x, d[i]);
            return;
        }
    }
}

/* Counts a back or front class cls of an ambiguous patch of values d within bound: wrong when
 * every value is beyond KREF_DOUBLE_SCALE times its bound (or exactly zero) and their class
 * differs, undecided when some value is not. */
static void check_ambiguous_cull(kref_result *res, const kref_ref *r, const double *d,
                                 const double *bound, unsigned cls)
{
    int i;
    res->ambiguous_culled++;
    for (i = 0; i < r->L; i++)
        if (bound[i] > 0 && fabs(d[i]) <= bound[i] * KREF_DOUBLE_SCALE) {
            res->culled_undecided++;
            return;
        }
    res->culled_wrong += (int)cls != kref_classify(d, r->L, r->rule);
}

void kref_check(kref_result *res, const kref_ref *r, const kref_set *s, const unsigned *cls,
                const float *planes)
{
    double *d = malloc(2 * (size_t)r->L * sizeof *d), *bound = d + r->L;
    ptp_i128 *ev = s->exact ? malloc((size_t)r->L * sizeof *ev) : NULL;
    int64_t(*cr)[3] = s->exact ? malloc((size_t)r->K * (size_t)r->K * sizeof *cr) : NULL;
    static const char *const names[] = {"front", "back", "silhouette"};
    size_t p;
    int i;
    if (!d || (s->exact && (!ev || !cr))) {
        free(d);
        free(ev);
        free(cr);
        return;
    }
    res->certified = r->certified;
    res->one_sided = r->L == 1 && r->rule == KREF_DEGENERATE;
    res->degenerate = r->rule == KREF_DEGENERATE;
    for (p = 0; p < s->count; p++) {
        int ambiguous = 0, want;
        if (cls[p] <= 2)
            res->kernel_counts[cls[p]]++;
        if (s->exact) {
            check_exact(res, r, s, p, cls[p], cr, ev);
            if (p % KREF_EXACT_SAMPLE) {
                if (cls[p] > 2 && !res->class_bad++)
                    snprintf(res->first_class, sizeof res->first_class, "%s patch %zu: class %u",
                             s->name, p, cls[p]);
                continue;
            }
        }
        kref_values(r, s, p, d, bound);
        if (s->exact)
            compare_exact(res, r, s, p, d, bound, cr, ev);
        for (i = 0; i < r->L; i++)
            ambiguous |= bound[i] > 0 && fabs(d[i]) <= bound[i]; /* bound 0: exactly zero */
        want = kref_classify(d, r->L, r->rule);
        res->patches++;
        if (r->certified && !ambiguous && cls[p] == KREF_SILHOUETTE && want != KREF_SILHOUETTE) {
            res->given_up++; /* a certified kernel may give up a class */
        } else if (cls[p] > 2 || (!ambiguous && (int)cls[p] != want)) {
            if (!res->class_bad++)
                snprintf(res->first_class, sizeof res->first_class, "%s patch %zu: class %u, reference %s%s",
                         s->name, p, cls[p], names[want], ambiguous ? " (ambiguous)" : "");
        }
        for (i = 0; i < r->L && !(bound[i] == 0 && d[i] == 0); i++)
            ;
        res->exact_zero += i < r->L;
        if (ambiguous) {
            res->ambiguous++;
            if (cls[p] == KREF_FRONT || cls[p] == KREF_BACK)
                check_ambiguous_cull(res, r, d, bound, cls[p]);
        } else
            res->counts[want]++;
        for (i = 0; planes && i < r->L; i++) {
            double got = planes[p * (size_t)r->L + (size_t)i], e = fabs(got - d[i]);
            res->values++;
            if (bound[i] > 0)
                res->worst = fmax(res->worst, e / bound[i]);
            if (!(e <= bound[i])) {
                if (!res->value_bad++)
                    snprintf(res->first_value, sizeof res->first_value,
                             "%s patch %zu plane %d: %.9g, reference %.9g, bound %.3g", s->name, p,
                             i, got, d[i], bound[i]);
            }
        }
    }
    free(d);
    free(ev);
    free(cr);
}

/* The check lines and the "# " line of the exact sets (kref_report); returns 1 if all passed. */
static int report_exact(const kref_result *res, const char *name)
{
    char label[400];
    size_t unsafe = res->unsafe_back + res->unsafe_front, certain = res->exact_certain;
    int ok = 1;
    snprintf(label, sizeof label, "%s: exact values of %zu patches agree with the double "
             "reference on every %dth (%zu compared)", name, res->exact, KREF_EXACT_SAMPLE,
             res->exact_compared);
    ok &= check(res->exact_bad == 0 && res->exact_compared > 0, label, "%zu bad: %s",
                res->exact_bad, res->exact_bad ? res->first_exact : "none compared");
    if (res->certified) {
        snprintf(label, sizeof label, "%s: certified: no unsafe class on %zu exact patches "
                 "(back only if every exact value %s 0, front only if every one %s 0)", name,
                 res->exact, res->degenerate ? "<=" : "<",
                 res->degenerate ? ">=" : ">");
        ok &= check(unsafe == 0, label, "%zu unsafe (back %zu, front %zu), first: %s", unsafe,
                    res->unsafe_back, res->unsafe_front, res->first_unsafe);
    } else {
        snprintf(label, sizeof label, "%s: %zu exact patches classified (plain float may be "
                 "unsafe near zero: %zu are)", name, res->exact, unsafe);
        ok &= check(1, label, "");
        if (unsafe)
            printf("# %s: first unsafe: %s\n", name, res->first_unsafe);
    }
    printf("# %s: exact: %zu patches; strict rule front %zu, back %zu, silhouette %zu; "
           "degenerate rule front %zu, back %zu, silhouette %zu; kernel unsafe %zu (back %zu, "
           "front %zu); given up %zu of %zu exactly back or front (%.2f%%)\n", name, res->exact,
           res->exact_counts[0][0], res->exact_counts[0][1], res->exact_counts[0][2],
           res->exact_counts[1][0], res->exact_counts[1][1], res->exact_counts[1][2], unsafe,
           res->unsafe_back, res->unsafe_front, res->exact_given_up, certain,
           certain ? 100.0 * (double)res->exact_given_up / (double)certain : 0.0);
    return ok;
}

int kref_report(const kref_result *res, const char *name)
{
    char label[320];
    int ok = 1;
    if (res->certified)
        snprintf(label, sizeof label, "%s: %zu patches, classes agree with the double reference "
                 "or are silhouette (certified: %zu given up, %zu ambiguous within the bound)",
                 name, res->patches, res->given_up, res->ambiguous);
    else
        snprintf(label, sizeof label, "%s: %zu patches, classes agree with the double reference "
                 "(%zu ambiguous within the bound)", name, res->patches, res->ambiguous);
    ok &= check(res->patches > 0 && res->class_bad == 0, label, "%zu wrong: %s", res->class_bad,
                res->first_class);
    if (res->values) {
        snprintf(label, sizeof label, "%s: %zu plane values within the float32 bound", name,
                 res->values);
        ok &= check(res->value_bad == 0, label, "%zu off: %s", res->value_bad, res->first_value);
    }
    if (res->patches >= 500) {
        snprintf(label, sizeof label, "%s: the patches include front, back%s ones", name,
                 res->one_sided ? " (one plane, degenerate rule: no silhouette)" : " and silhouette");
        ok &= check(res->counts[0] && res->counts[1] && (res->counts[2] || res->one_sided), label,
                    "front %zu, back %zu, silhouette %zu", res->counts[0], res->counts[1],
                    res->counts[2]);
    }
    printf("# %s: front %zu, back %zu, silhouette %zu, ambiguous %zu, with exact zero planes %zu, "
           "worst value error %.3g of the bound", name, res->counts[0], res->counts[1],
           res->counts[2], res->ambiguous, res->exact_zero, res->worst);
    if (res->certified) {
        size_t certain = res->counts[0] + res->counts[1];
        printf(", certified: given up %zu of %zu back or front (%.2f%%)", res->given_up,
               certain, certain ? 100.0 * (double)res->given_up / (double)certain : 0.0);
    }
    printf("\n# %s: kernel front %zu, back %zu, silhouette %zu; back or front on %zu ambiguous "
           "patches: %zu wrong, %zu undecided in double\n", name, res->kernel_counts[0],
           res->kernel_counts[1], res->kernel_counts[2], res->ambiguous_culled, res->culled_wrong,
           res->culled_undecided);
    if (res->certified && res->ambiguous_culled) {
        snprintf(label, sizeof label, "%s: certified: its back or front classes of %zu ambiguous "
                 "patches agree with the double reference where it decides them", name,
                 res->ambiguous_culled);
        ok &= check(res->culled_wrong == 0, label, "%zu wrong", res->culled_wrong);
    }
    if (res->exact)
        ok &= report_exact(res, name);
    return ok;
}

/* Removes "--bench RUNS", which kref_parse_args does not know, from argv and returns RUNS as
 * given; NULL when absent. A "--bench" without a value stays, for kref_parse_args to refuse. */
static const char *take_bench(int *argc, char **argv)
{
    const char *runs = NULL;
    int i, j = 1;
    for (i = 1; i < *argc; i++) {
        if (!runs && !strcmp(argv[i], "--bench") && i + 1 < *argc)
            runs = argv[++i];
        else
            argv[j++] = argv[i];
    }
    *argc = j;
    argv[j] = NULL;
    return runs;
}

/* RUNS of --bench, 1 to 1000; 0 if s is not such a number. */
static long bench_runs(const char *s)
{
    char *end;
    long r;
    errno = 0;
    r = strtol(s, &end, 10);
    return !errno && end != s && !*end && r >= 1 && r <= 1000 ? r : 0;
}

int kref_parse_bench_args(kref_args *a, long *runs, int argc, char **argv, const char *host,
                          unsigned need)
{
    const char *bench = take_bench(&argc, argv);
    *runs = 0;
    if (kref_parse_args(a, argc, argv, host, need))
        return 2;
    if (bench && !(*runs = bench_runs(bench))) {
        check(0, a->label, "--bench takes RUNS, 1 to 1000");
        return 2;
    }
    return 0;
}

int kref_start(kref_args *a, kref_ref *r, long *runs, int argc, char **argv, const char *host,
               unsigned need)
{
    if (runs ? kref_parse_bench_args(a, runs, argc, argv, host, need)
             : kref_parse_args(a, argc, argv, host, need))
        return 2;
    return kref_init_args(r, a) ? 1 : 0;
}

int kref_host_main(const kref_host *h, void *ctx, int argc, char **argv)
{
    kref_args a;
    kref_ref r;
    int st = kref_start(&a, &r, NULL, argc, argv, h->name, 0), ok;
    if (st)
        return st;
    if ((h->ready && h->ready(ctx, &a, &r)) || kref_each_set(&r, &a, h->set, ctx, NULL)) {
        kref_clear(&r);
        return 1;
    }
    ok = h->report(ctx, &a, &r);
    kref_clear(&r);
    return !ok;
}
