/* main.c: the ptpgen command: parse, derive, render, write.
 * The only place that prints errors and exits; output reaches -o only complete (temp + rename). */
#define _POSIX_C_SOURCE 200809L
#include "cli.h"
#include "kern.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* Writes b to stdout, or to path: a regular file atomically (a temporary file beside it,
 * then rename), a device or pipe directly. */
static int write_output(const char *path, const sbuf *b, ptp_error *err)
{
    char tmp[4096];
    FILE *f;
    mode_t mask;
    int fd;
    struct stat st;
    if (!path) {
        if (fwrite(b->s, 1, b->len, stdout) != b->len || fflush(stdout) != 0)
            return ptp_fail(err, PTP_EIO, "cannot write standard output: %s", strerror(errno));
        return PTP_OK;
    }
    if (stat(path, &st) == 0 && !S_ISREG(st.st_mode) && !S_ISDIR(st.st_mode)) {
        /* A device or pipe (-o /dev/null) is written in place: renaming over it would replace it. */
        int bad;
        if (!(f = fopen(path, "wb")))
            return ptp_fail(err, PTP_EIO, "cannot write %s: %s", path, strerror(errno));
        bad = fwrite(b->s, 1, b->len, f) != b->len;
        if (fclose(f) != 0 || bad)
            return ptp_fail(err, PTP_EIO, "cannot write %s: %s", path, strerror(errno));
        return PTP_OK;
    }
    if (snprintf(tmp, sizeof tmp, "%s.tmp-XXXXXX", path) >= (int)sizeof tmp)
        return ptp_fail(err, PTP_EIO, "cannot write %s: path too long", path);
    if ((fd = mkstemp(tmp)) < 0)
        return ptp_fail(err, PTP_EIO, "cannot write %s: %s", path, strerror(errno));
    if (!(f = fdopen(fd, "wb"))) {
        close(fd);
        unlink(tmp);
        return ptp_fail(err, PTP_EIO, "cannot write %s: %s", path, strerror(errno));
    }
    mask = umask(0); /* mkstemp makes 0600; give the file the mode fopen would */
    umask(mask);
    if (fchmod(fd, 0666 & ~mask) != 0 || fwrite(b->s, 1, b->len, f) != b->len || fclose(f) != 0) {
        int e = errno;
        unlink(tmp);
        return ptp_fail(err, PTP_EIO, "cannot write %s: %s", path, strerror(e));
    }
    if (rename(tmp, path) != 0) {
        int e = errno;
        unlink(tmp);
        return ptp_fail(err, PTP_EIO, "cannot write %s: %s", path, strerror(e));
    }
    return PTP_OK;
}

static int run(const cli_options *o, ptp_error *err)
{
    static int (*const render[])(sbuf *, const tp_table *, const out_info *, ptp_error *) = {
        out_json, out_table, out_stats, emit_c, emit_glsl, emit_hlsl, emit_opencl, emit_cuda};
    out_info info;
    tp_table t;
    sched s;
    sbuf b;
    int st, P, Q;
    if ((st = tp_derive(&t, o->n, o->m, err)))
        return st;
    P = o->threads >= 0 ? o->threads : sched_default_threads(&t);
    Q = o->patches >= 0 ? o->patches : sched_default_patches(P);
    if ((st = sched_build(&s, &t, P, Q, err))) {
        tp_clear(&t);
        return st;
    }
    info.command = o->command;
    info.prefix = o->prefix;
    info.sched = &s;
    info.space = o->world ? OUT_WORLD : OUT_CLIP;
    info.rule = o->degenerate ? OUT_DEGENERATE : OUT_STRICT;
    info.planes = o->planes;
    sbuf_init(&b);
    if (!(st = render[o->target](&b, &t, &info, err)))
        st = write_output(o->output, &b, err);
    sbuf_clear(&b);
    sched_clear(&s);
    tp_clear(&t);
    return st;
}

int main(int argc, char **argv)
{
    cli_options o;
    ptp_error err;
    int st = cli_parse(&o, argc, argv, &err);
    if (!st && o.help) {
        fputs(cli_usage, stdout);
        return 0;
    }
    if (!st && o.version) {
        printf("ptpgen %s\n", PTP_VERSION);
        return 0;
    }
    if (!st)
        st = run(&o, &err);
    if (st) {
        fprintf(stderr, "ptpgen: %s\n", err.msg);
        return st == PTP_EUSAGE ? 2 : 1;
    }
    return 0;
}
