/* stepper.c: explicit Euler, symplectic (semi-implicit) Euler, velocity Verlet, classic
 * RK4 (Kutta 1901; Hairer, Norsett and Wanner, Solving ODEs I, II.1) and the exact
 * stepper (exact.c), on y = (x, v, D, W, P) with D' = sum c_i v_i^2 + sum cs_j s_j'^2
 * (s_j spring j's stretch), W' = (k_N (u - x_N) + cs_N (u' - v_N)) u', P' = F w v_K.
 * The equation of motion is model_rates, the one in model.c, plus the force F w(t) / m_K
 * on mass K. */
#include "stepper.h"

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <lapacke.h>

#include "exact.h"
#include "vec2.h"
#include "rest.h"

/* The sine drive's angle carried from step to step by rotations (sine_drive). */
struct rotation {
    double w, h;           /* w and h the rotations below were made for */
    double s1, c1, s2, c2; /* sin, cos of w h/2 and of w h */
    double next_t;         /* where the last sine step ended (NAN: none) */
    double phase;          /* the drive's phase then */
    double sn, cs;         /* sin and cos of the drive's angle there */
    int carried;           /* steps since sin and cos were last taken afresh */
};

struct stepper {
    struct model *model;   /* own copy of the parameters */
    int n;
    double dt;             /* the grid step, for the sine's rotations */
    double *inv_m;         /* 1/m_i */
    double *k1, *k2, *tmp; /* stage scratch, STEPPER_LEN(N) each */
    double *tri;           /* 3N: Verlet's tridiagonal solve with spring dampers */
    struct exact *exact;   /* the exact stepper's workspace, made when first needed */
    struct rotation rot;   /* the sine drive's rotations */
    struct rotation rot_before; /* as they were before the last stepper_rk4 */
    double end_u, end_du;  /* the drive at the end of the last step taken */
    double start_u, start_du; /* and at its start */
    const struct rest *rest;  /* resting contacts held as constraints, or NULL */
    bool constrained;         /* some rest now: the step being taken projects its rates */
    double ddu_factor;        /* u'' = ddu_factor u on the piece being stepped */
    double reach_x, reach_v;  /* the last stepper_rk4's largest |x_i| change and |v_i| */
};

double drive_ddu_factor(const struct drive *d)
{
    if (d->kind != DRIVE_SINE)
        return 0.0; /* constants and ramps */
    double w = 2.0 * M_PI * d->motor->frequency;
    return -w * w;
}

void drive_eval(const struct drive *d, double t, double *u, double *du)
{
    switch (d->kind) {
    case DRIVE_SINE: {
        double w = 2.0 * M_PI * d->motor->frequency, s, c;
        sincos(w * t + 2.0 * M_PI * d->motor->phase, &s, &c);
        *u = d->amp * s;
        *du = d->amp * w * c;
        return;
    }
    case DRIVE_PIECE:
        if (d->amp != 0.0) {
            motor_piece_eval(&d->piece, t, u, du);
            return;
        }
        break;
    case DRIVE_NONE:
        break;
    }
    *u = *du = 0.0;
}

void drive_unit(const struct drive *d, double t, double *w, double *dw)
{
    *w = *dw = 0.0;
    if (d->kind == DRIVE_SINE) {
        double om = 2.0 * M_PI * d->motor->frequency, s, c;
        sincos(om * t + 2.0 * M_PI * d->motor->phase, &s, &c);
        *w = s, *dw = om * c;
    } else if (d->kind == DRIVE_PIECE) {
        motor_piece_unit(&d->piece, t, w, dw);
    }
}

double drive_force(const struct drive *d, double t)
{
    if (d->force == 0.0)
        return 0.0;
    double w, dw;
    drive_unit(d, t, &w, &dw);
    return d->force * w;
}

struct stepper *stepper_new(const struct model *m)
{
    int n = m->n;
    size_t len = (size_t)STEPPER_LEN(n);
    struct stepper *st = calloc(1, sizeof *st);
    if (!st)
        return NULL;
    st->model = model_new(n);
    st->inv_m = calloc(3 * len + (size_t)(4 * n), sizeof *st->inv_m);
    if (!st->model || !st->inv_m) {
        stepper_free(st);
        return NULL;
    }
    st->n = n;
    st->k1 = st->inv_m + n;
    st->k2 = st->k1 + len;
    st->tmp = st->k2 + len;
    st->tri = st->tmp + len;
    st->rot.next_t = NAN;
    stepper_set_model(st, m, 0.01);
    return st;
}

