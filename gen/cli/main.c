/* main.c: the ptpgen command: parse, then generate, verify or write vectors, and write.
 * The only place that prints errors and exits; output reaches -o only complete (temp + rename). */
#define _POSIX_C_SOURCE 200809L
#include "cli/cli.h"
#include "emit/targets.h"
#include "tools/vectors.h"
#include "tools/verify.h"

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

/* Reads the whole file at path ("-": standard input) into *text (NUL-terminated). */
static int read_input(char **text, size_t *len, const char *path, ptp_error *err)
{
    FILE *f = strcmp(path, "-") == 0 ? stdin : fopen(path, "rb");
    size_t cap = 1 << 16;
    char *buf = NULL, *grown;
    *len = 0;
    if (!f)
        return ptp_fail(err, PTP_EUSAGE, "cannot read %s: %s", path, strerror(errno));
    for (;;) {
        if (!(grown = realloc(buf, cap + 1))) {
            free(buf);
            if (f != stdin)
                fclose(f);
            return ptp_fail(err, PTP_ENOMEM, "out of memory reading %s", path);
        }
        buf = grown;
        *len += fread(buf + *len, 1, cap - *len, f);
        if (*len < cap)
            break;
        cap *= 2;
    }
    if (ferror(f)) {
        free(buf);
        if (f != stdin)
            fclose(f);
        return ptp_fail(err, PTP_EUSAGE, "cannot read %s: %s", path, strerror(errno));
    }
    if (f != stdin)
        fclose(f);
    buf[*len] = '\0';
    *text = buf;
    return PTP_OK;
}

/* ptpgen verify: the report goes to the output; *verdict is VERIFY_RIGHT or VERIFY_WRONG. */
static int run_verify(const cli_options *o, int *verdict, ptp_error *err)
{
    char *text = NULL;
    size_t len;
    sbuf b;
    int st = read_input(&text, &len, o->input, err);
    if (st)
        return st;
    sbuf_init(&b);
    if (!(st = verify_table(&b, verdict, text, len, o->input,
                             o->kind_given ? (int)o->kind : VERIFY_KIND_ANY, o->dom.n, o->dom.m,
                             o->vfirst ? VERIFY_V_FIRST : VERIFY_U_FIRST, err)))
        st = write_output(o->output, &b, err);
    sbuf_clear(&b);
    free(text);
    return st;
}

/* ptpgen vectors. */
static int run_vectors(const cli_options *o, ptp_error *err)
{
    tp_table t;
    sbuf b;
    int st = tp_derive_domain(&t, &o->dom, err);
    if (st)
        return st;
    sbuf_init(&b);
    if (!(st = vectors_write(&b, &t, o->count, o->seed, o->world ? OUT_WORLD : OUT_CLIP,
                             o->format_c ? VECTORS_C : VECTORS_JSON, o->command, err)))
        st = write_output(o->output, &b, err);
    sbuf_clear(&b);
    tp_clear(&t);
    return st;
}

static int run(const cli_options *o, ptp_error *err)
{
    out_info info = {0};
    tp_table t;
    sched s;
    sbuf b, h;
    int st, P, Q;
    if ((st = tp_derive_domain(&t, &o->dom, err)))
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
    info.certified = o->certified;
    info.absolute = o->absolute;
    info.bspline = o->bspline;
    info.vmajor = o->vmajor;
    info.refine = o->refine;
    info.table = o->table;
    info.functions = o->functions;
    info.indexed = o->indexed;
    info.lanes = o->lanes;
    if (o->target->options & TGT_KERNEL) /* the GPU targets */
        info.group = o->patches >= 0 ? o->patches : OUT_SLP_GROUP;
    sbuf_init(&b);
    sbuf_init(&h);
    st = tgt_emit_target(&b, o->target, &t, &info, err);
    if (!st && o->host_header) { /* both in memory before either file is written */
        info.suffix = o->target->suffix;
        st = hh_write(&h, &t, &info, o->target->gpu, &b, err);
    }
    if (!st && o->host_header)
        st = write_output(o->host_header, &h, err);
    if (!st)
        st = write_output(o->output, &b, err);
    sbuf_clear(&h);
    sbuf_clear(&b);
    sched_clear(&s);
    tp_clear(&t);
    return st;
}

/* --help, --list-targets or --version (in that order of precedence): its text to standard output. */
static int run_info(const cli_options *o, ptp_error *err)
{
    sbuf b;
    int st;
    sbuf_init(&b);
    if (o->help)
        cli_usage_command(&b, o->mode);
    else if (o->list)
        tgt_write_list(&b);
    else
        sbuf_printf(&b, "ptpgen %s\n", PTP_VERSION);
    st = write_output(NULL, &b, err);
    sbuf_clear(&b);
    return st;
}

int main(int argc, char **argv)
{
    cli_options o;
    ptp_error err;
    int st = cli_parse(&o, argc, argv, &err);
    if (!st && (o.help || o.list || o.version)) {
        st = run_info(&o, &err);
    } else if (!st && o.mode == CLI_VERIFY) {
        /* exit 0 right, 1 wrong, 2 when the input cannot be read */
        int verdict = VERIFY_WRONG;
        if (!(st = run_verify(&o, &verdict, &err)))
            return verdict == VERIFY_RIGHT ? 0 : 1;
    } else if (!st) {
        st = o.mode == CLI_VECTORS ? run_vectors(&o, &err) : run(&o, &err);
    }
    if (st) {
        fprintf(stderr, "ptpgen: %s\n", err.msg);
        return st == PTP_EUSAGE ? 2 : 1;
    }
    return 0;
}
