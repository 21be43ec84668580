/* template.c: fills the named slots of an embedded template.
 * A mismatch between a template and its emitter is an internal error, never silent output. */
#include "emit/template.h"

#include <string.h>

int tpl_fill(sbuf *o, const char *name, const tpl_slot *slots, size_t nslots, ptp_error *err)
{
    const char *text = NULL, *p;
    unsigned long used = 0;
    size_t i;
    for (i = 0; i < tpl_count && !text; i++)
        if (strcmp(tpl_files[i].name, name) == 0)
            text = tpl_files[i].text;
    if (!text)
        return ptp_fail(err, PTP_EINTERNAL, "template %s is not built in", name);
    if (nslots > 8 * sizeof used)
        return ptp_fail(err, PTP_EINTERNAL, "template %s: too many slots", name);
    for (p = text; *p;) {
        const char *open = strstr(p, "{{"), *close;
        size_t len;
        if (!open) {
            sbuf_puts(o, p);
            break;
        }
        if (!(close = strstr(open, "}}")))
            return ptp_fail(err, PTP_EINTERNAL, "template %s: unclosed {{", name);
        sbuf_printf(o, "%.*s", (int)(open - p), p);
        len = (size_t)(close - open - 2);
        for (i = 0; i < nslots; i++)
            if (strlen(slots[i].name) == len && strncmp(slots[i].name, open + 2, len) == 0)
                break;
        if (i == nslots)
            return ptp_fail(err, PTP_EINTERNAL, "template %s: unknown slot {{%.*s}}", name, (int)len,
                            open + 2);
        sbuf_puts(o, slots[i].value);
        used |= 1ul << i;
        p = close + 2;
    }
    for (i = 0; i < nslots; i++)
        if (!(used >> i & 1))
            return ptp_fail(err, PTP_EINTERNAL, "template %s: slot {{%s}} is never used", name,
                            slots[i].name);
    return o->failed ? ptp_fail(err, PTP_ENOMEM, "out of memory filling %s", name) : PTP_OK;
}
