/* bench_tri.c: `make bench`'s triangle rows: triangles per second of ptpgen's degree-1 mesh path,
 * the facet-normal test and the projected signed-area test on one indexed mesh, each against its
 * memory-bandwidth bound, and the PN-triangle (cubic triangular) batch path against the bicubic.
 *
 * Built around four emitted headers (prefixes ptp_tri1w_ world, ptp_tri1_ clip, ptp_tri3_ and
 * ptp_3x3_ clip; Makefile: $(B)/bench/bench_tri), with _GNU_SOURCE on the command line:
 *   bench_tri [--grid NU NV] [--reps N]
 * Runs on the first CPU it may use (taskset -c 1 picks it). */
#include <math.h>
#include <sched.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

/* ---- the mesh: a torus of nu x nv quads, two triangles each, vertices shared ---- */

typedef struct {
    size_t nv, nt;
    float (*v)[4];     /* object-space vertices, w = 1 */
    float (*clip)[4];  /* the same in clip space (for the clip-space mesh path) */
    uint32_t *ix;      /* 3 per triangle, counterclockwise seen from outside */
    float (*facet)[6]; /* per triangle: a point (vertex 0) and the facet normal, object space */
    float (*nrm)[3];   /* per vertex: the torus's exact unit normal (for PN triangles) */
} mesh;

static const double torus_R = 1.0, torus_r = 0.4;

/* The torus point at (a, b) turns around its axis and its tube into v (w = 1) and its unit
 * normal into n. */
static void torus_point(float v[4], float n[3], double a, double b)
{
    double c = torus_R + torus_r * cos(2 * M_PI * b);
    v[0] = (float)(c * cos(2 * M_PI * a));
    v[1] = (float)(c * sin(2 * M_PI * a));
    v[2] = (float)(torus_r * sin(2 * M_PI * b));
    v[3] = 1.0f;
    n[0] = (float)(cos(2 * M_PI * b) * cos(2 * M_PI * a));
    n[1] = (float)(cos(2 * M_PI * b) * sin(2 * M_PI * a));
    n[2] = (float)sin(2 * M_PI * b);
}

/* The facet record of triangle t: vertex 0 and (v1 - v0) x (v2 - v0). */
static void make_facet(float f[6], const mesh *m, size_t t)
{
    const float *a = m->v[m->ix[3 * t]], *b = m->v[m->ix[3 * t + 1]], *c = m->v[m->ix[3 * t + 2]];
    float e1[3], e2[3];
    int k;
    for (k = 0; k < 3; k++) {
        e1[k] = b[k] - a[k];
        e2[k] = c[k] - a[k];
        f[k] = a[k];
    }
    f[3] = e1[1] * e2[2] - e1[2] * e2[1];
    f[4] = e1[2] * e2[0] - e1[0] * e2[2];
    f[5] = e1[0] * e2[1] - e1[1] * e2[0];
}

