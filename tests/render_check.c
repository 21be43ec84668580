/* render_check.c: checks build/render's cull passes from its --dump-clip files: the ptp kernels'
 * classes against ptpgen's C header (classify_batch) on the same clip-space floats, and the
 * TCONE / NCONE shader's culled set against bench/cones.c on the same model and eye (the cone's
 * axis negated for --orientation in).
 *
 *   render_check ptp|ptp-certified DUMP          (compiled with rc_s.h and rc_c.h: ptpgen's
 *   render_check tcone|ncone DUMP MODEL.bez       clip-space C headers, strict and certified)
 *
 * Prints "# ..." with the counts and exits 0 when the culled sets agree, 1 otherwise, 2 for
 * bad input. */
#include "bez.h"
#include "cones.h"

#define RC_S_IMPLEMENTATION
#include "rc_s.h"
#define RC_C_IMPLEMENTATION
#include "rc_c.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* A dump of build/render (main.c's format). */
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

/* Compares the culled sets (class 1) of the renderer (gpu) and the reference (ref); prints
 * the counts; returns the number of patches where they differ. */
static size_t compare(const char *what, const uint32_t *gpu, const unsigned char *ref,
                      uint32_t n)
{
    size_t g = 0, r = 0, only_gpu = 0, only_ref = 0;
    for (uint32_t p = 0; p < n; p++) {
        g += gpu[p] == 1;
        r += ref[p] == 1;
        only_gpu += gpu[p] == 1 && ref[p] != 1;
        only_ref += gpu[p] != 1 && ref[p] == 1;
        if ((gpu[p] == 1) != (ref[p] == 1) && only_gpu + only_ref <= 5)
            printf("# %s: patch %u: renderer class %u, reference %u\n", what, p, gpu[p], ref[p]);
    }
    printf("# %s: patches=%u renderer_culled=%zu reference_culled=%zu only_renderer=%zu "
           "only_reference=%zu\n",
           what, n, g, r, only_gpu, only_ref);
    return only_gpu + only_ref;
}

static int check_ptp(const dump *d, int certified)
{
    const float eye[4] = {0, 0, d->alpha, 0};
    unsigned char *ref = malloc(d->n);
    size_t bad;
    if (!ref)
        return 2;
    if (certified)
        rc_c_classify_batch((const float(*)[4])d->cp, d->n, eye, ref);
    else
        rc_s_classify_batch((const float(*)[4])d->cp, d->n, eye, ref);
    bad = compare(certified ? "ptp-certified vs classify_batch --certified"
                            : "ptp vs classify_batch",
                  d->cls, ref, d->n);
    free(ref);
    return bad ? 1 : 0;
}

static int check_cone(const dump *d, const char *model, int tcone)
{
    bez_model m;
    char err[512];
    unsigned char *ref;
    size_t bad = 0;
    if (bez_read(&m, model, err, sizeof err) || m.npatches != d->n) {
        fprintf(stderr, "render_check: %s\n", m.pts ? "patch count differs" : err);
        bez_free(&m);
        return 2;
    }
    if (!(ref = malloc(m.npatches * sizeof *ref)))
        return 2;
    for (size_t p = 0; p < m.npatches && !bad; p++) {
        cone_patch b;
        cone_bound c;
        for (int k = 0; k < 16; k++)
            for (int i = 0; i < 3; i++)
                b.p[k][i] = m.pts[(p * 16 + (size_t)k) * 3 + (size_t)i];
        bad = (tcone ? cone_tcone(&b, &c) : cone_ncone(&b, &c)) != CONE_OK;
        for (int i = 0; i < 3 && d->inward; i++)
            c.axis[i] = -c.axis[i];
        ref[p] = cone_cull(&c, d->eye) ? 1 : 2;
    }
    if (!bad)
        bad = compare(tcone ? "tcone vs bench/cones.c" : "ncone vs bench/cones.c", d->cls, ref,
                      d->n);
    free(ref);
    bez_free(&m);
    return bad ? 1 : 0;
}

int main(int argc, char **argv)
{
    dump d;
    int rc;
    if (argc < 3 || read_dump(&d, argv[2])) {
        fprintf(stderr, "usage: render_check ptp|ptp-certified DUMP | tcone|ncone DUMP MODEL "
                        "(a readable build/render --dump-clip file)\n");
        return 2;
    }
    if (!strcmp(argv[1], "ptp") || !strcmp(argv[1], "ptp-certified"))
        rc = check_ptp(&d, argv[1][3] == '-');
    else if ((!strcmp(argv[1], "tcone") || !strcmp(argv[1], "ncone")) && argc == 4)
        rc = check_cone(&d, argv[3], argv[1][0] == 't');
    else
        rc = 2;
    free(d.cp);
    free(d.cls);
    return rc;
}
