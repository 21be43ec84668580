/* kern_c_syntax.c: the C family's syntax hooks (kern_c_syntax, kern.h): how GLSL, HLSL, OpenCL
 * C and CUDA write constants, tables, shared arrays, functions, locals and selects. */
#include "emit/kern_gpu.h"

#include <stdio.h>

/* The C family's hooks: the contracts are kern_syntax's (kern.h). */
static void c_constant(sbuf *o, const kern_target *g, const char *name, const char *type,
                       const char *value, const char *comment)
{
    (void)g, (void)type;
    if (comment)
        sbuf_printf(o, "#define %s %s /* %s */\n", name, value, comment);
    else
        sbuf_printf(o, "#define %s %s\n", name, value);
}

static void c_table_open(sbuf *o, const kern_target *g, const char *type, const char *name, long n)
{
    sbuf_printf(o, "%s %s %s[%ld] = {", g->table_qual, type, name, n);
}

static void c_shared(sbuf *o, const kern_target *g, const char *indent, const char *type,
                     const char *name, const char *count)
{
    sbuf_printf(o, "%s%s %s %s[%s];\n", indent, g->shared_qual, type, name, count);
}

static void c_array(sbuf *o, const kern_target *g, const char *indent, const char *type,
                    const char *name, const char *count)
{
    (void)g;
    sbuf_printf(o, "%s%s %s[%s];\n", indent, type, name, count);
}

static void c_function(sbuf *o, const kern_target *g, const char *ret, const char *name,
                       const kern_param *p, int n)
{
    int i;
    sbuf_printf(o, "%s%s %s(", kgpu_opt(g->func_qual), ret, name);
    for (i = 0; i < n; i++)
        sbuf_printf(o, "%s%s %s", i == 0 ? "" : ", ", p[i].type, p[i].name);
    sbuf_puts(o, ")\n{\n");
}

static void c_locals(sbuf *o, const kern_target *g, const char *indent, const char *type,
                     const kern_var *v, int n, int exact)
{
    int i;
    sbuf_printf(o, "%s%s%s ", indent, exact ? kgpu_opt(g->precise) : "", type);
    for (i = 0; i < n; i++)
        sbuf_printf(o, "%s%s%s%s", i == 0 ? "" : ", ", v[i].name, v[i].init ? " = " : "",
                    kgpu_opt(v[i].init));
    sbuf_puts(o, ";\n");
}

static void c_select(char *out, size_t size, const char *cond, const char *t, const char *f)
{
    snprintf(out, size, "%s ? %s : %s", cond, t, f);
}

const kern_syntax kern_c_syntax = {
    .constant = c_constant,
    .table_open = c_table_open,
    .table_close = "\n};\n",
    .shared = c_shared,
    .array = c_array,
    .function = c_function,
    .locals = c_locals,
    .select = c_select,
    .isnan = "isnan(%s)",
    .braces = 0,
};
