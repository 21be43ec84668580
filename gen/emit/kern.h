/* kern.h: the kernel emitters (the GPU targets' and the C header's) and kern_target, the data
 * table that specializes the one GPU emitter, with kern_syntax, its hooks for a language's form. */
#ifndef KERN_H
#define KERN_H

#include "emit/out.h"

/* --kernel lanes: the straight-line program in vectors of width patches, each work-item a vector
 * (for CPU devices, whose compilers vectorize across work-items poorly). */
typedef struct {
    int width;
    const char *real;     /* the vector of floats: "float16" */
    const char *flag;     /* the vector comparisons give, -1 or 0 a lane: "int16" */
    const char *decl;     /* declares vector locals: "const float16 " */
    const char *point;    /* the points' struct, printf format of the prefix */
    const char *classify; /* classify_lanes' head through its brace, of its name, the prefix, K */
    const char *interface; /* the banner's, in the target's interface's place */
    /* the kernel's body: gathers each work-item's patches, classifies, scatters; $ stands for
     * the prefix, @ for the upper-case prefix (kgpu_lanes_body) */
    const char *body;
} kern_lanes;

typedef struct kern_target kern_target;

/* A member of the kernel's parameter block as the host writes it (--host-header): C type
 * ("float" or "uint32_t"), name, element count (1: a scalar, else an array), and byte offset
 * where the kernel reads it; pad members are named pad and must be 0. */
typedef struct {
    const char *type, *name;
    int count;
    unsigned offset;
} kern_host_field;

/* When a host slot exists: always, with --planes, with --kernel indexed, or with --kernel
 * indexed --basis bspline. */
enum { KERN_SLOT_ALWAYS, KERN_SLOT_PLANES, KERN_SLOT_INDEXED, KERN_SLOT_BOUNDARY };

/* A binding slot or argument index the host header declares as PREFIX_NAME (--host-header): the
 * name after the prefix, its value, what it is, and when it exists (KERN_SLOT_). */
typedef struct {
    const char *name;
    long value;
    const char *comment;
    int when;
} kern_host_slot;

/* A variable of a local declaration: its name, its initializer (NULL: none; the kernel assigns
 * the variable before it reads it), and whether it is assigned again after its declaration. */
typedef struct {
    const char *name, *init;
    int assigned;
} kern_var;

/* A parameter of a helper function. */
typedef struct {
    const char *type, *name;
} kern_param;

/* How a family of languages writes what differs in structure. kern_gpu*.c write everything else
 * in one syntax every target accepts: the operators + - * / % & | >> == != < > ! && (operands of
 * & and | parenthesized), indexing, .x .y .z .w components, calls, the assignments = += |= and
 * i++, `for (init; cond; step)` and `if (cond)` with braced or single-statement bodies (see
 * braces), `return`, slash-star comments, and literals that carry their type (16u, 0xffffu, 1.0f),
 * with no implicit conversion between integers and floats. Type names passed to the hooks are
 * the target's uint, real or vec4, or "bool". kern_c_syntax is the C family's. */
typedef struct {
    /* Appends a whole line declaring the compile-time constant name of the given type, with
     * value (a literal) and comment (words, or NULL). C: #define NAME VALUE and the comment. */
    void (*constant)(sbuf *o, const kern_target *g, const char *name, const char *type,
                     const char *value, const char *comment);
    /* Appends the start of a file-scope constant table name of n values of type, up to the first
     * value; the caller then writes the values (the first after "\n    ", the others after ", "
     * or ",\n    ") and table_close. C: `table_qual type name[n] = {`. */
    void (*table_open)(sbuf *o, const kern_target *g, const char *type, const char *name, long n);
    const char *table_close; /* ends a table after its last value, with the newline; C "\n};\n" */
    /* Appends a whole line, starting with indent, declaring the workgroup-shared array name of
     * count values of type; count is an expression of constants. C: `shared_qual type name[count];` */
    void (*shared)(sbuf *o, const kern_target *g, const char *indent, const char *type,
                   const char *name, const char *count);
    /* Appends a whole line, starting with indent, declaring the local array name of count values
     * of type. C: `type name[count];` */
    void (*array)(sbuf *o, const kern_target *g, const char *indent, const char *type,
                  const char *name, const char *count);
    /* Appends the head of a helper function through the line with its opening brace: the result
     * type ret, the name and the n parameters p. The body follows; the caller closes it with "}".
     * C: `func_qual ret name(type a, type b)` and "{" on its own line. */
    void (*function)(sbuf *o, const kern_target *g, const char *ret, const char *name,
                     const kern_param *p, int n);
    /* Appends whole lines, starting with indent, declaring the n local variables v of one type.
     * exact: no product of the initializers may be contracted into an FMA (where the language can
     * say so: C family, the target's precise qualifier; WGSL cannot, its mul keeps the products
     * apart instead). C: `type a = x, b;` on one line. */
    void (*locals)(sbuf *o, const kern_target *g, const char *indent, const char *type,
                   const kern_var *v, int n, int exact);
    /* Writes to out (size bytes, truncating as snprintf) the expression "t if cond, else f", with
     * no parentheses around it (the caller adds them where an operator follows); f may itself be
     * a select. C: `cond ? t : f`. */
    void (*select)(char *out, size_t size, const char *cond, const char *t, const char *f);
    const char *isnan; /* printf format of whether the float %s is NaN, a bool; C "isnan(%s)" */
    int braces;        /* 1: bodies of for and if are always braced; 0: a single statement is not */
} kern_syntax;