/* m = the torus mesh, clip = mvp * v (mvp row-major, column vectors); 0, or 1 out of memory. */
static int make_mesh(mesh *m, int nu, int nv, const double mvp[16])
{
    size_t i, j, t = 0, q;
    int r;
    m->nv = (size_t)nu * (size_t)nv;
    m->nt = 2 * m->nv;
    m->v = malloc(m->nv * sizeof *m->v);
    m->clip = malloc(m->nv * sizeof *m->clip);
    m->nrm = malloc(m->nv * sizeof *m->nrm);
    m->ix = malloc(3 * m->nt * sizeof *m->ix);
    m->facet = malloc(m->nt * sizeof *m->facet);
    if (!m->v || !m->clip || !m->nrm || !m->ix || !m->facet)
        return 1;
    for (i = 0; i < (size_t)nu; i++)
        for (j = 0; j < (size_t)nv; j++) {
            q = i * (size_t)nv + j;
            torus_point(m->v[q], m->nrm[q], (double)i / nu, (double)j / nv);
            for (r = 0; r < 4; r++)
                m->clip[q][r] = (float)(mvp[4 * r] * m->v[q][0] + mvp[4 * r + 1] * m->v[q][1] +
                                        mvp[4 * r + 2] * m->v[q][2] + mvp[4 * r + 3]);
        }
    for (i = 0; i < (size_t)nu; i++)
        for (j = 0; j < (size_t)nv; j++) {
            uint32_t a = (uint32_t)(i * (size_t)nv + j), b = (uint32_t)((i + 1) % (size_t)nu * (size_t)nv + j);
            uint32_t c = (uint32_t)((i + 1) % (size_t)nu * (size_t)nv + (j + 1) % (size_t)nv);
            uint32_t d = (uint32_t)(i * (size_t)nv + (j + 1) % (size_t)nv);
            uint32_t tri[6] = {a, b, c, a, c, d};
            memcpy(m->ix + 3 * t, tri, sizeof tri);
            t += 2;
        }
    for (t = 0; t < m->nt; t++)
        make_facet(m->facet[t], m, t);
    return 0;
}

/* ---- the camera ---- */

/* mvp (row-major, clip = mvp * (x, y, z, 1)) of an OpenGL camera at eye looking at the origin
 * with up +z, and its projection P: a 60 degree perspective, near 0.1, far 100. */
static void camera(double mvp[16], double P[16], const double eye[3])
{
    double f[3], s[3], u[3], V[16] = {0}, len;
    double h = 1 / tan(M_PI / 6), n = 0.1, fa = 100;
    int r, c, k;
    for (k = 0; k < 3; k++)
        f[k] = -eye[k];
    len = sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
    for (k = 0; k < 3; k++)
        f[k] /= len;
    s[0] = f[1]; /* f x (0, 0, 1) */
    s[1] = -f[0];
    s[2] = 0;
    len = sqrt(s[0] * s[0] + s[1] * s[1]);
    s[0] /= len;
    s[1] /= len;
    u[0] = s[1] * f[2] - s[2] * f[1];
    u[1] = s[2] * f[0] - s[0] * f[2];
    u[2] = s[0] * f[1] - s[1] * f[0];
    for (k = 0; k < 3; k++) {
        V[k] = s[k];
        V[4 + k] = u[k];
        V[8 + k] = -f[k];
    }
    V[3] = -(s[0] * eye[0] + s[1] * eye[1] + s[2] * eye[2]);
    V[7] = -(u[0] * eye[0] + u[1] * eye[1] + u[2] * eye[2]);
    V[11] = f[0] * eye[0] + f[1] * eye[1] + f[2] * eye[2];
    V[15] = 1;
    memset(P, 0, 16 * sizeof *P);
    P[0] = h;
    P[5] = h;
    P[10] = -(fa + n) / (fa - n);
    P[11] = -2 * fa * n / (fa - n);
    P[14] = -1;
    for (r = 0; r < 4; r++)
        for (c = 0; c < 4; c++) {
            mvp[4 * r + c] = 0;
            for (k = 0; k < 4; k++)
                mvp[4 * r + c] += P[4 * r + k] * V[4 * k + c];
        }
}

/* p[0..3] = mvp * (v, 1) for a point v with w = 1. */
static void transform(float p[4], const double mvp[16], const float v[4])
{
    int r;
    for (r = 0; r < 4; r++)
        p[r] = (float)(mvp[4 * r] * v[0] + mvp[4 * r + 1] * v[1] + mvp[4 * r + 2] * v[2] + mvp[4 * r + 3]);
}

/* ---- patches: PN triangles of the mesh's triangles, bicubic patches of its quads ---- */

/* Control point b_ijk (i + j + k = 3) of the PN triangle (Vlachos et al. 2001) of corners P[3]
 * with unit normals N[3]: a corner, an edge point (2 P_a + P_b - ((P_b - P_a) . N_a) N_a) / 3,
 * or the centre E + (E - V) / 2 (E the mean of the six edge points, V of the corners). */
