/* kern_gpu_df.c: the second look's double-float arithmetic: error-free transformations and the
 * term in double-float, as helper functions of the GPU kernel, written in a small shorthand. */
#include "emit/kern_gpu.h"

#include <stdio.h>
#include <string.h>

void kgpu_df_text(sbuf *o, const out_info *info, const kern_target *g, const char *src)
{
    while (*src) {
        const char *end = *src == '{' ? strchr(src, '}') : NULL;
        if (*src == '$') {
            sbuf_puts(o, info->prefix);
            src++;
        } else if (end) {
            char a[64], b[64], c[64] = "";
            size_t n = strcspn(src + 1, "*;"), m = strcspn(src + n + 2, "+}");
            snprintf(a, sizeof a, "%.*s", (int)n, src + 1);
            snprintf(b, sizeof b, "%.*s", (int)m, src + n + 2);
            if (src[n + 2 + m] == '+')
                snprintf(c, sizeof c, "%.*s", (int)(end - src - n - m - 3), src + n + m + 3);
            sbuf_printf(o, *c ? g->fma : src[1 + n] == '*' ? g->mul : g->vec2_make, a, b, c);
            src = end + 1;
        } else {
            sbuf_printf(o, "%c", *src++);
        }
    }
}

/* A double-float helper: its name (after the prefix), parameters and locals as a type letter
 * (f real, v the pair, 4 vec4) and a name, the locals with their initializers, and the value it
 * returns, all in kgpu_df_text's shorthand. Every local is exact (never contracted). */
typedef struct {
    const char *name, *params[6], *locals[6], *ret;
    int fma; /* 1: only for a target with a one-rounding FMA; -1: only without; 0: always */
} df_helper;

/* The double-float operations: error-free two-sum (Knuth), fast two-sum, the two-product (with a
 * one-rounding FMA, or Dekker's on Veltkamp's split, exact for 24-bit floats), and from them (Joldes, Muller and Popescu
 * 2017) the pair times a float, times a pair, and the accurate sum; then 2x2 minors and cofactor
 * sums of the determinants. */
static const df_helper df_helpers[] = {
    {"df_two_sum", {"fa", "fb"}, {"fs=a + b", "fv=s - a", "fe=(a - (s - v)) + (b - v)"}, "{s;e}", 0},
    {"df_fast_two_sum", {"fa", "fb"}, {"fs=a + b", "fe=b - (s - a)"}, "{s;e}", 0},
    {"df_split", {"fa"}, {"fc={4097.0f*a}", "fh=c - (c - a)", "fl=a - h"}, "{h;l}", -1},
    {"df_two_prod", {"fa", "fb"},
     {"vx=$df_split(a)", "vy=$df_split(b)", "fp={a*b}",
      "fe=(({x.x*y.x} - p) + {x.x*y.y} + {x.y*y.x}) + {x.y*y.y}"}, "{p;e}", -1},
    {"df_two_prod", {"fa", "fb"}, {"fp={a*b}", "fe={a*b+-p}"}, "{p;e}", 1},
    {"df_mul_f", {"vx", "fb"}, {"vc=$df_two_prod(x.x, b)", "fl=c.y + {x.y*b}"},
     "$df_fast_two_sum(c.x, l)", 0},
    {"df_mul", {"vx", "vy"}, {"vc=$df_two_prod(x.x, y.x)", "fl=c.y + ({x.x*y.y} + {x.y*y.x})"},
     "$df_fast_two_sum(c.x, l)", 0},
    {"df_add", {"vx", "vy"},
     {"vs=$df_two_sum(x.x, y.x)", "vt=$df_two_sum(x.y, y.y)", "fh=s.y + t.x",
      "vv=$df_fast_two_sum(s.x, h)", "fl=v.y + t.y"}, "$df_fast_two_sum(v.x, l)", 0},
    {"df_sub", {"vx", "vy"}, {NULL}, "$df_add(x, {-y.x;-y.y})", 0},
    {"df_minor", {"fa", "fb", "fc", "fd"}, {NULL}, "$df_sub($df_two_prod(a, b), $df_two_prod(c, d))", 0},
    {"df_cof", {"vm0", "fa0", "vm1", "fa1", "vm2", "fa2"}, {NULL},
     "$df_add($df_sub($df_mul_f(m0, a0), $df_mul_f(m1, a1)), $df_mul_f(m2, a2))", 0},
};

