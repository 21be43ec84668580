/* bez.h: reading BEZ models (bicubic Bezier patches over a shared vertex list) into float
 * control points, patch-major, with a precise one-line message for malformed input. */
#ifndef RENDER_BEZ_H
#define RENDER_BEZ_H

#include <stddef.h>

/* A model: point k (row-major 4x4, first index along u) of patch p at pts[(p*16 + k)*3 ..]. */
typedef struct bez_model {
    size_t npatches;
    float *pts;          /* npatches * 16 * 3 floats */
    double center[3];    /* bounding sphere of every control point (box centre) */
    double radius;
} bez_model;

/* Reads path into *m with bench/bezfile.c. Returns 0, or -1 with bez_file_read's one-line
 * message (file, line, what was expected) in err (size errsz). On failure m->pts is NULL. */
int bez_read(bez_model *m, const char *path, char *err, size_t errsz);

/* Frees m->pts. */
void bez_free(bez_model *m);

#endif
