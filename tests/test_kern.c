/* test_kern.c: checks that the GPU emitter writes every construct of the C family through its
 * syntax hooks (a WGSL kernel keeps none of C's), the exact-zero edge masks, split rounds and
 * the float products outside cross4 (CUDA's through __fmul_rn). */
#include "check.h"
#include "emit/kern_gpu.h"
#include "emit/targets.h"
#include "plan/sched.h"

#include <stdio.h>
#include <stdlib.h>
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

/* Reads the values of the table named ptp_zero in s (one a line after its head) into v (room for
 * n); returns how many, or -1 when s has no such table. */
static int zero_table(long *v, int n, const char *s)
{
    const char *p = strstr(s, "ptp_zero");
    int k = 0;
    if (!p || !(p = strchr(p, '\n')))
        return -1;
    while (k < n) {
        char *end;
        p += strspn(p, " ,u\n");
        v[k] = strtol(p, &end, 10);
        if (end == p)
            break;
        p = end, k++;
    }
    return k;
}

/* Every GPU target's certified degenerate kernel of t lists the C header's per-plane edge masks
 * (each computed its own way); the strict rule's kernels list none. */
static void check_zeros(const tp_table *t, const sched *s)
{
    static const char *const targets[] = {"glsl", "hlsl", "opencl", "cuda", "wgsl"};
    long ref[2][1024], v[1024];
    int i, c, n[2] = {-1, -1}, k, st;
    for (i = -1; i < 5; i++)
        for (c = 0; c < 2; c++) {
            out_info info = {.command = "test", .prefix = "ptp_", .sched = s, .space = c ? OUT_WORLD : OUT_CLIP,
                             .rule = OUT_DEGENERATE, .certified = 1, .table = 1};
            ptp_error err = {0};
            char name[160], deg[32];
            sbuf o;
            sbuf_init(&o);
            st = tgt_emit_target(&o, tgt_find(i < 0 ? "c" : targets[i]), t, &info, &err);
            k = st ? -1 : zero_table(i < 0 ? ref[c] : v, 1024, o.s);
            sbuf_clear(&o);
            snprintf(name, sizeof name, "%s %s %s certified degenerate: the edge masks of the C header",
                     i < 0 ? "c" : targets[i], tp_domain_format(deg, sizeof deg, &t->dom), c ? "world" : "clip");
            if (i < 0) {
                n[c] = k;
                check(k == t->dom.nplanes, name, "%d values, %s", k, err.msg);
                continue;
            }
            check(k == n[c] && k > 0 && !memcmp(ref[c], v, (size_t)k * sizeof *v), name,
                  "%d values against %d, %s", k, n[c], err.msg);
            info.rule = OUT_STRICT;
            sbuf_init(&o);
            st = tgt_emit_target(&o, tgt_find(targets[i]), t, &info, &err);
            snprintf(name, sizeof name, "%s %s %s strict certified: no edge masks", targets[i], deg,
                     c ? "world" : "clip");
            check(!st && zero_table(v, 1, o.s) < 0, name, "a zero table, or %s", err.msg);
            sbuf_clear(&o);
        }
}

/* The number of tests of a round's weight in s ("if (ptp_w<r>[t] != 0.0f) {"), when they are
 * those of rounds 0, 1, ... in order; else -1. */
static int round_tests(const char *s, int rounds)
{
    int n = 0, all = 0;
    const char *p;
    char head[64];
    for (p = s; (p = strstr(p, "[t] != 0.0f) {")); p++)
        all++;
    for (p = s; n < rounds; n++) {
        snprintf(head, sizeof head, "if (ptp_w%d[t] != 0.0f) {", n);
        if (!(p = strstr(p, head)))
            break;
    }
    return n == all ? n : -1;
}

/* The certified kernels of the targets with split_rounds (HLSL) put each round of the second look
 * under a test of its weight, a basic block of its own (a legalizer inlines every call, in a time
 * quadratic in a block's size); the others keep the rounds in one block. */
static void check_split_rounds(const tp_table *t, const sched *s)
{
    int i, c;
    for (i = 0; i < tgt_count; i++)
        for (c = 0; c < 2 && tgt_targets[i].gpu && tgt_targets[i].gpu->vec2; c++) {
            const kern_target *g = tgt_targets[i].gpu;
            out_info info = {.command = "test", .prefix = "ptp_", .sched = s, .space = c ? OUT_WORLD : OUT_CLIP,
                             .rule = c ? OUT_DEGENERATE : OUT_STRICT, .certified = 1, .table = 1};
            ptp_error err = {0};
            char name[160], deg[32];
            int st, n, want = g->split_rounds ? s->rounds : 0;
            sbuf o;
            sbuf_init(&o);
            st = tgt_emit_target(&o, &tgt_targets[i], t, &info, &err);
            n = st ? -2 : round_tests(o.s, s->rounds);
            sbuf_clear(&o);
            snprintf(name, sizeof name, "%s %s %s certified: %d of %d second-look rounds under a test of their weight",
                     g->name, tp_domain_format(deg, sizeof deg, &t->dom), c ? "world" : "clip", want, s->rounds);
            check(n == want, name, "%d, %s", n, err.msg);
        }
}

