/* model.h: the chain's parameters and its equations of motion. */
#ifndef SPRINGSIM_MODEL_H
#define SPRINGSIM_MODEL_H

#include <stdbool.h>

#include "motor.h"

#define MODEL_MAX_MASSES 1000 /* the core takes 1..1000 masses */
#define MODEL_LENGTH 10.0     /* L: left wall at 0, right end's base at L (m) */
#define MODEL_BLOCK 0.4       /* block width w unless half the spacing is smaller (m) */
#define MODEL_RESTITUTION 0.8 /* e for walls, piston and mass-mass contacts */
#define MODEL_VMAX 50.0       /* velocity cap (m/s) */

/* The page's chain, model_new's values and the settings table's defaults. */
#define MODEL_DEFAULT_MASS 1.0       /* kg */
#define MODEL_DEFAULT_SPRING 10.0    /* N/m */
#define MODEL_DEFAULT_DAMPING 0.1    /* N s/m */
#define MODEL_DEFAULT_AMPLITUDE 0.1  /* m */
#define MODEL_DEFAULT_FREQUENCY 1.0  /* Hz */

enum boundary { BOUNDARY_MOTOR, BOUNDARY_WALL, BOUNDARY_FREE, BOUNDARY_COUNT };

struct model {
    int n;                   /* number of masses N */
    double *m;               /* N masses (kg) */
    double *k;               /* N+1 spring constants (N/m); k[N] joins mass N to the right end */
    double *c;               /* N damping coefficients (N s/m), each mass to the ground */
    double *cs;              /* N+1 spring dampers (N s/m): cs[j] beside spring j, on the
                                rate of its stretch (the walls' and the motor's included) */
    double *k3;              /* N+1 cubic spring constants (N/m^3): force k s + k3 s^3 */
    double force;            /* F (N): a force F w(2 pi f t) on mass force_on, the motor's
                                waveform and frequency; 0: none */
    int force_on;            /* the mass the force acts on, 0-based (0 .. N-1) */
    bool spring_damped;      /* some cs[j] > 0: model_rates takes the general path
                                (model_sync sets it) */
    bool cubic;              /* some k3 is not 0 (model_sync or model_set_cubic): the
                                chain is nonlinear */
    enum boundary boundary;  /* right end */
    struct motor motor;      /* drive, used when boundary is BOUNDARY_MOTOR */
    bool collisions;         /* walls, piston and mass-mass contacts on */
};

/* A model of n masses with the page's defaults (1 kg, 10 N/m, 0.1 N s/m, motor,
 * sine 0.1 m 1 Hz), or NULL when n is out of range or memory runs out. */
struct model *model_new(int n);

/* Frees a model from model_new. */
void model_free(struct model *m);

/* Copies every parameter of src into dst; both must have the same n. */
void model_copy(struct model *dst, const struct model *src);

/* Sets m->spring_damped from m->cs and m->cubic from m->k3: call it after changing
 * them by hand. */
void model_sync(struct model *m);

/* How many rigid-body modes m has (0 Hz): the groups of masses joined by springs of
 * k > 0 that no such spring ties to the wall or to the right end (a motor or a wall). */
int model_rigid_modes(const struct model *m);

/* Whether m's damping is Rayleigh's, C = alpha M + beta K (to rounding): c_i / m_i the
 * same for every mass and cs_j / k_j the same for every spring there is (cs_j = 0 where
 * k_j = 0). Undamped chains and ground dampers proportional to the masses are. Such a C
 * is diagonal in the undamped modes: 2 zeta_j omega_j = alpha + beta omega_j^2. */
bool model_rayleigh(const struct model *m);

/* Whether m has a force input (F != 0). */
bool model_forced(const struct model *m);

/* Whether m's right end is a motor that moves (A != 0). */
bool model_motor_moves(const struct model *m);

/* Whether m's right end or its force moves anything: a motor end with A != 0, or F != 0. */
bool model_driven(const struct model *m);

/* model_rates' general path, for chains with spring dampers (model_rates calls it); each
 * spring's force model_spring_force, so cubic springs beside dampers are right too. */
void model_rates_damped_springs(const struct model *m, const double *inv_m, const double *x,
                                const double *v, double u, double du, double *a, double *diss,
                                double *work);

/* Equilibrium position of mass i (0-based), metres from the left wall. */
double model_equilibrium(const struct model *m, int i);

/* Block width w: 0.4 m, or half the equilibrium spacing if that is smaller. */
double model_block_width(const struct model *m);

/* Right-end position u(t): the motor's for BOUNDARY_MOTOR, 0 otherwise. */
double model_end_position(const struct model *m, double t);

