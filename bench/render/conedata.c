/* conedata.c: bench/cones.c's cone_tcone and cone_ncone per patch, rounded to the float layout
 * of cone.comp (whose per-eye test is cone_cull's). */
#include "conedata.h"

#include "cones.h"

int conedata_fill(float *out, const bez_model *m, render_method method, int inward)
{
    for (size_t p = 0; p < m->npatches; p++) {
        cone_patch b = {.domain = CONE_QUAD};
        cone_bound c;
        float *o = out + p * 8;
        for (int k = 0; k < 16; k++)
            for (int i = 0; i < 3; i++)
                b.p[k][i] = m->pts[(p * 16 + (size_t)k) * 3 + (size_t)i];
        if ((method == RENDER_TCONE ? cone_tcone(&b, &c) : cone_ncone(&b, &c)) != CONE_OK)
            return -1;
        for (int i = 0; i < 3; i++) {
            o[i] = (float)(inward ? -c.axis[i] : c.axis[i]);
            o[4 + i] = (float)c.center[i];
        }
        o[3] = c.usable ? (float)c.alpha : -1.0f;
        o[7] = (float)c.radius;
    }
    return 0;
}
