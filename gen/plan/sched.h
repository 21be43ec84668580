/* sched.h: the race-free schedule of a tangent-plane table's terms over the threads of a patch.
 * Threads own whole planes, so no two ever add into one plane; rounds = the largest load. */
#ifndef SCHED_H
#define SCHED_H

#include "core/ptp.h"
#include "core/tplane.h"

/* The most threads of one block (P*Q), the CUDA limit. */
#define SCHED_MAX_THREADS 1024
/* The block size the default Q aims at. */
#define SCHED_BLOCK_THREADS 128

typedef struct {
    int threads;     /* P, threads per patch */
    int patches;     /* Q, patches per block */
    int rounds;      /* R = the largest load of any thread */
    int lower_bound; /* LB = max(ceil(nterms/P), largest term count of one plane) */
    int proven;      /* 1 when R == LB or a complete search proved R optimal; 0 when a gap R-LB
                        remains unproven */
    int nplanes;
    int *owner;      /* owner[plane] = the thread (0..P-1) that owns it */
    int *load;       /* load[thread] = its number of terms */
    long *slot;      /* rounds*threads entries: slot[r*P + t] = index into t->terms of thread t's
                        r-th term, or -1 for padding */
} sched;

/* Schedules the terms of t over P threads per patch, Q patches per block. Every plane gets
 * exactly one owner and a thread's slots hold only terms of its own planes, in (plane, table)
 * order, round-major. R is minimized: LPT, pair repartitions and a fixed-seed perturbation
 * search aim at LB; a branch and bound tries to pack below R, proving R optimal when it finds
 * no packing and leaving proven = 0 when its work cap (counted, not timed: the result is
 * deterministic) runs out first.
 * Fails with PTP_EUSAGE when P is outside 1..SCHED_MAX_THREADS, when P exceeds t->dom.nplanes (a
 * thread without a plane would idle, so it is refused rather than padded), when Q < 1 or when
 * P*Q exceeds SCHED_MAX_THREADS; PTP_ELIMIT when nterms does not fit an int, PTP_ENOMEM, and
 * PTP_EINTERNAL if t is not sorted by plane. s is uninitialized on entry; on failure it holds
 * no memory. */
int sched_build(sched *s, const tp_table *t, int P, int Q, ptp_error *err);
/* Frees s's storage. */
void sched_clear(sched *s);
/* The plane a padding slot of thread th names: the lowest plane th owns (every thread owns
 * one), so that even a padding write stays within the thread's own planes. */
int sched_padding_plane(const sched *s, int th);
/* The default P: the largest power of two P <= min(64, nplanes) whose lower bound keeps at
 * least 95% of the thread-rounds busy, nterms >= 0.95 * P * LB(P); 16 for bicubic. */
int sched_default_threads(const tp_table *t);
/* The default Q for P threads per patch: SCHED_BLOCK_THREADS / P, at least 1. */
int sched_default_patches(int P);

#endif
