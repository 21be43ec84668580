/* test_float_rounding.c: a float model kept in doubles really is the float model under this
 * compiler and the project's flags (float_widen.h), where the naive (double)(float)x copy is not. */
#include <float.h>

#include "check.h"
#include "float_widen.h"

#define NPTS 16
#define NOINLINE __attribute__((noinline))

typedef struct {
    double p[NPTS][3];
} dpatch;

typedef struct {
    float p[NPTS][3];
} fpatch;

/* The copy bench/cullrate.c's reader once made: gcc 12.2 -O2 vectorizes x and y and stores
 * them unrounded. */
NOINLINE static void copy_naive(dpatch *b, const double (*v)[3])
{
    int k, c;
    for (k = 0; k < NPTS; k++)
        for (c = 0; c < 3; c++)
            b->p[k][c] = (float)v[k][c];
}

/* The fixed form: round into float storage, widen with float_widen. */
NOINLINE static void copy_widened(dpatch *b, fpatch *f, const double (*v)[3])
{
    int k, c;
    for (k = 0; k < NPTS; k++)
        for (c = 0; c < 3; c++)
            f->p[k][c] = (float)v[k][c];
    for (k = 0; k < NPTS; k++)
        for (c = 0; c < 3; c++)
            b->p[k][c] = float_widen(&f->p[k][c]);
}

/* The eye in bench/cullrate.c: three floats, then the doubles from them (the plain widening
 * eye[k] = eyef[k] also loses the rounding under gcc 12.2 -O2). */
NOINLINE static void eye_widened(double eye[3], float eyef[3])
{
    int k;
    for (k = 0; k < 3; k++)
        eyef[k] = (float)eye[k];
    for (k = 0; k < 3; k++)
        eye[k] = float_widen(&eyef[k]);
}

/* The number of values of b that are not a float, by float_value of their rounding. */
static int unrounded(const double *b, int n)
{
    int i, bad = 0;
    for (i = 0; i < n; i++) {
        float f = (float)b[i];
        bad += !float_same(&b[i], 1, &f, 1, 1);
    }
    return bad;
}

int main(void)
{
    static const float probe[] = {0.0f, -0.0f, 1.0f, -1.5f, 0x1p-149f, -0x1.fffffcp-127f,
                                  0x1p-126f, FLT_MAX, 44.123456f};
    static const double probe_d[] = {0.0, -0.0, 1.0, -1.5, 0x1p-149, -0x1.fffffcp-127,
                                     0x1p-126, 0x1.fffffep127, 44.123456f};
    double v[NPTS][3], eye[3];
    uint64_t rng = 20;
    dpatch naive, fixed;
    fpatch f;
    float eyef[3];
    int k, c, bad = 0;
    for (k = 0; k < (int)(sizeof probe / sizeof *probe); k++)
        bad += !float_same(&probe_d[k], 1, &probe[k], 1, 1);
    check(!bad, "float_value decodes zeros, normals, subnormals and FLT_MAX exactly",
          "%d of %d wrong", bad, k);
    for (k = 0; k < NPTS; k++) /* 12-digit coordinates up to 45, like a raw-unit model */
        for (c = 0; c < 3; c++)
            v[k][c] = (double)(ptp_splitmix64(&rng) >> 11) * 0x1p-53 * 90 - 45;
    memcpy(eye, v[5], sizeof eye);
    copy_naive(&naive, (const double(*)[3])v);
    copy_widened(&fixed, &f, (const double(*)[3])v);
    eye_widened(eye, eyef);
    printf("# the naive copy b = (float)v left %d of %d doubles unrounded with this compiler\n",
           unrounded(&naive.p[0][0], NPTS * 3), NPTS * 3);
    check(!unrounded(&fixed.p[0][0], NPTS * 3) &&
              float_same(&fixed.p[0][0], 1, &f.p[0][0], 1, NPTS * 3),
          "float_widen: 16 points copied through float storage are the floats bit for bit",
          "%d of %d unrounded", unrounded(&fixed.p[0][0], NPTS * 3), NPTS * 3);
    check(float_same(eye, 1, eyef, 1, 3), "float_widen: the eye is the float eye bit for bit",
          "%.17g %.17g %.17g", eye[0], eye[1], eye[2]);
    return check_exit();
}
