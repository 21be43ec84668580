/* kref.h: test data and the double-precision reference for executing emitted kernels.
 * Patch sets (random or from BEZ models) with an eye, reference values with bounds, checks. */
#ifndef KREF_H
#define KREF_H

#include "core/tplane.h"

#include <stddef.h>
#include <stdint.h>

typedef enum { KREF_CLIP, KREF_WORLD } kref_space;
typedef enum { KREF_STRICT, KREF_DEGENERATE } kref_rule;

/* Classes, as every kernel writes them. */
enum { KREF_FRONT = 0, KREF_BACK = 1, KREF_SILHOUETTE = 2 };

/* Patches that one dispatch classifies against one eye. */
typedef struct {
    char name[64];     /* e.g. "random 3x3 #2" or "teapot eye 7" */
    size_t count;      /* patches */
    int K;             /* control points per patch */
    float (*cp)[4];    /* count*K points, patch-major: point k of patch p at p*K + k */
    float eye[4];      /* world: the homogeneous eye point; clip: (0, 0, alpha, 0) */
    unsigned char *exact; /* kref_exact_sets: per patch, its exact class under the strict rule
                             plus 4 times the one under the degenerate rule; NULL otherwise */
} kref_set;
/* The exact class of patch p of s under rule (KREF_FRONT, KREF_BACK or KREF_SILHOUETTE); -1 when
 * s has no exact classes. */
int kref_exact_class(const kref_set *s, size_t p, kref_rule rule);

/* The exact table of one patch domain (quad or triangle), for the reference. */
typedef struct {
    tp_table t;
    int K, L;          /* points and planes per patch */
    kref_space space;
    kref_rule rule;
    int certified;     /* the kernel is certified (ptpgen --certified); kref_init sets 0 */
    int local_bound;   /* the values' bound for patch-local coordinates alone (--local-bound);
                          kref_init sets 0: the larger of it and the bound as given */
    int64_t *wint;     /* per term: den[plane] * w, an integer; NULL when a plane's sum of
                          |den * w| reaches 2^47 (exact sets are then refused) */
    ptp_i128 *den;     /* per plane: the lcm of its weights' denominators (> 0) */
    unsigned char *edge; /* per plane: 1 when every term has two points on one boundary edge, so
                            that collapsing that edge zeros the plane exactly (else NULL: none) */
} kref_ref;

/* Accumulated comparison of a kernel's output with the reference. */
typedef struct {
    size_t patches;    /* patches compared */
    size_t ambiguous;  /* patches with a reference value within its bound of zero (class not compared) */
    size_t class_bad;  /* unambiguous patches whose class differs */
    size_t value_bad;  /* planes whose value is off by more than the bound */
    size_t values;     /* plane values compared */
    size_t counts[3];  /* reference classes of the unambiguous patches: front, back, silhouette */
    size_t exact_zero; /* patches with a plane that is exactly zero (a collapsed edge) */
    double worst;      /* largest |value - reference| / bound seen */
    char first_class[256], first_value[256]; /* the first failures, for the report */
    int certified;     /* checked as a certified kernel (kref_ref.certified) */
    int one_sided;     /* a single plane under the degenerate rule: no patch can be silhouette */
    int degenerate;    /* checked under the degenerate rule */
    size_t given_up;   /* certified: silhouette where the unambiguous reference is back or front */
    size_t kernel_counts[3]; /* the kernel's classes of every patch checked: front, back, silhouette */
    size_t ambiguous_culled; /* ambiguous patches the kernel called back or front */
    size_t culled_wrong;     /* of those, the ones whose class the double reference decides
                                (every value beyond KREF_DOUBLE_SCALE times its bound) otherwise */
    size_t culled_undecided; /* of those, the ones it cannot decide so */
    /* Sets from kref_exact_sets: every patch is classified exactly (in integers), the double
     * reference above runs on every KREF_EXACT_SAMPLE-th patch only. */
    size_t exact;            /* patches classified exactly */
    size_t exact_counts[2][3]; /* their exact classes: [0] strict rule, [1] degenerate rule */
    size_t exact_certain;    /* exact class back or front, under the rule the kernel is held to */
    size_t unsafe_back;      /* kernel back where that exact class is not back */
    size_t unsafe_front;     /* kernel front where that exact class is not front */
    size_t exact_given_up;   /* kernel silhouette where that exact class is back or front */
    size_t exact_compared;   /* sampled patches whose exact values were compared with doubles */
    size_t exact_bad;        /* patches whose exact values disagree with the double reference
                                or cannot be computed (not integers, too large, overflow) */
    char first_unsafe[512], first_exact[256];
} kref_result;

