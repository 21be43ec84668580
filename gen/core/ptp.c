/* ptp.c: the shared error helper.
 * Library functions report failures through ptp_fail and return its status. */
#include "core/ptp.h"

#include <stdarg.h>
#include <stdio.h>

int ptp_fail(ptp_error *err, int status, const char *fmt, ...)
{
    if (err) {
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(err->msg, sizeof err->msg, fmt, ap);
        va_end(ap);
        err->status = status;
    }
    return status;
}
