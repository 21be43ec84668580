/* emit_c_boundary.h: the B-spline header's boundary section (extrapolate,
 * classify_indexed_boundary): OpenSubdiv's phantom vertices, from a mask per patch. */
#ifndef EMIT_C_BOUNDARY_H
#define EMIT_C_BOUNDARY_H

#include "core/ptp.h"
#include "emit/out.h"
#include "emit/sbuf.h"

/* Appends templates/c/boundary.h filled for info (nothing unless its input is B-spline). */
int emit_c_boundary(sbuf *o, const out_info *info, ptp_error *err);

#endif