/* The force of spring j stretched by s: k_j s + k3_j s^3. */
static inline double model_spring_force(const struct model *m, int j, double s)
{
    return m->cubic ? (m->k[j] + m->k3[j] * s * s) * s : m->k[j] * s;
}

/* The energy of spring j stretched by s: k_j s^2/2 + k3_j s^4/4. */
static inline double model_spring_energy(const struct model *m, int j, double s)
{
    double e = 0.5 * m->k[j] * s * s;
    return m->cubic ? e + 0.25 * m->k3[j] * s * s * s * s : e;
}

/* model_rates for a chain with cubic springs (model.c): the same equation, each spring's
 * force k s + k3 s^3. */
void model_rates_cubic(const struct model *m, const double *inv_m, const double *x,
                       const double *v, double u, double du, double *a, double *diss,
                       double *work);

/* The one equation of motion: accelerations a[i] at displacements x,
 * velocities v and right end u moving at du; with diss and work not NULL, also the power
 * the dampers take (sum c_i v_i^2 + sum cs_j (stretch rate_j)^2) and the power the motor
 * gives (k_N (u - x_N) + cs_N (du - v_N)) du. The force input is not in it: its value
 * depends on time, and the stepper adds it (F w / m_K on mass K). inv_m (1/m_i) saves the
 * divisions where a caller keeps it; NULL divides. Inline: it is the inner loop of every
 * stepper; a chain with spring dampers takes the general path, out of line. */
__attribute__((always_inline)) static inline void
model_rates(const struct model *m, const double *inv_m, const double *x, const double *v, double u,
            double du, double *a, double *diss, double *work)
{
    if (m->spring_damped) {
        model_rates_damped_springs(m, inv_m, x, v, u, du, a, diss, work);
        return;
    }
    if (m->cubic) {
        model_rates_cubic(m, inv_m, x, v, u, du, a, diss, work);
        return;
    }
    int n = m->n;
    const double *k = m->k, *c = m->c;
    /* Force of spring j is k_j * stretch_j, stretch_j = (right end) - (left end). */
    double left = k[0] * x[0], d = 0.0;
    for (int i = 0; i < n - 1; i++) {
        double right = k[i + 1] * (x[i + 1] - x[i]);
        double fd = c[i] * v[i];
        a[i] = inv_m ? (right - left - fd) * inv_m[i] : (right - left - fd) / m->m[i];
        d += fd * v[i];
        left = right;
    }
    int i = n - 1;
    double right = m->boundary == BOUNDARY_FREE ? 0.0 : k[n] * (u - x[i]);
    double fd = c[i] * v[i];
    a[i] = inv_m ? (right - left - fd) * inv_m[i] : (right - left - fd) / m->m[i];
    if (diss)
        *diss = d + fd * v[i];
    if (work)
        *work = right * du;
}

/* model_rates' accelerations of masses lo..hi only, each the same bits (inv_m NULL); the
 * other values of a are left as they were. */
void model_accel_span(const struct model *m, const double *x, const double *v, double u,
                      double du, int lo, int hi, double *a);

/* Accelerations a[i] from the equation of motion at displacements x, velocities v and
 * right-end position u (ignored for BOUNDARY_FREE). */
void model_accel(const struct model *m, const double *x, const double *v, double u, double *a);

/* The force input's value F w(2 pi (f t + phase)) at time t (0 without one). */
double model_force(const struct model *m, double t);

/* Spring potential energy sum k_j s_j^2/2 + k3_j s_j^4/4 (s_j spring j's stretch) at
 * displacements x, end position u. */
double model_potential(const struct model *m, const double *x, double u);

/* Kinetic energy sum 1/2 m_i v_i^2. */
double model_kinetic(const struct model *m, const double *v);

/* The smallest stretch (m) at which a softening spring's force k s + k3 s^3 turns over
 * (its stiffness k + 3 k3 s^2 reaches 0: s = sqrt(k / (3 |k3|))), its spring into *spring;
 * INFINITY when no spring softens. */
double model_turnover(const struct model *m, int *spring);

/* Whether some spring hardens (k3 > 0). */
bool model_hardening(const struct model *m);

/* Sets m->cubic from m->k3 (after the k3 are written). */
void model_set_cubic(struct model *m);

/* The first-order matrix A = [[0, I], [-M^-1 K, -M^-1 C]] of z' = A z, z = (x, v), with
 * the right end held at 0 (a chain with cubic springs linearised at rest): 2N x 2N,
 * column-major, into a; work holds 3N doubles.
 * Returns 0, or -2 when an entry overflows. */
int model_first_order(const struct model *m, double *a, double *work);

/* The boundary's name ("motor", ...), or NULL. */
const char *model_boundary_name(enum boundary b);

/* The boundary named by s, or -1. */
int model_boundary_parse(const char *s);

#endif
