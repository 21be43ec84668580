/* sbuf.h: a growable string that output is built in before it is written anywhere.
 * Allocation failure is sticky: later appends do nothing and sbuf_failed reports it. */
#ifndef SBUF_H
#define SBUF_H

#include <stddef.h>

typedef struct {
    char *s;      /* NUL-terminated contents (NULL while empty) */
    size_t len, cap;
    int failed;   /* an allocation failed */
} sbuf;

/* Initializes b as the empty string. */
void sbuf_init(sbuf *b);
/* Frees b's storage. */
void sbuf_clear(sbuf *b);
/* Appends the printf-style text. */
void sbuf_printf(sbuf *b, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;
/* Appends s. */
void sbuf_puts(sbuf *b, const char *s);

#endif
