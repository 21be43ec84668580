/* emit_c_mesh.h: the C header's indexed-mesh section (classify_mesh, classify_clusters), which
 * the degree-1 triangle header carries after its implementation. */
#ifndef EMIT_C_MESH_H
#define EMIT_C_MESH_H

#include "emit/out.h"

/* Appends the mesh section of the C header of t to o when t is the degree-1 triangle; for any
 * other table appends nothing. PTP_OK, or an error from the template. */
int emit_c_mesh(sbuf *o, const tp_table *t, const out_info *info, ptp_error *err);

#endif
