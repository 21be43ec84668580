/* domain.h: the patch domain: its kind and degrees, how its points and planes are numbered,
 * and how its degree is read and written. Every index map and degree name goes through here. */
#ifndef DOMAIN_H
#define DOMAIN_H

#include "core/ptp.h"

/* The kinds of patch. Quad: tensor-product, bidegree (n, m), n along u. Triangle: total
 * degree d (n = m = d), points b_ijk (i + j + k = d) weighted by u^i v^j w^k, w = 1 - u - v. */
typedef enum { TP_QUAD, TP_TRI } tp_kind;

/* The largest supported triangle degree: every weight up to it is exact in 128-bit rationals. */
#define PTP_MAX_TRI_DEGREE 28

/* A patch domain. Points and planes are both numbered over a grid: a point over the degrees
 * (n, m), a plane over the plane degrees (pu, pv), by the kind's rule (quad: row-major, the
 * first index along u: k = i*(m+1) + j, P = I*(pv+1) + J; triangle: (i, j) in descending
 * lexicographic order, k = (d-i)(d-i+1)/2 + (d-i-j), P = (D-I)(D-I+1)/2 + (D-I-J) with
 * D = 3d-3). */
typedef struct {
    tp_kind kind;
    int n, m;            /* patch degrees (quad: n along u, m along v) */
    int pu, pv;          /* plane degrees of T = cross4(B, dB/du, dB/dv) (quad: 3n-2, 3m-2;
                            triangle: pu = pv = 3d-3) */
    int npoints, nplanes;
} tp_domain;

/* The names a domain prints, e.g. for the bicubic quad the comments show. */
typedef struct {
    const char *word;        /* "bidegree" */
    char degree[16];         /* "3x3": the --degree argument that reads back as this domain */
    char name[32];           /* "bidegree 3x3" */
    char patches[64];        /* "bidegree 3x3 Bezier patches", "degree 3 triangular Bezier patches" */
    char plane_degree[16];   /* "7x7" */
    char plane_name[32];     /* "bidegree 7x7" */
    char degrees[16];        /* "3, 3": the items of the JSON "degree" list */
    char plane_degrees[16];  /* "7, 7": the items of the JSON "plane_degree" list */
    char json[80];           /* the JSON members naming the domain: "\"degree\": [3, 3],
                                \"plane_degree\": [7, 7]" for quads, "\"domain\": \"triangle\",
                                \"degree\": 3, \"plane_degree\": 6" for triangles (one a line,
                                the lines after the first indented by two spaces) */
    char point_rule[32];     /* "k = i*4 + j" */
    char plane_rule[32];     /* "P = I*8 + J" */
    const char *point_axes;  /* "i along u" */
    const char *plane_axes;  /* "I along u" */
    const char *plane_rows;  /* "row I along u, column J along v": the layout of plane matrices */
    const char *conventions; /* both numberings in symbols: "point k = i*(m+1)+j and ..." */
} tp_domain_text;

/* d = the domain of the kind and degrees (m is ignored by kinds with one degree). Fails with
 * PTP_EUSAGE for a degree below 1 and PTP_ELIMIT beyond the kind's limit (PTP_MAX_DEGREE,
 * PTP_MAX_TRI_DEGREE); d is then unset. */
int tp_domain_init(tp_domain *d, tp_kind kind, int n, int m, ptp_error *err);
/* d = the domain of the kind that the --degree argument arg names (quad: "N" for NxN, or
 * "NxM", 'x' or 'X', decimal digits only; triangle: "N" only). Every rejection is PTP_EUSAGE,
 * with a message starting "--degree 'ARG': ". */
int tp_domain_parse(tp_domain *d, tp_kind kind, const char *arg, ptp_error *err);
/* The domain with u and v exchanged: point (i, j) and plane (I, J) of d are point (j, i) and
 * plane (J, I) of *t. */
void tp_domain_transpose(tp_domain *t, const tp_domain *d);

/* The cells of the kind's grid of degrees (a, b) (b is ignored by kinds with one degree):
 * their number, the number 0 <= k < count of cell (i, j), and back. Points are the grid
 * (n, m), planes the grid (pu, pv). */
int tp_grid_count(tp_kind kind, int a, int b);
int tp_grid_index(tp_kind kind, int a, int b, int i, int j);
void tp_grid_coords(int *i, int *j, tp_kind kind, int a, int b, int k);
/* Nonzero when (i, j) is a cell of the grid. */
int tp_grid_has(tp_kind kind, int a, int b, int i, int j);
/* The name of the kind as --domain reads it and the json writes it: "quad", "triangle". */
const char *tp_kind_name(tp_kind kind);

/* The number of point (i, j), 0 <= k < npoints; and back. */
int tp_domain_point(const tp_domain *d, int i, int j);
void tp_domain_point_ij(int *i, int *j, const tp_domain *d, int k);
/* The number of plane (I, J), 0 <= P < nplanes; and back. */
int tp_domain_plane(const tp_domain *d, int I, int J);
void tp_domain_plane_ij(int *I, int *J, const tp_domain *d, int P);
/* Nonzero when plane P starts a row of the plane matrix that stats and tables print, the
 * planes in numbering order (both kinds: J == 0, a row per I). */
int tp_domain_plane_row_start(const tp_domain *d, int P);

/* The number of boundary edges of d's patch (quad 4, triangle 3), and whether point (i, j) is
 * on edge e (quad: 0 i = 0, 1 i = n, 2 j = 0, 3 j = m; triangle: 0 i = 0, 1 j = 0,
 * 2 k = 0 (i + j = d)). */
int tp_domain_edges(const tp_domain *d);
int tp_domain_on_edge(const tp_domain *d, int e, int i, int j);
/* The most points a boundary edge has (of the largest triangle). */
#define TP_EDGE_POINTS_MAX (PTP_MAX_TRI_DEGREE + 1)
/* k[0 .. count-1] = the points on boundary edge e of d, in increasing order; returns count
 * (the edge's degree plus 1, at most TP_EDGE_POINTS_MAX). */
int tp_domain_edge_points(int *k, const tp_domain *d, int e);
/* The boundary edges e of d (bit e) on which at least two of the points k[0..2] lie: collapsing
 * such an edge (all its points equal) makes the term det[b_k0 b_k1 b_k2 ...] exactly zero. */
unsigned tp_domain_term_edges(const tp_domain *d, const int k[3]);

/* Writes the degree as --degree reads it ("3x3") to buf (size bytes); returns buf. */
char *tp_domain_format(char *buf, size_t size, const tp_domain *d);
/* Writes the default prefix of generated names ("ptp_3x3_") to buf (size bytes); returns buf. */
char *tp_domain_prefix(char *buf, size_t size, const tp_domain *d);
/* Fills x with the names of d. */
void tp_domain_text_get(tp_domain_text *x, const tp_domain *d);

#endif
