/* integrator.h: the integrators a run can use (--integrator): their
 * names, orders, and how one step of each acts on a single damped mode, which is what
 * their stability and accuracy limits are measured with. */
#ifndef SPRINGSIM_INTEGRATOR_H
#define SPRINGSIM_INTEGRATOR_H

enum integrator {
    INTEGRATOR_EULER,         /* explicit Euler, order 1 */
    INTEGRATOR_SEMI_IMPLICIT, /* symplectic Euler: v first, then x with the new v; order 1 */
    INTEGRATOR_VERLET,        /* velocity Verlet (half kick, drift, half kick); order 2 */
    INTEGRATOR_RK4,           /* classic Runge-Kutta, order 4 (the default) */
    INTEGRATOR_EXACT,         /* matrix exponential of each smooth piece: exact */
    INTEGRATOR_COUNT
};

/* The integrator's name as --integrator spells it, or NULL. */
const char *integrator_name(enum integrator i);

/* The integrator named by s, or -1. */
int integrator_parse(const char *s);

/* The order of accuracy (0 for exact: no truncation error). */
int integrator_order(enum integrator i);

/* One step h of integrator i on the single mode x'' = -w2 x - 2 s x' (no drive), as the
 * 2x2 matrix M with (x, v)_{n+1} = M (x, v)_n, row-major into m[4]. */
void integrator_mode_step(enum integrator i, double w2, double s, double h, double m[4]);

#endif
