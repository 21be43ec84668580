/* bezfile.h: the one BEZ reader of the benchmarks and tests (cullrate, build/render, kref, the
 * README example's check): bicubic patches over a shared vertex list, every line checked. */
#ifndef BEZFILE_H
#define BEZFILE_H

#include <stddef.h>

/* The BEZ format: line 1 the patch count P; P lines of 16 comma-separated 1-based vertex
 * indices (row-major 4x4, first index along u); a line with the vertex count V; V lines x,y,z.
 * Spaces and tabs around numbers and a CR before the newline are accepted; so are blank lines
 * after the last vertex, nothing else. */
typedef struct bez_file {
    size_t npatches, nverts;
    size_t (*idx)[16]; /* 0-based vertex indices of each patch's control points */
    double (*v)[3];    /* the vertices, each coordinate finite and within float's range */
} bez_file;

/* Reads path into *m. Returns 0, or -1 with one line in err (size errsz) that names the file,
 * the line and what was expected there ("f.bez:17: expected 16 comma-separated vertex indices,
 * found 15"); on failure m holds nothing to free. */
int bez_file_read(bez_file *m, const char *path, char *err, size_t errsz);

/* Frees m's arrays. */
void bez_file_free(bez_file *m);

#endif
