/* limits.h: how large dt may be for a chain and an integrator (SPEC section 1, "Limits"):
 * the stability limit from the damped system's eigenvalues, the accuracy of the highest
 * modes and of the drive, and the warnings that say so. */
#ifndef SPRINGSIM_LIMITS_H
#define SPRINGSIM_LIMITS_H

#include <stdbool.h>
#include <stddef.h>

#include "integrator.h"
#include "model.h"

#define LIMITS_LOSS 0.01        /* amplitude change per period still called accurate */
#define LIMITS_DRIVE_STEPS 20.0 /* steps per drive period still called accurate */
#define LIMITS_DGEEV_MAX 100    /* above this many masses, the modal approximation */

/* One mode of the damped chain as the single oscillator x'' = -w2 x - 2 s x', whose
 * eigenvalues are a pair of the first-order system's: w2 = |lambda|^2, s = -Re lambda
 * for a complex pair; w2 = lambda1 lambda2, s = -(lambda1 + lambda2) / 2 for two real
 * ones (an overdamped mode). */
struct limits_mode {
    double w2; /* 1/s^2 */
    double s;  /* 1/s */
};

/* The N modes of the damped chain m into mode[N], highest |lambda| last: the eigenvalues
 * of [[0, I], [-M^-1 K, -M^-1 C]] (LAPACK dgeev) up to LIMITS_DGEEV_MAX masses, above it
 * the undamped modes (dstev) with modal damping. Returns 0, -1 on no memory, -2 when the
 * numbers overflow, or LAPACK's info. */
int limits_modes(const struct model *m, struct limits_mode *mode);

/* The largest dt at which integrator i is stable on every one of the n modes: the step
 * matrix of each has spectral radius <= 1. INFINITY for exact; 0 (or a tiny value) when
 * no step is, e.g. euler on an undamped mode. */
double limits_stable_dt(const struct limits_mode *mode, int n, enum integrator i);

/* Amplitude change per period of mode md to integrator i at step dt, relative to the
 * exact decay over the same time: rho^(T/dt) / exp(-s T) - 1, with rho the step
 * matrix's spectral radius and T = 2 pi / sqrt(w2). Negative: the method takes
 * amplitude away; 0 for exact. NAN for an overdamped mode (no period). */
double limits_mode_error(const struct limits_mode *md, enum integrator i, double dt);

/* The largest dt at which every oscillating mode of the n changes by at most
 * LIMITS_LOSS per period (INFINITY for exact). */
double limits_accurate_dt(const struct limits_mode *mode, int n, enum integrator i);

/* What dt is worth for one chain, drive and integrator. */
struct limits {
    enum integrator integrator; /* the integrator judged */
    double dt;                  /* the step judged (s) */
    double stable_dt;           /* the largest stable step (s), INFINITY for none */
    double accurate_dt;         /* the largest step keeping every mode within 1 % (s) */
    int worst;                  /* the mode changed most per period at dt, or -1 */
    double error;               /* its change per period (fraction; < 0: a loss) */
    double worst_hz;            /* its natural frequency sqrt(w2) / 2 pi (Hz) */
    bool worst_is_top;          /* it is the highest oscillating mode */
    double drive_hz;            /* the drive's frequency, 0 without a drive */
    double drive_steps;         /* steps per drive period at dt, INFINITY without one */
};

/* Judges dt for integrator i on the n modes of model m (its drive included). */
void limits_judge(const struct limits_mode *mode, int n, const struct model *m,
                  enum integrator i, double dt, struct limits *out);

/* Whether dt is unstable; whether (being stable) a mode is off by more than LIMITS_LOSS
 * per period; whether the drive has fewer than LIMITS_DRIVE_STEPS steps per period. */
bool limits_unstable(const struct limits *l);
bool limits_rough_modes(const struct limits *l);
bool limits_rough_drive(const struct limits *l);

/* x rounded down to three significant digits: a limit quoted that way is never past the
 * real one. */
double limits_round_down(double x);

/* The warnings, one phrase each (no "springsim: "), empty when there is nothing to say:
 * dt unstable, a mode inaccurate, the drive with too few steps. short_form fits a status
 * line of 80 columns. */
void limits_say_stability(const struct limits *l, bool short_form, char *buf, size_t len);
void limits_say_modes(const struct limits *l, bool short_form, char *buf, size_t len);
void limits_say_drive(const struct limits *l, bool short_form, char *buf, size_t len);

#endif
