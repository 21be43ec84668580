/* kref.c: test data and the double-precision reference for executing emitted kernels.
 * The bound on a float32 evaluation is (terms + 16) * 2^-24 times the sum of |monomials|; exact
 * zeros (two equal points in every term of a plane) have bound 0. */
#include "kref.h"
#include "check.h"

#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define M_PI_6 0.52359877559829887308 /* 30 degrees: half the field of view */

/* Prints the usage failure as one "not ok" line; returns 2. */
static int usage(const char *host, const char *label, const char *detail)
{
    check(0, label ? label : host,
          "%s; usage: %s [FILE] [--kernel NAME] --degree N M --space clip|world "
          "--rule strict|degenerate [--block-threads PQ --patches-per-block Q] [--planes] "
          "[--groups-x-constant] (--random SETS COUNT SEED | --model PATH NEYES SEED)... "
          "--name LABEL",
          detail, host);
    return 2;
}

/* Parses a decimal integer in [lo, hi] into *out; 0 on success. */
static int parse_ull(const char *s, unsigned long long lo, unsigned long long hi,
                     unsigned long long *out)
{
    char *end;
    unsigned long long v;
    if (!s || *s < '0' || *s > '9')
        return -1;
    errno = 0;
    v = strtoull(s, &end, 10);
    if (errno || *end || v < lo || v > hi)
        return -1;
    *out = v;
    return 0;
}

int kref_parse_args(kref_args *o, int argc, char **argv, const char *host, unsigned need)
{
    int i, have_degree = 0, have_space = 0, have_rule = 0;
    unsigned long long a, b, c;
    memset(o, 0, sizeof *o);
    /* the label first, so that every usage failure carries it */
    for (i = 1; i + 1 < argc; i++)
        if (!strcmp(argv[i], "--name"))
            o->label = argv[i + 1];
    for (i = 1; i < argc; i++) {
        const char *s = argv[i];
        int left = argc - i - 1;
        if (!strcmp(s, "--name") && left >= 1) {
            o->label = argv[++i];
        } else if (!strcmp(s, "--kernel") && left >= 1) {
            o->kernel_name = argv[++i];
        } else if (!strcmp(s, "--degree") && left >= 2) {
            if (parse_ull(argv[i + 1], 1, PTP_MAX_DEGREE, &a) ||
                parse_ull(argv[i + 2], 1, PTP_MAX_DEGREE, &b))
                return usage(host, o->label, "--degree takes N M, each 1..16");
            o->n = (int)a;
            o->m = (int)b;
            have_degree = 1;
            i += 2;
        } else if (!strcmp(s, "--space") && left >= 1) {
            s = argv[++i];
            if (!strcmp(s, "clip"))
                o->space = KREF_CLIP;
            else if (!strcmp(s, "world"))
                o->space = KREF_WORLD;
            else
                return usage(host, o->label, "--space is clip or world");
            have_space = 1;
        } else if (!strcmp(s, "--rule") && left >= 1) {
            s = argv[++i];
            if (!strcmp(s, "strict"))
                o->rule = KREF_STRICT;
            else if (!strcmp(s, "degenerate"))
                o->rule = KREF_DEGENERATE;
            else
                return usage(host, o->label, "--rule is strict or degenerate");
            have_rule = 1;
        } else if (!strcmp(s, "--block-threads") && left >= 1) {
            if (parse_ull(argv[++i], 1, 1u << 20, &a))
                return usage(host, o->label, "--block-threads takes a positive integer");
            o->pq = (size_t)a;
        } else if (!strcmp(s, "--patches-per-block") && left >= 1) {
            if (parse_ull(argv[++i], 1, 1u << 20, &a))
                return usage(host, o->label, "--patches-per-block takes a positive integer");
            o->q = (size_t)a;
        } else if (!strcmp(s, "--planes")) {
            o->planes = 1;
        } else if (!strcmp(s, "--groups-x-constant")) {
            o->groups_x_constant = 1;
        } else if ((!strcmp(s, "--random") || !strcmp(s, "--model")) && left >= 3) {
            kref_source *sr;
            int model = !strcmp(s, "--model");
            if (o->nsources == KREF_MAX_SOURCES)
                return usage(host, o->label, "too many --random and --model options");
            sr = &o->src[o->nsources++];
            sr->is_model = model;
            if (model) {
                sr->path = argv[i + 1];
                if (parse_ull(argv[i + 2], 1, INT_MAX, &a) ||
                    parse_ull(argv[i + 3], 0, UINT64_MAX, &c))
                    return usage(host, o->label, "--model takes PATH NEYES SEED");
                sr->nsets = (long)a;
            } else {
                if (parse_ull(argv[i + 1], 1, INT_MAX, &a) ||
                    parse_ull(argv[i + 2], 1, UINT32_MAX, &b) ||
                    parse_ull(argv[i + 3], 0, UINT64_MAX, &c))
                    return usage(host, o->label, "--random takes SETS COUNT SEED (COUNT >= 1)");
                sr->nsets = (long)a;
                sr->count = (size_t)b;
            }
            sr->seed = (uint64_t)c;
            i += 3;
        } else if (s[0] == '-' && s[1] == '-') {
            char msg[200];
            snprintf(msg, sizeof msg, "unknown option or missing values: %.100s", s);
            return usage(host, o->label, msg);
        } else if (!o->file) {
            o->file = s;
        } else {
            char msg[200];
            snprintf(msg, sizeof msg, "unexpected argument %.100s", s);
            return usage(host, o->label, msg);
        }
    }
    if (!o->label)
        return usage(host, NULL, "--name LABEL is required");
    if (!have_degree || !have_space || !have_rule || (need & KREF_NEED_FILE && !o->file) ||
        (need & KREF_NEED_KERNEL && !o->kernel_name) || (need & KREF_NEED_BLOCK && (!o->pq || !o->q)))
        return usage(host, o->label, "a required argument is missing");
    if (o->q && o->pq % o->q)
        return usage(host, o->label, "--block-threads PQ must be a multiple of --patches-per-block Q");
    if (!o->nsources)
        return usage(host, o->label, "give at least one --random or --model");
    return 0;
}