void stepper_free(struct stepper *st)
{
    if (!st)
        return;
    model_free(st->model);
    exact_free(st->exact);
    free(st->inv_m);
    free(st);
}

void stepper_set_model(struct stepper *st, const struct model *m, double dt)
{
    model_copy(st->model, m);
    for (int i = 0; i < st->n; i++)
        st->inv_m[i] = 1.0 / m->m[i];
    st->dt = dt;
}

void stepper_set_phase(struct stepper *st, double phase, double dt)
{
    st->model->motor.phase = phase;
    st->dt = dt;
}

void stepper_end_drive(const struct stepper *st, double *u, double *du)
{
    *u = st->end_u;
    *du = st->end_du;
}

void stepper_start_drive(const struct stepper *st, double *u, double *du)
{
    *u = st->start_u;
    *du = st->start_du;
}

void stepper_set_rest(struct stepper *st, const struct rest *r)
{
    st->rest = r;
}

int stepper_copy(struct stepper *dst, const struct stepper *src)
{
    if (src->exact && !dst->exact && !(dst->exact = exact_new(src->n)))
        return -1;
    if (src->exact && exact_copy(dst->exact, src->exact) != 0)
        return -1;
    stepper_set_model(dst, src->model, src->dt);
    dst->rot = src->rot;
    dst->end_u = src->end_u, dst->end_du = src->end_du;
    dst->start_u = src->start_u, dst->start_du = src->start_du;
    return 0;
}

const struct model *stepper_model(const struct stepper *st)
{
    return st->model;
}

const double *stepper_inv_m(const struct stepper *st)
{
    return st->inv_m;
}

/* Resting contacts: the accelerations a made the constrained ones, and the piston's push
 * on its cluster booked as the motor's work (*dw). */
static void constrain(const struct stepper *st, double u, double du, double *a, double *dw)
{
    double push = rest_project(st->rest, st->model, a, st->ddu_factor * u);
    *dw -= push * du;
}

/* One stage of a step: the accelerations a at (x, v) with the right end at u moving at du
 * and the force input at f, the dampers' power *dd, the motor's *dw and the force's *dp
 * (the rates of D, W and P). Inline: the inner loop of every stepper. */
__attribute__((always_inline)) static inline void
stage(const struct stepper *st, const double *x, const double *v, double u, double du,
      double f, double *a, double *dd, double *dw, double *dp)
{
    const double *inv_m = st->inv_m;
    if (!inv_m)
        __builtin_unreachable(); /* so the inlined rates multiply, with no test a mass */
    model_rates(st->model, inv_m, x, v, u, du, a, dd, dw);
    *dp = 0.0;
    if (f != 0.0) {
        int k = st->model->force_on;
        a[k] += f * inv_m[k];
        *dp = f * v[k];
    }
    if (st->constrained)
        constrain(st, u, du, a, dw);
}

/* dy/dt at state y with the right end at u moving at du and the force input at f. */
static void deriv(const struct stepper *st, const double *y, double u, double du, double f,
                  double *dy)
{
    int n = st->n;
    for (int i = 0; i < n; i++) /* a loop: for a short chain memcpy's call costs more */
        dy[i] = y[n + i];
    stage(st, y, y + n, u, du, f, dy + n, &dy[2 * n], &dy[2 * n + 1], &dy[2 * n + 2]);
}

/* The sine drive u = A sin(th), du = A w cos(th) at a, a + h/2 and a + h, with one
 * sincos: sin and cos at the later times follow from the angle-addition formulas with
 * sin, cos of w h/2 and w h, kept while w and h stay the same. Exact to a few ulp. */
