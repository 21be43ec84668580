/* kern.h: the compute-kernel targets: what differs between them, as data, and the emitters.
 * All logic (tables, schedule, classification) is computed in C; templates hold boilerplate. */
#ifndef KERN_H
#define KERN_H

#include "emit/out.h"

/* What differs between the GPU targets: one table per target (emit_glsl.c, ...). */
typedef struct {
    const char *name;          /* "glsl" */
    const char *language;      /* for the banner: "GLSL 4.50 compute shader" */
    const char *template_name; /* "glsl/kernel.comp" */
    const char *file_ext;      /* ".comp" */
    int named_kernel;          /* the kernel is <prefix>classify (else the entry point is main) */
    const char *uint, *vec4;   /* the scalar and vector type names */
    const char *table_qual;    /* qualifier of constant tables */
    const char *func_qual;     /* qualifier of helper functions */
    const char *shared_qual;   /* qualifier of workgroup-shared arrays */
    int shared_in_body;        /* shared arrays are declared inside the kernel (else at file scope) */
    const char *barrier;       /* a workgroup barrier with shared-memory ordering, as a statement */
    const char *precise;       /* qualifier that forbids contracting a*b - c*d into an FMA, or "" */
    const char *mul;           /* a product of two operands, printf format ("%s * %s") */
    const char *local_id;      /* the invocation's index in its workgroup */
    const char *group_x, *group_y, *groups_x; /* workgroup ids and the number along x */
    const char *planes_buffer; /* file-scope declaration of the values buffer (with --planes), or
                                  NULL when it is a kernel parameter that may be null */
    const char *interface;     /* the banner's description of bindings / signature and dispatch */
    const char *fabs, *fmax;   /* absolute value and maximum of floats (--certified) */
} kern_target;

/* Writes a GPU kernel for target g: P threads per patch accumulate the planes they own in
 * shared memory from the scheduled tables, then one thread per patch combines the signs. */
int kern_emit_gpu(sbuf *o, const tp_table *t, const out_info *info, const kern_target *g,
                  ptp_error *err);

/* The targets (one emitter each); signatures as the outputs of out.h. */
int emit_glsl(sbuf *o, const tp_table *t, const out_info *info, ptp_error *err);
int emit_hlsl(sbuf *o, const tp_table *t, const out_info *info, ptp_error *err);
int emit_opencl(sbuf *o, const tp_table *t, const out_info *info, ptp_error *err);
int emit_cuda(sbuf *o, const tp_table *t, const out_info *info, ptp_error *err);
int emit_c(sbuf *o, const tp_table *t, const out_info *info, ptp_error *err);

#endif
