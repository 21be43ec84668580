/* test_form.c: randomized property tests of the sparse alternating forms (gen/form.c).
 * Keys and wedges against a naive reference, sums against per-key rat arithmetic. */
#include "check.h"
#include "core/form.h"
#include "core/ptp.h"
#include "core/rat.h"

#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAXI ((ptp_i128)(((ptp_u128)1 << 127) - 1))
#define MAXTERMS 200 /* long lists take form_set_terms' radix sort path (over 32 terms) */
#define MAXPOOL 64
#define MAXKEYS (2 * MAXPOOL)

#define SEED 0x13198A2E03707344u /* of check_rnd */

/* ---- printing ---- */

static const char *SR(const rat *a)
{
    static char pool[8][RAT_STRLEN];
    static int k;
    return rat_get_str(pool[k++ % 8], a);
}

/* The indices of a key, as "(j1,j2,...)". */
static const char *SK(form_key key, int rank)
{
    static char pool[8][64];
    static int k;
    char *b = pool[k++ % 8];
    int idx[FORM_MAX_RANK], i, n = 0;
    form_key_unpack(idx, key, rank);
    n += sprintf(b + n, "(");
    for (i = 0; i < rank; i++)
        n += sprintf(b + n, i ? ",%d" : "%d", idx[i]);
    sprintf(b + n, ")");
    if (rank < FORM_MAX_RANK + 1 && (key >> (16 * rank)))
        sprintf(b + n + 1, "+hi");
    return b;
}

/* A short text of a form: "{(1,2):3 (2,4):-1}/5" (at most 6 terms shown). */
static const char *SF(const form *f)
{
    static char pool[6][1400];
    static int k;
    char *b = pool[k++ % 6], nb[48];
    size_t i;
    int n = sprintf(b, "r%d{", f->rank);
    for (i = 0; i < f->len && i < 6; i++)
        n += sprintf(b + n, "%s%s:%s", i ? " " : "", SK(f->t[i].key, f->rank),
                     check_i128_str(nb, f->t[i].num));
    if (f->len > 6)
        n += sprintf(b + n, " ...+%zu", f->len - 6);
    sprintf(b + n, "}/%s", check_i128_str(nb, f->den));
    return b;
}


/* ---- keys: an independent packing and wedge ---- */

static form_key my_pack(const int *idx, int rank)
{
    form_key k = 0;
    int i;
    for (i = 0; i < rank; i++)
        k = (k << 16) | (form_key)idx[i];
    return k;
}

/* Sorted distinct random indices, from 0..range-1. */
static void rnd_indices(int *idx, int rank, int range)
{
    int i, j, ok;
    do {
        for (i = 0; i < rank; i++)
            idx[i] = (int)check_rnd_below((unsigned)range);
        for (i = 1; i < rank; i++) /* insertion sort */
            for (j = i; j > 0 && idx[j - 1] > idx[j]; j--) {
                int t = idx[j];
                idx[j] = idx[j - 1];
                idx[j - 1] = t;
            }
        ok = 1;
        for (i = 1; i < rank; i++)
            ok &= idx[i - 1] < idx[i];
    } while (!ok);
}

static int rnd_range(void)
{
    static const int ranges[] = {4, 6, 10, 40, 1000, FORM_MAX_POINT + 1};
    return ranges[check_rnd_below(6)];
}

static form_key rnd_key(int rank, int range)
{
    int idx[FORM_MAX_RANK];
    rnd_indices(idx, rank, range);
    return my_pack(idx, rank);
}

/* The wedge by definition: concatenate, sign of the sorting permutation by counting
 * inversions, 0 when an index repeats. */
static int my_wedge(form_key *r, form_key a, int ra, form_key b, int rb)
{
    int v[2 * FORM_MAX_RANK], n = ra + rb, i, j, inv = 0;
    for (i = 0; i < ra; i++)
        v[i] = (int)((a >> (16 * (ra - 1 - i))) & 0xFFFF);
    for (i = 0; i < rb; i++)
        v[ra + i] = (int)((b >> (16 * (rb - 1 - i))) & 0xFFFF);
    for (i = 0; i < n; i++)
        for (j = i + 1; j < n; j++) {
            if (v[i] == v[j])
                return 0;
            inv += v[i] > v[j];
        }
    for (i = 1; i < n; i++)
        for (j = i; j > 0 && v[j - 1] > v[j]; j--) {
            int t = v[j];
            v[j] = v[j - 1];
            v[j - 1] = t;
        }
    *r = my_pack(v, n);
    return inv % 2 ? -1 : 1;
}

static int key_sorted(form_key key, int rank)
{
    int idx[FORM_MAX_RANK], i;
    if (rank < 4 && (key >> (16 * rank)))
        return 0;
    form_key_unpack(idx, key, rank);
    for (i = 1; i < rank; i++)
        if (idx[i - 1] >= idx[i])
            return 0;
    return 1;
}

/* keys's properties. */
typedef struct {
    prop pu, pw, pa, pz, pas, ps;
} keys_props;

