/* bezfile.c: the BEZ reader (bezfile.h): reads line by line and says, for malformed input, the
 * file, the line number and what was expected there. */
#include "bezfile.h"

#include <errno.h>
#include <float.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAX_PATCHES 10000000L
#define MAX_VERTICES 100000000L

/* The reader's state: the file, the number of the line in buf, and the message buffer. */
typedef struct {
    FILE *f;
    const char *path;
    long line;
    char buf[4096];
    char *err;
    size_t errsz;
} reader;

/* Writes "path:line: what" into r->err; returns -1. */
static int bad(reader *r, const char *fmt, ...)
{
    va_list ap;
    int n = snprintf(r->err, r->errsz, "%s:%ld: ", r->path, r->line);
    va_start(ap, fmt);
    if (n >= 0 && (size_t)n < r->errsz)
        vsnprintf(r->err + n, r->errsz - (size_t)n, fmt, ap);
    va_end(ap);
    return -1;
}

/* Reads the next line into r->buf without its line end. At end of file returns 1 (r->line is
 * then the line that is missing); -1 for an overlong line. */
static int next_line(reader *r)
{
    size_t n;
    r->line++;
    if (!fgets(r->buf, sizeof r->buf, r->f))
        return 1;
    n = strlen(r->buf);
    if (n && r->buf[n - 1] == '\n')
        r->buf[--n] = 0;
    else if (!feof(r->f))
        return bad(r, "line longer than %zu characters", sizeof r->buf - 2);
    if (n && r->buf[n - 1] == '\r')
        r->buf[--n] = 0;
    return 0;
}

/* Splits r->buf at commas into at most max fields (trimmed of spaces and tabs); returns the
 * number of fields (an empty line has 0; more than max fields count past max, unstored). */
static int split(reader *r, char **field, int max)
{
    char *s = r->buf;
    int n = 0;
    if (!s[strspn(s, " \t")])
        return 0;
    for (;;) {
        char *end = strchr(s, ','), *e;
        if (end)
            *end = 0;
        s += strspn(s, " \t");
        for (e = s + strlen(s); e > s && (e[-1] == ' ' || e[-1] == '\t'); e--)
            ;
        *e = 0;
        if (n < max)
            field[n] = s;
        n++;
        if (!end)
            return n;
        s = end + 1;
    }
}

/* Parses the whole field s as a decimal integer into *v; returns 0 or -1. */
static int whole(const char *s, long *v)
{
    char *end;
    errno = 0;
    *v = strtol(s, &end, 10);
    return end == s || *end || errno ? -1 : 0;
}

/* Reads a count line ("the patch count", "the vertex count") in 1..max into *v. */
static int read_count(reader *r, const char *what, long max, long *v)
{
    char *f[1], line[44];
    int rc = next_line(r);
    if (rc > 0)
        return bad(r, "unexpected end of file, expected %s", what);
    if (rc < 0)
        return -1;
    snprintf(line, sizeof line, "%.40s", r->buf);
    if (split(r, f, 1) != 1 || whole(f[0], v) || *v < 1 || *v > max)
        return bad(r, "expected %s (a whole number 1..%ld), found \"%s\"", what, max, line);
    return 0;
}

/* Reads patch p's line of 16 indices into m->idx[p] (0-based; checked against the vertex count
 * later). */
static int read_patch(reader *r, bez_file *m, size_t p)
{
    char *f[16];
    long v;
    int n, rc = next_line(r);
    if (rc > 0)
        return bad(r, "unexpected end of file, expected %zu patch lines, found %zu", m->npatches,
                   p);
    if (rc < 0)
        return -1;
    if ((n = split(r, f, 16)) != 16)
        return bad(r, "expected 16 comma-separated vertex indices, found %d", n);
    for (int k = 0; k < 16; k++) {
        if (whole(f[k], &v) || v < 0 || v > MAX_VERTICES)
            return bad(r, "expected a vertex index (a whole number from 1), found \"%.40s\" "
                          "(index %d of 16)", f[k], k + 1);
        m->idx[p][k] = (size_t)v - 1; /* 0 wraps, and is out of range below */
    }
    return 0;
}

