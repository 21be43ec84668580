/* fmt.h: what every emitter writes the same way: the banner, file names, macro prefixes and
 * float literals. Pure formatting: no derivation, no target knowledge. */
#ifndef FMT_H
#define FMT_H

#include "emit/out.h"

/* Writes to file (size bytes) the file name a kernel is meant for: the prefix without its
 * trailing '_' and the extension, e.g. "ptp_3x3.comp". */
void fmt_file_name(char *file, size_t size, const char *prefix, const char *ext);
/* Appends the banner (contract and conventions) as a C-style comment; interface, if not NULL,
 * is the target's description of its bindings or signature and dispatch. */
void fmt_banner(sbuf *o, const tp_table *t, const out_info *info, const char *file_name,
                const char *language, const char *interface);
/* Writes prefix in upper case to up (size bytes, truncating): the prefix of generated macros. */
void fmt_upper(char *up, size_t size, const char *prefix);
/* Writes the float literal nearest to w, e.g. "-3.85714293f", to buf (48 bytes); returns buf. */
char *fmt_float_literal(char *buf, const rat *w);

#endif
