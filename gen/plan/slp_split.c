/* slp_split.c: the pieces of the C target's straight-line program for loop fission: cuts at
 * plane boundaries from the program's own operation counts. */
#include "plan/slp_split.h"
#include "plan/slp_order.h"

#include <stdlib.h>

/* Per plane: the sign masks' compares and ors. */
enum { MASK_OPS = 4 };

/* The program, the values its planes read, each plane's operations, and stamps that mark the
 * values of a range of planes (mark[v] == stamp). */
typedef struct {
    const slp_prog *p;
    const int *order;
    slp_values v;
    long *ops;
    int *mark, stamp, world;
} split_ctx;

static int ctx_init(split_ctx *c, const slp_prog *p, const int *order, int world, ptp_error *err)
{
    int P, st;
    c->p = p;
    c->order = order;
    c->world = world;
    c->stamp = 0;
    c->ops = malloc(((size_t)p->nplanes + 1) * sizeof *c->ops);
    c->mark = calloc(p->npairs + (size_t)p->npoints + 1, sizeof *c->mark);
    st = slp_values_build(&c->v, p, err);
    if (st == PTP_OK && (!c->ops || !c->mark))
        st = ptp_fail(err, PTP_ENOMEM, "out of memory splitting the straight-line program");
    for (P = 0; st == PTP_OK && P < p->nplanes; P++)
        c->ops[P] = slp_plane_ops(p, P, world) + MASK_OPS;
    return st;
}

static void ctx_clear(split_ctx *c)
{
    slp_values_clear(&c->v);
    free(c->ops);
    free(c->mark);
}

/* Marks the values of planes order[a, b) with a new stamp; returns their number. */
static long mark_range(split_ctx *c, int a, int b)
{
    long n = 0;
    int i, val;
    size_t k;
    c->stamp++;
    for (i = a; i < b; i++)
        for (k = c->v.start[c->order[i]]; k < c->v.start[c->order[i] + 1]; k++)
            if (c->mark[val = c->v.val[k]] != c->stamp) {
                c->mark[val] = c->stamp;
                n++;
            }
    return n;
}

/* The operations of the piece order[a, b): its planes, and a load of each value it reads (world
 * space: two, the kinds'). */
static long piece_ops(split_ctx *c, int a, int b)
{
    long n = (c->world ? 2 : 1) * mark_range(c, a, b);
    int i;
    for (i = a; i < b; i++)
        n += c->ops[c->order[i]];
    return n;
}

/* The values of order[a, b) that planes order[b, n) read again. */
static long shared(split_ctx *c, int a, int b, int n)
{
    long s = 0;
    int i, stamp, val;
    size_t k;
    mark_range(c, a, b);
    stamp = c->stamp;
    for (i = b; i < n; i++)
        for (k = c->v.start[c->order[i]]; k < c->v.start[c->order[i] + 1]; k++)
            if (c->mark[val = c->v.val[k]] == stamp) {
                c->mark[val] = -1; /* counted once */
                s++;
            }
    return s;
}

/* The end of the piece from a: of the ends whose piece has at most cap operations and at least
 * 7/8 of the most such a piece has, the one that shares the fewest values with the planes after
 * it (the latest on ties); a + 1 when plane a alone has more. */
static int piece_end(split_ctx *c, int a, int n, long cap)
{
    long most = 0, best_s = -1, ops, s;
    int b, last = a + 1, best = a + 1;
    for (b = a + 1; b <= n && (ops = piece_ops(c, a, b)) <= cap; b++) {
        last = b;
        most = ops;
    }
    for (b = last; b > a && 8 * piece_ops(c, a, b) >= 7 * most; b--)
        if ((s = b < n ? shared(c, a, b, n) : 0) < best_s || best_s < 0) {
            best = b;
            best_s = s;
        }
    return best;
}

/* Cuts order[0, n) with piece_end at cap into cut[0 ..]; returns the number of pieces. */
static int cut_at(int *cut, split_ctx *c, int n, long cap)
{
    int k = 0;
    cut[0] = 0;
    while (cut[k] < n) {
        cut[k + 1] = piece_end(c, cut[k], n, cap);
        k++;
    }
    return k;
}

int slp_split(int *cut, int *npieces, const slp_prog *p, const int *order, int n, int world,
              ptp_error *err)
{
    split_ctx c;
    int st = ctx_init(&c, p, order, world, err), k = 1;
    long lo = 1, hi = SLP_SPLIT_OPS;
    if (st == PTP_OK && slp_ops(p, world) + MASK_OPS * n > SLP_SPLIT_OPS && n > 1)
        k = cut_at(cut, &c, n, SLP_SPLIT_OPS);
    while (st == PTP_OK && k > 1 && lo < hi) { /* the least cap that keeps k pieces */
        long mid = lo + (hi - lo) / 2;
        if (cut_at(cut, &c, n, mid) <= k)
            hi = mid;
        else
            lo = mid + 1;
    }
    if (st == PTP_OK && k > 1)
        k = cut_at(cut, &c, n, hi);
    cut[0] = 0;
    cut[k] = n;
    *npieces = k;
    ctx_clear(&c);
    return st;
}

long slp_split_ops(const slp_prog *p, const int *order, int a, int b, int world)
{
    split_ctx c;
    long n = ctx_init(&c, p, order, world, NULL) == PTP_OK ? piece_ops(&c, a, b) : -1;
    ctx_clear(&c);
    return n;
}
