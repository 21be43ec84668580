/* host_refine.c: runs a C header emitted with --refine K (quad or triangle): decided classes
 * kept, refined ones never against samples; --certified ones also on exact data. */
#include "host_c.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The counts of one run over all sets. */
typedef struct {
    size_t patches, refined, unsafe, changed, batch_bad;
    size_t given_up; /* certified: silhouette where the control planes clearly decide */
    size_t exact, exact_decided, exact_unsafe; /* exact data: patches, back or front, unsafe */
    char first[256], first_exact[256];
    double *grid; /* the basis functions at the exact check's points: grid[x * L + P] */
    int ngrid;    /* their number */
} tally;

/* The Bernstein polynomial binomial(n, i) t^i (1 - t)^(n - i); with c = j and n - i the
 * trinomial n!/(i! j! (n-i-j)!) t^i s^j (1 - t - s)^(n-i-j) when s is given (c >= 0). */
static double basis1(int n, int i, int j, double t, double s)
{
    double b = 1, w = 1 - t - (j >= 0 ? s : 0);
    int x, k = n - i - (j >= 0 ? j : 0);
    for (x = 1; x <= i; x++) /* binomial(n, i) * binomial(n - i, j), exact in double */
        b = b * (n - i + x) / x;
    for (x = 1; x <= j; x++)
        b = b * (k + x) / x;
    for (x = 0; x < i; x++)
        b *= t;
    for (x = 0; x < j; x++)
        b *= s;
    for (x = 0; x < k; x++)
        b *= w;
    return b;
}

/* The basis function of plane P of dom at (u, v): B_I(u) B_J(v) (quad), or the triangular
 * D!/(I! J! K!) u^I v^J w^K, w = 1 - u - v, D = I + J + K (triangle). */
static double basis(const tp_domain *dom, int P, double u, double v)
{
    int I, J;
    tp_domain_plane_ij(&I, &J, dom, P);
    if (dom->kind == TP_TRI)
        return basis1(dom->pu, I, J, u, v);
    return basis1(dom->pu, I, -1, u, 0) * basis1(dom->pv, J, -1, v, 0);
}

/* The largest and smallest of the scalar function with control values d (the plane values, in
 * dom's plane numbering) at the points (a, b) / (n - 1) of dom's domain (a + b <= n - 1 for
 * triangles). */
static void sample(double *lo, double *hi, const double *d, const tp_domain *dom, int n)
{
    int a, b, P;
    *lo = 1e300;
    *hi = -1e300;
    for (a = 0; a < n; a++)
        for (b = 0; b < n && (dom->kind != TP_TRI || a + b < n); b++) {
            double f = 0;
            for (P = 0; P < dom->nplanes; P++)
                f += d[P] * basis(dom, P, (double)a / (n - 1), (double)b / (n - 1));
            *lo = f < *lo ? f : *lo;
            *hi = f > *hi ? f : *hi;
        }
}

/* split_class of control values f taken as exact (certified: each with bound 0). */
static unsigned split_exact(const float *f, int L)
{
#if MACRO(CERTIFIED)
    FN(cval) *d = (FN(cval) *)malloc((size_t)L * sizeof *d);
    unsigned c;
    int i;
    for (i = 0; i < L; i++) {
        d[i].v = f[i];
        d[i].b = 0;
    }
    c = FN(split_class)(d, MACRO(REFINE));
    free(d);
    return c;
#else
    (void)L;
    return FN(split_class)(f, MACRO(REFINE));
#endif
}

#if MACRO(CERTIFIED)
/* The number of random pairs (a, b) whose mid bound is below the exact error of the average: the
 * inputs' bounds averaged plus half the rounding error of s = a.v + b.v (Knuth's two-sum, exact).
 * Half the pairs have exact inputs (bound 0), so that only the rounding term covers the error. */
