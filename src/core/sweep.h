/* sweep.h: the stepped-sine experiment of a test rig: drive at one frequency after
 * another, let the chain settle (for a time, or until its swings are steady), record each
 * mass's peak amplitude and its phase to the drive (a lock-in: x correlated with the
 * drive's sine and cosine over whole periods), move on. Pure bookkeeping: the caller
 * steps the simulation and retunes the motor. */
#ifndef SPRINGSIM_SWEEP_H
#define SPRINGSIM_SWEEP_H

#include <stdbool.h>

#include "model.h"

#define SWEEP_LEVEL 0.01 /* swings steady: level within this of the largest (relative) */

enum sweep_event {
    SWEEP_IDLE,     /* not running */
    SWEEP_SAME,     /* keep driving at the current frequency */
    SWEEP_RETUNE,   /* drive at sweep_frequency() from now on */
    SWEEP_DONE      /* the last point has been measured */
};

struct sweep {
    int n;          /* masses */
    int points;     /* frequencies in the sweep */
    int index;      /* the point being driven */
    bool active;    /* running */
    bool measuring; /* past the settling time of this point */
    double t_point; /* time the current point began */
    double settle_min; /* settling time asked for (s) */
    double settle;  /* settling time of this point (s) */
    double measure; /* measuring time per point (s) */
    double *freq;   /* points frequencies (Hz) */
    double *peak;   /* points x n peak |x| (m); NAN until measured */
    double *phase;  /* points x n phase of x to the drive (degrees, (-180, 180]); NAN
                     * until measured */
    double *in, *quad; /* n sums of x sin(theta) and x cos(theta) over this point */
    long contacts;  /* contacts while it ran: with any, the linear theory does not hold */
    double hold;    /* 0: settle for settle; else also until the swings stay level this
                     * long (s; sweep_until_steady) */
    double most;    /* with hold: a point settles at most this long (s) */
    double t_measure; /* when this point's measuring began */
    double t_level; /* the swings have been level since then (NAN: not yet) */
    long cycle;     /* the drive's period being watched (floor of its cycles) */
    int seen;       /* samples taken at this point (the parabola needs two before) */
    bool whole;     /* the period being watched began at this point */
    double *x1, *x2; /* n: the last two samples of each mass */
    double *swing;  /* n: each mass's largest |x| in this period (parabola-refined) */
    double *band;   /* 6n: each mass's least and largest swing, phasor real part and
                     * imaginary part since t_level */
    double *lock;   /* 2n: each mass's sums of x sin(theta), x cos(theta) in this period */
    double gram[3]; /* this period's sums of sin^2, sin cos and cos^2 of theta */
    double *extreme; /* n: each mass's |x| at the last sample, parabola-refined at a turn */
    int unsteady;   /* points measured after `most` without becoming steady */
};

/* A sweep of up to points frequencies for n masses, or NULL on no memory. */
struct sweep *sweep_new(int n, int points);

/* Frees a sweep. */
void sweep_free(struct sweep *s);

/* Frequency p of points spaced evenly from fmin to fmax (fmin when points is 1). */
double sweep_point(double fmin, double fmax, int points, int p);

/* Starts at time t over fmin..fmax (evenly spaced), settling for at least settle
 * seconds and 8 periods at each point, then measuring 3 s or 4 periods. */
void sweep_start(struct sweep *s, double fmin, double fmax, double settle, double t);

/* From the next point on (call it after sweep_start), a point settles also until, for
 * hold seconds and 4 periods, every mass's swing (its largest |x| in each whole drive
 * period, by the parabola through the extreme sample and its neighbours) has stayed
 * within SWEEP_LEVEL of the largest swing of any mass, and so has its phasor (that
 * period's lock-in: amplitude and phase together); or for most seconds at most, or twice
 * the least it can take if that is longer (counted in unsteady). */
void sweep_until_steady(struct sweep *s, double hold, double most);

/* The least factor of model m's whole drive (the motor's amplitude and the force
 * together) at which the linear steady state at one of the count frequencies (Hz) would
 * close a gap (a mass on a wall, its neighbour or the piston): at most 1, the drive as it
 * is makes contacts. INFINITY when none would (no collisions, no drive, a response
 * unknown). */
double sweep_contact_scale(const struct model *m, const double *freq, int count);

/* sweep_contact_scale as a motor amplitude (m), for a chain the motor alone drives;
 * INFINITY otherwise. */
double sweep_contact_amplitude(const struct model *m, const double *freq, int count);

/* Stops a sweep; what was measured stays. */
void sweep_stop(struct sweep *s);

/* The frequency to drive now. */
double sweep_frequency(const struct sweep *s);

/* Takes the displacements x at time t after a step, when the drive's phase is cycles
 * (theta / 2 pi: the motor is A w(theta), and its fundamental is in phase with
 * sin theta); says what to do next. */
enum sweep_event sweep_update(struct sweep *s, double t, const double *x, double cycles);

/* The phase in degrees, in (-180, 180], of a signal whose correlations with sin theta and
 * cos theta are in and quad: X sin(theta + phi) gives in ~ X cos phi, quad ~ X sin phi. */
double sweep_phase_deg(double in, double quad);

/* Counts the contacts a step of the running sweep made (nothing when it is not running). */
void sweep_count_contacts(struct sweep *s, int contacts);

/* Points measured so far. */
int sweep_measured(const struct sweep *s);

#endif
