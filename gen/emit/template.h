/* template.h: the templates compiled into ptpgen (the boilerplate of the C header and kernels,
 * templates/<target>/), and filling their slots {{NAME}}, each given and used exactly as named. */
#ifndef TEMPLATE_H
#define TEMPLATE_H

#include "core/ptp.h"
#include "emit/sbuf.h"

typedef struct {
    const char *name; /* path below templates/, e.g. "glsl/kernel.comp" */
    const char *text;
} tpl_file;

/* The embedded templates (build/<cc>/templates.c, made from templates/ by gen/embed). */
extern const tpl_file tpl_files[];
extern const size_t tpl_count;

typedef struct {
    const char *name;  /* NAME of {{NAME}} */
    const char *value;
} tpl_slot;

/* Appends template `name` to o with every {{NAME}} replaced by its slot's value, verbatim. Fails
 * with PTP_EINTERNAL if the template is missing, has an unclosed {{ or names an unknown slot,
 * a slot given is unused, or more slots are given than bits in an unsigned long; PTP_ENOMEM
 * if o failed. */
int tpl_fill(sbuf *o, const char *name, const tpl_slot *slots, size_t nslots, ptp_error *err);

#endif
