/* check.h: the small harness every tests/test_*.c program uses.
 * Each check prints "ok - NAME" or "not ok - NAME: detail"; tests/run.sh counts the lines. */
#ifndef CHECK_H
#define CHECK_H

#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>

static int check_failed_count;

/* Reports one named check; detail (printf-style, may be "") is printed only on failure.
 * Returns ok. */
static inline int check(int ok, const char *name, const char *detail, ...)
{
    if (ok) {
        printf("ok - %s\n", name);
    } else {
        va_list ap;
        printf("not ok - %s: ", name);
        va_start(ap, detail);
        vprintf(detail, ap);
        va_end(ap);
        printf("\n");
        check_failed_count++;
    }
    fflush(stdout);
    return ok;
}

/* A property checked on many cases, reported as one check line with the first counterexample:
 * prop_init, then per case tried++ and prop_fail on a failure, then prop_report. */
typedef struct {
    char name[220];
    long tried, bad;
    char detail[1500];
} prop;

static inline void prop_init(prop *p, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(p->name, sizeof p->name, fmt, ap);
    va_end(ap);
    p->tried = p->bad = 0;
    p->detail[0] = '\0';
}

/* Records a failure; the first one's detail (printf-style) is kept. */
static inline void prop_fail(prop *p, const char *fmt, ...)
{
    if (!p->bad++) {
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(p->detail, sizeof p->detail, fmt, ap);
        va_end(ap);
    }
}

static inline void prop_report(const prop *p)
{
    check(!p->bad && p->tried > 0, p->name, "%s (%ld of %ld cases failed)",
          p->tried ? p->detail : "no case was tried", p->bad, p->tried);
}

/* splitmix64: the next value of the deterministic pseudo-random stream *state. */
static inline uint64_t check_rand(uint64_t *state)
{
    uint64_t z = (*state += 0x9E3779B97F4A7C15u);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9u;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBu;
    return z ^ (z >> 31);
}

/* The exit status of a test program: 0 when every check passed. */
static inline int check_exit(void)
{
    return check_failed_count ? 1 : 0;
}

#endif
