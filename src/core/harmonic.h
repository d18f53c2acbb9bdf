/* harmonic.h: the steady motions of a chain with cubic springs (and any dampers) under the
 * motor's sine drive and the force input's, by harmonic balance with one harmonic (each
 * mass x_i = a_i cos wt + b_i sin wt), followed along the frequency by pseudo-arclength
 * continuation, so the curve turns round its folds; each solution's stability by Hill's
 * method on the same harmonic. */
#ifndef SPRINGSIM_HARMONIC_H
#define SPRINGSIM_HARMONIC_H

#include <stdbool.h>
#include <stddef.h>

#include "model.h"

#define HARMONIC_MAX_FOLDS 64 /* folds a curve keeps */
#define HARMONIC_MAX_MASSES 200 /* the stability's dense eigenvalues: (2N)^3 a point */

/* The continuation's curve from below fmin to past fmax: its points in order along it,
 * and its folds (where the frequency turns back). The pieces between folds are the
 * branches, numbered from 1 along the curve. */
struct harmonic_curve {
    int n;          /* masses */
    int count;      /* points */
    int cap;        /* room for points */
    double *f;      /* count frequencies (Hz) */
    double *ab;     /* count x 2N: a_0, b_0, a_1, b_1, ... (m) */
    int folds;      /* folds found */
    double fold_f[HARMONIC_MAX_FOLDS];    /* their frequencies (Hz) */
    int fold_after[HARMONIC_MAX_FOLDS];   /* the point each comes after */
    double fold_amp[HARMONIC_MAX_FOLDS];  /* the largest mass amplitude there (m) */
    bool complete;  /* it reached fmax; false: it stopped (amplitude past the walls, or too
                     * many points) */
};

/* One steady motion at a frequency. */
struct harmonic_solution {
    int branch;     /* 1, 2, ...: the piece of the curve it is on */
    bool stable;    /* every eigenvalue of the slow flow (Hill's method) decays */
    double rate;    /* the largest real part of those eigenvalues (1/s) */
    double *amp;    /* n amplitudes sqrt(a^2 + b^2) (m) */
    double *phase;  /* n phases to the drive's sine, the motor's displacement and the
                     * force's (degrees, (-180, 180]) */
};

/* Follows the steady motion of m (its motor's sine at amplitude A and its force's F sin on
 * mass K) from below fmin to past fmax. Returns the curve, or NULL on no memory or when no start was found (err
 * says why: no drive, too many masses). */
struct harmonic_curve *harmonic_trace(const struct model *m, double fmin, double fmax,
                                      char *err, size_t errlen);

/* Frees a curve. */
void harmonic_curve_free(struct harmonic_curve *c);

/* Every steady motion the curve has at f (one per branch crossing it, in branch order),
 * each solved afresh at f and judged for stability, into out[0 .. max-1] (each with room
 * for n amplitudes and phases). Returns how many. */
int harmonic_at(const struct model *m, const struct harmonic_curve *c, double f,
                struct harmonic_solution *out, int max);

/* The stability of every point of curve c of m: the largest real part of the slow flow's
 * eigenvalues there (1/s; below 0 stable, NAN unknown) into rate[0 .. c->count - 1].
 * 0, or -1 on no memory. */
int harmonic_curve_rates(const struct model *m, const struct harmonic_curve *c, double *rate);

/* The amplitude a of the single-mass backbone w^2 = (k + 3/4 k3 a^2) / m at frequency
 * f of a chain of one mass (k and k3 the sum of its two springs' with the motor held):
 * NAN where there is none. */
double harmonic_backbone(const struct model *m, double f);

#endif
