/* cli.c: parses and validates ptpgen's options.
 * Accepts "--opt value" and "--opt=value", each option once and only where it applies. */
#include "cli/cli.h"

#include "plan/sched.h"

#include <ctype.h>
#include <stdio.h>
#include <string.h>

/* Appends the --target lines: one per run of targets with the same description. */
static void usage_targets(sbuf *o)
{
    int i, k;
    for (i = 0; i < tgt_count; i = k) {
        sbuf_puts(o, i == 0 ? "  --target T       " : "                   ");
        for (k = i; k < tgt_count &&
                    strcmp(tgt_targets[k].description, tgt_targets[i].description) == 0; k++)
            sbuf_printf(o, "%s%s", k == i ? "" : ", ", tgt_targets[k].name);
        sbuf_printf(o, "%s: %s\n", i == 0 ? " (default)" : "", tgt_targets[i].description);
    }
}

/* The synopsis of every command and what ptpgen derives. */
static void usage_synopsis(sbuf *o)
{
    sbuf_puts(o,
        "usage: ptpgen --degree N|NxM [--domain quad|triangle] [--target T] [--space clip|world]\n"
        "              [--rule strict|degenerate] [--coordinates local|absolute] [--planes]\n"
        "              [--basis bezier|bspline] [--order u-major|v-major] [--certified]\n"
        "              [--refine K] [--prefix NAME] [--kernel slp|table|indexed|lanes]\n"
        "              [--stage kernel|function] [--threads-per-patch P]\n"
        "              [--patches-per-block Q] [-o FILE] [--host-header FILE]\n"
        "       ptpgen verify FILE [--degree N|NxM] [--domain quad|triangle]\n"
        "              [--convention u-first|v-first] [-o REPORT]\n"
        "       ptpgen vectors --degree NxM [--domain quad|triangle] --count K --seed S\n"
        "              [--space clip|world] [--format json|c] [-o FILE]\n"
        "       ptpgen --help | help [verify|vectors] | --version | --list-targets\n"
        "\n"
        "Derives the exact control planes of the parametric tangent plane\n"
        "T = cross4(B, dB/du, dB/dv) of a Bezier patch of bidegree NxM (N along u) or of a\n"
        "triangular Bezier patch of degree N, and writes them, or a back-patch culling kernel\n"
        "built on them.\n"
        "\n");
}

