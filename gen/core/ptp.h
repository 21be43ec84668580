/* ptp.h: definitions shared by every ptpgen module. Status codes with a message (library code
 * never exits), the 128-bit integer type, limits, and the numbers of the classes of a patch. */
#ifndef PTP_H
#define PTP_H

#include <stddef.h>
#include <stdint.h>

#define PTP_VERSION "0.1.0"

/* The largest supported degree along u or v.  Every weight of every bidegree up to
 * (PTP_MAX_DEGREE, PTP_MAX_DEGREE) is derived exactly in 128-bit rationals. */
#define PTP_MAX_DEGREE 16

__extension__ typedef __int128 ptp_i128;
__extension__ typedef unsigned __int128 ptp_u128;

/* The class of a patch, as every output numbers it (kernels, the C header, test vectors). */
typedef enum { PTP_FRONT = 0, PTP_BACK = 1, PTP_SILHOUETTE = 2 } ptp_class;

/* Status codes returned by library functions; 0 is success. */
enum {
    PTP_OK = 0,
    PTP_EUSAGE,    /* bad argument from the user */
    PTP_ELIMIT,    /* request beyond a documented limit */
    PTP_EOVERFLOW, /* exact arithmetic overflowed 128 bits */
    PTP_ENOMEM,    /* allocation failed */
    PTP_EIO,       /* reading or writing a file failed */
    PTP_EINTERNAL  /* an invariant failed: a bug in ptpgen */
};

/* An error: the status and a one-line message (no "ptpgen:" prefix, no newline). */
typedef struct {
    int status;
    char msg[512];
} ptp_error;

/* Sets err (if not NULL) to status and the printf-style message; returns status. */
int ptp_fail(ptp_error *err, int status, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

/* The next value of the splitmix64 stream *state (Steele, Lea and Flood 2014): the one
 * deterministic pseudo-random stream of ptpgen and its tests. */
uint64_t ptp_splitmix64(uint64_t *state);

#endif