/* Names keys's properties for n random cases. */
static void keys_init(keys_props *kp, long n)
{
    prop_init(&kp->pu, "form: form_key_unpack inverts the packing, form_key_point(j) is (j) (%ld "
                   "random keys)",
              n);
    prop_init(&kp->pw, "form: form_key_wedge matches the definition (sorted key, sign of the "
                   "permutation) for ranks 1^1, 1^2, 2^1 (%ld random pairs)",
              n);
    prop_init(&kp->pa, "form: form_key_wedge is graded alternating: a^b == (-1)^(ra*rb) b^a (%ld "
                   "random pairs of distinct indices)",
              n);
    prop_init(&kp->pz, "form: form_key_wedge is 0 when an index repeats (%ld random pairs)", n);
    prop_init(&kp->pas, "form: form_key_wedge is associative with signs: (a^b)^c == a^(b^c) (%ld "
                    "random triples of points)",
              n);
    prop_init(&kp->ps, "form: form_key_wedge results are sorted keys of rank ra+rb (%ld random "
                   "pairs)",
              n);
}

/* form_key_unpack inverts the packing of r random indices below range, and form_key_point(j)
 * is (j). */
static void check_pack(keys_props *kp, int r, int range)
{
    int idx[FORM_MAX_RANK], out[FORM_MAX_RANK], j;
    form_key a;
    rnd_indices(idx, r, range);
    a = my_pack(idx, r);
    for (j = 0; j < FORM_MAX_RANK; j++)
        out[j] = -1;
    form_key_unpack(out, a, r);
    kp->pu.tried++;
    for (j = 0; j < r; j++)
        if (out[j] != idx[j])
            break;
    if (j < r || (r == 1 && form_key_point(idx[0]) != a) || (r < FORM_MAX_RANK && out[r] != -1))
        prop_fail(&kp->pu, "indices %d,%d,%d rank %d: packed %llx unpacks to %d,%d,%d", idx[0],
                  r > 1 ? idx[1] : -1, r > 2 ? idx[2] : -1, r, (unsigned long long)a, out[0],
                  out[1], out[2]);
}

/* a ^ b (ranks ra, rb) matches my_wedge; when nonzero it is a sorted key and b ^ a has the
 * graded sign. */
static void check_wedge(keys_props *kp, form_key a, int ra, form_key b, int rb)
{
    form_key kw = 0, kr = 0, k1 = 0;
    int sw = form_key_wedge(&kw, a, ra, b, rb), sr = my_wedge(&kr, a, ra, b, rb), s1;
    kp->pw.tried++;
    if (sw != sr || (sr && kw != kr))
        prop_fail(&kp->pw, "%s ^ %s: sign %d key %s, want sign %d key %s", SK(a, ra), SK(b, rb),
                  sw, SK(kw, ra + rb), sr, SK(kr, ra + rb));
    if (sw) {
        kp->ps.tried++;
        if (!key_sorted(kw, ra + rb))
            prop_fail(&kp->ps, "%s ^ %s = %s (%llx) is not a sorted key", SK(a, ra), SK(b, rb),
                      SK(kw, ra + rb), (unsigned long long)kw);
        kp->pa.tried++;
        s1 = form_key_wedge(&k1, b, rb, a, ra);
        if (s1 != ((ra * rb) % 2 ? -sw : sw) || k1 != kw)
            prop_fail(&kp->pa, "%s ^ %s = %d %s but %s ^ %s = %d %s", SK(a, ra), SK(b, rb), sw,
                      SK(kw, ra + rb), SK(b, rb), SK(a, ra), s1, SK(k1, ra + rb));
    } else {
        kp->pz.tried++;
    }
}

/* The wedge is 0 when an index repeats: a (rank ra) with a random b of rank rb below range
 * that shares one of a's indices, both ways, and a random point with itself. */
static void check_repeated(keys_props *kp, form_key a, int ra, int rb, int range)
{
    int ia[FORM_MAX_RANK], ib[FORM_MAX_RANK], j, k, s1, s2, p;
    form_key b, k1, k2 = 0;
    form_key_unpack(ia, a, ra);
    rnd_indices(ib, rb, range);
    j = (int)check_rnd_below((unsigned)rb);
    ib[j] = ia[check_rnd_below((unsigned)ra)];
    for (j = 1; j < rb; j++) /* re-sort; skip if b itself now repeats */
        for (k = j; k > 0 && ib[k - 1] > ib[k]; k--) {
            int t = ib[k];
            ib[k] = ib[k - 1];
            ib[k - 1] = t;
        }
    if (rb == 1 || ib[0] != ib[1]) {
        b = my_pack(ib, rb);
        kp->pz.tried++;
        k1 = 0x1234;
        s1 = form_key_wedge(&k1, a, ra, b, rb);
        s2 = form_key_wedge(&k2, b, rb, a, ra);
        if (s1 || s2)
            prop_fail(&kp->pz, "%s ^ %s = %d, reversed %d (want 0)", SK(a, ra), SK(b, rb), s1,
                      s2);
    }
    p = (int)check_rnd_below(FORM_MAX_POINT + 1);
    kp->pz.tried++;
    if (form_key_wedge(&k1, form_key_point(p), 1, form_key_point(p), 1))
        prop_fail(&kp->pz, "(%d) ^ (%d) is not 0", p, p);
}

