/* sim.c: the driver (GSL odeiv2's "driver" layer): the simulation object, its time grid
 * t = t_base + n dt, its accessors, the energy books read out, and snapshots. The step
 * itself (pieces between the drive's breakpoints, contacts located inside them) is
 * sim_step.c's; this file calls nothing there. */
#include "sim.h"

#include <math.h>
#include <stdbool.h>
#include <stdlib.h>
#include <string.h>

#include "sim_state.h"

struct sim *sim_new(const struct model *model, double dt)
{
    int n = model->n;
    size_t len = (size_t)STEPPER_LEN(n);
    struct sim *s = calloc(1, sizeof *s);
    if (!s)
        return NULL;
    s->st = stepper_new(model);
    s->y = calloc(3 * len + (size_t)(3 * n + 1), sizeof *s->y);
    s->rest = rest_new(n);
    if (!s->st || !s->y || !s->rest) {
        sim_free(s);
        return NULL;
    }
    s->n = n;
    s->y0 = s->y + len;
    s->ya_buf = s->y0 + len;
    s->ya = s->ya_buf;
    s->work = s->ya_buf + len;
    s->force = s->work + 2 * n;
    stepper_set_rest(s->st, s->rest);
    s->rest->enabled = true;
    s->dt = dt;
    s->integrator = INTEGRATOR_RK4;
    sim_set_model(s, model);
    return s;
}

int sim_copy(struct sim *dst, const struct sim *src)
{
    clearance_forget(&dst->clear);
    if (stepper_copy(dst->st, src->st) != 0)
        return -1;
    dst->lim = src->lim;
    dst->dt = src->dt;
    dst->t_base = src->t_base;
    dst->steps = src->steps;
    dst->integrator = src->integrator;
    dst->contact = src->contact;
    dst->last_contacts = src->last_contacts;
    dst->sine_err = src->sine_err;
    dst->last_capped = src->last_capped;
    rest_copy(dst->rest, src->rest);
    memcpy(dst->y, src->y, (size_t)STEPPER_LEN(src->n) * sizeof *src->y);
    return 0;
}

void sim_free(struct sim *s)
{
    if (!s)
        return;
    stepper_free(s->st);
    rest_free(s->rest);
    free(s->y);
    free(s);
}

const struct model *sim_model(const struct sim *s)
{
    return stepper_model(s->st);
}

void sim_set_phase(struct sim *s, double phase)
{
    clearance_forget(&s->clear);
    stepper_set_phase(s->st, phase, s->dt);
}

void sim_set_model(struct sim *s, const struct model *model)
{
    clearance_forget(&s->clear);
    stepper_set_model(s->st, model, s->dt);
    collision_limits(&s->lim, model);
    /* The cubic Hermite interpolant's error bound, max |u''''| h^4 / 384. */
    double w = 2.0 * M_PI * model->motor.frequency;
    s->sine_err = model->motor.amplitude * w * w * w * w / 384.0;
    /* Resting contacts stay while the same constraints exist; the next step parts any
     * the new parameters pull apart. */
    if (s->rest->count != s->lim.count || !s->lim.on)
        rest_clear(s->rest, &s->lim);
    else if (s->lim.count > s->n)
        rest_set(s->rest, s->n, false); /* the drive may have changed under it */
}

void sim_set_integrator(struct sim *s, enum integrator i)
{
    clearance_forget(&s->clear);
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
    clearance_forget(&s->clear);
    s->t_base = sim_time(s);
    s->steps = 0.0;
    s->dt = dt;
    stepper_set_model(s->st, sim_model(s), dt);
}

double sim_dt(const struct sim *s)
{
    return s->dt;
}

void sim_reset(struct sim *s, const double *x, const double *v)
{
    clearance_forget(&s->clear);
    int n = s->n;
    memset(s->y, 0, (size_t)STEPPER_LEN(n) * sizeof *s->y);
    if (x)
        memcpy(s->y, x, (size_t)n * sizeof *x);
    if (v)
        memcpy(s->y + n, v, (size_t)n * sizeof *v);
    s->t_base = 0.0;
    s->steps = 0.0;
    s->contact = 0.0;
    s->last_contacts = 0;
    s->last_capped = 0;
    rest_clear(s->rest, &s->lim);
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
    return model_end_position(sim_model(s), sim_time(s));
}

