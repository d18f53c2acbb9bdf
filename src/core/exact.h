/* exact.h: the chain integrated exactly over one smooth piece of the drive, by the
 * matrix exponential of the linear system augmented with the drive's own small linear
 * system (a sine is the output of a rotation, a straight line of a double integrator):
 * exact to rounding at any step. */
#ifndef SPRINGSIM_EXACT_H
#define SPRINGSIM_EXACT_H

#include "model.h"

struct exact;

/* Workspace for chains of n masses, or NULL on no memory (or n out of 1..1000). A chain
 * with Rayleigh's damping (c_i / m_i all equal, cs_j / k_j all equal: the default chain,
 * any undamped one), with or without a force and a damper on the motor's spring, is
 * stepped in its modes (exact_modal.c): n^2 + 393 n doubles, 11 MB at n = 1000. Any other adds, when first stepped, three (2n+2)^2 matrices of scratch and
 * the exponentials of the last steps seen (four steps below n = 418, one above n = 723):
 * 42 KB at n = 10, 160 MB at n = 1000. */
struct exact *exact_new(int n);

/* 1 when m's dampers are proportional to its masses (c_i / m_i all equal to rounding:
 * undamped chains and the default one included), so that exact steps it in its modes,
 * whose cost does not grow with the step lengths it meets; 0 otherwise. */
int exact_proportional(const struct model *m);

/* 1 when exact steps m in its modes (barring a failure of LAPACK there): Rayleigh's
 * damping, a force and a damper on the motor's spring included, and no spring of k = 0;
 * 0 when it takes a dense exponential of order 2N+2. */
int exact_in_modes(const struct model *m);

/* Frees it. */
void exact_free(struct exact *e);

/* 1 when the last step taken went through the modes (exact_modal.c, O(n^2) a step: ground
 * dampers proportional to the masses, or Rayleigh's C = alpha M + beta K), 0 when it took
 * a dense exponential. */
int exact_stepped_in_modes(const struct exact *e);

/* Makes dst (made for the same n) hold what src holds, its cached steps included, so the
 * two step alike. 0, or -1 on no memory (dst then steps afresh). */
int exact_copy(struct exact *dst, const struct exact *src);

/* The right end over the piece: u(t) = amp * sin(omega * t + phi) when sine is set, else
 * u(t) = u0 + du * (t - t0) (a constant or a ramp; 0 for wall and free ends). */
struct exact_drive {
    int sine;                /* 1: the sine form */
    double amp, omega, phi;  /* the sine's amplitude (m), angular frequency, phase (rad) */
    double t0, u0, du;       /* the line's reference time, value and slope */
    double force;            /* F (N): the force input F w on mass m->force_on, 0: none */
    double w0, dw;           /* the line's waveform w and w' at t0 (amplitude 1) */
};

/* Advances displacements x and velocities v (n each) of model m from time a to b with
 * the drive d, in place; adds to *diss the energy dissipated by the dampers, integral of
 * sum c_i v_i^2, and to *work the motor's work, integral of k_N (u - x_N) u', over the
 * piece (both to about 1e-12 relative). 0, or -1 when the exponential fails, b < a, m has
 * another n or a parameter out of range (m, k <= 0, c < 0, not finite; k_N unread for a
 * free end), or the result would not be finite: x, v, *diss and *work are then as they
 * were. a == b does nothing. The drive is read for a motor end only (d may be NULL: u = 0);
 * a jump of u between pieces is the caller's to book (its work is the change of the end
 * spring's energy).
 * Cost, Rayleigh's damping (model_rayleigh; exact_proportional without spring dampers):
 * two N x N by N x 2 products a step, and a new step length (every contact makes one)
 * seven 4 x 4 exponentials a mode;
 * the modes themselves once per model values: a second of motion at dt = 0.01 with
 * collisions 0.15 s at n = 100, 2.2 s at n = 1000 (make bench).
 * Cost, other dampers: a step with the same model values, drive form, omega (sine) and
 * b - a as one of the last few (within 1e-8 / ||A||, the difference corrected to first
 * order: a long run's steps differ by the rounding of its times) is one matrix-vector
 * product and one quadratic form: 0.1 us at n = 2, 0.5 us at n = 10, 47 us at n = 100,
 * 6.5 ms at n = 1000; amplitude, phase, t0, u0 and du may change freely. Any other step
 * takes about eight exponentials of (2n+2)-square matrices from GSL (which allocates
 * inside them): 0.2 ms at n = 10, 33 ms at n = 100, 30 s at n = 1000 at dt = 0.01; each
 * doubling of ||A|| (b - a) past 1/2 adds one exponential and two products. */
int exact_advance(struct exact *e, const struct model *m, const struct exact_drive *d,
                  double a, double b, double *x, double *v, double *diss, double *work);

/* Whether m needs exact_general.c's dense exponential in the chain's own coordinates:
 * spring dampers or a force input with damping other than Rayleigh's, or a spring of
 * k = 0 (a rigid-body mode). */
int exact_needs_general(const struct model *m);

/* exact_advance with the force input's work, integral of F w v_K, added to *fwork too;
 * the motor's work is then integral of (k_N (u - x_N) + cs_N (u' - v_N)) u' and the loss
 * takes the spring dampers' too. For a force, d must give it and, for a line, w0 and dw.
 * With Rayleigh's damping the modes step it (the force d->force); with other spring
 * dampers or ground dampers beside a force, or a spring of k = 0, exact_general.c does
 * (the dense exponential of the chain's first-order system with the drive's, books as
 * quadratic forms; the force m->force, the end's amplitude m->motor.amplitude). */
int exact_advance_all(struct exact *e, const struct model *m, const struct exact_drive *d,
                      double a, double b, double *x, double *v, double *diss, double *work,
                      double *fwork);

#endif
