/* domain.c: the patch domains: counts, index maps, degree parsing and names per kind.
 * What differs between kinds is one row of `kinds`; everything else is shared. */
#include "core/domain.h"

#include <stdio.h>

/* The numbering of one kind over a grid of degrees (a, b): points over (n, m), planes over
 * (pu, pv). */
typedef struct {
    int ndeg;            /* degrees named by --degree: 2 is NxM */
    const char *tag;     /* between "ptp_" and the degree in the default prefix */
    const char *word, *point_axes, *plane_axes, *plane_rows, *conventions;
    void (*plane_degrees)(int *pu, int *pv, int n, int m);
    int (*count)(int a, int b);
    int (*index)(int a, int b, int i, int j);
    void (*coords)(int *i, int *j, int a, int b, int k);
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

static const kind_ops kinds[] = {
    {2, "", "bidegree", "i along u", "I along u", "row I along u, column J along v",
     "point k = i*(m+1)+j and plane P = I*(3m-1)+J, with i and I along u", quad_plane_degrees,
     quad_count, quad_index, quad_coords, quad_row_start, quad_rule},
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
    put_degrees(lim, sizeof lim, k, PTP_MAX_DEGREE, PTP_MAX_DEGREE, "x");
    if (n > PTP_MAX_DEGREE || m > PTP_MAX_DEGREE)
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

/* PTP_EUSAGE: arg is not a degree of the accepted form. */
static int bad_form(const char *arg, ptp_error *err)
{
    return ptp_fail(err, PTP_EUSAGE,
                    "--degree '%s': expected N or NxM with whole numbers 1 to %d (e.g. 3 or 2x3)", arg,
                    PTP_MAX_DEGREE);
}

/* Reads one degree at s: decimal digits only, 1..PTP_MAX_DEGREE; *end is where it stopped. */
static int parse_one(int *v, const char *s, const char **end, const char *arg, ptp_error *err)
{
    long x = 0;
    const char *p = s;
    int big = 0;
    for (; *p >= '0' && *p <= '9'; p++) {
        x = x * 10 + (*p - '0');
        if (x > PTP_MAX_DEGREE) {
            big = 1;
            x = PTP_MAX_DEGREE + 1;
        }
    }
    if (p == s)
        return bad_form(arg, err);
    *end = p;
    if (big)
        return ptp_fail(err, PTP_EUSAGE, "--degree '%s': the largest supported degree is %d", arg,
                        PTP_MAX_DEGREE);
    if (x == 0)
        return ptp_fail(err, PTP_EUSAGE, "--degree '%s': degrees must be at least 1", arg);
    *v = (int)x;
    return PTP_OK;
}

int tp_domain_parse(tp_domain *d, tp_kind kind, const char *arg, ptp_error *err)
{
    const char *p;
    int n, m, st;
    if ((st = parse_one(&n, arg, &p, arg, err)))
        return st;
    m = n;
    if (kinds[kind].ndeg > 1 && (*p == 'x' || *p == 'X') &&
        (st = parse_one(&m, p + 1, &p, arg, err)))
        return st;
    if (*p != '\0')
        return bad_form(arg, err);
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
    put_degrees(x->plane_degree, sizeof x->plane_degree, k, d->pu, d->pv, "x");
    put_degrees(x->degrees, sizeof x->degrees, k, d->n, d->m, ", ");
    put_degrees(x->plane_degrees, sizeof x->plane_degrees, k, d->pu, d->pv, ", ");
    snprintf(x->plane_name, sizeof x->plane_name, "%s %s", k->word, x->plane_degree);
    k->rule(x->point_rule, sizeof x->point_rule, "kij", d->n, d->m);
    k->rule(x->plane_rule, sizeof x->plane_rule, "PIJ", d->pu, d->pv);
    x->point_axes = k->point_axes;
    x->plane_axes = k->plane_axes;
    x->plane_rows = k->plane_rows;
    x->conventions = k->conventions;
}