static void sine_drive(struct stepper *st, const struct drive *d, double a, double b,
                       double u[3], double du[3], double f[3])
{
    double h = b - a;
    const struct motor *mot = &st->model->motor;
    double w = 2.0 * M_PI * mot->frequency, amp = d->amp;
    struct rotation *r = &st->rot;
    /* b - a of a grid step differs from dt by the rounding of t (a few ulp of b, which
     * grow with t): such a step keeps the rotation made for dt, an angle error no larger
     * than that rounding makes anyway. */
    if (fabs(h - st->dt) <= 1e-12 * st->dt + 8.0 * DBL_EPSILON * fabs(b))
        h = st->dt;
    if (w != r->w || h != r->h) {
        sincos(0.5 * w * h, &r->s1, &r->c1);
        sincos(w * h, &r->s2, &r->c2);
        r->w = w;
        r->h = h;
        r->next_t = NAN; /* nothing to carry over */
    }
    double sn, cs;
    if (a == r->next_t && mot->phase == r->phase && r->carried < 64) {
        /* This step starts where the last ended: carry its sin and cos over, and only
         * every 64 steps take them afresh, so rounding cannot build up. */
        sn = r->sn, cs = r->cs;
        r->carried++;
    } else {
        sincos(w * a + 2.0 * M_PI * mot->phase, &sn, &cs);
        r->carried = 0;
    }
    double sm = sn * r->c1 + cs * r->s1, cm = cs * r->c1 - sn * r->s1;
    double se = sn * r->c2 + cs * r->s2, ce = cs * r->c2 - sn * r->s2;
    r->next_t = b;
    r->phase = mot->phase;
    r->sn = se, r->cs = ce;
    u[0] = amp * sn, du[0] = amp * w * cs;
    u[1] = amp * sm, du[1] = amp * w * cm;
    u[2] = amp * se, du[2] = amp * w * ce;
    f[0] = d->force * sn, f[1] = d->force * sm, f[2] = d->force * se;
}

/* The drive at a, the middle and b: the end (u, du) and the force f. */
static void drive3(struct stepper *st, const struct drive *d, double a, double b, double u[3],
                   double du[3], double f[3])
{
    if (d->kind == DRIVE_SINE) {
        sine_drive(st, d, a, b, u, du, f);
        return;
    }
    double t[3] = {a, a + 0.5 * (b - a), b};
    for (int i = 0; i < 3; i++) {
        drive_eval(d, t[i], &u[i], &du[i]);
        f[i] = drive_force(d, t[i]);
    }
}

/* Classic RK4, y += h/6 (k1 + 2 k2 + 2 k3 + k4), with the stages folded together: x' = v
 * needs no copy, and the books (D, W, P), which no rate reads, no stage arguments. The
 * sum builds up in acc as the stages come, each pass also making the next stage's
 * argument. */
