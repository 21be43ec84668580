/* main.c: build/render: ptpgen's cull kernels in a tessellation pipeline. Reads a BEZ model,
 * renders K frames (transform, cull, tessellated draw), prints one line of key=value pairs,
 * and writes the image, the Figure-1 overview and the clip-space dump when asked. */
#include "cam.h"
#include "cli.h"
#include "conedata.h"
#include "png.h"
#include "render.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The main camera and the overview camera as the shaders take them. */
static int cameras(const cli_opts *o, const bez_model *m, render_cam *cam, render_cam *ov,
                   char *err)
{
    cam_view v, w;
    double aspect = (double)o->w / o->h;
    const double *target = o->has_target ? o->target : m->center;
    if (cam_look(&v, o->eye, target, o->up, o->fov, aspect, m->center, m->radius) ||
        cam_overview(&w, &v, o->up, aspect, m->center, m->radius))
        return vkx_fail(err, "bad camera: the eye is on the target or --up is along the view");
    cam_to_gl(cam->mvp, &v.mvp);
    cam_to_gl(ov->mvp, &w.mvp);
    for (int i = 0; i < 3; i++) {
        cam->eye[i] = (float)v.eye[i];
        ov->eye[i] = (float)w.eye[i];
    }
    cam->eye[3] = ov->eye[3] = 1.0f;
    cam->alpha = (float)((o->flip_alpha != o->inward) ? -v.alpha : v.alpha);
    ov->alpha = (float)w.alpha;
    return 0;
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* The median of n values (sorted in place). */
static double median(double *v, unsigned n)
{
    qsort(v, n, sizeof *v, cmp_double);
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

/* Writes the clip-space points and classes of the last frame: "PTPCLIP1", uint32 patches,
 * float alpha, uint32 inward, double eye[3], float points[patches*16*4],
 * uint32 classes[patches]. */
static int dump(const render_gpu *g, const render_cam *cam, const char *path, char *err)
{
    FILE *f = fopen(path, "wb");
    uint32_t n = g->npatches, inward = (uint32_t)g->inward;
    double eye[3] = {cam->eye[0], cam->eye[1], cam->eye[2]};
    int ok = f && fwrite("PTPCLIP1", 1, 8, f) == 8 && fwrite(&n, 4, 1, f) == 1 &&
             fwrite(&cam->alpha, 4, 1, f) == 1 && fwrite(&inward, 4, 1, f) == 1 &&
             fwrite(eye, 8, 3, f) == 3 &&
             fwrite(g->clip.map, 16 * 16, n, f) == n && fwrite(g->cls.map, 4, n, f) == n;
    if (f && fclose(f))
        ok = 0;
    return ok ? 0 : vkx_fail(err, "cannot write %s", path);
}

/* The timings of the output line, in the order of render_stats. */
#define MAIN_NTIMES 9
static const char *const time_keys[MAIN_NTIMES] = {
    "cull_ms",     "draw_ms",     "xform_wall_ms", "cull_wall_ms", "draw_wall_ms",
    "frame_ms",    "cull_cpu_ms", "draw_cpu_ms",   "frame_cpu_ms"};

/* The frame's timings in the order of time_keys. */
static void times_of(const render_stats *s, double t[MAIN_NTIMES])
{
    t[0] = s->cull_ms;
    t[1] = s->draw_ms;
    t[2] = s->xform_wall_ms;
    t[3] = s->cull_wall_ms;
    t[4] = s->draw_wall_ms;
    t[5] = s->frame_ms;
    t[6] = s->cull_cpu_ms;
    t[7] = s->draw_cpu_ms;
    t[8] = s->frame_cpu_ms;
}

/* Prints the output line: counts, the statistics of the last frame, the median timings (t:
 * MAIN_NTIMES rows of n frames) and the best of the wall times, the device. */
static void print_line(const render_gpu *g, const cli_opts *o, const render_cam *cam,
                       const render_stats *s, unsigned culled, double *t)
{
    printf("model=%s method=%s%s orientation=%s tess=%g size=%ux%u frames=%u patches=%u culled=%u "
           "tcs_patches=%llu tes_invocations=%llu clip_primitives=%llu",
           o->model, o->method_name, o->flip_alpha ? "+flip-alpha" : "", o->inward ? "in" : "out",
           o->tess, g->w, g->h,
           o->frames, g->npatches, culled, (unsigned long long)s->tcs_patches,
           (unsigned long long)s->tes_invocations, (unsigned long long)s->clip_primitives);
    for (int k = 0; k < MAIN_NTIMES; k++)
        printf(" %s=%.3f", time_keys[k], median(t + k * o->frames, o->frames));
    for (int k = 3; k < 6; k++) /* the best wall times: median() sorted the row */
        printf(" %.*s_min_ms=%.3f", (int)strlen(time_keys[k]) - 3, time_keys[k],
               t[k * o->frames]);
    printf(" alpha=%.9g device=", cam->alpha);
    for (const char *c = g->vk.props.deviceName; *c; c++)
        putchar(*c == ' ' ? '_' : *c);
    printf("(%s)\n", vkx_type_name(g->vk.props.deviceType));
}

/* Runs the frames, then writes what was asked and prints the line. */
static int run(render_gpu *g, const cli_opts *o, const render_cam *cam, const render_cam *ov,
               char *err)
{
    double *t = malloc(MAIN_NTIMES * o->frames * sizeof *t), ft[MAIN_NTIMES];
    render_stats s;
    unsigned culled = 0;
    const uint32_t *cls = g->cls.map;
    if (!t)
        return vkx_fail(err, "out of memory");
    for (unsigned f = 0; f < o->frames; f++) {
        if (render_frame(g, cam, ov, (float)o->tess, 0, &s, err)) {
            free(t);
            return -1;
        }
        times_of(&s, ft);
        for (int k = 0; k < MAIN_NTIMES; k++)
            t[k * o->frames + f] = ft[k];
    }
    for (uint32_t p = 0; p < g->npatches; p++)
        culled += cls[p] == 1;
    if ((o->png && png_write(o->png, g->pixels.map, g->w, g->h, err, VKX_ERRSZ)) ||
        (o->dump && dump(g, cam, o->dump, err))) {
        free(t);
        return -1;
    }
    print_line(g, o, cam, &s, culled, t);
    free(t);
    if (o->overview && (render_frame(g, cam, ov, (float)o->tess, 1, &s, err) ||
                        png_write(o->overview, g->pixels.map, g->w, g->h, err, VKX_ERRSZ)))
        return -1;
    return 0;
}

/* The cones of the cone methods (NULL otherwise, and on failure with a message). */
static float *cones(const cli_opts *o, const bez_model *m, char *err)
{
    float *c;
    if (o->method != RENDER_TCONE && o->method != RENDER_NCONE)
        return NULL;
    if (!(c = malloc(m->npatches * 8 * sizeof *c)) || conedata_fill(c, m, o->method, o->inward)) {
        free(c);
        vkx_fail(err, "cannot compute the cones of %s", o->model);
        return NULL;
    }
    return c;
}

int main(int argc, char **argv)
{
    cli_opts o;
    char err[VKX_ERRSZ];
    bez_model m;
    render_gpu g;
    render_cam cam, ov;
    float *cd = NULL;
    int rc;
    memset(&g, 0, sizeof g);
    if ((rc = cli_parse(&o, argc, argv, err, sizeof err)) != 0) {
        if (rc == 2)
            fprintf(stderr, "render: %s\n", err);
        return rc == 1 ? 0 : 2;
    }
    if (bez_read(&m, o.model, err, sizeof err)) {
        fprintf(stderr, "render: %s\n", err);
        return 1;
    }
    rc = 1;
    g.w = o.w;
    g.h = o.h;
    g.method = o.method;
    g.inward = o.inward;
    if (cameras(&o, &m, &cam, &ov, err) ||
        ((o.method == RENDER_TCONE || o.method == RENDER_NCONE) && !(cd = cones(&o, &m, err))) ||
        vkx_open(&g.vk, o.device, err) || render_resources(&g, &m, cd, err) ||
        render_pipelines(&g, err) || run(&g, &o, &cam, &ov, err))
        fprintf(stderr, "render: %s\n", err);
    else
        rc = 0;
    render_destroy(&g);
    free(cd);
    bez_free(&m);
    return rc;
}
