/* sbuf.c: the growable output string.
 * Appends are amortized O(1); a failed allocation marks the buffer failed. */
#include "emit/sbuf.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void sbuf_init(sbuf *b)
{
    b->s = NULL;
    b->len = b->cap = 0;
    b->failed = 0;
}

void sbuf_clear(sbuf *b)
{
    free(b->s);
    sbuf_init(b);
}

/* Makes room for n more characters and the NUL; returns 0 when b has failed. */
static int grow(sbuf *b, size_t n)
{
    size_t cap;
    char *s;
    if (b->failed)
        return 0;
    if (b->len + n + 1 <= b->cap)
        return 1;
    cap = b->cap ? b->cap : 4096;
    while (cap < b->len + n + 1)
        cap *= 2;
    if (!(s = realloc(b->s, cap))) {
        b->failed = 1;
        return 0;
    }
    b->s = s;
    b->cap = cap;
    return 1;
}

void sbuf_printf(sbuf *b, const char *fmt, ...)
{
    va_list ap;
    size_t room = b->cap - b->len;
    int n;
    if (b->failed)
        return;
    va_start(ap, fmt); /* usually fits in the room left: one formatting pass */
    n = vsnprintf(room ? b->s + b->len : NULL, room, fmt, ap);
    va_end(ap);
    if (n < 0) {
        b->failed = 1;
        return;
    }
    if ((size_t)n >= room) {
        if (!grow(b, (size_t)n))
            return;
        va_start(ap, fmt);
        vsnprintf(b->s + b->len, (size_t)n + 1, fmt, ap);
        va_end(ap);
    }
    b->len += (size_t)n;
}

void sbuf_puts(sbuf *b, const char *s)
{
    size_t n = strlen(s);
    if (!grow(b, n))
        return;
    memcpy(b->s + b->len, s, n + 1);
    b->len += n;
}
