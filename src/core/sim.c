/* sim.c: fixed-step classic RK4 (Runge-Kutta 1901/Kutta; e.g. Hairer, Norsett and
 * Wanner, Solving ODEs I, II.1) on the state y = (d, v, D, W):
 *   d' = v,  v' = a(t, d, v),  D' = sum c_i v_i^2,  W' = k_N (u - d_N) u',
 * so the dissipated energy D and the motor's work W are integrated to the same order
 * as the motion. A step that contains a breakpoint of the waveform is split there into
 * RK4 sub-steps, each evaluating the drive on its own smooth piece, which keeps 4th
 * order for square, triangle and sawtooth drives. Where the drive jumps, the motor does
 * the work 1/2 k_N ((u+ - d_N)^2 - (u- - d_N)^2) in an instant; it is added to W.
 * After each full step: collisions, then the velocity cap. */
#include "sim.h"

#include <float.h>
#include <math.h>
#include <stdbool.h>
#include <stdlib.h>
#include <string.h>

#include "collision.h"

/* Breakpoints inside one step: dt <= 0.05 s and f of a few hertz give at most one, but
 * any number is handled, MAX_SPLIT at a time. */
#define MAX_SPLIT 16

struct sim {
    struct model *model; /* own copy of the parameters */
    int n;               /* masses */
    double dt;           /* step */
    double t_base;       /* time at step 0 of the current dt */
    double steps;        /* whole steps since t_base (exact in a double to 2^53) */
    double contact;      /* energy removed by contacts and the cap */
    int last_contacts;   /* contacts and caps in the last step */
    int last_capped;     /* caps in the last step */
    double *y;           /* 2N+2: d, v, D, W */
    double *y0;          /* state at the start of the step, for restoring */
    double *k1, *k2, *tmp; /* RK4: the stages' running sum, one stage, its argument */
    double *inv_m;       /* 1/m_i */
    double rot_w, rot_h; /* w and h the rotations below were made for */
    double rot_s1, rot_c1, rot_s2, rot_c2; /* sin, cos of w h/2 and of w h */
    double end_u, end_du; /* a sine drive's u and u' at the end of the last sub-step */
    double rot_next_t;   /* where the last sine step ended (NAN: none) */
    double rot_phase;    /* the drive's phase then */
    double rot_sn, rot_cs; /* sin and cos of the drive's angle there */
    int rot_carried;     /* steps since sin and cos were last taken afresh */
    enum integrator integrator; /* the stepper in use */
};

struct sim *sim_new(const struct model *model, double dt)
{
    int n = model->n;
    size_t len = (size_t)(2 * n + 2);
    struct sim *s = calloc(1, sizeof *s);
    if (!s)
        return NULL;
    s->model = model_new(n);
    s->y = calloc(5 * len + (size_t)n, sizeof *s->y);
    if (!s->model || !s->y) {
        sim_free(s);
        return NULL;
    }
    s->n = n;
    s->y0 = s->y + len;
    s->k1 = s->y0 + len;
    s->k2 = s->k1 + len;
    s->tmp = s->k2 + len;
    s->inv_m = s->tmp + len;
    s->dt = dt;
    s->integrator = INTEGRATOR_RK4;
    sim_set_model(s, model);
    return s;
}

void sim_free(struct sim *s)
{
    if (!s)
        return;
    model_free(s->model);
    free(s->y);
    free(s);
}

const struct model *sim_model(const struct sim *s)
{
    return s->model;
}

void sim_set_model(struct sim *s, const struct model *model)
{
    model_copy(s->model, model);
    for (int i = 0; i < s->n; i++)
        s->inv_m[i] = 1.0 / s->model->m[i];
}

void sim_set_integrator(struct sim *s, enum integrator i)
{
    s->integrator = i;
}

enum integrator sim_integrator(const struct sim *s)
{
    return s->integrator;
}

double sim_time(const struct sim *s)
{
    return s->t_base + s->steps * s->dt;
}

void sim_set_dt(struct sim *s, double dt)
{
    s->t_base = sim_time(s);
    s->steps = 0.0;
    s->dt = dt;
}

double sim_dt(const struct sim *s)
{
    return s->dt;
}

