
/* Indexed triangle meshes (degree 1 only): the class of every triangle, or of every cluster of
 * consecutive triangles, from a vertex array and an index array, as classify gives it. */
#ifndef {{UPREFIX}}MESH_H
#define {{UPREFIX}}MESH_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Triangles classify_mesh gathers and classifies at a time (define it to override). */
#ifndef {{UPREFIX}}MESH_LANES
#define {{UPREFIX}}MESH_LANES 64
#endif

/* cls[t] = the class of triangle t for triangle_count triangles: the class {{PREFIX}}classify gives
 * the triangle (vertices[indices[3t]], vertices[indices[3t + 1]], vertices[indices[3t + 2]]) with
 * {{VALUE}}.
 * Indices may repeat (shared vertices, collapsed triangles). */
void {{PREFIX}}classify_mesh(const float (*vertices)[4], const uint32_t *indices,
                            size_t triangle_count, const float eye[4], unsigned char *cls);
/* cls[c] = the class of cluster c, triangles c * cluster_size up to (c + 1) * cluster_size - 1
 * (the last cluster may be shorter), for the ceil(triangle_count / cluster_size) clusters:
 * {{UPREFIX}}BACK iff every triangle of it is back, {{UPREFIX}}FRONT iff every one is front, else
 * {{UPREFIX}}SILHOUETTE (clustered back-face culling). cluster_size 0 writes nothing. */
void {{PREFIX}}classify_clusters(const float (*vertices)[4], const uint32_t *indices,
                                size_t triangle_count, size_t cluster_size, const float eye[4],
                                unsigned char *cls);

#ifdef __cplusplus
}
#endif
#endif

#if defined({{UPREFIX}}IMPLEMENTATION) && !defined({{UPREFIX}}MESH_IMPLEMENTED)
#define {{UPREFIX}}MESH_IMPLEMENTED
/* Blocks of MESH_LANES triangles gathered through their indices into the SoA layout (SSE2: 4x4
 * transposes, one vertex of four triangles) and classified by classify_soa: the same code as
 * classify, so the same classes (certified: with the same second look). */
void {{PREFIX}}classify_mesh(const float (*vertices)[4], const uint32_t *indices,
                            size_t triangle_count, const float eye[4], unsigned char *cls)
{
    float soa[3 * 4 * {{UPREFIX}}MESH_LANES];
    size_t p, l, n;
    unsigned k, c;
    for (p = 0; p < triangle_count; p += n) {
        const uint32_t *ix = indices + 3 * p;
        n = triangle_count - p < {{UPREFIX}}MESH_LANES ? triangle_count - p : {{UPREFIX}}MESH_LANES;
        l = 0;
#if defined(__SSE2__) && !defined({{UPREFIX}}NO_SSE)
        for (; l + 4 <= n; l += 4)
            for (k = 0; k < 3; k++) {
                __m128 r0 = _mm_loadu_ps(vertices[ix[3 * l + k]]);
                __m128 r1 = _mm_loadu_ps(vertices[ix[3 * l + 3 + k]]);
                __m128 r2 = _mm_loadu_ps(vertices[ix[3 * l + 6 + k]]);
                __m128 r3 = _mm_loadu_ps(vertices[ix[3 * l + 9 + k]]);
                _MM_TRANSPOSE4_PS(r0, r1, r2, r3);
{{STORES}}            }
#endif
        for (; l < n; l++)
            for (k = 0; k < 3; k++)
                for (c = 0; c < 4; c++)
                    soa[(k * 4 + c) * {{UPREFIX}}MESH_LANES + l] = vertices[ix[3 * l + k]][c];
        {{PREFIX}}classify_soa(soa, {{UPREFIX}}MESH_LANES, n, eye, cls + p);
    }
}

/* Blocks of MESH_LANES triangles classified by classify_mesh; each cluster's classes reduced
 * to their AND and OR: back iff the AND has bit 0 (every class is 1), front iff the OR is 0. */
void {{PREFIX}}classify_clusters(const float (*vertices)[4], const uint32_t *indices,
                                size_t triangle_count, size_t cluster_size, const float eye[4],
                                unsigned char *cls)
{
    unsigned char t[{{UPREFIX}}MESH_LANES];
    unsigned all = 0xffu, any = 0u; /* AND and OR of the current cluster's classes so far */
    size_t p, n, i, j, m, seen = 0; /* seen: triangles of the current cluster so far */
    if (cluster_size == 0)
        return;
    for (p = 0; p < triangle_count; p += n) {
        n = triangle_count - p < {{UPREFIX}}MESH_LANES ? triangle_count - p : {{UPREFIX}}MESH_LANES;
        {{PREFIX}}classify_mesh(vertices, indices + 3 * p, n, eye, t);
        for (i = 0; i < n; i += m) {
            m = cluster_size - seen < n - i ? cluster_size - seen : n - i;
            for (j = i; j < i + m; j++) {
                all &= t[j];
                any |= t[j];
            }
            seen += m;
            if (seen == cluster_size || p + i + m == triangle_count) {
                *cls++ = (unsigned char)((all & 1u) + 2u * (1u - (all & 1u)) * (any != 0u));
                all = 0xffu;
                any = 0u;
                seen = 0;
            }
        }
    }
}
#endif