static int rk4(struct stepper *st, const struct drive *d, double a, double b, double *y)
{
    int n = st->n;
    double h = b - a, h2 = 0.5 * h, u[3], du[3], f[3];
    /* acc: the stages' sum for x (first n) and v; kv: a stage's accelerations; tx, tv:
     * the next stage's argument. None overlaps another (restrict: the loops may go two
     * values at a time, which changes no bit: each value is its own). */
    double *restrict x = y, *restrict v = y + n;
    double *restrict acc = st->k1, *restrict kv = st->k2;
    double *restrict tx = st->tmp, *restrict tv = st->tmp + n;
    drive3(st, d, a, b, u, du, f);
    st->start_u = u[0], st->start_du = du[0];
    st->end_u = u[2], st->end_du = du[2];
    double d0, w0, p0, dk, wk, pk;
    stage(st, x, v, u[0], du[0], f[0], acc + n, &d0, &w0, &p0);
    /* Each pass two values at a time (vec2.h: the same bits), the odd one alone; what a
     * stage has just stored a value at a time (kv, acc's v) loaded in halves. */
    int i = 0;
    for (; i + 1 < n; i += 2) {
        vec2 vi = vec2_load(v + i);
        vec2_store(tx + i, vec2_load(x + i) + h2 * vi);
        vec2_store(tv + i, vi + h2 * vec2_load_halves(acc + n + i));
    }
    for (; i < n; i++) {
        tx[i] = x[i] + h2 * v[i];
        tv[i] = v[i] + h2 * acc[n + i];
    }
    stage(st, tx, tv, u[1], du[1], f[1], kv, &dk, &wk, &pk);
    double sd = d0 + 2.0 * dk, sw = w0 + 2.0 * wk, sp = p0 + 2.0 * pk;
    for (i = 0; i + 1 < n; i += 2) {
        vec2 vi = vec2_load(tv + i), v0 = vec2_load(v + i), ki = vec2_load_halves(kv + i);
        vec2_store(acc + i, v0 + 2.0 * vi);
        vec2_store(acc + n + i, vec2_load(acc + n + i) + 2.0 * ki);
        vec2_store(tx + i, vec2_load(x + i) + h2 * vi);
        vec2_store(tv + i, v0 + h2 * ki);
    }
    for (; i < n; i++) {
        double vi = tv[i];
        acc[i] = v[i] + 2.0 * vi;
        acc[n + i] += 2.0 * kv[i];
        tx[i] = x[i] + h2 * vi;
        tv[i] = v[i] + h2 * kv[i];
    }
    stage(st, tx, tv, u[1], du[1], f[1], kv, &dk, &wk, &pk);
    sd += 2.0 * dk, sw += 2.0 * wk, sp += 2.0 * pk;
    for (i = 0; i + 1 < n; i += 2) {
        vec2 vi = vec2_load(tv + i), ki = vec2_load_halves(kv + i);
        vec2_store(acc + i, vec2_load(acc + i) + 2.0 * vi);
        vec2_store(acc + n + i, vec2_load(acc + n + i) + 2.0 * ki);
        vec2_store(tx + i, vec2_load(x + i) + h * vi);
        vec2_store(tv + i, vec2_load(v + i) + h * ki);
    }
    for (; i < n; i++) {
        double vi = tv[i];
        acc[i] += 2.0 * vi;
        acc[n + i] += 2.0 * kv[i];
        tx[i] = x[i] + h * vi;
        tv[i] = v[i] + h * kv[i];
    }
    stage(st, tx, tv, u[2], du[2], f[2], kv, &dk, &wk, &pk);
    double h6 = h / 6.0;
    /* The new state, and on it as it is made: some value not finite (bad's sign bits),
     * the largest |v_i| (vtop: past the cap?) and |x_i| change (xtop), for clearance.h. */
    vec2_bits bad = {0, 0};
    vec2 vtop = {0.0, 0.0}, xtop = {0.0, 0.0};
    for (i = 0; i + 1 < n; i += 2) {
        vec2 xo = vec2_load(x + i);
        vec2 xi = xo + h6 * (vec2_load(acc + i) + vec2_load(tv + i));
        vec2 vi = vec2_load(v + i) + h6 * (vec2_load(acc + n + i) + vec2_load_halves(kv + i));
        vec2_store(x + i, xi);
        vec2_store(v + i, vi);
        bad |= vec2_nonfinite_bits(xi) | vec2_nonfinite_bits(vi);
        vtop = vec2_max(vec2_abs(vi), vtop);
        xtop = vec2_max(vec2_abs(xi - xo), xtop);
    }
    uint64_t bad1 = bad[0] | bad[1];
    double vmax = vtop[0] > vtop[1] ? vtop[0] : vtop[1];
    double xmax = xtop[0] > xtop[1] ? xtop[0] : xtop[1];
    for (; i < n; i++) {
        double xo = x[i];
        x[i] += h6 * (acc[i] + tv[i]);
        v[i] += h6 * (acc[n + i] + kv[i]);
        bad1 |= nonfinite_bit(x[i]) | nonfinite_bit(v[i]);
        double av = fabs(v[i]), ax = fabs(x[i] - xo);
        vmax = av > vmax ? av : vmax;
        xmax = ax > xmax ? ax : xmax;
    }
    st->reach_v = vmax, st->reach_x = xmax;
    y[2 * n] += h6 * (sd + dk);
    y[2 * n + 1] += h6 * (sw + wk);
    y[2 * n + 2] += h6 * (sp + pk);
    bad1 |= nonfinite_bit(y[2 * n]) | nonfinite_bit(y[2 * n + 1]) | nonfinite_bit(y[2 * n + 2]);
    return (bad1 >> 63 ? STEPPER_NONFINITE : 0) | (vmax > MODEL_VMAX ? STEPPER_OVER_CAP : 0);
}

int stepper_rk4(struct stepper *st, const struct drive *d, double a, double b, double *y)
{
    st->constrained = st->rest && st->rest->active;
    if (st->constrained) /* only constrain reads it */
        st->ddu_factor = drive_ddu_factor(d);
    st->rot_before = st->rot; /* for stepper_undo_rk4 */
    return rk4(st, d, a, b, y);
}

