/* tess.h: a coarse triangle mesh with exact surface normals from bicubic Bezier patches: the input
 * of cullrate's PN-triangle models. */
#ifndef TESS_H
#define TESS_H

#include <stddef.h>
#include <stdint.h>

/* An indexed triangle mesh with vertex normals. */
typedef struct tess_mesh {
    size_t nverts, ntris;
    double (*pos)[3];
    double (*nrm)[3];   /* unit normals; (0, 0, 0) where none was found */
    uint32_t (*tri)[3]; /* counter-clockwise seen from where B_u x B_v points */
} tess_mesh;

/* Tessellates npatches bicubic patches (point k = i*4 + j of patch p at pts[p*16 + k], i along u)
 * into a grid of n x n quads each, each quad split into two triangles: 2 n^2 triangles a patch.
 * Vertices are welded where their positions rounded to float are equal (so along shared edges), and
 * a triangle with two welded corners (at a collapsed edge) is dropped. A vertex's normal is the
 * normalized mean of the unit normals B_u x B_v of the patches that meet there; where B_u x B_v is
 * zero (a collapsed edge), the normal a hundredth of the way towards the patch's centre stands in.
 * Returns 0, -1 for n outside 1..64 or too many vertices for 32-bit indices, -3 out of memory (then
 * *m is empty). */
int tess_bicubic(tess_mesh *m, const double (*pts)[3], size_t npatches, int n);

/* Frees the mesh's arrays and empties it. */
void tess_free(tess_mesh *m);

#endif
