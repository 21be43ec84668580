/* emit_c_batch.c: the C header's classify_batch: blocks of LANES patch-major patches transposed
 * into the lanes' structure-of-arrays layout, in tiles of GNU C vector shuffles, then classified. */
#include "emit/emit_c_batch.h"

#include <stdio.h>
#include <string.h>

/* The shuffles of a tile, for a vector of w floats; the operands' lanes are numbered a 0 .. w-1,
 * b w .. 2w-1. */
typedef enum { SH_LO32, SH_HI32, SH_LO64, SH_HI64, SH_EVEN128, SH_ODD128, SH_COUNT } shuffle;
static const char *const shuffle_name[SH_COUNT] = {"LO32", "HI32", "LO64", "HI64", "EVEN128",
                                                   "ODD128"};

/* idx[0 .. w-1] = the lanes of shuffle s for vectors of w floats: in each 128-bit block, the low
 * (LO) or high (HI) pairs of a and b interleaved (32) or their 64-bit halves (64); or the even
 * or odd 128-bit blocks of a, then of b (128). */
static void shuffle_lanes(int *idx, shuffle s, int w)
{
    int i;
    for (i = 0; i < w; i++) {
        int blk = i / 4, e = i % 4, hi = s == SH_HI32 || s == SH_HI64;
        if (s == SH_EVEN128 || s == SH_ODD128) /* block i/4 of the result: a's then b's */
            idx[i] = (2 * blk + (s == SH_ODD128)) * 4 + e;
        else if (s == SH_LO32 || s == SH_HI32) /* a, b, a, b from pairs 0 (LO) or 1 (HI) */
            idx[i] = 4 * blk + 2 * hi + e / 2 + (e % 2) * w;
        else /* a, a, b, b from the low (LO) or high (HI) 64-bit half */
            idx[i] = 4 * blk + 2 * hi + e % 2 + (e / 2) * w;
    }
}

/* The shuffle macros of the transposition for w floats (the 128-bit ones only where w > 4). */
static void put_shuffles(sbuf *o, const char *up, int w)
{
    int s, i, idx[16];
    for (s = 0; s < SH_COUNT && (s < SH_EVEN128 || w > 4); s++) {
        shuffle_lanes(idx, (shuffle)s, w);
        sbuf_printf(o, "#define %s%s(a, b) %sSHUFFLE(a, b", up, shuffle_name[s], up);
        for (i = 0; i < w; i++)
            sbuf_printf(o, ", %d", idx[i]);
        sbuf_puts(o, ")\n");
    }
}

/* Names vector q of coordinate c after round r of the 128-bit rounds (r 0: before them). */
static void vec_name(char *name, size_t size, int c, int r, int q)
{
    if (r)
        snprintf(name, size, "c%d_%d_%d", c, r, q);
    else
        snprintf(name, size, "c%d_%d", c, q);
}

/* One coordinate c of a tile of w floats, from its vectors c<c>_<q> (q < w/4: block b of vector q
 * is point k+b of patches 4q .. 4q+3): rounds that take the even and odd 128-bit blocks of pairs
 * until vector b holds point k+b of all w patches; then the stores. */
static void put_tile_coordinate(sbuf *o, const char *px, const char *up, int w, int c)
{
    int r, q, n = w / 4;
    char a[24], b[24], d[24];
    for (r = 1; 1 << (r - 1) < n; r++)
        for (q = 0; q < n; q++) {
            vec_name(a, sizeof a, c, r - 1, 2 * (q % (n / 2)));
            vec_name(b, sizeof b, c, r - 1, 2 * (q % (n / 2)) + 1);
            vec_name(d, sizeof d, c, r, q);
            sbuf_printf(o, "    const %stf %s = %s%s(%s, %s);\n", px, d, up,
                        q < n / 2 ? "EVEN128" : "ODD128", a, b);
        }
    for (q = 0; q < n; q++) {
        vec_name(a, sizeof a, c, r - 1, q);
        sbuf_printf(o, "    %ststore(soa + %d * %sLANES, %s);\n", px, 4 * q + c, up, a);
    }
}

/* The tile of w patches by w/4 points (coordinate 2 only when world): loads, the 4x4 transposes
 * in every 128-bit block (32-bit, then 64-bit interleaves), then each coordinate's rounds. */
