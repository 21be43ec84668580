/* emit_c.h: what the C header's emitter files share and nothing outside them needs (emit_c
 * itself is in kern.h, with the other targets' emitters). */
#ifndef EMIT_C_H
#define EMIT_C_H

#include "emit/sbuf.h"

/* Appends component i of cross4(a, b, c) (Appendix A), for the C header's float and double
 * table loops: +-det of the rows other than i, expanded along the first of them; cast (e.g.
 * "(double)") converts the first factor of every product of a 2x2 minor, and ind is the
 * indentation of continuation lines. */
void emit_c_cross4_component(sbuf *o, int i, const char *cast, int ind);

#endif
