/* main.c: the CMake consumer's program: classifies a flat bicubic patch and its mirror with the
 * header ptpgen_generate() made, and checks the GLSL kernel generated beside it opens with its banner. */
#define PTP_3X3_IMPLEMENTATION
#include "ptp3.h"
#include <stdio.h>
#include <string.h>

int main(void)
{
    float cp[16][4], mirror[16][4], eye[4] = {0, 0, 1, 0};
    char line[256] = "";
    unsigned a, b;
    FILE *f;
    int i, j;
    for (i = 0; i < 4; i++) /* the plane z = 0.5, point (i, j) at (i, j); the mirror swaps u and v */
        for (j = 0; j < 4; j++) {
            float p[4] = {(float)i - 1.5f, (float)j - 1.5f, 0.5f, 1};
            memcpy(cp[i * 4 + j], p, sizeof p);
            memcpy(mirror[j * 4 + i], p, sizeof p);
        }
    a = ptp_3x3_classify((const float (*)[4])cp, eye);
    b = ptp_3x3_classify((const float (*)[4])mirror, eye);
    printf("classes %u %u\n", a, b);
    if (a != PTP_3X3_FRONT || b != PTP_3X3_BACK) /* the plane faces the eye (0, 0, 1, 0); the mirror away */
        return 1;
    f = fopen(KERNEL, "r");
    if (!f || !fgets(line, sizeof line, f) || strncmp(line, "/* ptp_tri3", 11) != 0) {
        printf("kernel %s: first line '%s'\n", KERNEL, line);
        return 1;
    }
    fclose(f);
    printf("kernel %s", line);
    return 0;
}