static void pn_point(float b[4], const float *P[3], const float *N[3], const int ijk[3])
{
    int a = -1, c = -1, x, y, k;
    for (x = 0; x < 3; x++) {
        if (ijk[x] == 3) {
            memcpy(b, P[x], 4 * sizeof *b);
            return;
        }
        if (ijk[x] == 2)
            a = x;
        if (ijk[x] == 1 && c < 0)
            c = x;
    }
    if (a >= 0) { /* an edge point */
        float w = 0;
        for (k = 0; k < 3; k++)
            w += (P[c][k] - P[a][k]) * N[a][k];
        for (k = 0; k < 3; k++)
            b[k] = (2 * P[a][k] + P[c][k] - w * N[a][k]) / 3;
        b[3] = 1.0f;
        return;
    }
    for (k = 0; k < 3; k++) { /* the centre: the edge points sum to 3 (P_a + ...) - sum w N */
        double e = 0, v = (P[0][k] + P[1][k] + P[2][k]) / 3.0;
        for (x = 0; x < 3; x++)
            for (y = 0; y < 3; y++)
                if (x != y) {
                    double w = 0;
                    int l;
                    for (l = 0; l < 3; l++)
                        w += (P[y][l] - P[x][l]) * N[x][l];
                    e += (2 * P[x][k] + P[y][k] - w * N[x][k]) / 3;
                }
        e /= 6;
        b[k] = (float)(e + (e - v) / 2);
    }
    b[3] = 1.0f;
}

/* cp = the clip-space PN triangles of the mesh's first np triangles, 10 points each in ptpgen's
 * order ((3,0,0), (2,1,0), (2,0,1), (1,2,0), ..., (0,0,3)). */
static void make_pn(float (*cp)[4], const mesh *m, size_t np, const double mvp[16])
{
    size_t t;
    for (t = 0; t < np; t++) {
        const float *P[3], *N[3];
        int i, j, x = 0, k;
        for (k = 0; k < 3; k++) {
            P[k] = m->v[m->ix[3 * t + k]];
            N[k] = m->nrm[m->ix[3 * t + k]];
        }
        for (i = 3; i >= 0; i--)
            for (j = 3 - i; j >= 0; j--) {
                int ijk[3] = {i, j, 3 - i - j};
                float b[4];
                pn_point(b, P, N, ijk);
                transform(cp[10 * t + (size_t)x++], mvp, b);
            }
    }
}

/* cp = np clip-space bicubic patches of the torus, patch q over the quad q of a grid of nu
 * quads around: control point (i, j) on the torus at a third of the quad's steps. */
static void make_bicubic(float (*cp)[4], size_t np, int nu, int nv, const double mvp[16])
{
    size_t q;
    for (q = 0; q < np; q++) {
        int i, j;
        for (i = 0; i < 4; i++)
            for (j = 0; j < 4; j++) {
                float v[4], n[3];
                torus_point(v, n, ((double)(q % (size_t)nu) + i / 3.0) / nu,
                            ((double)(q / (size_t)nu % (size_t)nv) + j / 3.0) / nv);
                transform(cp[16 * q + (size_t)(4 * i + j)], mvp, v);
            }
    }
}

/* ---- the baselines ---- */

/* The facet-normal test (Gamasutra 1999): front when the precomputed object-space normal points
 * to the eye, (e - p) . n > 0, back when < 0, silhouette when 0; e the object-space eye. */
static void facet_cull(const float (*f)[6], size_t nt, const float e[4], unsigned char *cls)
{
    size_t t;
    for (t = 0; t < nt; t++) {
        float v = (e[0] - f[t][0]) * f[t][3] + (e[1] - f[t][1]) * f[t][4] + (e[2] - f[t][2]) * f[t][5];
        cls[t] = (unsigned char)((v < 0.0f) + 2 * (v == 0.0f));
    }
}

