{{BANNER}}
#ifndef {{UPREFIX}}H
#define {{UPREFIX}}H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* The variant: DOMAIN_QUAD with bidegree DEGREE_U x DEGREE_V, or DOMAIN_TRIANGLE with DEGREE
 * (POINTS control points, PLANES control planes); SPACE_CLIP or SPACE_WORLD (--space) and RULE_STRICT or RULE_DEGENERATE (--rule), whichever
 * applies, defined as 1; CERTIFIED 1 with --certified, else 0; REFINE K with --refine K, else 0. */
{{VARIANT}}#define {{UPREFIX}}POINTS {{POINTS}}
#define {{UPREFIX}}PLANES {{PLANES}}
#define {{UPREFIX}}FRONT 0u
#define {{UPREFIX}}BACK 1u
#define {{UPREFIX}}SILHOUETTE 2u
/* Floating-point operations per patch of classify, classify_batch and classify_soa (a
 * multiply-add counts 2), and those of them on the multiply pipes (multiplies, multiply-adds). */
#define {{UPREFIX}}FLOPS {{FLOPS}}
#define {{UPREFIX}}MULS {{MULS}}
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
/* The same from one vertex array and {{POINTS}} indices a patch: point k of patch p is
 * vertices[indices[p * {{POINTS}} + k]] (a BEZ file's or OpenSubdiv's patch table); gathered
 * INDEXED_LANES patches at a time into classify_batch. */
void {{PREFIX}}classify_indexed(const float (*vertices)[4], const uint32_t *indices, size_t patch_count,
                                const float eye[4], unsigned char *cls);

/* How alpha() reads a 4x4 projection. P is the matrix that maps column vectors, clip = P * view,
 * and P(r, c) its element in row r, column c. COLUMN_MAJOR: P(r, c) at proj[c * 4 + r], as
 * OpenGL, glm and Vulkan programs hold it; DirectXMath's XMMATRIX and XMFLOAT4X4 too: they hold
 * M = P^T for row vectors (clip = view * M) row by row, the same 16 floats. ROW_MAJOR: P(r, c) at
 * proj[r * 4 + c] (P written row by row, as on paper). */
#define {{UPREFIX}}COLUMN_MAJOR 0
#define {{UPREFIX}}ROW_MAJOR 1
/* alpha of the clip-space eye (0, 0, alpha, 0) for a perspective projection proj in layout:
 * sign(det P) * P(2, 3). The view-space eye (0, 0, 0, 1) maps to column 3 of P, (0, 0, P(2, 3),
 * 0), and cross4 of transformed points is det(P) P^-T cross4, so the sign of det P keeps the
 * world-space classes (for a model-view matrix of positive determinant; negate alpha for a
 * mirroring one). 0 if det P is 0. */
float {{PREFIX}}alpha(const float proj[16], int layout);

#ifdef __cplusplus
}
#endif
#endif

#if defined({{UPREFIX}}IMPLEMENTATION) && !defined({{UPREFIX}}IMPLEMENTED)
#define {{UPREFIX}}IMPLEMENTED
#include <string.h>
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
/* The lanes functions: never inlined (they are large). clang on x86 also realigns their stack:
 * without it, it spills 64-byte vectors unaligned, across cache lines (bench/README: clang's spills). */
#if defined(__GNUC__) && !defined(__clang__)
#define {{UPREFIX}}NOINLINE __attribute__((noinline, noclone))
#elif defined(__clang__) && (defined(__x86_64__) || defined(__i386__))
#define {{UPREFIX}}NOINLINE __attribute__((noinline, force_align_arg_pointer))
#elif defined(__clang__)
#define {{UPREFIX}}NOINLINE __attribute__((noinline))
#else
#define {{UPREFIX}}NOINLINE
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
/* cls[i] = c[i] for the first count (at most {{UPREFIX}}VW) lanes; a whole vector in one store
 * (gcc 9 and later). */