static void put_tile(sbuf *o, const char *px, const char *up, int w, int world)
{
    int i, c;
    sbuf_printf(o, "/* A tile of %d patches by %d point%s: row i, the %d floats at cp + i * 4 * "
                   "POINTS (patch i\n * from point k); column j, coordinate j %% 4 of point k + "
                   "j / 4, to soa + j * LANES. */\n"
                   "static inline void %stile(float *%sRESTRICT soa, const float *%sRESTRICT cp)\n{\n",
                w, w / 4, w > 4 ? "s" : "", w, px, up, up);
    for (i = 0; i < w; i++)
        sbuf_printf(o, "    const %stf r%d = %stload(cp + %d * 4 * %sPOINTS);\n", px, i, px, i, up);
    for (i = 0; i < w; i += 2)
        sbuf_printf(o, "    const %stf t%d = %sLO32(r%d, r%d), t%d = %sHI32(r%d, r%d);\n", px, i, up,
                    i, i + 1, i + 1, up, i, i + 1);
    for (i = 0; i < w; i += 4)
        for (c = 0; c < 4; c++)
            if (c != 2 || world)
                sbuf_printf(o, "    const %stf c%d_%d = %s%s(t%d, t%d);\n", px, c, i / 4, up,
                            c % 2 ? "HI64" : "LO64", i + c / 2, i + c / 2 + 2);
    for (c = 0; c < 4; c++)
        if (c != 2 || world)
            put_tile_coordinate(o, px, up, w, c);
    sbuf_puts(o, "}\n");
}

/* The tile width TW by instruction set (16 floats need 4 points a patch), its vector type, the
 * shuffles (clang's __builtin_shufflevector, gcc's __builtin_shuffle) and a tile per width. */
static void put_vectors(sbuf *o, const tp_table *t, const char *px, const char *up, int world)
{
    static const int widths[] = {16, 8, 4};
    int i;
    sbuf_printf(o, "/* classify_batch's transposition: tiles of %sTW patches in GNU C vectors "
                   "(gcc, clang) where\n * SSE2 or NEON is, unless %sNO_SSE is defined. */\n"
                   "#if defined(__GNUC__) && !defined(%sNO_SSE) && (defined(__SSE2__) || "
                   "defined(__ARM_NEON))\n#include <string.h>\n",
                up, up, up);
    if (t->dom.npoints >= 4)
        sbuf_printf(o, "#if defined(__AVX512F__)\n#define %sTW 16\n#elif", up);
    else
        sbuf_puts(o, "#if");
    sbuf_printf(o, " defined(__AVX__)\n#define %sTW 8\n#else\n#define %sTW 4\n#endif\n"
                   "#define %sTALIGN __attribute__((aligned(4 * %sTW)))\n"
                   "typedef float %stf __attribute__((vector_size(4 * %sTW)));\n"
                   "#if defined(__clang__)\n"
                   "#define %sSHUFFLE(a, b, ...) __builtin_shufflevector(a, b, __VA_ARGS__)\n"
                   "#else\n"
                   "typedef int %sti __attribute__((vector_size(4 * %sTW)));\n"
                   "#define %sSHUFFLE(a, b, ...) __builtin_shuffle(a, b, __extension__(%sti){__VA_ARGS__})\n"
                   "#endif\n"
                   "static inline %stf %stload(const float *p)\n{\n    %stf v;\n"
                   "    memcpy(&v, p, sizeof v);\n    return v;\n}\n"
                   "static inline void %ststore(float *p, %stf v)\n{\n    memcpy(p, &v, sizeof v);\n}\n",
                up, up, up, up, px, up, up, px, up, up, px, px, px, px, px, px);
    for (i = t->dom.npoints < 4; i < 3; i++) { /* the widths this patch has points for */
        sbuf_printf(o, i == 2 ? "#else\n" : "#%s %sTW == %d\n",
                    i == (t->dom.npoints < 4) ? "if" : "elif", up, widths[i]);
        put_shuffles(o, up, widths[i]);
        put_tile(o, px, up, widths[i], world);
    }
    sbuf_printf(o, "#endif\n#else\n#define %sTALIGN\n#endif\n\n", up);
}

