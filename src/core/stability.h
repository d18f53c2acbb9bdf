/* stability.h: stability limits of long chains without a 2N x 2N eigenproblem along h
 * (core/limits.c uses them above ONESTEP_MAX masses). M and C are diagonal, K symmetric
 * tridiagonal; every eigenvalue mu of a step of semi-implicit or verlet that lies on
 * the unit circle is +-1 (or belongs to a mode no damper touches), so the first unstable
 * step is where mu = -1 first appears; euler's and rk4's steps are R(h lambda) for the
 * eigenvalues lambda of the chain, which lie in a region known from M, C and K. */
#ifndef SPRINGSIM_STABILITY_H
#define SPRINGSIM_STABILITY_H

#include "model.h"

/* Semi-implicit (symplectic) Euler: the first h > 0 at which h^2 K + 2 h C - 4 M is
 * singular (mu = -1), by bisection on its inertia (LDL^T of a tridiagonal, O(N)).
 * INFINITY when there is none (no spring acts). */
double stability_semi_implicit(const struct model *m);

/* Velocity Verlet with the damping of the last half kick implicit: mu = -1 exactly when
 * h^2 K x = 4 M x, so 2 / omega_max, omega_max the undamped chain's highest angular
 * frequency (w2_max its square). */
double stability_verlet(double w2_max);

/* Modes (w2[k], s[k]) of x'' = -w2 x - 2 s x' sampled on the boundary of the set that
 * holds every eigenvalue of the chain: each solves lambda^2 + g lambda + w = 0 with
 * g = x*Cx / x*Mx between the least and largest c_i / m_i and w = x*Kx / x*Mx between
 * w2_min and w2_max (x its eigenvector). By the maximum principle a polynomial R has
 * |R(h lambda)| <= 1 on the whole set when it has on these modes (to the sampling).
 * count >= 16 modes are written; returns count. */
int stability_region_modes(const struct model *m, double w2_min, double w2_max, int count,
                           double *w2, double *s);

#endif
