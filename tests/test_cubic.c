/* test_cubic.c: cubic springs (force k s + k3 s^3) in the equation of motion, the energy
 * books and the integrators: against the force written out by hand, against GSL's
 * rk8pd on the same equations written here independently, the energy balance of a driven
 * chain, the linearisation the modes and limits use, and exact's refusal. */
#include "testutil.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>
#include <string.h>

#include "core/config.h"
#include "core/model.h"
#include "core/sim.h"

static struct model *three(void)
{
    struct model *m = model_new(3);
    const double mm[3] = {1.0, 2.0, 0.5}, k[4] = {3.0, 5.0, 7.0, 11.0};
    const double k3[4] = {40.0, -2.0, 0.0, 25.0}, c[3] = {0.1, 0.2, 0.3};
    for (int i = 0; i < 3; i++)
        m->m[i] = mm[i], m->c[i] = c[i];
    for (int j = 0; j < 4; j++)
        m->k[j] = k[j], m->k3[j] = k3[j];
    model_set_cubic(m);
    m->collisions = false;
    return m;
}

/* Spring force and energy by hand. */
static double force(double k, double k3, double s) { return k * s + k3 * s * s * s; }
static double energy(double k, double k3, double s)
{
    return 0.5 * k * s * s + 0.25 * k3 * s * s * s * s;
}

static void equation_of_motion(void **state)
{
    (void)state;
    struct model *m = three();
    assert_true(m->cubic);
    const double x[3] = {0.1, -0.2, 0.3}, v[3] = {1.0, -1.0, 0.5}, u = 0.7;
    double a[3];
    model_accel(m, x, v, u, a);
    double f0 = force(3, 40, 0.1), f1 = force(5, -2, -0.3), f2 = force(7, 0, 0.5),
           f3 = force(11, 25, u - 0.3);
    assert_close(a[0], (f1 - f0 - 0.1 * 1.0) / 1.0, 1e-14);
    assert_close(a[1], (f2 - f1 + 0.2) / 2.0, 1e-14);
    assert_close(a[2], (f3 - f2 - 0.3 * 0.5) / 0.5, 1e-14);
    double pe = energy(3, 40, 0.1) + energy(5, -2, -0.3) + energy(7, 0, 0.5) +
                energy(11, 25, u - 0.3);
    assert_close(model_potential(m, x, u), pe, 1e-15);
    /* The first-order matrix is the chain linearised at rest: the same as with k3 = 0. */
    double A1[36], A2[36], work[9];
    assert_int_equal(model_first_order(m, A1, work), 0);
    memset(m->k3, 0, 4 * sizeof *m->k3);
    model_set_cubic(m);
    assert_false(m->cubic);
    assert_int_equal(model_first_order(m, A2, work), 0);
    for (int i = 0; i < 36; i++)
        assert_close(A1[i], A2[i], 0.0);
    model_free(m);
}

/* The same chain's equations, written again here for GSL: y = (x, v). */
struct ref {
    const double *mm, *k, *k3, *c;
    double amp, w;
};

static int ref_rhs(double t, const double y[], double dy[], void *p)
{
    const struct ref *r = p;
    double u = r->amp * sin(r->w * t);
    double s[4] = {y[0], y[1] - y[0], y[2] - y[1], u - y[2]}, f[4];
    for (int j = 0; j < 4; j++)
        f[j] = force(r->k[j], r->k3[j], s[j]);
    for (int i = 0; i < 3; i++) {
        dy[i] = y[3 + i];
        dy[3 + i] = (f[i + 1] - f[i] - r->c[i] * y[3 + i]) / r->mm[i];
    }
    return GSL_SUCCESS;
}

/* rk4 at dt 1e-3 against rk8pd at 1e-12 over 10 s of a driven chain with hardening and
 * softening springs: the fourth-order error of the step, a few 1e-9 m. */