/* The options, one or more lines each, the targets' from the registry. */
static void usage_options(sbuf *o)
{
    sbuf_puts(o,
        "  --domain D       quad (default): tensor-product patches; triangle: triangular\n"
        "                   patches (every target and option)\n");
    sbuf_printf(o, "  --degree N|NxM   patch bidegree, 1 <= N, M <= %d (N alone means NxN);\n"
                   "                   triangles: the degree N, 1 <= N <= %d\n",
                PTP_MAX_DEGREE, PTP_MAX_TRI_DEGREE);
    usage_targets(o);
    sbuf_printf(o,
        "  --space S        clip (default): points in clip space, eye (0, 0, alpha, 0);\n"
        "                   world: the full planes dotted with a homogeneous eye point\n"
        "  --rule R         strict (default): back iff all values < 0, front iff all > 0;\n"
        "                   degenerate: back iff none > 0, front iff none < 0\n"
        "  --coordinates C  C and GPU code: local (default): each patch moved to its first\n"
        "                   control point's origin before the planes (exact up to one\n"
        "                   rounding a coordinate); absolute: as given (WGSL's certified\n"
        "                   table kernel reads them as given always)\n"
        "  --basis B        C and the straight-line GPU code: bezier (default): Bezier control\n"
        "                   points; bspline: the 16 control vertices of a uniform bicubic\n"
        "                   B-spline patch (--degree 3), converted in registers\n"
        "  --order O        C and the straight-line GPU code: u-major (default): point (i, j),\n"
        "                   i along u, at i*(M+1)+j; v-major: at j*(N+1)+i (OpenSubdiv's order)\n"
        "  --planes         kernels also write the value of every plane\n"
        "  --certified      call a patch back or front only when every value clears a rigorous\n"
        "                   bound on its float rounding error (README: Certified classification)\n"
        "  --refine K       C only: split the patch's scalar Bezier function e.T by de Casteljau,\n"
        "                   up to K levels (1 to %d), while its control values have mixed signs\n"
        "                   (quads into quarters, triangles at their edge midpoints); with\n"
        "                   --certified in double, every value with a bound on its error\n"
        "  --prefix NAME    prefix of generated names (default ptp_NxM_ or ptp_triN_, then world_,\n"
        "                   degenerate_, bspline_, vmajor_, absolute_, certified_, refineK_ for\n"
        "                   the options given); a _ is appended when NAME does not end in one\n",
        CLI_MAX_REFINE);
    sbuf_printf(o,
        "  --kernel K       GPU targets: slp (default): one patch an invocation, the\n"
        "                   straight-line program (--certified: a second look in double-\n"
        "                   float in OpenCL and CUDA, none in GLSL and HLSL; WGSL's\n"
        "                   --certified code is the table kernel); table: the paper's kernel, P\n"
        "                   threads a patch over the term table, with a second look in\n"
        "                   double-float; indexed: slp's, reading each patch's points from a\n"
        "                   vertex buffer through K indices a patch (--basis bspline: and\n"
        "                   OpenSubdiv's boundary masks); lanes (OpenCL, for CPU devices):\n"
        "                   16 patches a work-item in float16 vectors, plain float\n"
        "  --stage S        GPU targets: kernel (default): a compute kernel; function: only\n"
        "                   the functions classify_patch and values, for any shader stage\n"
        "                   (tessellation control or hull, mesh, task, compute)\n"
        "  --threads-per-patch P\n"
        "                   json, table, stats and --kernel table: threads that share one\n"
        "                   patch, 1..%d, at most the number of planes (default 16 for 3x3;\n"
        "                   see README for other degrees)\n"
        "  --patches-per-block Q\n"
        "                   patches per thread block (default %d/P, at least 1; the\n"
        "                   straight-line kernel: Q invocations, default %d)\n"
        "  --convention C   verify: the table's index convention: u-first (default, ptpgen's):\n"
        "                   point (i, j) is i*(M+1)+j, plane (I, J) is I*(3M-1)+J; v-first:\n"
        "                   point j*(N+1)+i, plane J*(3N-1)+I (triangles: (i, j) numbered as\n"
        "                   u-first numbers (j, i))\n"
        "  --count K        vectors: the number of cases, 1 to %d\n"
        "  --seed S         vectors: the seed of their random stream, 0 to 2^64 - 1\n"
        "  --format F       vectors: json (default) or c (a C include of the same vectors)\n"
        "  -o, --output F   write to F (atomically) instead of standard output\n"
        "  --host-header F  GPU compute kernels: also write F (atomically), a C/C++ header for the\n"
        "                   host: parameter struct, binding slots, workgroup size, dispatch\n"
        "                   function and the kernel's source (docs/gpu-hosts.md)\n"
        "  -h, --help       show this help\n"
        "  --version        show the version\n"
        "  --list-targets   list the targets, one a line: name, file suffix (- for none),\n"
        "                   the options it uses (comma-separated, - for none), description\n"
        "\n",
        SCHED_MAX_THREADS, SCHED_BLOCK_THREADS, OUT_SLP_GROUP, CLI_MAX_COUNT);
}

void cli_usage(sbuf *o)
{
    usage_synopsis(o);
    usage_options(o);
    sbuf_puts(o,
        "verify checks a table (the paper's idx/wgt C header with its iwgt, owner and sched_\n"
        "arrays, or ptpgen's json) against the exact derivation, names each problem with its\n"
        "line and lists what it checked and ignored: exit 0 right, 1 wrong, 2 unreadable.\n"
        "Code (such as the straight-line C header) cannot be checked from its text: run it on\n"
        "the vectors. vectors writes K random patches (small integers) with their exact plane\n"
        "values and classes under both rules, as JSON or a C include; the same seed gives the\n"
        "same bytes.\n"
        "\n"
        "Exit status: 0 success, 1 failure, 2 usage error.\n");
}

void cli_usage_command(sbuf *o, cli_mode mode)
{
    if (mode == CLI_VERIFY)
        sbuf_puts(o,
            "usage: ptpgen verify FILE [--degree N|NxM] [--domain quad|triangle]\n"
            "              [--convention u-first|v-first] [-o REPORT]\n"
            "\n"
            "verify checks a table (the paper's idx/wgt C header with its iwgt, owner and sched_\n"
            "arrays, or ptpgen's json) against the exact derivation, names each problem with its\n"
            "line and lists what it checked and ignored: exit 0 right, 1 wrong, 2 unreadable.\n"
            "--degree and --domain name the patch when the file does not; --convention u-first\n"
            "(default) or v-first is the table's index convention (ptpgen --help).\n");
    else if (mode == CLI_VECTORS)
        sbuf_puts(o,
            "usage: ptpgen vectors --degree NxM [--domain quad|triangle] --count K --seed S\n"
            "              [--space clip|world] [--format json|c] [-o FILE]\n"
            "\n"
            "vectors writes K random patches (small integers) with their exact plane values and\n"
            "classes under both rules, as JSON (--format json, default) or a C include\n"
            "(--format c); the same seed gives the same bytes.\n");
    else
        cli_usage(o);
}

