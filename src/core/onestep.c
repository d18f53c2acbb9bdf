/* onestep.c: the one-step matrix of each integrator on the chain, its spectral radius,
 * and the steady driven motion the integrator gives (onestep.h).
 *
 * Between contacts the chain is linear (cubic springs linearised at rest), and every
 * stepper but the exact one maps
 * z = (x, v) by z_{n+1} = S z_n + (the drive's part). S is built here by the stepper
 * itself, one unit vector at a time, so it is the integrator's own matrix, whatever
 * the damping: for euler and rk4 it is R(hA) (R the stability polynomial), for
 * semi-implicit and verlet, which treat x and v apart, no function of A at all. dt is
 * stable while S's spectral radius rho <= 1 (dgeev on 2N x 2N).
 *
 * The largest stable h is found along h: a scan of h * scale in steps of 1/16 up to 8,
 * then growing by 1/16 a step up to 1e6 (verlet's implicit damping keeps a heavily
 * damped chain stable far past its fastest eigenvalue), then bisection inside the first
 * bad interval (stopping when lo and hi are neighbouring doubles, where halving no
 * longer moves either). A stable interval narrower than the scan's step beyond the first
 * unstable h does not count: the limit is the first h that fails. */
#include "onestep.h"

#include <complex.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <lapacke.h>

#include "stepper.h"

#define RHO_TOL 1e-12    /* rho this far above 1 is rounding, not growth */
#define SCAN_STEP 0.0625 /* of h * scale, up to SCAN_LINEAR */
#define SCAN_LINEAR 8.0
#define SCAN_END 1e6 /* no bad h below this h * scale: none at all */
#define BISECTIONS 50

struct onestep {
    int n;
    struct model *model;     /* the chain, its drive a unit sine of phase 0 */
    struct stepper *stepper; /* its steps */
    double *s;               /* S, 2N x 2N */
    double *a;               /* dgeev's copy, then A */
    double *re, *im;         /* eigenvalues, 2N each */
    double *y;               /* a state for the stepper, STEPPER_LEN(N) */
    bool by_force;           /* the drive is the force input (no motor end), F = 1 */
    lapack_complex_double *lhs, *rhs; /* the steady-state solves, 2N x 2N and 2N x 2 */
    lapack_int *pivot;       /* 2N */
    double exact_f;          /* the drive frequency whose exact steady state rhs's second
                              * column holds, or NAN */
    double exact_near;       /* its size one part in a million off exact_f */
};

struct onestep *onestep_new(const struct model *m)
{
    int n = m->n;
    if (n < 1 || n > ONESTEP_MAX)
        return NULL;
    size_t n2 = (size_t)(2 * n), sq = n2 * n2;
    struct onestep *o = calloc(1, sizeof *o);
    if (!o)
        return NULL;
    o->n = n;
    o->exact_f = NAN;
    o->model = model_new(n);
    o->s = malloc((2 * sq + 3 * n2 + 3) * sizeof *o->s);
    o->lhs = malloc((sq + 2 * n2) * sizeof *o->lhs);
    o->pivot = malloc(n2 * sizeof *o->pivot);
    if (!o->model || !o->s || !o->lhs || !o->pivot) {
        onestep_free(o);
        return NULL;
    }
    model_copy(o->model, m);
    /* A chain with cubic springs linearised at rest: k3 cleared, not just the flag, so that
     * the stepper's own copy (model_copy, model_sync) stays linear too. */
    memset(o->model->k3, 0, (size_t)(m->n + 1) * sizeof *o->model->k3);
    o->model->cubic = false;
    o->model->motor.wave = WAVE_SINE;
    o->model->motor.amplitude = 1.0;
    o->model->motor.phase = 0.0;
    /* The drive judged: the motor's where it has one, else the force's, at unit size. */
    o->by_force = m->boundary != BOUNDARY_MOTOR && model_forced(m);
    o->model->force = o->by_force ? 1.0 : 0.0;
    o->stepper = stepper_new(o->model);
    if (!o->stepper) {
        onestep_free(o);
        return NULL;
    }
    o->a = o->s + sq;
    o->re = o->a + sq;
    o->im = o->re + n2;
    o->y = o->im + n2;
    o->rhs = o->lhs + sq;
    return o;
}

void onestep_free(struct onestep *o)
{
    if (!o)
        return;
    stepper_free(o->stepper);
    model_free(o->model);
    free(o->s);
    free(o->lhs);
    free(o->pivot);
    free(o);
}

