/* domain.c: the patch domains: counts, index maps, degree parsing and names per kind.
 * What differs between kinds is one row of `kinds`; everything else is shared. */
#include "core/domain.h"

#include <stdio.h>

/* The numbering of one kind over a grid of degrees (a, b): points over (n, m), planes over
 * (pu, pv). */
typedef struct {
    const char *name;    /* as --domain reads it */
    int ndeg;            /* degrees named by --degree: 2 is NxM */
    int max;             /* the largest supported degree */
    const char *tag;     /* between "ptp_" and the degree in the default prefix */
    const char *word, *patches, *point_axes, *plane_axes, *plane_rows, *conventions;
    void (*plane_degrees)(int *pu, int *pv, int n, int m);
    int (*count)(int a, int b);
    int (*index)(int a, int b, int i, int j);
    void (*coords)(int *i, int *j, int a, int b, int k);
    int (*has)(int a, int b, int i, int j);
    int (*row_start)(int a, int b, int k);
    /* the index rule, e.g. "k = i*4 + j", with the letters k, i, j given */
    void (*rule)(char *buf, size_t size, const char *kij, int a, int b);
} kind_ops;

static void quad_plane_degrees(int *pu, int *pv, int n, int m)
{
    *pu = 3 * n - 2;
    *pv = 3 * m - 2;
}

static int quad_count(int a, int b)
{
    return (a + 1) * (b + 1);
}

static int quad_index(int a, int b, int i, int j)
{
    (void)a;
    return i * (b + 1) + j;
}

static void quad_coords(int *i, int *j, int a, int b, int k)
{
    (void)a;
    *i = k / (b + 1);
    *j = k % (b + 1);
}

static int quad_has(int a, int b, int i, int j)
{
    return i >= 0 && i <= a && j >= 0 && j <= b;
}

static int quad_row_start(int a, int b, int k)
{
    (void)a;
    return k % (b + 1) == 0;
}

static void quad_rule(char *buf, size_t size, const char *kij, int a, int b)
{
    (void)a;
    snprintf(buf, size, "%c = %c*%d + %c", kij[0], kij[1], b + 1, kij[2]);
}

/* Triangles: one degree a; cell (i, j) stands for (i, j, a-i-j), numbered in descending
 * lexicographic order of (i, j): row r = a - i holds r + 1 cells, j = r down to 0. */
static void tri_plane_degrees(int *pu, int *pv, int n, int m)
{
    (void)m;
    *pu = *pv = 3 * n - 3;
}

static int tri_count(int a, int b)
{
    (void)b;
    return (a + 1) * (a + 2) / 2;
}

static int tri_index(int a, int b, int i, int j)
{
    (void)b;
    return (a - i) * (a - i + 1) / 2 + (a - i - j);
}

/* The row r = a - i of cell k, and k's place in the row (0 at j = r). */
static int tri_row(int *at, int k)
{
    int r = 0;
    while ((r + 1) * (r + 2) / 2 <= k)
        r++;
    *at = k - r * (r + 1) / 2;
    return r;
}

static void tri_coords(int *i, int *j, int a, int b, int k)
{
    int at, r = tri_row(&at, k);
    (void)b;
    *i = a - r;
    *j = r - at;
}

static int tri_has(int a, int b, int i, int j)
{
    (void)b;
    return i >= 0 && j >= 0 && i + j <= a;
}

static int tri_row_start(int a, int b, int k)
{
    int at;
    (void)a;
    (void)b;
    tri_row(&at, k);
    return at == 0;
}

static void tri_rule(char *buf, size_t size, const char *kij, int a, int b)
{
    (void)b;
    snprintf(buf, size, "%c = (%d-%c)(%d-%c)/2 + %d-%c-%c", kij[0], a, kij[1], a + 1, kij[1], a,
             kij[1], kij[2]);
}

static const kind_ops kinds[] = {
    {"quad", 2, PTP_MAX_DEGREE, "", "bidegree", "Bezier patches", "i along u", "I along u",
     "row I along u, column J along v",
     "point k = i*(m+1)+j and plane P = I*(3m-1)+J, with i and I along u", quad_plane_degrees,
     quad_count, quad_index, quad_coords, quad_has, quad_row_start, quad_rule},
    {"triangle", 1, PTP_MAX_TRI_DEGREE, "tri", "degree", "triangular Bezier patches",
     "b_ijk weighted by u^i v^j w^k",
     "t_IJK weighted by u^I v^J w^K", "row I (power of u), J (power of v) descending",
     "point b_ijk (i+j+k = d) numbered (d-i)(d-i+1)/2+k and plane t_IJK (I+J+K = 3d-3) "
     "numbered (3d-3-I)(3d-2-I)/2+K, descending (i, j), weights u^i v^j w^k with w = 1-u-v",
     tri_plane_degrees, tri_count, tri_index, tri_coords, tri_has, tri_row_start, tri_rule},
};

