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

/* Steady-state amplitudes |X_i| (m) of every mass under the sine drive at freq_hz, the
 * motor's amplitude A and the force's F together: X = (K - w^2 M + i w C)^-1 G,
 * G = (k_N + i w cs_N) A e_N (a motor end) + F e_K. Another waveform: the response to its
 * fundamental (motor_fundamental times A and F), the first harmonic of the motion. Zero
 * for a wall or free end without a force, which nothing drives. Returns 0, -1 on no
 * memory, or LAPACK's info. */
int modes_response(const struct model *m, double freq_hz, double *amp);

/* As modes_response, with the phase of each mass's displacement relative to the drive's
 * sine (the motor's displacement and the force share it) in degrees, in (-180, 180] (a
 * lag is negative), into phase_deg unless it is NULL. Undriven, amplitude 0 and phase 0. */
int modes_response_phase(const struct model *m, double freq_hz, double *amp, double *phase_deg);

/* Damping of each undamped mode j (ascending frequency, as modes_compute, whose shapes
 * these are): the damped first-order system's eigenvalues (LAPACK dgeev with right
 * eigenvectors, for every N; the modal damping of modes_modal where it is exact),
 * paired with the undamped modes by the largest overlap |phi_j^T M psi| of shapes, each
 * eigen pair used once. ratio[j] = zeta_j = -Re(lambda) / |lambda| for a complex pair,
 * damped_hz[j] = |Im lambda| / 2 pi; for two real eigenvalues (overdamped)
 * zeta = -(l1 + l2) / (2 sqrt(l1 l2)) >= 1 and damped_hz[j] = 0. Returns 0, -1 on no
 * memory, -2 when the numbers overflow (or do not pair), or LAPACK's info. */
int modes_damped(const struct model *m, const double *shapes, double *ratio, double *damped_hz);

/* As modes_damped, with each mode's eigen frequency (Hz) into eigen: |lambda| / 2 pi of
 * its pair, sqrt(l1 l2) / 2 pi of its two real eigenvalues (the undamped frequency where
 * C is Rayleigh's). The dense eigen-solve is taken for every N unless C = alpha M +
 * beta K (model_rayleigh), whose modal answer is exact; a rigid-body mode (0 Hz) has
 * ratio NAN and frequencies 0. */
int modes_damped_all(const struct model *m, const double *shapes, double *ratio,
                     double *damped_hz, double *eigen);

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