void sim_reset(struct sim *s, const double *x, const double *v)
{
    int n = s->n;
    memset(s->y, 0, (size_t)(2 * n + 2) * sizeof *s->y);
    if (x)
        memcpy(s->y, x, (size_t)n * sizeof *x);
    if (v)
        memcpy(s->y + n, v, (size_t)n * sizeof *v);
    s->t_base = 0.0;
    s->steps = 0.0;
    s->contact = 0.0;
    s->last_contacts = 0;
    s->last_capped = 0;
}

/* dy/dt at state y with the right end at u moving at du. */
static void deriv(const struct sim *s, const double *y, double u, double du, double *dy)
{
    const struct model *m = s->model;
    int n = s->n;
    const double *x = y, *v = y + n;
    const double *k = m->k, *c = m->c;
    double *dx = dy, *dv = dy + n;
    double left = k[0] * x[0], diss = 0.0;

    for (int i = 0; i < n - 1; i++) {
        double right = k[i + 1] * (x[i + 1] - x[i]);
        double fd = c[i] * v[i];
        dx[i] = v[i];
        dv[i] = (right - left - fd) * s->inv_m[i];
        diss += fd * v[i];
        left = right;
    }
    int i = n - 1;
    double right = 0.0, work = 0.0;
    if (m->boundary != BOUNDARY_FREE) {
        right = k[n] * (u - x[i]);
        work = right * du;
    }
    double fd = c[i] * v[i];
    dx[i] = v[i];
    dv[i] = (right - left - fd) * s->inv_m[i];
    dy[2 * n] = diss + fd * v[i];
    dy[2 * n + 1] = work;
}

/* The sine drive u = A sin(th), du = A w cos(th) at a, a + h/2 and a + h, with one
 * sincos: sin and cos at the later times follow from the angle-addition formulas with
 * sin, cos of w h/2 and w h, kept while w and h stay the same. Exact to a few ulp. */
static void sine_drive(struct sim *s, double a, double b, double *u0, double *du0,
                       double *um, double *dum, double *u1, double *du1)
{
    double h = b - a;
    const struct motor *mot = &s->model->motor;
    double w = 2.0 * M_PI * mot->frequency, amp = mot->amplitude;
    /* b - a of a grid step differs from dt by the rounding of t (a few ulp of b, which
     * grow with t): such a step keeps the rotation made for dt, an angle error no larger
     * than that rounding makes anyway. */
    if (fabs(h - s->dt) <= 1e-12 * s->dt + 8.0 * DBL_EPSILON * fabs(b))
        h = s->dt;
    if (w != s->rot_w || h != s->rot_h) {
        sincos(0.5 * w * h, &s->rot_s1, &s->rot_c1);
        sincos(w * h, &s->rot_s2, &s->rot_c2);
        s->rot_w = w;
        s->rot_h = h;
        s->rot_next_t = NAN; /* nothing to carry over */
    }
    double sn, cs;
    if (a == s->rot_next_t && mot->phase == s->rot_phase && s->rot_carried < 64) {
        /* This step starts where the last ended: carry its sin and cos over, and only
         * every 64 steps take them afresh, so rounding cannot build up. */
        sn = s->rot_sn, cs = s->rot_cs;
        s->rot_carried++;
    } else {
        sincos(w * a + 2.0 * M_PI * mot->phase, &sn, &cs);
        s->rot_carried = 0;
    }
    double sm = sn * s->rot_c1 + cs * s->rot_s1, cm = cs * s->rot_c1 - sn * s->rot_s1;
    double se = sn * s->rot_c2 + cs * s->rot_s2, ce = cs * s->rot_c2 - sn * s->rot_s2;
    s->rot_next_t = b;
    s->rot_phase = mot->phase;
    s->rot_sn = se, s->rot_cs = ce;
    *u0 = amp * sn, *du0 = amp * w * cs;
    *um = amp * sm, *dum = amp * w * cm;
    *u1 = amp * se, *du1 = amp * w * ce;
}