/* The double reference's own rounding error, as a share of the float32 bound of the same sums
 * (2^-29 for unit roundoff 2^-53 against 2^-24, with a factor 2 to spare). */
#define KREF_DOUBLE_SCALE 0x1p-28

/* kref_check runs the double reference on every KREF_EXACT_SAMPLE-th patch of an exact set. */
#define KREF_EXACT_SAMPLE 64

/* The command line every host shares:
 *   [FILE] [--kernel NAME] --degree N M [--domain quad|triangle] --space clip|world
 *   --rule strict|degenerate
 *   [--block-threads PQ --patches-per-block Q] [--planes] [--groups-x-constant] [--certified]
 *   [--local-bound]
 *   (--random SETS COUNT SEED | --model PATH NEYES SEED | --exact SETS COUNT SEED
 *    | --exact-far SETS COUNT SEED)... [--eye-radius R] --name LABEL
 * --exact-far: kref_exact_sets' far tangent corners (far set).
 * --eye-radius R: the eyes of every --model at R bounding radii (1..1000) instead of 2 to 5.
 * --domain triangle: triangular patches of degree N (M is ignored).
 * --certified: the kernel was generated with --certified: it may answer silhouette wherever the
 * reference says back or front (counted as given up), and on --exact data it must never call a
 * patch back or front unless the exact class under --rule is that class.
 * --local-bound: hold the values (and the classes' ambiguity) to the bound of a kernel in
 * patch-local coordinates alone (kref_values), which a kernel in the coordinates as given
 * exceeds on small patches far from the origin. */
#define KREF_MAX_SOURCES 16
typedef enum { KREF_SRC_RANDOM, KREF_SRC_MODEL, KREF_SRC_EXACT, KREF_SRC_EXACT_FAR } kref_source_kind;
typedef struct {
    kref_source_kind kind;
    const char *path; /* model */
    long nsets;       /* random, exact(-far): sets; model: eyes */
    size_t count;     /* random, exact(-far): patches per set */
    uint64_t seed;
    int radius;       /* model: eyes at this many bounding radii; 0: uniform in 2 to 5 */
} kref_source;

typedef struct {
    const char *file, *kernel_name, *label; /* the kernel file, --kernel, --name */
    tp_kind kind;                           /* --domain (default quad) */
    int n, m;
    kref_space space;
    kref_rule rule;
    size_t pq, q;                           /* --block-threads, --patches-per-block */
    int planes, groups_x_constant, certified, local_bound;
    int nsources;
    kref_source src[KREF_MAX_SOURCES];
} kref_args;

/* What a host requires besides the degree, space, rule, a source and --name. */
enum { KREF_NEED_FILE = 1, KREF_NEED_KERNEL = 2, KREF_NEED_BLOCK = 4 };

/* Parses the shared command line into a; on a usage error prints one "not ok" line (with the
 * host's name and usage) and returns 2, else 0. */
int kref_parse_args(kref_args *a, int argc, char **argv, const char *host, unsigned need);
/* The sets of one source (random, a model or exact), or NULL after printing a "not ok" line. */
kref_set *kref_source_sets(const kref_ref *r, const kref_source *src, const char *label);
/* What a host does with one set; nonzero stops kref_each_set. */
typedef int (*kref_set_fn)(void *ctx, const kref_ref *r, const kref_set *s);
/* Makes the sets of each source of a in turn and calls fn(ctx, r, set) on every one until fn
 * returns nonzero; *nsets (unless NULL) counts the sets made. Returns 0, fn's nonzero value, or
 * -1 when a source's sets could not be made (after a "not ok" line). */
int kref_each_set(const kref_ref *r, const kref_args *a, kref_set_fn fn, void *ctx, int *nsets);

