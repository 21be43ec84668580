/* verify_parse.h: reading a control-plane table written by someone else, for verify.c.
 * The paper's C arrays (idx rows, wgt weights) or ptpgen's JSON, with the line of every term. */
#ifndef VERIFY_PARSE_H
#define VERIFY_PARSE_H

#include "core/domain.h"
#include "core/rat.h"

/* A weight as written: its value, exact when it was written exactly. Integer literals, float
 * literals with an integer value below 2^24 (-9.0f, 2.), their products with such a value, and in
 * JSON their quotients ("-27/7") are exact; anything else (-3.85714293f, 1e-3, -27.0f/7 in C,
 * which C rounds to a float) is a rounding. In C a quotient of two integer literals (-27/7) is
 * an error: C evaluates it as an integer division. */
typedef struct {
    double d;  /* the value (the nearest double) */
    rat r;     /* the exact value, when exact */
    int exact;
    int cint;  /* it is a C integer constant expression: integer literals, signs, '*' */
} verify_weight;

/* Writes w to buf (RAT_STRLEN + 32 bytes): "p/q" when exact, else its decimal; returns buf. */
const char *verify_weight_str(char *buf, const verify_weight *w);

/* The largest index a table may name (the largest bidegree has 2209 planes and 289 points). */
#define VERIFY_MAX_INDEX 99999

/* One term as written: t[plane] += w * cross4(b[p[0]], b[p[1]], b[p[2]]). */
typedef struct {
    int plane, p[3]; /* 0..VERIFY_MAX_INDEX, the points in the order written */
    verify_weight w;
    int line;        /* the line of the term: its idx row, or its JSON array */
    int wline;       /* the line of its weight (the term's own line in JSON) */
} verify_term;

/* The C arrays verify reads besides idx and wgt (names matched by suffix, like idx and wgt). */
enum {
    VERIFY_IWGT,       /* iwgt: wgt times DENOM, integers */
    VERIFY_OWNER,      /* owner: the thread of each plane */
    VERIFY_SCHED_IDX,  /* sched_idx: the scheduled slots, rows {plane, j, k, l} */
    VERIFY_SCHED_WGT,  /* sched_wgt: their weights */
    VERIFY_SCHED_IWGT, /* sched_iwgt: their weights times DENOM */
    VERIFY_NARRAYS
};

/* One of those arrays as read: rows (plane, p, line) or numbers (w, line = wline). */
typedef struct {
    verify_term *e;
    size_t n;
    int line; /* its declaration; 0 when the document has none */
} verify_array;

/* A macro #define NAME INTEGER whose name ends in DENOM or THREADS. */
typedef struct {
    long v;
    int line; /* 0 when absent */
} verify_macro;

/* The most characters of the names of ignored arrays kept for the report. */
#define VERIFY_IGNORED_LEN 200

/* A table as read. */
typedef struct {
    verify_term *terms;
    size_t nterms;
    int c_source;      /* read as C (else JSON) */
    verify_array arr[VERIFY_NARRAYS];
    verify_macro denom, threads;
    char ignored[VERIFY_IGNORED_LEN]; /* the other arrays defined, or the JSON keys other than
                                         terms, degree, format, generator and command: "foo, bar"
                                         (cut short with "...") */
    int nfunctions, function_line;    /* function definitions, and the line of the first */
    int n, m;          /* the degrees the document names, 0 when it names none: JSON "degree"
                          ([n, m], or one number d for a triangle: n = m = d), or an idx array
                          named like ptp_2x3_idx, ptp_2x3_table_idx or ptp_tri3_table_idx */
    int degree_line;   /* the line that names it */
    int degree_named;  /* 1: from the "degree" field (binding); 2: from the array name (a hint) */
    int degree_one;    /* the "degree" field is one number (a triangle's) */
    tp_kind kind;      /* the domain the document names: JSON "domain", or the array name
                          (ptp_tri3_idx: triangle, ptp_2x3_idx: quad); TP_QUAD when none */
    int kind_named;    /* 0: none; 1: from the "domain" field (binding); 2: the array name */
    int kind_line;     /* the line that names it */
} verify_doc;

/* Reads text[0..len) (any bytes, no NUL needed) as a ptpgen JSON document (it starts with '{'
 * or '[': an object with "terms", or the terms array itself) or as C source holding one array
 * named idx or *_idx (not *sched_idx) of rows {plane, j, k, l} and one named wgt or *_wgt (not
 * *iwgt, *sched_wgt) of as many weights, both in any order among comments, preprocessor lines and
 * other declarations; also at most one of each of d->arr's arrays, the DENOM and THREADS macros,
 * and the names of other arrays and the count of function definitions. C source with functions
 * but no idx array is an error saying its code cannot be checked from its text. Returns PTP_OK,
 * PTP_EUSAGE with "NAME:LINE: why" in err, or PTP_ENOMEM.
 * d is uninitialized on entry; on success the caller frees it with verify_doc_clear, on failure
 * it holds no memory. Depth and literal lengths are bounded: no input recurses deeply. */
int verify_parse(verify_doc *d, const char *text, size_t len, const char *name, ptp_error *err);
/* Frees d's storage. */
void verify_doc_clear(verify_doc *d);
/* Sets *dom to the domain to check d against. Its kind: kind0 when not negative, else the one
 * d names, else quad unless only a triangle fits the numbers of points and planes its indices
 * use (PTP_EUSAGE when kind0 and a kind d names differ). Its degrees: (n0, m0)
 * when not 0 (a triangle's: n0 = m0); else the "degree" field; else the one degree of the kind
 * whose numbers of planes and points the indices of d use (a square one, or one agreeing with
 * the array name). PTP_EUSAGE (err "NAME:LINE: why ...; use --degree") when that is absent or
 * ambiguous, and tp_domain_init's status for degrees out of range. */
int verify_doc_domain(tp_domain *dom, const verify_doc *d, int kind0, int n0, int m0,
                      const char *name, ptp_error *err);
/* The one unordered pair of degrees {*a <= *b} of the kind (a triangle's: *a = *b) whose numbers
 * of points and planes the indices of d use (the largest index plus one); returns 0 when none
 * fits. */
int verify_doc_fit(int *a, int *b, const verify_doc *d, tp_kind kind);
/* Writes the name of the degrees (a, b) of the kind to buf (32 bytes), as the domain names them
 * ("bidegree 2x3", "degree 3"); returns buf. */
const char *verify_degree_name(char *buf, tp_kind kind, int a, int b);

#endif