/* y += h/6 (k1 + 2 k2 + 2 k3 + k4) over [a, b] with the drive taken from one piece. */
static void rk4(struct sim *s, double a, double b, const struct motor_piece *piece)
{
    int len = 2 * s->n + 2;
    double h = b - a, h2 = 0.5 * h;
    double u0 = 0, du0 = 0, um = 0, dum = 0, u1 = 0, du1 = 0;
    double *y = s->y, *tmp = s->tmp, *k1 = s->k1, *k2 = s->k2;

    const struct model *m = s->model;
    if (m->boundary == BOUNDARY_MOTOR && m->motor.wave == WAVE_SINE) {
        sine_drive(s, a, b, &u0, &du0, &um, &dum, &u1, &du1);
        s->end_u = u1;
        s->end_du = du1;
    } else if (m->boundary == BOUNDARY_MOTOR) {
        motor_piece_eval(piece, a, &u0, &du0);
        motor_piece_eval(piece, a + h2, &um, &dum);
        motor_piece_eval(piece, b, &u1, &du1);
    }
    /* The sum k1 + 2 k2 + 2 k3 + k4 builds up in acc as the stages come, each loop also
     * making the next stage's argument: four passes over the state instead of seven. */
    double *acc = k1, *k = k2;
    deriv(s, y, u0, du0, acc);
    for (int i = 0; i < len; i++)
        tmp[i] = y[i] + h2 * acc[i];
    deriv(s, tmp, um, dum, k);
    for (int i = 0; i < len; i++) {
        acc[i] += 2.0 * k[i];
        tmp[i] = y[i] + h2 * k[i];
    }
    deriv(s, tmp, um, dum, k);
    for (int i = 0; i < len; i++) {
        acc[i] += 2.0 * k[i];
        tmp[i] = y[i] + h * k[i];
    }
    deriv(s, tmp, u1, du1, k);
    double h6 = h / 6.0;
    for (int i = 0; i < len; i++)
        y[i] += h6 * (acc[i] + k[i]);
}

/* Work done by the motor when the end jumps from u_from to u_to with the last mass at
 * displacement x: the change of spring N's energy, 1/2 k_N ((u_to-x)^2 - (u_from-x)^2). */
static double jump_work(const struct sim *s, double u_from, double u_to)
{
    double x = s->y[s->n - 1];
    double a = u_from - x, b = u_to - x;
    return 0.5 * s->model->k[s->n] * (b * b - a * a);
}

/* Integrates from t0 to t1 in pieces split at the motor's breakpoints. */
static void advance(struct sim *s, double t0, double t1)
{
    const struct model *m = s->model;
    const struct motor *mot = &m->motor;
    struct motor_piece piece;
    double cuts[MAX_SPLIT];

    if (m->boundary != BOUNDARY_MOTOR || mot->wave == WAVE_SINE || mot->amplitude == 0.0) {
        /* One smooth piece: the sine needs no piece; the others a constant one. */
        if (m->boundary == BOUNDARY_MOTOR && mot->wave != WAVE_SINE)
            motor_piece_at(mot, 0.5 * (t0 + t1), &piece);
        rk4(s, t0, t1, &piece);
        return;
    }
    int jumps = motor_has_jumps(mot->wave);
    double *work = &s->y[2 * s->n + 1];
    double u_now = jumps ? motor_position(mot, t0) : 0.0; /* the end's position now */
    double a = t0;
    while (a < t1) {
        /* Up to MAX_SPLIT breakpoints at a time; after the last of a full batch, the
         * next batch is looked up from there. */
        int nb = motor_breakpoints(mot, a, t1, cuts, MAX_SPLIT);
        bool more = nb > MAX_SPLIT;
        if (more)
            nb = MAX_SPLIT;
        for (int j = 0; j < nb + !more; j++) {
            double b = j < nb ? cuts[j] : t1;
            motor_piece_at(mot, 0.5 * (a + b), &piece);
            if (jumps) {
                double ua, ub, du;
                motor_piece_eval(&piece, a, &ua, &du);
                *work += jump_work(s, u_now, ua);
                rk4(s, a, b, &piece);
                motor_piece_eval(&piece, b, &ub, &du);
                u_now = ub;
            } else {
                rk4(s, a, b, &piece);
            }
            a = b;
        }
    }
    if (jumps)
        *work += jump_work(s, u_now, motor_position(mot, t1));
}

static int all_finite(const double *y, int len)
{
    for (int i = 0; i < len; i++)
        if (!isfinite(y[i]))
            return 0;
    return 1;
}

/* Kinetic plus potential energy of a state (d, v) with the end at u. */
static double mechanical(const struct sim *s, const double *y, double u)
{
    return model_kinetic(s->model, y + s->n) + model_potential(s->model, y, u);
}