static size_t mid_short(void)
{
    uint64_t rng = 12345;
    size_t bad = 0, i;
    for (i = 0; i < 200000; i++) {
        FN(cval) a, b, r;
        double s, bb, err, need;
        rng = rng * 6364136223846793005u + 1442695040888963407u;
        a.v = ldexp((double)(rng >> 11), (int)(rng % 41) - 73);
        b.v = ldexp((double)(rng >> 13) * (rng & 1 ? 1 : -1), (int)(rng % 37) - 70);
        a.b = i % 2 ? 0 : ldexp(fabs(a.v), -50 - (int)(rng % 9));
        b.b = i % 2 ? 0 : ldexp(fabs(b.v), -52);
        r = FN(mid)(a, b);
        s = a.v + b.v;
        bb = s - a.v;
        err = (a.v - (s - bb)) + (b.v - bb); /* a.v + b.v = s + err exactly */
        need = 0.5 * (a.b + b.b) + 0.5 * fabs(err);
        bad += !(r.b >= need) || r.v != 0.5 * s;
    }
    return bad;
}
#endif

/* The crafted functions: for every plane P, its basis function less r times its peak (at the
 * point its indices name), r = 0.8 and 0.9: positive only around that point, so that a
 * subdivision that misses a region calls some of them back. Counts into t. */
static void crafted(tally *t, const kref_ref *ref)
{
    const tp_domain *dom = &ref->t.dom;
    double *d = (double *)malloc((size_t)ref->L * sizeof *d), lo, hi;
    float *f = (float *)malloc((size_t)ref->L * sizeof *f);
    double D = dom->pu > 0 ? dom->pu : 1; /* triangles of degree 1: one constant plane */
    int P, Q, I, J, r;
    for (P = 0; P < ref->L; P++)
        for (r = 8; r <= 9; r++) {
            unsigned c;
            tp_domain_plane_ij(&I, &J, dom, P);
            for (Q = 0; Q < ref->L; Q++)
                f[Q] = (float)(-r * 0.1 * basis(dom, P, I / D, J / (dom->kind == TP_TRI ? D : dom->pv)) +
                               (Q == P));
            for (Q = 0; Q < ref->L; Q++)
                d[Q] = f[Q];
            c = split_exact(f, ref->L);
            sample(&lo, &hi, d, dom, 33);
            if ((c == KREF_BACK && hi > 0) || (c == KREF_FRONT && lo < 0)) {
                if (!t->unsafe++)
                    snprintf(t->first, sizeof t->first, "crafted plane %d, r = 0.%d: class %u but "
                             "samples in [%g, %g]", P, r, c, lo, hi);
            }
        }
    free(d);
    free(f);
}

/* The points (a, b) / (n - 1) of dom's domain (a + b <= n - 1 for triangles), n = 17, and the
 * value of every basis function there: t->grid, t->ngrid. */
static void exact_grid(tally *t, const tp_domain *dom)
{
    int n = 17, a, b, P, x = 0;
    t->grid = (double *)malloc((size_t)(n * n * dom->nplanes) * sizeof *t->grid);
    for (a = 0; a < n; a++)
        for (b = 0; b < n && (dom->kind != TP_TRI || a + b < n); b++, x++)
            for (P = 0; P < dom->nplanes; P++)
                t->grid[x * dom->nplanes + P] = basis(dom, P, (double)a / (n - 1), (double)b / (n - 1));
    t->ngrid = x;
}

/* 1 if plane P's basis function peaks at a corner of dom's domain, where it is the function. */
static int corner_plane(const tp_domain *dom, int P)
{
    int I, J, K;
    tp_domain_plane_ij(&I, &J, dom, P);
    K = dom->pu - I - J;
    if (dom->kind == TP_TRI)
        return I == dom->pu || J == dom->pu || K == dom->pu;
    return (I == 0 || I == dom->pu) && (J == 0 || J == dom->pv);
}

/* Nonzero when class c (back or front) of patch p of the exact set s is unsafe under the rule: a
 * corner of the function (a corner plane's exact value) of the wrong sign (strict: or zero), or,
 * at t's grid, the function from the exact values beyond 2^-40 of its size on the wrong side.
 * Exact values that cannot be computed count as unsafe. */