/* (a^b)^c == a^(b^c) with signs on three random points below range. */
static void check_assoc_points(keys_props *kp, int range)
{
    form_key a, b, c, k1 = 0, k2 = 0, t1 = 0, t2 = 0;
    int s1, s2;
    a = form_key_point((int)check_rnd_below((unsigned)range));
    b = form_key_point((int)check_rnd_below((unsigned)range));
    c = form_key_point((int)check_rnd_below((unsigned)range));
    s1 = form_key_wedge(&t1, a, 1, b, 1);
    if (s1)
        s1 *= form_key_wedge(&k1, t1, 2, c, 1);
    s2 = form_key_wedge(&t2, b, 1, c, 1);
    if (s2)
        s2 *= form_key_wedge(&k2, a, 1, t2, 2);
    kp->pas.tried++;
    if (s1 != s2 || (s1 && k1 != k2))
        prop_fail(&kp->pas, "a=%d b=%d c=%d: (a^b)^c = %d %s, a^(b^c) = %d %s", (int)a, (int)b,
                  (int)c, s1, SK(k1, 3), s2, SK(k2, 3));
}

/* Key packing and the wedge of keys on random keys. */
static void keys(void)
{
    keys_props kp;
    long i;
    const long n = 200000;
    keys_init(&kp, n);
    for (i = 0; i < n; i++) {
        int range = rnd_range(), ra = 1 + (int)check_rnd_below(2), rb = ra == 2 ? 1 : 1 + (int)check_rnd_below(2);
        int r = 1 + (int)check_rnd_below(3);
        form_key a, b;
        check_pack(&kp, r, range);
        a = rnd_key(ra, range);
        b = rnd_key(rb, range);
        check_wedge(&kp, a, ra, b, rb);
        check_repeated(&kp, a, ra, rb, range);
        check_assoc_points(&kp, range);
    }
    prop_report(&kp.pu);
    prop_report(&kp.pw);
    prop_report(&kp.pa);
    prop_report(&kp.pz);
    prop_report(&kp.pas);
    prop_report(&kp.ps);
}

/* ---- random term lists and a naive per-key reference ---- */

typedef struct {
    size_t n;
    form_key key[MAXKEYS];
    rat w[MAXKEYS];
} refmap;

static rat *ref_slot(refmap *m, form_key key)
{
    size_t i;
    for (i = 0; i < m->n; i++)
        if (m->key[i] == key)
            return &m->w[i];
    m->key[m->n] = key;
    rat_set_si(&m->w[m->n], 0);
    return &m->w[m->n++];
}

static size_t ref_nonzero(const refmap *m)
{
    size_t i, n = 0;
    for (i = 0; i < m->n; i++)
        n += m->w[i].num != 0;
    return n;
}

/* Checks that f is exactly the reference: canonical, same nonzero keys, same weights. */
static int form_matches(const form *f, const refmap *m, char *why, size_t whylen)
{
    size_t i, j;
    if (!form_is_canonical(f)) {
        snprintf(why, whylen, "not canonical");
        return 0;
    }
    if (f->len != ref_nonzero(m)) {
        snprintf(why, whylen, "%zu terms, want %zu", f->len, ref_nonzero(m));
        return 0;
    }
    for (i = 0; i < f->len; i++) {
        rat w;
        for (j = 0; j < m->n && m->key[j] != f->t[i].key; j++)
            ;
        form_get_weight(&w, f, i);
        if (j == m->n || !rat_equal(&w, &m->w[j])) {
            snprintf(why, whylen, "weight of %s is %s, want %s", SK(f->t[i].key, f->rank),
                     SR(&w), j == m->n ? "absent" : SR(&m->w[j]));
            return 0;
        }
    }
    return 1;
}

/* A random numerator magnitude: mostly small, sometimes 30 or 60 bits; big adds 90 bits. */
static ptp_i128 rnd_num(int big)
{
    ptp_i128 v;
    switch (check_rnd_below(big ? 5 : 4)) {
    case 0:
        v = (ptp_i128)check_rnd_below(4);
        break;
    case 1:
        v = (ptp_i128)check_rnd_below(1000);
        break;
    case 2:
        v = (ptp_i128)check_rnd_bits(30);
        break;
    case 3:
        v = (ptp_i128)check_rnd_bits(big ? 60 : 40);
        break;
    default:
        v = (ptp_i128)check_rnd_bits(90);
        break;
    }
    return check_rnd() & 1 ? -v : v;
}

static ptp_i128 rnd_den(int big)
{
    static const ptp_i128 smooth[] = {1, 2, 3, 4, 6, 12, 36, 720, 5040, 40320, 362880};
    ptp_i128 d;
    switch (check_rnd_below(big ? 4 : 3)) {
    case 0:
        d = smooth[check_rnd_below(11)];
        break;
    case 1:
        d = 1 + (ptp_i128)check_rnd_below(100);
        break;
    case 2:
        d = (ptp_i128)check_rnd_bits(big ? 60 : 30);
        break;
    default:
        d = (ptp_i128)check_rnd_bits(90);
        break;
    }
    return d ? d : 1;
}

/* A random term list of rank r over a small key pool (so keys repeat), with cancellations
 * and a common factor now and then; fills the reference (nums/den summed with rat). Returns
 * the number of terms, or -1 when the reference overflowed (the case is skipped). With m
 * NULL no reference is computed. */
