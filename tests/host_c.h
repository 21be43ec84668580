/* host_c.h: what the hosts built around an emitted C header share, as C and as C++: the test
 * helpers with C linkage, host_report, and FN and MACRO (the header's names by -DPFX, -DUPFX). */
#ifndef HOST_C_H
#define HOST_C_H

#ifdef __cplusplus
extern "C" {
#endif
#include "check.h"
#include "kref.h"
#ifdef __cplusplus
}
#endif

#define CAT2(a, b) a##b
#define CAT(a, b) CAT2(a, b)
#define FN(name) CAT(PFX, name)
#define MACRO(name) CAT(UPFX, name)

/* kref_report under the name "LABEL WHAT" (LABEL: o's --name); 1 if its checks passed. */
static inline int host_report(const kref_result *res, const kref_args *o, const char *what)
{
    char name[200];
    snprintf(name, sizeof name, "%s %s", o->label, what);
    return kref_report(res, name);
}

#endif
