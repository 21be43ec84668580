/* phantom.c: the phantom vertices of a B-spline patch's boundary edges (phantom.h). */
#include "plan/phantom.h"

void phantom_table(int q[4][4][3], const plan_slp *p)
{
    /* per edge: the first vertex (i, j), i along u, the step along the edge, the step inward */
    static const int edge[4][6] = {{0, 0, 1, 0, 0, 1}, {3, 0, 0, 1, -1, 0},
                                   {0, 3, 1, 0, 0, -1}, {0, 0, 0, 1, 1, 0}};
    int b, k, s;
    for (b = 0; b < 4; b++)
        for (k = 0; k < 4; k++)
            for (s = 0; s < 3; s++) {
                const int *e = edge[b];
                int i = e[0] + k * e[2] + s * e[4], j = e[1] + k * e[3] + s * e[5];
                q[b][k][s] = plan_input_index(p, i, j);
            }
}