/* Writes the degrees (a, b) of a kind separated by sep ("x" the way --degree reads them). */
static void put_degrees(char *buf, size_t size, const kind_ops *k, int a, int b, const char *sep)
{
    if (k->ndeg > 1)
        snprintf(buf, size, "%d%s%d", a, sep, b);
    else
        snprintf(buf, size, "%d", a);
}

int tp_domain_init(tp_domain *d, tp_kind kind, int n, int m, ptp_error *err)
{
    const kind_ops *k = &kinds[kind];
    char deg[16], lim[16];
    m = k->ndeg > 1 ? m : n;
    put_degrees(deg, sizeof deg, k, n, m, "x");
    if (n < 1 || m < 1)
        return ptp_fail(err, PTP_EUSAGE, "%s %s: degrees must be at least 1", k->word, deg);
    put_degrees(lim, sizeof lim, k, k->max, k->max, "x");
    if (n > k->max || m > k->max)
        return ptp_fail(err, PTP_ELIMIT,
                        "%s %s is beyond the supported limit %s (exact weights in 128-bit "
                        "rationals)", k->word, deg, lim);
    d->kind = kind;
    d->n = n;
    d->m = m;
    k->plane_degrees(&d->pu, &d->pv, n, m);
    d->npoints = k->count(n, m);
    d->nplanes = k->count(d->pu, d->pv);
    return PTP_OK;
}

/* PTP_EUSAGE: arg is not a degree of the accepted form for kind k. */
static int bad_form(const char *arg, const kind_ops *k, ptp_error *err)
{
    if (k->ndeg == 1)
        return ptp_fail(err, PTP_EUSAGE,
                        "--degree '%s': expected N, a whole number 1 to %d (--degree for %ss "
                        "takes one degree)", arg, k->max, k->name);
    return ptp_fail(err, PTP_EUSAGE,
                    "--degree '%s': expected N or NxM with whole numbers 1 to %d (e.g. 3 or 2x3)", arg,
                    k->max);
}

/* Reads one degree at s: decimal digits only, 1..k->max; *end is where it stopped. */
static int parse_one(int *v, const char *s, const char **end, const char *arg, const kind_ops *k,
                     ptp_error *err)
{
    long x = 0;
    const char *p = s;
    int big = 0;
    for (; *p >= '0' && *p <= '9'; p++) {
        x = x * 10 + (*p - '0');
        if (x > k->max) {
            big = 1;
            x = k->max + 1;
        }
    }
    if (p == s)
        return bad_form(arg, k, err);
    *end = p;
    if (big)
        return ptp_fail(err, PTP_EUSAGE, "--degree '%s': the largest supported degree is %d", arg,
                        k->max);
    if (x == 0)
        return ptp_fail(err, PTP_EUSAGE, "--degree '%s': degrees must be at least 1", arg);
    *v = (int)x;
    return PTP_OK;
}

int tp_domain_parse(tp_domain *d, tp_kind kind, const char *arg, ptp_error *err)
{
    const kind_ops *k = &kinds[kind];
    const char *p = arg;
    int n = 0, m, st;
    if ((st = parse_one(&n, arg, &p, arg, k, err)))
        return st;
    m = n;
    if (k->ndeg > 1 && (*p == 'x' || *p == 'X') && (st = parse_one(&m, p + 1, &p, arg, k, err)))
        return st;
    if (*p != '\0')
        return bad_form(arg, k, err);
    return tp_domain_init(d, kind, n, m, err);
}

void tp_domain_transpose(tp_domain *t, const tp_domain *d)
{
    *t = *d;
    t->n = d->m;
    t->m = d->n;
    t->pu = d->pv;
    t->pv = d->pu;
}

int tp_grid_count(tp_kind kind, int a, int b)
{
    return kinds[kind].count(a, b);
}

int tp_grid_index(tp_kind kind, int a, int b, int i, int j)
{
    return kinds[kind].index(a, b, i, j);
}

void tp_grid_coords(int *i, int *j, tp_kind kind, int a, int b, int k)
{
    kinds[kind].coords(i, j, a, b, k);
}

