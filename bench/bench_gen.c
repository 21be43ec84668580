/* bench_gen.c: `make bench-gen`: wall time and peak memory of `ptpgen --target json` per bidegree.
 * Runs the installed-style binary as a user would, and the exact-fraction Python derivation for scale. */
#define _DEFAULT_SOURCE
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

/* Runs argv with stdout to /dev/null; stores wall seconds and peak RSS (KiB). Returns the
 * exit status, or -1 if it could not run. */
static int run(char *const argv[], double *secs, long *rss_kib)
{
    struct timespec a, b;
    struct rusage ru;
    int status;
    pid_t pid;
    clock_gettime(CLOCK_MONOTONIC, &a);
    if ((pid = fork()) < 0)
        return -1;
    if (pid == 0) {
        int fd = open("/dev/null", O_WRONLY);
        dup2(fd, 1);
        execvp(argv[0], argv);
        _exit(127);
    }
    if (wait4(pid, &status, 0, &ru) < 0)
        return -1;
    clock_gettime(CLOCK_MONOTONIC, &b);
    *secs = (double)(b.tv_sec - a.tv_sec) + (double)(b.tv_nsec - a.tv_nsec) * 1e-9;
    *rss_kib = ru.ru_maxrss;
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

int main(int argc, char **argv)
{
    static const int degrees[] = {1, 2, 3, 4, 5, 6, 7, 8, 12, 16};
    const char *ptpgen = argc > 1 ? argv[1] : "./ptpgen";
    int python = argc > 2 ? strcmp(argv[2], "--no-python") != 0 : 1;
    size_t d;
    printf("ptpgen --target json: median wall time and peak memory of the whole process\n");
    printf("%-7s %7s %12s %10s %14s %9s\n", "degree", "runs", "wall", "peak RSS", "python exact",
               "speedup");
    for (d = 0; d < sizeof degrees / sizeof *degrees; d++) {
        char deg[16], py_deg[8];
        char *args[] = {(char *)ptpgen, "--degree", deg, "--target", "json", NULL};
        char *py[] = {"python3", "tests/ref_derive.py", py_deg, py_deg, NULL};
        int k = degrees[d], runs = k <= 4 ? 200 : k <= 8 ? 10 : 1, r;
        double t[200], med, pysecs = 0;
        long rss = 0, rss1;
        snprintf(deg, sizeof deg, "%dx%d", k, k);
        snprintf(py_deg, sizeof py_deg, "%d", k);
        for (r = 0; r < runs; r++) {
            if (run(args, &t[r], &rss1) != 0) {
                fprintf(stderr, "bench_gen: %s --degree %s failed\n", ptpgen, deg);
                return 1;
            }
            rss = rss1 > rss ? rss1 : rss;
        }
        qsort(t, (size_t)runs, sizeof *t, cmp_double);
        med = t[runs / 2];
        printf("%-7s %7d %9.3f ms %7ld KiB", deg, runs, med * 1e3, rss);
        if (python && k <= 8 && run(py, &pysecs, &rss1) == 0)
            printf(" %12.3f s %8.0fx\n", pysecs, pysecs / med);
        else
            printf(" %14s %9s\n", "-", "-");
    }
    return 0;
}
