/* exact.h: the chain integrated exactly over one smooth piece of the drive, by the
 * matrix exponential of the linear system augmented with the drive's own small linear
 * system (a sine is the output of a rotation, a straight line of a double integrator):
 * exact to rounding at any step. */
#ifndef SPRINGSIM_EXACT_H
#define SPRINGSIM_EXACT_H

#include "model.h"

struct exact;

/* Workspace for chains of n masses, or NULL on no memory. */
struct exact *exact_new(int n);

/* Frees it. */
void exact_free(struct exact *e);

/* The right end over the piece: u(t) = amp * sin(omega * t + phi) when sine is set, else
 * u(t) = u0 + du * (t - t0) (a constant or a ramp; 0 for wall and free ends). */
struct exact_drive {
    int sine;                /* 1: the sine form */
    double amp, omega, phi;  /* the sine's amplitude (m), angular frequency, phase (rad) */
    double t0, u0, du;       /* the line's reference time, value and slope */
};

/* Advances displacements x and velocities v (n each) of model m from time a to b with
 * the drive d, in place; adds to *diss the energy dissipated by the dampers, integral of
 * sum c_i v_i^2, and to *work the motor's work, integral of k_N (u - x_N) u', over the
 * piece (both to about 1e-12 relative). 0, or -1 when the exponential fails. */
int exact_advance(struct exact *e, const struct model *m, const struct exact_drive *d,
                  double a, double b, double *x, double *v, double *diss, double *work);

#endif