static inline void {{PREFIX}}vstore(unsigned char *cls, {{PREFIX}}vm c, size_t count)
{
    size_t i;
#if __GNUC__ >= 9
    typedef unsigned char {{PREFIX}}vb __attribute__((vector_size({{UPREFIX}}VW)));
    if (count >= {{UPREFIX}}VW) {
        {{PREFIX}}vb b = __builtin_convertvector(c, {{PREFIX}}vb);
        memcpy(cls, &b, sizeof b);
        return;
    }
#endif
    for (i = 0; i < count && i < {{UPREFIX}}VW; i++)
        cls[i] = (unsigned char)c[i];
}
/* d[i] = v[i] for the first count (at most {{UPREFIX}}VW) lanes; a whole vector in one store (gcc
 * otherwise stores lane by lane, and each plane's store grows the lanes' code). */
static inline void {{PREFIX}}vstoref(float *d, {{PREFIX}}vf v, size_t count)
{
    size_t i;
    if (count >= {{UPREFIX}}VW) {
        memcpy(d, &v, sizeof v);
        return;
    }
    for (i = 0; i < count; i++)
        d[i] = v[i];
}
/* VFMA(a, b, c) = a * b + c, VFMAS the same with a float a: one rounding through the target's
 * multiply-add instructions, else two (the certified bound allows both). VLOCAL(o, w, x) = x +
 * o * w, a patch-local coordinate: the multiply-add, else in double (the product exact, two
 * roundings in all, which the certified bound counts). Macros: gcc inlines no
 * function into code compiled with other optimize options, such as the lanes' fp-contract=off. */
#if {{UPREFIX}}VW == 16
#include <immintrin.h>
#define {{UPREFIX}}VFMA(a, b, c) (({{PREFIX}}vf)_mm512_fmadd_ps((__m512)(a), (__m512)(b), (__m512)(c)))
#define {{UPREFIX}}VFMAS(a, b, c) {{UPREFIX}}VFMA(_mm512_set1_ps(a), b, c)
#elif {{UPREFIX}}VW == 8 && defined(__FMA__)
#include <immintrin.h>
#define {{UPREFIX}}VFMA(a, b, c) (({{PREFIX}}vf)_mm256_fmadd_ps((__m256)(a), (__m256)(b), (__m256)(c)))
#define {{UPREFIX}}VFMAS(a, b, c) {{UPREFIX}}VFMA(_mm256_set1_ps(a), b, c)
#elif {{UPREFIX}}VW == 4 && defined(__FMA__)
#include <immintrin.h>
#define {{UPREFIX}}VFMA(a, b, c) (({{PREFIX}}vf)_mm_fmadd_ps((__m128)(a), (__m128)(b), (__m128)(c)))
#define {{UPREFIX}}VFMAS(a, b, c) {{UPREFIX}}VFMA(_mm_set1_ps(a), b, c)
#elif {{UPREFIX}}VW == 4 && defined(__ARM_FEATURE_FMA)
#include <arm_neon.h>
#define {{UPREFIX}}VFMA(a, b, c) (({{PREFIX}}vf)vfmaq_f32((float32x4_t)(c), (float32x4_t)(a), (float32x4_t)(b)))
#define {{UPREFIX}}VFMAS(a, b, c) {{UPREFIX}}VFMA(vdupq_n_f32(a), b, c)
#else
#define {{UPREFIX}}VFMA(a, b, c) ((a) * (b) + (c))
#define {{UPREFIX}}VFMAS(a, b, c) ((a) * (b) + (c))
typedef double {{PREFIX}}vd __attribute__((vector_size(8 * {{UPREFIX}}VW)));
#define {{UPREFIX}}VLOCAL(o, w, x) (({{PREFIX}}vf)__builtin_convertvector(__builtin_convertvector(x, {{PREFIX}}vd) + \
    __builtin_convertvector(o, {{PREFIX}}vd) * __builtin_convertvector(w, {{PREFIX}}vd), {{PREFIX}}vf))