/* One step of integrator i from (x, v) = y over [0, h] with drive d; y's books zeroed. */
static void step(struct onestep *o, enum integrator i, const struct drive *d, double h)
{
    int n2 = 2 * o->n;
    o->y[n2] = o->y[n2 + 1] = o->y[n2 + 2] = 0.0;
    stepper_apply(o->stepper, i, d, 0.0, h, o->y);
}

void onestep_matrix(struct onestep *o, enum integrator i, double h, double *s)
{
    int n2 = 2 * o->n;
    struct drive still = {.kind = DRIVE_NONE, .motor = &o->model->motor};
    stepper_set_model(o->stepper, o->model, h);
    for (int j = 0; j < n2; j++) {
        memset(o->y, 0, (size_t)(n2 + 3) * sizeof *o->y);
        o->y[j] = 1.0;
        step(o, i, &still, h);
        memcpy(s + (size_t)j * (size_t)n2, o->y, (size_t)n2 * sizeof *s);
    }
}

double onestep_radius(struct onestep *o, enum integrator i, double h)
{
    int n2 = 2 * o->n;
    onestep_matrix(o, i, h, o->a);
    for (size_t k = 0; k < (size_t)n2 * (size_t)n2; k++)
        if (!isfinite(o->a[k]))
            return INFINITY; /* a step this long overflows: no use */
    if (LAPACKE_dgeev(LAPACK_COL_MAJOR, 'N', 'N', n2, o->a, n2, o->re, o->im, NULL, 1, NULL,
                      1) != 0)
        return NAN;
    double rho = 0.0;
    for (int k = 0; k < n2; k++)
        rho = fmax(rho, hypot(o->re[k], o->im[k]));
    return rho;
}

double onestep_search_below(bool (*good)(void *ctx, double h), void *ctx, double scale,
                            double ceiling)
{
    if (!(scale > 0.0) || !isfinite(scale))
        return INFINITY;
    double lo = 0.0, hi = NAN;
    for (double t = SCAN_STEP; t <= SCAN_END;
         t = t < SCAN_LINEAR ? t + SCAN_STEP : t * (1.0 + SCAN_STEP)) {
        if (!good(ctx, t / scale)) {
            hi = t;
            break;
        }
        lo = t;
        if (lo / scale >= ceiling)
            return INFINITY; /* the answer is at least lo / scale */
    }
    if (isnan(hi))
        return INFINITY;
    for (int k = 0; k < BISECTIONS; k++) {
        double mid = 0.5 * (lo + hi);
        if (mid == lo || mid == hi)
            break; /* lo and hi are neighbours: no later halving moves either */
        if (good(ctx, mid / scale))
            lo = mid;
        else
            hi = mid;
        if (lo / scale >= ceiling)
            return INFINITY;
    }
    return lo / scale;
}

double onestep_search(bool (*good)(void *ctx, double h), void *ctx, double scale)
{
    return onestep_search_below(good, ctx, scale, INFINITY);
}

/* What the search along h is given. */
struct stable_ctx {
    struct onestep *o;
    enum integrator i;
};

static bool stable_at(void *ctx, double h)
{
    struct stable_ctx *c = ctx;
    return onestep_radius(c->o, c->i, h) <= 1.0 + RHO_TOL; /* NAN: not known stable */
}

double onestep_stable_dt(struct onestep *o, enum integrator i, double scale)
{
    if (i == INTEGRATOR_EXACT)
        return INFINITY;
    struct stable_ctx c = {o, i};
    return onestep_search(stable_at, &c, scale);
}

/* The drive's part of one step from rest: the state after [0, h] under u = sin(w t +
 * 2 pi phase), into column col of o->rhs's real or imaginary part (sign). */
static void drive_column(struct onestep *o, enum integrator i, double h, double phase,
                         double complex weight)
{
    int n2 = 2 * o->n;
    stepper_set_phase(o->stepper, phase, h);
    /* The stepper's own motor, which carries the phase: euler, semi-implicit and verlet
     * evaluate the drive through d.motor, rk4 through the stepper's model. */
    const struct model *sm = stepper_model(o->stepper);
    struct drive d = {.kind = DRIVE_SINE, .motor = &sm->motor, .amp = o->by_force ? 0.0 : 1.0,
                      .force = sm->force, .force_on = sm->force_on};
    memset(o->y, 0, (size_t)(n2 + 3) * sizeof *o->y);
    step(o, i, &d, h);
    for (int k = 0; k < n2; k++)
        o->rhs[k] += weight * o->y[k];
}

