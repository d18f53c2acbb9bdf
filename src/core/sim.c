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
#include "stepper.h"

/* Breakpoints of the drive inside one step, handled MAX_SPLIT at a time. */
#define MAX_SPLIT 16
/* Contacts located inside one piece; any more are resolved at its end. */
#define MAX_EVENTS 16
/* Contacts closing in one piece that are located one by one; more is a pile-up. */
#define MAX_LOCATED 3
/* Gaps within this of zero count as touching. */
#define TOUCH 1e-12

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
    double *y;           /* 2N+2: x, v, D (dissipated), W (motor work) */
    double *y0;          /* the state at the start of the step, for restoring */
    const double *ya;    /* the state at the start of the piece being stepped: y0 or ya_buf */
    double *ya_buf;      /* room for it when the piece starts inside the step */
};

struct sim *sim_new(const struct model *model, double dt)
{
    int n = model->n;
    size_t len = (size_t)(2 * n + 2);
    struct sim *s = calloc(1, sizeof *s);
    if (!s)
        return NULL;
    s->st = stepper_new(model);
    s->y = calloc(3 * len, sizeof *s->y);
    if (!s->st || !s->y) {
        sim_free(s);
        return NULL;
    }
    s->n = n;
    s->y0 = s->y + len;
    s->ya_buf = s->y0 + len;
    s->ya = s->ya_buf;
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
    dst->last_capped = src->last_capped;
    memcpy(dst->y, src->y, (size_t)(2 * src->n + 2) * sizeof *src->y);
    return 0;
}

void sim_free(struct sim *s)
{
    if (!s)
        return;
    stepper_free(s->st);
    free(s->y);
    free(s);
}

const struct model *sim_model(const struct sim *s)
{
    return stepper_model(s->st);
}

