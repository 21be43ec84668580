
/* OpenSubdiv's boundary patches (--basis bspline): the vertices beyond a boundary edge are
 * phantoms, extrapolated from the two rows inside it as OpenSubdiv evaluates them. */
#ifndef {{UPREFIX}}BOUNDARY_H
#define {{UPREFIX}}BOUNDARY_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Replaces in cp (16 B-spline vertices, as classify reads them) the phantom vertices of the
 * edges whose bits boundary sets, OpenSubdiv's Far::PatchParam::GetBoundary(): 1 the edge v = 0,
 * 2 u = 1, 4 v = 1, 8 u = 0. Each vertex p0 of such an edge becomes 2 p1 - p2 (rounded once),
 * p1 and p2 the next two inward. Returns 1 when every phantom is exact (its float is 2 p1 - p2),
 * else 0. */
int {{PREFIX}}extrapolate(float cp[][4], unsigned boundary);
/* classify_indexed with boundary masks: patch p's vertices extrapolated by boundary[p] (NULL:
 * none) before they are classified; certified, a patch whose phantoms are not exact is
 * silhouette (its vertices are then not the patch's). */
void {{PREFIX}}classify_indexed_boundary(const float (*vertices)[4], const uint32_t *indices,
                                         const unsigned char *boundary, size_t patch_count,
                                         const float eye[4], unsigned char *cls);

#ifdef __cplusplus
}
#endif
#endif

#if defined({{UPREFIX}}IMPLEMENTATION) && !defined({{UPREFIX}}BOUNDARY_IMPLEMENTED)
#define {{UPREFIX}}BOUNDARY_IMPLEMENTED
/* For bit b of a boundary mask, its four phantoms as input indices {p0, p1, p2}. */
static const unsigned char {{PREFIX}}phantoms[4][4][3] = {{PHANTOMS}};

int {{PREFIX}}extrapolate(float cp[][4], unsigned boundary)
{
    unsigned b, i, c;
    int exact = 1;
    for (b = 0; b < 4; b++)
        for (i = 0; boundary >> b & 1u && i < 4; i++) {
            const unsigned char *q = {{PREFIX}}phantoms[b][i];
            for (c = 0; c < 4; c++) {
                /* s = 2 p1 - p2 rounded, and its error by Knuth's two-sum (2 p1 is exact) */
                const float x = 2.0f * cp[q[1]][c], y = -cp[q[2]][c], s = x + y, t = s - x;
                exact &= (x - (s - t)) + (y - t) == 0.0f;
                cp[q[0]][c] = s;
            }
        }
    return exact;
}

void {{PREFIX}}classify_indexed_boundary(const float (*vertices)[4], const uint32_t *indices,
                                         const unsigned char *boundary, size_t patch_count,
                                         const float eye[4], unsigned char *cls)
{
    float cp[16 * {{UPREFIX}}INDEXED_LANES][4];
    unsigned char exact[{{UPREFIX}}INDEXED_LANES];
    size_t p, n, l;
    for (p = 0; p < patch_count; p += n) {
        n = patch_count - p < {{UPREFIX}}INDEXED_LANES ? patch_count - p : {{UPREFIX}}INDEXED_LANES;
        {{PREFIX}}gather(cp, vertices, indices + p * 16, n);
        for (l = 0; l < n; l++)
            exact[l] = (unsigned char)(!boundary || !(boundary[p + l] & 15u) ||
                                       {{PREFIX}}extrapolate(cp + 16 * l, boundary[p + l]));
        {{PREFIX}}classify_batch((const float(*)[4])cp, n, eye, cls + p);
        for (l = 0; {{UPREFIX}}CERTIFIED && l < n; l++)
            if (!exact[l])
                cls[p + l] = (unsigned char){{UPREFIX}}SILHOUETTE;
    }
}
#endif
