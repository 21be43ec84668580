/* kern_gpu.h: the parts of the one GPU kernel emitter (kern_emit_gpu, kern.h), one file each,
 * and the words and options they share; up is the prefix in upper case (at most 63 bytes). */
#ifndef KERN_GPU_H
#define KERN_GPU_H

#include "emit/kern.h"
#include "emit/slp_text.h"

/* kern_gpu.c: the words every part writes with, and the options they test. */

/* s, or "" for NULL (a string field left out of a table). */
const char *kgpu_opt(const char *s);

/* Ends the head of a for or an if whose body, one statement, follows on the next line. */
void kgpu_then(sbuf *o, const kern_target *g);

/* Closes the body kgpu_then opened, at the head's indent. */
void kgpu_end(sbuf *o, const kern_target *g, const char *indent);

/* Declares one local variable (see kern_syntax.locals). */
void kgpu_local(sbuf *o, const kern_target *g, const char *type, const char *name,
                const char *init, int assigned);

/* Whether the kernel is the paper's table kernel (--kernel table, the default with --certified);
 * else the straight-line kernel. */
int kgpu_table_kernel(const out_info *info);

/* Whether the kernel has the second look: the certified table kernel on a target with
 * double-float (the certified straight-line code has none: it gives up instead). */
int kgpu_second_look(const out_info *info, const kern_target *g);

/* Whether the second look sums its planes again from the rounds' tables (no df_table): the
 * weights' low parts and the accumulators' low parts acc2 are emitted for it. */
int kgpu_second_look_rounds(const out_info *info, const kern_target *g);

/* Whether the code knows exact zeros: --certified under the degenerate rule on Bezier input, where
 * a plane that a collapsed boundary edge zeros counts as exactly 0 (both <= 0 and >= 0), as in
 * the C header. */
int kgpu_exact_zeros(const out_info *info);

/* Whether the table kernel moves each patch to patch-local coordinates as it loads it: unless
 * --coordinates absolute, and certified only where the target certifies the shear (slp_cert_u;
 * elsewhere, WGSL, the certified terms read differences of the points as given). */
int kgpu_table_local(const out_info *info, const kern_target *g);

/* Whether the certified table kernel in patch-local coordinates keeps the points as given too,
 * in the shared array given, for the tests of collapsed edges and the second look (a shear may
 * round distinct points equal, and its roundings would undo the look's precision). */
int kgpu_given(const out_info *info, const kern_target *g);

/* Whether the table kernel's terms read differences of points (the target's diff, --certified,
 * in the points as given). */
int kgpu_differences(const out_info *info, const kern_target *g);

/* Writes to out (size bytes) the shear x + o w as a printf format of o, w, x: with --certified
 * where the target's fma may round its product apart, its exact-product shift (slp_cert_shift),
 * else slp_fma. */
void kgpu_shear(char *out, size_t size, const out_info *info, const kern_target *g);

/* Writes to out (size bytes, truncating as snprintf) the product of the n factors f, left to
 * right, as the kernel writes every float product but cross4's (kern_target.product): the
 * target's function p(p(f0, f1), f2), else f0 * f1 * f2; brk follows each comma or operator:
 * " ", or a line break and indent. A factor that is a sum, or a product after the first, comes
 * from kgpu_group. Returns out. */
char *kgpu_product(char *out, size_t size, const kern_target *g, const char *brk, int n,
                   const char *const *f);

/* kgpu_product of the two factors a and b on one line. */
char *kgpu_mul(char *out, size_t size, const kern_target *g, const char *a, const char *b);

/* Writes to out (size bytes) e, a sum or a product, as a factor of kgpu_product: (e) between
 * operators, e as an argument of the target's product function. Returns out. */
char *kgpu_group(char *out, size_t size, const kern_target *g, const char *e);

/* kern_gpu_tables.c: the constant tables. */

/* Appends a constant table prefix+name of n uints, `per_line` values to a line, in hex (packed
 * fields) or decimal. */
void kgpu_uint_table(sbuf *o, const kern_target *g, const char *prefix, const char *name,
                     const unsigned long *v, long n, int per_line, int hex);

/* Appends a constant float table prefix+name of n values (rounded to floats exactly, 9 digits). */
void kgpu_float_table(sbuf *o, const kern_target *g, const char *prefix, const char *name,
                      const float *v, int n);

/* The constants and the constant tables: the owned planes of each thread, per round the slots of
 * the P threads and, certified, the bounds. */
int kgpu_tables(sbuf *o, const tp_table *t, const out_info *info, const kern_target *g,
                const char *up, ptp_error *err);

/* kern_gpu_funcs.c: the helper functions. */

/* Appends the kernel's helper functions: the term (cross4z or eye_cross4), certified in
 * patch-local coordinates the target's shift (kgpu_shear), with differences diff,
 * with exact zeros finite and same, with the second look kgpu_df_functions, then flags and
 * class_of. */
