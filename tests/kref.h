/* kref.h: test data and the double-precision reference for executing emitted kernels.
 * Patch sets (random or from ../shared/models) with an eye, reference values with bounds, checks. */
#ifndef KREF_H
#define KREF_H

#include "tplane.h"

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
} kref_set;

/* The exact table of one bidegree, for the reference. */
typedef struct {
    tp_table t;
    int K, L;          /* points and planes per patch */
    kref_space space;
    kref_rule rule;
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
} kref_result;

/* The command line every host shares:
 *   [FILE] [--kernel NAME] --degree N M --space clip|world --rule strict|degenerate
 *   [--block-threads PQ --patches-per-block Q] [--planes] [--groups-x-constant]
 *   (--random SETS COUNT SEED | --model PATH NEYES SEED)... --name LABEL */
#define KREF_MAX_SOURCES 16
typedef struct {
    int is_model;
    const char *path; /* model */
    long nsets;       /* random: sets; model: eyes */
    size_t count;     /* random: patches per set */
    uint64_t seed;
} kref_source;

typedef struct {
    const char *file, *kernel_name, *label; /* the kernel file, --kernel, --name */
    int n, m;
    kref_space space;
    kref_rule rule;
    size_t pq, q;                           /* --block-threads, --patches-per-block */
    int planes, groups_x_constant;
    int nsources;
    kref_source src[KREF_MAX_SOURCES];
} kref_args;

/* What a host requires besides the degree, space, rule, a source and --name. */
enum { KREF_NEED_FILE = 1, KREF_NEED_KERNEL = 2, KREF_NEED_BLOCK = 4 };

/* Parses the shared command line into a; on a usage error prints one "not ok" line (with the
 * host's name and usage) and returns 2, else 0. */
int kref_parse_args(kref_args *a, int argc, char **argv, const char *host, unsigned need);
/* The sets of one source (random or a model), or NULL after printing a "not ok" line. */
kref_set *kref_source_sets(const kref_ref *r, const kref_source *src, const char *label);

/* Derives the table for the reference; 0 on success (messages go to err). */
int kref_init(kref_ref *r, int n, int m, kref_space space, kref_rule rule, ptp_error *err);
void kref_clear(kref_ref *r);

/* nsets sets of count random patches each (deterministic in seed): near-planar patches with
 * noise of varied size, w != 1 (rational) in a third, one edge collapsed to a point in a quarter
 * (exactly zero planes, where the rules differ), so that all three classes occur.
 * Returns an array of nsets sets, or NULL on failure. */
kref_set *kref_random_sets(const kref_ref *r, int nsets, size_t count, uint64_t seed);
/* One set per eye for a bicubic BEZ model (the format of ../shared/models): eyes uniform on
 * spheres of 2 to 5 bounding radii around the model; in clip space the points are transformed by
 * an OpenGL perspective camera looking at the model and the eye is (0, 0, alpha, 0) with
 * alpha = sign(det P) P[2][3] > 0, which gives the same classes as world space.
 * Returns NULL (message in err) if the file cannot be read. */
kref_set *kref_model_sets(const kref_ref *r, const char *path, int neyes, uint64_t seed,
                          ptp_error *err);
void kref_free_sets(kref_set *sets, int nsets);
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
 * planes[p*L + i] for every patch of s; accumulates into res. */
void kref_check(kref_result *res, const kref_ref *r, const kref_set *s, const unsigned *cls,
                const float *planes);
/* Prints the check lines for res ("ok - NAME: ..." or "not ok - ..."); returns 1 if all passed.
 * The caller's exit status must use it: check.h's failure count is per source file.
 * Also prints a "# " line with the counts (ambiguous patches, classes, worst value error). */
int kref_report(const kref_result *res, const char *name);

#endif
