/* limits.h: how large dt may be for a chain and an integrator (docs/accuracy.md):
 * the stability limit from each integrator's own one-step matrix, the accuracy (amplitude
 * and phase) of the modes and of the motion at the drive's frequency, and the warnings
 * that say so. */
#ifndef SPRINGSIM_LIMITS_H
#define SPRINGSIM_LIMITS_H

#include <stdbool.h>
#include <stddef.h>

#include "integrator.h"
#include "model.h"
#include "sim.h"

#define LIMITS_LOSS 0.01     /* error per period (of the amplitude) still called accurate */
#define LIMITS_DGEEV_MAX 100 /* above this many masses, the undamped modes (dstevr) */
#define LIMITS_RUNAWAY 10.0  /* energy, in all the chain could have, that is a blow-up */

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

/* The largest dt at which integrator i is stable on chain m, whose n modes are mode
 * (limits_modes): up to ONESTEP_MAX masses the first h at which the spectral radius of
 * the integrator's own one-step matrix passes 1 (onestep.c); above, for euler and rk4
 * |R(h lambda)| <= 1 on the modes' eigenvalues (exact up to LIMITS_DGEEV_MAX masses, then
 * on the region that holds them), for semi-implicit and verlet the first h with an
 * eigenvalue -1 (stability.c). INFINITY for exact; 0 (or a tiny value) when no step is,
 * e.g. euler on an undamped chain. */
double limits_stable_dt(const struct model *m, const struct limits_mode *mode, int n,
                        enum integrator i);

/* How far integrator i at step dt takes mode md from its exact motion: returns the
 * largest error within one period T = 2 pi / omega_d, over every start, relative to the
 * start's size (x scaled by sqrt(w2), so that the exact motion keeps its shape); *amp
 * (unless NULL) gets the amplitude's change per period relative to the exact decay
 * (< 0: a loss) and *phase the phase's (radians, < 0: a lag), from the eigenvalue mu
 * of the method's step: (mu / exp(lambda dt))^(T/dt) = (1 + amp) e^{i phase}.
 * 0 for exact; NAN for an overdamped mode (no period). */
double limits_mode_error(const struct limits_mode *md, enum integrator i, double dt,
                         double *amp, double *phase);

/* The largest dt at which every oscillating mode of the n is off by at most LIMITS_LOSS
 * per period (INFINITY for exact). */
double limits_accurate_dt(const struct limits_mode *mode, int n, enum integrator i);

/* What dt is worth for one chain, drive and integrator. */
struct limits {
    enum integrator integrator; /* the integrator judged */
    double dt;                  /* the step judged (s) */
    double stable_dt;           /* the largest stable step (s), INFINITY for none, NAN when
                                 * not known (the numbers overflow) */
    double accurate_dt;         /* the largest step keeping every mode within 1 % (s) */
    int worst;                  /* the mode off most per period at dt, or -1 */
    double error;               /* its largest error within a period (fraction of its size) */
    double amp_error;           /* its amplitude's change per period (fraction; < 0: loss) */
    double phase_error;         /* its phase's change per period (radians; < 0: a lag) */
    double worst_hz;            /* its natural frequency sqrt(w2) / 2 pi (Hz) */
    bool worst_is_top;          /* it is the highest oscillating mode */
    double drive_hz;            /* the drive's frequency, 0 without a drive */
    double drive_steps;         /* steps per drive period at dt, INFINITY without one */
    double drive_error;         /* the steady motion at the drive's frequency: its error
                                 * (fraction; onestep_drive_error), 0 for exact or none */
    double drive_dt;            /* the largest step keeping it within LIMITS_LOSS (s) */
};

/* Judges dt for integrator i on model m (its drive included), whose n modes are mode. */
void limits_judge(const struct limits_mode *mode, int n, const struct model *m,
                  enum integrator i, double dt, struct limits *out);

/* Whether dt is unstable; whether (being stable) a mode is off by more than LIMITS_LOSS
 * per period; whether (being stable) the steady motion at the drive's frequency is off
 * by more than LIMITS_LOSS. */
bool limits_unstable(const struct limits *l);
bool limits_rough_modes(const struct limits *l);
bool limits_rough_drive(const struct limits *l);

/* Watches a run past the stability limit for a blow-up: its kinetic + spring energy
 * more than LIMITS_RUNAWAY times all it could have had, exactly, with a margin: the energy
 * at the start, the most net work the motor has done since, and the drive's own scale
 * k_N A^2 / 2 (the explicit methods' books are only first order). Contacts bound an
 * unstable chain's positions, so its velocities need not reach the cap; its energy says
 * it all the same. */
struct limits_runaway {
    double base;  /* the start's kinetic + spring energy, and the drive's scale (J) */
    double work0; /* the motor's work at the start (J) */
    double most;  /* the most net work since (J) */
};

/* Starts watching chain m from the state whose books are e0. */
void limits_runaway_start(struct limits_runaway *r, const struct model *m,
                          const struct energy *e0);

/* Whether the run, now at books e, has blown up. */
bool limits_runaway_check(struct limits_runaway *r, const struct energy *e);

/* x rounded down to three significant digits: a limit quoted that way is never past the
 * real one. */
double limits_round_down(double x);

/* The warnings, one phrase each (no "springsim: "), empty when there is nothing to say:
 * dt unstable, a mode inaccurate, the motion at the drive's frequency inaccurate.
 * short_form fits a status line of 80 columns. */
void limits_say_stability(const struct limits *l, bool short_form, char *buf, size_t len);
void limits_say_modes(const struct limits *l, bool short_form, char *buf, size_t len);
void limits_say_drive(const struct limits *l, bool short_form, char *buf, size_t len);

/* What a limit said of a chain with hardening cubic springs must add: the limits are the
 * chain's linearised at rest, and large swings stiffen it and lower them. "" for any
 * other chain. */
const char *limits_linearised_note(const struct model *m);

#endif
