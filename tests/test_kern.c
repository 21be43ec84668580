/* test_kern.c: checks that the GPU emitter writes every construct of the C family through its
 * syntax hooks: a kernel written with a probe syntax of another form keeps none of C's. */
#include "check.h"
#include "emit/kern.h"
#include "plan/sched.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The probe syntax: the forms a WGSL-like language would use, each contract of kern_syntax. */
static void p_constant(sbuf *o, const kern_target *g, const char *name, const char *type,
                       const char *value, const char *comment)
{
    (void)g;
    sbuf_printf(o, "const %s: %s = %s;%s%s\n", name, type, value, comment ? " // " : "",
                comment ? comment : "");
}

static void p_table_open(sbuf *o, const kern_target *g, const char *type, const char *name, long n)
{
    (void)g;
    sbuf_printf(o, "const %s = array<%s, %ld>(", name, type, n);
}

static void p_shared(sbuf *o, const kern_target *g, const char *indent, const char *type,
                     const char *name, const char *count)
{
    (void)g;
    sbuf_printf(o, "%svar<workgroup> %s: array<%s, %s>;\n", indent, name, type, count);
}

static void p_function(sbuf *o, const kern_target *g, const char *ret, const char *name,
                       const kern_param *p, int n)
{
    int i;
    (void)g;
    sbuf_printf(o, "fn %s(", name);
    for (i = 0; i < n; i++)
        sbuf_printf(o, "%s%s: %s", i == 0 ? "" : ", ", p[i].name, p[i].type);
    sbuf_printf(o, ") -> %s\n{\n", ret);
}

static void p_locals(sbuf *o, const kern_target *g, const char *indent, const char *type,
                     const kern_var *v, int n, int exact)
{
    int i;
    (void)g, (void)exact;
    for (i = 0; i < n; i++)
        sbuf_printf(o, "%s%s %s: %s%s%s;\n", indent, v[i].assigned ? "var" : "let", v[i].name, type,
                    v[i].init ? " = " : "", v[i].init ? v[i].init : "");
}

static void p_select(char *out, size_t size, const char *cond, const char *t, const char *f)
{
    snprintf(out, size, "select(%s, %s, %s)", f, t, cond);
}

static const kern_syntax probe = {
    .constant = p_constant,
    .table_open = p_table_open,
    .table_close = "\n);\n",
    .shared = p_shared,
    .function = p_function,
    .locals = p_locals,
    .select = p_select,
    .isnan = "is_nan(%s)",
    .braces = 1,
};

/* The first line of the kernel's text s (banner and template boilerplate left out: the tables
 * on) that keeps a C-family construct, or NULL. */
static const char *c_construct(const char *s, char *why, size_t size)
{
    static const char *const decl[] = {"float ", "uint ", "bool ", "vec4 ", "precise ", "const uint",
                                       "const float", "shared "};
    const char *line = strstr(s, "const PTP_"), *end;
    size_t i;
    for (; line && *line; line = *end ? end + 1 : end) {
        const char *p = line;
        end = strchr(line, '\n');
        if (!end)
            end = line + strlen(line);
        while (*p == ' ')
            p++;
        snprintf(why, size, "%.*s", (int)(end - line), line);
        if (memchr(line, '?', (size_t)(end - line)) || strncmp(p, "#define", 7) == 0)
            return line;
        for (i = 0; i < sizeof decl / sizeof decl[0]; i++)
            if (strncmp(p, decl[i], strlen(decl[i])) == 0)
                return line;
        if ((strncmp(p, "for (", 5) == 0 || strncmp(p, "if (", 4) == 0) && end[-1] != '{')
            return line;
    }
    return NULL;
}

int main(void)
{
    static const int degrees[][2] = {{1, 1}, {2, 3}, {3, 3}};
    kern_target g = kern_glsl;
    int d, c;
    g.syntax = &probe;
    for (d = 0; d < 3; d++) {
        tp_table t;
        sched s;
        ptp_error err;
        int P;
        if (tp_derive(&t, degrees[d][0], degrees[d][1], &err))
            return check(0, "derive", "%s", err.msg), 1;
        P = sched_default_threads(&t);
        if (sched_build(&s, &t, P, sched_default_patches(P), &err))
            return check(0, "schedule", "%s", err.msg), 1;
        for (c = 0; c < 8; c++) { /* space, rule, certified */
            out_info info = {"test", "ptp_", &s, c & 1 ? OUT_WORLD : OUT_CLIP,
                             c & 2 ? OUT_DEGENERATE : OUT_STRICT, 1, c >> 2, 0};
            char name[160], why[256] = "";
            sbuf o;
            int st;
            sbuf_init(&o);
            st = kern_emit_gpu(&o, &t, &info, &g, &err);
            snprintf(name, sizeof name, "probe syntax %dx%d %s %s%s: no C-family construct left",
                     degrees[d][0], degrees[d][1], c & 1 ? "world" : "clip",
                     c & 2 ? "degenerate" : "strict", c & 4 ? " certified" : "");
            if (check(!st, name, "%s", err.msg))
                check(!c_construct(o.s, why, sizeof why) && strstr(o.s, "select(") &&
                          strstr(o.s, "var<workgroup> pts") && strstr(o.s, "fn ptp_class_of(f: uint)"),
                      name, "kept: %s", why);
            sbuf_clear(&o);
        }
        sched_clear(&s);
        tp_clear(&t);
    }
    return check_failed_count != 0;
}