/* Sets *v to the index of arg in names[0..n-1]; a usage error naming the choices otherwise. */
static int parse_choice(int *v, const char *opt, const char *arg, const char *const *names, int n,
                        ptp_error *err)
{
    char choices[128] = "";
    int i;
    for (i = 0; i < n; i++) {
        if (strcmp(arg, names[i]) == 0) {
            *v = i;
            return PTP_OK;
        }
        snprintf(choices + strlen(choices), sizeof choices - strlen(choices), "%s%s",
                 i == 0 ? "" : i == n - 1 ? " or " : ", ", names[i]);
    }
    return ptp_fail(err, PTP_EUSAGE, "unknown %s '%s' (expected %s)", opt, arg, choices);
}

/* A prefix is a C identifier start: a letter or '_', then letters, digits and '_'; a '_' is
 * appended when it does not end in one. */
static int parse_prefix(cli_options *o, const char *arg, ptp_error *err)
{
    size_t i, n = strlen(arg);
    int ok = n > 0 && n < sizeof o->prefix - 1 && (isalpha((unsigned char)arg[0]) || arg[0] == '_');
    for (i = 1; ok && i < n; i++)
        ok = isalnum((unsigned char)arg[i]) || arg[i] == '_';
    if (!ok)
        return ptp_fail(err, PTP_EUSAGE,
                        "--prefix '%s': expected an identifier prefix (letters, digits and _, not "
                        "starting with a digit, at most %zu characters)",
                        arg, sizeof o->prefix - 2);
    strcpy(o->prefix, arg);
    if (arg[n - 1] != '_')
        strcpy(o->prefix + n, "_");
    return PTP_OK;
}

/* Parses an unsigned decimal number up to max into *v (digits only). */
static int parse_ulong(uint64_t *v, const char *opt, const char *arg, uint64_t max, ptp_error *err)
{
    const char *p = arg;
    uint64_t x = 0;
    for (; *p >= '0' && *p <= '9'; p++) {
        uint64_t d = (uint64_t)(*p - '0');
        if (d > max || x > (max - d) / 10)
            return ptp_fail(err, PTP_EUSAGE, "%s '%s': the largest allowed is %llu", opt, arg,
                            (unsigned long long)max);
        x = x * 10 + d;
    }
    if (p == arg || *p != '\0')
        return ptp_fail(err, PTP_EUSAGE, "%s '%s': expected a whole number", opt, arg);
    *v = x;
    return PTP_OK;
}

/* Parses a thread or patch count up to SCHED_MAX_THREADS (digits only) into *v; zero is left
 * to the scheduler's range check, which names the lower limit. */
static int parse_count(int *v, const char *opt, const char *arg, ptp_error *err)
{
    uint64_t x = 0;
    int st = parse_ulong(&x, opt, arg, SCHED_MAX_THREADS, err);
    if (st == PTP_OK)
        *v = (int)x;
    return st;
}

/* The options, in the order the mode check names them. */
typedef enum {
    OPT_DEGREE, OPT_DOMAIN, OPT_TARGET, OPT_SPACE, OPT_RULE, OPT_PLANES, OPT_PREFIX, OPT_THREADS,
    OPT_PATCHES, OPT_COUNT, OPT_SEED, OPT_CERTIFIED, OPT_REFINE, OPT_CONVENTION, OPT_FORMAT,
    OPT_OUTPUT, OPT_HELP,
    OPT_VERSION, OPT_LIST, OPT_KERNEL, OPT_STAGE, OPT_HOST_HEADER, OPT_COORDINATES, OPT_BASIS,
    OPT_ORDER, OPT_N
} opt_id;

/* The modes an option belongs to, as bits 1 << cli_mode. */
#define GEN (1u << CLI_GENERATE)
#define VER (1u << CLI_VERIFY)
#define VEC (1u << CLI_VECTORS)

