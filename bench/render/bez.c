/* bez.c: the BEZ reader: patch count, 16 one-based indices per patch, vertex count, one x,y,z
 * line per vertex; every line checked, the points rounded to float as the GPU sees them. */
#include "bez.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define BEZ_MAX_PATCHES 10000000L
#define BEZ_MAX_VERTICES 100000000L

/* The reader's state: the file, its current line and the message buffer. */
typedef struct {
    FILE *f;
    long line;
    char buf[4096];
    char *err;
    size_t errsz;
    const char *path;
} reader;

static int bad(reader *r, const char *what)
{
    snprintf(r->err, r->errsz, "%s:%ld: %s", r->path, r->line, what);
    return -1;
}

/* Reads the next line into r->buf; -1 at end of file or for an overlong line. */
static int next_line(reader *r)
{
    r->line++;
    if (!fgets(r->buf, sizeof r->buf, r->f))
        return bad(r, "unexpected end of file");
    if (!strchr(r->buf, '\n') && !feof(r->f))
        return bad(r, "line too long");
    return 0;
}

/* Parses exactly n comma-separated longs from the line into v. */
static int parse_longs(reader *r, long *v, int n)
{
    char *s = r->buf, *end;
    for (int i = 0; i < n; i++) {
        errno = 0;
        v[i] = strtol(s, &end, 10);
        if (end == s || errno)
            return bad(r, n > 1 ? "expected comma-separated integers" : "expected an integer");
        s = end + strspn(end, " \t\r");
        if (i + 1 < n && *s++ != ',')
            return bad(r, "expected a comma");
    }
    if (*s && *s != '\n')
        return bad(r, "trailing characters");
    return 0;
}

/* Parses a line x,y,z of finite numbers into v. */
static int parse_xyz(reader *r, double v[3])
{
    char *s = r->buf, *end;
    for (int i = 0; i < 3; i++) {
        v[i] = strtod(s, &end);
        if (end == s || !isfinite(v[i]))
            return bad(r, "expected x,y,z (finite numbers)");
        s = end + strspn(end, " \t\r");
        if (i < 2 && *s++ != ',')
            return bad(r, "expected a comma");
    }
    if (*s && *s != '\n')
        return bad(r, "trailing characters");
    return 0;
}

/* The bounding sphere about the centre of the box of all points. */
static void bound(bez_model *m)
{
    double lo[3], hi[3], r2 = 0;
    size_t n = m->npatches * 16;
    for (int c = 0; c < 3; c++)
        lo[c] = hi[c] = m->pts[c];
    for (size_t k = 0; k < n; k++)
        for (int c = 0; c < 3; c++) {
            lo[c] = fmin(lo[c], m->pts[k * 3 + c]);
            hi[c] = fmax(hi[c], m->pts[k * 3 + c]);
        }
    for (int c = 0; c < 3; c++)
        m->center[c] = 0.5 * (lo[c] + hi[c]);
    for (size_t k = 0; k < n; k++) {
        double d2 = 0;
        for (int c = 0; c < 3; c++)
            d2 += (m->pts[k * 3 + c] - m->center[c]) * (m->pts[k * 3 + c] - m->center[c]);
        r2 = fmax(r2, d2);
    }
    m->radius = sqrt(r2);
}

/* Reads the vertices and resolves the indices idx into m->pts. */
static int read_vertices(reader *r, bez_model *m, const long *idx)
{
    long nv;
    double(*v)[3];
    if (next_line(r) || parse_longs(r, &nv, 1))
        return -1;
    if (nv < 1 || nv > BEZ_MAX_VERTICES)
        return bad(r, "vertex count out of range");
    if (!(v = malloc((size_t)nv * sizeof *v)))
        return bad(r, "out of memory");
    for (long k = 0; k < nv; k++)
        if (next_line(r) || parse_xyz(r, v[k])) {
            free(v);
            return -1;
        }
    for (size_t k = 0; k < m->npatches * 16; k++) {
        if (idx[k] < 1 || idx[k] > nv) {
            free(v);
            snprintf(r->err, r->errsz, "%s: patch %zu: vertex index %ld out of range 1..%ld",
                     r->path, k / 16 + 1, idx[k], nv);
            return -1;
        }
        for (int c = 0; c < 3; c++)
            m->pts[k * 3 + c] = (float)v[idx[k] - 1][c];
    }
    free(v);
    return 0;
}

int bez_read(bez_model *m, const char *path, char *err, size_t errsz)
{
    reader r = {NULL, 0, {0}, err, errsz, path};
    long np, *idx = NULL;
    int rc = -1;
    memset(m, 0, sizeof *m);
    if (!(r.f = fopen(path, "r"))) {
        snprintf(err, errsz, "cannot open %s: %s", path, strerror(errno));
        return -1;
    }
    if (next_line(&r) || parse_longs(&r, &np, 1))
        goto done;
    if (np < 1 || np > BEZ_MAX_PATCHES) {
        bad(&r, "patch count out of range");
        goto done;
    }
    m->npatches = (size_t)np;
    idx = malloc(m->npatches * 16 * sizeof *idx);
    m->pts = malloc(m->npatches * 16 * 3 * sizeof *m->pts);
    if (!idx || !m->pts) {
        bad(&r, "out of memory");
        goto done;
    }
    for (size_t p = 0; p < m->npatches; p++)
        if (next_line(&r) || parse_longs(&r, idx + p * 16, 16))
            goto done;
    if (read_vertices(&r, m, idx) == 0) {
        bound(m);
        rc = 0;
    }
done:
    fclose(r.f);
    free(idx);
    if (rc)
        bez_free(m);
    return rc;
}

void bez_free(bez_model *m)
{
    free(m->pts);
    m->pts = NULL;
    m->npatches = 0;
}