/* slp_cert_shift for languages with `precise float` (GLSL, HLSL): Dekker's exact product on
 * Veltkamp's split, as written (kern_gpu_slp_cert.c). */
extern const char kern_precise_shift[];

/* What differs between the GPU targets: one table per target (kern_glsl in emit_glsl.c, ...).
 * A string field documented "or NULL" may be left out of the initializer. The kernel's text
 * names what its template declares: cp (the points, vec4), cls (the classes), planes, eye,
 * patch_count and, in its slot INDEXED, indices_decl and boundary_decl. A new target is a file
 * with its table (and, outside the C family, its kern_syntax), its template templates/<name>/,
 * and an entry naming the table in emit/targets.c. */
struct kern_target {
    const char *name;          /* "glsl" */
    const char *language;      /* for the banner: "GLSL 4.50 compute shader" */
    const char *template_name; /* "glsl/kernel.comp" */
    int named_kernel;          /* the kernel is <prefix>classify (else the entry point is main) */
    const kern_syntax *syntax; /* the language's structure */
    const char *uint, *real, *vec4; /* the type names: 32-bit unsigned, float, 4 floats */
    const char *table_qual;    /* qualifier of constant tables */
    const char *func_qual;     /* qualifier of helper functions, with its space, or NULL */
    const char *shared_qual;   /* qualifier of workgroup-shared arrays */
    int shared_in_body;        /* shared arrays are declared inside the kernel (else at file scope) */
    const char *barrier;       /* a workgroup barrier with shared-memory ordering, as a statement */
    const char *precise;       /* qualifier that forbids contracting a*b - c*d into an FMA, with
                                  its space, or NULL */
    const char *mul;           /* a product of two operands of cross4, printf format ("%s * %s");
                                  CUDA's and WGSL's are never contracted into an FMA */
    /* every other float product of the kernel (a round's weight times its term, the world
     * term's eye products, the clip value's eye.z, the certified bound's): the name of a
     * function of two floats, product(a, b), or NULL: a * b, left to the language's contraction
     * rules (precise, FP_CONTRACT OFF). CUDA's __fmul_rn: nvcc contracts a product into the add
     * it feeds by default (-fmad=true), whatever the pragmas say */
    const char *product;
    const char *local_id;      /* the invocation's index in its workgroup */
    const char *group_x, *group_y, *groups_x; /* workgroup ids and the number along x */
    const char *planes_buffer; /* file-scope declaration of the values buffer (with --planes), or
                                  NULL when it is a kernel parameter that may be null */
    const char *interface;     /* the banner's description of bindings / signature and dispatch */
    /* --kernel indexed: the declarations of the indices (uint, K a patch) and of the boundary
     * masks (--basis bspline: uint, one a patch), read-only buffers point_index and
     * boundary_mask: whole file-scope lines, or a named kernel's parameters after patch_count,
     * each from its comma; and the banner's lines on each */
    const char *indices_decl, *boundary_decl, *indices_note, *boundary_note;
    const char *fabs, *fmax;   /* absolute value and maximum of floats (--certified) */
    double unit_roundoff;      /* --certified: the largest relative error of one float + - *:
                                  0x1p-24 rounding to nearest, 0x1p-23 where the language lets a
                                  result be either neighbour of the exact value */
    /* --certified: the difference b - a of two points (vec4), rounded once per component and
     * crossed by no reassociation or contraction (the kernel's diff function returns it from an
     * exact local), printf format of the arguments b, a, b, a, b, a, b, a (a format may take the
     * components one by one); the terms then read b_j, b_k - b_j, b_l - b_j, whose monomials
     * are far smaller than b_j, b_k, b_l's (docs/errors.md: differences); NULL: b_j, b_k, b_l */
    const char *diff;
    const char *bits;          /* a float's bits as a uint, printf format of the float (--certified
                                  --rule degenerate: the exact tests of collapsed edges) */
    /* --certified's second look in double-float: the type of two floats (.x hi, .y lo) and its
     * constructor, a printf format of two floats; NULL: no second look (WGSL: the language may
     * reassociate and fuse the error-free transformations and fixes no rounding mode). */
    const char *vec2, *vec2_make;
    /* a fused multiply-add with one rounding, printf format of a, b, c for a * b + c (the second
     * look's exact two-product), or NULL: Dekker's product on Veltkamp's split instead */
    const char *fma;
    /* 1: the second look tests each round's weight, so that every round is a basic block of its
     * own: HLSL's SPIR-V legalization (glslang, DXC) inlines every call, in a time quadratic in
     * the size of the block that receives the inlined code */
    int split_rounds;
    /* 1: the table kernel's second look reads the terms of the planes it looks at again from one
     * table of all terms (constant memory); 0: it sums every plane again from the rounds' small
     * tables (lavapipe copies a large constant array at every dynamic access, and compiles a loop
     * over one for minutes) */
    int df_table;
    const kern_lanes *lanes; /* --kernel lanes (NULL: the target has none) */
    /* The straight-line functions (kern_gpu_slp.c): classify_patch and values. */
    const char *slp_classify; /* classify_patch's head through its opening brace, printf format of
                                 its name and the point count K: "uint %s(vec4 cp[%d], vec4 eye)\n{" */
    const char *slp_values;   /* values' head, printf format of its name, K and the plane count L */
    const char *slp_look;     /* --certified: second_look's head (the class c, the planes to look
                                 at again as bits of redo), format of its name, K and the words W;
                                 NULL: no second look (a patch whose bounds do not clear is
                                 silhouette) */
    const char *slp_d;        /* values' element P of d, printf format of P: "d[%d]" */
    const char *slp_decl;     /* declares float locals that no contraction crosses: "precise float " */
    const char *slp_fma;      /* an explicitly fused a * b + c, printf format of a, b, c */
    /* --certified straight-line code: the largest relative error of one of its operations:
     * 0x1p-24 where slp_fma rounds once; 0x1p-23 (and a little) where it may round the product and
     * the sum apart (Vulkan's precision of Fma, HLSL's precise mad); 0: not certified (WGSL, which
     * may reassociate) */
    double slp_cert_u;
    /* --certified straight-line code where slp_fma may round its product apart: the definition of
     * <prefix>shift(o, w, x), x + o * w with the product exact, which the shear then calls,
     * printf format of the prefix; NULL: slp_fma rounds once */
    const char *slp_cert_shift;
    /* the program's product, printf format of the prefix giving that of a and b, or NULL: mul */
    const char *slp_mul;
    const char *slp_helpers;  /* functions the program calls, printf format of the prefix, or NULL */
    const char *slp_zero;     /* the kernel's last argument of a call, with its comma, or NULL */
    const char *slp_ref;      /* a call's argument for the array d, printf format of d: "%s" */
    const char *slp_note;     /* the banner's words on calling the functions, or NULL */
    const char *slp_preamble; /* what --stage function's file needs before them, or NULL */
    const char *slp_suffix;   /* --stage function's file suffix, for the banner: ".glsl" */
    const char *slp_language; /* --stage function's language, for the banner: "GLSL 4.50 functions" */
    /* The host header (--host-header, host_header.c). */
    const char *host_params_note; /* where the parameter block goes and its layout, comment lines
                                     " * ..." each ending in \n; or the argument order */
    const kern_host_field *host_params; /* the parameter block's members, ending at name NULL;
                                           NULL: no block (kernel arguments, host_slots) */
    unsigned host_params_size;          /* its size in bytes, padding included */
    const kern_host_slot *host_slots;   /* bindings, registers or argument indices, ending at
                                           name NULL */
};

