/* emit_c_refine.h: the second look of the C header under --refine K, for emit_c.c: the patch's
 * scalar Bezier function e.T subdivided by de Casteljau, per patch domain. */
#ifndef EMIT_C_REFINE_H
#define EMIT_C_REFINE_H

#include "emit/out.h"

/* Appends <prefix>split_class (with its helpers) and <prefix>refined(cp, eye), the class of a
 * patch the plane values leave silhouette: its function e.T, whose control values are the plane
 * values in t's plane numbering, split into four pieces while their corners agree, up to
 * info->refine levels (quad: quarters at u = v = 1/2; triangle: the four triangles of the edge
 * midpoints). up is the upper-case prefix. Needs <prefix>values and the class macros before it.
 * With info->certified, split_class takes <prefix>cval (a double value and a bound on its error)
 * and refined starts from <prefix>certify64(cp, eye, d, b), which must come before it. */
void emit_c_refine(sbuf *o, const tp_table *t, const out_info *info, const char *up);

#endif
