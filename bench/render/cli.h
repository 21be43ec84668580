/* cli.h: the renderer's command line: options, their defaults and their checks. */
#ifndef RENDER_CLI_H
#define RENDER_CLI_H

#include "render.h"

/* Everything the command line sets. */
typedef struct cli_opts {
    const char *model, *png, *overview, *dump;
    double eye[3], target[3], up[3];
    int has_eye, has_target;
    double fov;                /* degrees, vertical */
    double tess;               /* the uniform tessellation factor, 1 to 64 */
    render_method method;
    const char *method_name;
    unsigned w, h, frames;
    int device;                /* -1: choose */
    int inward;                /* --orientation in: dB/dv x dB/du faces out (the Utah teapot) */
    int flip_alpha;            /* debug: negate the kernels' alpha (a broken cull pass) */
} cli_opts;

/* Parses argv into *o. Returns 0, 1 for --help (usage printed), or 2 with a message in err
 * (size errsz) for a usage error: an unknown option, a missing or malformed value. */
int cli_parse(cli_opts *o, int argc, char **argv, char *err, size_t errsz);

#endif