kref_set *kref_source_sets(const kref_ref *r, const kref_source *src, const char *label)
{
    ptp_error err;
    kref_set *sets;
    if (src->is_model) {
        if (!(sets = kref_model_sets(r, src->path, (int)src->nsets, src->seed, &err)))
            check(0, label, "model %s: %s", src->path, err.msg);
    } else if (!(sets = kref_random_sets(r, (int)src->nsets, src->count, src->seed))) {
        check(0, label, "%ld random sets of %zu patches: out of memory", src->nsets, src->count);
    }
    return sets;
}

int kref_init(kref_ref *r, int n, int m, kref_space space, kref_rule rule, ptp_error *err)
{
    int st = tp_derive(&r->t, n, m, err);
    if (st)
        return st;
    r->K = r->t.npoints;
    r->L = r->t.nplanes;
    r->space = space;
    r->rule = rule;
    return PTP_OK;
}

void kref_clear(kref_ref *r)
{
    tp_clear(&r->t);
}

/* A uniform double in [lo, hi) from the stream *s. */
static double uniform(uint64_t *s, double lo, double hi)
{
    return lo + (hi - lo) * (double)(check_rand(s) >> 11) / 9007199254740992.0;
}

static kref_set *alloc_sets(int nsets, size_t count, int K)
{
    kref_set *sets = calloc((size_t)nsets, sizeof *sets);
    int i;
    if (!sets)
        return NULL;
    for (i = 0; i < nsets; i++) {
        sets[i].count = count;
        sets[i].K = K;
        if (!(sets[i].cp = malloc(count * (size_t)K * sizeof *sets[i].cp))) {
            kref_free_sets(sets, nsets);
            return NULL;
        }
    }
    return sets;
}

void kref_free_sets(kref_set *sets, int nsets)
{
    int i;
    if (!sets)
        return;
    for (i = 0; i < nsets; i++)
        free(sets[i].cp);
    free(sets);
}

