/* sweep.h: the stepped-sine experiment of a test rig: drive at one frequency after
 * another, let the chain settle, record each mass's peak amplitude and its phase to the
 * drive (a lock-in: x correlated with the drive's sine and cosine over whole periods),
 * move on. Pure bookkeeping: the caller steps the simulation and retunes the motor. */
#ifndef SPRINGSIM_SWEEP_H
#define SPRINGSIM_SWEEP_H

#include <stdbool.h>

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
};

/* A sweep of up to points frequencies for n masses, or NULL on no memory. */
struct sweep *sweep_new(int n, int points);

/* Frees a sweep. */
void sweep_free(struct sweep *s);

/* Starts at time t over fmin..fmax (evenly spaced), settling for at least settle
 * seconds and 8 periods at each point, then measuring 3 s or 4 periods. */
void sweep_start(struct sweep *s, double fmin, double fmax, double settle, double t);

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
