/* modes.h: natural frequencies and mode shapes of the undamped chain, the modal damping
 * of each, and the steady-state response to a sine drive. */
#ifndef SPRINGSIM_MODES_H
#define SPRINGSIM_MODES_H

#include "model.h"

/* Natural frequencies (Hz, ascending) into freq[N] and, if shapes is not NULL, mode
 * shapes into shapes[j*N + i] (mode j, mass i), each scaled so its largest |component|
 * is 1 and that component is positive. Returns 0, -1 on no memory, -2 when the numbers
 * overflow, or LAPACK's info. */
int modes_compute(const struct model *m, double *freq, double *shapes);

/* The undamped modes with modal damping: w2[j] = omega_j^2 (ascending) and
 * s[j] = phi_j^T C phi_j / (2 phi_j^T M phi_j), so mode j is x'' = -w2 x - 2 s x' when
 * C is diagonal in the modes (LAPACK dstevr, O(N^2)). Returns 0, -1 on no memory, -2
 * when the numbers overflow, or LAPACK's info. */
int modes_modal(const struct model *m, double *w2, double *s);

/* Index of the frequency in f[0..n-1] closest to freq. */
int modes_nearest(const double *f, int n, double freq);

/* Steady-state amplitudes |X_i| (m) of every mass under the sine drive of amplitude
 * m->motor.amplitude at freq_hz: X = (K - w^2 M + i w C)^-1 k_N A e_N. Zero for a wall
 * or free end, which do not drive. Returns 0, -1 on no memory, or LAPACK's info. */
int modes_response(const struct model *m, double freq_hz, double *amp);

#endif
