/* cli.c: parsing the renderer's options: numbers and vectors checked in full (no trailing
 * characters, finite, in range), every option named in its error. */
#include "cli.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char usage[] =
    "usage: render --model FILE.bez --eye X,Y,Z [--target X,Y,Z] [--up X,Y,Z] [--fov DEG]\n"
    "              --tess F --cull none|tcone|ncone|ptp|ptp-certified|ptp-table|ptp-tcs\n"
    "                              |ptp-tcs-certified\n"
    "              [--orientation out|in] [--size WxH] [--frames K] [--png FILE]\n"
    "              [--overview FILE.png] [--dump-clip FILE] [--device N]\n";

static const char *const method_names[] = {"none",          "tcone",     "ncone",   "ptp",
                                           "ptp-certified", "ptp-table", "ptp-tcs", "ptp-tcs-certified"};

/* Parses the whole of s as n comma-separated finite doubles into v. */
static int parse_doubles(const char *s, double *v, int n)
{
    char *end;
    for (int i = 0; i < n; i++) {
        errno = 0;
        v[i] = strtod(s, &end);
        if (end == s || errno || !isfinite(v[i]))
            return -1;
        s = end;
        if (i + 1 < n && *s++ != ',')
            return -1;
    }
    return *s ? -1 : 0;
}

/* Parses the whole of s as an unsigned long in [lo, hi]. */
static int parse_ulong(const char *s, unsigned long lo, unsigned long hi, unsigned *v)
{
    char *end;
    unsigned long x;
    errno = 0;
    if (*s < '0' || *s > '9')
        return -1;
    x = strtoul(s, &end, 10);
    if (*end || errno || x < lo || x > hi)
        return -1;
    *v = (unsigned)x;
    return 0;
}

static int parse_method(cli_opts *o, const char *s)
{
    for (int i = 0; i < (int)(sizeof method_names / sizeof *method_names); i++)
        if (!strcmp(s, method_names[i])) {
            o->method = (render_method)i;
            o->method_name = method_names[i];
            return 0;
        }
    return -1;
}

static const char *const option_names[] = {
    "--model", "--eye", "--target", "--up", "--fov", "--tess", "--cull", "--orientation",
    "--size", "--frames", "--png", "--overview", "--dump-clip", "--device"};

/* The value of one option (name, its argument s) into o: 0, or -1 when s is malformed, -2 for
 * an unknown option, -3 for a missing argument (s NULL). */
static int option(cli_opts *o, const char *name, const char *s)
{
    unsigned dev;
    size_t known = 0;
    while (known < sizeof option_names / sizeof *option_names && strcmp(name, option_names[known]))
        known++;
    if (known == sizeof option_names / sizeof *option_names)
        return -2;
    if (!s)
        return -3;
    if (!strcmp(name, "--model"))
        o->model = s;
    else if (!strcmp(name, "--eye"))
        return o->has_eye = 1, parse_doubles(s, o->eye, 3);
    else if (!strcmp(name, "--target"))
        return o->has_target = 1, parse_doubles(s, o->target, 3);
    else if (!strcmp(name, "--up"))
        return parse_doubles(s, o->up, 3);
    else if (!strcmp(name, "--fov"))
        return parse_doubles(s, &o->fov, 1) || !(o->fov > 0 && o->fov < 179) ? -1 : 0;
    else if (!strcmp(name, "--tess"))
        return parse_doubles(s, &o->tess, 1) || !(o->tess >= 1 && o->tess <= 64) ? -1 : 0;
    else if (!strcmp(name, "--cull"))
        return parse_method(o, s);
    else if (!strcmp(name, "--size")) {
        char w[16];
        const char *x = strchr(s, 'x');
        if (!x || x - s >= (long)sizeof w)
            return -1;
        memcpy(w, s, (size_t)(x - s));
        w[x - s] = '\0';
        return parse_ulong(w, 1, 8192, &o->w) || parse_ulong(x + 1, 1, 8192, &o->h) ? -1 : 0;
    } else if (!strcmp(name, "--frames"))
        return parse_ulong(s, 1, 10000, &o->frames);
    else if (!strcmp(name, "--orientation")) {
        o->inward = !strcmp(s, "in");
        return o->inward || !strcmp(s, "out") ? 0 : -1;
    } else if (!strcmp(name, "--png"))
        o->png = s;
    else if (!strcmp(name, "--overview"))
        o->overview = s;
    else if (!strcmp(name, "--dump-clip"))
        o->dump = s;
    else /* --device */
        return parse_ulong(s, 0, 1000, &dev) ? -1 : (o->device = (int)dev, 0);
    return 0;
}

static void defaults(cli_opts *o)
{
    memset(o, 0, sizeof *o);
    o->up[1] = 1;
    o->fov = 40;
    o->tess = -1;
    o->method = RENDER_NONE;
    o->w = o->h = 512;
    o->frames = 3;
    o->device = -1;
}

int cli_parse(cli_opts *o, int argc, char **argv, char *err, size_t errsz)
{
    defaults(o);
    for (int i = 1; i < argc; i++) {
        int r;
        if (!strcmp(argv[i], "-h") || !strcmp(argv[i], "--help")) {
            fputs(usage, stdout);
            return 1;
        }
        if (!strcmp(argv[i], "--flip-alpha")) {
            o->flip_alpha = 1;
            continue;
        }
        r = option(o, argv[i], i + 1 < argc ? argv[i + 1] : NULL);
        if (r == -2 || r == -3) {
            snprintf(err, errsz, r == -2 ? "unknown option %s" : "option %s needs a value",
                     argv[i]);
            return 2;
        }
        if (r) {
            snprintf(err, errsz, "bad value for %s: '%s'", argv[i], argv[i + 1]);
            return 2;
        }
        i++;
    }
    if (!o->model || !o->has_eye || o->tess < 0 || !o->method_name) {
        snprintf(err, errsz, "--model, --eye, --tess and --cull are required");
        return 2;
    }
    return 0;
}
