/* check.h: the small harness every tests/test_*.c program uses.
 * Each check prints "ok - NAME" or "not ok - NAME: detail"; tests/run.sh counts the lines. */
#ifndef CHECK_H
#define CHECK_H

#include "core/ptp.h"

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

/* The test program's deterministic pseudo-random stream (ptp_splitmix64): a program seeds it by
 * assigning check_rng before its first draw. */
static uint64_t check_rng = 1;

static inline uint64_t check_rnd(void)
{
    return ptp_splitmix64(&check_rng);
}

/* A value below n (> 0; the modulo bias does not matter here). */
static inline unsigned check_rnd_below(unsigned n)
{
    return (unsigned)(check_rnd() % n);
}

/* A uniform value of at most bits bits (0 < bits <= 128). */
static inline ptp_u128 check_rnd_bits(int bits)
{
    ptp_u128 u = check_rnd();
    u = (u << 64) | check_rnd();
    return bits >= 128 ? u : u & (((ptp_u128)1 << bits) - 1);
}

/* Writes v in decimal to buf (at least 41 bytes), independently of the library's i128_to_str;
 * returns buf. */
static inline char *check_i128_str(char *buf, ptp_i128 v)
{
    const uint64_t e19 = 10000000000000000000u;
    ptp_u128 u = v < 0 ? (ptp_u128)0 - (ptp_u128)v : (ptp_u128)v;
    uint64_t parts[3];
    int n = 0, i;
    char *p = buf;
    do {
        parts[n++] = (uint64_t)(u % e19);
        u /= e19;
    } while (u);
    if (v < 0)
        *p++ = '-';
    p += sprintf(p, "%llu", (unsigned long long)parts[n - 1]);
    for (i = n - 2; i >= 0; i--)
        p += sprintf(p, "%019llu", (unsigned long long)parts[i]);
    return buf;
}

/* The exit status of a test program: 0 when every check passed. */
static inline int check_exit(void)
{
    return check_failed_count ? 1 : 0;
}

#endif
