/* emit_c_cert.h: the C header's --certified parts, for emit_c.c: the lanes' magnitudes, margins
 * and collapsed edges, and certify64, the second look in double at the patches float leaves. */
#ifndef EMIT_C_CERT_H
#define EMIT_C_CERT_H

#include "emit/out.h"
#include "emit/slp_text.h"
#include "plan/cert.h"
#include "plan/slp.h"

/* Nonzero for a certified header under the degenerate rule on Bezier input: a plane that a
 * collapsed boundary edge zeros (slp_prog.zero) counts as exactly 0 there, both <= 0 and >= 0.
 * (Converted B-spline points are equal without the exact ones being equal: every plane then
 * takes its bound.) */
int emit_c_cert_zeros(const out_info *info);

/* Appends the certified lanes' macros (prefix px, upper case up): VABS(x) = |x| lane by lane
 * (NaN stays NaN); VMIN(a, b) = the lesser of a and b, with vectors by their bits as signed
 * integers (the float order on floats >= +0, and a negative float or -0 below every one of
 * those): a minimum above F > 0 is the least value above F. */
void emit_c_cert_macros(sbuf *o, const char *px, const char *up);

/* Nonzero for a certified header whose planes all take the strict bound (no collapsed-edge
 * zeros): its lanes bound the values after the planes where they run on vectors (CLATE). */
int emit_c_cert_late(const out_info *info);

/* Appends cert_k (the planes' -K_P from cb) and the macros CMIN(P, x) (x bounded as plane P's
 * value, into s), CLATE (1 where the lanes run on vectors, VW > 1) and CBOUND(P) (plane P's value
 * v kept in raw[P] under CLATE, else CMIN at once), for a header where emit_c_cert_late holds. */
void emit_c_cert_late_macros(sbuf *o, const cert_bounds *cb, const char *px, const char *up);

/* Appends, under CLATE, the magnitudes (emit_c_cert_magnitudes, from the points loaded again)
 * and the loop that bounds every plane's kept value raw[P] into s. After the planes. */
void emit_c_cert_late_bounds(const slpt_writer *w, int npoints, const out_info *info,
                             const cert_bounds *cb, const char *up);

/* Appends the lanes' certified magnitudes from loads of their own: the largest |coordinate| Rc
 * of each coordinate c the kernel reads over the npoints points, their maximum R, ER3 >= every
 * monomial's magnitude (clip: E Rx Ry Rw; world: |e_i| times the other three coordinates' Rc,
 * e_i x_j y_k z_l with i, j, k, l distinct), F with cb's largest K2, and the size guard amb
 * (cb->q_max). Needs E (and world: E0..E3) and the point loads q, qs before it. */
void emit_c_cert_magnitudes(const slpt_writer *w, int npoints, const out_info *info,
                            const cert_bounds *cb);

/* Appends the lanes' masks c<e>: boundary edge e of d is collapsed, its points equal in every
 * coordinate the kernel reads (== : +0 and -0 are one number, NaN never equal) and every
 * coordinate finite. Needs every point's coordinates (x<k>, y<k>, ...) declared before it. */
void emit_c_cert_collapsed(sbuf *o, const tp_domain *d, const out_info *info);

/* Appends plane's value v into the certified masks (set by the first plane): the strict masks
 * lt and gt (the lanes whose values so far are all < 0, all > 0; under the degenerate rule a
 * plane that a collapsed edge of p->zero[plane] zeros counts as both); t = |v| - K_P ER3
 * (cb->k), rounded once (twice without FMA: K_P allows it), into s, their minimum (or, on a
 * plane a collapsed edge can zero, into amb where t is not above F and the edge is not
 * collapsed); the signs are certified where s > F and amb is clear (docs/errors.md). Where
 * emit_c_cert_late holds, t and s come from CBOUND(plane). */
void emit_c_cert_masks(sbuf *o, const slp_prog *p, const cert_bounds *cb, const out_info *info,
                       const char *up, int plane, int first);

/* Appends the double tables (wgt64, tau64_k, tau64_f) and <prefix>certify64(cp, eye), the second
 * look at a patch float cannot certify, in double: the table loop with double weights and the
 * bounds of cert_table for u = 2^-53, which are 2^29 times smaller; under the degenerate rule
 * (with <prefix>zero, same and collapsed) a plane of a collapsed edge counts as exactly 0. With
 * --refine it also writes the values and bounds (an exact zero: both 0) to d[] and b[] for
 * refined. p is t's straight-line program (its zero[]). PTP_OK, or an error from cert_table or
 * out of memory. */
int emit_c_cert_certify64(sbuf *o, const tp_table *t, const slp_prog *p, const out_info *info,
                          const char *up, ptp_error *err);

#endif