static long rnd_terms(form_term *t, ptp_i128 *den, refmap *m, int rank, int big)
{
    form_key pool[MAXPOOL];
    int longlist = check_rnd_below(6) == 0, range = rnd_range(), i;
    int npool = 1 + (int)check_rnd_below(longlist ? MAXPOOL : 8);
    long n = longlist ? 33 + (long)check_rnd_below(MAXTERMS - 32) : (long)check_rnd_below(25), k;
    ptp_i128 d = rnd_den(big), f = 1;
    if (rank == 3 && range < 4)
        range = 4;
    for (i = 0; i < npool; i++)
        pool[i] = rnd_key(rank, range);
    if (check_rnd_below(4) == 0)
        f = 1 + (ptp_i128)check_rnd_below(30); /* a common factor for canonicalize to remove */
    d *= f;
    for (k = 0; k < n; k++) {
        t[k].key = pool[check_rnd_below((unsigned)npool)];
        if (k && check_rnd_below(5) == 0) {
            t[k].num = -t[check_rnd_below((unsigned)k)].num; /* cancels an earlier term */
        } else {
            t[k].num = rnd_num(big) * f;
        }
    }
    *den = d;
    if (!m)
        return n;
    m->n = 0;
    for (k = 0; k < n; k++) {
        rat w, *s = ref_slot(m, t[k].key);
        if (rat_set_frac(&w, t[k].num, d) || rat_add(s, s, &w))
            return -1;
    }
    return n;
}

static void form_copy(form *dst, const form *src)
{
    form_init(dst, src->rank);
    dst->den = src->den;
    dst->len = dst->cap = src->len;
    if (src->len) {
        dst->t = malloc(src->len * sizeof *dst->t);
        if (!dst->t) {
            fprintf(stderr, "test_form: out of memory\n");
            exit(2);
        }
        memcpy(dst->t, src->t, src->len * sizeof *dst->t);
    }
}

/* Fills f (initialized, of rank r) with a random canonical form. */
static int rnd_form(form *f, int big)
{
    form_term t[MAXTERMS];
    ptp_i128 den;
    ptp_error err;
    long n;
    do
        n = rnd_terms(t, &den, NULL, f->rank, big);
    while (n < 0);
    return form_set_terms(f, t, (size_t)n, den, &err);
}

static int cmp_term_full(const void *pa, const void *pb)
{
    const form_term *a = pa, *b = pb;
    if (a->key != b->key)
        return a->key < b->key ? -1 : 1;
    return (a->num > b->num) - (a->num < b->num);
}

/* Nonzero when t[0..n-1] is sorted by key and holds the same terms as orig. */
static int sorted_permutation(const form_term *t, const form_term *orig, size_t n)
{
    form_term x[MAXTERMS], y[MAXTERMS];
    size_t i;
    for (i = 1; i < n; i++)
        if (t[i - 1].key > t[i].key)
            return 0;
    memcpy(x, t, n * sizeof *t);
    memcpy(y, orig, n * sizeof *t);
    qsort(x, n, sizeof *x, cmp_term_full);
    qsort(y, n, sizeof *y, cmp_term_full);
    for (i = 0; i < n; i++)
        if (x[i].key != y[i].key || x[i].num != y[i].num)
            return 0;
    return 1;
}

/* One random term list (rnd_terms, with big) of a random rank into f[rank - 1]: sorted in
 * place as a permutation (pp), and merged, reduced and equal to the rat sum (ps); returns its
 * length, or -1 when the reference overflowed and nothing was checked. */
static long check_set_terms(prop *ps, prop *pp, form *f, int big)
{
    form_term t[MAXTERMS], orig[MAXTERMS];
    refmap m;
    ptp_i128 den;
    ptp_error err;
    int rank = 1 + (int)check_rnd_below(FORM_MAX_RANK), st;
    long nt = rnd_terms(t, &den, &m, rank, big);
    char why[300];
    if (nt < 0)
        return -1;
    memcpy(orig, t, (size_t)nt * sizeof *t);
    ps->tried++;
    st = form_set_terms(&f[rank - 1], t, (size_t)nt, den, &err);
    pp->tried++;
    if (!sorted_permutation(t, orig, (size_t)nt))
        prop_fail(pp, "rank %d, %ld terms: the list left behind is not a sorted "
                      "permutation of the input",
                  rank, nt);
    if (st != PTP_OK) {
        prop_fail(ps, "rank %d, %ld terms over %s: status %d (%s)", rank, nt, SR(&(rat){den, 1}),
                  st, err.msg);
    } else if (!form_matches(&f[rank - 1], &m, why, sizeof why)) {
        char first[200];
        long k;
        int o = 0;
        for (k = 0; k < nt && k < 4; k++)
            o += snprintf(first + o, sizeof first - (size_t)o, "%s%s:%s", k ? " " : "",
                          SK(orig[k].key, rank), SR(&(rat){orig[k].num, 1}));
        prop_fail(ps, "rank %d, %ld terms [%s ...] over %s gave %s: %s", rank, nt, first,
                  SR(&(rat){den, 1}), SF(&f[rank - 1]), why);
    }
    return nt;
}

/* form_set_terms into f (rank 1) rejects den <= 0 (pd) and reports merged numerators that
 * overflow (po). */
