/* bench_cull.c: `make bench`: patches per second of one emitted C header (clip space, strict
 * rule) and of the paper's serial loop over its table, on one core and on every core it may use.
 *
 * Built once per header, like tests/host_c.c (bench/run_bench.sh runs it and prints the table):
 *   cc -O3 -march=native -D_GNU_SOURCE -include HEADER -D<PREFIX>IMPLEMENTATION -DPFX=<prefix>
 *      -DUPFX=<PREFIX> -DDEGREE='"NxM"' bench/bench_cull.c -lm -pthread
 * (_GNU_SOURCE, for sched_setaffinity, on the command line: the header comes before this file.)
 *
 *   bench_cull --peak GFLOPS_1 GFLOPS_ALL [--patches N]   the table's rows for this bidegree
 *     (built with -DVARIANT='"--refine 3"' around a header with that option: its batch row only)
 *   bench_cull --batch [--patches N]    one line, "classify_batch M": classify_batch's million
 *     patches per second on one core (bench/paired.sh alternates builds on it); status 1 when its
 *     classes differ from classify's
 *   bench_cull --gen PTPGEN                               median ms of PTPGEN --target c */
#include <math.h>
#include <pthread.h>
#include <sched.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#define CAT2(a, b) a##b
#define CAT(a, b) CAT2(a, b)
#define FN(name) CAT(PFX, name)
#define MACRO(name) CAT(UPFX, name)

#define NPOINTS MACRO(POINTS)
#define NPLANES MACRO(PLANES)
#define NTERMS MACRO(TERMS)

/* Flops per patch of the paper's loop: per term 14 for cross4's z (9 in the three 2x2 minors,
 * 3 products with a0, b0 and c0, 2 adds), 1 for the weight product and 1 for the accumulation;
 * per plane 1 for the product with alpha. Counted as written, whether or not the compiler
 * contracts a product and an add into an FMA (clang does by default, gcc -std=c11 does not). */
#define PAPER_FLOPS (16 * NTERMS + NPLANES)

/* The header's option (-DVARIANT, e.g. "--refine 3"), or NULL for the plain header. */
#ifdef VARIANT
static const char *const variant = VARIANT;
#else
static const char *const variant = NULL;
#endif

/* The clip-space eye (0, 0, alpha, 0) with alpha = 1 > 0 (an OpenGL-style projection). */
static const float eye[4] = {0.0f, 0.0f, 1.0f, 0.0f};

/* ---- the paper's serial loop ---- */

/* The class of one patch b (NPOINTS points) by the paper's loop over the table,
 * t_P += wgt * cross4(b_j, b_k, b_l), only the z component (clip space), then the strict rule on
 * alpha * t_P.z. */
static unsigned paper_classify(const float (*b)[4], float alpha)
{
    float d[NPLANES] = {0.0f};
    unsigned x, lt = 0, gt = 0;
    for (x = 0; x < NTERMS; x++) {
        const float *a = b[FN(term_idx)[x][1]], *bb = b[FN(term_idx)[x][2]], *c = b[FN(term_idx)[x][3]];
        float z = a[0] * (bb[1] * c[3] - bb[3] * c[1]) - bb[0] * (a[1] * c[3] - a[3] * c[1]) +
                  c[0] * (a[1] * bb[3] - a[3] * bb[1]);
        d[FN(term_idx)[x][0]] += FN(term_wgt)[x] * z;
    }
    for (x = 0; x < NPLANES; x++) {
        float v = alpha * d[x];
        lt += v < 0.0f;
        gt += v > 0.0f;
    }
    return lt == NPLANES ? MACRO(BACK) : gt == NPLANES ? MACRO(FRONT) : MACRO(SILHOUETTE);
}

/* ---- data ---- */