/* The screen-space signed area (Real-Time Rendering 14.2.1): the three vertices projected by
 * the rows x, y and w of the 4x4 matrix M (m[0..3], m[4..7], m[8..11]), divided by w, and
 * (v1 - v0) x (v2 - v0): front when > 0 (counterclockwise), back when < 0, silhouette when 0. */
static void area_cull(const float (*v)[4], const uint32_t *ix, size_t nt, const float m[12],
                      unsigned char *cls)
{
    size_t t;
    for (t = 0; t < nt; t++) {
        float sx[3], sy[3], a;
        int k;
        for (k = 0; k < 3; k++) {
            const float *p = v[ix[3 * t + (size_t)k]];
            float x = m[0] * p[0] + m[1] * p[1] + m[2] * p[2] + m[3];
            float y = m[4] * p[0] + m[5] * p[1] + m[6] * p[2] + m[7];
            float w = m[8] * p[0] + m[9] * p[1] + m[10] * p[2] + m[11];
            sx[k] = x / w;
            sy[k] = y / w;
        }
        a = (sx[1] - sx[0]) * (sy[2] - sy[0]) - (sx[2] - sx[0]) * (sy[1] - sy[0]);
        cls[t] = (unsigned char)((a < 0.0f) + 2 * (a == 0.0f));
    }
}

/* ---- timing ---- */

/* Seconds of CPU time of this thread: time it spends descheduled (by other load on a shared
 * machine) does not count; cache and memory contention do. */
static double cpu_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

/* What one timed path reads. */
typedef struct {
    const mesh *m;
    float eye[4], clip_eye[4], rows[12]; /* object-space eye, clip-space eye, mvp rows x, y, w */
    const float (*pn)[4], (*bicubic)[4];
    size_t npatches;
} ctx;

/* A path: classifies everything it times into cls; returns how many (triangles or patches). */
typedef size_t path_fn(const ctx *c, unsigned char *cls);

static size_t run_mesh(const ctx *c, unsigned char *cls)
{
    ptp_tri1w_classify_mesh((const float(*)[4])c->m->v, c->m->ix, c->m->nt, c->eye, cls);
    return c->m->nt;
}

static size_t run_mesh_clip(const ctx *c, unsigned char *cls)
{
    ptp_tri1_classify_mesh((const float(*)[4])c->m->clip, c->m->ix, c->m->nt, c->clip_eye, cls);
    return c->m->nt;
}

/* Clusters of 64 triangles; returns the triangles. */
static size_t run_clusters(const ctx *c, unsigned char *cls)
{
    ptp_tri1w_classify_clusters((const float(*)[4])c->m->v, c->m->ix, c->m->nt, 64, c->eye, cls);
    return c->m->nt;
}

static size_t run_facet(const ctx *c, unsigned char *cls)
{
    facet_cull((const float(*)[6])c->m->facet, c->m->nt, c->eye, cls);
    return c->m->nt;
}

static size_t run_area(const ctx *c, unsigned char *cls)
{
    area_cull((const float(*)[4])c->m->v, c->m->ix, c->m->nt, c->rows, cls);
    return c->m->nt;
}

static size_t run_pn(const ctx *c, unsigned char *cls)
{
    ptp_tri3_classify_batch(c->pn, c->npatches, c->clip_eye, cls);
    return c->npatches;
}

static size_t run_bicubic(const ctx *c, unsigned char *cls)
{
    ptp_3x3_classify_batch(c->bicubic, c->npatches, c->clip_eye, cls);
    return c->npatches;
}

/* Single-core streaming read: one sum of p[0..n) in 64-byte vectors with four accumulators;
 * returns its seconds of CPU time. */