static void set_terms_bad(prop *pd, prop *po, form *f)
{
    {
        form_term t[2] = {{1, 3}, {2, 5}};
        ptp_error err;
        int st0, st1;
        pd->tried++;
        st0 = form_set_terms(f, t, 2, 0, &err);
        st1 = form_set_terms(f, t, 2, -3, &err);
        if (st0 == PTP_OK || st1 == PTP_OK)
            prop_fail(pd, "den 0 gave %d, den -3 gave %d", st0, st1);
    }
    {
        form_term t[3] = {{7, MAXI}, {7, MAXI}, {7, -MAXI}};
        form_term u[2] = {{7, -MAXI}, {7, -1}};
        ptp_error err;
        int st0, st1;
        po->tried++;
        st0 = form_set_terms(f, t, 2, 1, &err);
        st1 = form_set_terms(f, u, 2, 1, &err);
        if (st0 != PTP_EOVERFLOW || st1 != PTP_EOVERFLOW)
            prop_fail(po, "MAX+MAX gave %d, -MAX-1 gave %d", st0, st1);
    }
}

/* form_set_terms on random term lists and on bad input. */
static void set_terms(void)
{
    prop ps, pd, po, pp;
    long i, skipped = 0, longlists = 0;
    const long n = 20000;
    form f[FORM_MAX_RANK];
    int r;
    prop_init(&ps, "form: form_set_terms merges duplicate keys, drops zeros, reduces, and "
                   "equals a per-key rat sum (%ld random term lists)",
              n);
    prop_init(&pp, "form: form_set_terms leaves the term list sorted by key, a permutation of "
                   "the input (%ld random lists, 1 in 6 over 32 terms)",
              n);
    prop_init(&pd, "form: form_set_terms rejects den <= 0");
    prop_init(&po, "form: form_set_terms reports PTP_EOVERFLOW when a merged numerator "
                   "overflows");
    for (r = 0; r < FORM_MAX_RANK; r++)
        form_init(&f[r], r + 1);
    for (i = 0; i < n; i++) {
        long nt = check_set_terms(&ps, &pp, f, (int)(i % 2));
        if (nt < 0)
            skipped++;
        else
            longlists += nt > 32;
    }
    printf("# form_set_terms: %ld lists over 32 terms, %ld skipped (reference overflow)\n",
           longlists, skipped);
    set_terms_bad(&pd, &po, &f[0]);
    prop_report(&ps);
    prop_report(&pp);
    prop_report(&pd);
    prop_report(&po);
    for (r = 0; r < FORM_MAX_RANK; r++)
        form_clear(&f[r]);
}

/* ---- linear combinations ---- */

static rat rnd_coef(void)
{
    rat a;
    ptp_i128 n, d;
    switch (check_rnd_below(6)) {
    case 0:
        rat_set_si(&a, (int64_t)check_rnd_below(3) - 1); /* -1, 0, 1 */
        return a;
    case 1:
        n = (ptp_i128)check_rnd_below(21) - 10;
        d = 1 + (ptp_i128)check_rnd_below(12);
        break;
    case 2:
    case 3:
        n = (ptp_i128)check_rnd_bits(20) - ((ptp_i128)1 << 19);
        d = 1 + (ptp_i128)check_rnd_bits(20);
        break;
    default:
        n = (ptp_i128)check_rnd_bits(40) - ((ptp_i128)1 << 39);
        d = 1 + (ptp_i128)check_rnd_bits(40);
        break;
    }
    rat_set_frac(&a, n, d);
    return a;
}

/* The reference of a*x + b*y per key, from the weights of x and y; -1 on rat overflow. */
static int ref_lincomb(refmap *m, const rat *a, const form *x, const rat *b, const form *y)
{
    size_t i;
    m->n = 0;
    for (i = 0; i < x->len; i++) {
        rat w, *s = ref_slot(m, x->t[i].key);
        form_get_weight(&w, x, i);
        if (rat_mul(&w, &w, a) || rat_add(s, s, &w))
            return -1;
    }
    for (i = 0; i < y->len; i++) {
        rat w, *s = ref_slot(m, y->t[i].key);
        form_get_weight(&w, y, i);
        if (rat_mul(&w, &w, b) || rat_add(s, s, &w))
            return -1;
    }
    return 0;
}

/* lincomb's properties and counts. */
typedef struct {
    prop pl, pu, pax, pay, paxy, pneg, pid, peq;
    long exact, ovf;
} lincomb_props;

/* Names lincomb's properties for n random cases, counts 0. */
static void lincomb_init(lincomb_props *lp, long n)
{
    lp->exact = lp->ovf = 0;
    prop_init(&lp->pl, "form: form_lincomb a*x + b*y is canonical and equals the per-key rat "
                   "computation (%ld random forms and coefficients)",
              n);
    prop_init(&lp->pu, "form: form_lincomb on PTP_EOVERFLOW leaves r unchanged and sets err (%ld "
                   "random)",
              n);
    prop_init(&lp->pax, "form: form_lincomb with r == x matches the unaliased result (%ld random)",
              n);
    prop_init(&lp->pay, "form: form_lincomb with r == y matches the unaliased result (%ld random)",
              n);
    prop_init(&lp->paxy, "form: form_lincomb with x == y (and r == x == y) equals (a+b)*x (%ld "
                     "random)",
              n);
    prop_init(&lp->pneg, "form: x + (-1)*x is the zero form (len 0, den 1) (%ld random)", n);
    prop_init(&lp->pid, "form: 1*x + 0*y == x and 0*x + 1*y == y (%ld random)", n);
    prop_init(&lp->peq, "form: form_equal is equality of rank, den and terms (copies equal; any "
                    "one changed field differs) (%ld random)",
              n);
}