kref_set *kref_random_sets(const kref_ref *r, int nsets, size_t count, uint64_t seed)
{
    static const double noise[] = {0, 0.003, 0.03, 0.1, 0.3, 1.0};
    kref_set *sets = alloc_sets(nsets, count, r->K);
    int n = r->t.n, m = r->t.m, i, j, c, s;
    size_t p;
    if (!sets)
        return NULL;
    for (s = 0; s < nsets; s++) {
        kref_set *set = &sets[s];
        uint64_t rng = seed * 1000003u + (uint64_t)s;
        snprintf(set->name, sizeof set->name, "random %dx%d #%d", n, m, s);
        if (r->space == KREF_WORLD) {
            for (c = 0; c < 3; c++)
                set->eye[c] = (float)uniform(&rng, -4, 4);
            set->eye[3] = 1;
        } else {
            set->eye[0] = set->eye[1] = set->eye[3] = 0;
            set->eye[2] = (float)(uniform(&rng, 0, 1) < 0.5 ? -uniform(&rng, 0.5, 2) : uniform(&rng, 0.5, 2));
        }
        for (p = 0; p < count; p++) {
            /* A random parallelogram frame, bent by noise of a random size; a third rational. */
            double o[3], a[3], b[3], amp = noise[(int)uniform(&rng, 0, 6)];
            int rational = uniform(&rng, 0, 3) < 1, collapse = (int)uniform(&rng, 0, 16);
            for (c = 0; c < 3; c++) {
                o[c] = uniform(&rng, -1, 1);
                a[c] = uniform(&rng, -1, 1);
                b[c] = uniform(&rng, -1, 1);
            }
            for (i = 0; i <= n; i++)
                for (j = 0; j <= m; j++) {
                    float *pt = set->cp[p * (size_t)r->K + (size_t)(i * (m + 1) + j)];
                    double w = rational ? uniform(&rng, 0.5, 2) : 1.0, x[3];
                    for (c = 0; c < 3; c++)
                        x[c] = o[c] + a[c] * i / n + b[c] * j / m + amp * uniform(&rng, -1, 1);
                    if (r->space == KREF_CLIP)
                        x[2] = 0.5 * x[2]; /* keep clip z inside the w range */
                    for (c = 0; c < 3; c++)
                        pt[c] = (float)(w * x[c]);
                    pt[3] = (float)(w * (r->space == KREF_CLIP ? uniform(&rng, 1.5, 2.5) : 1.0));
                }
            /* A quarter collapse one edge (0: i = 0, 1: i = n, 2: j = 0, 3: j = m) to a point,
             * like the Utah teapot's lid: that edge's planes are then exactly zero. */
            for (i = 0; collapse < 4 && i <= n; i++)
                for (j = 0; j <= m; j++) {
                    int on = collapse == 0 ? i == 0 : collapse == 1 ? i == n : collapse == 2 ? j == 0 : j == m;
                    int first = collapse < 2 ? i * (m + 1) : j;
                    if (on)
                        memcpy(set->cp[p * (size_t)r->K + (size_t)(i * (m + 1) + j)],
                               set->cp[p * (size_t)r->K + (size_t)first], sizeof *set->cp);
                }
        }
    }
    return sets;
}

/* The BEZ model: patches of 16 1-based vertex indices and the vertices. */
typedef struct {
    int npatches, nverts;
    int (*idx)[16];
    double (*v)[3];
} bez_model;

static int read_model(bez_model *mo, const char *path, ptp_error *err)
{
    FILE *f = fopen(path, "r");
    int p, k, c;
    memset(mo, 0, sizeof *mo);
    if (!f)
        return ptp_fail(err, PTP_EIO, "cannot open %s", path);
    if (fscanf(f, "%d", &mo->npatches) != 1 || mo->npatches < 1 || mo->npatches > 10000000)
        goto bad;
    if (!(mo->idx = malloc((size_t)mo->npatches * sizeof *mo->idx)))
        goto bad;
    for (p = 0; p < mo->npatches; p++)
        for (k = 0; k < 16; k++)
            if (fscanf(f, k ? " ,%d" : "%d", &mo->idx[p][k]) != 1)
                goto bad;
    if (fscanf(f, "%d", &mo->nverts) != 1 || mo->nverts < 1 || mo->nverts > 100000000)
        goto bad;
    if (!(mo->v = malloc((size_t)mo->nverts * sizeof *mo->v)))
        goto bad;
    for (k = 0; k < mo->nverts; k++)
        for (c = 0; c < 3; c++)
            if (fscanf(f, c ? " ,%lf" : "%lf", &mo->v[k][c]) != 1)
                goto bad;
    for (p = 0; p < mo->npatches; p++)
        for (k = 0; k < 16; k++)
            if (mo->idx[p][k] < 1 || mo->idx[p][k] > mo->nverts)
                goto bad;
    fclose(f);
    return PTP_OK;
bad:
    fclose(f);
    free(mo->idx);
    free(mo->v);
    return ptp_fail(err, PTP_EIO, "%s is not a BEZ file of bicubic patches", path);
}

