{{BANNER}}
#ifndef {{UPREFIX}}H
#define {{UPREFIX}}H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

#define {{UPREFIX}}POINTS {{POINTS}}
#define {{UPREFIX}}PLANES {{PLANES}}
#define {{UPREFIX}}FRONT 0u
#define {{UPREFIX}}BACK 1u
#define {{UPREFIX}}SILHOUETTE 2u
/* Floating-point operations per patch of classify, classify_batch and classify_soa. */
#define {{UPREFIX}}FLOPS {{FLOPS}}
/* Patches classify_batch transposes and classifies at a time (define it to override). */
#ifndef {{UPREFIX}}LANES
#define {{UPREFIX}}LANES 64
#endif

/* The {{PLANES}} control planes of one patch, all four components, at true scale. */
void {{PREFIX}}planes(const float cp[][4], float t[][4]);
/* d[P] = the value of plane P ({{VALUE}}) for every plane. */
void {{PREFIX}}values(const float cp[][4], const float eye[4], float d[]);
/* The class of one patch: {{UPREFIX}}FRONT, {{UPREFIX}}BACK or {{UPREFIX}}SILHOUETTE. */
unsigned {{PREFIX}}classify(const float cp[][4], const float eye[4]);
/* cls[p] = the class of patch p for patch_count patches, cp patch-major ({{POINTS}} points each). */
void {{PREFIX}}classify_batch(const float (*cp)[4], size_t patch_count, const float eye[4],
                              unsigned char *cls);
/* The same from structure-of-arrays: coordinate c of point k of patch p at
 * soa[(k * 4 + c) * stride + p], stride >= patch_count. */
void {{PREFIX}}classify_soa(const float *soa, size_t stride, size_t patch_count, const float eye[4],
                            unsigned char *cls);

#ifdef __cplusplus
}
#endif
#endif

#if defined({{UPREFIX}}IMPLEMENTATION) && !defined({{UPREFIX}}IMPLEMENTED)
#define {{UPREFIX}}IMPLEMENTED
#if defined(__SSE2__) && !defined({{UPREFIX}}NO_SSE)
#include <emmintrin.h>
#endif
/* max(r, |x|) without branches; NaN in x gives NaN. */
#define {{UPREFIX}}ABSMAX(r, x) ((r) > ((x) < 0.0f ? -(x) : (x)) ? (r) : ((x) < 0.0f ? -(x) : (x)))
{{TABLES}}
{{FUNCTIONS}}#endif
