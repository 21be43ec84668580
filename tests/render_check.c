/* render_check.c: checks build/render's cull passes on its --dump-clip files: the ptp kernels'
 * classes against the kernel tests' double reference (kref) and against ptpgen's C header
 * (classify_batch) on the same clip-space floats, and the TCONE / NCONE shader's culled set
 * against bench/cones.c on the same model and eye (the axis negated for --orientation in).
 *
 *   render_check ptp|ptp-table|ptp-tcs|ptp-certified|ptp-tcs-certified DUMP LABEL
 *   render_check tcone|ncone DUMP MODEL.bez LABEL
 * (compiled with rc_s.h and rc_c.h, ptpgen's clip-space C headers, strict and certified, and
 * linked with libptptest.a)
 *
 * Prints "ok - LABEL: ..." / "not ok - ..." lines; exits 0 when every check passed, 1 when one
 * failed, 2 for bad input. */
#include "bez.h"
#include "check.h"
#include "cones.h"
#include "kref.h"

#define RC_S_IMPLEMENTATION
#include "rc_s.h"
#define RC_C_IMPLEMENTATION
#include "rc_c.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* A dump of build/render (bench/render/main.c's format). */
typedef struct dump {
    uint32_t n;
    float alpha;
    uint32_t inward;
    double eye[3];
    float (*cp)[4];
    uint32_t *cls;
} dump;

static int read_dump(dump *d, const char *path)
{
    FILE *f = fopen(path, "rb");
    char magic[8];
    int ok = f && fread(magic, 1, 8, f) == 8 && !memcmp(magic, "PTPCLIP1", 8) &&
             fread(&d->n, 4, 1, f) == 1 && d->n > 0 && d->n < 100000000 &&
             fread(&d->alpha, 4, 1, f) == 1 && fread(&d->inward, 4, 1, f) == 1 &&
             fread(d->eye, 8, 3, f) == 3;
    d->cp = NULL;
    d->cls = NULL;
    if (ok) {
        d->cp = malloc((size_t)d->n * 16 * sizeof *d->cp);
        d->cls = malloc((size_t)d->n * sizeof *d->cls);
        ok = d->cp && d->cls && fread(d->cp, 16 * 16, d->n, f) == d->n &&
             fread(d->cls, 4, d->n, f) == d->n;
    }
    if (f)
        fclose(f);
    return ok ? 0 : -1;
}

/* 1 when some plane of patch p has its double reference value within its float bound of zero
 * (the kernel tests' ambiguity: either class is a correct float answer). */
static int ambiguous(const kref_ref *r, const kref_set *s, size_t p)
{
    double d[64], bound[64];
    kref_values(r, s, p, d, bound);
    for (int i = 0; i < r->L; i++)
        if (bound[i] > 0 && fabs(d[i]) <= bound[i])
            return 1;
    return 0;
}

/* The renderer's classes against classify_batch: culls the same patches, or (certified: the
 * header also certifies in double, the GPU in float only) among the header's culls; every other
 * difference must be ambiguous. */
static int against_header(const kref_ref *r, const kref_set *s, const unsigned *cls,
                          int certified, const char *label)
{
    unsigned char *ref = malloc(s->count);
    size_t g = 0, h = 0, differ = 0, unexplained = 0, first = SIZE_MAX;
    if (!ref)
        return check(0, label, "out of memory");
    (certified ? rc_c_classify_batch : rc_s_classify_batch)((const float(*)[4])s->cp, s->count,
                                                            s->eye, ref);
    for (size_t p = 0; p < s->count; p++) {
        int mine = cls[p] == 1, theirs = ref[p] == 1;
        g += mine;
        h += theirs;
        if (mine == theirs || (certified && !mine))
            continue;
        differ++;
        if (!ambiguous(r, s, p) && !unexplained++)
            first = p;
    }
    free(ref);
    return check(!unexplained, label,
                 "renderer %zu, header %zu, %zu differ, %zu not within float ambiguity (first: "
                 "patch %zu)",
                 g, h, differ, unexplained, first) &&
           printf("# culled: renderer %zu, classify_batch%s %zu; %zu differ, all within float "
                  "ambiguity\n",
                  g, certified ? " --certified" : "", h, differ) > 0;
}

