/* slp_order.c: a greedy emission order of the straight-line program's planes over a simulated
 * most-recently-used set of registers (minors and points), for the C target's classify. */
#include "plan/slp_order.h"

#include <stdlib.h>
#include <string.h>

/* The values each plane reads, in the order its code reads them: minor pairs are 0 .. npairs,
 * point b is npairs + b. start[P] .. start[P + 1] index val; a plane lists a value once. */
typedef struct {
    size_t *start;
    int *val;
} plane_values;

/* Appends value v to plane P's list (the last one) unless mark[v] == P + 1. */
static void add_value(plane_values *pv, int *mark, size_t *n, int P, int v)
{
    if (mark[v] == P + 1)
        return;
    mark[v] = P + 1;
    pv->val[(*n)++] = v;
}

/* Fills pv from p: an exact plane reads its terms' minors and points, a fused or point-form
 * plane each point's minors, then the point. */
static void list_values(plane_values *pv, int *mark, const slp_prog *p)
{
    size_t i, e = 0, n = 0;
    int P, k;
    for (P = 0; P < p->nplanes; P++) {
        pv->start[P] = n;
        for (i = 0; i < p->nterms; i++)
            if (p->terms[i].plane == P && (p->form[P] == SLP_BRACKET))
                for (k = 0; k < 6; k++)
                    add_value(pv, mark, &n, P,
                              k < 3 ? p->terms[i].pair[k] : (int)p->npairs + p->terms[i].point[k - 3]);
        for (i = 0; i < p->nitems; i++)
            if (p->items[i].plane == P) {
                add_value(pv, mark, &n, P, p->items[i].pair);
                if (i + 1 == p->nitems || p->items[i + 1].point != p->items[i].point ||
                    p->items[i + 1].plane != P)
                    add_value(pv, mark, &n, P, (int)p->npairs + p->items[i].point);
            }
        for (; e < p->nentries && p->entries[e].plane == P; e++) {
            add_value(pv, mark, &n, P, p->entries[e].pair);
            if (e + 1 == p->nentries || p->entries[e + 1].point != p->entries[e].point ||
                p->entries[e + 1].group != p->entries[e].group)
                add_value(pv, mark, &n, P, (int)p->npairs + p->entries[e].point);
        }
    }
    pv->start[p->nplanes] = n;
}

/* Moves v to the front of the most-recently-used list lru (length *len, at most nv). */
static void touch(int *lru, int *len, int v)
{
    int i = 0;
    while (i < *len && lru[i] != v)
        i++;
    if (i == *len)
        (*len)++;
    memmove(lru + 1, lru, (size_t)i * sizeof *lru);
    lru[0] = v;
}

/* The next plane: of the first win planes not done (in number order, those with values), the one
 * with the fewest values outside the first cap of lru (in[v] marks them), the first on ties; -1
 * when every plane with values is done. */
static int next_plane(const plane_values *pv, const unsigned char *done, const unsigned char *in,
                      int nplanes, int win)
{
    int P, best = -1, seen = 0;
    size_t i, best_miss = 0;
    for (P = 0; P < nplanes && seen < win; P++) {
        size_t miss = 0;
        if (done[P] || pv->start[P] == pv->start[P + 1])
            continue;
        seen++;
        for (i = pv->start[P]; i < pv->start[P + 1]; i++)
            miss += !in[pv->val[i]];
        if (best < 0 || miss < best_miss) {
            best = P;
            best_miss = miss;
        }
    }
    return best;
}

int slp_order(int *order, int *n, const slp_prog *p, int cap, int win, ptp_error *err)
{
    int nv = (int)p->npairs + p->npoints, len = 0, P, i;
    size_t k, nval = 6 * p->nterms + p->nentries * 2 + p->nitems * 2;
    plane_values pv = {malloc(((size_t)p->nplanes + 1) * sizeof *pv.start),
                       malloc((nval + 1) * sizeof *pv.val)};
    int *mark = calloc((size_t)nv + 1, sizeof *mark), *lru = malloc(((size_t)nv + 1) * sizeof *lru);
    unsigned char *done = calloc((size_t)p->nplanes + 1, 1), *in = calloc((size_t)nv + 1, 1);
    int st = PTP_OK;
    *n = 0;
    if (!pv.start || !pv.val || !mark || !lru || !done || !in) {
        st = ptp_fail(err, PTP_ENOMEM, "out of memory ordering the straight-line program");
        goto out;
    }
    list_values(&pv, mark, p);
    while ((P = next_plane(&pv, done, in, p->nplanes, win)) >= 0) {
        done[P] = 1;
        order[(*n)++] = P;
        for (k = pv.start[P]; k < pv.start[P + 1]; k++)
            touch(lru, &len, pv.val[k]);
        memset(in, 0, (size_t)nv);
        for (i = 0; i < len && i < cap; i++)
            in[lru[i]] = 1;
    }
out:
    free(pv.start);
    free(pv.val);
    free(mark);
    free(lru);
    free(done);
    free(in);
    return st;
}
