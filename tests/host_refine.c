/* host_refine.c: runs a C header emitted with --refine K and checks the refined classes: equal to
 * the reference where the control planes decide, and never back or front against samples. */
#include "host_c.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The counts of one run over all sets. */
typedef struct {
    size_t patches, refined, unsafe, changed, batch_bad;
    char first[256];
} tally;

/* Bernstein basis values B^d_i(t), i = 0..d. */
static void bernstein(double *b, int d, double t)
{
    int i, k;
    b[0] = 1;
    for (k = 1; k <= d; k++) {
        double carry = 0;
        for (i = 0; i < k; i++) {
            double x = b[i];
            b[i] = carry + (1 - t) * x;
            carry = t * x;
        }
        b[k] = carry;
    }
}

/* The largest and smallest of the scalar patch sum d_IJ B_I(u) B_J(v) on an n x n grid, and
 * the largest bound (a sample's error allowance: the float evaluation of the values). */
static void sample(double *lo, double *hi, const double *d, int pu, int pv, int n)
{
    double bu[64], bv[64];
    int a, b, I, J;
    *lo = 1e300;
    *hi = -1e300;
    for (a = 0; a < n; a++) {
        bernstein(bu, pu, (double)a / (n - 1));
        for (b = 0; b < n; b++) {
            double f = 0;
            bernstein(bv, pv, (double)b / (n - 1));
            for (I = 0; I <= pu; I++)
                for (J = 0; J <= pv; J++)
                    f += d[I * (pv + 1) + J] * bu[I] * bv[J];
            *lo = f < *lo ? f : *lo;
            *hi = f > *hi ? f : *hi;
        }
    }
}

/* Classifies one set and counts into ctx (a tally); returns 0. */
static int run_set(void *ctx, const kref_ref *ref, const kref_set *s)
{
    tally *t = (tally *)ctx;
    size_t p, L = (size_t)ref->L;
    double *d = (double *)malloc(2 * L * sizeof *d), *bound = d + L;
    unsigned char *batch = (unsigned char *)malloc(s->count);
    FN(classify_batch)((const float(*)[4])s->cp, s->count, s->eye, batch);
    for (p = 0; p < s->count; p++) {
        const float(*cp)[4] = (const float(*)[4])s->cp + p * (size_t)ref->K;
        unsigned c = FN(classify)(cp, s->eye);
        int rc, ambiguous = 0;
        size_t i;
        double lo, hi, slack = 0;
        kref_values(ref, s, p, d, bound);
        rc = kref_classify(d, ref->L, ref->rule);
        for (i = 0; i < L; i++) {
            ambiguous |= bound[i] > 0 && (d[i] < 0 ? -d[i] : d[i]) <= bound[i];
            slack = bound[i] > slack ? bound[i] : slack;
        }
        t->patches++;
        t->batch_bad += batch[p] != c;
        if (rc != KREF_SILHOUETTE && !ambiguous) {
            t->changed += c != (unsigned)rc;
            continue;
        }
        if (c == KREF_SILHOUETTE || ambiguous)
            continue;
        t->refined++;
        /* Back must mean no sample above the rounding slack, front none below it. */
        sample(&lo, &hi, d, ref->t.dom.pu, ref->t.dom.pv, 33);
        if ((c == KREF_BACK && hi > slack) || (c == KREF_FRONT && lo < -slack)) {
            if (!t->unsafe++)
                snprintf(t->first, sizeof t->first, "%s patch %zu: class %u but samples in [%g, %g]",
                         s->name, p, c, lo, hi);
        }
    }
    free(d);
    free(batch);
    return 0;
}

int main(int argc, char **argv)
{
    kref_args o;
    kref_ref ref;
    tally t;
    char name[300];
    int ok = 1, st;
    memset(&t, 0, sizeof t);
    if ((st = kref_run_sets(&o, &ref, argc, argv, "host_refine", run_set, &t)))
        return st;
    printf("# %s: %zu patches, %zu refined from silhouette to back or front\n", o.label, t.patches,
           t.refined);
    snprintf(name, sizeof name, "%s: the classes the control planes decide are kept", o.label);
    ok &= check(t.changed == 0, name, "%zu patches changed class", t.changed);
    snprintf(name, sizeof name, "%s: no refined class contradicts 33x33 samples", o.label);
    ok &= check(t.unsafe == 0, name, "%zu do; first: %s", t.unsafe, t.first);
    snprintf(name, sizeof name, "%s: refinement decides some silhouette patches", o.label);
    ok &= check(t.refined > 0, name, "none of %zu patches", t.patches);
    snprintf(name, sizeof name, "%s: classify_batch equals classify", o.label);
    ok &= check(t.batch_bad == 0, name, "they differ on %zu patches", t.batch_bad);
    kref_clear(&ref);
    return check_exit() || !ok;
}
