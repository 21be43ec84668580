/* fuzz_verify.c: the libFuzzer target of verify_table (any bytes, inferred degree and 3x3).
 * With -DFUZZ_REPLAY it is a program that replays the files it is given, for sanitizer builds. */
#include "tools/verify.h"
#include "tools/verify_parse.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Inferred bidegrees above this are skipped: deriving 16x16 takes seconds and gigabytes, which
 * is work, not a hang, but would stall the fuzzer. */
#define FUZZ_MAX_DEGREE 6

/* Checks one call's contract; aborts (a finding) when it is broken. */
static void run(const uint8_t *data, size_t size, int n, int m, int convention)
{
    sbuf out;
    ptp_error err;
    int verdict = -1, st;
    sbuf_init(&out);
    err.msg[0] = '\0';
    st = verify_table(&out, &verdict, (const char *)data, size, "fuzz", VERIFY_KIND_ANY, n, m,
                      convention, &err);
    if (st == PTP_OK && (verdict < VERIFY_RIGHT || verdict > VERIFY_WRONG || !out.s ||
                         out.s[out.len - 1] != '\n' || strncmp(out.s, "fuzz", 4)))
        abort();
    if (st == PTP_OK && verdict == VERIFY_RIGHT && !strstr(out.s, ": RIGHT: "))
        abort();
    if (st != PTP_OK && (verdict != VERIFY_WRONG || out.len || strncmp(err.msg, "fuzz:", 5)))
        abort();
    sbuf_clear(&out);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    verify_doc d;
    ptp_error err;
    tp_domain dom;
    if (!verify_parse(&d, (const char *)data, size, "fuzz", &err)) {
        int small = verify_doc_domain(&dom, &d, VERIFY_KIND_ANY, 0, 0, "fuzz", &err) ||
                    (dom.n <= FUZZ_MAX_DEGREE && dom.m <= FUZZ_MAX_DEGREE);
        verify_doc_clear(&d);
        if (small)
            run(data, size, 0, 0, VERIFY_U_FIRST);
    } else {
        run(data, size, 0, 0, VERIFY_U_FIRST);
    }
    run(data, size, 3, 3, VERIFY_V_FIRST);
    return 0;
}

#ifdef FUZZ_REPLAY
/* Replays every file named on the command line. */
int main(int argc, char **argv)
{
    int i;
    for (i = 1; i < argc; i++) {
        FILE *f = fopen(argv[i], "rb");
        uint8_t *buf = NULL;
        size_t len = 0, cap = 0, k;
        if (!f) {
            fprintf(stderr, "fuzz_verify: cannot open %s\n", argv[i]);
            return 1;
        }
        for (;;) {
            if (len == cap) {
                uint8_t *b = realloc(buf, cap = cap ? 2 * cap : 65536);
                if (!b) {
                    fprintf(stderr, "fuzz_verify: out of memory reading %s\n", argv[i]);
                    return 1;
                }
                buf = b;
            }
            if (!(k = fread(buf + len, 1, cap - len, f)))
                break;
            len += k;
        }
        fclose(f);
        LLVMFuzzerTestOneInput(buf, len);
        free(buf);
    }
    printf("fuzz_verify: replayed %d file%s\n", argc - 1, argc == 2 ? "" : "s");
    return 0;
}
#endif
