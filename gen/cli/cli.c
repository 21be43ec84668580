/* cli.c: parses and validates ptpgen's options.
 * Accepts "--opt value" and "--opt=value"; the last occurrence of an option wins. */
#include "cli/cli.h"

#include <ctype.h>
#include <stdio.h>
#include <string.h>

const char *const cli_targets[] = {"json", "table", "stats", "c", "glsl", "hlsl", "opencl", "cuda"};

const char cli_usage[] =
    "usage: ptpgen --degree N|NxM [--target T] [--space clip|world] [--rule strict|degenerate]\n"
    "              [--planes] [--certified] [--refine K] [--prefix NAME]\n"
    "              [--threads-per-patch P] [--patches-per-block Q]\n"
    "              [-o FILE]\n"
    "       ptpgen verify FILE [--degree NxM] [-o REPORT]\n"
    "       ptpgen vectors --degree NxM --count K --seed S [--space clip|world] [-o FILE]\n"
    "       ptpgen --help | --version\n"
    "\n"
    "Derives the exact control planes of the parametric tangent plane\n"
    "T = cross4(B, dB/du, dB/dv) of a Bezier patch of bidegree NxM (N along u) and\n"
    "writes them, or a back-patch culling kernel built on them.\n"
    "\n"
    "  --degree N|NxM   patch bidegree, 1 <= N, M <= 16 (N alone means NxN)\n"
    "  --target T       json (default): the exact terms and schedule, ptpgen-planes/1\n"
    "                   table: a C header in the paper's idx/wgt format\n"
    "                   stats: the term count of every plane and the schedule\n"
    "                   c: a C99 single header (stb style)\n"
    "                   glsl, hlsl, opencl, cuda: a compute kernel\n"
    "  --space S        clip (default): points in clip space, eye (0, 0, alpha, 0);\n"
    "                   world: the full planes dotted with a homogeneous eye point\n"
    "  --rule R         strict (default): back iff all values < 0, front iff all > 0;\n"
    "                   degenerate: back iff none > 0, front iff none < 0\n"
    "  --planes         kernels also write the value of every plane\n"
    "  --certified      call a patch back or front only when every value clears a rigorous\n"
    "                   bound on its float rounding error (README: Certified classification)\n"
    "  --refine K       C only: split the patch's scalar Bezier function e.T by de Casteljau,\n"
    "                   up to K levels (1 to 6), while its control values have mixed signs\n"
    "  --prefix NAME    prefix of generated names (default ptp_NxM_)\n"
    "  --threads-per-patch P\n"
    "                   threads that share one patch, 1..1024, at most the number of\n"
    "                   planes (default 16 for 3x3; see README for other degrees)\n"
    "  --patches-per-block Q\n"
    "                   patches per thread block (default 128/P, at least 1)\n"
    "  -o, --output F   write to F (atomically) instead of standard output\n"
    "  -h, --help       show this help\n"
    "  --version        show the version\n"
    "\n"
    "verify checks a table (the paper's idx/wgt C header or ptpgen's json) against the\n"
    "exact derivation and names each problem with its line: exit 0 right, 1 wrong, 2 unreadable.\n"
    "vectors writes K random patches (small integers) with their exact plane values and\n"
    "classes under both rules, as JSON; the same seed gives the same bytes.\n"
    "\n"
    "Exit status: 0 success, 1 failure, 2 usage error.\n";

/* Parses one degree: decimal digits only, 1..PTP_MAX_DEGREE. *end is where it stopped. */
static int parse_one(int *d, const char *s, const char **end, const char *arg, ptp_error *err)
{
    long v = 0;
    const char *p = s;
    int big = 0;
    for (; *p >= '0' && *p <= '9'; p++) {
        v = v * 10 + (*p - '0');
        if (v > PTP_MAX_DEGREE) {
            big = 1;
            v = PTP_MAX_DEGREE + 1;
        }
    }
    if (p == s)
        return ptp_fail(err, PTP_EUSAGE,
                        "--degree '%s': expected N or NxM with whole numbers 1 to %d (e.g. 3 or 2x3)",
                        arg, PTP_MAX_DEGREE);
    *end = p;
    if (big)
        return ptp_fail(err, PTP_EUSAGE, "--degree '%s': the largest supported degree is %d", arg,
                        PTP_MAX_DEGREE);
    if (v == 0)
        return ptp_fail(err, PTP_EUSAGE, "--degree '%s': degrees must be at least 1", arg);
    *d = (int)v;
    return PTP_OK;
}

