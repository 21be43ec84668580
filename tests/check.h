/* check.h: the small harness every tests/test_*.c program uses.
 * Each check prints "ok - NAME" or "not ok - NAME: detail"; tests/run.sh counts the lines. */
#ifndef CHECK_H
#define CHECK_H

#include <stdarg.h>
#include <stdio.h>

static int check_failed_count;

/* Reports one named check; detail (printf-style, may be "") is printed only on failure.
 * Returns ok. */
static int check(int ok, const char *name, const char *detail, ...)
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

/* The exit status of a test program: 0 when every check passed. */
static int check_exit(void)
{
    return check_failed_count ? 1 : 0;
}

#endif
