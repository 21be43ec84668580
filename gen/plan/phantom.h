/* phantom.h: OpenSubdiv's phantom vertices of a B-spline patch's boundary edges (--basis
 * bspline): for each edge bit of Far::PatchParam::GetBoundary() (1 v = 0, 2 u = 1, 4 v = 1,
 * 8 u = 0), its four vertices p0 with the two inward p1, p2, extrapolated p0 = 2 p1 - p2. */
#ifndef PHANTOM_H
#define PHANTOM_H
#include "plan/plan.h"

/* Fills q[b][k] with the input indices {p0, p1, p2} of phantom k of edge bit b, for the 16
 * vertices of a bicubic plan's input (plan_input_index). The writers apply bits 0 to 3 in
 * turn, each reading the values the earlier ones wrote. */
void phantom_table(int q[4][4][3], const plan_slp *p);

#endif
