/* sim_step.c: one step of the driver (sim.c holds the object and its time grid): it
 * splits each step at the drive's breakpoints so every stepper sees one smooth piece,
 * locates each contact inside the step, and keeps the energy books.
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
#include <stdint.h>
#include <string.h>

#include "events.h"
#include "sim_state.h"
#include "vec2.h"

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

/* Books what contacts did: the losses, and the piston's work as the motor's. */
static void book(struct sim *s, const struct collision_books *b)
{
    s->contact += b->lost;
    s->y[2 * s->n + 1] += b->piston;
}

/* At an instant of contact on constraint k (or of a release, k < 0): the contact rule,
 * then resting contacts made or parted. u, du, ddu: the end then; f: the force input. */
static void at_event(struct sim *s, int k, double u, double du, double ddu, double f)
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
            a[m->force_on] += f / m->m[m->force_on];
            rest_project(s->rest, m, a, ddu);
            double arel = k == 0 ? a[0] : k < n ? a[k] - a[k - 1] : ddu - a[n - 1];
            s->rest->v_rest = fmax(COLLISION_V_REST, fmin(FIRST_ORDER_REST, s->dt * fabs(arel)));
        }
        s->last_contacts += events_hit(&s->lim, m, s->rest, k, s->y, s->y + n, u, du, &b);
        book(s, &b);
    }
    events_settle_rest(&s->lim, m, s->rest, s->y, s->y + n, u, du, ddu, f, s->force);
}

/* Moves the state by a short time delta along its Taylor series to second order, the
 * energy books to first (an event's instant refined; delta is at most SHIFT_MAX of the
 * piece, so what is left out is far below the step's own error). u, du, ddu: the end;
 * f: the force input. */
static void shift(struct sim *s, double delta, double u, double du, double ddu, double f)
{
    int n = s->n;
    const struct model *m = sim_model(s);
    double *x = s->y, *v = s->y + n, *acc = s->work, diss, power;
    model_rates(m, NULL, x, v, u, du, acc, &diss, &power);
    acc[m->force_on] += f / m->m[m->force_on];
    s->y[2 * n + 2] += delta * f * v[m->force_on]; /* the force's work */
    power -= rest_project(s->rest, m, acc, ddu) * du;
    for (int i = 0; i < n; i++) {
        x[i] += delta * (v[i] + 0.5 * delta * acc[i]);
        v[i] += delta * acc[i];
    }
    s->y[2 * n] += delta * diss;
    s->y[2 * n + 1] += delta * power;
}

/* The earliest event in the piece p: a gap closing (or grazing) on constraint *which, or
 * a resting contact *released starting to pull (each -1 when not the one); its instant
 * as a fraction of the piece. */
static double next_event(struct sim *s, struct events_piece *p, int *which, int *released)
{
    int closing;
    double first = events_contact(p, which, &closing);
    *released = -1;
    if (s->rest->active) {
        double th = events_release(p, s->work, s->force, released);
        if (th >= 0.0 && (*which < 0 || th < first))
            first = th, *which = -1;
        else
            *released = -1;
    }
    return first;
}

/* The instant *tc of contact on constraint k inside the piece [a, b], refined: the
 * interpolant's instant is good to O(h^4); Newton on the gap of the stepped state itself
 * (its rate known there) takes it to the method's own accuracy, which a graze, whose
 * instant moves much with a small error of the gap, needs. A small correction moves the
 * state along its Taylor series instead of stepping again. *uc, *duc: the drive at *tc.
 * 0, or -1 on a stepper failure. */
static int refine(struct sim *s, const struct drive *d, double ddu_factor, double a, double b,
                  int k, double *tc, double *uc, double *duc)
{
    int n = s->n, len = STEPPER_LEN(n);
    for (int it = 0; it < 3; it++) {
        double g = collision_gap(&s->lim, k, s->y, *uc);
        double r = collision_rate(&s->lim, k, s->y + n, *duc);
        if (fabs(g) < 1e-14 || r >= 0.0)
            break;
        double next = fmin(b, fmax(a, *tc - g / r));
        if (fabs(next - *tc) <= SHIFT_MAX * (b - a)) {
            shift(s, next - *tc, *uc, *duc, ddu_factor * *uc, drive_force(d, *tc));
        } else {
            memcpy(s->y, s->ya, (size_t)len * sizeof *s->y);
            if (next > a && stepper_apply(s->st, s->integrator, d, a, next, s->y) != 0)
                return -1;
        }
        *tc = next;
        drive_eval(d, *tc, uc, duc);
    }
    return 0;
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
        int which, released;
        double first = next_event(s, &p, &which, &released);
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
        if (which >= 0 && refine(s, d, p.ddu_factor, a, b, which, &tc, &uc, &duc) != 0)
            return -1;
        if (released >= 0)
            rest_set(s->rest, released, false);
        at_event(s, which, uc, duc, p.ddu_factor * uc, drive_force(d, tc));
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
        at_event(s, -1, p.ub, p.dub, p.ddu_factor * p.ub, drive_force(d, b));
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

/* A jump of the end to u (moving at du after it, the force input f): the motor's work on
 * the spring, and a contact if the piston jumped into the last mass. */
static void jump(struct sim *s, double u_from, double u, double du, double f)
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
        events_settle_rest(&s->lim, m, s->rest, s->y, s->y + n, u, du, 0.0, f, s->force);
}

