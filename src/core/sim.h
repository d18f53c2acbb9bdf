/* sim.h: the running simulation: state, fixed-step RK4 split at the motor's
 * breakpoints, collisions and the velocity cap after each step, energy accounting. */
#ifndef SPRINGSIM_SIM_H
#define SPRINGSIM_SIM_H

#include "integrator.h"
#include "model.h"

enum sim_status {
    SIM_OK = 0,       /* the step was taken */
    SIM_NONFINITE = 1 /* the step produced a non-finite number; the state is unchanged */
};

/* Energy accounting, joules. Without collisions or the velocity cap,
 * kinetic + potential + dissipated - motor_work - force_work is constant. */
struct energy {
    double kinetic;    /* sum 1/2 m v^2 */
    double potential;  /* sum 1/2 k stretch^2 */
    double dissipated; /* integral of sum c v^2 + sum cs stretch'^2 dt (every damper) */
    double motor_work; /* integral of T_N u' dt, T_N = k_N (u - d_N) + cs_N (u' - v_N) */
    double force_work; /* integral of F w(2 pi f t) v_K dt: the force input's work */
    double contact;    /* energy removed by collisions and the velocity cap */
    double balance;    /* kinetic + potential + dissipated + contact - motor_work - force_work */
};

struct sim;

/* A simulation of a copy of model with step dt, at rest in equilibrium at t = 0;
 * NULL when memory runs out. */
struct sim *sim_new(const struct model *model, double dt);

/* Makes dst (made for the same n) a copy of src: parameters, integrator, time grid,
 * state, energy books and what the steppers carry from step to step, so that the two go
 * on bit for bit alike while nothing of either is changed. 0, or -1 on no memory with
 * dst as it was. */
int sim_copy(struct sim *dst, const struct sim *src);

/* Frees a simulation. */
void sim_free(struct sim *s);

/* The simulation's own model (read only: change it with sim_set_model). */
const struct model *sim_model(const struct sim *s);

/* Replaces every parameter with those of model (same n); takes effect at the next step. */
void sim_set_model(struct sim *s, const struct model *model);

/* Sets the drive's phase (cycles at t = 0) in the simulation's own model, every other
 * parameter kept: a restart from t = 0 sets it to 0. */
void sim_set_phase(struct sim *s, double phase);

/* Chooses the integrator for the steps from now on (rk4 unless set). */
void sim_set_integrator(struct sim *s, enum integrator i);

/* The integrator in use. */
enum integrator sim_integrator(const struct sim *s);

/* Changes the step; the time so far is kept and later steps lie on t + n*dt. */
void sim_set_dt(struct sim *s, double dt);

/* The step dt (s). */
double sim_dt(const struct sim *s);

/* Restarts at t = 0 from displacements x and velocities v (NULL for zeros), with the
 * energy integrals cleared. */
void sim_reset(struct sim *s, const double *x, const double *v);

/* Advances one step dt. On SIM_NONFINITE the state is left as it was. */
enum sim_status sim_step(struct sim *s);

/* Simulation time t (s). */
double sim_time(const struct sim *s);

/* Displacements d_i (N values). */
const double *sim_x(const struct sim *s);

/* Velocities v_i (N values). */
const double *sim_v(const struct sim *s);

/* Accelerations from the equation of motion at the current state into a (N values). */
void sim_accel(const struct sim *s, double *a);

/* Right-end position u(t) now (0 for wall and free ends). */
double sim_end_position(const struct sim *s);

/* Energy accounting at the current state. */
void sim_energy(const struct sim *s, struct energy *e);

/* Contacts resolved and velocities capped by the last step. */
int sim_last_contacts(const struct sim *s);

/* Velocities capped by the last step (the usual sign of a blow-up). */
int sim_last_capped(const struct sim *s);

/* The contact limits the sim works with (walls, piston, gaps between masses;
 * collision.h). */
struct collision_limits;
const struct collision_limits *sim_limits(const struct sim *s);

/* Number of doubles a snapshot of the state takes. */
int sim_snapshot_size(const struct sim *s);

/* Saves the whole state (time included) into buf. */
void sim_save(const struct sim *s, double *buf);

/* Restores a state saved by sim_save on a simulation with the same n; the drive goes on
 * from the angle it had then (at the frequency in force now). */
void sim_restore(struct sim *s, const double *buf);

#endif
