/* peak.c: `make bench`'s own measure of this machine's peak single-precision GFLOP/s, on one core
 * and on every core it may use, from independent fused multiply-add chains mixed with add chains. */
#define _GNU_SOURCE
#include <pthread.h>
#include <sched.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>
#include <unistd.h>

/* The widest vector the target has, as a GNU vector-extension type (compile with -O3
 * -march=native and -ffp-contract=fast, so that a * b + c becomes one fused multiply-add). */
#if defined(__AVX512F__)
#define VBYTES 64
#elif defined(__AVX__)
#define VBYTES 32
#else
#define VBYTES 16
#endif
typedef float vec __attribute__((vector_size(VBYTES)));
#define LANES (VBYTES / (int)sizeof(float))

/* Independent chains: NFMA of a = a * m + c and NADD of s = s + c. 8 FMA chains cover a 4-cycle
 * latency at two FMAs a cycle; the adds issue beside them where the core has separate add pipes
 * (Zen). With the two constants they fit the register file: 32 registers with AVX-512, 16 else. */
#define NFMA 8
#if VBYTES == 64
#define NADD 8
#else
#define NADD 4
#endif
#define FLOPS_PER_ITER ((2 * NFMA + NADD) * LANES)

/* Runs iters iterations of the chains; returns a sum of the accumulators, so that none is dead. */
static float chains(long iters, float mf, float cf)
{
    vec a[NFMA], s[NADD], m, c;
    float sum = 0.0f;
    long it;
    int i, l;
    for (i = 0; i < LANES; i++) {
        m[i] = mf;
        c[i] = cf;
    }
    for (i = 0; i < NFMA; i++)
        a[i] = c * (float)(i + 1);
    for (i = 0; i < NADD; i++)
        s[i] = c * (float)(i + 2);
    for (it = 0; it < iters; it++) {
        for (i = 0; i < NFMA; i++)
            a[i] = a[i] * m + c;
        for (i = 0; i < NADD; i++)
            s[i] = s[i] + c;
    }
    for (i = 0; i < NFMA; i++)
        for (l = 0; l < LANES; l++)
            sum += a[i][l];
    for (i = 0; i < NADD; i++)
        for (l = 0; l < LANES; l++)
            sum += s[i][l];
    return sum;
}

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

/* The constants come from volatile objects, so the compiler cannot fold the chains. */
static volatile float mul_v = 0.9999999f, add_v = 1e-7f;

/* One thread of a run: pinned to its CPU when cpu >= 0, it runs iters iterations into out. */
typedef struct {
    int cpu;
    long iters;
    volatile float out;
} worker;

static void *work(void *arg)
{
    worker *w = arg;
    if (w->cpu >= 0) {
        cpu_set_t set;
        CPU_ZERO(&set);
        CPU_SET(w->cpu, &set);
        sched_setaffinity(0, sizeof set, &set);
    }
    w->out = chains(w->iters, mul_v, add_v);
    return NULL;
}

/* GFLOP/s of nthreads threads (threads pinned to the CPUs of cpus[], or unpinned when cpus
 * is NULL) each running iters iterations: the best of reps runs; 0 if a thread cannot start. */
static double gflops(int nthreads, const int *cpus, long iters, int reps)
{
    double best = 0.0;
    worker *w = malloc((size_t)nthreads * sizeof *w);
    pthread_t *th = malloc((size_t)nthreads * sizeof *th);
    int r, t, started = 0;
    if (!w || !th)
        goto out;
    for (r = 0; r < reps; r++) {
        double t0 = now(), secs;
        for (t = 0; t < nthreads; t++) {
            w[t].cpu = cpus ? cpus[t] : -1;
            w[t].iters = iters;
            if (pthread_create(&th[t], NULL, work, &w[t]))
                break;
        }
        started = t;
        for (t = 0; t < started; t++)
            pthread_join(th[t], NULL);
        if (started < nthreads)
            goto out;
        secs = now() - t0;
        if ((double)iters * FLOPS_PER_ITER * nthreads / secs * 1e-9 > best)
            best = (double)iters * FLOPS_PER_ITER * nthreads / secs * 1e-9;
    }
out:
    free(w);
    free(th);
    return best;
}

/* Prints one line "peak GFLOPS_1 GFLOPS_ALL NCPU BITS": GFLOP/s on one core and on the NCPU cores
 * this process may use (one pinned thread each; every online core, unpinned, when its affinity
 * cannot be read), counting an FMA as 2 flops, and the vector width in bits. */
int main(void)
{
    long ncpu = sysconf(_SC_NPROCESSORS_ONLN), iters = 1 << 20;
    int *cpus, n = 0, c;
    cpu_set_t allowed;
    double one, all, t0;
    worker cal;
    if (ncpu < 1)
        ncpu = 1;
    cpus = malloc((size_t)ncpu * sizeof *cpus);
    if (!cpus)
        return 1;
    /* the CPUs this process may run on (taskset narrows them), in order, one per thread */
    if (sched_getaffinity(0, sizeof allowed, &allowed) == 0)
        for (c = 0; c < CPU_SETSIZE && n < ncpu; c++)
            if (CPU_ISSET(c, &allowed))
                cpus[n++] = c;
    /* about 0.1 s a run on one core */
    cal.cpu = n ? cpus[0] : -1;
    cal.iters = iters;
    t0 = now();
    work(&cal);
    iters = (long)((double)iters * 0.1 / (now() - t0 + 1e-9)) + 1;
    one = gflops(1, n ? cpus : NULL, iters, 5);
    if (n)
        ncpu = n;
    all = gflops((int)ncpu, n ? cpus : NULL, iters, 5);
    free(cpus);
    if (one <= 0.0 || all <= 0.0)
        return 1;
    printf("peak %.1f %.1f %ld %d\n", one, all, ncpu, VBYTES * 8);
    return 0;
}