static void against_gsl(void **state)
{
    (void)state;
    struct model *m = three();
    m->motor = (struct motor){WAVE_SINE, 0.3, 0.8, 0.0};
    struct sim *s = sim_new(m, 1e-3);
    sim_set_integrator(s, INTEGRATOR_RK4);
    double x0[3] = {0.2, -0.1, 0.05};
    sim_reset(s, x0, NULL);
    struct ref r = {m->m, m->k, m->k3, m->c, 0.3, 2.0 * M_PI * 0.8};
    gsl_odeiv2_system sys = {ref_rhs, NULL, 6, &r};
    gsl_odeiv2_driver *d = gsl_odeiv2_driver_alloc_y_new(&sys, gsl_odeiv2_step_rk8pd, 1e-4,
                                                         1e-13, 1e-13);
    double y[6] = {0.2, -0.1, 0.05, 0, 0, 0}, t = 0.0, worst = 0.0;
    for (int k = 1; k <= 10000; k++) {
        sim_step(s);
        if (k % 100 == 0) {
            assert_int_equal(gsl_odeiv2_driver_apply(d, &t, k * 1e-3, y), GSL_SUCCESS);
            for (int i = 0; i < 3; i++)
                worst = fmax(worst, fabs(sim_x(s)[i] - y[i]));
        }
    }
    printf("  rk4 dt 1e-3 against rk8pd over 10 s: %.3g m\n", worst);
    assert_true(worst < 1e-9);
    assert_true(worst > 0.0); /* two different solvers */
    gsl_odeiv2_driver_free(d);
    sim_free(s);
    model_free(m);
}

/* The energy balance (kinetic + quartic potential + dissipated - motor's work) of a driven
 * chain with cubic springs stays within 1e-6 of the peak energy: rk4, dt 0.001, 60 s. */
static void energy_balance(void **state)
{
    (void)state;
    for (int w = 0; w < 2; w++) {
        struct model *m = three();
        m->motor = (struct motor){w ? WAVE_SQUARE : WAVE_SINE, 0.4, 0.9, 0.0};
        struct sim *s = sim_new(m, 1e-3);
        sim_set_integrator(s, INTEGRATOR_RK4);
        double x0[3] = {0.3, -0.2, 0.1};
        sim_reset(s, x0, NULL);
        struct energy e;
        sim_energy(s, &e);
        double start = e.balance, drift = 0.0, peak = 0.0, quartic = 0.0;
        for (int k = 0; k < 60000; k++) {
            sim_step(s);
            sim_energy(s, &e);
            drift = fmax(drift, fabs(e.balance - start));
            peak = fmax(peak, e.kinetic + e.potential);
            const double *x = sim_x(s);
            quartic = fmax(quartic, 0.25 * 40.0 * pow(x[0], 4));
        }
        printf("  %s drive, 60 s: balance drift %.3g of peak %.4g J (quartic energy up to "
               "%.3g J)\n", w ? "square" : "sine", drift / peak, peak, quartic);
        assert_true(drift <= 1e-6 * peak);
        assert_true(quartic > 1e-3 * peak); /* the quartic term matters to the books */
        sim_free(s);
        model_free(m);
    }
}

/* The exact integrator is refused for a chain with a cubic spring, with the reason. */
static void exact_refused(void **state)
{
    (void)state;
    struct config c;
    char err[400];
    int bad;
    config_init(&c);
    assert_int_equal(config_set(&c, CFG_SPRING_CUBIC, "0,5,0", err, sizeof err), 0);
    assert_int_equal(config_set(&c, CFG_INTEGRATOR, "exact", err, sizeof err), 0);
    assert_null(config_model(&c, &bad, err, sizeof err));
    assert_int_equal(bad, CFG_INTEGRATOR);
    assert_non_null(strstr(err, "nonlinear"));
    assert_non_null(strstr(err, "rk4"));
    assert_int_equal(config_set(&c, CFG_SPRING_CUBIC, "0", err, sizeof err), 0);
    struct model *m = config_model(&c, &bad, err, sizeof err);
    assert_non_null(m);
    assert_false(m->cubic);
    model_free(m);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(equation_of_motion),
        cmocka_unit_test(against_gsl),
        cmocka_unit_test(energy_balance),
        cmocka_unit_test(exact_refused),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