/* The C family's syntax: GLSL, HLSL, OpenCL C and CUDA. */
extern const kern_syntax kern_c_syntax;
/* The GPU targets' tables. */
extern const kern_target kern_glsl, kern_hlsl, kern_opencl, kern_cuda, kern_wgsl;

/* Writes target g's GPU code: by default a compute kernel of one patch an invocation on the
 * straight-line functions; the table kernel (kgpu_table_kernel: P threads a patch accumulate the
 * planes they own in shared memory from the scheduled tables, one combines the signs); or, with
 * info->functions, the functions alone. */
int kern_emit_gpu(sbuf *o, const tp_table *t, const out_info *info, const kern_target *g,
                  ptp_error *err);

/* The workgroup of kern_emit_gpu's compute kernel for info: *threads invocations, handling
 * *patches patches (the straight-line kernel: info->group of each; the table kernel: the
 * schedule's P threads times Q patches, and Q). The kernel and the host header read it here. */
void kgpu_dispatch(const out_info *info, unsigned *threads, unsigned *patches);

/* --host-header: appends the C/C++ host header of the compute kernel `kernel` (kern_emit_gpu's
 * output for info and g): parameter block, slots, workgroup, dispatch and the source. */
int hh_write(sbuf *o, const tp_table *t, const out_info *info, const kern_target *g,
             const sbuf *kernel, ptp_error *err);

/* --stage function: the target's classify_patch and values, as kern_emit_gpu's kernel calls them. */
int kgpu_slp_functions(sbuf *o, const tp_table *t, const out_info *info, const kern_target *g,
                       ptp_error *err);

/* The C target (a header, not a kernel); the signature of the outputs of out.h. */
int emit_c(sbuf *o, const tp_table *t, const out_info *info, ptp_error *err);

#endif
