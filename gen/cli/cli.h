/* cli.h: the ptpgen command line, parsed into options without side effects.
 * Usage errors come back as PTP_EUSAGE with a message; main decides the exit code. */
#ifndef CLI_H
#define CLI_H

#include "core/domain.h"
#include "emit/sbuf.h"
#include "emit/targets.h"

#include <stdint.h>

/* The most de Casteljau levels --refine accepts. */
#define CLI_MAX_REFINE 6
/* The most test vectors --count accepts. */
#define CLI_MAX_COUNT 1000000

/* What ptpgen does: generate a target (the default), verify a table, or write test vectors. */
typedef enum { CLI_GENERATE, CLI_VERIFY, CLI_VECTORS } cli_mode;

typedef struct {
    cli_mode mode;
    const char *input;    /* verify: the table to check ("-": standard input) */
    long count;           /* vectors: --count */
    uint64_t seed;        /* vectors: --seed */
    tp_kind kind;         /* --domain (default quad) */
    int kind_given;       /* --domain was given (verify: else the table's own) */
    const char *degree;   /* the --degree argument, read by the domain once every option is in */
    tp_domain dom;        /* the patch domain of --degree; dom.n is 0 until it is given */
    const tgt_target *target; /* an entry of tgt_targets (default: the first) */
    const char *output;   /* -o path, or NULL for stdout */
    const char *host_header; /* --host-header path (GPU compute kernels), or NULL */
    int threads, patches; /* --threads-per-patch, --patches-per-block; -1 when not given */
    int world;            /* --space world (else clip) */
    int degenerate;       /* --rule degenerate (else strict) */
    int planes;           /* --planes */
    int certified;        /* --certified */
    int absolute;         /* --coordinates absolute (else local) */
    int bspline;          /* --basis bspline (else bezier) */
    int vmajor;           /* --order v-major (else u-major) */
    int refine;           /* --refine K (C only), 0 when not given */
    int table;            /* GPU targets: --kernel table (or --certified without --kernel) */
    int indexed;          /* GPU targets: --kernel indexed (the points through indices) */
    int lanes;            /* OpenCL: --kernel lanes (patches per work-item, in vectors) */
    int kernel_given;     /* --kernel was given */
    int functions;        /* GPU targets: --stage function */
    int vfirst;           /* verify: --convention v-first (else u-first) */
    int format_c;         /* vectors: --format c (else json) */
    int help, version;    /* --help or --version was given */
    int list;             /* --list-targets was given */
    char command[256];    /* the normalized command line, for banners */
    char prefix[64];      /* generated-name prefix: --prefix, or the domain's ("ptp_<n>x<m>_",
                             "ptp_tri<d>_") and the variant */
} cli_options;

/* Parses argv[1..argc-1] into o. Returns PTP_OK or PTP_EUSAGE with the message in err. */
int cli_parse(cli_options *o, int argc, char **argv, ptp_error *err);
/* Appends the --help text: the targets from the registry, the limits from their macros. */
void cli_usage(sbuf *o);
/* Appends the usage of one command: verify's or vectors' alone, else the whole --help text. */
void cli_usage_command(sbuf *o, cli_mode mode);

#endif