void kgpu_functions(sbuf *o, const out_info *info, const kern_target *g);
/* The straight-line code's second look's helpers: with exact zeros finite and same, then
 * kgpu_df_functions, flags and class_of (certified). */
void kgpu_look_functions(sbuf *o, const out_info *info, const kern_target *g);

/* kern_gpu_df.c: the second look's double-float helper functions. */

/* Appends src with its shorthands expanded: $ is the prefix, {a*b} the target's product of the
 * operands a and b, {a*b+c} its fused multiply-add, {h;l} the double-float of the floats h, l. */
void kgpu_df_text(sbuf *o, const out_info *info, const kern_target *g, const char *src);

/* --certified's second look: the double-float helpers and the term, as kgpu_functions's. */
void kgpu_df_functions(sbuf *o, const out_info *info, const kern_target *g);

/* kern_gpu_body.c: the kernel body. */

/* The workgroup-shared arrays: the patches' points (with kgpu_given, as given too), the planes'
 * accumulators (with the second look from the rounds, their low parts acc2 too), the flags. */
void kgpu_shared(sbuf *o, const out_info *info, const kern_target *g, const char *up,
                 const char *indent);

/* The kernel body, with the target's names and syntax. */
void kgpu_body(sbuf *o, const tp_domain *d, const out_info *info, const kern_target *g,
               const char *up);

/* kern_gpu_cert.c: --certified's tables and body parts. */

/* --certified: QMAX and the bounds' factors tau_k, tau_f of every plane; with the second look,
 * QMAX2, tau2_k and tau2_f of its double-float evaluation too; with exact zeros, zero. */
int kgpu_cert_tables(sbuf *o, const tp_table *t, const out_info *info, const kern_target *g,
                     const char *up, ptp_error *err);
/* The second look's QMAX2, tau2_k and tau2_f from cb (cert_table_df's). */
void kgpu_look_bounds(sbuf *o, const out_info *info, const kern_target *g, const char *up,
                      const cert_bounds *cb);
/* With exact zeros, the table zero: per plane the boundary edges (bit e) on which every term has
 * two points, so that collapsing any of them makes the plane exactly 0. PTP_OK or PTP_ENOMEM. */
int kgpu_zero_table(sbuf *o, const tp_table *t, const out_info *info, const kern_target *g,
                    ptp_error *err);

/* Appends at indent the head of the test that the patch is too large for the bound (or NaN),
 * if (!(max(E, 1) * R3 < <up>qmax)), with the target's product, E and R3 of the suffix s. */
void kgpu_too_large(sbuf *o, const kern_target *g, const char *indent, const char *up,
                    const char *qmax, const char *s);

/* The suffix of the table kernel's second look's magnitudes (E, R3, F): "_o" with kgpu_given,
 * where it reads the points as given from given[], else "" (the first look's, of pts[]). */
const char *kgpu_look_names(const out_info *info, const kern_target *g);
/* With kgpu_given, at the second look's start (indent 8): the magnitudes of the points as given
 * (suffix _o), M2 and F_o. */
void kgpu_look_magnitudes(sbuf *o, const out_info *info, const kern_target *g, const char *up);

/* --certified: the patch's largest |coordinates| Rx, Ry, (Rz,) Rw, R the largest of them, E the
 * eye's largest |component|, M the largest |monomial| (with differences, of the terms as they
 * read them), with the second look M2 that of the points (kgpu_look_names: in patch-local
 * coordinates from the points as given, with their own magnitudes and F_o), and F the
 * underflow term's factor; patches too large for the bound get flags 3 (never certified). With
 * exact zeros, the collapsed edges of d too, of the points as given. */
void kgpu_cert_scale(sbuf *o, const tp_domain *d, const out_info *info, const kern_target *g,
                     const char *up);
/* The straight-line second look's scale, from the points cp[0..K-1] of d: the magnitudes as
 * kgpu_cert_scale's, M2, F, a return of silhouette for a patch too large for QMAX2 (or NaN) and,
 * with exact zeros, fin and col. Reads the locals i (uint) declared before. */
void kgpu_cert_look_scale(sbuf *o, const tp_domain *d, const out_info *info, const kern_target *g,
                          const char *up);

/* With exact zeros, the local keep of the plane numbered by the expression plane: 0u where a
 * collapsed edge makes it exactly 0, so that its flags certify both signs; else 3u. */
void kgpu_keep(sbuf *o, const out_info *info, const kern_target *g, const char *indent,
               const char *plane);

/* --certified: the flags of the plane numbered plane, of value d, into f: with exact zeros its
 * keep first; with the second look its certified flags into f, its plain flags into pf, and the
 * plane's bit into redo where they differ, else its certified flags into fd. */
void kgpu_cert_flags(sbuf *o, const out_info *info, const kern_target *g);

/* kern_gpu_look.c: the second look's tables and body. */

