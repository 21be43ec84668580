/* host_mesh.c: runs the degree-1 triangle header's classify_mesh and classify_clusters on
 * indexed meshes made from kref's sets and holds them to classify and to kref (C and C++). */
#include "host_c.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The counts over all sets. */
typedef struct {
    kref_result mesh;      /* classify_mesh on each set's own triangles, against kref */
    size_t triangles;      /* triangles of all meshes compared with classify */
    size_t mesh_differ;    /* classify_mesh's class differs from classify's */
    size_t clusters;       /* clusters compared with the reference loop */
    size_t cluster_differ; /* classify_clusters differs from it */
    size_t shared;         /* vertices the meshes share between triangles */
    size_t collapsed;      /* adversarial triangles with a repeated index */
} results;

/* A mesh: nv vertices and nt triangles (3 indices each). */
typedef struct {
    float (*v)[4];
    uint32_t *ix;
    size_t nv, nt;
} mesh;

static const float *sort_base; /* the points compare_points orders (qsort has no context) */

/* qsort order of point indices by their four coordinates' bits. */
static int compare_points(const void *a, const void *b)
{
    uint32_t i = *(const uint32_t *)a, j = *(const uint32_t *)b;
    int c = memcmp(sort_base + 4 * (size_t)i, sort_base + 4 * (size_t)j, 4 * sizeof(float));
    return c ? c : (i > j) - (i < j);
}

/* m = the triangles of s over a vertex array without repeated points (bitwise): points equal
 * in one triangle (collapsed edges) or across triangles become one shared vertex. */
static void mesh_of_set(mesh *m, const kref_set *s)
{
    size_t n = s->count * 3, k;
    uint32_t *order = (uint32_t *)malloc(n * sizeof *order);
    m->v = (float(*)[4])malloc(n * sizeof *m->v);
    m->ix = (uint32_t *)malloc(n * sizeof *m->ix);
    m->nt = s->count;
    m->nv = 0;
    for (k = 0; k < n; k++)
        order[k] = (uint32_t)k;
    sort_base = s->cp[0];
    qsort(order, n, sizeof *order, compare_points);
    for (k = 0; k < n; k++) {
        if (k == 0 || memcmp(s->cp[order[k]], s->cp[order[k - 1]], sizeof *m->v))
            memcpy(m->v[m->nv++], s->cp[order[k]], sizeof *m->v);
        m->ix[order[k]] = (uint32_t)(m->nv - 1);
    }
    free(order);
}

/* a = nt triangles over m's vertices, deterministic in seed: strips that share an edge with the
 * triangle before, random triples, and one in eight with a repeated index (collapsed). */
static size_t adversarial_mesh(mesh *a, const mesh *m, size_t nt, uint64_t seed)
{
    size_t t, collapsed = 0;
    a->v = m->v;
    a->nv = m->nv;
    a->nt = nt;
    a->ix = (uint32_t *)malloc(3 * nt * sizeof *a->ix);
    for (t = 0; t < nt; t++) {
        uint32_t *x = a->ix + 3 * t;
        int k;
        for (k = 0; k < 3; k++) {
            seed = seed * 6364136223846793005u + 1442695040888963407u;
            x[k] = (uint32_t)((seed >> 33) % m->nv);
        }
        if (t > 0 && (seed >> 20) % 2) { /* the edge (2, 1) of the one before, reversed */
            x[0] = x[-1];
            x[1] = x[-2];
        }
        if ((seed >> 24) % 8 == 0)
            x[(seed >> 28) % 3] = x[(seed >> 30) % 2 ? 0 : 1];
        collapsed += x[0] == x[1] || x[1] == x[2] || x[0] == x[2];
    }
    return collapsed;
}

/* Classifies every triangle of m with classify (gathered) into ref, and with classify_mesh
 * (all at once, and from the second triangle on); returns the triangles that differ. */
static size_t mesh_vs_classify(unsigned char *ref, const mesh *m, const float eye[4])
{
    unsigned char *cls = (unsigned char *)malloc(m->nt + 1);
    size_t t, bad = 0;
    int k;
    for (t = 0; t < m->nt; t++) {
        float cp[3][4];
        for (k = 0; k < 3; k++)
            memcpy(cp[k], m->v[m->ix[3 * t + k]], sizeof cp[k]);
        ref[t] = (unsigned char)FN(classify)((const float(*)[4])cp, eye);
    }
    FN(classify_mesh)((const float(*)[4])m->v, m->ix, m->nt, eye, cls);
    for (t = 0; t < m->nt; t++)
        bad += cls[t] != ref[t];
    if (m->nt > 1) { /* a start that is not a block's */
        FN(classify_mesh)((const float(*)[4])m->v, m->ix + 3, m->nt - 1, eye, cls);
        for (t = 1; t < m->nt; t++)
            bad += cls[t - 1] != ref[t];
    }
    free(cls);
    return bad;
}