void sim_accel(const struct sim *s, double *a)
{
    const struct model *m = sim_model(s);
    double u = sim_end_position(s);
    model_accel(m, s->y, s->y + s->n, u, a);
    if (model_forced(m))
        a[m->force_on] += model_force(m, sim_time(s)) / m->m[m->force_on];
    if (s->rest->active) {
        /* What rests moves with what holds it: the end's acceleration for the piston's. */
        double w = 2.0 * M_PI * m->motor.frequency;
        bool sine = m->boundary == BOUNDARY_MOTOR && m->motor.wave == WAVE_SINE;
        rest_project(s->rest, m, a, sine ? -w * w * u : 0.0);
    }
}

void sim_energy(const struct sim *s, struct energy *e)
{
    double u = sim_end_position(s);
    e->kinetic = model_kinetic(sim_model(s), s->y + s->n);
    e->potential = model_potential(sim_model(s), s->y, u);
    e->dissipated = s->y[2 * s->n];
    e->motor_work = s->y[2 * s->n + 1];
    e->force_work = s->y[2 * s->n + 2];
    e->contact = s->contact;
    e->balance = e->kinetic + e->potential + e->dissipated + e->contact - e->motor_work -
                 e->force_work;
}

int sim_last_contacts(const struct sim *s)
{
    return s->last_contacts;
}

int sim_last_capped(const struct sim *s)
{
    return s->last_capped;
}

const struct collision_limits *sim_limits(const struct sim *s)
{
    return &s->lim;
}

/* What a snapshot holds besides the state: a named head at the start of the buffer. */
struct snapshot_head {
    double t_base, steps, dt; /* the time grid */
    double contact;           /* energy removed by contacts so far */
    double last_contacts;     /* contacts in the last step */
    double cycles;            /* the drive's angle then, in cycles in [0, 1) */
};
#define HEAD_DOUBLES ((int)(sizeof(struct snapshot_head) / sizeof(double)))
/* The resting contacts follow the state, as whole numbers of REST_BITS flags each. */
#define REST_BITS 52
#define REST_DOUBLES(n) (((n) + REST_BITS) / REST_BITS)

int sim_snapshot_size(const struct sim *s)
{
    return STEPPER_LEN(s->n) + HEAD_DOUBLES + REST_DOUBLES(s->n);
}

/* The drive's angle (cycles, in [0, 1)) at time t. */
static double drive_cycles(const struct motor *m, double t)
{
    double c = m->frequency * t + m->phase;
    return c - floor(c);
}

void sim_save(const struct sim *s, double *buf)
{
    struct snapshot_head h = {s->t_base, s->steps, s->dt, s->contact, s->last_contacts,
                              drive_cycles(&sim_model(s)->motor, sim_time(s))};
    memcpy(buf, &h, sizeof h);
    memcpy(buf + HEAD_DOUBLES, s->y, (size_t)STEPPER_LEN(s->n) * sizeof *buf);
    double *flags = buf + HEAD_DOUBLES + STEPPER_LEN(s->n);
    for (int j = 0; j < REST_DOUBLES(s->n); j++) {
        double word = 0.0;
        for (int b = REST_BITS - 1; b >= 0; b--) {
            int k = j * REST_BITS + b;
            word = 2.0 * word + (k <= s->n && s->rest->on[k]);
        }
        flags[j] = word;
    }
}

void sim_restore(struct sim *s, const double *buf)
{
    clearance_forget(&s->clear);
    struct snapshot_head h;
    memcpy(&h, buf, sizeof h);
    s->t_base = h.t_base;
    s->steps = h.steps;
    s->dt = h.dt;
    s->contact = h.contact;
    s->last_contacts = (int)h.last_contacts;
    memcpy(s->y, buf + HEAD_DOUBLES, (size_t)STEPPER_LEN(s->n) * sizeof *buf);
    const double *flags = buf + HEAD_DOUBLES + STEPPER_LEN(s->n);
    rest_clear(s->rest, &s->lim);
    for (int j = 0; j < REST_DOUBLES(s->n); j++) {
        double word = flags[j];
        for (int b = 0; b < REST_BITS; b++) {
            int k = j * REST_BITS + b;
            bool on = fmod(word, 2.0) != 0.0;
            word = floor(word / 2.0);
            if (on && k < s->lim.count)
                rest_set(s->rest, k, true);
        }
    }
    /* The drive goes on from the angle it had then, at the frequency in force now: if the
     * frequency changed since, the phase is re-anchored so the piston does not jump. */
    double p = h.cycles - sim_model(s)->motor.frequency * sim_time(s);
    stepper_set_phase(s->st, p - floor(p), s->dt);
}
