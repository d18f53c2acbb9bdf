/* test_sim.c: the stepper against independent answers: a single undamped mass against
 * cos(w t), a non-uniform chain under every waveform against a Taylor-series solution
 * of the same linear ODE (order 24, stopped exactly at every breakpoint), 4th-order
 * convergence, the energy balance, and a failed step leaving the state untouched. */
#include "testutil.h"

#include <stdlib.h>
#include <string.h>

#include "core/model.h"
#include "core/sim.h"

#define N3 3

/* The non-uniform 3-mass chain of the accuracy goals. */
static struct model *chain3(enum wave wave)
{
    static const double m[N3] = {1.0, 1.5, 0.8}, k[N3 + 1] = {10, 14, 8, 12};
    static const double c[N3] = {0.1, 0.2, 0.05};
    struct model *md = model_new(N3);
    memcpy(md->m, m, sizeof m);
    memcpy(md->k, k, sizeof k);
    memcpy(md->c, c, sizeof c);
    md->motor = (struct motor){wave, 0.3, 0.9, 0.0};
    md->collisions = false;
    return md;
}

/* ---- the reference: Taylor series of y' = A y + b(t), written from the model's definition alone ---- */

#define ORDER 24

struct drive {          /* u(t) on one smooth piece */
    int sine;           /* 1: u = A sin(w t) */
    double amp, w;      /* for the sine */
    double u0, slope, t0; /* otherwise u = u0 + slope (t - t0) */
};

/* The waveform formulas of the definition, evaluated inside a piece around tm. */
static struct drive drive_at(enum wave wave, double a, double f, double tm)
{
    double th = 2.0 * M_PI * f * tm;
    struct drive d = {0, a, 2.0 * M_PI * f, 0.0, 0.0, tm};
    switch (wave) {
    case WAVE_SINE:
        d.sine = 1;
        break;
    case WAVE_SQUARE:
        d.u0 = a * (sin(th) > 0 ? 1.0 : -1.0);
        break;
    case WAVE_TRIANGLE:
        d.u0 = a * (2.0 / M_PI) * asin(sin(th));
        d.slope = a * 4.0 * f * (cos(th) > 0 ? 1.0 : -1.0);
        break;
    case WAVE_SAWTOOTH: {
        double q = th / (2.0 * M_PI) + 0.5;
        d.u0 = a * (2.0 * (q - floor(q)) - 1.0);
        d.slope = a * 2.0 * f;
        break;
    }
    default:
        break;
    }
    return d;
}

/* p-th derivative of u at t. */
static double drive_deriv(const struct drive *d, int p, double t)
{
    if (d->sine)
        return d->amp * pow(d->w, p) * sin(d->w * t + p * M_PI / 2.0);
    if (p == 0)
        return d->u0 + d->slope * (t - d->t0);
    return p == 1 ? d->slope : 0.0;
}

/* One Taylor step of length h from t for the chain md (motor end). */
static void taylor_step(const struct model *md, const struct drive *d, double t, double h,
                        double *y)
{
    int n = md->n;
    double term[2 * N3], next[2 * N3] = {0}, sum[2 * N3];
    memcpy(term, y, sizeof term);
    memcpy(sum, y, sizeof sum);
    double fact = 1.0;
    for (int p = 0; p < ORDER; p++) {
        /* next = d/dt of the p-th derivative: x' = v, v' = M^-1(-K x - C v + k_N e_N u) */
        for (int i = 0; i < n; i++) {
            double xl = i > 0 ? term[i - 1] : 0.0;
            double xr = i < n - 1 ? term[i + 1] : drive_deriv(d, p, t);
            double f = -md->k[i] * (term[i] - xl) + md->k[i + 1] * (xr - term[i]) -
                       md->c[i] * term[n + i];
            next[i] = term[n + i];
            next[n + i] = f / md->m[i];
        }
        memcpy(term, next, sizeof term);
        fact *= h / (p + 1);
        for (int i = 0; i < 2 * n; i++)
            sum[i] += fact * term[i];
    }
    memcpy(y, sum, sizeof sum);
}

/* Breakpoints of the waveform in cycles: first and period. */
static void breaks_of(enum wave wave, double *first, double *period)
{
    *first = wave == WAVE_TRIANGLE ? 0.25 : wave == WAVE_SAWTOOTH ? 0.5 : 0.0;
    *period = wave == WAVE_SAWTOOTH ? 1.0 : wave == WAVE_SINE ? 1e30 : 0.5;
}

