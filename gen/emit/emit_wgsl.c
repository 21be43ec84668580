/* emit_wgsl.c: the WGSL target: a WebGPU compute shader (storage buffers, a uniform block).
 * What is WGSL's own is this table and its syntax; the kernel comes from kern_gpu.c. */
#include "emit/kern.h"

#include <stdio.h>

/* WGSL's hooks: the contracts are kern_syntax's (kern.h). */
static void wgsl_constant(sbuf *o, const kern_target *g, const char *name, const char *type,
                          const char *value, const char *comment)
{
    (void)g;
    sbuf_printf(o, "const %s: %s = %s;", name, type, value);
    if (comment)
        sbuf_printf(o, " /* %s */", comment);
    sbuf_puts(o, "\n");
}

static void wgsl_table_open(sbuf *o, const kern_target *g, const char *type, const char *name,
                            long n)
{
    sbuf_printf(o, "%s %s: array<%s, %ld> = array<%s, %ld>(", g->table_qual, name, type, n, type, n);
}

static void wgsl_shared(sbuf *o, const kern_target *g, const char *indent, const char *type,
                        const char *name, const char *count)
{
    sbuf_printf(o, "%s%s %s: array<%s, %s>;\n", indent, g->shared_qual, name, type, count);
}

static void wgsl_array(sbuf *o, const kern_target *g, const char *indent, const char *type,
                       const char *name, const char *count)
{
    (void)g;
    sbuf_printf(o, "%svar %s: array<%s, %s>;\n", indent, name, type, count);
}

static void wgsl_function(sbuf *o, const kern_target *g, const char *ret, const char *name,
                          const kern_param *p, int n)
{
    int i;
    (void)g;
    sbuf_printf(o, "fn %s(", name);
    for (i = 0; i < n; i++)
        sbuf_printf(o, "%s%s: %s", i == 0 ? "" : ", ", p[i].name, p[i].type);
    sbuf_printf(o, ") -> %s {\n", ret);
}

/* One declaration a line, `let` for a variable never assigned again. exact needs nothing here:
 * the target's products (mul) are kept out of FMAs themselves. */
static void wgsl_locals(sbuf *o, const kern_target *g, const char *indent, const char *type,
                        const kern_var *v, int n, int exact)
{
    int i;
    (void)g, (void)exact;
    for (i = 0; i < n; i++)
        sbuf_printf(o, "%s%s %s: %s%s%s;\n", indent, v[i].assigned ? "var" : "let", v[i].name, type,
                    v[i].init ? " = " : "", v[i].init ? v[i].init : "");
}

static void wgsl_select(char *out, size_t size, const char *cond, const char *t, const char *f)
{
    snprintf(out, size, "select(%s, %s, %s)", f, t, cond);
}

static const kern_syntax wgsl_syntax = {
    .constant = wgsl_constant,
    .table_open = wgsl_table_open,
    .table_close = "\n);\n",
    .shared = wgsl_shared,
    .array = wgsl_array,
    .function = wgsl_function,
    .locals = wgsl_locals,
    .select = wgsl_select,
    /* WGSL has no isnan, and its compilers may assume there is no NaN: test the bits. */
    .isnan = "(bitcast<u32>(%s) & 0x7fffffffu) > 0x7f800000u",
    .braces = 1,
};

/* --host-header: the uniform Params at binding 3, 32 bytes (zero and the padding 0). */
static const kern_host_field host_params[] = {
    {"float", "eye", 4, 0}, {"uint32_t", "patch_count", 1, 16}, {"uint32_t", "zero", 1, 20},
    {"uint32_t", "pad", 2, 24}, {NULL, NULL, 0, 0}};
static const kern_host_slot host_slots[] = {
    {"GROUP", 0, "bind group of every binding", 0},
    {"BINDING_POINTS", 0, "storage, read-only: the control points, array<vec4<f32>>", 0},
    {"BINDING_CLASSES", 1, "storage: the classes, array<u32>", 0},
    {"BINDING_PLANES", 2, "storage: the values d[p*L + P], array<f32>", KERN_SLOT_PLANES},
    {"BINDING_INDICES", 4, "storage, read-only: the indices, K a patch, array<u32>", KERN_SLOT_INDEXED},
    {"BINDING_BOUNDARY", 5, "storage, read-only: the boundary masks, one a patch, array<u32>",
     KERN_SLOT_BOUNDARY},
    {"BINDING_PARAMS", 3, "uniform: Params, sizeof(params) bytes", 0},
    {NULL, 0, NULL, 0}};