#endif
#ifndef {{UPREFIX}}VLOCAL
#define {{UPREFIX}}VLOCAL {{UPREFIX}}VFMA
#endif
/* x in every lane. */
static inline {{PREFIX}}vf {{PREFIX}}vsplat(float x)
{
    {{PREFIX}}vf v = {0};
    int i;
    for (i = 0; i < {{UPREFIX}}VW; i++)
        v[i] = x;
    return v;
}
/* 1 / x lane by lane, 0 where x is 0. */
#define {{UPREFIX}}VRECIP0(x) (({{PREFIX}}vf)(({{PREFIX}}vm)(1.0f / (x)) & ((x) != 0.0f)))
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
static inline void {{PREFIX}}vstoref(float *d, {{PREFIX}}vf v, size_t count)
{
    (void)count;
    *d = v;
}
#if defined(__GNUC__) && (defined(__FMA__) || defined(__ARM_FEATURE_FMA))
#define {{UPREFIX}}VFMA(a, b, c) __builtin_fmaf(a, b, c)
#define {{UPREFIX}}VLOCAL {{UPREFIX}}VFMA
#else
#define {{UPREFIX}}VFMA(a, b, c) ((a) * (b) + (c))
#define {{UPREFIX}}VLOCAL(o, w, x) ((float)((double)(x) + (double)(o) * (double)(w)))
#endif
#define {{UPREFIX}}VFMAS {{UPREFIX}}VFMA
#define {{UPREFIX}}VRECIP0(x) ((x) != 0.0f ? 1.0f / (x) : 0.0f)
static inline float {{PREFIX}}vsplat(float x)
{
    return x;
}
#endif

float {{PREFIX}}alpha(const float proj[16], int layout)
{
    double m[4][4], s[6], c[6], det;
    int r, k;
    for (r = 0; r < 4; r++)
        for (k = 0; k < 4; k++)
            m[r][k] = proj[layout == {{UPREFIX}}ROW_MAJOR ? r * 4 + k : k * 4 + r];
    /* det P by Laplace along rows 0 and 1: their 2x2 minors s times the complementary c */
    s[0] = m[0][0] * m[1][1] - m[0][1] * m[1][0];
    s[1] = m[0][0] * m[1][2] - m[0][2] * m[1][0];
    s[2] = m[0][0] * m[1][3] - m[0][3] * m[1][0];
    s[3] = m[0][1] * m[1][2] - m[0][2] * m[1][1];
    s[4] = m[0][1] * m[1][3] - m[0][3] * m[1][1];
    s[5] = m[0][2] * m[1][3] - m[0][3] * m[1][2];
    c[0] = m[2][2] * m[3][3] - m[2][3] * m[3][2];
    c[1] = m[2][1] * m[3][3] - m[2][3] * m[3][1];
    c[2] = m[2][1] * m[3][2] - m[2][2] * m[3][1];
    c[3] = m[2][0] * m[3][3] - m[2][3] * m[3][0];
    c[4] = m[2][0] * m[3][2] - m[2][2] * m[3][0];
    c[5] = m[2][0] * m[3][1] - m[2][1] * m[3][0];
    det = s[0] * c[0] - s[1] * c[1] + s[2] * c[2] + s[3] * c[3] - s[4] * c[4] + s[5] * c[5];
    return det > 0 ? (float)m[2][3] : det < 0 ? (float)-m[2][3] : 0.0f;
}
{{TABLES}}
{{FUNCTIONS}}
/* Patches classify_indexed gathers at a time: at most 32 KB of points on the stack. */
#define {{UPREFIX}}INDEXED_LANES ({{UPREFIX}}POINTS <= 32 ? 64 : 8)

/* cp = the points of n patches, patch-major, point k of patch l from vertices[indices[l * POINTS + k]]. */
static void {{PREFIX}}gather(float (*cp)[4], const float (*vertices)[4], const uint32_t *indices, size_t n)
{
    size_t k;
    for (k = 0; k < n * {{UPREFIX}}POINTS; k++)
        memcpy(cp[k], vertices[indices[k]], sizeof cp[k]);
}

void {{PREFIX}}classify_indexed(const float (*vertices)[4], const uint32_t *indices, size_t patch_count,
                                const float eye[4], unsigned char *cls)
{
    float cp[{{UPREFIX}}POINTS * {{UPREFIX}}INDEXED_LANES][4];
    size_t p, n;
    for (p = 0; p < patch_count; p += n) {
        n = patch_count - p < {{UPREFIX}}INDEXED_LANES ? patch_count - p : {{UPREFIX}}INDEXED_LANES;
        {{PREFIX}}gather(cp, vertices, indices + p * {{UPREFIX}}POINTS, n);
        {{PREFIX}}classify_batch((const float(*)[4])cp, n, eye, cls + p);
    }
}
#endif