void sim_set_model(struct sim *s, const struct model *model)
{
    stepper_set_model(s->st, model, s->dt);
    collision_limits(&s->lim, model);
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

/* Books what contacts did: the losses, and the piston's work as the motor's. */
static void book(struct sim *s, const struct collision_books *b)
{
    s->contact += b->lost;
    s->y[2 * s->n + 1] += b->piston;
}

/* Position of mass i at theta in [0, 1] of a step of length h from state ya to y: the
 * cubic Hermite interpolant (Hermite, 1878) of x with x' = v at both ends. */
static double hermite(const double *ya, const double *y, int n, int i, double h, double th)
{
    double t2 = th * th, t3 = t2 * th;
    double h00 = 2 * t3 - 3 * t2 + 1, h10 = t3 - 2 * t2 + th, h01 = -2 * t3 + 3 * t2,
           h11 = t3 - t2;
    return h00 * ya[i] + h10 * h * ya[n + i] + h01 * y[i] + h11 * h * y[n + i];
}

/* Gap of constraint k at theta of the step [a, a + h] from ya to y. */
static double gap_at(const struct sim *s, const struct drive *d, int k, double a, double h,
                     double th)
{
    const double *ya = s->ya, *y = s->y;
    int n = s->n;
    const struct collision_limits *l = &s->lim;
    if (k == 0)
        return l->spacing + hermite(ya, y, n, 0, h, th) - 0.5 * l->w;
    if (k < n)
        return l->spacing + hermite(ya, y, n, k, h, th) - hermite(ya, y, n, k - 1, h, th) -
               l->w;
    double u, du;
    drive_eval(d, a + th * h, &u, &du);
    return MODEL_LENGTH + u - 0.5 * l->w - (n * l->spacing + hermite(ya, y, n, n - 1, h, th));
}

/* The first theta in (0, 1] at which constraint k's gap closes along the step, given that
 * it is violated at its end: a coarse scan for the first sign change, then regula falsi
 * (Illinois) to the root. */
static double closing_time(const struct sim *s, const struct drive *d, int k, double a,
                           double h)
{
    enum { SCAN = 8 };
    double lo = 0.0, glo = gap_at(s, d, k, a, h, 0.0);
    if (glo <= 0.0)
        return 0.0;
    double hi = 1.0, ghi = gap_at(s, d, k, a, h, 1.0);
    for (int j = 1; j < SCAN; j++) {
        double th = (double)j / SCAN, g = gap_at(s, d, k, a, h, th);
        if (g < 0.0) {
            hi = th, ghi = g;
            break;
        }
        lo = th, glo = g;
    }
    int side = 0;
    for (int it = 0; it < 100 && hi - lo > 1e-15; it++) {
        double th = (lo * ghi - hi * glo) / (ghi - glo);
        double g = gap_at(s, d, k, a, h, th);
        if (g > 0.0) {
            lo = th, glo = g;
            if (side == -1)
                ghi *= 0.5;
            side = -1;
        } else {
            hi = th, ghi = g;
            if (side == 1)
                glo *= 0.5;
            side = 1;
        }
        if (fabs(g) < 1e-15)
            return th;
    }
    return hi;
}

/* At an instant of contact: every touching constraint that is closing gets the contact
 * rule; what is still closing after three sweeps is a cluster, which moves as one.
 * Returns the contacts. */
static int hit_touching(struct sim *s, double u, double du)
{
    int n = s->n, hits = 0;
    struct collision_books b = {0.0, 0.0};
    const struct model *m = sim_model(s);
    int found = 1;
    for (int sweep = 0; sweep < 3 && found; sweep++) {
        found = 0;
        for (int k = 0; k < s->lim.count; k++)
            if (collision_gap(&s->lim, k, s->y, u) <= TOUCH)
                found += collision_hit(&s->lim, m, k, s->y + n, du, &b);
        hits += found;
    }
    if (found) /* still closing after three sweeps: a cluster, which moves as one */
        hits += collision_merge(&s->lim, m, s->y, s->y + n, u, du, &b);
    book(s, &b);
    return hits;
}

/* Steps the piece [a, b] on drive d with its contacts; at_start when the piece starts
 * the step (the state is still y0). 0, or -1 on a stepper failure. */
static int piece(struct sim *s, const struct drive *d, double a, double b, bool at_start)
{
    int n = s->n, len = 2 * n + 2;
    enum integrator integ = s->integrator;
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
        double ua, dua, ub, dub;
        stepper_end_drive(s->st, &ub, &dub);
        if (!collision_needed(&s->lim, s->y, s->y + n, ub))
            return 0; /* the common step: nothing touches */
        drive_eval(d, a, &ua, &dua);
        /* The earliest contact in the piece, resting contacts apart. Where more than a
         * few close in one piece, the chain is piling up: those are settled at its end,
         * so a pile-up costs a step, not a step per contact. */
        double first = 2.0;
        int which = -1, closing = 0;
        for (int k = 0; k < s->lim.count && closing <= MAX_LOCATED; k++) {
            if (collision_gap(&s->lim, k, s->y, ub) >= -TOUCH)
                continue;
            if (collision_gap(&s->lim, k, s->ya, ua) <= TOUCH &&
                fabs(collision_rate(&s->lim, k, s->ya + n, dua)) < COLLISION_V_REST)
                continue;
            /* A mass joining a pile (its other side already touching) is settled with
             * the pile at the piece's end. */
            if ((k > 0 && collision_gap(&s->lim, k - 1, s->ya, ua) <= TOUCH) ||
                (k + 1 < s->lim.count && collision_gap(&s->lim, k + 1, s->ya, ua) <= TOUCH))
                continue;
            closing++;
            double th = closing_time(s, d, k, a, b - a);
            if (th < first)
                first = th, which = k;
        }
        if (which < 0 || events >= MAX_EVENTS || closing > MAX_LOCATED)
            break;
        /* Step again, to the instant of contact. */
        double tc = a + first * (b - a);
        memcpy(s->y, s->ya, (size_t)len * sizeof *s->y);
        if (tc > a && stepper_apply(s->st, integ, d, a, tc, s->y) != 0)
            return -1;
        double uc, duc;
        drive_eval(d, tc, &uc, &duc);
        if (integ == INTEGRATOR_EXACT) {
            /* On the exact solution: Newton on the gap, whose rate is known exactly. */
            for (int it = 0; it < 4; it++) {
                double g = collision_gap(&s->lim, which, s->y, uc);
                double r = collision_rate(&s->lim, which, s->y + n, duc);
                if (fabs(g) < 1e-14 || r >= 0.0)
                    break;
                double next = fmin(b, fmax(a, tc - g / r));
                memcpy(s->y, s->ya, (size_t)len * sizeof *s->y);
                if (stepper_apply(s->st, integ, d, a, next, s->y) != 0)
                    return -1;
                tc = next;
                drive_eval(d, tc, &uc, &duc);
            }
        }
        s->last_contacts += hit_touching(s, uc, duc);
        if (b - tc <= 1e-12 * s->dt)
            break;
        a = tc;
    }
    /* Resting contacts, and any beyond MAX_EVENTS, are put back at the piece's end. */
    double ub, dub;
    stepper_end_drive(s->st, &ub, &dub);
    if (collision_needed(&s->lim, s->y, s->y + n, ub)) {
        struct collision_books bk = {0.0, 0.0};
        s->last_contacts += collision_settle(&s->lim, sim_model(s), s->y, s->y + n, ub, dub, &bk);
        book(s, &bk);
    }
    return 0;
}

