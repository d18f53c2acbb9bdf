/* sim.c: the driver (GSL odeiv2's "driver" layer): it owns the time grid t = t_base +
 * n dt, splits each step at the drive's breakpoints so every stepper sees one smooth
 * piece, locates each contact inside the step, and keeps the energy books.
 *
 * Contacts are events: after a piece is stepped, a constraint that ended up violated is
 * traced back along the step's cubic Hermite interpolant of the positions (the velocities
 * are their exact derivatives) to the instant its gap closed; the piece is stepped again
 * to that instant, the contact rule is applied there, and the piece goes on from it. A
 * step error of O(h^5) in the state gives a contact instant to O(h^4), so the method's
 * order survives contacts. A constraint that was already touching and barely moving is
 * a resting contact: it is put back on its limit at the end of the step instead. */
#include "sim.h"

#include <math.h>
#include <stdbool.h>
#include <stdlib.h>
#include <string.h>

#include "collision.h"
#include "events.h"
#include "rest.h"
#include "stepper.h"

/* Breakpoints of the drive inside one step, handled MAX_SPLIT at a time. */
#define MAX_SPLIT 16
/* Events located inside one piece (a mass coming to rest on a wall bounces about 30
 * times, the last ones in one step); any more are resolved at its end. */
#define MAX_EVENTS 256
/* The most a first-order method's error in a contact's speed may make it inelastic (m/s):
 * an unstable run must still run away. */
#define FIRST_ORDER_REST 0.1
/* A refinement of an event's instant shorter than this fraction of the piece moves the
 * state along its Taylor series rather than stepping again. */
#define SHIFT_MAX 1e-3
/* Gaps within this of zero count as touching. */
#define TOUCH EVENTS_TOUCH

struct sim {
    struct stepper *st;  /* the steppers, with the model's own copy */
    struct collision_limits lim;
    int n;               /* masses */
    double dt;           /* step */
    double t_base;       /* time at step 0 of the current dt */
    double steps;        /* whole steps since t_base (exact in a double to 2^53) */
    enum integrator integrator;
    double contact;      /* energy removed by contacts and the cap */
    int last_contacts;   /* contacts and caps in the last step */
    int last_capped;     /* caps in the last step */
    double *y;           /* STEPPER_LEN(N): x, v, D (dissipated), W (motor work), P (force) */
    double *y0;          /* the state at the start of the step, for restoring */
    const double *ya;    /* the state at the start of the piece being stepped: y0 or ya_buf */
    double *ya_buf;      /* room for it when the piece starts inside the step */
    struct rest *rest;   /* the contacts resting now */
    double *work;        /* 2N of scratch for the events */
    double *force;       /* N + 1: the resting contacts' forces */
    double sine_err;     /* a sine drive's straying from its cubic over h is this h^4 */
};

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
    stepper_set_phase(s->st, phase, s->dt);
}

void sim_set_model(struct sim *s, const struct model *model)
{
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
    stepper_set_model(s->st, sim_model(s), dt);
}

double sim_dt(const struct sim *s)
{
    return s->dt;
}