/* Advances y from t0 to t1 with Taylor steps of at most 1 ms, stopping at breakpoints. */
static void reference_advance(const struct model *md, double t0, double t1, double *y)
{
    double first, period, f = md->motor.frequency;
    breaks_of(md->motor.wave, &first, &period);
    double t = t0;
    while (t < t1 - 1e-15) {
        double c = f * t;
        double next_b = (first + period * floor((c - first) / period + 1.0)) / f;
        if (next_b <= t + 1e-13)
            next_b += period / f;
        double end = fmin(t1, next_b);
        int steps = (int)ceil((end - t) / 1e-3);
        double h = (end - t) / steps;
        struct drive d = drive_at(md->motor.wave, md->motor.amplitude, f, 0.5 * (t + end));
        for (int s = 0; s < steps; s++)
            taylor_step(md, &d, t + s * h, h, y);
        t = end;
    }
}

/* Max |displacement error| of sim with integrator i against the reference over
 * [0, duration]. */
static double integrator_error(enum wave wave, enum integrator integ, double dt,
                               double duration)
{
    struct model *md = chain3(wave);
    struct sim *s = sim_new(md, dt);
    sim_set_integrator(s, integ);
    double y[2 * N3] = {0};
    double err = 0.0;
    int steps = (int)lround(duration / dt);
    for (int n = 1; n <= steps; n++) {
        assert_int_equal(sim_step(s), SIM_OK);
        reference_advance(md, (n - 1) * dt, n * dt, y);
        for (int i = 0; i < N3; i++)
            err = fmax(err, fabs(sim_x(s)[i] - y[i]));
    }
    sim_free(s);
    model_free(md);
    return err;
}

/* Max |displacement error| of the default RK4 over [0, 20 s]. */
static double chain_error(enum wave wave, double dt)
{
    return integrator_error(wave, INTEGRATOR_RK4, dt, 20.0);
}

/* Each integrator shows its order on every waveform: 1 for Euler and symplectic Euler,
 * 2 for Verlet, 4 for RK4, when dt is halved; exact is exact to rounding at dt = 0.05,
 * 0.01, 0.005 and 0.001. */
static void integrator_orders(void **state)
{
    (void)state;
    static const struct {
        enum integrator i;
        double lo, hi, dt;
    } want[] = {{INTEGRATOR_EULER, 0.85, 1.2, 0.002},
                {INTEGRATOR_SEMI_IMPLICIT, 0.85, 1.2, 0.002},
                {INTEGRATOR_VERLET, 1.85, 2.2, 0.004},
                {INTEGRATOR_RK4, 3.7, 4.4, 0.02}};
    printf("  %-14s %-9s %12s %12s %7s\n", "integrator", "waveform", "err dt", "err dt/2",
           "order");
    for (size_t k = 0; k < sizeof want / sizeof *want; k++)
        for (int w = 0; w < WAVE_COUNT; w++) {
            double e1 = integrator_error((enum wave)w, want[k].i, want[k].dt, 2.0);
            double e2 = integrator_error((enum wave)w, want[k].i, 0.5 * want[k].dt, 2.0);
            double order = log2(e1 / e2);
            printf("  %-14s %-9s %12.3e %12.3e %7.2f\n", integrator_name(want[k].i),
                   motor_wave_name((enum wave)w), e1, e2, order);
            if (!(order >= want[k].lo && order <= want[k].hi))
                fail_msg("%s on %s: order %.2f, expected %.2f..%.2f", integrator_name(want[k].i),
                         motor_wave_name((enum wave)w), order, want[k].lo, want[k].hi);
        }
    static const double exact_dts[] = {0.05, 0.01, 0.005, 0.001};
    double worst = 0.0;
    for (size_t k = 0; k < sizeof exact_dts / sizeof *exact_dts; k++)
        for (int w = 0; w < WAVE_COUNT; w++) {
            double e = integrator_error((enum wave)w, INTEGRATOR_EXACT, exact_dts[k], 20.0);
            printf("  %-14s %-9s %12.3e at dt = %g over 20 s\n", "exact",
                   motor_wave_name((enum wave)w), e, exact_dts[k]);
            assert_true(e <= 1e-9);
            worst = fmax(worst, e);
        }
    printf("  exact: at most %.2e m over those dt and waveforms\n", worst);
}

static void accuracy_and_order(void **state)
{
    (void)state;
    printf("  non-uniform 3-mass chain, A = 0.3 m, f = 0.9 Hz, 20 s, against Taylor order %d\n",
           ORDER);
    printf("  %-9s %14s %14s %8s\n", "waveform", "err dt=0.01", "err dt=0.005", "order");
    for (int w = 0; w < WAVE_COUNT; w++) {
        double e1 = chain_error((enum wave)w, 0.01);
        double e2 = chain_error((enum wave)w, 0.005);
        double order = log2(e1 / e2);
        printf("  %-9s %14.3e %14.3e %8.2f\n", motor_wave_name((enum wave)w), e1, e2, order);
        assert_true(e1 <= 5e-5);
        assert_true(order >= 3.5);
    }
}

