/* stepper.h: the steppers behind one interface (GSL odeiv2's "step" layer): each advances
 * the state y = (x, v, D, W, P) of a chain, D the energy the dampers took, W the work
 * the motor did and P the force input's, over one smooth piece of the drive. The driver (sim.c) owns the time
 * grid, breakpoints, contacts and energy books. */
#ifndef SPRINGSIM_STEPPER_H
#define SPRINGSIM_STEPPER_H

#include "integrator.h"
#include "model.h"

/* The drive over one smooth piece: the right end u = amp w and the force F w, w the
 * motor's waveform (DRIVE_NONE when neither moves anything). */
struct drive {
    enum { DRIVE_NONE, DRIVE_SINE, DRIVE_PIECE } kind;
    const struct motor *motor; /* the waveform, frequency and phase */
    struct motor_piece piece;  /* DRIVE_PIECE: a constant or a ramp */
    double amp;                /* the right end's amplitude: A for a motor end, else 0 */
    double force;              /* F (N) on mass force_on, 0: none */
    int force_on;              /* 0-based */
};

/* The length of a stepper's state y for n masses: x, v, D, W, P. */
#define STEPPER_LEN(n) (2 * (n) + 3)

/* The drive for the piece of model m's right end that contains time t (pass a time
 * inside the piece, not on a breakpoint). Inline: every step takes one. */
static inline void drive_at(struct drive *d, const struct model *m, double t)
{
    d->motor = &m->motor;
    d->amp = m->boundary == BOUNDARY_MOTOR ? m->motor.amplitude : 0.0;
    d->force = m->force;
    d->force_on = m->force_on;
    if (d->amp == 0.0 && d->force == 0.0) {
        d->kind = DRIVE_NONE;
    } else if (m->motor.wave == WAVE_SINE) {
        d->kind = DRIVE_SINE;
    } else {
        d->kind = DRIVE_PIECE;
        motor_piece_at(&m->motor, t, &d->piece);
    }
}

/* u'' on the piece is drive_ddu_factor(d) u: a sine's -w^2, 0 for constants and ramps. */
double drive_ddu_factor(const struct drive *d);

/* u(t) and u'(t) on the piece. */
void drive_eval(const struct drive *d, double t, double *u, double *du);

/* The waveform w(t) and w'(t) on the piece, amplitude 1 (0 for DRIVE_NONE). */
void drive_unit(const struct drive *d, double t, double *w, double *dw);

/* The force F w(t) on the piece (0 without a force). */
double drive_force(const struct drive *d, double t);

/* The piece's drive in exact.c's terms (exact.h), its line referred to time a. */
struct exact_drive;
void drive_exact(const struct drive *d, double a, struct exact_drive *ed);

struct stepper;

/* Scratch and caches for chains of model's size, or NULL on no memory. */
struct stepper *stepper_new(const struct model *m);

/* Frees it. */
void stepper_free(struct stepper *st);

/* Takes model m's parameters (same n) for the steps from now on; dt is the grid step,
 * which a sine drive's rotations are made for. */
void stepper_set_model(struct stepper *st, const struct model *m, double dt);

/* Advances y (STEPPER_LEN(N) values) from time a to b on drive d with integrator i: 0, or -1 when
 * the exact stepper's exponential fails. */
int stepper_apply(struct stepper *st, enum integrator i, const struct drive *d, double a,
                  double b, double *y);

/* The drive (u, u') at the end of the last step taken: a sine's costs no sincos. */
void stepper_end_drive(const struct stepper *st, double *u, double *du);

/* The drive at the start of the last step taken. */
void stepper_start_drive(const struct stepper *st, double *u, double *du);

struct rest;
/* Resting contacts to hold as constraints in every step from now on (NULL: none); the
 * stepper reads them, the caller keeps them. */
void stepper_set_rest(struct stepper *st, const struct rest *r);

/* Classic RK4 over [a, b] on drive d, as stepper_apply takes it (the stages folded
 * together, no copies: the common step as cheap as a hand-written loop). Returns what
 * it found on the state it made (STEPPER_NONFINITE, STEPPER_OVER_CAP), looked at as it
 * was made. */
int stepper_rk4(struct stepper *st, const struct drive *d, double a, double b, double *y);

/* stepper_rk4's findings on the state it made, or'd together (0: neither). */
enum {
    STEPPER_NONFINITE = 1, /* some value of y is an infinity or a NaN */
    STEPPER_OVER_CAP = 2   /* some |v_i| > MODEL_VMAX (meant when all are finite) */
};

/* What the last stepper_rk4 did: the drive at its start and end, the largest change of an
 * x_i and the largest |v_i| at its end (as stored; a NaN is passed by). */
struct stepper_reach {
    double ua, dua, ub, dub;
    double dx, v;
};
void stepper_rk4_reach(const struct stepper *st, struct stepper_reach *r);

/* Puts the sine drive's carried angle back as it was before the last stepper_rk4, so that
 * the step can be taken again another way with the same bits. */
void stepper_undo_rk4(struct stepper *st);

/* Sets the drive's phase (cycles) in the stepper's model; dt as for stepper_set_model. */
void stepper_set_phase(struct stepper *st, double phase, double dt);

/* Makes dst (same n) step as src does: its parameters, grid step, the sine drive's
 * carried sin and cos and the exact stepper's cached steps. 0, or -1 on no memory (for
 * that cache; dst is then as it was). */
int stepper_copy(struct stepper *dst, const struct stepper *src);

/* The model the stepper uses (its own copy). */
const struct model *stepper_model(const struct stepper *st);

/* 1 / m_i, kept by the stepper. */
const double *stepper_inv_m(const struct stepper *st);

#endif
