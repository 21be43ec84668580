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

/* The {{PLANES}} control planes of one patch, all four components, at true scale. */
void {{PREFIX}}planes(const float cp[][4], float t[][4]);
/* d[P] = the value of plane P ({{VALUE}}) for every plane. */
void {{PREFIX}}values(const float cp[][4], const float eye[4], float d[]);
/* The class of one patch: {{UPREFIX}}FRONT, {{UPREFIX}}BACK or {{UPREFIX}}SILHOUETTE. */
unsigned {{PREFIX}}classify(const float cp[][4], const float eye[4]);
/* cls[p] = the class of patch p for patch_count patches, cp patch-major ({{POINTS}} points each). */
void {{PREFIX}}classify_batch(const float (*cp)[4], size_t patch_count, const float eye[4],
                              unsigned char *cls);

#ifdef __cplusplus
}
#endif
#endif

#if defined({{UPREFIX}}IMPLEMENTATION) && !defined({{UPREFIX}}IMPLEMENTED)
#define {{UPREFIX}}IMPLEMENTED
{{TABLES}}
{{FUNCTIONS}}#endif
