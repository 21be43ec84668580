{{BANNER}}
#ifndef {{UPREFIX}}H
#define {{UPREFIX}}H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* The variant: bidegree DEGREE_U x DEGREE_V (POINTS control points, PLANES control planes);
 * SPACE_CLIP or SPACE_WORLD (--space) and RULE_STRICT or RULE_DEGENERATE (--rule), whichever
 * applies, defined as 1; CERTIFIED 1 with --certified, else 0; REFINE K with --refine K, else 0. */
{{VARIANT}}#define {{UPREFIX}}POINTS {{POINTS}}
#define {{UPREFIX}}PLANES {{PLANES}}
#define {{UPREFIX}}FRONT 0u
#define {{UPREFIX}}BACK 1u
#define {{UPREFIX}}SILHOUETTE 2u
/* Floating-point operations per patch of classify, classify_batch and classify_soa. */
#define {{UPREFIX}}FLOPS {{FLOPS}}
/* Patches classify_batch transposes and classifies at a time (define it to override). */
#ifndef {{UPREFIX}}LANES
#define {{UPREFIX}}LANES 16
#endif

/* The {{PLANES}} control planes of one patch, all four components, at true scale. */
void {{PREFIX}}planes(const float cp[][4], float t[][4]);
/* d[P] = the value of plane P ({{VALUE}}) for every plane: the numbers classify decides on
 * (the same code), so a class is their sign pattern under the rule (certified: under margins). */
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
/* -ffast-math (and its parts -ffinite-math-only, -fassociative-math) breaks this code: it drops
 * the NaN checks and regroups the sums whose exact zeros and signs the classes are. */
#if defined(__FAST_MATH__) || (defined(__FINITE_MATH_ONLY__) && __FINITE_MATH_ONLY__) || \
    defined(__ASSOCIATIVE_MATH__)
#error "{{PREFIX}}: do not compile this header's implementation with -ffast-math, -ffinite-math-only or -fassociative-math: they drop the NaN checks and regroup the sums whose signs are the classes"
#endif
/* restrict: C99's, GNU C++'s and MSVC's __restrict, else nothing. */
#if defined(__cplusplus) && (defined(__GNUC__) || defined(_MSC_VER))
#define {{UPREFIX}}RESTRICT __restrict
#elif !defined(__cplusplus) && defined(__STDC_VERSION__) && __STDC_VERSION__ >= 199901L
#define {{UPREFIX}}RESTRICT restrict
#else
#define {{UPREFIX}}RESTRICT
#endif
#if defined(__SSE2__) && !defined({{UPREFIX}}NO_SSE)
#include <emmintrin.h>
#endif
/* max(r, |x|) without branches; NaN in x gives NaN. */
#define {{UPREFIX}}ABSMAX(r, x) ((r) > ((x) < 0.0f ? -(x) : (x)) ? (r) : ((x) < 0.0f ? -(x) : (x)))
/* The straight-line code's value type {{PREFIX}}vf and mask type {{PREFIX}}vm (a comparison's
 * result: 1 or -1 where true), {{UPREFIX}}VW patches wide. gcc gets GNU C vectors: it does not
 * vectorize the loop below -O3, and slowly at -O3. Elsewhere one patch: clang vectorizes the loop. */
#if defined(__GNUC__) && !defined(__clang__) && !defined({{UPREFIX}}NO_VECTOR)
#include <string.h>
#if defined(__AVX512F__)
#define {{UPREFIX}}VW 16
#elif defined(__AVX__)
#define {{UPREFIX}}VW 8
#else
#define {{UPREFIX}}VW 4
#endif
typedef float {{PREFIX}}vf __attribute__((vector_size(4 * {{UPREFIX}}VW)));
typedef int {{PREFIX}}vm __attribute__((vector_size(4 * {{UPREFIX}}VW)));
/* {{UPREFIX}}VW consecutive floats from p, any alignment. */
static inline {{PREFIX}}vf {{PREFIX}}vload(const float *p)
{
    {{PREFIX}}vf v;
    memcpy(&v, p, sizeof v);
    return v;
}
/* cls[i] = c[i] for the first count (at most {{UPREFIX}}VW) lanes. */
static inline void {{PREFIX}}vstore(unsigned char *cls, {{PREFIX}}vm c, size_t count)
{
    size_t i;
    for (i = 0; i < count && i < {{UPREFIX}}VW; i++)
        cls[i] = (unsigned char)c[i];
}
/* Lane 0 of v. */
static inline float {{PREFIX}}vfirst({{PREFIX}}vf v)
{
    return v[0];
}
/* max(r, |x|) lane by lane; NaN in x gives NaN. */
static inline {{PREFIX}}vf {{PREFIX}}vabsmax({{PREFIX}}vf r, {{PREFIX}}vf x)
{
    {{PREFIX}}vm a = ({{PREFIX}}vm)x & 0x7fffffff, m = r > ({{PREFIX}}vf)a;
    return ({{PREFIX}}vf)((({{PREFIX}}vm)r & m) | (a & ~m));
}
#else
#define {{UPREFIX}}VW 1
typedef float {{PREFIX}}vf;
typedef int {{PREFIX}}vm;
static inline {{PREFIX}}vf {{PREFIX}}vload(const float *p)
{
    return *p;
}
static inline void {{PREFIX}}vstore(unsigned char *cls, {{PREFIX}}vm c, size_t count)
{
    (void)count;
    *cls = (unsigned char)c;
}
static inline {{PREFIX}}vf {{PREFIX}}vabsmax({{PREFIX}}vf r, {{PREFIX}}vf x)
{
    return {{UPREFIX}}ABSMAX(r, x);
}
static inline float {{PREFIX}}vfirst({{PREFIX}}vf v)
{
    return v;
}
#endif
{{TABLES}}
{{FUNCTIONS}}#endif
