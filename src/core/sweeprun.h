/* sweeprun.h: a simulated sweep of a chain, one frequency after another, each started
 * from the state the last one ended in (so a nonlinear chain stays on the branch it is on
 * until that branch ends, and jumps), each run until its amplitude is steady, then its
 * first harmonic measured. */
#ifndef SPRINGSIM_SWEEPRUN_H
#define SPRINGSIM_SWEEPRUN_H

#include <stdbool.h>

#include "sim.h"

#define SWEEPRUN_STEADY 1e-3     /* the amplitude's change a period, and its tail, at most */
#define SWEEPRUN_MAX_PERIODS 3000 /* periods a point may take before it is given up on */
#define SWEEPRUN_MAX_SECONDS 1200.0 /* simulated seconds a point may take */

/* What a point came to. */
struct sweeprun_point {
    bool settled;  /* steady to SWEEPRUN_STEADY; false: the cap was reached */
    int periods;   /* drive periods run */
    bool diverged; /* the state stopped being finite */
    long capped;   /* steps whose velocities the cap held (sim_last_capped) */
};

/* Retunes s's drive to f (its phase kept, so the motor does not jump), runs it until
 * every mass's first-harmonic amplitude is steady over the slowest mode's decay time (a
 * step that fails ends it as diverged), then writes each mass's amplitude (m)
 * and phase to the motor's displacement (degrees, (-180, 180]) over the last whole period
 * into amp and phase. The drive's phase and the state carry on to the next call. */
struct sweeprun_point sweeprun_point(struct sim *s, double f, double *amp, double *phase);

#endif