static uint64_t rng_next(uint64_t *s)
{
    uint64_t z = (*s += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

/* Uniform in [lo, hi). */
static double uni(uint64_t *s, double lo, double hi)
{
    return lo + (hi - lo) * (double)(rng_next(s) >> 11) * 0x1p-53;
}

/* count random near-planar patches of bidegree n x m in clip space, patch-major into cp: each a
 * square piece (0.02 to 0.1 wide in normalized device coordinates) of a random plane with a
 * random normal, bent along it by a random quadratic, its points jittered by 2% of its size,
 * at a depth w of 1 to 10 that varies by up to 10% across it as under a perspective view; the
 * stored point is (x w, y w, z w, w). */
static void make_patches(float (*cp)[4], size_t count, int n, int m, uint64_t seed)
{
    uint64_t s = seed;
    size_t p;
    for (p = 0; p < count; p++) {
        double nrm[3], t1[3], t2[3], c[3], len, size, ku, kv, w0, gu, gv;
        int i, j, a;
        do { /* a uniform unit normal */
            for (a = 0; a < 3; a++)
                nrm[a] = uni(&s, -1, 1);
            len = nrm[0] * nrm[0] + nrm[1] * nrm[1] + nrm[2] * nrm[2];
        } while (len > 1 || len < 1e-6);
        len = 1 / sqrt(len);
        for (a = 0; a < 3; a++)
            nrm[a] *= len;
        /* t1 perpendicular to the normal, t2 = normal x t1 */
        if (nrm[0] * nrm[0] < 0.5) {
            t1[0] = 0;
            t1[1] = nrm[2];
            t1[2] = -nrm[1];
        } else {
            t1[0] = -nrm[2];
            t1[1] = 0;
            t1[2] = nrm[0];
        }
        len = 1 / sqrt(t1[0] * t1[0] + t1[1] * t1[1] + t1[2] * t1[2]);
        for (a = 0; a < 3; a++)
            t1[a] *= len;
        t2[0] = nrm[1] * t1[2] - nrm[2] * t1[1];
        t2[1] = nrm[2] * t1[0] - nrm[0] * t1[2];
        t2[2] = nrm[0] * t1[1] - nrm[1] * t1[0];
        for (a = 0; a < 3; a++)
            c[a] = uni(&s, -0.9, 0.9);
        size = uni(&s, 0.02, 0.1);
        ku = uni(&s, -0.5, 0.5);
        kv = uni(&s, -0.5, 0.5);
        w0 = uni(&s, 1, 10);
        gu = uni(&s, -0.1, 0.1);
        gv = uni(&s, -0.1, 0.1);
        for (i = 0; i <= n; i++)
            for (j = 0; j <= m; j++) {
                float *q = cp[p * (size_t)NPOINTS + (size_t)(i * (m + 1) + j)];
                double u = (double)i / n - 0.5, v = (double)j / m - 0.5;
                double bend = size * (ku * u * u + kv * v * v);
                double w = w0 * (1 + gu * u + gv * v);
                for (a = 0; a < 3; a++)
                    q[a] = (float)(w * (c[a] + size * (u * t1[a] + v * t2[a]) + bend * nrm[a] +
                                        size * uni(&s, -0.02, 0.02)));
                q[3] = (float)w;
            }
    }
}

/* ---- timing ---- */

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

/* The patches, patch-major, and their structure-of-arrays copy. */
typedef struct {
    size_t count;
    const float (*cp)[4]; /* count * NPOINTS points */
    const float *soa;     /* coordinate c of point k of patch p at soa[(k*4 + c) * count + p] */
    const uint32_t *idx;  /* cp's points as classify_indexed's vertices: p * NPOINTS + k, in order */
} data;

/* A path classifies patches [first, first + count) of d into cls + first. */
typedef void path_fn(const data *d, size_t first, size_t count, unsigned char *cls);

static void run_paper(const data *d, size_t first, size_t count, unsigned char *cls)
{
    size_t p;
    for (p = first; p < first + count; p++)
        cls[p] = (unsigned char)paper_classify(d->cp + p * NPOINTS, eye[2]);
}

static void run_classify(const data *d, size_t first, size_t count, unsigned char *cls)
{
    size_t p;
    for (p = first; p < first + count; p++)
        cls[p] = (unsigned char)FN(classify)(d->cp + p * NPOINTS, eye);
}

static void run_batch(const data *d, size_t first, size_t count, unsigned char *cls)
{
    FN(classify_batch)(d->cp + first * NPOINTS, count, eye, cls + first);
}

static void run_soa(const data *d, size_t first, size_t count, unsigned char *cls)
{
    FN(classify_soa)(d->soa + first, d->count, count, eye, cls + first);
}

static void run_indexed(const data *d, size_t first, size_t count, unsigned char *cls)
{
    FN(classify_indexed)(d->cp, d->idx + first * NPOINTS, count, eye, cls + first);
}

/* Patches per second of fn on this thread: the best of at least 5 calls on the first n patches
 * and of as many as 0.3 s allow. n is all of them when all is set; else n grows (doubling from
 * 256) until one call takes 20 ms or n is all of them. *used is n. */
static double measure(path_fn *fn, const data *d, unsigned char *cls, int all, size_t *used)
{
    size_t n = all || d->count < 256 ? d->count : 256;
    double best = 1e30, start, t0, secs;
    int reps;
    while (!all) {
        t0 = now();
        fn(d, 0, n, cls);
        secs = now() - t0;
        if (secs >= 0.02 || n == d->count)
            break;
        n = 2 * n < d->count ? 2 * n : d->count;
    }
    start = now();
    for (reps = 0; reps < 5 || now() - start < 0.3; reps++) {
        t0 = now();
        fn(d, 0, n, cls);
        secs = now() - t0;
        best = secs < best ? secs : best;
    }
    *used = n;
    return (double)n / best;
}

/* One thread of the all-core run: classify_batch on its slice, pinned to cpu when cpu >= 0. */
typedef struct {
    const data *d;
    size_t first, count;
    unsigned char *cls;
    int cpu;
} slice;

static void pin(int cpu)
{
    cpu_set_t set;
    CPU_ZERO(&set);
    CPU_SET(cpu, &set);
    sched_setaffinity(0, sizeof set, &set);
}

static void *run_slice(void *arg)
{
    const slice *s = arg;
    if (s->cpu >= 0)
        pin(s->cpu);
    run_batch(s->d, s->first, s->count, s->cls);
    return NULL;
}

/* Patches per second of classify_batch over all patches in nthreads threads, each on its own
 * slice (and CPU, cpus[t], when cpus is not NULL): the best of at least 5 runs and of as many
 * as 0.3 s allow. 0 if a thread cannot be created. */
static double measure_threads(const data *d, unsigned char *cls, int nthreads, const int *cpus)
{
    slice *s = malloc((size_t)nthreads * sizeof *s);
    pthread_t *th = malloc((size_t)nthreads * sizeof *th);
    double best = 1e30, start = now();
    int reps, t, started;
    if (!s || !th) {
        free(s);
        free(th);
        return 0;
    }
    for (t = 0; t < nthreads; t++) {
        s[t].d = d;
        s[t].first = d->count * (size_t)t / (size_t)nthreads;
        s[t].count = d->count * (size_t)(t + 1) / (size_t)nthreads - s[t].first;
        s[t].cls = cls;
        s[t].cpu = cpus ? cpus[t] : -1;
    }
    for (reps = 0; reps < 5 || now() - start < 0.3; reps++) {
        double t0 = now(), secs;
        for (started = 0; started < nthreads; started++)
            if (pthread_create(&th[started], NULL, run_slice, &s[started]))
                break;
        for (t = 0; t < started; t++)
            pthread_join(th[t], NULL);
        if (started < nthreads) {
            best = 1e30;
            break;
        }
        secs = now() - t0;
        best = secs < best ? secs : best;
    }
    free(s);
    free(th);
    return best < 1e30 ? (double)d->count / best : 0;
}

/* ---- output ---- */

/* One row of the table; peak in GFLOP/s, paper_rate the paper loop's patches/s (0 for the paper
 * loop itself), differ and of: the classes that differ from classify's, over the first of
 * patches (of == 0 prints "-"). */
static void row(const char *path, double rate, long flops, double peak, double paper_rate,
                size_t differ, size_t of)
{
    char vs[32], diff[48];
    double gf = rate * (double)flops * 1e-9;
    snprintf(vs, sizeof vs, "%.1fx", paper_rate > 0 ? rate / paper_rate : 1.0);
    if (of)
        snprintf(diff, sizeof diff, "%zu/%zu", differ, of);
    else
        snprintf(diff, sizeof diff, "-");
    printf("%-8s  %-37s %10.3f %11ld %8.1f %6.1f%% %8s  %s\n", DEGREE, path, rate * 1e-6, flops,
           gf, 100 * gf / peak, vs, diff);
}

static size_t count_differ(const unsigned char *a, const unsigned char *b, size_t n)
{
    size_t p, c = 0;
    for (p = 0; p < n; p++)
        c += a[p] != b[p];
    return c;
}

/* Prints the median wall time in ms of ptpgen --degree DEGREE --target c (clip, strict) to
 * /dev/null over 21 runs of the whole process; 0 on success. */
static int gen_time(const char *ptpgen)
{
    char *args[] = {(char *)ptpgen, "--degree", DEGREE, "--target", "c", "--space", "clip",
                    "--rule", "strict", "-o", "/dev/null", NULL};
    double t[21], tmp;
    int r, i, status;
    for (r = 0; r < 21; r++) {
        double t0 = now();
        pid_t pid = fork();
        if (pid < 0)
            return 1;
        if (pid == 0) {
            execv(ptpgen, args);
            _exit(127);
        }
        if (waitpid(pid, &status, 0) < 0 || !WIFEXITED(status) || WEXITSTATUS(status))
            return 1;
        t[r] = now() - t0;
    }
    for (r = 1; r < 21; r++) /* insertion sort */
        for (i = r; i > 0 && t[i - 1] > t[i]; i--) {
            tmp = t[i];
            t[i] = t[i - 1];
            t[i - 1] = tmp;
        }
    printf("%.2f\n", t[10] * 1e3);
    return 0;
}

/* bytes of memory aligned to 64 (a cache line, an AVX-512 vector); NULL when out of memory. */
static void *alloc64(size_t bytes)
{
    return aligned_alloc(64, (bytes + 63) / 64 * 64);
}

/* Parses "--peak GFLOPS_1 GFLOPS_ALL [--patches N]" into peak[0], peak[1] and *count, or
 * "--batch [--patches N]" into *batch = 1 and *count, and DEGREE into *n, *m; 0, or 2 after the
 * usage line. */
static int parse_args(double peak[2], size_t *count, int *n, int *m, int *batch, int argc,
                      char **argv)
{
    int i;
    for (i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--batch")) {
            *batch = 1;
        } else if (!strcmp(argv[i], "--peak") && i + 2 < argc) {
            peak[0] = atof(argv[i + 1]);
            peak[1] = atof(argv[i + 2]);
            i += 2;
        } else if (!strcmp(argv[i], "--patches") && i + 1 < argc) {
            *count = (size_t)strtoull(argv[++i], NULL, 10);
        } else {
            break;
        }
    }
    if (i < argc || (!*batch && (peak[0] <= 0 || peak[1] <= 0)) || *count == 0 ||
        sscanf(DEGREE, "%dx%d", n, m) != 2 || (*n + 1) * (*m + 1) != NPOINTS) {
        fprintf(stderr,
                "usage: %s --peak GFLOPS_1 GFLOPS_ALL [--patches N] | --batch [--patches N] | "
                "--gen PTPGEN\n",
                argv[0]);
        return 2;
    }
    return 0;
}

/* Into cpus (room for ncpu) the CPUs this process may use (taskset narrows them), at most ncpu,
 * and pins it to the first: the one-core runs run there, the all-core run has one thread on each.
 * Returns their number; 0 when the affinity cannot be read (every online CPU, unpinned). */
static long usable_cpus(int *cpus, long ncpu)
{
    cpu_set_t allowed;
    long ncpus = 0;
    int i;
    if (sched_getaffinity(0, sizeof allowed, &allowed) == 0)
        for (i = 0; i < CPU_SETSIZE && ncpus < ncpu; i++)
            if (CPU_ISSET(i, &allowed))
                cpus[ncpus++] = i;
    if (ncpus)
        pin(cpus[0]);
    return ncpus;
}

/* Prints "front F%, back B%, silhouette S%" and a newline: the shares of counts[3] in count. */
static void print_shares(const size_t counts[3], size_t count)
{
    printf("front %.1f%%, back %.1f%%, silhouette %.1f%%\n",
           100.0 * (double)counts[0] / (double)count, 100.0 * (double)counts[1] / (double)count,
           100.0 * (double)counts[2] / (double)count);
}

/* The rows of the plain header: the paper's loop (its rate paper, its classes in cls over used
 * patches), classify, classify_batch and classify_soa on one core, classify_batch on the ncpu
 * CPUs cpus (NULL: unpinned), against the classes ref (counts: their tally). */
static void plain_rows(const data *d, unsigned char *cls, const unsigned char *ref,
                       const size_t counts[3], const double peak[2], double paper, size_t used,
                       long ncpu, const int *cpus)
{
    char label[64];
    double rate;
    row("paper loop", paper, PAPER_FLOPS, peak[0], 0, count_differ(cls, ref, used), used);
    rate = measure(run_classify, d, cls, 0, &used);
    row("classify", rate, MACRO(FLOPS), peak[0], paper, 0, 0);
    rate = measure(run_batch, d, cls, 1, &used);
    row("classify_batch", rate, MACRO(FLOPS), peak[0], paper, count_differ(cls, ref, used), used);
    rate = measure(run_soa, d, cls, 1, &used);
    row("classify_soa", rate, MACRO(FLOPS), peak[0], paper, count_differ(cls, ref, used), used);
    rate = measure(run_indexed, d, cls, 1, &used);
    row("classify_indexed", rate, MACRO(FLOPS), peak[0], paper, count_differ(cls, ref, used), used);
    memset(cls, 0xFF, d->count);
    rate = measure_threads(d, cls, (int)ncpu, cpus);
    snprintf(label, sizeof label, "classify_batch, %ld thread%s", ncpu, ncpu > 1 ? "s" : "");
    row(label, rate, MACRO(FLOPS), peak[1], paper, count_differ(cls, ref, d->count), d->count);
    printf("# data %s: %zu patches, %.0f MB of points; classify: ", DEGREE, d->count,
           (double)d->count * NPOINTS * 16 / 1e6);
    print_shares(counts, d->count);
}

/* The line of --batch: classify_batch's rate in M patches/s. Returns 1 when its classes differ
 * from ref's, else 0. */
static int batch_line(const data *d, unsigned char *cls, const unsigned char *ref)
{
    size_t used, differ;
    double rate = measure(run_batch, d, cls, 1, &used);
    printf("classify_batch %.3f\n", rate * 1e-6);
    differ = count_differ(cls, ref, used);
    if (differ)
        fprintf(stderr, "bench_cull: classify_batch differs from classify on %zu patches\n", differ);
    return differ != 0;
}

/* The row of a header with an option: its batch path only, and its classes (as plain_rows). */
static void variant_rows(const data *d, unsigned char *cls, const unsigned char *ref,
                         const size_t counts[3], const double peak[2], double paper)
{
    char label[64];
    size_t used;
    double rate = measure(run_batch, d, cls, 1, &used);
    snprintf(label, sizeof label, "classify_batch %s", variant);
    row(label, rate, MACRO(FLOPS), peak[0], paper, count_differ(cls, ref, used), used);
    printf("# %s %s: %.1f ns a patch; classes ", DEGREE, variant, 1e9 / rate);
    print_shares(counts, d->count);
}

int main(int argc, char **argv)
{
    double peak[2] = {0, 0}, paper;
    long ncpu = sysconf(_SC_NPROCESSORS_ONLN), ncpus;
    size_t count = 262144, used, p, counts[3] = {0, 0, 0};
    int n = 0, m = 0, batch = 0, status = 0, i, *cpus;
    float(*cp)[4], *soa;
    uint32_t *idx;
    unsigned char *ref, *cls;
    data d;

    if (argc == 3 && !strcmp(argv[1], "--gen"))
        return gen_time(argv[2]);
    if (parse_args(peak, &count, &n, &m, &batch, argc, argv))
        return 2;
    if (ncpu < 1)
        ncpu = 1;

    cp = alloc64(count * NPOINTS * sizeof *cp);
    soa = alloc64(count * NPOINTS * 4 * sizeof *soa);
    idx = malloc(count * NPOINTS * sizeof *idx);
    ref = malloc(count);
    cls = malloc(count);
    cpus = malloc((size_t)ncpu * sizeof *cpus);
    if (!cp || !soa || !idx || !ref || !cls || !cpus) {
        fprintf(stderr, "bench_cull: out of memory for %zu patches\n", count);
        return 1;
    }
    make_patches(cp, count, n, m, 0x5eed0000u + (uint64_t)NPOINTS);
    for (p = 0; p < count; p++)
        for (i = 0; i < NPOINTS * 4; i++)
            soa[(size_t)i * count + p] = cp[p * NPOINTS + (size_t)(i / 4)][i % 4];
    for (p = 0; p < count * NPOINTS; p++)
        idx[p] = (uint32_t)p;
    d.count = count;
    d.cp = (const float(*)[4])cp;
    d.soa = soa;
    d.idx = idx;
    if ((ncpus = usable_cpus(cpus, ncpu)))
        ncpu = ncpus;

    run_classify(&d, 0, count, ref); /* the classes the other paths are compared with */
    for (p = 0; p < count; p++)
        counts[ref[p] < 3 ? ref[p] : 2]++;
    if (batch) {
        status = batch_line(&d, cls, ref);
    } else {
        paper = measure(run_paper, &d, cls, 0, &used);
        if (variant)
            variant_rows(&d, cls, ref, counts, peak, paper);
        else
            plain_rows(&d, cls, ref, counts, peak, paper, used, ncpu, ncpus ? cpus : NULL);
    }
    free(cp);
    free(soa);
    free(idx);
    free(ref);
    free(cls);
    free(cpus);
    return status;
}