/* kgpu_product writes factors left to right as infix products, with groups in parentheses, or
 * through the target's product function (CUDA's __fmul_rn), with groups as plain arguments. */
static void check_product_text(void)
{
    static const char *const want[2][3] = {
        {"(1.0f + R) * R * R", "w *\n    t", "E * (a * b)"},
        {"__fmul_rn(__fmul_rn(1.0f + R, R), R)", "__fmul_rn(w,\n    t)", "__fmul_rn(E, __fmul_rn(a, b))"}};
    const kern_target *g[2] = {&kern_opencl, &kern_cuda};
    char e[3][96], x[2][32], name[96];
    int i, k;
    for (i = 0; i < 2; i++) {
        kgpu_group(x[0], sizeof x[0], g[i], "1.0f + R");
        kgpu_product(e[0], sizeof e[0], g[i], " ", 3, (const char *const[]){x[0], "R", "R"});
        kgpu_product(e[1], sizeof e[1], g[i], "\n    ", 2, (const char *const[]){"w", "t"});
        kgpu_group(x[1], sizeof x[1], g[i], kgpu_mul(x[0], sizeof x[0], g[i], "a", "b"));
        kgpu_mul(e[2], sizeof e[2], g[i], "E", x[1]);
        for (k = 0; k < 3; k++) {
            snprintf(name, sizeof name, "%s: kgpu_product's %s", g[i]->name,
                     k == 0 ? "group and factors" : k == 1 ? "line break" : "product as a group");
            check(strcmp(e[k], want[i][k]) == 0, name, "%s, not %s", e[k], want[i][k]);
        }
    }
}

/* The certified kernel's scale, from R3 through the test of its size, has infix products in
 * OpenCL and none in CUDA, whose products all go through __fmul_rn. */
static void check_scale_products(const tp_table *t, const sched *s)
{
    static const char *const target[2] = {"opencl", "cuda"};
    int i;
    for (i = 0; i < 2; i++) {
        out_info info = {.command = "test", .prefix = "ptp_", .sched = s, .space = OUT_WORLD,
                         .rule = OUT_STRICT, .certified = 1, .table = 1};
        ptp_error err = {0};
        char name[160], deg[32];
        const char *a, *b;
        int st, infix = 0;
        sbuf o;
        sbuf_init(&o);
        st = tgt_emit_target(&o, tgt_find(target[i]), t, &info, &err);
        a = st ? NULL : strstr(o.s, "R3 = ");
        b = a ? strstr(a, "if (!(") : NULL;
        if (b)
            b = strchr(b, '\n');
        for (; a && b && a < b; a++)
            infix += strncmp(a, " * ", 3) == 0;
        sbuf_clear(&o);
        snprintf(name, sizeof name, "%s %s world certified: the scale's products %s", target[i],
                 tp_domain_format(deg, sizeof deg, &t->dom), i ? "through __fmul_rn" : "infix");
        check(b && (i ? infix == 0 : infix >= 8), name, "%d infix products, %s", infix, err.msg);
    }
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
            out_info info = {.command = "test", .prefix = "ptp_", .sched = &s,
                             .space = c & 1 ? OUT_WORLD : OUT_CLIP,
                             .rule = c & 2 ? OUT_DEGENERATE : OUT_STRICT, .planes = 1,
                             .certified = c >> 2, .table = 1};
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
            if (c >> 2) /* certified: the table kernel only */
                continue;
            info.table = 0; /* the straight-line kernel */
            info.group = OUT_SLP_GROUP;
            sbuf_init(&o);
            st = tgt_emit_target(&o, tgt_find("wgsl"), &t, &info, &err);
            snprintf(name, sizeof name, "wgsl %dx%d %s %s straight-line: no C-family construct left",
                     degrees[d][0], degrees[d][1], c & 1 ? "world" : "clip",
                     c & 2 ? "degenerate" : "strict");
            if (check(!st, name, "%s", err.msg))
                check(!c_construct(o.s, why, sizeof why) && strstr(o.s, "select(") &&
                          strstr(o.s, "fn ptp_classify_patch(cp: array<vec4<f32>,"),
                      name, "kept: %s", why);
            sbuf_clear(&o);
        }
        check_zeros(&t, &s);
        check_split_rounds(&t, &s);
        check_scale_products(&t, &s);
        sched_clear(&s);
        tp_clear(&t);
    }
    check_product_text();
    return check_failed_count != 0;
}