static const struct {
    const char *name;  /* "--output"; "--name=value" is accepted too when it takes a value */
    const char *alias; /* "-o", or NULL */
    int arg;           /* it takes a value */
    unsigned modes;    /* the modes it belongs to */
    unsigned target;   /* the TGT_ bit a target needs for it, 0 for every target */
} opts[OPT_N] = {
    [OPT_DEGREE] = {"--degree", NULL, 1, GEN | VER | VEC, 0},
    [OPT_DOMAIN] = {"--domain", NULL, 1, GEN | VER | VEC, 0},
    [OPT_TARGET] = {"--target", NULL, 1, GEN, 0},
    [OPT_SPACE] = {"--space", NULL, 1, GEN | VEC, TGT_SPACE},
    [OPT_RULE] = {"--rule", NULL, 1, GEN, TGT_RULE},
    [OPT_PLANES] = {"--planes", NULL, 0, GEN, TGT_PLANES},
    [OPT_PREFIX] = {"--prefix", NULL, 1, GEN, TGT_PREFIX},
    [OPT_THREADS] = {"--threads-per-patch", NULL, 1, GEN, TGT_SCHEDULE},
    [OPT_PATCHES] = {"--patches-per-block", NULL, 1, GEN, TGT_SCHEDULE},
    [OPT_COUNT] = {"--count", NULL, 1, VEC, 0},
    [OPT_SEED] = {"--seed", NULL, 1, VEC, 0},
    [OPT_CERTIFIED] = {"--certified", NULL, 0, GEN, TGT_CERTIFIED},
    [OPT_REFINE] = {"--refine", NULL, 1, GEN, TGT_REFINE},
    [OPT_CONVENTION] = {"--convention", NULL, 1, VER, 0},
    [OPT_FORMAT] = {"--format", NULL, 1, VEC, 0},
    [OPT_OUTPUT] = {"--output", "-o", 1, GEN | VER | VEC, 0},
    [OPT_HELP] = {"--help", "-h", 0, GEN | VER | VEC, 0},
    [OPT_VERSION] = {"--version", NULL, 0, GEN | VER | VEC, 0},
    [OPT_LIST] = {"--list-targets", NULL, 0, GEN | VER | VEC, 0},
    [OPT_KERNEL] = {"--kernel", NULL, 1, GEN, TGT_KERNEL},
    [OPT_STAGE] = {"--stage", NULL, 1, GEN, TGT_KERNEL},
    [OPT_HOST_HEADER] = {"--host-header", NULL, 1, GEN, TGT_KERNEL},
    [OPT_COORDINATES] = {"--coordinates", NULL, 1, GEN, TGT_SPACE},
    [OPT_BASIS] = {"--basis", NULL, 1, GEN, TGT_SPACE},
    [OPT_ORDER] = {"--order", NULL, 1, GEN, TGT_SPACE},
};

/* Finds the option argv[*i] names ("--name", its alias, or "--name=value" for one that takes a
 * value) and sets *val to its value (advancing *i past a separate one). Returns its opt_id,
 * -1 if argv[*i] is no option, or -2 with the usage error in err when the value is missing. */
static int match(const char **val, int argc, char **argv, int *i, ptp_error *err)
{
    const char *a = argv[*i];
    int k;
    for (k = 0; k < OPT_N; k++) {
        size_t n = strlen(opts[k].name);
        if (opts[k].arg && strncmp(a, opts[k].name, n) == 0 && a[n] == '=') {
            *val = a + n + 1;
            return k;
        }
        if (strcmp(a, opts[k].name) != 0 && !(opts[k].alias && strcmp(a, opts[k].alias) == 0))
            continue;
        if (opts[k].arg && *i + 1 >= argc) {
            ptp_fail(err, PTP_EUSAGE, "option %s needs an argument", a);
            return -2;
        }
        *val = opts[k].arg ? argv[++*i] : NULL;
        return k;
    }
    return -1;
}

/* Sets o->target to the registry's target named arg; a usage error naming them otherwise. */
static int parse_target(cli_options *o, const char *arg, ptp_error *err)
{
    char choices[128] = "";
    int i;
    if ((o->target = tgt_find(arg)))
        return PTP_OK;
    for (i = 0; i < tgt_count; i++)
        snprintf(choices + strlen(choices), sizeof choices - strlen(choices), "%s%s",
                 i == 0 ? "" : i == tgt_count - 1 ? " or " : ", ", tgt_targets[i].name);
    return ptp_fail(err, PTP_EUSAGE, "unknown target '%s' (expected %s)", arg, choices);
}