typedef uint32_t stream_vec __attribute__((vector_size(64)));
static volatile uint32_t stream_sink; /* keeps the sum alive */
static double read_pass(const stream_vec *p, size_t n)
{
    stream_vec a = {0}, b = {0}, c = {0}, d = {0};
    double t0 = cpu_now(), secs;
    size_t i;
    for (i = 0; i + 4 <= n; i += 4) {
        a += p[i];
        b += p[i + 1];
        c += p[i + 2];
        d += p[i + 3];
    }
    secs = cpu_now() - t0;
    a += b + c + d;
    stream_sink = a[0];
    return secs;
}

static int compare_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* The median of v[0..n) (sorts v). */
static double median(double *v, int n)
{
    qsort(v, (size_t)n, sizeof *v, compare_double);
    return v[n / 2];
}

/* ---- output ---- */

/* Pins this thread to the first CPU it may use (taskset narrows them); returns it, or -1. */
static int pin_first(void)
{
    cpu_set_t allowed, one;
    int c;
    if (sched_getaffinity(0, sizeof allowed, &allowed))
        return -1;
    for (c = 0; c < CPU_SETSIZE; c++)
        if (CPU_ISSET(c, &allowed)) {
            CPU_ZERO(&one);
            CPU_SET(c, &one);
            return sched_setaffinity(0, sizeof one, &one) ? -1 : c;
        }
    return -1;
}

/* The 1-minute load average, or -1. */
static double load_average(void)
{
    FILE *f = fopen("/proc/loadavg", "r");
    double l = -1;
    if (f) {
        if (fscanf(f, "%lf", &l) != 1)
            l = -1;
        fclose(f);
    }
    return l;
}

/* A timed path: its row's name, function, bytes per item for the bandwidth bound (0: none),
 * and its times (seconds of CPU time per round) and classes. */
#define MAX_REPS 64
typedef struct {
    const char *name;
    path_fn *fn;
    double bytes;
    double t[MAX_REPS];
    size_t items;
    unsigned char *cls;
} path;

/* One row: items/s at the median and best time, ns per item, and with bytes the bound at the
 * bandwidth bw (bytes/s) and the median time over the bound's; classes differing from ref
 * (NULL: "-"). */
static void print_row(path *p, int reps, double bw, const unsigned char *ref)
{
    char bytes[32] = "-", bound[32] = "-", of[32] = "-", diff[48] = "-";
    double med = median(p->t, reps), best = p->t[0];
    size_t i, d = 0;
    if (p->bytes > 0) {
        snprintf(bytes, sizeof bytes, "%.1f", p->bytes);
        snprintf(bound, sizeof bound, "%.0f", bw / p->bytes * 1e-6);
        snprintf(of, sizeof of, "%.2fx", med * bw / p->bytes / (double)p->items);
    }
    if (ref && ref != p->cls) {
        for (i = 0; i < p->items; i++)
            d += p->cls[i] != ref[i];
        snprintf(diff, sizeof diff, "%zu/%zu", d, p->items);
    }
    printf("%-40s %8.1f %8.1f %7.2f %6s %8s %8s  %s\n", p->name, (double)p->items / med * 1e-6,
           (double)p->items / best * 1e-6, med * 1e9 / (double)p->items, bytes, bound, of, diff);
}

/* The median over rounds of path a's rate over path b's (both timed in every round). */
static double ratio(const path *a, const path *b, int reps)
{
    double r[MAX_REPS];
    int i;
    for (i = 0; i < reps; i++)
        r[i] = (b->t[i] / (double)b->items) / (a->t[i] / (double)a->items);
    return median(r, reps);
}