int tp_grid_has(tp_kind kind, int a, int b, int i, int j)
{
    return kinds[kind].has(a, b, i, j);
}

const char *tp_kind_name(tp_kind kind)
{
    return kinds[kind].name;
}

int tp_domain_point(const tp_domain *d, int i, int j)
{
    return kinds[d->kind].index(d->n, d->m, i, j);
}

void tp_domain_point_ij(int *i, int *j, const tp_domain *d, int k)
{
    kinds[d->kind].coords(i, j, d->n, d->m, k);
}

int tp_domain_plane(const tp_domain *d, int I, int J)
{
    return kinds[d->kind].index(d->pu, d->pv, I, J);
}

void tp_domain_plane_ij(int *I, int *J, const tp_domain *d, int P)
{
    kinds[d->kind].coords(I, J, d->pu, d->pv, P);
}

int tp_domain_plane_row_start(const tp_domain *d, int P)
{
    return kinds[d->kind].row_start(d->pu, d->pv, P);
}

int tp_domain_edges(const tp_domain *d)
{
    return d->kind == TP_TRI ? 3 : 4;
}

int tp_domain_on_edge(const tp_domain *d, int e, int i, int j)
{
    if (d->kind == TP_TRI)
        return e == 0 ? i == 0 : e == 1 ? j == 0 : i + j == d->n;
    return e == 0 ? i == 0 : e == 1 ? i == d->n : e == 2 ? j == 0 : j == d->m;
}

_Static_assert(PTP_MAX_DEGREE <= PTP_MAX_TRI_DEGREE, "TP_EDGE_POINTS_MAX holds a quad's edge");

int tp_domain_edge_points(int *k, const tp_domain *d, int e)
{
    int p, i, j, count = 0;
    for (p = 0; p < d->npoints; p++) {
        tp_domain_point_ij(&i, &j, d, p);
        if (tp_domain_on_edge(d, e, i, j))
            k[count++] = p;
    }
    return count;
}

unsigned tp_domain_term_edges(const tp_domain *d, const int k[3])
{
    unsigned z = 0;
    int e, x, i, j, c;
    for (e = 0; e < tp_domain_edges(d); e++) {
        for (x = 0, c = 0; x < 3; x++) {
            tp_domain_point_ij(&i, &j, d, k[x]);
            c += tp_domain_on_edge(d, e, i, j) != 0;
        }
        z |= (unsigned)(c >= 2) << e;
    }
    return z;
}

char *tp_domain_format(char *buf, size_t size, const tp_domain *d)
{
    put_degrees(buf, size, &kinds[d->kind], d->n, d->m, "x");
    return buf;
}

char *tp_domain_prefix(char *buf, size_t size, const tp_domain *d)
{
    char deg[16];
    snprintf(buf, size, "ptp_%s%s_", kinds[d->kind].tag, tp_domain_format(deg, sizeof deg, d));
    return buf;
}

void tp_domain_text_get(tp_domain_text *x, const tp_domain *d)
{
    const kind_ops *k = &kinds[d->kind];
    x->word = k->word;
    tp_domain_format(x->degree, sizeof x->degree, d);
    snprintf(x->name, sizeof x->name, "%s %s", k->word, x->degree);
    snprintf(x->patches, sizeof x->patches, "%s %s", x->name, k->patches);
    put_degrees(x->plane_degree, sizeof x->plane_degree, k, d->pu, d->pv, "x");
    put_degrees(x->degrees, sizeof x->degrees, k, d->n, d->m, ", ");
    put_degrees(x->plane_degrees, sizeof x->plane_degrees, k, d->pu, d->pv, ", ");
    snprintf(x->plane_name, sizeof x->plane_name, "%s %s", k->word, x->plane_degree);
    k->rule(x->point_rule, sizeof x->point_rule, "kij", d->n, d->m);
    k->rule(x->plane_rule, sizeof x->plane_rule, "PIJ", d->pu, d->pv);
    if (d->kind == TP_QUAD)
        snprintf(x->json, sizeof x->json, "\"degree\": [%s],\n  \"plane_degree\": [%s]",
                 x->degrees, x->plane_degrees);
    else
        snprintf(x->json, sizeof x->json,
                 "\"domain\": \"%s\",\n  \"degree\": %s,\n  \"plane_degree\": %s", k->name,
                 x->degrees, x->plane_degrees);
    x->point_axes = k->point_axes;
    x->plane_axes = k->plane_axes;
    x->plane_rows = k->plane_rows;
    x->conventions = k->conventions;
}