static int check_ptp(const dump *dm, int certified, const char *label)
{
    kref_ref r;
    kref_result res;
    ptp_error err;
    kref_set s;
    unsigned *cls = malloc((size_t)dm->n * sizeof *cls);
    char name[400];
    int ok;
    memset(&err, 0, sizeof err);
    memset(&res, 0, sizeof res);
    if (!cls || kref_init(&r, TP_QUAD, 3, 3, KREF_CLIP, KREF_STRICT, &err))
        return check(0, label, "kref_init: %s", err.msg);
    r.certified = certified;
    memset(&s, 0, sizeof s);
    snprintf(s.name, sizeof s.name, "dump");
    s.count = dm->n;
    s.K = 16;
    s.cp = dm->cp;
    s.eye[2] = dm->alpha;
    for (uint32_t p = 0; p < dm->n; p++)
        cls[p] = dm->cls[p];
    kref_check(&res, &r, &s, cls, NULL);
    ok = kref_report(&res, label);
    snprintf(name, sizeof name, "%s: culls what classify_batch%s culls on the same points", label,
             certified ? " --certified" : "");
    ok = against_header(&r, &s, cls, certified, name) && ok;
    kref_clear(&r);
    free(cls);
    return ok;
}

static int check_cone(const dump *d, const char *model, int tcone, const char *label)
{
    bez_model m;
    char err[512], name[400];
    size_t g = 0, c = 0, differ = 0, first = SIZE_MAX;
    if (bez_read(&m, model, err, sizeof err) || m.npatches != d->n) {
        bez_free(&m);
        return check(0, label, "%s", m.pts ? "the patch count differs from the dump's" : err);
    }
    for (size_t p = 0; p < m.npatches; p++) {
        cone_patch b = {.domain = CONE_QUAD};
        cone_bound cb;
        int mine = d->cls[p] == 1, theirs;
        for (int k = 0; k < 16; k++)
            for (int i = 0; i < 3; i++)
                b.p[k][i] = m.pts[(p * 16 + (size_t)k) * 3 + (size_t)i];
        if ((tcone ? cone_tcone(&b, &cb) : cone_ncone(&b, &cb)) != CONE_OK)
            cb.usable = 0;
        for (int i = 0; i < 3 && d->inward; i++)
            cb.axis[i] = -cb.axis[i];
        theirs = cone_cull(&cb, d->eye);
        g += mine;
        c += theirs;
        if (mine != theirs && !differ++)
            first = p;
    }
    bez_free(&m);
    snprintf(name, sizeof name, "%s: culls what bench/cones.c's %s culls (%zu of %u)", label,
             tcone ? "TCONE" : "NCONE", c, d->n);
    return check(!differ, name, "renderer %zu, cones.c %zu, %zu differ (first: patch %zu)", g, c,
                 differ, first);
}

int main(int argc, char **argv)
{
    dump d;
    int ok = 0, rc = 2;
    if (argc < 4 || read_dump(&d, argv[2])) {
        fprintf(stderr, "usage: render_check ptp|ptp-table|ptp-tcs|ptp-certified|ptp-tcs-certified DUMP LABEL | "
                        "tcone|ncone DUMP "
                        "MODEL LABEL (DUMP: a build/render --dump-clip file)\n");
        return 2;
    }
    if (!strncmp(argv[1], "ptp", 3) && argc == 4) { /* every plain ptp method, or certified */
        ok = check_ptp(&d, strstr(argv[1], "certified") != NULL, argv[3]);
        rc = ok ? 0 : 1;
    } else if ((!strcmp(argv[1], "tcone") || !strcmp(argv[1], "ncone")) && argc == 5) {
        ok = check_cone(&d, argv[3], argv[1][0] == 't', argv[4]);
        rc = ok ? 0 : 1;
    }
    free(d.cp);
    free(d.cls);
    return rc;
}