/* Builds the mesh, the camera and the patches into m and c; 0, or 1 out of memory. */
static int setup(mesh *m, ctx *c, int nu, int nv, size_t np)
{
    double eye3[3] = {2.2, 1.3, 1.6}, mvp[16], proj[16];
    float mvpf[16], projf[16], (*pn)[4], (*bi)[4];
    int i;
    camera(mvp, proj, eye3);
    for (i = 0; i < 16; i++) {
        mvpf[i] = (float)mvp[i];
        projf[i] = (float)proj[i];
    }
    if (make_mesh(m, nu, nv, mvp))
        return 1;
    np = np < m->nt ? np : m->nt;
    pn = aligned_alloc(64, np * 10 * sizeof *pn);
    bi = aligned_alloc(64, np * 16 * sizeof *bi);
    if (!pn || !bi)
        return 1;
    make_pn(pn, m, np, mvp);
    make_bicubic(bi, np, nu, nv, mvp);
    memset(c, 0, sizeof *c);
    c->m = m;
    for (i = 0; i < 3; i++)
        c->eye[i] = (float)eye3[i];
    c->eye[3] = 1.0f;
    c->clip_eye[2] = ptp_tri1_alpha(projf, PTP_TRI1_ROW_MAJOR);
    memcpy(c->rows, mvpf, 8 * sizeof *mvpf);
    memcpy(c->rows + 8, mvpf + 12, 4 * sizeof *mvpf);
    c->pn = (const float(*)[4])pn;
    c->bicubic = (const float(*)[4])bi;
    c->npatches = np;
    return 0;
}

/* Reads --grid NU NV and --reps N into *nu, *nv and *reps (left as given when absent); 0, or 2
 * after printing the usage. */
static int parse_args(int *nu, int *nv, int *reps, int argc, char **argv)
{
    int i;
    for (i = 1; i < argc; i++)
        if (!strcmp(argv[i], "--grid") && i + 2 < argc) {
            *nu = atoi(argv[i + 1]);
            *nv = atoi(argv[i + 2]);
            i += 2;
        } else if (!strcmp(argv[i], "--reps") && i + 1 < argc) {
            *reps = atoi(argv[++i]);
        } else {
            break;
        }
    if (i < argc || *nu < 3 || *nv < 3 || (double)*nu * *nv > 1e8 || *reps < 1 || *reps > MAX_REPS) {
        fprintf(stderr, "usage: %s [--grid NU NV] [--reps N (1 to %d)]\n", argv[0], MAX_REPS);
        return 2;
    }
    return 0;
}

/* Gives the first paths but the facet normal mesh_bytes per triangle, allocates every path's
 * classes (one per triangle of c's mesh) and runs it once, a warm-up; 0, or 1 out of memory. */
static int warm_up(path *paths, int npaths, const ctx *c, double mesh_bytes)
{
    int i;
    for (i = 0; i < npaths; i++) {
        if (i != 1 && i < 5)
            paths[i].bytes = mesh_bytes;
        if (!(paths[i].cls = malloc(c->m->nt)))
            return 1;
        paths[i].items = paths[i].fn(c, paths[i].cls); /* a warm-up */
    }
    return 0;
}

/* Times reps rounds, each a streaming read of buf (nbuf vectors) and then every path once,
 * interleaved with the others, into paths[].t; returns the best read bandwidth in bytes/s. */
static double run_rounds(path *paths, int npaths, const ctx *c, const stream_vec *buf,
                         size_t nbuf, int reps)
{
    double bw = 0;
    int r, i;
    for (r = 0; r < reps; r++) { /* rounds: every path once, interleaved with the others */
        double secs = read_pass(buf, nbuf);
        bw = (double)(nbuf * sizeof *buf) / secs > bw ? (double)(nbuf * sizeof *buf) / secs : bw;
        for (i = 0; i < npaths; i++) {
            double t0 = cpu_now();
            paths[i].fn(c, paths[i].cls);
            paths[i].t[r] = cpu_now() - t0;
        }
    }
    return bw;
}

/* Prints the table of the timed paths (the first four against paths[0]'s classes) with its
 * header and footer lines: the mesh of nu x nv quads, CPU cpu, bandwidth bw, load0 the load
 * average before. */
