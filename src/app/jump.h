/* jump.h: the sweep experiment on a chain with cubic springs: the sweep up, then down
 * (each point from the state the last one ended in, as --sweep-run does), where each
 * leg jumped, and the harmonic-balance theory it is drawn over (harmonic.h), sampled for
 * the response view. No curses. */
#ifndef SPRINGSIM_JUMP_H
#define SPRINGSIM_JUMP_H

#include <stdbool.h>
#include <stdint.h>

#include "../core/harmonic.h"
#include "../core/sweep.h"

#define JUMP_RATIO 1.3 /* a jump: the amplitude changes by this factor between two points */

/* The harmonic-balance curve of a chain over a sweep's range, for drawing. */
struct jump_theory {
    int n, count;   /* masses, points along the curve */
    double lo, hi;  /* the range asked for (Hz) */
    double *f;      /* count frequencies (Hz), in order along the curve */
    double *amp;    /* count x n amplitudes (m) */
    double *phase;  /* count x n phases to the drive's sine (degrees, (-180, 180]) */
    double *rate;   /* count: the slow flow's largest real part (below 0: stable) */
    int folds;      /* folds found */
    double fold_f[HARMONIC_MAX_FOLDS]; /* their frequencies (Hz), lowest first */
    double top;     /* the largest amplitude in [lo, hi] (m) */
};

/* Whether a sweep of m goes up, then down, over harmonic balance: some spring is cubic
 * and the motor's wave is a sine. */
bool jump_two_way(const struct model *m);

/* The sweep *run has ended: if it went up, it is kept in *up and *run, swapped with it,
 * starts down over the same frequencies at time t, settling as the up one did; true then.
 * False (nothing changed) when it went down. */
bool jump_turn(struct sweep **run, struct sweep **up, double t);

/* Where the measured points of s jumped: the first k >= from (k + 1 < points measured) at which
 * some mass's amplitude changes by JUMP_RATIO or more from point k to k + 1, and by more
 * than twice (in ratio's logarithm) the change from k - 1 to k and from k + 1 to k + 2;
 * -1 when none did. */
int jump_find(const struct sweep *s, int from);

/* Whether the jump from point k to k + 1 of s goes up (the amplitude that changes most
 * grows) or down. */
bool jump_rises(const struct sweep *s, int k);

/* Solves t (emptied first) for m from lo to hi Hz: 0, or -1 with the reason in why
 * (harmonic_trace's: no drive, too many masses, no memory). */
int jump_theory_solve(struct jump_theory *t, const struct model *m, double lo, double hi,
                      char *why, size_t len);

/* A hash of what the theory of m depends on: the chain, the drive's wave and amplitude, the
 * force; not the drive's frequency, which a sweep changes at every point. */
uint64_t jump_theory_key(const struct model *m);

/* Frees what t holds (t stays usable, empty). */
void jump_theory_free(struct jump_theory *t);

#endif
