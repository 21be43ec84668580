/* vectors.h: test vectors for other implementations: random patches with exact plane values.
 * Small integer patches from a seeded splitmix64 stream, so every value and class is exact. */
#ifndef VECTORS_H
#define VECTORS_H

#include "emit/out.h"

/* The most cases one document may hold. */
#define VECTORS_MAX_COUNT 1000000L

/* Bounds of the generated coordinates (every case, every bidegree): world-space points have
 * |x|, |y|, |z| <= VECTORS_XYZ_MAX and 1 <= w <= VECTORS_W_MAX; clip-space points the same
 * |x|, |y| and w, and |z| < w; a world eye is (x, y, z, 1) with |x|, |y|, |z| <= VECTORS_EYE_MAX,
 * a clip eye (0, 0, +-1, 0). */
#define VECTORS_XYZ_MAX 64
#define VECTORS_W_MAX 4
#define VECTORS_EYE_MAX 48

/* The formats of the test vectors: the JSON document, or the same cases as a C include. */
enum { VECTORS_JSON, VECTORS_C };

/* Appends the test vectors in format (VECTORS_JSON or VECTORS_C): count cases of t's domain (a
 * quad of bidegree (t->dom.n, t->dom.m) or a triangle of degree d = t->dom.n) from seed, in space.
 *
 * The document (format "ptpgen-vectors/1"; fixed key order, two-space indents, one case per
 * five lines, no timestamps, so the same arguments give the same bytes):
 *
 *   {
 *     "format": "ptpgen-vectors/1",
 *     "generator": "ptpgen <PTP_VERSION>",
 *     "command": "<command>",                  (JSON-escaped)
 *     "degree": [n, m],                        (triangles: "domain": "triangle", "degree": d)
 *     "space": "clip" | "world",
 *     "seed": S,                               (unsigned 64-bit, decimal)
 *     "points": K,                             ((n+1)(m+1) control points per case)
 *     "planes": L,                             ((3n-1)(3m-1) values per case)
 *     "conventions": "<one sentence>",
 *     "cases": [
 *       {"eye": [x, y, z, w],
 *        "points": [[x, y, z, w], ...K],        (point k = i*(m+1) + j, i along u; triangles
 *                                                the domain's numbering)
 *        "values": ["p/q" or "p", ...L],        (exact d_P, plane P = I*(3m-1) + J, I along u)
 *        "values_double": [d, ...L],            (each the double nearest to d_P, as %.17g)
 *        "class_strict": c, "class_degenerate": c, "kind": "<kind>"},
 *       ...
 *     ]
 *   }
 *
 * with every coordinate an integer, t_P = sum of weight * cross4(b_j, b_k, b_l) over the
 * ptpgen-planes/1 terms of plane P (cross4 of Appendix A, as in README.md), d_P = eye . t_P in
 * world space and eye.z * t_P.z in clip space, and classes 0 front, 1 back, 2 silhouette:
 * strict, back iff every d_P < 0 and front iff every d_P > 0; degenerate, back iff no d_P > 0 and
 * front iff no d_P < 0 (all zero counts as back).
 *
 * Each case is a patch b = w * (X, 1) (clip: (w X_x, w X_y, trunc(w X_z / 17), w)) over an
 * integer 3-D grid X_ij = C + a_i U + b_j V + noise, a_i = 6i/n - 3, b_j = 6j/m - 3 (integer
 * division), C, U, V in [-2, 2]^3 with U x V != 0 (in clip space with a nonzero z, but for
 * "edge-on"), noise in [-A, A]^3 per point, A in {1, 2}; so |X| <= 16. A third of the cases are
 * rational (each w in 1..4), the rest have w = 1. The kinds, drawn with these odds:
 *   "near-planar"     8/20  the noisy grid; world eye C + k (U x V) + a U + b V, 1 <= |k| <= 4,
 *                           |a|, |b| <= 2 (on U x V's side of the grid's plane when k > 0)
 *   "flat"            3/20  the grid without noise (a plane), eye as above: either side of it
 *   "collapsed-edge"  3/20  near-planar with one boundary row (i = 0, i = n, j = 0 or j = m)
 *                           replaced by copies of its first point: the planes along it are
 *                           exactly zero, so strict and degenerate differ
 *   "edge-on"         3/20  flat with the eye in its plane (world: eye C + a U + b V with
 *                           |a|, |b| <= 8; clip: a plane containing the z axis): every value
 *                           exactly zero (strict silhouette, degenerate back)
 *   "corner-tangent"  3/20  flat with one corner X_0 moved by noise in [-2, 2]^3 and the eye in
 *                           the tangent plane there (world: eye = X_0 +- (X_1 - X_0) +-
 *                           (X_2 - X_0), X_1 and X_2 its neighbours; clip: X_2's x, y set to
 *                           X_0's or X_1's): the corner plane is exactly zero, the others often
 *                           of one sign, so strict and degenerate differ
 * In clip space the eye is (0, 0, +-1, 0) with a random sign. Cases are drawn in order from one
 * stream seeded by seed, so the first k cases do not depend on count.
 *
 * Beyond 6 x 6 the noise-free grid repeats rows (a_i = a_{i+1}), so flat patches get zero planes.
 *
 * Exactness and the overflow limit: |eye . cross4| <= 3 * 48 * 6 * 64 * 64 * 4 + 6 * 64^3 < 2^24,
 * and d_P is summed in integers over the common denominator D_P of the plane's weights, so every
 * intermediate is at most 2^24 * D_P * sum |weight|: below 2^51 for every bidegree up to 6 x 6
 * (tests/test_vectors.c checks the bound) and about 2^106 at 16 x 16, within 128 bits for every
 * supported degree. Every operation is still checked: PTP_EOVERFLOW, never a wrong value.
 *
 * The C include (VECTORS_C) holds the same cases, the same numbering, for code to include and
 * run (a comment with the command, seed, space and conventions; guard PTP_VECTORS_H):
 *
 *   #define PTP_VECTORS_COUNT count, PTP_VECTORS_K K, PTP_VECTORS_L L,
 *           PTP_VECTORS_CLIP 1 (clip space) or 0 (world space)
 *   static const float ptp_vectors_points[COUNT][K][4];        (integers, exact in float)
 *   static const float ptp_vectors_eye[COUNT][4];
 *   static const double ptp_vectors_values[COUNT][L];          (the nearest doubles, %.17g)
 *   static const unsigned char ptp_vectors_class_strict[COUNT], ptp_vectors_class_degenerate[COUNT];
 *
 * Returns PTP_OK; PTP_EUSAGE when count < 0 (in C also when count is 0: C has no empty arrays); PTP_ELIMIT when count > VECTORS_MAX_COUNT;
 * PTP_EOVERFLOW; PTP_ENOMEM. On failure out is left as it was on entry. */
int vectors_write(sbuf *out, const tp_table *t, long count, uint64_t seed, out_space space,
                  int format, const char *command, ptp_error *err);

#endif