void stepper_rk4_reach(const struct stepper *st, struct stepper_reach *r)
{
    *r = (struct stepper_reach){st->start_u, st->start_du, st->end_u, st->end_du, st->reach_x,
                                st->reach_v};
}

void stepper_undo_rk4(struct stepper *st)
{
    st->rot = st->rot_before;
}

/* Explicit Euler: y += h f(a, y). */
static void euler(struct stepper *st, const struct drive *d, double a, double b, double *y)
{
    int len = STEPPER_LEN(st->n);
    double u, du;
    drive_eval(d, a, &u, &du);
    deriv(st, y, u, du, drive_force(d, a), st->k1);
    for (int i = 0; i < len; i++)
        y[i] += (b - a) * st->k1[i];
}

/* Symplectic Euler: v from the forces at the start, then x with the new v; the books by
 * the rectangle rule. */
static void semi_implicit(struct stepper *st, const struct drive *d, double a, double b,
                          double *y)
{
    int n = st->n;
    double h = b - a, u, du;
    double *dy = st->k1;
    drive_eval(d, a, &u, &du);
    deriv(st, y, u, du, drive_force(d, a), dy);
    for (int i = 0; i < n; i++) {
        y[n + i] += h * dy[n + i];
        y[i] += h * y[n + i];
    }
    y[2 * n] += h * dy[2 * n];
    y[2 * n + 1] += h * dy[2 * n + 1];
    y[2 * n + 2] += h * dy[2 * n + 2];
}

/* Verlet's last half kick with spring dampers: the damping matrix C (ground dampers on
 * the diagonal, each spring damper coupling its two ends) is tridiagonal, so the new
 * velocity solves (M + h/2 C) v = M (vh + h/2 a0), a0 the accelerations at v = 0 (the
 * springs, the motor end's damper on u', the force): LAPACK's dptsv, M + h/2 C being
 * symmetric positive definite. */
static void verlet_kick_coupled(struct stepper *st, double h, const double *vh,
                                const double *a0, double *v)
{
    const struct model *m = st->model;
    int n = st->n;
    double *dg = st->tri, *off = st->tri + n, *rhs = st->tri + 2 * n;
    for (int i = 0; i < n; i++) {
        bool right = i < n - 1 || m->boundary != BOUNDARY_FREE;
        dg[i] = m->m[i] + 0.5 * h * (m->c[i] + m->cs[i] + (right ? m->cs[i + 1] : 0.0));
        if (i < n - 1)
            off[i] = -0.5 * h * m->cs[i + 1];
        rhs[i] = m->m[i] * (vh[i] + 0.5 * h * a0[i]);
    }
    if (LAPACKE_dptsv(LAPACK_COL_MAJOR, n, 1, dg, off, rhs, n) == 0) {
        memcpy(v, rhs, (size_t)n * sizeof *v);
        return;
    }
    for (int i = 0; i < n; i++) /* not positive definite: cannot be, but stay finite */
        v[i] = vh[i] + 0.5 * h * a0[i];
}

/* Velocity Verlet: half kick, drift, half kick. The damping force in the last half kick
 * is taken at the new velocity, solved for (it is linear in v), which keeps the method
 * second order with dampers; the books by the trapezoidal rule. */
static void verlet(struct stepper *st, const struct drive *d, double a, double b, double *y)
{
    int n = st->n;
    double h = b - a, u0, du0, u1, du1, f1 = drive_force(d, b);
    double *d0 = st->k1, *d1 = st->k2, *vh = st->tmp, *zero = st->tmp + n;
    drive_eval(d, a, &u0, &du0);
    drive_eval(d, b, &u1, &du1);
    deriv(st, y, u0, du0, drive_force(d, a), d0);
    for (int i = 0; i < n; i++) {
        vh[i] = y[n + i] + 0.5 * h * d0[n + i];
        y[i] += h * vh[i];
        zero[i] = 0.0;
    }
    /* The springs' accelerations at the new positions (no damping: v = 0). */
    model_rates(st->model, st->inv_m, y, zero, u1, du1, d1 + n, NULL, NULL);
    if (f1 != 0.0)
        d1[n + st->model->force_on] += f1 * st->inv_m[st->model->force_on];
    if (st->model->spring_damped)
        verlet_kick_coupled(st, h, vh, d1 + n, y + n);
    else
        for (int i = 0; i < n; i++)
            y[n + i] = (vh[i] + 0.5 * h * d1[n + i]) /
                       (1.0 + 0.5 * h * st->model->c[i] * st->inv_m[i]);
    deriv(st, y, u1, du1, f1, d1);
    y[2 * n] += 0.5 * h * (d0[2 * n] + d1[2 * n]);
    y[2 * n + 1] += 0.5 * h * (d0[2 * n + 1] + d1[2 * n + 1]);
    y[2 * n + 2] += 0.5 * h * (d0[2 * n + 2] + d1[2 * n + 2]);
}