enum sim_status sim_step(struct sim *s)
{
    int n = s->n, len = 2 * n + 2;
    const struct model *m = s->model;
    double t0 = sim_time(s);
    double t1 = s->t_base + (s->steps + 1.0) * s->dt;

    memcpy(s->y0, s->y, (size_t)len * sizeof *s->y);
    advance(s, t0, t1);
    if (!all_finite(s->y, len)) {
        memcpy(s->y, s->y0, (size_t)len * sizeof *s->y);
        return SIM_NONFINITE;
    }
    s->steps += 1.0;

    double u = 0.0, du = 0.0;
    if (m->boundary == BOUNDARY_MOTOR && m->motor.wave == WAVE_SINE) {
        /* The last sub-step ended at t1 and left the piston's position and velocity. */
        u = s->end_u;
        du = s->end_du;
    } else if (m->boundary == BOUNDARY_MOTOR) {
        struct motor_piece piece;
        double u_left;
        /* The piston's velocity just before t1, its position at t1. */
        motor_piece_at(&m->motor, t1 - 1e-6 * s->dt, &piece);
        motor_piece_eval(&piece, t1, &u_left, &du);
        u = motor_position(&m->motor, t1);
    }
    s->last_contacts = s->last_capped = 0;
    if (!collision_needed(m, s->y, s->y + n, u))
        return SIM_OK;
    /* Keep the state before contacts so their energy can be booked. */
    memcpy(s->tmp, s->y, (size_t)(2 * n) * sizeof *s->y);
    int contacts = collision_apply(m, s->y, s->y + n, u, du);
    s->last_capped = collision_cap(n, s->y + n);
    contacts += s->last_capped;
    if (contacts)
        s->contact += mechanical(s, s->tmp, u) - mechanical(s, s->y, u);
    s->last_contacts = contacts;
    return SIM_OK;
}

const double *sim_x(const struct sim *s)
{
    return s->y;
}

const double *sim_v(const struct sim *s)
{
    return s->y + s->n;
}

double sim_end_position(const struct sim *s)
{
    return model_end_position(s->model, sim_time(s));
}

void sim_accel(const struct sim *s, double *a)
{
    model_accel(s->model, s->y, s->y + s->n, sim_end_position(s), a);
}

void sim_energy(const struct sim *s, struct energy *e)
{
    double u = sim_end_position(s);
    e->kinetic = model_kinetic(s->model, s->y + s->n);
    e->potential = model_potential(s->model, s->y, u);
    e->dissipated = s->y[2 * s->n];
    e->motor_work = s->y[2 * s->n + 1];
    e->contact = s->contact;
    e->balance = e->kinetic + e->potential + e->dissipated + e->contact - e->motor_work;
}

int sim_last_contacts(const struct sim *s)
{
    return s->last_contacts;
}

int sim_last_capped(const struct sim *s)
{
    return s->last_capped;
}

int sim_snapshot_size(const struct sim *s)
{
    return 2 * s->n + 2 + 6;
}

/* The drive's angle (cycles, in [0, 1)) at time t. */
static double drive_cycles(const struct motor *m, double t)
{
    double c = m->frequency * t + m->phase;
    return c - floor(c);
}

void sim_save(const struct sim *s, double *buf)
{
    int len = 2 * s->n + 2;
    buf[0] = s->t_base;
    buf[1] = s->steps;
    buf[2] = s->dt;
    buf[3] = s->contact;
    buf[4] = s->last_contacts;
    buf[5] = drive_cycles(&s->model->motor, sim_time(s));
    memcpy(buf + 6, s->y, (size_t)len * sizeof *buf);
}

void sim_restore(struct sim *s, const double *buf)
{
    int len = 2 * s->n + 2;
    s->t_base = buf[0];
    s->steps = buf[1];
    s->dt = buf[2];
    s->contact = buf[3];
    s->last_contacts = (int)buf[4];
    memcpy(s->y, buf + 6, (size_t)len * sizeof *buf);
    /* The drive goes on from the angle it had then, at the frequency in force now: if the
     * frequency changed since, the phase is re-anchored so the piston does not jump. */
    struct motor *m = &s->model->motor;
    double p = buf[5] - m->frequency * sim_time(s);
    m->phase = p - floor(p);
}