/* Sets the field of o that option k stands for from its value v (NULL for a flag). */
static int apply(cli_options *o, opt_id k, const char *v, ptp_error *err)
{
    static const char *const spaces[] = {"clip", "world"}, *const rules[] = {"strict", "degenerate"};
    static const char *const conventions[] = {"u-first", "v-first"}, *const formats[] = {"json", "c"};
    static const char *const kernels[] = {"slp", "table", "indexed", "lanes"};
    static const char *const stages[] = {"kernel", "function"};
    static const char *const coordinates[] = {"local", "absolute"}, *const bases[] = {"bezier", "bspline"};
    static const char *const orders[] = {"u-major", "v-major"};
    const char *kinds[] = {tp_kind_name(TP_QUAD), tp_kind_name(TP_TRI)};
    uint64_t u = 0;
    int st = PTP_OK, x = 0;
    switch (k) {
    case OPT_DEGREE: o->degree = v; break;
    case OPT_DOMAIN:
        if (!(st = parse_choice(&x, "domain", v, kinds, 2, err))) {
            o->kind = (tp_kind)x;
            o->kind_given = 1;
        }
        break;
    case OPT_TARGET: return parse_target(o, v, err);
    case OPT_SPACE: return parse_choice(&o->world, "space", v, spaces, 2, err);
    case OPT_RULE: return parse_choice(&o->degenerate, "rule", v, rules, 2, err);
    case OPT_PLANES: o->planes = 1; break;
    case OPT_PREFIX: return parse_prefix(o, v, err);
    case OPT_THREADS: return parse_count(&o->threads, "--threads-per-patch", v, err);
    case OPT_PATCHES: return parse_count(&o->patches, "--patches-per-block", v, err);
    case OPT_COUNT:
        if (!(st = parse_ulong(&u, "--count", v, CLI_MAX_COUNT, err)))
            o->count = (long)u;
        break;
    case OPT_SEED: return parse_ulong(&o->seed, "--seed", v, UINT64_MAX, err);
    case OPT_CERTIFIED: o->certified = 1; break;
    case OPT_REFINE:
        if (!(st = parse_ulong(&u, "--refine", v, CLI_MAX_REFINE, err)))
            o->refine = (int)u;
        break;
    case OPT_CONVENTION: return parse_choice(&o->vfirst, "convention", v, conventions, 2, err);
    case OPT_FORMAT: return parse_choice(&o->format_c, "format", v, formats, 2, err);
    case OPT_OUTPUT: o->output = v; break;
    case OPT_HELP: o->help = 1; break;
    case OPT_VERSION: o->version = 1; break;
    case OPT_LIST: o->list = 1; break;
    case OPT_KERNEL:
        if (!(st = parse_choice(&x, "kernel", v, kernels, 4, err))) {
            o->table = x == 1;
            o->indexed = x == 2;
            o->lanes = x == 3;
        }
        break;
    case OPT_COORDINATES: return parse_choice(&o->absolute, "coordinates", v, coordinates, 2, err);
    case OPT_BASIS: return parse_choice(&o->bspline, "basis", v, bases, 2, err);
    case OPT_ORDER: return parse_choice(&o->vmajor, "order", v, orders, 2, err);
    case OPT_STAGE: return parse_choice(&o->functions, "stage", v, stages, 2, err);
    case OPT_HOST_HEADER: o->host_header = v; break;
    case OPT_N: break;
    }
    return st;
}

/* "ptpgen help [verify|vectors]": sets o->help, and o->mode to the command asked about;
 * anything more is a usage error. */
static int parse_help(cli_options *o, int argc, char **argv, ptp_error *err)
{
    o->help = 1;
    if (argc == 2)
        return PTP_OK;
    if (argc == 3 && strcmp(argv[2], "verify") == 0)
        o->mode = CLI_VERIFY;
    else if (argc == 3 && strcmp(argv[2], "vectors") == 0)
        o->mode = CLI_VECTORS;
    else
        return ptp_fail(err, PTP_EUSAGE, "help takes verify, vectors or nothing, not '%s'",
                        argv[argc == 3 ? 2 : 3]);
    return PTP_OK;
}

/* Sets o->mode from the first word ("verify", "vectors", else generation); returns the index of
 * the first option. */