/* The type a df_helper's letter names. */
static const char *df_type(const kern_target *g, char c)
{
    return c == 'f' ? g->real : c == 'v' ? g->vec2 : g->vec4;
}

/* Appends helper h's function. */
static void put_df_helper(sbuf *o, const out_info *info, const kern_target *g, const df_helper *h)
{
    kern_param p[6];
    char name[128];
    sbuf e;
    int n, i;
    for (n = 0; n < 6 && h->params[n]; n++)
        p[n] = (kern_param){df_type(g, h->params[n][0]), h->params[n] + 1};
    snprintf(name, sizeof name, "%s%s", info->prefix, h->name);
    g->syntax->function(o, g, g->vec2, name, p, n);
    for (i = 0; i < 6 && h->locals[i]; i++) {
        char var[8];
        const char *eq = strchr(h->locals[i], '=');
        snprintf(var, sizeof var, "%.*s", (int)(eq - h->locals[i] - 1), h->locals[i] + 1);
        sbuf_init(&e);
        kgpu_df_text(&e, info, g, eq + 1);
        g->syntax->locals(o, g, "    ", df_type(g, h->locals[i][0]), &(kern_var){var, kgpu_opt(e.s), 0},
                          1, 1);
        o->failed |= e.failed;
        sbuf_clear(&e);
    }
    sbuf_puts(o, "    return ");
    kgpu_df_text(o, info, g, h->ret);
    sbuf_puts(o, ";\n}\n\n");
}

/* Writes to d (256 bytes) the double-float det[a b c] of rows p, q, s, as put_det expands it. */
static void put_df_det(char *d, int p, int q, int s)
{
    static const char comp[] = "xyzw";
    const char *u = "baa", *v = "ccb";
    size_t n = (size_t)snprintf(d, 256, "$df_cof(");
    int i;
    for (i = 0; i < 3; i++)
        n += (size_t)snprintf(d + n, 256 - n, "%s$df_minor(%c.%c, %c.%c, %c.%c, %c.%c), %c.%c",
                              i ? ",\n        " : "", u[i], comp[q], v[i], comp[s], u[i], comp[s],
                              v[i], comp[q], "abc"[i], comp[p]);
    snprintf(d + n, 256 - n, ")");
}

void kgpu_df_functions(sbuf *o, const out_info *info, const kern_target *g)
{
    static const int rows[5][3] = {{1, 2, 3}, {0, 2, 3}, {0, 1, 3}, {0, 1, 2}, {0, 1, 3}};
    static const char *const names[4] = {"x", "y", "z", "w"};
    const char *v = g->vec4;
    kern_param p[4] = {{v, "a"}, {v, "b"}, {v, "c"}, {v, "e"}};
    int world = info->space == OUT_WORLD, c;
    char name[128], det[256];
    sbuf_puts(o, "/* Second look: double-float arithmetic (hi .x + lo .y) from error-free transformations\n"
                 " * with + - * only, none contracted into an FMA. */\n");
    for (c = 0; c < (int)(sizeof df_helpers / sizeof *df_helpers); c++)
        if (df_helpers[c].fma != (g->fma ? -1 : 1))
            put_df_helper(o, info, g, &df_helpers[c]);
    sbuf_printf(o, "/* %s, in double-float. */\n", world ? "e . cross4(a, b, c)" : "cross4z(a, b, c)");
    snprintf(name, sizeof name, "%sdf_%s", info->prefix, world ? "eye_cross4" : "cross4z");
    g->syntax->function(o, g, g->vec2, name, p, world ? 4 : 3);
    for (c = world ? 0 : 4; c < (world ? 4 : 5); c++) {
        put_df_det(det, rows[c][0], rows[c][1], rows[c][2]);
        sbuf_printf(o, "    %s %s = ", g->vec2, world ? names[c] : "z");
        kgpu_df_text(o, info, g, det);
        sbuf_puts(o, ";\n");
    }
    if (world)
        kgpu_df_text(o, info, g, "    return $df_sub($df_add($df_sub($df_mul_f(x, e.x), $df_mul_f(y, e.y)),\n"
                                "        $df_mul_f(z, e.z)), $df_mul_f(w, e.w));\n}\n\n");
    else
        sbuf_puts(o, "    return z;\n}\n\n");
}