/* classify_clusters of m against a loop over its triangles' classes ref, for several cluster
 * sizes; counts into r. */
static void clusters_vs_loop(results *r, const mesh *m, const unsigned char *ref, const float eye[4])
{
    size_t sizes[] = {1, 2, 3, 7, 64, 65, 200, m->nt, m->nt + 5}, i, c, t;
    unsigned char *cls = (unsigned char *)malloc(m->nt + 2);
    for (i = 0; i < sizeof sizes / sizeof *sizes; i++) {
        size_t z = sizes[i], nc = (m->nt + z - 1) / z;
        cls[nc] = 0xee; /* must stay: one class per cluster, no more */
        FN(classify_clusters)((const float(*)[4])m->v, m->ix, m->nt, z, eye, cls);
        for (c = 0; c < nc; c++) {
            int back = 1, front = 1;
            for (t = c * z; t < (c + 1) * z && t < m->nt; t++) {
                back &= ref[t] == MACRO(BACK);
                front &= ref[t] == MACRO(FRONT);
            }
            r->cluster_differ += cls[c] != (back ? MACRO(BACK) : front ? MACRO(FRONT) : MACRO(SILHOUETTE));
        }
        r->cluster_differ += cls[nc] != 0xee;
        r->clusters += nc;
    }
    free(cls);
}

/* Runs the mesh entry points over one set and accumulates into ctx (results); returns 0. */
static int run_set(void *ctx, const kref_ref *ref, const kref_set *s)
{
    results *r = (results *)ctx;
    mesh m, a;
    unsigned char *rc = (unsigned char *)malloc(2 * s->count + 1);
    unsigned *cls = (unsigned *)malloc(s->count * sizeof *cls + 1);
    size_t t;
    mesh_of_set(&m, s);
    r->shared += 3 * s->count - m.nv;
    r->mesh_differ += mesh_vs_classify(rc, &m, s->eye);
    r->triangles += m.nt;
    for (t = 0; t < s->count; t++)
        cls[t] = rc[t];
    kref_check(&r->mesh, ref, s, cls, NULL);
    clusters_vs_loop(r, &m, rc, s->eye);
    r->collapsed += adversarial_mesh(&a, &m, 2 * s->count, s->count * 31 + 7);
    r->mesh_differ += mesh_vs_classify(rc, &a, s->eye);
    r->triangles += a.nt;
    clusters_vs_loop(r, &a, rc, s->eye);
    free(a.ix);
    free(m.v);
    free(m.ix);
    free(rc);
    free(cls);
    return 0;
}

/* Before the sets: the mesh entry points are the degree-1 triangle's; 1 otherwise. */
static int ready(void *ctx, const kref_args *o, const kref_ref *ref)
{
    (void)ctx;
    if (o->kind != TP_TRI || o->n != 1 || ref->K != MACRO(POINTS))
        return !check(0, o->label, "the mesh entry points are the degree-1 triangle's");
    return 0;
}

/* The check lines of all sets; 1 if they all passed. */
static int report(void *ctx, const kref_args *o, const kref_ref *ref)
{
    const results *r = (const results *)ctx;
    char label[200];
    int ok = host_report(&r->mesh, o, "classify_mesh");
    (void)ref;
    snprintf(label, sizeof label,
             "%s classify_mesh equals classify on all %zu triangles (%zu shared vertices, %zu collapsed)",
             o->label, r->triangles, r->shared, r->collapsed);
    ok &= check(r->mesh_differ == 0 && r->shared > 0 && r->collapsed > 0, label,
                "it differs %zu times", r->mesh_differ);
    snprintf(label, sizeof label, "%s classify_clusters equals the loop on all %zu clusters",
             o->label, r->clusters);
    ok &= check(r->cluster_differ == 0, label, "it differs %zu times", r->cluster_differ);
    return ok;
}

int main(int argc, char **argv)
{
    static const kref_host host = {"host_mesh", ready, run_set, report};
    results r;
    int st;
    memset(&r, 0, sizeof r);
    st = kref_host_main(&host, &r, argc, argv);
    return st ? st : check_exit();
}