static int parse_mode(cli_options *o, int argc, char **argv)
{
    if (argc > 1 && strcmp(argv[1], "verify") == 0)
        o->mode = CLI_VERIFY;
    else if (argc > 1 && strcmp(argv[1], "vectors") == 0)
        o->mode = CLI_VECTORS;
    return o->mode == CLI_GENERATE ? 1 : 2;
}

/* Parses argv[first..argc-1] into o, recording each option given in *seen (bit opt_id); an
 * option given twice is an error. Stops at the first error. */
static int parse_args(cli_options *o, unsigned *seen, int first, int argc, char **argv,
                      ptp_error *err)
{
    int i, k, st = PTP_OK;
    for (i = first; i < argc && !st; i++) {
        const char *a = argv[i], *v = NULL;
        if ((k = match(&v, argc, argv, &i, err)) == -2)
            return PTP_EUSAGE;
        if (k >= 0 && *seen >> k & 1)
            st = ptp_fail(err, PTP_EUSAGE, "option %s is given twice", opts[k].name);
        else if (k >= 0) {
            *seen |= 1u << k;
            st = apply(o, (opt_id)k, v, err);
        } else if (o->mode == CLI_VERIFY && !o->input && (a[0] != '-' || a[1] == '\0'))
            o->input = a;
        else if (a[0] == '-')
            st = ptp_fail(err, PTP_EUSAGE, "unknown option '%s' (see ptpgen --help)", a);
        else
            st = ptp_fail(err, PTP_EUSAGE, "unexpected argument '%s' (see ptpgen --help)", a);
    }
    return st;
}

/* Checks that the options in seen belong to o's mode and its requirements are met. */
static int check_mode(const cli_options *o, unsigned seen, ptp_error *err)
{
    static const char *const modes[] = {"code generation", "verify", "vectors"};
    int k;
    for (k = 0; k < OPT_N; k++)
        if (seen >> k & 1 && !(opts[k].modes >> o->mode & 1))
            return ptp_fail(err, PTP_EUSAGE, "option %s does not apply to %s", opts[k].name,
                            modes[o->mode]);
    if (o->mode == CLI_VERIFY)
        return o->input ? PTP_OK
                        : ptp_fail(err, PTP_EUSAGE,
                                   "verify: missing the FILE to check (see ptpgen --help)");
    if (!o->dom.n)
        return ptp_fail(err, PTP_EUSAGE, "missing --degree N%s (see ptpgen --help)",
                        o->kind == TP_QUAD ? " or --degree NxM" : "");
    if (o->mode == CLI_VECTORS &&
        (!(seen >> OPT_COUNT & 1) || !(seen >> OPT_SEED & 1) || o->count < 1))
        return ptp_fail(err, PTP_EUSAGE, "vectors needs --count K (1 to %d) and --seed S",
                        CLI_MAX_COUNT);
    return PTP_OK;
}

/* Checks that every option in seen applies to o's target (its registry bit), else a usage error
 * naming the targets it applies to; and that the options go together. */
static int check_target(const cli_options *o, unsigned seen, ptp_error *err)
{
    char names[128] = "";
    int i, k, n = 0;
    for (k = 0; k < OPT_N; k++) {
        if (!(seen >> k & 1) || !opts[k].target || o->target->options & opts[k].target)
            continue;
        for (i = 0; i < tgt_count; i++)
            if (tgt_targets[i].options & opts[k].target)
                snprintf(names + strlen(names), sizeof names - strlen(names), "%s%s",
                         n++ ? ", " : "", tgt_targets[i].name);
        return ptp_fail(err, PTP_EUSAGE, "%s applies to target%s %s (not %s)", opts[k].name,
                        n == 1 ? "" : "s", names, o->target->name);
    }
    return PTP_OK;
}

/* --kernel lanes: the target's vectors, plain float, Bezier points, a whole number of vectors of
 * patches a workgroup; o->lanes becomes the vectors' width. */
static int check_lanes(cli_options *o, unsigned seen, ptp_error *err)
{
    const char *other = o->certified ? "--certified" : o->planes ? "--planes" : o->functions
                        ? "--stage function" : o->bspline ? "--basis bspline" : o->vmajor
                        ? "--order v-major" : NULL;
    int w = o->target->gpu->lanes ? o->target->gpu->lanes->width : 0, q = o->patches;
    if (!w)
        return ptp_fail(err, PTP_EUSAGE, "--kernel lanes is OpenCL's (float16 vectors for CPU "
                                         "devices), not %s's", o->target->name);
    if (other)
        return ptp_fail(err, PTP_EUSAGE, "--kernel lanes classifies Bezier patches in plain float: "
                                         "not with %s", other);
    if (seen >> OPT_PATCHES & 1 && q % w)
        return ptp_fail(err, PTP_EUSAGE, "--kernel lanes: --patches-per-block must be a multiple "
                                         "of %d (the vectors' width)", w);
    o->lanes = w;
    return PTP_OK;
}

