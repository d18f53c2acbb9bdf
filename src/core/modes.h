/* modes.h: natural frequencies and mode shapes of the undamped chain, the RK4
 * stability limit they imply, and the steady-state response to a sine drive. */
#ifndef SPRINGSIM_MODES_H
#define SPRINGSIM_MODES_H

#include "model.h"

/* RK4 is stable for an undamped mode while omega * dt stays below this. */
#define MODES_RK4_LIMIT 2.78

/* Natural frequencies (Hz, ascending) into freq[N] and, if shapes is not NULL, mode
 * shapes into shapes[j*N + i] (mode j, mass i), each scaled so its largest |component|
 * is 1 and that component is positive. Returns 0, -1 on no memory, -2 when the numbers
 * overflow, or LAPACK's info. */
int modes_compute(const struct model *m, double *freq, double *shapes);

/* Index of the frequency in f[0..n-1] closest to freq. */
int modes_nearest(const double *f, int n, double freq);

/* The highest natural angular frequency (rad/s), or a negative value on failure. */
double modes_omega_max(const struct model *m);

/* The largest stable RK4 step for the chain, MODES_RK4_LIMIT / omega_max (s). */
double modes_stable_dt(const struct model *m);

/* Steady-state amplitudes |X_i| (m) of every mass under the sine drive of amplitude
 * m->motor.amplitude at freq_hz: X = (K - w^2 M + i w C)^-1 k_N A e_N. Zero for a wall
 * or free end, which do not drive. Returns 0, -1 on no memory, or LAPACK's info. */
int modes_response(const struct model *m, double freq_hz, double *amp);

#endif
