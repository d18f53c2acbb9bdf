/* modes.h: natural frequencies and mode shapes of the undamped chain, the damping of
 * each, the energy in each, a start along one, and the steady-state response (amplitude
 * and phase) to a sine drive. */
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

/* As modes_response, with the phase of each mass's displacement relative to the motor's
 * displacement in degrees, in (-180, 180] (a lag is negative), into phase_deg unless it is
 * NULL. For a wall or free end, amplitude 0 and phase 0. */
int modes_response_phase(const struct model *m, double freq_hz, double *amp, double *phase_deg);

/* Damping of each undamped mode j (ascending frequency, as modes_compute, whose shapes
 * these are): the damped first-order system's eigenvalues (LAPACK dgeev with right
 * eigenvectors, up to LIMITS_DGEEV_MAX masses; above it the modal damping of modes_modal),
 * paired with the undamped modes by the largest overlap |phi_j^T M psi| of shapes, each
 * eigen pair used once. ratio[j] = zeta_j = -Re(lambda) / |lambda| for a complex pair,
 * damped_hz[j] = |Im lambda| / 2 pi; for two real eigenvalues (overdamped)
 * zeta = -(l1 + l2) / (2 sqrt(l1 l2)) >= 1 and damped_hz[j] = 0. Returns 0, -1 on no
 * memory, -2 when the numbers overflow (or do not pair), or LAPACK's info. */
int modes_damped(const struct model *m, const double *shapes, double *ratio, double *damped_hz);

/* Energy of each mode in the state (x, v) (displacements from equilibrium, right end at
 * rest): with mass-normalised shapes phi^_j = phi_j / sqrt(phi_j^T M phi_j),
 * q_j = phi^_j^T M x, p_j = phi^_j^T M v, energy[j] = (p_j^2 + w_j^2 q_j^2) / 2,
 * w_j = 2 pi freq[j]; freq and shapes are modes_compute's. They sum to the chain's kinetic
 * and spring energy. No allocation: callable every frame. */
void modes_energy(const struct model *m, const double *freq, const double *shapes,
                  const double *x, const double *v, double *energy);

/* Initial displacements x0[N] along mode k (1-based, from 1 to N): amp times its shape as
 * modes_compute scales it (largest |component| 1, positive), so max |x0| = amp. Returns 0,
 * -2 when k is out of range, or modes_compute's error. */
int modes_start(const struct model *m, int k, double amp, double *x0);

#endif
