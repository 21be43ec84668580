/* slp_text.h: the straight-line program (plan/slp.h) as statements of a C-like language: the one
 * writer behind the C header's lanes and every GPU target's classify and values functions. */
#ifndef SLP_TEXT_H
#define SLP_TEXT_H

#include "emit/sbuf.h"
#include "plan/plan.h"

typedef struct slpt_writer slpt_writer;

/* What a language (and a caller) makes of the program: the writer's words are the float locals
 * x<k> y<k> z<k> w<k> (point k; z only in world space), g<k> (clip space: e2 w) or a<k> b<k>
 * (world: e0 y - e1 x, e2 w - e3 z), the minors m<k>_<l> (x, y) and n<k>_<l> (z, w), and u, v,
 * e0..e3, which the caller declares. In patch-local coordinates (slpt_frame) also rw, ox, oy, oz
 * and, in world space, the local eye l0 l1 l2 in e0 e1 e2's place; from B-spline input the
 * converted points bx<k> by<k> bz<k> bw<k> and the first pass's h<c><i>_<j>. Every product goes through
 * mul, so a language that would contract a * b - c * d into an FMA can forbid it there or in
 * decl. */
typedef struct {
    const char *indent; /* of every statement */
    const char *decl;   /* starts a declaration of float locals, with its space: "const float " */
    int multi;          /* 1: several variables in one declaration, "a = x, b = y;" */
    const char *mul;    /* printf format of the product of a and b: "%s * %s" */
    const char *fma;    /* printf format of a * b + c, explicitly fused: "fma(%s, %s, %s)" */
    const char *fmas;   /* the same with a a float literal (C: a scalar times a vector) */
    const char *shift;  /* printf format of x + o * w rounded once, of o, w, x: "fma(%s, %s, %s)" */
    /* Writes to out (size bytes) 1 / x, or 0 where x is 0. */
    void (*recip0)(char *out, size_t size, const slpt_writer *w, const char *x);
    /* Writes to out (size bytes) coordinate c (0 x, 1 y, 2 z, 3 w) of input point k (as stored:
     * Bezier points or B-spline vertices, u-major or v-major). */
    void (*load)(char *out, size_t size, const slpt_writer *w, int k, int c);
    /* Appends the statements after plane's value v (first: the first plane written). */
    void (*plane_end)(slpt_writer *w, int plane, int first);
} slpt_syntax;

struct slpt_writer {
    sbuf *o;
    const slp_prog *p;
    const plan_slp *plan; /* p's plan: the input's form (local, bspline, vmajor) */
    const slpt_syntax *s;
    int world;           /* world space (else clip) */
    const void *ctx;     /* the caller's, for its hooks */
    unsigned char *done; /* the minors, then the points, declared so far */
};

/* Starts a writer of plan's program into o, reading its input form. Returns PTP_OK or
 * PTP_ENOMEM (w is then cleared). */
int slpt_init(slpt_writer *w, sbuf *o, const plan_slp *plan, const slpt_syntax *s, int world,
              const void *ctx, ptp_error *err);
/* Frees w's storage. */
void slpt_clear(slpt_writer *w);
/* Declares what the points need once a patch, before any point: in patch-local coordinates rw =
 * 1 / w0 of input point 0 (0 where w0 is 0), the origin's negation o = -(x0, y0[, z0]) rw and in
 * world space the local eye l = e + o e3; every input coordinate is then read as x + o w (and y,
 * z), each rounded once: a shear of determinant 1, which leaves every plane's value as it is
 * (docs/math.md). From B-spline input then the Bezier points times 36 of the sheared vertices
 * (the map is linear, so they are the sheared Bezier points): two passes of the uniform cubic
 * map, rows (1 4 1 0), (0 4 2 0), (0 2 4 0), (0 1 4 1), exact products by 2 and 4, the sums
 * rounded (in local coordinates relative to the patch, not to the origin). */
void slpt_frame(slpt_writer *w);
/* The size of slpt_coordinate's text. */
#define SLPT_EXPR 1024
/* Writes to out (SLPT_EXPR bytes) coordinate c of Bezier point k as the program reads it: the
 * input's load, in patch-local coordinates x + o w (c < 3), or B-spline input's converted point.
 * Needs slpt_frame's names. */
void slpt_coordinate(char *out, const slpt_writer *w, int k, int c);
/* Writes to out (SLPT_EXPR bytes) coordinate c of input point idx (as stored: a Bezier point or a
 * B-spline vertex, in the input's order), in patch-local coordinates x + o w when c < 3. Needs
 * slpt_frame's names. */
void slpt_input(char *out, const slpt_writer *w, int idx, int c);
/* Declares point k's coordinates and eye products unless done. */
void slpt_point(slpt_writer *w, int k);
/* Writes every plane in slp_order's order (consecutive planes reuse values), each followed by
 * the syntax's plane_end. */
int slpt_program(slpt_writer *w, ptp_error *err);
/* Writes to out the float literal of 1 / c_P, or nothing when c_P = 1: the factor that takes
 * plane P's value v to its true scale (v * factor). Returns 1 when it appended one. */
int slpt_inverse_scale(char *out, size_t size, const slp_prog *p, int plane);

#endif