void drive_exact(const struct drive *d, double a, struct exact_drive *ed)
{
    *ed = (struct exact_drive){0};
    ed->force = d->force;
    if (d->kind == DRIVE_SINE) {
        ed->sine = 1;
        ed->amp = d->amp;
        ed->omega = 2.0 * M_PI * d->motor->frequency;
        ed->phi = 2.0 * M_PI * d->motor->phase;
    } else if (d->kind == DRIVE_PIECE) {
        ed->t0 = a;
        drive_eval(d, a, &ed->u0, &ed->du);
        drive_unit(d, a, &ed->w0, &ed->dw);
    }
}

/* The exact stepper: the piece's drive in exact.c's terms. */
static int exact_step(struct stepper *st, const struct drive *d, double a, double b, double *y)
{
    int n = st->n;
    if (!st->exact && !(st->exact = exact_new(n)))
        return -1;
    struct exact_drive ed;
    drive_exact(d, a, &ed);
    return exact_advance_all(st->exact, st->model, &ed, a, b, y, y + n, &y[2 * n],
                             &y[2 * n + 1], &y[2 * n + 2]);
}

/* The exact stepper while contacts rest: the constrained chain is another linear system,
 * taken here by RK4 in sub-steps short enough (the fastest rate times the sub-step at
 * most EXACT_REST_STEP) to keep its error near 1e-12 of the motion. */
#define EXACT_REST_STEP 0.01
static void exact_resting(struct stepper *st, const struct drive *d, double a, double b,
                          double *y)
{
    const struct model *m = st->model;
    double rate = 0.0;
    for (int i = 0; i < st->n; i++) {
        /* Gershgorin: w^2 <= 2 max (k_i + k_i+1) / m_i; the damper's rate c / m. */
        double k = m->k[i] + (i + 1 < st->n || m->boundary != BOUNDARY_FREE ? m->k[i + 1] : 0);
        double c = m->c[i] + 2.0 * (m->cs[i] + m->cs[i + 1]);
        rate = fmax(rate, sqrt(2.0 * k / m->m[i]) + c / m->m[i]);
    }
    int subs = (int)fmin(1e5, ceil((b - a) * rate / EXACT_REST_STEP));
    subs = subs < 1 ? 1 : subs;
    for (int j = 0; j < subs; j++)
        rk4(st, d, a + (b - a) * j / subs, j + 1 == subs ? b : a + (b - a) * (j + 1) / subs, y);
}

int stepper_apply(struct stepper *st, enum integrator i, const struct drive *d, double a,
                  double b, double *y)
{
    st->ddu_factor = drive_ddu_factor(d);
    st->constrained = st->rest && st->rest->active;
    if (i != INTEGRATOR_RK4) {
        drive_eval(d, a, &st->start_u, &st->start_du);
        drive_eval(d, b, &st->end_u, &st->end_du);
    }
    switch (i) {
    case INTEGRATOR_EULER:
        euler(st, d, a, b, y);
        return 0;
    case INTEGRATOR_SEMI_IMPLICIT:
        semi_implicit(st, d, a, b, y);
        return 0;
    case INTEGRATOR_VERLET:
        verlet(st, d, a, b, y);
        return 0;
    case INTEGRATOR_EXACT:
        if (st->constrained) {
            exact_resting(st, d, a, b, y);
            drive_eval(d, a, &st->start_u, &st->start_du);
            drive_eval(d, b, &st->end_u, &st->end_du);
            return 0;
        }
        return exact_step(st, d, a, b, y);
    case INTEGRATOR_RK4:
    case INTEGRATOR_COUNT:
        break;
    }
    rk4(st, d, a, b, y);
    return 0;
}