/* r = a*x + b*y into r, which starts as r0: canonical and the per-key rat computation, or on
 * overflow r unchanged and err set; returns form_lincomb's status. */
static int lincomb_main(lincomb_props *lp, form *r, const form *r0, const rat *a, const form *x,
                        const rat *b, const form *y, ptp_error *err)
{
    refmap m;
    char why[300];
    int st;
    err->status = -1;
    st = form_lincomb(r, a, x, b, y, err);
    lp->pl.tried++;
    if (st == PTP_OK) {
        if (ref_lincomb(&m, a, x, b, y) == 0) {
            lp->exact++;
            if (!form_matches(r, &m, why, sizeof why))
                prop_fail(&lp->pl, "%s * %s + %s * %s = %s: %s", SR(a), SF(x), SR(b), SF(y),
                          SF(r), why);
        } else if (!form_is_canonical(r)) {
            prop_fail(&lp->pl, "%s * %s + %s * %s = %s: not canonical", SR(a), SF(x), SR(b),
                      SF(y), SF(r));
        }
    } else {
        lp->ovf++;
        lp->pu.tried++;
        if (st != PTP_EOVERFLOW || err->status != st || !form_equal(r, r0) ||
            !form_is_canonical(r))
            prop_fail(&lp->pu, "%s * %s + %s * %s: status %d (err %d), r %s, was %s", SR(a),
                      SF(x), SR(b), SF(y), st, err->status, SF(r), SF(r0));
    }
    return st;
}

/* a*x + b*y aliased r == x and r == y gives the unaliased result r and status st. */
static void lincomb_alias(lincomb_props *lp, const rat *a, const form *x, const rat *b,
                          const form *y, const form *r, int st, ptp_error *err)
{
    form t;
    int st2;
    form_copy(&t, x);
    lp->pax.tried++;
    st2 = form_lincomb(&t, a, &t, b, y, err);
    if (st2 != st || !form_equal(&t, st ? x : r))
        prop_fail(&lp->pax, "%s * %s + %s * %s: aliased %d %s, unaliased %d %s", SR(a), SF(x),
                  SR(b), SF(y), st2, SF(&t), st, SF(r));
    form_clear(&t);
    form_copy(&t, y);
    lp->pay.tried++;
    st2 = form_lincomb(&t, a, x, b, &t, err);
    if (st2 != st || !form_equal(&t, st ? y : r))
        prop_fail(&lp->pay, "%s * %s + %s * %s: aliased %d %s, unaliased %d %s", SR(a), SF(x),
                  SR(b), SF(y), st2, SF(&t), st, SF(r));
    form_clear(&t);
}

/* x == y (and r == x == y): a*x + b*x == (a+b)*x (y: only for ref_lincomb's shape). */
static void lincomb_same(lincomb_props *lp, int rank, const rat *a, const form *x, const rat *b,
                         const form *y, ptp_error *err)
{
    form t, z;
    refmap m;
    rat ab, zero;
    char why[300];
    int st, st2;
    rat_set_si(&zero, 0);
    form_init(&z, rank);
    st = form_lincomb(&z, a, x, b, x, err);
    lp->paxy.tried++;
    if (st == PTP_OK) {
        if (!rat_add(&ab, a, b) && ref_lincomb(&m, &ab, x, &zero, y) == 0 &&
            !form_matches(&z, &m, why, sizeof why))
            prop_fail(&lp->paxy, "%s * x + %s * x with x = %s gave %s: %s", SR(a), SR(b), SF(x),
                      SF(&z), why);
    }
    form_copy(&t, x);
    st2 = form_lincomb(&t, a, &t, b, &t, err);
    if (st2 != st || !form_equal(&t, st ? x : &z))
        prop_fail(&lp->paxy, "r == x == y: %s * x + %s * x with x = %s: %d %s, unaliased %d %s",
                  SR(a), SR(b), SF(x), st2, SF(&t), st, SF(&z));
    form_clear(&t);
    form_clear(&z);
}

/* x + (-1) x == 0, 1*x + 0*y == x and 0*x + 1*y == y. */
static void lincomb_identities(lincomb_props *lp, int rank, const form *x, const form *y,
                               ptp_error *err)
{
    form t, z;
    rat one, zero, mone;
    int st, st2;
    rat_set_si(&one, 1);
    rat_set_si(&zero, 0);
    rat_set_si(&mone, -1);
    form_init(&z, rank);
    st = form_lincomb(&z, &one, x, &mone, x, err);
    lp->pneg.tried++;
    if (st || z.len != 0 || z.den != 1 || !form_is_canonical(&z))
        prop_fail(&lp->pneg, "x = %s: x - x = %d %s", SF(x), st, SF(&z));
    form_clear(&z);
    form_init(&z, rank);
    form_init(&t, rank);
    st = form_lincomb(&z, &one, x, &zero, y, err);
    st2 = form_lincomb(&t, &zero, x, &one, y, err);
    lp->pid.tried++;
    if (st || !form_equal(&z, x) || st2 || !form_equal(&t, y))
        prop_fail(&lp->pid, "x = %s, y = %s: 1x+0y = %d %s, 0x+1y = %d %s", SF(x), SF(y), st,
                  SF(&z), st2, SF(&t));
    form_clear(&z);
    form_clear(&t);
}

/* Changes field k of t, a copy of x of rank rank: 0 den, 1 rank, 2 a numerator, 3 the length
 * or a key; returns 0 when t has no term to change (k 2 or 3). */