/* The reference itself must be right: it agrees with the closed-form undamped single
 * mass, so the chain comparison above is against a true answer. A mass m between springs
 * k0 and k1 to fixed ends, from x0 at rest, moves as x0 cos(w t), w = sqrt((k0 + k1)/m).
 * The end is held by a drive of zero amplitude, the reference's form of a wall. */
static void reference_single_mass_cosine(void **state)
{
    (void)state;
    struct model *md = model_new(1);
    md->c[0] = 0.0;
    md->k[0] = 7.0;
    md->k[1] = 5.0;
    md->m[0] = 2.0;
    md->motor = (struct motor){WAVE_SINE, 0.0, 0.9, 0.0};
    double x0 = 0.8, w = sqrt(12.0 / 2.0), dt = 0.01;
    double y[2 * N3] = {x0, 0.0}; /* x then v, as taylor_step lays them out for n = 1 */
    double err = 0.0, verr = 0.0;
    for (int n = 1; n <= 2000; n++) {
        reference_advance(md, (n - 1) * dt, n * dt, y);
        double t = n * dt;
        err = fmax(err, fabs(y[0] - x0 * cos(w * t)));
        verr = fmax(verr, fabs(y[1] + x0 * w * sin(w * t)));
    }
    /* Truncation, (w h)^25 / 25! a step, is nil; what is left is the rounding of 20000
     * steps and of cos(w t) itself at w t ~ 49. */
    printf("  Taylor reference vs cos(wt) over 20 s: |x err| %.2e m, |v err| %.2e m/s\n", err,
           verr);
    assert_true(err < 1e-12);
    assert_true(verr < 1e-12);
    model_free(md);
}

/* The stepper on the same single undamped mass, wall end, against x0 cos(w t). */
static void single_mass_cosine(void **state)
{
    (void)state;
    struct model *md = model_new(1);
    md->boundary = BOUNDARY_WALL;
    md->c[0] = 0.0;
    md->k[0] = 7.0;
    md->k[1] = 5.0;
    md->m[0] = 2.0;
    md->collisions = false;
    double x0 = 0.8, w = sqrt(12.0 / 2.0), dt = 0.01;
    struct sim *s = sim_new(md, dt);
    sim_reset(s, &x0, NULL);
    double err = 0.0, verr = 0.0;
    for (int n = 1; n <= 2000; n++) {
        sim_step(s);
        double t = n * dt;
        err = fmax(err, fabs(sim_x(s)[0] - x0 * cos(w * t)));
        verr = fmax(verr, fabs(sim_v(s)[0] + x0 * w * sin(w * t)));
    }
    /* RK4's global error here is about T (w dt)^4 w x0 / 120: 20 s gives ~3e-7 m. */
    printf("  single mass vs cos(wt) over 20 s: |x err| %.2e m, |v err| %.2e m/s\n", err, verr);
    assert_true(err < 1e-6);
    assert_true(verr < 3e-6);
    assert_close(sim_time(s), 20.0, 1e-12);
    sim_free(s);
    model_free(md);
}

/* Max |balance - initial balance| over 100 s, and the peak total energy. */
static double energy_drift(enum wave wave, double dt, double *peak)
{
    struct model *md = chain3(wave);
    struct sim *s = sim_new(md, dt);
    double x0[N3] = {0.3, -0.2, 0.1};
    sim_reset(s, x0, NULL);
    struct energy e;
    sim_energy(s, &e);
    double start = e.balance, drift = 0.0;
    *peak = 0.0;
    int steps = (int)lround(100.0 / dt);
    for (int n = 0; n < steps; n++) {
        sim_step(s);
        sim_energy(s, &e);
        drift = fmax(drift, fabs(e.balance - start));
        *peak = fmax(*peak, e.kinetic + e.potential);
        assert_true(e.contact == 0.0);
    }
    sim_free(s);
    model_free(md);
    return drift;
}

