/* template.h: the kernel templates compiled into ptpgen, and filling their named slots.
 * A slot is {{NAME}}; every slot a template names must be given, and every slot given used. */
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

/* Appends template `name` to o with every {{NAME}} replaced by its slot's value. Fails with
 * PTP_EINTERNAL if the template is missing, names an unknown slot, or leaves a slot unused. */
int tpl_fill(sbuf *o, const char *name, const tpl_slot *slots, size_t nslots, ptp_error *err);

#endif