/* r = A * B for 4x4 row-major matrices. */
static void mat_mul(double r[16], const double A[16], const double B[16])
{
    int i, j, k;
    for (i = 0; i < 4; i++)
        for (j = 0; j < 4; j++) {
            r[i * 4 + j] = 0;
            for (k = 0; k < 4; k++)
                r[i * 4 + j] += A[i * 4 + k] * B[k * 4 + j];
        }
}

void kref_look_at(double V[16], const double E[3], const double C[3], int d3d)
{
    double f[3], up[3] = {0, 1, 0}, s[3], u[3], d = 0, len;
    int c;
    for (c = 0; c < 3; c++)
        d += (C[c] - E[c]) * (C[c] - E[c]);
    for (c = 0; c < 3; c++)
        f[c] = (C[c] - E[c]) / sqrt(d);
    if (fabs(f[1]) > 0.9) {
        up[0] = 1;
        up[1] = 0;
    }
    s[0] = f[1] * up[2] - f[2] * up[1]; /* s = f x up, u = s x f */
    s[1] = f[2] * up[0] - f[0] * up[2];
    s[2] = f[0] * up[1] - f[1] * up[0];
    len = sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
    for (c = 0; c < 3; c++)
        s[c] /= len;
    u[0] = s[1] * f[2] - s[2] * f[1];
    u[1] = s[2] * f[0] - s[0] * f[2];
    u[2] = s[0] * f[1] - s[1] * f[0];
    for (c = 0; c < 3; c++) {
        V[c] = d3d ? -s[c] : s[c]; /* x = -s keeps the rotation proper with z = +f */
        V[4 + c] = u[c];
        V[8 + c] = d3d ? f[c] : -f[c];
        V[12 + c] = 0;
    }
    for (c = 0; c < 3; c++)
        V[c * 4 + 3] = -(V[c * 4] * E[0] + V[c * 4 + 1] * E[1] + V[c * 4 + 2] * E[2]);
    V[15] = 1;
}

/* An OpenGL camera at E looking at C: M = Proj * View. The eye maps to (0, 0, Proj[2][3], 0),
 * but cross4 of transformed points is det(M) M^-T cross4, so the clip-space eye that keeps the
 * world-space classes is (0, 0, sign(det Proj) * Proj[2][3], 0) = (0, 0, -Proj[3][2] * |.|, 0). */
static void camera(double M[16], double *alpha, const double E[3], const double C[3], double R)
{
    double V[16], P[16] = {0}, d = 0, n, far;
    int c;
    for (c = 0; c < 3; c++)
        d += (C[c] - E[c]) * (C[c] - E[c]);
    d = sqrt(d);
    kref_look_at(V, E, C, 0);
    n = 0.5 * (d - R);
    far = d + 2 * R;
    P[0] = P[5] = 1 / tan(M_PI_6);
    P[10] = -(far + n) / (far - n);
    P[11] = -2 * far * n / (far - n);
    P[14] = -1;
    mat_mul(M, P, V);
    *alpha = copysign(fabs(P[11]), -P[0] * P[5] * P[14]); /* det P = -P00 P11 P23 P32 */
}

