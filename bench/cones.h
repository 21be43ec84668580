/* cones.h: the classic back-patch culling baselines for bicubic and cubic triangular Bezier
 * patches (NCONE, TCONE) and a bracket of the exact tangent-plane answer (CVis), in double. */
#ifndef CONES_H
#define CONES_H

#include <stddef.h>

/* Status codes of the functions below. */
#define CONE_OK 0
#define CONE_EINVAL (-1) /* an argument out of range, or a non-finite input */

/* The patch domains, ptpgen's numbering (README "Conventions"). A bicubic patch has 16 points
 * k = i*4 + j (i along u) and 64 planes P = I*8 + J (bidegree 7x7). A cubic triangular patch
 * B(u,v) = sum 3!/(i! j! k!) u^i v^j w^k b_ijk, w = 1 - u - v, has 10 points and 28 planes (total
 * degree 6), both in descending (i, j) order: b300, b210, b201, b120, b111, ..., b003. */
#define CONE_QUAD 0
#define CONE_TRI 1

/* Control points of a patch as world (x, y, z): p[0..15] for CONE_QUAD, p[0..9] for CONE_TRI.
 * The surface normal throughout is N(u,v) = dB/du x dB/dv (w = 1 - u - v for triangles), and
 * the patch is back-facing from the eye E where (E - B(u,v)) . N(u,v) < 0; this is e . T(u,v)
 * for e = (E, 1) and T = cross4(B, B_u, B_v) with w = 1 (cone_planes), the sign ptpgen uses. */
typedef struct cone_patch {
    double p[16][3];
    int domain; /* CONE_QUAD or CONE_TRI */
} cone_patch;

/* The control planes t[P] = (x, y, z, w) of the tangent plane T: 64 or 28 by domain. */
typedef struct cone_tplane {
    double t[64][4];
    int domain;
} cone_tplane;

/* A normal cone and a bounding sphere. A cone with usable == 0 never culls. */
typedef struct cone_bound {
    double axis[3];   /* unit axis of the cone that holds every normal direction */
    double alpha;     /* half-angle in radians, < pi/2 when usable */
    double center[3]; /* bounding sphere of the 16 control points (so of the patch) */
    double radius;
    int usable;
} cone_bound;

/* NCONE (Shirman and Abi-Ezzi): the cone of the control vectors of the normal patch
 * N = B_u x B_v (exact Bernstein product: 36 of bidegree 5x5 for a bicubic patch, 15 of total
 * degree 4 for a cubic triangle), zero vectors skipped. Fills *c;
 * c->usable is 0 when every vector is zero or the cone is not narrower than a half-space.
 * Returns CONE_OK, or CONE_EINVAL for a non-finite point or an unknown domain (then *c never
 * culls). */
int cone_ncone(const cone_patch *b, cone_bound *c);

/* TCONE (Sederberg and Meyers): the cones of the control vectors of the tangent B_u and the
 * bitangent B_v (12 each for a bicubic patch, 6 each for a cubic triangle), combined into a cone
 * about a_u x a_v with sin(alpha) = sqrt(sin^2 a_u + 2 sin a_u sin a_v |cos beta| + sin^2 a_v) /
 * sin beta. Unusable when either cone is empty or a half-space or wider, when the two cones (or one
 * and the other's negation) overlap, or when sin(alpha) >= 1. Same contract as cone_ncone. */
int cone_tcone(const cone_patch *b, cone_bound *c);

/* 1 when the patch bounded by c is back-facing from eye: the angle between the axis and the
 * direction from the sphere's center to the eye exceeds pi/2 + alpha + asin(r / |eye - c|).
 * 0 otherwise (also for an eye inside the sphere and for an unusable cone). */
int cone_cull(const cone_bound *c, const double eye[3]);

/* The control planes t_P of T = cross4(B, B_u, B_v) of the patch with w = 1 (64 or 28, by
 * b->domain, which t->domain takes), from ptpgen's exact table for that domain: terms rows of
 * idx = {plane, j, k, l} and integer weights iwgt, each weight iwgt/denom. Each cross4 is
 * computed as (n, -b_j . n), n = (b_k - b_j) x (b_l - b_j), so a term with two equal points is
 * exactly zero and a collapsed edge's planes are exactly zero. Returns CONE_OK, or CONE_EINVAL
 * for an index out of range or denom <= 0 (t is then unspecified). */
int cone_planes(const cone_patch *b, size_t terms, const unsigned short idx[][4],
                const int iwgt[], int denom, cone_tplane *t);

/* c[P] = e . t_P for the eye e = (eye, 1): the Bezier control values of the scalar patch
 * f(u,v) = e . T(u,v), numbered as the planes (64, bidegree 7x7, or 28, total degree 6). */
void cone_values(const cone_tplane *t, const double eye[3], double c[64]);

/* f(u, v) from the control values c of a patch of the domain, by the Bernstein form. */
double cone_eval(int domain, const double c[64], double u, double v);

/* f(u, v) = (E - B) . (B_u x B_v) evaluated directly from the control points, without the
 * table: the check of cone_planes and of the sign convention. If sine is not NULL, stores
 * f / (|E - B| |B_u x B_v|) there, the sine of the eye's elevation above the tangent plane
 * at B(u, v) (0 where the normal or E - B is zero). */
double cone_direct(const cone_patch *b, const double eye[3], double u, double v, double *sine);

/* Verdicts of cone_split. */
#define CONE_NOT_BACK 0  /* f > 0 at a corner of some piece: visibly front-facing there */
#define CONE_BACK 1      /* every piece has no positive control value, so f <= 0 */
#define CONE_UNDECIDED 2 /* neither, within the depth */

/* Back here means f <= 0 on the whole domain (with f not identically 0, f < 0 on the open
 * domain except on a set of measure zero): a patch with a collapsed edge, where f is exactly
 * 0 along the edge, is back-facing when the rest of it is.
 * Recursive de Casteljau subdivision of f (a square into 4 by halving u and v, a triangle into
 * 4 at its edge midpoints) to at most depth levels (0 <= depth <= 12), stopping at a piece with
 * no positive control value (back) or with a positive corner (f > 0 there). Returns CONE_BACK
 * when every piece is back (for depth 0, ptpgen's degenerate rule on c itself), CONE_NOT_BACK
 * when a positive corner was found, CONE_UNDECIDED otherwise; CONE_EINVAL for depth or domain
 * out of range. */
int cone_split(int domain, const double c[64], int depth);

/* Dense sampling of f on the n x n grid u, v = 0, 1/(n-1), ..., 1 (2 <= n <= 257), corners
 * included; for a triangle, the grid's points with u + v <= 1. Stores in *positive 1 if some sample
 * is > 0 (f is positive there: the patch is not back-facing), else 0. Returns CONE_OK, or
 * CONE_EINVAL for n or domain out of range. */
int cone_sample(int domain, const double c[64], int n, int *positive);

#endif