static void energy_balance(void **state)
{
    (void)state;
    printf("  energy balance over 100 s, no collisions: drift / peak energy\n");
    for (int w = 0; w < WAVE_COUNT; w++) {
        double peak1, peak2;
        double d1 = energy_drift((enum wave)w, 0.01, &peak1);
        double d2 = energy_drift((enum wave)w, 0.005, &peak2);
        printf("  %-9s dt=0.01: %.2e   dt=0.005: %.2e   ratio %.1f\n",
               motor_wave_name((enum wave)w), d1 / peak1, d2 / peak2, d1 / d2);
        assert_true(d1 <= 1e-5 * peak1);
        /* It falls as dt^4: halving dt divides it by about 16. */
        assert_true(d1 / d2 >= 11.0);
    }
}

/* With nothing driving or damping, kinetic + potential alone is constant. */
static void free_oscillation_conserves(void **state)
{
    (void)state;
    struct model *md = model_new(4);
    md->boundary = BOUNDARY_FREE;
    for (int i = 0; i < 4; i++)
        md->c[i] = 0.0;
    md->collisions = false;
    struct sim *s = sim_new(md, 0.01);
    double x0[4] = {0.5, -0.3, 0.2, 0.4};
    sim_reset(s, x0, NULL);
    struct energy e;
    sim_energy(s, &e);
    double e0 = e.kinetic + e.potential;
    for (int n = 0; n < 5000; n++)
        sim_step(s);
    sim_energy(s, &e);
    /* RK4 on an oscillator scales each mode's amplitude by |R(iwh)| = 1 - (wh)^6/144 + ...
     * a step, so the energy may fall by at most 2 steps (w_max h)^6 / 144, and must not
     * rise. w_max < 2 sqrt(k/m) for this chain. */
    double wh = 2.0 * sqrt(10.0) * 0.01;
    double bound = 2.0 * 5000 * pow(wh, 6) / 144.0 * e0;
    assert_true(e.kinetic + e.potential <= e0);
    assert_close(e.kinetic + e.potential, e0, bound);
    assert_true(e.dissipated == 0.0 && e.motor_work == 0.0);
    sim_free(s);
    model_free(md);
}

/* Changing dt keeps the time and puts later steps on t + n*dt. */
static void dt_change_keeps_time(void **state)
{
    (void)state;
    struct model *md = model_new(2);
    struct sim *s = sim_new(md, 0.01);
    for (int n = 0; n < 100; n++)
        sim_step(s);
    assert_close(sim_time(s), 1.0, 1e-12);
    sim_set_dt(s, 0.005);
    for (int n = 0; n < 100; n++)
        sim_step(s);
    assert_close(sim_time(s), 1.5, 1e-12);
    sim_free(s);
    model_free(md);
}

/* A step that overflows is refused and leaves the state exactly as it was. */
static void nonfinite_step_restores(void **state)
{
    (void)state;
    struct model *md = model_new(2);
    md->k[0] = md->k[1] = md->k[2] = 1e308;
    md->collisions = false;
    struct sim *s = sim_new(md, 0.05);
    double x0[2] = {0.5, -0.5};
    sim_reset(s, x0, NULL);
    double before[64];
    sim_save(s, before);
    assert_int_equal(sim_step(s), SIM_NONFINITE);
    double after[64];
    sim_save(s, after);
    assert_memory_equal(before, after, (size_t)sim_snapshot_size(s) * sizeof(double));
    sim_free(s);
    model_free(md);
}

/* A drive so fast that a step holds more breakpoints than are split at once (16): every
 * one still counts. A square wave at 200 Hz has 20 jumps in a 0.05 s step; the chain
 * cannot follow it, so dt = 0.05 must agree with dt = 0.001. */
static void many_breakpoints_per_step(void **state)
{
    (void)state;
    double x[2];
    const double dts[2] = {0.05, 0.001};
    for (int k = 0; k < 2; k++) {
        struct model *md = model_new(2);
        md->motor = (struct motor){WAVE_SQUARE, 1.0, 200.0, 0.0};
        md->collisions = false;
        struct sim *s = sim_new(md, dts[k]);
        while (sim_time(s) < 1.0 - 1e-9)
            sim_step(s);
        x[k] = sim_x(s)[0];
        sim_free(s);
        model_free(md);
    }
    assert_close(x[0], x[1], 1e-6);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(reference_single_mass_cosine),
        cmocka_unit_test(single_mass_cosine),
        cmocka_unit_test(accuracy_and_order),
        cmocka_unit_test(integrator_orders),
        cmocka_unit_test(energy_balance),
        cmocka_unit_test(free_oscillation_conserves),
        cmocka_unit_test(dt_change_keeps_time),
        cmocka_unit_test(nonfinite_step_restores),
        cmocka_unit_test(many_breakpoints_per_step),
    };
    return cmocka_run_group_tests_name("sim", tests, NULL, NULL);
}