kref_set *kref_model_sets(const kref_ref *r, const char *path, int neyes, uint64_t seed,
                          ptp_error *err)
{
    bez_model mo;
    kref_set *sets;
    double C[3] = {0, 0, 0}, R = 0;
    const char *base = strrchr(path, '/') ? strrchr(path, '/') + 1 : path;
    int e, p, k, c;
    if (r->t.n != 3 || r->t.m != 3) {
        ptp_fail(err, PTP_EUSAGE, "models are bicubic: use bidegree 3x3");
        return NULL;
    }
    if (read_model(&mo, path, err))
        return NULL;
    if (!(sets = alloc_sets(neyes, (size_t)mo.npatches, 16))) {
        ptp_fail(err, PTP_ENOMEM, "out of memory");
        goto done;
    }
    for (k = 0; k < mo.nverts; k++)
        for (c = 0; c < 3; c++)
            C[c] += mo.v[k][c] / mo.nverts;
    for (k = 0; k < mo.nverts; k++) {
        double d2 = 0;
        for (c = 0; c < 3; c++)
            d2 += (mo.v[k][c] - C[c]) * (mo.v[k][c] - C[c]);
        R = fmax(R, sqrt(d2));
    }
    for (e = 0; e < neyes; e++) {
        kref_set *s = &sets[e];
        uint64_t rng = seed * 7919u + (uint64_t)e;
        double dir[3], len = 0, dist = uniform(&rng, 2, 5) * R, E[3], M[16], alpha;
        do { /* uniform on the sphere: a normalized Gaussian-free rejection sample */
            len = 0;
            for (c = 0; c < 3; c++) {
                dir[c] = uniform(&rng, -1, 1);
                len += dir[c] * dir[c];
            }
        } while (len > 1 || len < 1e-4);
        for (c = 0; c < 3; c++)
            E[c] = C[c] + dist * dir[c] / sqrt(len);
        snprintf(s->name, sizeof s->name, "%.*s eye %d", 40, base, e);
        camera(M, &alpha, E, C, R);
        for (p = 0; p < mo.npatches; p++)
            for (k = 0; k < 16; k++) {
                const double *v = mo.v[mo.idx[p][k] - 1];
                float *pt = s->cp[(size_t)p * 16 + (size_t)k];
                for (c = 0; c < 4; c++)
                    pt[c] = r->space == KREF_WORLD
                                ? (float)(c < 3 ? v[c] : 1.0)
                                : (float)(M[c * 4] * v[0] + M[c * 4 + 1] * v[1] + M[c * 4 + 2] * v[2] + M[c * 4 + 3]);
            }
        if (r->space == KREF_WORLD) {
            for (c = 0; c < 3; c++)
                s->eye[c] = (float)E[c];
            s->eye[3] = 1;
        } else {
            s->eye[0] = s->eye[1] = s->eye[3] = 0;
            s->eye[2] = (float)alpha;
        }
    }
done:
    free(mo.idx);
    free(mo.v);
    return sets;
}

/* cross4 of Appendix A in double, and the sum of |monomials| of each component. With two equal
 * points it is exactly zero (t = mag = 0): a float evaluation without contracted multiply-adds
 * gives exactly zero too, so such planes, e.g. along a collapsed edge, have bound 0. */
static void cross4_mag(double t[4], double mag[4], const float *a, const float *b, const float *c)
{
    static const int rows[4][3] = {{1, 2, 3}, {0, 2, 3}, {0, 1, 3}, {0, 1, 2}};
    int o;
    if (!memcmp(a, b, 4 * sizeof *a) || !memcmp(a, c, 4 * sizeof *a) || !memcmp(b, c, 4 * sizeof *b)) {
        for (o = 0; o < 4; o++)
            t[o] = mag[o] = 0;
        return;
    }
    for (o = 0; o < 4; o++) {
        int p = rows[o][0], q = rows[o][1], s = rows[o][2];
        double m1 = (double)a[p] * b[q] * c[s], m2 = (double)a[p] * b[s] * c[q];
        double m3 = (double)b[p] * a[q] * c[s], m4 = (double)b[p] * a[s] * c[q];
        double m5 = (double)c[p] * a[q] * b[s], m6 = (double)c[p] * a[s] * b[q];
        double det = (m1 - m2) - (m3 - m4) + (m5 - m6);
        t[o] = (o & 1) ? -det : det;
        mag[o] = fabs(m1) + fabs(m2) + fabs(m3) + fabs(m4) + fabs(m5) + fabs(m6);
    }
}

/* The bound, with u = 2^-24: a cross4 component rounds its three-factor monomials, two
 * differences and two sums (5u relative to the sum of |monomials|), the float weight and its
 * product add 2u, the eye's products and sums at most 5u (world space), and summing a plane's
 * terms in any order (count - 1)u: (count + 12)u in all, taken as (count + 16)u. */
void kref_values(const kref_ref *r, const kref_set *s, size_t p, double *d, double *bound)
{
    const float(*b)[4] = (const float(*)[4])s->cp + p * (size_t)r->K;
    size_t x;
    int i, count = 0;
    for (i = 0; i < r->L; i++)
        d[i] = bound[i] = 0;
    for (x = 0; x < r->t.nterms; x++) {
        const tp_term *e = &r->t.terms[x];
        double t[4], mag[4], w = rat_get_d(&e->w), v = 0, mg = 0;
        int c;
        cross4_mag(t, mag, b[e->j], b[e->k], b[e->l]);
        for (c = 0; c < 4; c++)
            if (r->space == KREF_WORLD || c == 2) {
                v += s->eye[c] * t[c];
                mg += fabs(s->eye[c]) * mag[c];
            }
        d[e->plane] += w * v;
        bound[e->plane] += fabs(w) * mg;
    }
    for (i = 0, x = 0; i < r->L; i++) {
        for (count = 0; x < r->t.nterms && r->t.terms[x].plane == i; x++)
            count++;
        bound[i] *= (count + 16) * ldexp(1, -24);
    }
}

