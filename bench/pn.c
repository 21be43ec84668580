/* pn.c: the control points of curved PN triangles (pn.h): corners, edge points projected into the
 * corners' tangent planes, and the centre point. */
#include "pn.h"

#include <math.h>

/* The edge point next to corner a towards corner c: (2 Pa + Pc - ((Pc - Pa) . Na) Na) / 3 with
 * Na the unit normal; without a usable normal, (2 Pa + Pc) / 3. */
static void edge_point(double r[3], const double pa[3], const double pc[3], const double na[3])
{
    double nn = na[0] * na[0] + na[1] * na[1] + na[2] * na[2], w = 0;
    int k;
    if (nn > 0 && isfinite(nn))
        for (k = 0; k < 3; k++)
            w += (pc[k] - pa[k]) * na[k] / nn;
    for (k = 0; k < 3; k++)
        r[k] = (2 * pa[k] + pc[k] - (w != 0 ? w * na[k] : 0)) / 3;
}

void pn_triangle(double b[PN_POINTS][3], const double p[3][3], const double n[3][3])
{
    /* The edge point at corner a towards c, and where it goes: b210 at 1, b201 at 2, ... */
    static const int edge[6][3] = {{0, 1, 1}, {0, 2, 2}, {1, 0, 3},
                                   {1, 2, 7}, {2, 1, 8}, {2, 0, 5}};
    double e[3] = {0, 0, 0}, v[3];
    int i, k;
    for (k = 0; k < 3; k++) {
        b[0][k] = p[0][k];
        b[6][k] = p[1][k];
        b[9][k] = p[2][k];
        v[k] = (p[0][k] + p[1][k] + p[2][k]) / 3;
    }
    for (i = 0; i < 6; i++) {
        edge_point(b[edge[i][2]], p[edge[i][0]], p[edge[i][1]], n[edge[i][0]]);
        for (k = 0; k < 3; k++)
            e[k] += b[edge[i][2]][k] / 6;
    }
    for (k = 0; k < 3; k++)
        b[4][k] = e[k] + (e[k] - v[k]) / 2;
}