static int change_field(form *t, int k, int rank)
{
    switch (k) {
    case 0:
        t->den += 1;
        break;
    case 1:
        t->rank = rank % FORM_MAX_RANK + 1;
        break;
    case 2:
        if (!t->len)
            return 0;
        t->t[check_rnd_below((unsigned)t->len)].num += 1;
        break;
    default:
        if (!t->len)
            return 0;
        if (check_rnd() & 1)
            t->len--;
        else
            t->t[check_rnd_below((unsigned)t->len)].key ^= 1;
        break;
    }
    return 1;
}

/* form_equal is equality of rank, den and terms: x equals its copy, x and y as their fields
 * say, and x differs from a copy with any one field changed. */
static void check_equal(lincomb_props *lp, int rank, const form *x, const form *y)
{
    form t;
    int same = form_equal(x, y), want = x->len == y->len && x->den == y->den, k;
    size_t j;
    lp->peq.tried++;
    form_copy(&t, x);
    for (j = 0; want && j < x->len; j++)
        want = x->t[j].key == y->t[j].key && x->t[j].num == y->t[j].num;
    if (!form_equal(x, &t) || !form_equal(&t, x) || same != want)
        prop_fail(&lp->peq, "x = %s, y = %s: equal(x, copy) %d, equal(x, y) %d", SF(x), SF(y),
                  form_equal(x, &t), same);
    for (k = 0; k < 4; k++) {
        form_clear(&t);
        form_copy(&t, x);
        if (!change_field(&t, k, rank))
            continue;
        if (form_equal(x, &t) || form_equal(&t, x))
            prop_fail(&lp->peq, "x = %s equals its changed copy %s (change %d)", SF(x), SF(&t),
                      k);
    }
    form_clear(&t);
}

/* form_lincomb and form_equal on random forms and coefficients. */
static void lincomb(void)
{
    lincomb_props lp;
    long i;
    const long n = 20000;
    lincomb_init(&lp, n);
    for (i = 0; i < n; i++) {
        int rank = 1 + (int)check_rnd_below(FORM_MAX_RANK), big = i % 3 == 0, st;
        form x, y, r, r0;
        rat a = rnd_coef(), b = rnd_coef();
        ptp_error err;
        form_init(&x, rank);
        form_init(&y, rank);
        form_init(&r, rank);
        if (rnd_form(&x, big) || rnd_form(&y, big)) {
            prop_fail(&lp.pl, "could not build random forms");
            break;
        }
        /* r starts as some other form, to see it replaced (or kept on failure) */
        if (rnd_form(&r, 0))
            prop_fail(&lp.pl, "could not build a random form");
        form_copy(&r0, &r);
        st = lincomb_main(&lp, &r, &r0, &a, &x, &b, &y, &err);
        lincomb_alias(&lp, &a, &x, &b, &y, &r, st, &err);
        lincomb_same(&lp, rank, &a, &x, &b, &y, &err);
        lincomb_identities(&lp, rank, &x, &y, &err);
        check_equal(&lp, rank, &x, &y);
        form_clear(&r0);
        form_clear(&x);
        form_clear(&y);
        form_clear(&r);
    }
    prop_report(&lp.pl);
    prop_report(&lp.pu);
    prop_report(&lp.pax);
    prop_report(&lp.pay);
    prop_report(&lp.paxy);
    prop_report(&lp.pneg);
    prop_report(&lp.pid);
    prop_report(&lp.peq);
    printf("# form_lincomb: %ld results compared exactly, %ld overflows\n", lp.exact, lp.ovf);
}

/* ---- form_set_point ---- */

static void set_point(void)
{
    prop p;
    long i;
    const long n = 50000;
    form f, g;
    ptp_error err;
    prop_init(&p, "form: form_set_point(j, w) is the canonical w*b_j, zero for w == 0, error "
                  "for bad j or rank (%ld random)",
              n);
    form_init(&f, 1);
    form_init(&g, 2);
    for (i = 0; i < n; i++) {
        int j = (int)check_rnd_below(FORM_MAX_POINT + 1), st;
        rat w;
        ptp_i128 wn = rnd_num(1), wd = rnd_den(1);
        rat_set_frac(&w, wn, wd);
        if (i % 10 == 0)
            rat_set_si(&w, 0);
        p.tried++;
        st = form_set_point(&f, j, &w, &err);
        if (st || !form_is_canonical(&f) || f.len != (w.num != 0) ||
            (f.len && f.t[0].key != form_key_point(j))) {
            prop_fail(&p, "form_set_point(%d, %s): %d %s", j, SR(&w), st, SF(&f));
        } else if (f.len) {
            rat got;
            form_get_weight(&got, &f, 0);
            if (!rat_equal(&got, &w))
                prop_fail(&p, "form_set_point(%d, %s): weight %s", j, SR(&w), SR(&got));
        }
    }
    {
        rat w;
        rat_set_si(&w, 3);
        p.tried++;
        if (form_set_point(&f, -1, &w, &err) == PTP_OK ||
            form_set_point(&f, FORM_MAX_POINT + 1, &w, &err) == PTP_OK ||
            form_set_point(&g, 5, &w, &err) == PTP_OK)
            prop_fail(&p, "a bad point or a rank-2 form was accepted");
    }
    prop_report(&p);
    form_clear(&f);
    form_clear(&g);
}