int kref_classify(const double *d, int L, kref_rule rule)
{
    int i, gt = 0, lt = 0, notgt = 0, notlt = 0, nan = 0;
    for (i = 0; i < L; i++) {
        gt |= d[i] > 0;
        lt |= d[i] < 0;
        notgt |= !(d[i] > 0);
        notlt |= !(d[i] < 0);
        nan |= d[i] != d[i];
    }
    if (rule == KREF_STRICT)
        return !notlt ? KREF_BACK : !notgt ? KREF_FRONT : KREF_SILHOUETTE;
    return nan ? KREF_SILHOUETTE : !gt ? KREF_BACK : !lt ? KREF_FRONT : KREF_SILHOUETTE;
}

void kref_check(kref_result *res, const kref_ref *r, const kref_set *s, const unsigned *cls,
                const float *planes)
{
    double *d = malloc(2 * (size_t)r->L * sizeof *d), *bound = d + r->L;
    static const char *const names[] = {"front", "back", "silhouette"};
    size_t p;
    int i;
    if (!d)
        return;
    for (p = 0; p < s->count; p++) {
        int ambiguous = 0, want;
        kref_values(r, s, p, d, bound);
        for (i = 0; i < r->L; i++)
            ambiguous |= bound[i] > 0 && fabs(d[i]) <= bound[i]; /* bound 0: exactly zero */
        want = kref_classify(d, r->L, r->rule);
        res->patches++;
        if (cls[p] > 2 || (!ambiguous && (int)cls[p] != want)) {
            if (!res->class_bad++)
                snprintf(res->first_class, sizeof res->first_class, "%s patch %zu: class %u, reference %s%s",
                         s->name, p, cls[p], names[want], ambiguous ? " (ambiguous)" : "");
        }
        for (i = 0; i < r->L && !(bound[i] == 0 && d[i] == 0); i++)
            ;
        res->exact_zero += i < r->L;
        if (ambiguous)
            res->ambiguous++;
        else
            res->counts[want]++;
        for (i = 0; planes && i < r->L; i++) {
            double got = planes[p * (size_t)r->L + (size_t)i], e = fabs(got - d[i]);
            res->values++;
            if (bound[i] > 0)
                res->worst = fmax(res->worst, e / bound[i]);
            if (!(e <= bound[i])) {
                if (!res->value_bad++)
                    snprintf(res->first_value, sizeof res->first_value,
                             "%s patch %zu plane %d: %.9g, reference %.9g, bound %.3g", s->name, p,
                             i, got, d[i], bound[i]);
            }
        }
    }
    free(d);
}

int kref_report(const kref_result *res, const char *name)
{
    char label[320];
    int ok = 1;
    snprintf(label, sizeof label, "%s: %zu patches, classes agree with the double reference "
             "(%zu ambiguous within the bound)", name, res->patches, res->ambiguous);
    ok &= check(res->patches > 0 && res->class_bad == 0, label, "%zu wrong: %s", res->class_bad,
                res->first_class);
    if (res->values) {
        snprintf(label, sizeof label, "%s: %zu plane values within the float32 bound", name,
                 res->values);
        ok &= check(res->value_bad == 0, label, "%zu off: %s", res->value_bad, res->first_value);
    }
    if (res->patches >= 500) {
        snprintf(label, sizeof label, "%s: the patches include front, back and silhouette ones", name);
        ok &= check(res->counts[0] && res->counts[1] && res->counts[2], label,
                    "front %zu, back %zu, silhouette %zu", res->counts[0], res->counts[1],
                    res->counts[2]);
    }
    printf("# %s: front %zu, back %zu, silhouette %zu, ambiguous %zu, with exact zero planes %zu, "
           "worst value error %.3g of the bound\n", name, res->counts[0], res->counts[1],
           res->counts[2], res->ambiguous, res->exact_zero, res->worst);
    return ok;
}