/* With the second look, its terms in the order of own_plane: those of own_plane[n] are
 * dj, dkl, dw, dwl[dstart[n] .. dstart[n+1]-1] (points j and k | l << 16, the weight's high and
 * low parts), so that a thread re-evaluates only the planes it chose. v has room for nplanes + 1
 * + 2 nterms values. */
int kgpu_df_terms(sbuf *o, const tp_table *t, const out_info *info, const kern_target *g,
                  unsigned long *v, ptp_error *err);

/* With the second look from the rounds, round r's weights' low parts wl (each weight's float
 * nearest its difference from the weight's float literal). */
void kgpu_df_weight_lo(sbuf *o, const tp_table *t, const out_info *info, const kern_target *g,
                       int r);

/* The second look: in the patches whose plain signs decide but whose bounds do not, f again,
 * from fd and the planes of redo in double-float against the bounds tau2 (plus twice the low
 * part, for comparing the high part alone). */
void kgpu_df_look(sbuf *o, const out_info *info, const kern_target *g, const char *up);
/* Writes to out (size bytes, 512 suffice) and returns the certified flags of the double-float
 * value d of the plane numbered by the expression plane: flags(d.x, tau2_k M2 + tau2_f F +
 * 2 |d.y|), F of kgpu_look_names' suffix. */
char *kgpu_df_flags(char *out, size_t size, const out_info *info, const kern_target *g,
                    const char *plane);
/* Writes at indent in the loop that adds to the double-float s the terms j from start to end of
 * the plane-order tables (dw, dwl, dj, dkl), their points read as pt[0..2] (expressions of j). */
void kgpu_df_term_sum(sbuf *o, const out_info *info, const kern_target *g, const char *in,
                      const char *start, const char *end, const char *const pt[3]);
/* The straight-line second look's terms in plane order (kgpu_df_terms' tables, dstart[n] for
 * plane n). PTP_OK or PTP_ENOMEM. */
int kgpu_df_plane_terms(sbuf *o, const tp_table *t, const out_info *info, const kern_target *g,
                        ptp_error *err);

/* kern_gpu_slp.c: the straight-line kernel, one patch an invocation. */

/* kern_gpu_slp_cert.c: --certified straight-line code (classify_patch): a patch whose float
 * signs decide but whose bounds do not all clear is looked at again in double-float, its planes
 * whose bounds do not clear (docs/errors.md). */

/* Declares, after slpt_frame and before the planes, the certified scale of the patch: the
 * magnitudes Rc, E, R, ER3, F, the bool clear (the patch small enough and, once every plane has
 * passed kgpu_slp_cert_plane, every value clear of its bound) and, with kgpu_exact_zeros, fin and
 * col<e> (boundary edge e collapsed as given). PTP_OK or PTP_ENOMEM. */
int kgpu_slp_cert_head(slpt_writer *w, const tp_domain *d, const out_info *info,
                       const kern_target *g, ptp_error *err);
/* Appends plane's bound on its value v (at p's scale): clear stays set only where |v| - K_P ER3 >
 * F, or where a collapsed edge zeros the plane exactly. */
void kgpu_slp_cert_plane(sbuf *o, const slp_prog *p, const out_info *info, const kern_target *g,
                         int plane);
/* Whether the certified straight-line code has the second look: g's slp_look (and vec2). */
int kgpu_slp_look(const out_info *info, const kern_target *g);
/* The uint words of the second look's plane bits redo, for L planes. */
int kgpu_redo_words(int L);
/* With kgpu_slp_look, what classify_patch's second look needs, before it: the term tables in
 * plane order, zero, the bounds of the plan's look, the helpers (kgpu_look_functions) and the
 * function second_look(cp, eye), the class from every plane in double-float against its own
 * bound. PTP_OK or PTP_ENOMEM. */
int kgpu_slp_look_functions(sbuf *o, const tp_table *t, const out_info *info,
                            const kern_target *g, ptp_error *err);

/* The straight-line kernel's constants P (1; --kernel lanes: LANES), Q, K, L into tables and its
 * functions into funcs (--kernel lanes: the points' struct and classify_lanes). */
int kgpu_slp_kernel_parts(sbuf *tables, sbuf *funcs, const tp_table *t, const out_info *info,
                          const kern_target *g, const char *up, ptp_error *err);

/* The straight-line kernel's body: invocation pid copies patch pid's points (--kernel indexed:
 * through its indices, with B-spline input its boundary's phantoms) and calls classify_patch
 * (with --planes, values too). */
void kgpu_slp_body(sbuf *o, const tp_domain *dom, const out_info *info, const kern_target *g,
                   const char *up);
/* --kernel lanes' body: g->lanes->body with $ the prefix and @ the upper-case prefix. */
void kgpu_lanes_body(sbuf *o, const out_info *info, const kern_target *g, const char *up);

#endif