/* The GPU targets' form: a --certified kernel is the straight-line one where the target certifies
 * it (the table kernel elsewhere, WGSL), and the options of one form do not go with the other. */
static int check_kernel(cli_options *o, unsigned seen, ptp_error *err)
{
    int st;
    if (!(o->target->options & TGT_KERNEL))
        return PTP_OK;
    if (o->certified && !o->functions && !(seen >> OPT_KERNEL & 1) && !o->target->gpu->slp_cert_u)
        o->table = 1;
    if (o->certified && !o->table && !o->target->gpu->slp_cert_u)
        return ptp_fail(err, PTP_EUSAGE, "--certified %s code is the table kernel (the language may "
                                         "reassociate the straight-line program's sums)",
                        o->target->name);
    if (o->certified && o->indexed)
        return ptp_fail(err, PTP_EUSAGE, "--kernel indexed is not certified (--kernel slp or table)");
    if (o->lanes && (st = check_lanes(o, seen, err)))
        return st;
    if (o->table && o->certified && seen >> OPT_COORDINATES & 1 && !o->target->gpu->slp_cert_u)
        return ptp_fail(err, PTP_EUSAGE, "--coordinates: %s's certified table kernel reads the "
                                         "coordinates as given (its terms read differences of "
                                         "points; the language may reassociate a shear)",
                        o->target->name);
    if (o->indexed && o->functions)
        return ptp_fail(err, PTP_EUSAGE, "--kernel indexed is a compute kernel; --stage function "
                                         "writes the functions alone (the caller gathers the points)");
    if (o->table && o->functions)
        return ptp_fail(err, PTP_EUSAGE, "--stage function writes the straight-line functions, not "
                                         "--kernel table");
    if (seen >> OPT_THREADS & 1 && !o->table)
        return ptp_fail(err, PTP_EUSAGE, "--threads-per-patch applies to --kernel table");
    if (o->functions && (o->planes || seen >> OPT_PATCHES & 1))
        return ptp_fail(err, PTP_EUSAGE, "%s applies to kernels (--stage function writes values "
                                         "always, and has no workgroup)",
                        o->planes ? "--planes" : "--patches-per-block");
    if (o->host_header && (o->functions || !o->host_header[0] ||
                           (o->output && strcmp(o->host_header, o->output) == 0)))
        return ptp_fail(err, PTP_EUSAGE, "--host-header %s", o->functions
                        ? "applies to compute kernels (--stage kernel), not --stage function"
                        : !o->host_header[0] ? "needs a file name"
                                             : "must name another file than -o");
    return PTP_OK;
}

/* The input's form: B-spline vertices are bicubic quads; both --basis bspline and --order v-major
 * are the straight-line program's, plain or certified in C (--refine and the table loop read
 * Bezier points, u-major). */
static int check_input(const cli_options *o, ptp_error *err)
{
    const char *what = o->bspline ? "--basis bspline" : "--order v-major";
    if (!o->bspline && !o->vmajor)
        return PTP_OK;
    if (o->dom.kind != TP_QUAD)
        return ptp_fail(err, PTP_EUSAGE, "%s applies to quads (--domain quad)", what);
    if (o->bspline && (o->dom.n != 3 || o->dom.m != 3))
        return ptp_fail(err, PTP_EUSAGE, "--basis bspline takes uniform bicubic B-spline patches "
                                         "(--degree 3)");
    if (o->certified && (o->target->options & TGT_KERNEL))
        return ptp_fail(err, PTP_EUSAGE, "%s with --certified is the C target's", what);
    if (o->refine || o->table)
        return ptp_fail(err, PTP_EUSAGE, "%s applies to the straight-line program, not %s (which "
                                         "reads Bezier points, u-major)", what,
                        o->refine ? "--refine" : "--kernel table");
    return PTP_OK;
}