/* A corner of the drive (its speed changes, as at a triangle's turn) under a cluster the
 * piston carries: turning away it leaves it, turning into it that is a contact. f: the
 * force input then. */
static void corner(struct sim *s, double u, double du, double f)
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
    events_settle_rest(&s->lim, m, s->rest, s->y, s->y + n, u, du, 0.0, f, s->force);
}

/* Whether m's drive is smooth across every step (a sine, or nothing): one piece a step. */
static bool one_piece(const struct model *m)
{
    return m->motor.wave == WAVE_SINE || !model_driven(m);
}

/* Integrates from t0 to t1 in pieces split at the drive's breakpoints. */
static int advance(struct sim *s, double t0, double t1)
{
    const struct model *m = sim_model(s);
    const struct motor *mot = &m->motor;
    struct drive d;
    double cuts[MAX_SPLIT];
    if (one_piece(m)) {
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
                jump(s, u_now, ua, du, drive_force(&d, a));
                fresh = false;
            }
            if (s->rest->active) {
                corner(s, ua, du, drive_force(&d, a));
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
        jump(s, u_now, u1, du, model_force(m, t1 + 1e-6 * s->dt));
    }
    return 0;
}

/* The common step, taken bare: RK4 in one piece (a sine drive or none), no contact
 * resting. When s->clear shows every gap far from closing, that is all; else when the
 * bound finds a gap that may close inside the step, the step is taken again from its
 * start by advance, which finds the same and locates it. *found: what stepper_rk4 found
 * on the state the step ends at, or -1 when advance took it. */
static int bare(struct sim *s, const struct model *m, double t0, double t1, int *found)
{
    struct drive d;
    drive_at(&d, m, 0.5 * (t0 + t1));
    *found = stepper_rk4(s->st, &d, t0, t1, s->y);
    if (!s->lim.on)
        return 0;
    double h = t1 - t0, h2 = h * h;
    double err = d.kind == DRIVE_SINE ? s->sine_err * h2 * h2 : 0.0;
    struct stepper_reach r;
    stepper_rk4_reach(s->st, &r);
    if (clearance_step(&s->clear, h, r.dx, r.v, r.ua, r.ub, r.dua, r.dub, err))
        return 0;
    struct events_piece p = {&s->lim, m, s->rest, &d, s->y0, s->y, t0, h, r.ua, r.dua, r.ub,
                             r.dub, 0, err};
    if (!events_may_close(&p))
        return 0;
    memcpy(s->y, s->y0, (size_t)STEPPER_LEN(s->n) * sizeof *s->y);
    stepper_undo_rk4(s->st);
    *found = -1;
    return advance(s, t0, t1);
}

/* Whether every value of y is finite (vec2.h's bit test). */
static bool all_finite(const double *y, int len)
{
    vec2_bits bad = {0, 0};
    int i = 0;
    for (; i + 2 <= len; i += 2)
        bad |= vec2_nonfinite_bits(vec2_load_halves(y + i)); /* just stored */
    uint64_t last = i < len ? nonfinite_bit(y[i]) : 0;
    return ((bad[0] | bad[1] | last) >> 63) == 0;
}

/* Whether some velocity, all finite, is past the cap (collision_cap has work to do). */
static bool over_cap(const double *v, int n)
{
    double top = 0.0; /* the largest |v_i|: every v_i is finite here */
    for (int i = 0; i < n; i++) {
        double a = fabs(v[i]);
        top = a > top ? a : top;
    }
    return top > MODEL_VMAX;
}

enum sim_status sim_step(struct sim *s)
{
    int n = s->n, len = STEPPER_LEN(n);
    const struct model *m = stepper_model(s->st);
    double t0 = s->t_base + s->steps * s->dt; /* sim_time */
    double t1 = s->t_base + (s->steps + 1.0) * s->dt;
    double contact0 = s->contact;
    memcpy(s->y0, s->y, (size_t)len * sizeof *s->y);
    s->last_contacts = s->last_capped = 0;
    bool bare_fits = s->integrator == INTEGRATOR_RK4 && !s->rest->active && one_piece(m);
    int found = -1; /* what the bare step found on the state, or -1: look */
    int failed = bare_fits ? bare(s, m, t0, t1, &found) : advance(s, t0, t1);
    if (failed || (found < 0 ? !all_finite(s->y, len) : found & STEPPER_NONFINITE)) {
        clearance_forget(&s->clear);
        memcpy(s->y, s->y0, (size_t)len * sizeof *s->y);
        s->contact = contact0;
        s->last_contacts = 0;
        return SIM_NONFINITE;
    }
    s->steps += 1.0;
    struct collision_books b = {0.0, 0.0};
    if (found < 0 ? over_cap(s->y + n, n) : found & STEPPER_OVER_CAP)
        s->last_capped = collision_cap(m, s->y + n, &b);
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
    if (!bare_fits)
        clearance_forget(&s->clear);
    else if (!s->clear.valid && s->lim.on)
        clearance_fill(&s->clear, &s->lim, s->y, model_end_position(m, t1));
    return SIM_OK;
}
