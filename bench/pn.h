/* pn.h: curved PN triangles (Vlachos, Peters, Boyd and Mitchell 2001): the cubic triangular Bezier
 * patch of a mesh triangle from its three positions and vertex normals, in ptpgen's point order. */
#ifndef PN_H
#define PN_H

/* Control points of a cubic triangle. */
#define PN_POINTS 10

/* The ten control points b of the PN triangle of corners p[0], p[1], p[2] with vertex normals
 * n[0], n[1], n[2], in ptpgen's order for degree 3 (descending (i, j)): b300, b210, b201, b120,
 * b111, b102, b030, b021, b012, b003, with b300 = p[0] (u = 1), b030 = p[1] (v = 1) and
 * b003 = p[2] (w = 1). Edge points are b210 = (2 P1 + P2 - w12 N1) / 3, w_ij = (Pj - Pi) . Ni,
 * and so on; the centre is b111 = E + (E - V) / 2, E the mean of the six edge points and V of
 * the corners. A normal need not be unit (it is used as n / |n|); a zero or non-finite normal
 * leaves the edge points at its corner on the straight edge. For corners in counter-clockwise
 * order seen from the side the normals point to, B_u x B_v points that way too. */
void pn_triangle(double b[PN_POINTS][3], const double p[3][3], const double n[3][3]);

#endif
