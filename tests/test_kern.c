/* test_kern.c: checks that the GPU emitter writes every construct of the C family through its
 * syntax hooks: a kernel of the WGSL target, whose syntax is of another form, keeps none of C's. */
#include "check.h"
#include "emit/targets.h"
#include "plan/sched.h"

#include <stdio.h>
#include <string.h>

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
    int d, c;
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
                             c & 2 ? OUT_DEGENERATE : OUT_STRICT, 1, c >> 2, 0, NULL};
            char name[160], why[256] = "";
            sbuf o;
            int st;
            sbuf_init(&o);
            st = tgt_emit_target(&o, tgt_find("wgsl"), &t, &info, &err);
            snprintf(name, sizeof name, "wgsl %dx%d %s %s%s: no C-family construct left",
                     degrees[d][0], degrees[d][1], c & 1 ? "world" : "clip",
                     c & 2 ? "degenerate" : "strict", c & 4 ? " certified" : "");
            if (check(!st, name, "%s", err.msg))
                check(!c_construct(o.s, why, sizeof why) && strstr(o.s, "select(") &&
                          strstr(o.s, "var<workgroup> pts") && strstr(o.s, "fn ptp_class_of(f: u32)"),
                      name, "kept: %s", why);
            sbuf_clear(&o);
        }
        sched_clear(&s);
        tp_clear(&t);
    }
    return check_failed_count != 0;
}