static void report(path *paths, int npaths, const ctx *c, int nu, int nv, int cpu, int reps,
                   double bw, double load0)
{
    const mesh *m = c->m;
    size_t t, front = 0, back = 0;
    int i;
    for (t = 0; t < m->nt; t++) {
        front += paths[0].cls[t] == 0;
        back += paths[0].cls[t] == 1;
    }
    printf("# triangles: a torus of %d x %d quads, %zu indexed triangles over %zu shared vertices "
           "(%.0f MB of indices and vertices, %.0f MB of facet records); CPU %d; %d rounds\n",
           nu, nv, m->nt, m->nv, (double)(m->nt * 12 + m->nv * 16) / 1e6, (double)m->nt * 24 / 1e6,
           cpu, reps);
    printf("%-40s %8s %8s %7s %6s %8s %8s  %s\n", "path", "M/s", "best", "ns", "B", "bound",
           "x bound", "differs");
    for (i = 0; i < npaths; i++)
        print_row(&paths[i], reps, bw, i < 4 ? paths[0].cls : NULL);
    printf("# classify_mesh (world) / facet normal: %.2fx; PN triangles / bicubic: %.2fx "
           "(medians of the per-round ratios; %zu patches each)\n",
           ratio(&paths[0], &paths[1], reps), ratio(&paths[5], &paths[6], reps), c->npatches);
    printf("# streaming read bandwidth, 1 core: %.1f GB/s (best of %d passes over 256 MiB); bound = "
           "that / B per triangle: indices 12, vertices 16 x %.2f (V/T, each read once), class 1; "
           "facet records 24\n",
           bw * 1e-9, reps, (double)m->nv / (double)m->nt);
    printf("# classes (classify_mesh, world): front %.1f%%, back %.1f%%; load average %.2f before, "
           "%.2f after\n",
           100.0 * (double)front / (double)m->nt, 100.0 * (double)back / (double)m->nt, load0,
           load_average());
}

int main(int argc, char **argv)
{
    int nu = 2048, nv = 1024, reps = 15, cpu;
    size_t nbuf = ((size_t)256 << 20) / sizeof(stream_vec);
    double bw, load0;
    path paths[] = {
        {"ptpgen classify_mesh (world)", run_mesh, 0, {0}, 0, NULL},
        {"facet normal (Gamasutra 1999)", run_facet, 24 + 1, {0}, 0, NULL},
        {"projected signed area (RTR 14.2.1)", run_area, 0, {0}, 0, NULL},
        {"ptpgen classify_mesh (clip)", run_mesh_clip, 0, {0}, 0, NULL},
        {"ptpgen classify_clusters (64, world)", run_clusters, 0, {0}, 0, NULL},
        {"PN triangles: classify_batch (tri3)", run_pn, 0, {0}, 0, NULL},
        {"bicubic: classify_batch (3x3)", run_bicubic, 0, {0}, 0, NULL},
    };
    const int npaths = (int)(sizeof paths / sizeof *paths);
    stream_vec *buf;
    mesh m;
    ctx c;
    if (parse_args(&nu, &nv, &reps, argc, argv))
        return 2;
    cpu = pin_first();
    load0 = load_average();
    buf = aligned_alloc(64, nbuf * sizeof *buf);
    if (!buf || setup(&m, &c, nu, nv, 131072))
        return fprintf(stderr, "bench_tri: out of memory\n"), 1;
    memset(buf, 1, nbuf * sizeof *buf);
    /* bytes per triangle: 12 of indices, 16 per vertex read once (V/T of them), 1 class */
    if (warm_up(paths, npaths, &c, 12 + 1 + 16.0 * (double)m.nv / (double)m.nt))
        return fprintf(stderr, "bench_tri: out of memory\n"), 1;
    bw = run_rounds(paths, npaths, &c, buf, nbuf, reps);
    report(paths, npaths, &c, nu, nv, cpu, reps, bw, load0);
    return 0;
}
