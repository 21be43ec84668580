/* conedata.h: the per-patch NCONE and TCONE cones of bench/cones.c in the layout cone.comp
 * reads, computed once per model on the CPU. */
#ifndef RENDER_CONEDATA_H
#define RENDER_CONEDATA_H

#include "bez.h"
#include "render.h"

/* Fills out (8 floats a patch: axis, half-angle or -1 when the cone never culls; sphere centre,
 * radius) with the cones of method (RENDER_TCONE or RENDER_NCONE) of m's patches, computed in
 * double from the float points, the axis negated for inward models. Returns 0, or -1 for a
 * non-finite patch. */
int conedata_fill(float *out, const bez_model *m, render_method method, int inward);

#endif
