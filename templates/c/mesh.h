
/* Indexed triangle meshes (degree 1 only): the class of every triangle, or of every cluster of
 * consecutive triangles, from a vertex array and an index array, as classify gives it. */
#ifndef {{UPREFIX}}MESH_H
#define {{UPREFIX}}MESH_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* 1: with AVX-512 (AVX), classify_mesh classifies 16 (8) triangles at a time in registers with
 * classify's float operations (in patch-local coordinates: with AVX-512, or AVX and FMA); 0
 * (certified headers, whose second look is classify_soa's): it gathers blocks of MESH_LANES
 * triangles for classify_soa. */
#define {{UPREFIX}}MESH_FUSED {{FUSED}}
/* 1: the header computes in patch-local coordinates (--coordinates local). */
#define {{UPREFIX}}MESH_LOCAL {{LOCAL}}
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
#if (defined(__AVX__) || defined(__AVX512F__)) && !defined({{UPREFIX}}NO_SSE)
#include <immintrin.h>
#endif
/* gcc contracts no product of the fused kernel into an FMA; the whole section, because gcc does
 * not inline across optimize options. */
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC push_options
#pragma GCC optimize("fp-contract=off")
#pragma GCC diagnostic push /* g++ 12 calls gcc's own _mm512_undefined_ps maybe uninitialized */
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
/* {{PREFIX}}mesh_rows(v, vertices, x): v[0] to v[3] = the rows x, y, z and w of one vertex of
 * MESH_W consecutive triangles, from x, that vertex's index in the first of them (triangle i's at
 * x[3 * i]): r[i] holds the vertex of triangles i, i + 4, ... in its 128-bit lanes, and a 4x4
 * transpose within the lanes gives the rows in triangle order. */
#if defined(__AVX512F__) && !defined({{UPREFIX}}NO_SSE)
#define {{UPREFIX}}MESH_W 16
typedef __m512 {{PREFIX}}mesh_v;
static inline void {{PREFIX}}mesh_rows(__m512 v[4], const float (*vertices)[4], const uint32_t *x)
{
    __m512 r[4];
    int i;
    for (i = 0; i < 4; i++) {
        const uint32_t *q = x + 3 * i;
        r[i] = _mm512_castps128_ps512(_mm_loadu_ps(vertices[q[0]]));
        r[i] = _mm512_insertf32x4(r[i], _mm_loadu_ps(vertices[q[12]]), 1);
        r[i] = _mm512_insertf32x4(r[i], _mm_loadu_ps(vertices[q[24]]), 2);
        r[i] = _mm512_insertf32x4(r[i], _mm_loadu_ps(vertices[q[36]]), 3);
    }
{{TRANSPOSE16}}}
#elif defined(__AVX__) && !defined({{UPREFIX}}NO_SSE)
#define {{UPREFIX}}MESH_W 8
typedef __m256 {{PREFIX}}mesh_v;
static inline void {{PREFIX}}mesh_rows(__m256 v[4], const float (*vertices)[4], const uint32_t *x)
{
    __m256 r[4];
    int i;
    for (i = 0; i < 4; i++) {
        const uint32_t *q = x + 3 * i;
        r[i] = _mm256_castps128_ps256(_mm_loadu_ps(vertices[q[0]]));
        r[i] = _mm256_insertf128_ps(r[i], _mm_loadu_ps(vertices[q[12]]), 1);
    }
{{TRANSPOSE8}}}
#endif
#if {{UPREFIX}}MESH_FUSED && defined({{UPREFIX}}MESH_W) && \
    (!{{UPREFIX}}MESH_LOCAL || defined(__FMA__) || {{UPREFIX}}MESH_W == 16)
#define {{UPREFIX}}MESH_FUSED_ON
/* The classes of the first triangle_count / MESH_W * MESH_W triangles, MESH_W at a time in
 * registers: classify's float operations for degree 1 in the same order (products never
 * contracted), and the class bytes from compares. Returns the triangles done. */
static size_t {{PREFIX}}mesh_fused(const float (*vertices)[4], const uint32_t *indices,
                                  size_t triangle_count, const float eye[4], unsigned char *cls)
{
#if defined(__clang__)
#pragma STDC FP_CONTRACT OFF
#endif
#if {{UPREFIX}}MESH_W == 16
{{EYE16}}#else
{{EYE8}}#endif
    size_t l;
    for (l = 0; l + {{UPREFIX}}MESH_W <= triangle_count; l += {{UPREFIX}}MESH_W) {
        {{PREFIX}}mesh_v v[3][4], u;
        {{PREFIX}}mesh_rows(v[0], vertices, indices + 3 * l);
        {{PREFIX}}mesh_rows(v[1], vertices, indices + 3 * l + 1);
        {{PREFIX}}mesh_rows(v[2], vertices, indices + 3 * l + 2);
#if {{UPREFIX}}MESH_W == 16
{{BODY16}}        _mm_storeu_si128((__m128i *)(cls + l), _mm512_cvtepi32_epi8(c));
#else
{{BODY8}}        const __m128i h = _mm_packs_epi32(_mm256_castsi256_si128(c), _mm256_extractf128_si256(c, 1));
        _mm_storel_epi64((__m128i *)(cls + l), _mm_packus_epi16(h, h));
#endif
    }
    return l;
}
#endif

/* Blocks of MESH_LANES triangles gathered through their indices into the SoA layout and
 * classified by classify_soa: the same code as classify, so the same classes (certified: with
 * the same second look). The gather transposes one vertex of 16 (AVX-512), 8 (AVX) or 4 (SSE2)
 * triangles at a time as mesh_rows does. With MESH_FUSED and AVX-512 or AVX, mesh_fused
 * classifies all but the last triangle_count % MESH_W triangles. */
void {{PREFIX}}classify_mesh(const float (*vertices)[4], const uint32_t *indices,
                            size_t triangle_count, const float eye[4], unsigned char *cls)
{
    float soa[3 * 4 * {{UPREFIX}}MESH_LANES];
    size_t p, l, n;
    unsigned k, c;
    p = 0;
#if defined({{UPREFIX}}MESH_FUSED_ON)
    p = {{PREFIX}}mesh_fused(vertices, indices, triangle_count, eye, cls);
#endif
    for (; p < triangle_count; p += n) {
        const uint32_t *ix = indices + 3 * p;
        n = triangle_count - p < {{UPREFIX}}MESH_LANES ? triangle_count - p : {{UPREFIX}}MESH_LANES;
        l = 0;
#if defined({{UPREFIX}}MESH_W)
        for (; l + {{UPREFIX}}MESH_W <= n; l += {{UPREFIX}}MESH_W)
            for (k = 0; k < 3; k++) {
                {{PREFIX}}mesh_v v[4];
                {{PREFIX}}mesh_rows(v, vertices, ix + 3 * l + k);
#if {{UPREFIX}}MESH_W == 16
{{STORES16}}#else
{{STORES8}}#endif
            }
#endif
#if defined(__SSE2__) && !defined({{UPREFIX}}NO_SSE)
        for (; l + 4 <= n; l += 4)
            for (k = 0; k < 3; k++) {
                __m128 r[4], t0, t1, t2, t3;
                int i;
                for (i = 0; i < 4; i++)
                    r[i] = _mm_loadu_ps(vertices[ix[3 * (l + (size_t)i) + k]]);
                t0 = _mm_unpacklo_ps(r[0], r[1]);
                t1 = _mm_unpacklo_ps(r[2], r[3]);
                t2 = _mm_unpackhi_ps(r[0], r[1]);
                t3 = _mm_unpackhi_ps(r[2], r[3]);
{{STORES4}}            }
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
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#pragma GCC pop_options
#endif
#endif