/* ---- form_is_canonical on hand-made forms ---- */

typedef struct {
    const char *why;
    int rank;
    size_t len;
    form_term t[3];
    ptp_i128 den;
} handmade;

#define K2(a, b) (((form_key)(a) << 16) | (form_key)(b))
#define K3(a, b, c) (((form_key)(a) << 32) | ((form_key)(b) << 16) | (form_key)(c))

static form as_form(const handmade *h)
{
    form f;
    f.rank = h->rank;
    f.len = f.cap = h->len;
    f.t = (form_term *)h->t;
    f.den = h->den;
    return f;
}

static void canonical(void)
{
    static const handmade bad[] = {
        {"unsorted keys", 1, 2, {{5, 1}, {3, 1}}, 1},
        {"duplicate keys", 1, 2, {{3, 1}, {3, 2}}, 1},
        {"unsorted keys, rank 2", 2, 2, {{K2(1, 4), 1}, {K2(1, 3), 1}}, 1},
        {"zero numerator", 1, 2, {{1, 0}, {2, 1}}, 1},
        {"den 0", 1, 1, {{1, 1}}, 0},
        {"den -1", 1, 1, {{1, 1}}, -1},
        {"den -3", 1, 2, {{1, 1}, {2, 1}}, -3},
        {"gcd 2 of nums and den", 1, 2, {{1, 2}, {2, 4}}, 6},
        {"gcd 3 of num and den", 2, 1, {{K2(0, 1), -3}}, 3},
        {"zero form with den 2", 1, 0, {{0, 0}}, 2},
        {"zero form with den 0", 2, 0, {{0, 0}}, 0},
        {"rank 0", 0, 0, {{0, 0}}, 1},
        {"rank 4", FORM_MAX_RANK + 1, 0, {{0, 0}}, 1},
        {"num -2^127", 1, 1, {{1, -MAXI - 1}}, 1},
        {"unsorted indices (5,3)", 2, 1, {{K2(5, 3), 1}}, 1},
        {"repeated indices (3,3)", 2, 1, {{K2(3, 3), 1}}, 1},
        {"unsorted indices (1,3,2)", 3, 1, {{K3(1, 3, 2), 1}}, 1},
        {"repeated indices (1,2,2)", 3, 1, {{K3(1, 2, 2), 1}}, 1},
        {"repeated indices (0,0,1)", 3, 1, {{K3(0, 0, 1), 1}}, 1},
        {"rank-1 key above 0xFFFF", 1, 1, {{0x10000, 1}}, 1},
        {"rank-2 key with bits above 32", 2, 1, {{((form_key)1 << 32) | K2(1, 2), 1}}, 1},
    };
    static const handmade bad_hi[] = {
        {"rank-3 key with bits above 48", 3, 1, {{((form_key)1 << 48) | K3(0, 1, 2), 1}}, 1},
        {"rank-3 key with bit 63 set", 3, 1, {{((form_key)1 << 63) | K3(4, 5, 6), 1}}, 1},
    };
    static const handmade good[] = {
        {"zero rank 1", 1, 0, {{0, 0}}, 1},
        {"zero rank 2", 2, 0, {{0, 0}}, 1},
        {"zero rank 3", 3, 0, {{0, 0}}, 1},
        {"one point", 1, 1, {{0, 1}}, 1},
        {"point 65535", 1, 1, {{0xFFFF, -7}}, 1},
        {"2/6 + 3/6 shape", 1, 2, {{1, 2}, {2, 3}}, 6},
        {"rank 2", 2, 2, {{K2(0, 1), -1}, {K2(0, 2), 1}}, 2},
        {"rank 3", 3, 2, {{K3(0, 1, 2), 5}, {K3(65533, 65534, 65535), -MAXI}}, MAXI},
    };
    prop p, ph;
    size_t i;
    prop_init(&p, "form: form_is_canonical rejects %zu hand-made non-canonical forms and "
                  "accepts %zu canonical ones",
              sizeof bad / sizeof bad[0], sizeof good / sizeof good[0]);
    for (i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        form f = as_form(&bad[i]);
        p.tried++;
        if (form_is_canonical(&f))
            prop_fail(&p, "accepts %s: %s", bad[i].why, SF(&f));
    }
    for (i = 0; i < sizeof good / sizeof good[0]; i++) {
        form f = as_form(&good[i]);
        p.tried++;
        if (!form_is_canonical(&f))
            prop_fail(&p, "rejects %s: %s", good[i].why, SF(&f));
    }
    prop_report(&p);

    /* Kept apart: a key must be a packing of rank indices, so bits above 16*rank must be 0
     * for rank 3 as for ranks 1 and 2 (otherwise two different keys stand for one product). */
    prop_init(&ph, "form: form_is_canonical rejects rank-3 keys with bits set above bit 47");
    for (i = 0; i < sizeof bad_hi / sizeof bad_hi[0]; i++) {
        form f = as_form(&bad_hi[i]);
        ph.tried++;
        if (form_is_canonical(&f))
            prop_fail(&ph, "accepts %s: key 0x%016llx", bad_hi[i].why,
                      (unsigned long long)bad_hi[i].t[0].key);
    }
    prop_report(&ph);
}

int main(void)
{
    check_rng = SEED;
    keys();
    set_terms();
    lincomb();
    set_point();
    canonical();
    return check_exit();
}