/* Writes o->command, the normalized command line: every option that was given, in one order. */
static void put_command(cli_options *o)
{
    char *c = o->command, degree[16];
    size_t size = sizeof o->command;
    int n;
    tp_domain_format(degree, sizeof degree, &o->dom);
    if (o->mode == CLI_VECTORS) {
        snprintf(c, size, "ptpgen vectors%s%s --degree %s --count %ld --seed %llu --space %s%s",
                 o->kind ? " --domain " : "", o->kind ? tp_kind_name(o->kind) : "", degree,
                 o->count, (unsigned long long)o->seed, o->world ? "world" : "clip",
                 o->format_c ? " --format c" : "");
        return;
    }
    n = snprintf(c, size, "ptpgen%s%s --degree %s --target %s", o->kind ? " --domain " : "",
                 o->kind ? tp_kind_name(o->kind) : "", degree, o->target->name);
    if (o->world)
        n += snprintf(c + n, size - (size_t)n, " --space world");
    if (o->degenerate)
        n += snprintf(c + n, size - (size_t)n, " --rule degenerate");
    if (o->bspline)
        n += snprintf(c + n, size - (size_t)n, " --basis bspline");
    if (o->vmajor)
        n += snprintf(c + n, size - (size_t)n, " --order v-major");
    if (o->absolute)
        n += snprintf(c + n, size - (size_t)n, " --coordinates absolute");
    if (o->planes)
        n += snprintf(c + n, size - (size_t)n, " --planes");
    if (o->certified)
        n += snprintf(c + n, size - (size_t)n, " --certified");
    if (o->refine)
        n += snprintf(c + n, size - (size_t)n, " --refine %d", o->refine);
    if (o->prefix[0])
        n += snprintf(c + n, size - (size_t)n, " --prefix %s", o->prefix);
    if (o->threads >= 0)
        n += snprintf(c + n, size - (size_t)n, " --threads-per-patch %d", o->threads);
    if (o->patches >= 0)
        n += snprintf(c + n, size - (size_t)n, " --patches-per-block %d", o->patches);
    if (o->kernel_given)
        n += snprintf(c + n, size - (size_t)n, " --kernel %s",
                      o->table ? "table" : o->indexed ? "indexed" : o->lanes ? "lanes" : "slp");
    if (o->functions)
        snprintf(c + n, size - (size_t)n, " --stage function");
}

/* Writes the default prefix: the domain's ("ptp_3x3_") and, in this order, each option that
 * differs from its default: world_, degenerate_, bspline_, vmajor_, absolute_, certified_, refineK_
 * (ptp_3x3_world_certified_);
 * options a target does not take are refused before, so every target names its variant. */
static void put_default_prefix(cli_options *o)
{
    char *p = o->prefix;
    size_t size = sizeof o->prefix, n = strlen(tp_domain_prefix(p, size, &o->dom));
    if (o->world)
        n += (size_t)snprintf(p + n, size - n, "world_");
    if (o->degenerate)
        n += (size_t)snprintf(p + n, size - n, "degenerate_");
    if (o->bspline)
        n += (size_t)snprintf(p + n, size - n, "bspline_");
    if (o->vmajor)
        n += (size_t)snprintf(p + n, size - n, "vmajor_");
    if (o->absolute)
        n += (size_t)snprintf(p + n, size - n, "absolute_");
    if (o->certified)
        n += (size_t)snprintf(p + n, size - n, "certified_");
    if (o->refine)
        snprintf(p + n, size - n, "refine%d_", o->refine);
}

int cli_parse(cli_options *o, int argc, char **argv, ptp_error *err)
{
    unsigned seen = 0;
    int st;
    memset(o, 0, sizeof *o);
    o->threads = o->patches = -1;
    o->target = &tgt_targets[0];
    if (argc > 1 && strcmp(argv[1], "help") == 0)
        return parse_help(o, argc, argv, err);
    st = parse_args(o, &seen, parse_mode(o, argc, argv), argc, argv, err);
    if (st || o->help || o->version || o->list)
        return st;
    if (o->degree && (st = tp_domain_parse(&o->dom, o->kind, o->degree, err)))
        return st;
    if ((st = check_mode(o, seen, err)) || o->mode == CLI_VERIFY)
        return st;
    if (o->mode == CLI_GENERATE && ((st = check_target(o, seen, err)) || (st = check_kernel(o, seen, err)) ||
                                    (st = check_input(o, err))))
        return st;
    o->kernel_given = seen >> OPT_KERNEL & 1;
    put_command(o);
    if (o->mode == CLI_GENERATE && !o->prefix[0])
        put_default_prefix(o);
    return PTP_OK;
}