static int parse_degree(cli_options *o, const char *arg, ptp_error *err)
{
    const char *p;
    int st;
    if ((st = parse_one(&o->n, arg, &p, arg, err)))
        return st;
    if (*p == '\0') {
        o->m = o->n;
        return PTP_OK;
    }
    if (*p == 'x' && (st = parse_one(&o->m, p + 1, &p, arg, err)))
        return st;
    if (*p != '\0')
        return ptp_fail(err, PTP_EUSAGE,
                        "--degree '%s': expected N or NxM with whole numbers 1 to %d (e.g. 3 or 2x3)",
                        arg, PTP_MAX_DEGREE);
    return PTP_OK;
}

/* Parses a thread count: decimal digits only; values past 10^6 are kept as 10^6 + 1 so that
 * the scheduler's range check names the limit. Zero is left to that check too. */
static int parse_count(int *v, const char *opt, const char *arg, ptp_error *err)
{
    const char *p = arg;
    long x = 0;
    for (; *p >= '0' && *p <= '9'; p++)
        x = x > 1000000 ? 1000001 : x * 10 + (*p - '0');
    if (p == arg || *p != '\0')
        return ptp_fail(err, PTP_EUSAGE, "%s '%s': expected a whole number", opt, arg);
    *v = (int)x;
    return PTP_OK;
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

/* A prefix is a C identifier start: a letter or '_', then letters, digits and '_'. */
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
    return PTP_OK;
}

/* If argv[*i] is option name (long "--name" or short "-c"), sets *val to its argument,
 * taken from "--name=value" or the next word, and returns 1; returns 0 if it is not. */