/* transpose: a block of patches to the lanes' layout, tiles where there are vectors. */
static void put_transpose(sbuf *o, const char *px, const char *up, int world)
{
    sbuf_printf(o, "/* soa[(k * 4 + c) * LANES + l] = cp[l * POINTS + k][c] for the n <= LANES "
                   "patches at cp and\n * the coordinates the lanes read%s: tiles of TW "
                   "patches, then one float at a time. */\n"
                   "static void %stranspose(float *%sRESTRICT soa, const float (*%sRESTRICT cp)[4], "
                   "size_t n)\n{\n    size_t l = 0;\n    unsigned k, c;\n"
                   "#if defined(%sTW)\n"
                   "    for (; l + %sTW <= n; l += %sTW) {\n"
                   "        for (k = 0; k + %sTW / 4 <= %sPOINTS; k += %sTW / 4)\n"
                   "            %stile(soa + k * 4 * %sLANES + l, cp[l * %sPOINTS + k]);\n"
                   "        if (k < %sPOINTS) /* the last points: a tile overlapping the one before */\n"
                   "            %stile(soa + (%sPOINTS - %sTW / 4) * 4 * %sLANES + l,\n"
                   "%*scp[l * %sPOINTS + %sPOINTS - %sTW / 4]);\n"
                   "    }\n#endif\n"
                   "    for (; l < n; l++)\n"
                   "        for (k = 0; k < %sPOINTS; k++)\n"
                   "            for (c = 0; c < 4; c++)\n%s"
                   "%*ssoa[(k * 4 + c) * %sLANES + l] = cp[l * %sPOINTS + k][c];\n}\n\n",
                world ? "" : " (clip space never reads z)", px, up, up, up, up, up, up, up, up,
                px, up, up, up, px, up, up, up, 17 + (int)strlen(px), "",
                up, up, up, up, world ? "" : "                if (c != 2)\n", world ? 16 : 20,
                "", up, up);
}

/* The second look at the block's patches [p, p + n): the refinement from the block's values dv
 * (block), else second(cp, eye) where the class satisfies again. */
static void put_second_look(sbuf *o, const out_info *info, const char *up, const char *second,
                            const char *again, int block)
{
    const char *px = info->prefix;
    if (block)
        sbuf_printf(o, "        for (l = 0; l < n; l++)\n"
                       "            if (cls[p + l] == %sSILHOUETTE) {\n"
                       "                float d[%sPLANES];\n"
                       "                for (k = 0; k < %sPLANES; k++)\n"
                       "                    d[k] = dv[k * %sLANES + l];\n"
                       "                cls[p + l] = (unsigned char)%ssplit_class(d, %d);\n"
                       "            }\n",
                    up, up, up, up, px, info->refine);
    else if (second)
        sbuf_printf(o, "        for (l = 0; l < n; l++)\n"
                       "            if (cls[p + l] %s)\n"
                       "                cls[p + l] = (unsigned char)%s%s(cp + (p + l) * %sPOINTS, eye);\n",
                    again, px, second, up);
}

void emit_c_batch(sbuf *o, const tp_table *t, const out_info *info, const char *up,
                  const char *second, const char *again)
{
    const char *px = info->prefix;
    int world = info->space == OUT_WORLD;
    int block = info->refine && !info->certified; /* refined from the block's values dv */
    char dv[160];
    snprintf(dv, sizeof dv, ", dv[%sPLANES * %sLANES]", up, up);
    put_vectors(o, t, px, up, world);
    put_transpose(o, px, up, world);
    sbuf_printf(o, "/* Blocks of LANES patches: transposed, a block AHEAD on prefetched, the lanes, "
                   "the second look. */\n"
                   "void %sclassify_batch(const float (*cp)[4], size_t patch_count, const float eye[4],\n"
                   "                    unsigned char *cls)\n{\n"
                   "    float soa[%sPOINTS * 4 * %sLANES] %sTALIGN%s;\n"
                   "    size_t p, n%s;\n%s"
                   "    for (p = 0; p < patch_count; p += n) {\n"
                   "        n = patch_count - p < %sLANES ? patch_count - p : %sLANES;\n"
                   "        %stranspose(soa, cp + p * %sPOINTS, n);\n"
                   "#if defined(__GNUC__) /* a later block into the caches while this one is classified */\n"
                   "        {\n"
                   "            size_t a = patch_count - p - n <= (%sAHEAD - 1) * %sLANES ? patch_count\n"
                   "                       : p + n + (%sAHEAD - 1) * %sLANES;\n"
                   "            const char *next = (const char *)(cp + a * %sPOINTS);\n"
                   "            size_t b, m = patch_count - a < %sLANES ? patch_count - a : %sLANES;\n"
                   "            for (b = 0; b < m * %sPOINTS * sizeof *cp; b += 64)\n"
                   "                __builtin_prefetch(next + b, 0, 0);\n"
                   "        }\n"
                   "#endif\n",
                px, up, up, up, block ? dv : "", block || second ? ", l" : "",
                block ? "    unsigned k;\n" : "", up, up, px, up, up, up, up, up, up, up, up, up);
    if (block)
        sbuf_printf(o, "        %slanes_values(soa, %sLANES, n, eye, cls + p, dv, %sLANES);\n", px, up, up);
    else
        sbuf_printf(o, "        %slanes_block(soa, n, eye, cls + p);\n", px);
    put_second_look(o, info, up, second, again, block);
    sbuf_puts(o, "    }\n}\n");
}
