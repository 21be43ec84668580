/* vectors_c.c: the execution check: a ptpgen C header's classify run on the points of a
 * `ptpgen vectors --format c` include, its classes compared with the include's. */
/* tests/test_cli.sh builds it with -DHEADER="ptp_NxM.h" -DVECTORS="v.h" -DCLASSIFY=ptp_NxM_classify
 * -DPTP_NxM_IMPLEMENTATION -DCLASS=ptp_vectors_class_strict (or _degenerate, for --rule
 * degenerate); it prints "N cases, M mismatches" and exits 1 on a mismatch. */
#include HEADER
#include VECTORS

#include <stdio.h>

int main(void)
{
    long c, bad = 0;
    for (c = 0; c < PTP_VECTORS_COUNT; c++) {
        unsigned got = CLASSIFY(ptp_vectors_points[c], ptp_vectors_eye[c]);
        if (got != CLASS[c] && bad++ < 5)
            fprintf(stderr, "case %ld: classify says %u, the vectors %u\n", c, got, CLASS[c]);
    }
    printf("%d cases, %ld mismatches\n", PTP_VECTORS_COUNT, bad);
    return bad != 0;
}
