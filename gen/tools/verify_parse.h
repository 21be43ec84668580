/* verify_parse.h: reading a control-plane table written by someone else, for verify.c.
 * The paper's C arrays (idx rows, wgt weights) or ptpgen's JSON, with the line of every term. */
#ifndef VERIFY_PARSE_H
#define VERIFY_PARSE_H

#include "core/rat.h"

/* A weight as written: its value, exact when it was written exactly. Integer literals, float
 * literals with an integer value below 2^24 (-9.0f, 2.) and quotients and products of those
 * (-27/7, -27.0f/7.0f, "-27/7") are exact; anything else (-3.85714293f, 1e-3) is a rounding. */
typedef struct {
    double d;  /* the value (the nearest double) */
    rat r;     /* the exact value, when exact */
    int exact;
} verify_weight;

/* The largest index a table may name (the largest bidegree has 2209 planes and 289 points). */
#define VERIFY_MAX_INDEX 99999

/* One term as written: t[plane] += w * cross4(b[p[0]], b[p[1]], b[p[2]]). */
typedef struct {
    int plane, p[3]; /* 0..VERIFY_MAX_INDEX, the points in the order written */
    verify_weight w;
    int line;        /* the line of the term: its idx row, or its JSON array */
    int wline;       /* the line of its weight (the term's own line in JSON) */
} verify_term;

/* A table as read. */
typedef struct {
    verify_term *terms;
    size_t nterms;
    int n, m;          /* the bidegree the document names, 0 when it names none: JSON "degree",
                          or an idx array named like ptp_2x3_idx or ptp_2x3_table_idx */
    int degree_line;   /* the line that names it */
    int degree_named;  /* 1: from the "degree" field (binding); 2: from the array name (a hint) */
} verify_doc;

/* Reads text[0..len) (any bytes, no NUL needed) as a ptpgen JSON document (it starts with '{'
 * or '[': an object with "terms", or the terms array itself) or as C source holding one array
 * named idx or *_idx (not *sched_idx) of rows {plane, j, k, l} and one named wgt or *_wgt (not
 * *iwgt, *sched_wgt) of as many weights, both in any order among comments, preprocessor lines and
 * other declarations. Returns PTP_OK, PTP_EUSAGE with "NAME:LINE: why" in err, or PTP_ENOMEM.
 * d is uninitialized on entry; on success the caller frees it with verify_doc_clear, on failure
 * it holds no memory. Depth and literal lengths are bounded: no input recurses deeply. */
int verify_parse(verify_doc *d, const char *text, size_t len, const char *name, ptp_error *err);
/* Frees d's storage. */
void verify_doc_clear(verify_doc *d);
/* Sets *n, *m to the bidegree to check d against: (n0, m0) when not 0; else the "degree" field;
 * else the one bidegree whose numbers of planes and points the indices of d use (a square one,
 * or one agreeing with the array name). PTP_EUSAGE (err "NAME:LINE: why ...; use --degree")
 * when that is absent or ambiguous. */
int verify_doc_degree(int *n, int *m, const verify_doc *d, int n0, int m0, const char *name,
                      ptp_error *err);
/* The one unordered bidegree {*a <= *b} with (a+1)(b+1) points and (3a-1)(3b-1) planes that
 * the indices of d use (the largest index plus one); returns 0 when no bidegree fits. */
int verify_doc_fit(int *a, int *b, const verify_doc *d);

#endif