/* Work done by the motor when the end jumps from u_from to u_to with the last mass at
 * displacement x: the change of spring N's energy, 1/2 k_N ((u_to-x)^2 - (u_from-x)^2). */
static double jump_work(const struct sim *s, double u_from, double u_to)
{
    double x = s->y[s->n - 1];
    double a = u_from - x, b = u_to - x;
    return 0.5 * sim_model(s)->k[s->n] * (b * b - a * a);
}

/* A jump of the end to u (moving at du after it): the motor's work on the spring, and a
 * contact if the piston jumped into the last mass. */
static void jump(struct sim *s, double u_from, double u, double du)
{
    s->y[2 * s->n + 1] += jump_work(s, u_from, u);
    if (s->lim.on && collision_gap(&s->lim, s->lim.n, s->y, u) < -TOUCH) {
        struct collision_books b = {0.0, 0.0};
        s->last_contacts +=
            collision_settle(&s->lim, sim_model(s), s->y, s->y + s->n, u, du, &b);
        book(s, &b);
    }
}

/* Integrates from t0 to t1 in pieces split at the drive's breakpoints. */
static int advance(struct sim *s, double t0, double t1)
{
    const struct model *m = sim_model(s);
    const struct motor *mot = &m->motor;
    struct drive d;
    double cuts[MAX_SPLIT];
    if (m->boundary != BOUNDARY_MOTOR || mot->wave == WAVE_SINE || mot->amplitude == 0.0) {
        drive_at(&d, m, 0.5 * (t0 + t1));
        return piece(s, &d, t0, t1, true);
    }
    bool jumps = motor_has_jumps(mot->wave);
    double u_now = motor_position(mot, t0); /* the end's position now */
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
            if (piece(s, &d, a, b, fresh) != 0)
                return -1;
            fresh = false;
            drive_eval(&d, b, &ub, &du);
            u_now = ub;
            a = b;
        }
    }
    double u1 = motor_position(mot, t1);
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
    int n = s->n, len = 2 * n + 2;
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
    model_accel(sim_model(s), s->y, s->y + s->n, sim_end_position(s), a);
}

void sim_energy(const struct sim *s, struct energy *e)
{
    double u = sim_end_position(s);
    e->kinetic = model_kinetic(sim_model(s), s->y + s->n);
    e->potential = model_potential(sim_model(s), s->y, u);
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

int sim_snapshot_size(const struct sim *s)
{
    return 2 * s->n + 2 + HEAD_DOUBLES;
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
    memcpy(buf + HEAD_DOUBLES, s->y, (size_t)(2 * s->n + 2) * sizeof *buf);
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
    memcpy(s->y, buf + HEAD_DOUBLES, (size_t)(2 * s->n + 2) * sizeof *buf);
    /* The drive goes on from the angle it had then, at the frequency in force now: if the
     * frequency changed since, the phase is re-anchored so the piston does not jump. */
    double p = h.cycles - sim_model(s)->motor.frequency * sim_time(s);
    stepper_set_phase(s->st, p - floor(p), s->dt);
}