/* Reads vertex k's line x,y,z into m->v[k]: finite numbers within float's range. */
static int read_vertex(reader *r, bez_file *m, size_t k)
{
    char *f[3], *end;
    int n, rc = next_line(r);
    if (rc > 0)
        return bad(r, "unexpected end of file, expected %zu vertex lines, found %zu", m->nverts,
                   k);
    if (rc < 0)
        return -1;
    if ((n = split(r, f, 3)) != 3)
        return bad(r, "expected x,y,z (3 comma-separated numbers), found %d fields", n);
    for (int c = 0; c < 3; c++) {
        m->v[k][c] = strtod(f[c], &end);
        if (end == f[c] || *end || !isfinite(m->v[k][c]))
            return bad(r, "expected a finite number, found \"%.40s\" (%c of vertex %zu)", f[c],
                       "xyz"[c], k + 1);
        if (fabs(m->v[k][c]) > FLT_MAX)
            return bad(r, "coordinate %.40s is beyond float's range (%c of vertex %zu)", f[c],
                       "xyz"[c], k + 1);
    }
    return 0;
}

/* Reads the vertices and checks every patch's indices against their count, and that only blank
 * lines follow. */
static int read_vertices(reader *r, bez_file *m)
{
    long nv, patch_line0 = 2;
    char *f[1], line[44];
    int rc;
    if (read_count(r, "the vertex count", MAX_VERTICES, &nv))
        return -1;
    m->nverts = (size_t)nv;
    if (!(m->v = malloc(m->nverts * sizeof *m->v)))
        return bad(r, "out of memory for %ld vertices", nv);
    for (size_t k = 0; k < m->nverts; k++)
        if (read_vertex(r, m, k))
            return -1;
    while (!(rc = next_line(r))) {
        snprintf(line, sizeof line, "%.40s", r->buf);
        if (split(r, f, 1))
            return bad(r, "expected the end of the file after %zu vertex lines, found \"%s\"",
                       m->nverts, line);
    }
    if (rc < 0)
        return -1;
    for (size_t p = 0; p < m->npatches; p++)
        for (int k = 0; k < 16; k++)
            if (m->idx[p][k] >= m->nverts) {
                r->line = patch_line0 + (long)p;
                return bad(r, "vertex index %zu is out of range 1..%zu (index %d of 16)",
                           m->idx[p][k] + 1, m->nverts, k + 1);
            }
    return 0;
}

int bez_file_read(bez_file *m, const char *path, char *err, size_t errsz)
{
    reader r = {NULL, path, 0, {0}, err, errsz};
    long np;
    int rc = -1;
    memset(m, 0, sizeof *m);
    if (!(r.f = fopen(path, "r"))) {
        snprintf(err, errsz, "%s: cannot open: %s", path, strerror(errno));
        return -1;
    }
    if (read_count(&r, "the patch count", MAX_PATCHES, &np))
        goto done;
    m->npatches = (size_t)np;
    if (!(m->idx = malloc(m->npatches * sizeof *m->idx))) {
        bad(&r, "out of memory for %ld patches", np);
        goto done;
    }
    for (size_t p = 0; p < m->npatches; p++)
        if (read_patch(&r, m, p))
            goto done;
    rc = read_vertices(&r, m);
done:
    if (ferror(r.f) && !rc)
        rc = bad(&r, "read error");
    fclose(r.f);
    if (rc)
        bez_file_free(m);
    return rc;
}

void bez_file_free(bez_file *m)
{
    free(m->idx);
    free(m->v);
    m->idx = NULL;
    m->v = NULL;
    m->npatches = m->nverts = 0;
}