const kern_target kern_wgsl = {
    .name = "wgsl",
    .language = "WGSL compute shader for WebGPU",
    .template_name = "wgsl/kernel.wgsl",
    .syntax = &wgsl_syntax,
    .uint = "u32", .real = "f32", .vec4 = "vec4<f32>",
    .table_qual = "const", /* var<private> runs faster on lavapipe, but compiles minutes longer */
    .shared_qual = "var<workgroup>",
    .barrier = "workgroupBarrier();",
    .mul = "mul_rn(%s, %s)", /* the template's product that no FMA contraction crosses */
    .local_id = "lid3.x",
    .group_x = "wid.x", .group_y = "wid.y", .groups_x = "nwg.x",
    .planes_buffer = "@group(0) @binding(2) var<storage, read_write> planes: array<f32>;\n",
    .interface =
        " * Bindings (group 0): 0 control points (var<storage, read> array<vec4<f32>>), 1 classes\n"
        " * (var<storage, read_write> array<u32>), 2 values d[p*L + P] (array<f32>, with --planes),\n"
        " * 3 var<uniform> { eye: vec4<f32>, patch_count: u32, zero: u32 } (32 bytes; zero, and the\n"
        " * rest of the padding, must be 0). Entry point main. Dispatch ceil(patch_count / Q)\n"
        " * workgroups, in 2-D (x, y) when x would exceed the limit: workgroup (x, y) handles the\n"
        " * patches of block y * num_workgroups.x + x.\n",
    .indices_decl = "@group(0) @binding(4) var<storage, read> point_index: array<u32>;\n",
    .boundary_decl = "@group(0) @binding(5) var<storage, read> boundary_mask: array<u32>;\n",
    .indices_note = " * Binding 4 the indices point_index (array<u32>, K a patch).\n",
    .boundary_note = " * Binding 5 the boundary masks boundary_mask (array<u32>, one a patch).\n",
    .fabs = "abs", .fmax = "max",
    .unit_roundoff = 0x1p-23, /* no rounding mode specified: either neighbour */
    .diff = "sub_rn(%s, %s)", /* the template's difference that no reassociation crosses */
    .bits = "bitcast<u32>(%s)",
    .slp_classify = "fn %s(cp: array<vec4<f32>, %d>, eye: vec4<f32>, zero: u32) -> u32 {",
    .slp_values = "fn %s(cp: array<vec4<f32>, %d>, eye: vec4<f32>, zero: u32,\n"
                  "        d: ptr<function, array<f32, %d>>) {",
    .slp_d = "(*d)[%d]",
    .slp_decl = "let ",
    .slp_fma = "fma(%s, %s, %s)",
    .slp_mul = "%smul_rn(%%s, %%s, zero)",
    .slp_helpers = "/* x * y rounded to a float: through an integer XOR with zero, 0 at run time but unknown to\n"
                   " * the compiler, which no FMA contraction can cross (WGSL has no `precise`). */\n"
                   "fn %smul_rn(x: f32, y: f32, zero: u32) -> f32 {\n"
                   "    return bitcast<f32>(bitcast<u32>(x * y) ^ zero);\n}\n\n",
    .slp_zero = ", params.zero",
    .slp_ref = "&%s",
    .slp_note = " * zero: 0, read from a uniform or storage buffer so that the compiler cannot know it\n"
                " * (it keeps the products out of FMAs, so that equal points give exact zeros).\n",
    .slp_suffix = ".wgsl",
    .slp_language = "WGSL functions",
    .host_params_note =
        " * var<uniform> params: Params at group 0 binding 3: a uniform buffer of sizeof(params) =\n"
        " * 32 bytes (WGSL rounds the struct up to its 16-byte alignment); zero and pad must be 0.\n",
    .host_params = host_params, .host_params_size = 32, .host_slots = host_slots,
};