static int take(const char **val, int *st, const char *name, int argc, char **argv, int *i,
                ptp_error *err)
{
    const char *a = argv[*i];
    size_t n = strlen(name);
    if (strncmp(a, name, n) != 0)
        return 0;
    if (a[n] == '=' && name[1] == '-') {
        *val = a + n + 1;
        return 1;
    }
    if (a[n] != '\0')
        return 0;
    if (*i + 1 >= argc) {
        *st = ptp_fail(err, PTP_EUSAGE, "option %s needs an argument", name);
        return 1;
    }
    *val = argv[++*i];
    return 1;
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

/* The options that belong to one mode or another: bit i stands for opt_names[i]. */
enum {
    OPT_DEGREE = 1 << 0,
    OPT_GENERATE = 0xCFE, /* --target, --space, --rule, --planes, --prefix, the thread counts,
                             --certified, --refine */
    OPT_SPACE = 1 << 2,
    OPT_COUNT = 1 << 8,
    OPT_SEED = 1 << 9
};
static const char *const opt_names[] = {"--degree", "--target", "--space", "--rule", "--planes",
                                        "--prefix", "--threads-per-patch", "--patches-per-block",
                                        "--count", "--seed", "--certified", "--refine"};

int cli_parse(cli_options *o, int argc, char **argv, ptp_error *err)
{
    static const char *const spaces[] = {"clip", "world"}, *const rules[] = {"strict", "degenerate"};
    static const char *const modes[] = {"code generation", "verify", "vectors"};
    static const unsigned allowed[] = {OPT_DEGREE | OPT_GENERATE, OPT_DEGREE,
                                       OPT_DEGREE | OPT_SPACE | OPT_COUNT | OPT_SEED};
    unsigned seen = 0;
    uint64_t u = 0;
    int i, k, st = PTP_OK, target = CLI_JSON, first = 1;
    memset(o, 0, sizeof *o);
    o->threads = o->patches = -1;
    if (argc > 1 && strcmp(argv[1], "verify") == 0)
        o->mode = CLI_VERIFY;
    else if (argc > 1 && strcmp(argv[1], "vectors") == 0)
        o->mode = CLI_VECTORS;
    first += o->mode != CLI_GENERATE;
    /* Each option's branch also records it in seen ((seen |= bit) is never 0), for the check
     * below that it belongs to the mode. */
    for (i = first; i < argc && !st; i++) {
        const char *a = argv[i], *v = NULL;
        if (strcmp(a, "-h") == 0 || strcmp(a, "--help") == 0)
            o->help = 1;
        else if (strcmp(a, "--version") == 0)
            o->version = 1;
        else if (strcmp(a, "--planes") == 0 && (seen |= 1u << 4))
            o->planes = 1;
        else if (strcmp(a, "--certified") == 0 && (seen |= 1u << 10))
            o->certified = 1;
        else if (take(&v, &st, "--degree", argc, argv, &i, err) && (seen |= 1u << 0))
            st = st ? st : parse_degree(o, v, err);
        else if (take(&v, &st, "--target", argc, argv, &i, err) && (seen |= 1u << 1))
            st = st ? st : parse_choice(&target, "target", v, cli_targets, 8, err);
        else if (take(&v, &st, "--space", argc, argv, &i, err) && (seen |= 1u << 2))
            st = st ? st : parse_choice(&o->world, "space", v, spaces, 2, err);
        else if (take(&v, &st, "--rule", argc, argv, &i, err) && (seen |= 1u << 3))
            st = st ? st : parse_choice(&o->degenerate, "rule", v, rules, 2, err);
        else if (take(&v, &st, "--prefix", argc, argv, &i, err) && (seen |= 1u << 5))
            st = st ? st : parse_prefix(o, v, err);
        else if (take(&v, &st, "--threads-per-patch", argc, argv, &i, err) && (seen |= 1u << 6))
            st = st ? st : parse_count(&o->threads, "--threads-per-patch", v, err);
        else if (take(&v, &st, "--patches-per-block", argc, argv, &i, err) && (seen |= 1u << 7))
            st = st ? st : parse_count(&o->patches, "--patches-per-block", v, err);
        else if (take(&v, &st, "--count", argc, argv, &i, err) && (seen |= 1u << 8)) {
            if (!st && !(st = parse_ulong(&u, "--count", v, 1000000, err)))
                o->count = (long)u;
        } else if (take(&v, &st, "--refine", argc, argv, &i, err) && (seen |= 1u << 11)) {
            if (!st && !(st = parse_ulong(&u, "--refine", v, CLI_MAX_REFINE, err)))
                o->refine = (int)u;
        } else if (take(&v, &st, "--seed", argc, argv, &i, err) && (seen |= 1u << 9))
            st = st ? st : parse_ulong(&o->seed, "--seed", v, UINT64_MAX, err);
        else if (take(&v, &st, "--output", argc, argv, &i, err) ||
                 take(&v, &st, "-o", argc, argv, &i, err))
            o->output = v;
        else if (o->mode == CLI_VERIFY && !o->input && (a[0] != '-' || a[1] == '\0'))
            o->input = a;
        else if (a[0] == '-')
            st = ptp_fail(err, PTP_EUSAGE, "unknown option '%s' (see ptpgen --help)", a);
        else
            st = ptp_fail(err, PTP_EUSAGE, "unexpected argument '%s' (see ptpgen --help)", a);
    }
    o->target = (cli_target)target;
    if (st || o->help || o->version)
        return st;
    for (k = 0; k < (int)(sizeof opt_names / sizeof *opt_names); k++)
        if (seen >> k & 1 && !(allowed[o->mode] >> k & 1))
            return ptp_fail(err, PTP_EUSAGE, "option %s does not apply to %s", opt_names[k],
                            modes[o->mode]);
    if (o->mode == CLI_VERIFY) {
        if (!o->input)
            return ptp_fail(err, PTP_EUSAGE, "verify: missing the FILE to check (see ptpgen --help)");
        return PTP_OK;
    }
    if (!o->n)
        return ptp_fail(err, PTP_EUSAGE, "missing --degree N or --degree NxM (see ptpgen --help)");
    if (o->mode == CLI_VECTORS) {
        if (!(seen & OPT_COUNT) || !(seen & OPT_SEED) || o->count < 1)
            return ptp_fail(err, PTP_EUSAGE, "vectors needs --count K (1 to 1000000) and --seed S");
        snprintf(o->command, sizeof o->command,
                 "ptpgen vectors --degree %dx%d --count %ld --seed %llu --space %s", o->n, o->m,
                 o->count, (unsigned long long)o->seed, o->world ? "world" : "clip");
        return PTP_OK;
    }
    if (o->refine && o->target != CLI_C)
        return ptp_fail(err, PTP_EUSAGE, "--refine applies to --target c only");
    if (o->refine && o->certified)
        return ptp_fail(err, PTP_EUSAGE, "--refine and --certified do not go together: the "
                                         "subdivision is not certified");
    {
        int n = snprintf(o->command, sizeof o->command, "ptpgen --degree %dx%d --target %s", o->n,
                         o->m, cli_targets[o->target]);
        if (o->world)
            n += snprintf(o->command + n, sizeof o->command - (size_t)n, " --space world");
        if (o->degenerate)
            n += snprintf(o->command + n, sizeof o->command - (size_t)n, " --rule degenerate");
        if (o->planes)
            n += snprintf(o->command + n, sizeof o->command - (size_t)n, " --planes");
        if (o->certified)
            n += snprintf(o->command + n, sizeof o->command - (size_t)n, " --certified");
        if (o->refine)
            n += snprintf(o->command + n, sizeof o->command - (size_t)n, " --refine %d", o->refine);
        if (o->prefix[0])
            n += snprintf(o->command + n, sizeof o->command - (size_t)n, " --prefix %s", o->prefix);
        if (o->threads >= 0)
            n += snprintf(o->command + n, sizeof o->command - (size_t)n,
                          " --threads-per-patch %d", o->threads);
        if (o->patches >= 0)
            snprintf(o->command + n, sizeof o->command - (size_t)n, " --patches-per-block %d",
                     o->patches);
    }
    if (!o->prefix[0])
        snprintf(o->prefix, sizeof o->prefix, "ptp_%dx%d_", o->n, o->m);
    return PTP_OK;
}