/* The steady state of z_{n+1} = S z_n + Re(G e^{i w t_n}): Z = (e^{i w h} - S)^-1 G.
 * A step from t_n under sin(w (t_n + tau)) = sin(w tau) cos(w t_n) + cos(w tau)
 * sin(w t_n) gives g_s cos(w t_n) + g_c sin(w t_n) = Re((g_s - i g_c) e^{i w t_n}),
 * g_s and g_c the steps from rest under sin(w tau) and cos(w tau). Into rhs; 0 or -1. */
static int numerical_steady(struct onestep *o, enum integrator i, double h, double w)
{
    int n2 = 2 * o->n;
    onestep_matrix(o, i, h, o->s);
    double complex rot = cexp(I * w * h);
    for (int j = 0; j < n2; j++)
        for (int k = 0; k < n2; k++)
            o->lhs[k + (size_t)j * n2] = (k == j ? rot : 0.0) - o->s[k + (size_t)j * n2];
    memset(o->rhs, 0, (size_t)n2 * sizeof *o->rhs);
    drive_column(o, i, h, 0.0, 1.0);
    drive_column(o, i, h, 0.25, -I);
    stepper_set_phase(o->stepper, 0.0, h);
    return LAPACKE_zgesv(LAPACK_COL_MAJOR, n2, 1, o->lhs, n2, o->pivot, o->rhs, n2) == 0 ? 0
                                                                                        : -1;
}

/* The exact steady state of z' = A z + Re(F e^{i w t}) with the right end at
 * u = sin(w t) = Re(-i e^{i w t}): F = -i (k_N + i w cs_N) / m_N at v_N (the end's spring
 * and damper), or under the force sin(w t) on mass K, F = -i / m_K at v_K;
 * Z = (i w - A)^-1 F, into rhs's second column; 0 or -1. */
static int exact_steady(struct onestep *o, double w)
{
    int n = o->n, n2 = 2 * n;
    lapack_complex_double *z = o->rhs + n2;
    if (model_first_order(o->model, o->a, o->s) != 0) /* o->s: 3N of scratch here */
        return -1;
    for (int j = 0; j < n2; j++)
        for (int k = 0; k < n2; k++)
            o->lhs[k + (size_t)j * n2] = (k == j ? I * w : 0.0) - o->a[k + (size_t)j * n2];
    memset(z, 0, (size_t)n2 * sizeof *z);
    const struct model *m = o->model;
    if (o->by_force)
        z[n + m->force_on] = -I / m->m[m->force_on];
    else
        z[n2 - 1] = -I * (m->k[n] + I * w * m->cs[n]) / m->m[n - 1];
    return LAPACKE_zgesv(LAPACK_COL_MAJOR, n2, 1, o->lhs, n2, o->pivot, z, n2) == 0 ? 0 : -1;
}

/* onestep_drive_error, h stable or not. The exact steady state depends on f alone: it is
 * solved once for a search along h and waits in rhs's second column, which the
 * integrator's solve (the first) leaves alone. */
static double drive_error(struct onestep *o, enum integrator i, double h, double f)
{
    int n = o->n;
    double w = 2.0 * M_PI * f;
    o->model->motor.frequency = f;
    stepper_set_model(o->stepper, o->model, h);
    if (!(o->exact_f == f)) {
        o->exact_f = NAN;
        /* On an undamped mode the steady motion has no size: one part in a million off
         * the drive's frequency it changes by more than a tenth. Not known rough, then. */
        if (exact_steady(o, w * (1.0 + 1e-6)) != 0)
            return NAN;
        double near = 0.0;
        for (int k = 0; k < n; k++)
            near = fmax(near, cabs(o->rhs[2 * n + k]));
        if (exact_steady(o, w) != 0)
            return NAN;
        o->exact_near = near;
        o->exact_f = f;
    }
    if (numerical_steady(o, i, h, w) != 0)
        return NAN;
    const lapack_complex_double *num = o->rhs, *ex = o->rhs + 2 * n;
    double diff = 0.0, size = 0.0;
    for (int k = 0; k < n; k++) {
        diff = fmax(diff, cabs(num[k] - ex[k]));
        size = fmax(size, cabs(ex[k]));
    }
    if (!(fabs(o->exact_near - size) <= 0.1 * size))
        return NAN;
    return size > 0.0 ? diff / size : NAN;
}

double onestep_drive_error(struct onestep *o, enum integrator i, double h, double f)
{
    stepper_set_model(o->stepper, o->model, h);
    if (onestep_radius(o, i, h) > 1.0 + RHO_TOL)
        return NAN;
    return drive_error(o, i, h, f);
}

double onestep_drive_error_stable(struct onestep *o, enum integrator i, double h, double f)
{
    return drive_error(o, i, h, f);
}