/* Derives the table of the domain of the kind and degrees for the reference; 0 on success
 * (messages go to err). The kernel is taken as not certified: a host sets r->certified after
 * this call. */
int kref_init(kref_ref *r, tp_kind kind, int n, int m, kref_space space, kref_rule rule,
              ptp_error *err);
/* kref_init for the domain, degree, space and rule of a host's command line a, with its
 * --certified; 0, or 1 after a "not ok" line. */
int kref_init_args(kref_ref *r, const kref_args *a);
void kref_clear(kref_ref *r);
/* Writes d's degree as the hosts and set names show it: "3x3", "tri3". */
void kref_degree_name(char *buf, size_t size, const tp_domain *d);
/* The largest plane (*maxp) and point (*maxk) index the terms of t use; -1 when it has none. */
void kref_table_max(int *maxp, int *maxk, const tp_table *t);

/* nsets sets of count random patches each (deterministic in seed): near-planar patches with
 * noise of varied size, w != 1 (rational) in a third, one edge collapsed to a point in a quarter
 * (exactly zero planes, where the rules differ), so that all three classes occur. Points sit
 * at o + a i/n + b j/m plus noise, (i, j) the point's cell (triangles: an affine triangle).
 * Returns an array of nsets sets, or NULL on failure. */
kref_set *kref_random_sets(const kref_ref *r, int nsets, size_t count, uint64_t seed);
/* One set per eye for a bicubic BEZ model (models/README.md, bench/bezfile.c): eyes uniform on
 * spheres of 2 to 5 bounding radii around the model; in clip space the points are transformed by
 * an OpenGL perspective camera looking at the model and the eye is (0, 0, alpha, 0) with
 * alpha = sign(det P) P[2][3] > 0, which gives the same classes as world space.
 * Returns NULL (message in err) if the file cannot be read. */
kref_set *kref_model_sets(const kref_ref *r, const char *path, int neyes, uint64_t seed,
                          ptp_error *err);
/* kref_model_sets with every eye at radius bounding radii (the same directions); radius 0 is
 * kref_model_sets. */
kref_set *kref_model_sets_at(const kref_ref *r, const char *path, int neyes, uint64_t seed,
                             int radius, ptp_error *err);
/* nsets sets of count patches each (deterministic in seed) whose coordinates and eye are small
 * integers, stored exactly in float, built to sit on the edge between the classes; unless far,
 * set s is of kind s % 5 with magnitudes varying with s / 5:
 *   0 random integers in [-2^a, 2^a], a in {2, 4, 8, 12}, w small and positive;
 *   1 near-planar patches (as 4) or random ones (as 0) with a boundary row or column collapsed;
 *   2 planar patches through the eye: every exact value is zero;
 *   3 the eye exactly on the tangent plane at a corner (or one unit off it) and the rest of the
 *     patch curving away, so that the corner value is 0 or tiny and every other value is large
 *     and of one sign; a quarter get one to three coordinates moved by 1;
 *   4 patches on a plane through the eye or near it, with coordinates moved by 1.
 * With far every set is of kind 5, a far tangent corner: kind 3 (with normals up to 2^9 to 2^12
 * by s % 4 and the smallest bump) slid along its tangent plane to 2^22 to 2^23 from the eye, so
 * that the points' magnitudes dwarf their extent (by 2^13 to 2^15) and products of three of them
 * round in double-float: what a certified kernel's second look must bound by the points' own
 * magnitudes, not by their differences'.
 * World space: the eye is an integer point (ex, ey, ez, 1) and a point is (v + w e, w) for an
 * integer eye-relative v; clip space: the eye is (0, 0, alpha, 0), alpha in {1, -1, 2, 3}, and
 * a point is (v0, v1, v2 / 2, v2). Eye-relative coordinates reach 2^18 (far: 2^23), so that
 * float products round. The exact classes are computed here, in 128-bit integers (set.exact).
 * Returns NULL (message in err) when out of memory or r->wint is NULL. */
kref_set *kref_exact_sets(const kref_ref *r, int nsets, size_t count, uint64_t seed, int far,
                          ptp_error *err);