void sim_reset(struct sim *s, const double *x, const double *v)
{
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

/* Books what contacts did: the losses, and the piston's work as the motor's. */
static void book(struct sim *s, const struct collision_books *b)
{
    s->contact += b->lost;
    s->y[2 * s->n + 1] += b->piston;
}

/* At an instant of contact on constraint k (or of a release, k < 0): the contact rule,
 * then resting contacts made or parted. u, du: the drive then. */
static void at_event(struct sim *s, int k, double u, double du, double ddu)
{
    int n = s->n;
    const struct model *m = sim_model(s);
    if (k >= 0) {
        struct collision_books b = {0.0, 0.0};
        s->rest->v_rest = COLLISION_V_REST;
        if (s->integrator == INTEGRATOR_EULER || s->integrator == INTEGRATOR_SEMI_IMPLICIT) {
            /* A first-order method's velocity at the instant is off by about dt times
             * the gap's acceleration: slower than that (up to FIRST_ORDER_REST), a
             * contact is at rest already. */
            double *a = s->work;
            model_rates(m, NULL, s->y, s->y + n, u, du, a, NULL, NULL);
            rest_project(s->rest, m, a, ddu);
            double arel = k == 0 ? a[0] : k < n ? a[k] - a[k - 1] : ddu - a[n - 1];
            s->rest->v_rest = fmax(COLLISION_V_REST, fmin(FIRST_ORDER_REST, s->dt * fabs(arel)));
        }
        s->last_contacts += events_hit(&s->lim, m, s->rest, k, s->y, s->y + n, u, du, &b);
        book(s, &b);
    }
    events_settle_rest(&s->lim, m, s->rest, s->y, s->y + n, u, du, ddu, s->force);
}

/* Moves the state by a short time delta along its Taylor series to second order, the
 * energy books to first (an event's instant refined; delta is at most SHIFT_MAX of the
 * piece, so what is left out is far below the step's own error). u, du, ddu: the drive. */
static void shift(struct sim *s, double delta, double u, double du, double ddu)
{
    int n = s->n;
    const struct model *m = sim_model(s);
    double *x = s->y, *v = s->y + n, *acc = s->work, diss, power;
    model_rates(m, NULL, x, v, u, du, acc, &diss, &power);
    power -= rest_project(s->rest, m, acc, ddu) * du;
    for (int i = 0; i < n; i++) {
        x[i] += delta * (v[i] + 0.5 * delta * acc[i]);
        v[i] += delta * acc[i];
    }
    s->y[2 * n] += delta * diss;
    s->y[2 * n + 1] += delta * power;
}

/* Steps the piece [a, b] on drive d with its contacts; at_start when the piece starts
 * the step (the state is still y0). 0, or -1 on a stepper failure. */
static int piece(struct sim *s, const struct drive *d, double a, double b, bool at_start)
{
    int n = s->n, len = STEPPER_LEN(n);
    enum integrator integ = s->integrator;
    const struct model *m = sim_model(s);
    struct events_piece p = {&s->lim, m, s->rest, d, NULL, s->y, a, b - a, 0, 0, 0, 0, 0, 0};
    int budget = MAX_EVENTS;
    p.ddu_factor = drive_ddu_factor(d);
    bool leftover = true; /* a gap may be left closed at the end */
    int stalls = 0;       /* events in a row at the start of what is left */
    for (int events = 0;; events++) {
        if (events == 0 && at_start) {
            s->ya = s->y0;
        } else {
            memcpy(s->ya_buf, s->y, (size_t)len * sizeof *s->y);
            s->ya = s->ya_buf;
        }
        if (stepper_apply(s->st, integ, d, a, b, s->y) != 0)
            return -1;
        if (!s->lim.on)
            return 0;
        stepper_start_drive(s->st, &p.ua, &p.dua);
        stepper_end_drive(s->st, &p.ub, &p.dub);
        if (s->rest->active)
            rest_snap(s->rest, &s->lim, m, s->y, s->y + n, p.ub, p.dub);
        if (budget == 0)
            break; /* no progress: settled below */
        p.ya = s->ya, p.a = a, p.h = b - a;
        double h2 = (b - a) * (b - a);
        p.drive_err = d->kind == DRIVE_SINE ? s->sine_err * h2 * h2 : 0.0;
        /* The earliest event in the piece: a gap closing (or grazing), or a resting
         * contact starting to pull. */
        int which, closing, released = -1;
        double first = events_contact(&p, &which, &closing);
        if (s->rest->active) {
            double th = events_release(&p, s->work, s->force, &released);
            if (th >= 0.0 && (which < 0 || th < first))
                first = th, which = -1;
            else
                released = -1;
        }
        if (which < 0 && released < 0) {
            leftover = false; /* every gap stays open to its end */
            break;
        }
        if (events >= budget)
            break;
        /* Step again, to the instant of the event. */
        double tc = a + first * (b - a);
        memcpy(s->y, s->ya, (size_t)len * sizeof *s->y);
        if (tc > a && stepper_apply(s->st, integ, d, a, tc, s->y) != 0)
            return -1;
        double uc, duc;
        drive_eval(d, tc, &uc, &duc);
        if (which >= 0) {
            /* The interpolant's instant is good to O(h^4); Newton on the gap of the stepped
             * state itself (its rate known there) takes it to the method's own accuracy,
             * which a graze, whose instant moves much with a small error of the gap,
             * needs. A small correction moves the state along its Taylor series instead
             * of stepping again. */
            for (int it = 0; it < 3; it++) {
                double g = collision_gap(&s->lim, which, s->y, uc);
                double r = collision_rate(&s->lim, which, s->y + n, duc);
                if (fabs(g) < 1e-14 || r >= 0.0)
                    break;
                double next = fmin(b, fmax(a, tc - g / r));
                if (fabs(next - tc) <= SHIFT_MAX * (b - a)) {
                    shift(s, next - tc, uc, duc, p.ddu_factor * uc);
                } else {
                    memcpy(s->y, s->ya, (size_t)len * sizeof *s->y);
                    if (next > a && stepper_apply(s->st, integ, d, a, next, s->y) != 0)
                        return -1;
                }
                tc = next;
                drive_eval(d, tc, &uc, &duc);
            }
        }
        if (released >= 0)
            rest_set(s->rest, released, false);
        at_event(s, which, uc, duc, p.ddu_factor * uc);
        if (b - tc <= 1e-12 * s->dt)
            break;
        if (tc <= a && ++stalls > 2) {
            /* Events that make no progress: the rest of the piece is stepped whole and
             * what it leaves closed is settled at its end, so the run moves on. */
            budget = 0;
            continue;
        }
        a = tc;
    }
    /* Anything left over (events that made no progress, or more than MAX_EVENTS) is put
     * back at the piece's end. */
    stepper_end_drive(s->st, &p.ub, &p.dub);
    if (leftover && collision_needed(&s->lim, s->y, s->y + n, p.ub)) {
        struct collision_books bk = {0.0, 0.0};
        s->last_contacts += collision_settle(&s->lim, m, s->y, s->y + n, p.ub, p.dub, &bk);
        book(s, &bk);
        at_event(s, -1, p.ub, p.dub, p.ddu_factor * p.ub);
    }
    return 0;
}

/* Work done by the motor when the end jumps from u_from to u_to with the last mass at
 * displacement x: the change of spring N's energy, E(u_to - x) - E(u_from - x). */
static double jump_work(const struct sim *s, double u_from, double u_to)
{
    double x = s->y[s->n - 1];
    const struct model *m = sim_model(s);
    if (m->cubic)
        return model_spring_energy(m, s->n, u_to - x) - model_spring_energy(m, s->n, u_from - x);
    double a = u_from - x, b = u_to - x;
    return 0.5 * m->k[s->n] * (b * b - a * a);
}

/* The piston jumped to u, into the last mass: every mass in its way is pushed ahead of
 * its face, each against the next (a row on the face), the motor paying what that does to
 * the springs; then the face's contact rule, passed along the row pair by pair. -1 when
 * the row would not fit between the face and the wall (nothing moved), else the contacts. */
static int plow(struct sim *s, double u, double du)
{
    int n = s->n, first = n;
    const struct collision_limits *l = &s->lim;
    const struct model *m = sim_model(s);
    /* Mass i's displacement on the face; each left neighbour sits `pair` below. */
    double face = MODEL_LENGTH + u - 0.5 * l->w - n * l->spacing, pair = l->w - l->spacing;
    double lim = face;
    for (int i = n - 1; i >= 0 && s->y[i] > lim; i--, lim -= pair)
        first = i;
    if (first == 0 && lim + pair < 0.5 * l->w - l->spacing - TOUCH)
        return -1;
    double e0 = model_potential(m, s->y, u);
    lim = face;
    for (int i = n - 1; i >= first; i--, lim -= pair)
        s->y[i] = lim;
    s->y[2 * n + 1] += model_potential(m, s->y, u) - e0;
    if (s->rest->on[n])
        return 0; /* the piston carried it: no impact */
    struct collision_books b = {0.0, 0.0};
    s->rest->v_rest = COLLISION_V_REST;
    int hits = events_hit(&s->lim, m, s->rest, n, s->y, s->y + n, u, du, &b);
    book(s, &b);
    return hits > 0 ? hits : 1;
}

/* A jump of the end to u (moving at du after it): the motor's work on the spring, and a
 * contact if the piston jumped into the last mass. */
static void jump(struct sim *s, double u_from, double u, double du)
{
    int n = s->n;
    const struct model *m = sim_model(s);
    s->y[2 * n + 1] += jump_work(s, u_from, u);
    if (!s->lim.on)
        return;
    double gap = collision_gap(&s->lim, n, s->y, u);
    if (s->rest->on[n] && gap > TOUCH) /* the piston jumped away from what it carried */
        rest_set(s->rest, n, false);
    if (gap < -TOUCH) {
        int hits = plow(s, u, du);
        if (hits < 0) {
            /* No room for the row (an amplitude the settings refuse): settled as a pile. */
            struct collision_books b = {0.0, 0.0};
            hits = collision_settle(&s->lim, m, s->y, s->y + n, u, du, &b);
            book(s, &b);
        }
        s->last_contacts += hits;
    }
    if (s->rest->active || gap < -TOUCH)
        events_settle_rest(&s->lim, m, s->rest, s->y, s->y + n, u, du, 0.0, s->force);
}

/* A corner of the drive (its speed changes, as at a triangle's turn) under a cluster the
 * piston carries: turning away it leaves it, turning into it that is a contact. */
static void corner(struct sim *s, double u, double du)
{
    int n = s->n;
    double v = s->y[2 * n - 1];
    if (!s->lim.on || !s->rest->on[n] || du == v)
        return;
    const struct model *m = sim_model(s);
    rest_set(s->rest, n, false);
    if (du < v) {
        struct collision_books b = {0.0, 0.0};
        s->last_contacts += events_hit(&s->lim, m, s->rest, n, s->y, s->y + n, u, du, &b);
        book(s, &b);
    }
    events_settle_rest(&s->lim, m, s->rest, s->y, s->y + n, u, du, 0.0, s->force);
}

/* Integrates from t0 to t1 in pieces split at the drive's breakpoints. */
static int advance(struct sim *s, double t0, double t1)
{
    const struct model *m = sim_model(s);
    const struct motor *mot = &m->motor;
    struct drive d;
    double cuts[MAX_SPLIT];
    if (mot->wave == WAVE_SINE || !model_driven(m)) {
        drive_at(&d, m, 0.5 * (t0 + t1));
        return piece(s, &d, t0, t1, true);
    }
    bool jumps = motor_has_jumps(mot->wave);
    double u_now = model_end_position(m, t0); /* the end's position now */
    double a = t0;
    bool fresh = true; /* the state is still y0: nothing has been stepped or jumped yet */
    while (a < t1) {
        /* Up to MAX_SPLIT breakpoints at a time; after the last of a full batch, the
         * next batch is looked up from there. */
        int nb = motor_breakpoints(mot, a, t1, cuts, MAX_SPLIT);
        bool more = nb > MAX_SPLIT;
        if (more)
            nb = MAX_SPLIT;
        for (int j = 0; j < nb + !more; j++) {
            double b = j < nb ? cuts[j] : t1, ua, ub, du;
            drive_at(&d, m, 0.5 * (a + b));
            drive_eval(&d, a, &ua, &du);
            if (jumps && ua != u_now) {
                jump(s, u_now, ua, du);
                fresh = false;
            }
            if (s->rest->active) {
                corner(s, ua, du);
                fresh = false;
            }
            if (piece(s, &d, a, b, fresh) != 0)
                return -1;
            fresh = false;
            drive_eval(&d, b, &ub, &du);
            u_now = ub;
            a = b;
        }
    }
    double u1 = model_end_position(m, t1);
    if (jumps && u1 != u_now) {
        struct motor_piece p;
        double u, du;
        motor_piece_at(mot, t1 + 1e-6 * s->dt, &p);
        motor_piece_eval(&p, t1, &u, &du);
        jump(s, u_now, u1, du);
    }
    return 0;
}

static bool all_finite(const double *y, int len)
{
    for (int i = 0; i < len; i++)
        if (!isfinite(y[i]))
            return false;
    return true;
}

enum sim_status sim_step(struct sim *s)
{
    int n = s->n, len = STEPPER_LEN(n);
    double t0 = sim_time(s);
    double t1 = s->t_base + (s->steps + 1.0) * s->dt;
    double contact0 = s->contact;
    memcpy(s->y0, s->y, (size_t)len * sizeof *s->y);
    s->last_contacts = s->last_capped = 0;
    if (advance(s, t0, t1) != 0 || !all_finite(s->y, len)) {
        memcpy(s->y, s->y0, (size_t)len * sizeof *s->y);
        s->contact = contact0;
        s->last_contacts = 0;
        return SIM_NONFINITE;
    }
    s->steps += 1.0;
    struct collision_books b = {0.0, 0.0};
    s->last_capped = collision_cap(sim_model(s), s->y + n, &b);
    book(s, &b);
    if (s->last_capped && s->rest->active) {
        /* A capped mass moves no longer as what holds it: its resting contacts part. */
        for (int i = 0; i < n; i++)
            if (fabs(s->y[n + i]) >= MODEL_VMAX) {
                rest_set(s->rest, i, false);
                if (i + 1 < s->lim.count)
                    rest_set(s->rest, i + 1, false);
            }
    }
    s->last_contacts += s->last_capped;
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