static int exact_unsafe(const tally *t, const kref_ref *ref, const kref_set *s, size_t p, unsigned c)
{
    const tp_domain *dom = &ref->t.dom;
    signed char *sg = (signed char *)malloc((size_t)ref->L);
    double *x = (double *)malloc((size_t)ref->L * sizeof *x), wrong = c == KREF_BACK ? 1 : -1;
    int bad = kref_exact_signs(ref, s, p, sg, x) != 0, P, g;
    for (P = 0; !bad && P < ref->L; P++)
        bad = corner_plane(dom, P) && (sg[P] * wrong > 0 || (ref->rule == KREF_STRICT && !sg[P]));
    for (g = 0; !bad && g < t->ngrid; g++) {
        double f = 0, m = 0;
        for (P = 0; P < ref->L; P++) {
            f += x[P] * t->grid[g * ref->L + P];
            m += fabs(x[P]) * t->grid[g * ref->L + P];
        }
        bad = f * wrong > ldexp(m, -40);
    }
    free(sg);
    free(x);
    return bad;
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
        if (s->exact) {
            t->exact++;
            t->exact_decided += c != KREF_SILHOUETTE;
            if (c != KREF_SILHOUETTE && exact_unsafe(t, ref, s, p, c) && !t->exact_unsafe++)
                snprintf(t->first_exact, sizeof t->first_exact, "%s patch %zu: class %u", s->name, p, c);
        }
        if (rc != KREF_SILHOUETTE && !ambiguous) {
            if (ref->certified && c == KREF_SILHOUETTE)
                t->given_up++;
            else
                t->changed += c != (unsigned)rc;
            continue;
        }
        if (c == KREF_SILHOUETTE || ambiguous)
            continue;
        t->refined++;
        /* Back must mean no sample above the rounding slack, front none below it. */
        sample(&lo, &hi, d, &ref->t.dom, 33);
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

/* Before the sets: the crafted functions, and the grid of the exact check. */
static int ready(void *ctx, const kref_args *o, const kref_ref *ref)
{
    (void)o;
    crafted((tally *)ctx, ref);
    exact_grid((tally *)ctx, &ref->t.dom);
    return 0;
}

/* The check lines of all sets; 1 if they all passed. */
static int report(void *ctx, const kref_args *o, const kref_ref *ref)
{
    const tally *t = (const tally *)ctx;
    char name[300];
    int ok = 1;
    printf("# %s: %zu patches, %zu refined from silhouette to back or front\n", o->label,
           t->patches, t->refined);
    snprintf(name, sizeof name, "%s: the classes the control planes decide are kept", o->label);
    ok &= check(t->changed == 0, name, "%zu patches changed class", t->changed);
    snprintf(name, sizeof name, "%s: no refined class contradicts 33 samples a side", o->label);
    ok &= check(t->unsafe == 0, name, "%zu do; first: %s", t->unsafe, t->first);
    if (ref->L > 1) {
        snprintf(name, sizeof name, "%s: refinement decides some silhouette patches", o->label);
        ok &= check(t->refined > 0, name, "none of %zu patches", t->patches);
    } else { /* one plane: its value is the constant function, nothing is left to split */
        snprintf(name, sizeof name, "%s: one constant value: refinement decides nothing more",
                 o->label);
        ok &= check(t->refined == 0, name, "%zu of %zu patches refined", t->refined, t->patches);
    }
    snprintf(name, sizeof name, "%s: classify_batch equals classify", o->label);
    ok &= check(t->batch_bad == 0, name, "they differ on %zu patches", t->batch_bad);
#if MACRO(CERTIFIED)
    snprintf(name, sizeof name, "%s: mid's bound covers the rounding of 200000 random averages",
             o->label);
    ok &= check(mid_short() == 0, name, "it is short on %zu", mid_short());
#endif
    if (ref->certified) /* as the certified header without --refine (tests/host_c.c) */
        printf("# %s: certified: silhouette where the control planes clearly decide: %zu\n",
               o->label, t->given_up);
    if (t->exact) {
        printf("# %s: exact data: %zu patches, %zu back or front, %zu unsafe%s%s\n", o->label,
               t->exact, t->exact_decided, t->exact_unsafe, t->exact_unsafe ? "; first: " : "",
               t->first_exact);
        snprintf(name, sizeof name, "%s: on exact data no back or front is unsafe", o->label);
        if (ref->certified)
            ok &= check(t->exact_unsafe == 0, name, "%zu are; first: %s", t->exact_unsafe,
                        t->first_exact);
    }
    return ok;
}

int main(int argc, char **argv)
{
    static const kref_host host = {"host_refine", ready, run_set, report};
    tally t;
    int st;
    memset(&t, 0, sizeof t);
    st = kref_host_main(&host, &t, argc, argv);
    free(t.grid);
    return st ? st : check_exit();
}