void kref_free_sets(kref_set *sets, int nsets);
/* The exact signs (sign[L]: -1, 0 or 1) of the plane values of patch p of an exact set s, and
 * the values rounded to double (x[L], within 2^-51 of each relative). Returns 0, or -1 when they
 * cannot be computed (out of memory, or s not from kref_exact_sets). */
int kref_exact_signs(const kref_ref *r, const kref_set *s, size_t p, signed char *sign,
                     double *x);
/* A view matrix (row-major, a rotation and translation) putting the eye E at the origin, looking
 * at C along -z (OpenGL, d3d == 0) or +z (Direct3D). */
void kref_look_at(double V[16], const double E[3], const double C[3], int d3d);

/* The reference value of every plane of patch p of s in double (d[L]) and its bound (bound[L]):
 * the largest error a float32 evaluation of the table may make; bound 0 for an exact zero, which
 * a kernel must reproduce exactly (it may not contract multiply-adds in cross4). */
void kref_values(const kref_ref *r, const kref_set *s, size_t p, double *d, double *bound);
/* The class of values d[0..L-1] under rule (NaN makes a patch silhouette). */
int kref_classify(const double *d, int L, kref_rule rule);

/* Compares a kernel's classes cls[count] and, if planes is not NULL, its values
 * planes[p*L + i] for every patch of s; accumulates into res. The class of a certified kernel
 * (r->certified) may also be silhouette where the reference is back or front. For an exact set
 * every class is also compared with the exact one under r->rule, and the double reference runs
 * on every KREF_EXACT_SAMPLE-th
 * patch, where the exact values must agree with it. */
void kref_check(kref_result *res, const kref_ref *r, const kref_set *s, const unsigned *cls,
                const float *planes);
/* Prints the check lines for res ("ok - NAME: ..." or "not ok - ..."); returns 1 if all passed.
 * The caller's exit status must use it: check.h's failure count is per source file.
 * Also prints a "# " line with the counts (ambiguous patches, classes, worst value error) and
 * one with the kernel's classes ("# NAME: kernel front F, back B, silhouette S; ..."); for a
 * certified kernel, a check that its back or front classes of ambiguous patches agree with the
 * double reference wherever every value is beyond KREF_DOUBLE_SCALE times its bound.
 * After exact sets: a check that the sampled exact values agree with the double reference, and
 * for a certified kernel that no class is unsafe (for a plain one the unsafe count is printed
 * with an "ok" line: float may be wrong near zero), and a "# NAME: exact: ..." line with the
 * exact classes, "kernel unsafe N" and the classes given up. */
int kref_report(const kref_result *res, const char *name);

/* kref_parse_args for a host that also takes the timing option of make bench, "--bench RUNS"
 * (1 to 1000): *runs = RUNS, or 0 without it. Returns 2 after a "not ok" line on a usage error,
 * else 0. */
int kref_parse_bench_args(kref_args *a, long *runs, int argc, char **argv, const char *host,
                          unsigned need);
/* The start of a host's main: parses the command line (kref_parse_args with need; with runs not
 * NULL, kref_parse_bench_args) and derives the reference for a kernel certified as --certified
 * says. Returns 0 (kref_clear(r) when done), or 2 on a usage error and 1 when the reference
 * cannot be derived, after a "not ok" line. */
int kref_start(kref_args *a, kref_ref *r, long *runs, int argc, char **argv, const char *host,
               unsigned need);
/* The steps of a host without --bench around its sets; kref_host_main runs them. */
typedef struct {
    const char *name; /* the host's name, for its usage line */
    /* Before the sets, once the reference is made (NULL: nothing); nonzero stops the run, after
     * a "not ok" line. */
    int (*ready)(void *ctx, const kref_args *a, const kref_ref *r);
    kref_set_fn set; /* with every set (kref_each_set) */
    /* After the sets: prints the host's check lines; 1 if they all passed, else 0. */
    int (*report)(void *ctx, const kref_args *a, const kref_ref *r);
} kref_host;
/* A host's main: kref_start (no --bench), h->ready, h->set on every set, h->report, kref_clear;
 * a and r live until it returns. Returns kref_start's status, 1 when ready or a set stopped the
 * run or the report failed, else 0. The host's own check lines count in its own check_exit(). */
int kref_host_main(const kref_host *h, void *ctx, int argc, char **argv);

#endif
