/* test_force.c: the chain's own dampers (a damper beside each spring), the force input on
 * a mass and springs of k = 0, in every integrator: against closed forms (a mass on a
 * spring and damper to the wall; two masses joined by a spring and damper, nothing else,
 * whose centre drifts and whose stretch rings down with the reduced mass), against an
 * independent complex solve of (K - w^2 M + i w C) X = G (LAPACK's dense zgesv) for the
 * steady state on 20 random chains, and the energy books balancing. */
#include "testutil.h"

#include <complex.h>
#include <stdlib.h>
#include <string.h>

#include <lapacke.h>

#include "core/model.h"
#include "core/sim.h"

/* x'' + 2 s x' + w^2 x = 0 from (x0, 0), underdamped. */
static double ring(double s, double w, double x0, double t)
{
    double wd = sqrt(w * w - s * s);
    return x0 * exp(-s * t) * (cos(wd * t) + s / wd * sin(wd * t));
}

static struct sim *run_sim(const struct model *m, enum integrator integ, double dt,
                           const double *x0, const double *v0)
{
    struct sim *s = sim_new(m, dt);
    assert_non_null(s);
    sim_set_integrator(s, integ);
    sim_reset(s, x0, v0);
    return s;
}

/* A mass whose only damper is the one beside its wall spring: the damper acts on the
 * stretch rate v - 0, as a damper to the ground would: m x'' = -k x - cs x'. */
static void test_wall_damper_closed_form(void **state)
{
    (void)state;
    for (int integ = 0; integ < INTEGRATOR_COUNT; integ++) {
        struct model *m = model_new(1);
        m->m[0] = 2.0, m->k[0] = 8.0, m->c[0] = 0.0, m->cs[0] = 0.6;
        m->boundary = BOUNDARY_FREE, m->collisions = false;
        model_sync(m);
        double x0 = 0.3, dt = integ == INTEGRATOR_RK4 || integ == INTEGRATOR_EXACT ? 1e-3 : 1e-5;
        struct sim *s = run_sim(m, (enum integrator)integ, dt, &x0, NULL);
        double worst = 0.0;
        for (int i = 1; i <= (int)(3.0 / dt + 0.5); i++) {
            assert_int_equal(sim_step(s), SIM_OK);
            worst = fmax(worst, fabs(sim_x(s)[0] - ring(0.15, 2.0, x0, i * dt)));
        }
        double tol = integ == INTEGRATOR_EXACT ? 1e-12 : integ == INTEGRATOR_RK4 ? 1e-12 : 2e-5;
        printf("# %s: wall damper against the closed form: %.2e m\n",
               integrator_name((enum integrator)integ), worst);
        assert_true(worst <= tol);
        sim_free(s);
        model_free(m);
    }
}

/* Two masses joined by a spring and its damper, no wall springs, a free end: momentum is
 * kept (the centre moves uniformly) and the stretch r = x2 - x1 rings as
 * mu r'' + cs r' + k r = 0, mu = m1 m2 / (m1 + m2). */
static void test_free_pair(void **state)
{
    (void)state;
    for (int integ = 0; integ < INTEGRATOR_COUNT; integ++) {
        struct model *m = model_new(2);
        double m1 = 1.0, m2 = 3.0, k = 12.0, cs = 0.45;
        m->m[0] = m1, m->m[1] = m2, m->c[0] = m->c[1] = 0.0;
        m->k[0] = 0.0, m->k[1] = k, m->k[2] = 0.0, m->cs[1] = cs;
        m->boundary = BOUNDARY_FREE, m->collisions = false;
        model_sync(m);
        double x0[2] = {-0.1, 0.1}, v0[2] = {0.2, 0.2}, mu = m1 * m2 / (m1 + m2);
        bool high = integ == INTEGRATOR_RK4 || integ == INTEGRATOR_EXACT;
        double dt = high ? 1e-3 : 1e-5;
        struct sim *s = run_sim(m, (enum integrator)integ, dt, x0, v0);
        double worst = 0.0, drift = 0.0;
        for (int i = 1; i <= (int)(2.0 / dt + 0.5); i++) {
            assert_int_equal(sim_step(s), SIM_OK);
            const double *x = sim_x(s), *v = sim_v(s);
            double t = i * dt, r = x[1] - x[0];
            double centre = (m1 * x[0] + m2 * x[1]) / (m1 + m2);
            worst = fmax(worst, fabs(r - ring(0.5 * cs / mu, sqrt(k / mu), 0.2, t)));
            drift = fmax(drift, fabs(m1 * v[0] + m2 * v[1] - 0.8) + fabs(centre - 0.05 - 0.2 * t));
        }
        printf("# %s: free pair's stretch %.2e m, momentum and centre %.2e\n",
               integrator_name((enum integrator)integ), worst, drift);
        assert_true(worst <= (high ? 1e-11 : 2e-5));
        assert_true(drift <= 1e-11);
        sim_free(s);
        model_free(m);
    }
}

static double uniform(unsigned *seed, double lo, double hi)
{
    *seed = *seed * 1103515245u + 12345u;
    return lo + (hi - lo) * (double)((*seed >> 8) & 0xffffff) / 16777216.0;
}

/* The steady state X of M x'' + C x' + K x = Im(G e^{i w t}) by LAPACK's dense complex
 * solve: G = F e_K + (k_N + i w cs_N) A e_N (the force and the motor end's spring and
 * damper). Written here from the chain's parameters, not from the program's code. */
static void steady(const struct model *m, double w, double complex *x)
{
    int n = m->n;
    double complex *h = calloc((size_t)n * (size_t)n, sizeof *h);
    lapack_int *piv = malloc((size_t)n * sizeof *piv);
    for (int i = 0; i < n; i++) {
        bool right = i < n - 1 || m->boundary != BOUNDARY_FREE;
        double kd = m->k[i] + (right ? m->k[i + 1] : 0.0);
        double cd = m->c[i] + m->cs[i] + (right ? m->cs[i + 1] : 0.0);
        h[i + (size_t)i * n] = kd - w * w * m->m[i] + I * w * cd;
        if (i + 1 < n)
            h[i + (size_t)(i + 1) * n] = h[i + 1 + (size_t)i * n] =
                -m->k[i + 1] - I * w * m->cs[i + 1];
        x[i] = 0.0;
    }
    x[m->force_on] += m->force;
    if (m->boundary == BOUNDARY_MOTOR)
        x[n - 1] += (m->k[n] + I * w * m->cs[n]) * m->motor.amplitude;
    assert_int_equal(LAPACKE_zgesv(LAPACK_COL_MAJOR, n, 1, h, n, piv, x, n), 0);
    free(h);
    free(piv);
}

/* 20 random chains (springs of k = 0 among them, dampers beside springs, a force on a
 * random mass, any right end), started on the steady state the complex solve gives: the
 * exact integrator stays on it to 1e-9 of its size over 8 s, rk4 at dt 1e-3 to 1e-7. */
static void test_steady_state_against_complex_solve(void **state)
{
    (void)state;
    unsigned seed = 29;
    for (int trial = 0; trial < 20; trial++) {
        int n = 1 + trial % 6;
        struct model *m = model_new(n);
        for (int i = 0; i < n; i++) {
            m->m[i] = uniform(&seed, 0.3, 3.0);
            m->c[i] = uniform(&seed, 0.0, 1.0) < 0.5 ? 0.0 : uniform(&seed, 0.0, 0.5);
        }
        for (int j = 0; j <= n; j++) {
            m->k[j] = uniform(&seed, 0.0, 1.0) < 0.2 ? 0.0 : uniform(&seed, 1.0, 30.0);
            m->cs[j] = uniform(&seed, 0.0, 1.0) < 0.3 ? 0.0 : uniform(&seed, 0.05, 0.8);
        }
        m->k[0] = m->k[0] == 0.0 && m->c[0] == 0.0 && m->cs[0] == 0.0 ? 5.0 : m->k[0];
        m->boundary = (enum boundary)(trial % 3);
        m->motor = (struct motor){WAVE_SINE, uniform(&seed, 0.0, 0.5), uniform(&seed, 0.2, 2.0), 0.0};
        m->force = uniform(&seed, 0.5, 5.0);
        m->force_on = (int)uniform(&seed, 0.0, n - 0.001);
        m->collisions = false;
        model_sync(m);
        double w = 2.0 * M_PI * m->motor.frequency;
        double complex xs[6];
        steady(m, w, xs);
        double x0[6], v0[6], size = 0.0;
        for (int i = 0; i < n; i++) {
            x0[i] = cimag(xs[i]);
            v0[i] = cimag(I * w * xs[i]);
            size = fmax(size, cabs(xs[i]));
        }
        for (int pass = 0; pass < 2; pass++) {
            enum integrator integ = pass ? INTEGRATOR_RK4 : INTEGRATOR_EXACT;
            double dt = pass ? 1e-3 : 0.01;
            struct sim *s = run_sim(m, integ, dt, x0, v0);
            double worst = 0.0;
            for (int k = 1; k <= (int)(8.0 / dt + 0.5); k++) {
                assert_int_equal(sim_step(s), SIM_OK);
                double complex e = cexp(I * w * k * dt);
                for (int i = 0; i < n; i++)
                    worst = fmax(worst, fabs(sim_x(s)[i] - cimag(xs[i] * e)));
            }
            if (!(worst <= (pass ? 1e-7 : 1e-9) * size))
                fail_msg("chain %d (%d masses, %s end), %s: %.3e of %.3e", trial, n,
                         model_boundary_name(m->boundary), integrator_name(integ), worst, size);
            sim_free(s);
        }
        model_free(m);
    }
}

/* The books with spring dampers, a missing spring, a force and the motor: kinetic +
 * potential + dissipated - motor_work - force_work stays put. rk4 at dt 1e-3 and exact to
 * 1e-6 of the peak energy over 20 s, each waveform (no damper on the motor's spring for
 * the jumping ones); euler, semi-implicit and verlet drift at their order (halving dt
 * divides the drift by about 2, 2 and 4). */
static double balance_drift(enum integrator integ, enum wave wave, double dt)
{
    struct model *m = model_new(3);
    double k[4] = {10, 0, 5, 10}, cs[4] = {0.3, 0.2, 0.5, 0.2};
    for (int j = 0; j < 4; j++)
        m->k[j] = k[j], m->cs[j] = cs[j];
    if (motor_has_jumps(wave))
        m->cs[3] = 0.0;
    m->c[0] = 0.05, m->c[1] = 0.0, m->c[2] = 0.1;
    m->m[1] = 2.0;
    m->motor = (struct motor){wave, 0.2, 0.7, 0.0};
    m->force = 2.0, m->force_on = 1, m->collisions = false;
    model_sync(m);
    double x0[3] = {0.1, -0.2, 0.0};
    struct sim *s = run_sim(m, integ, dt, x0, NULL);
    struct energy e;
    sim_energy(s, &e);
    double b0 = e.balance, peak = 0.0, drift = 0.0;
    for (int i = 0; i < (int)(20.0 / dt + 0.5); i++) {
        assert_int_equal(sim_step(s), SIM_OK);
        sim_energy(s, &e);
        peak = fmax(peak, e.kinetic + e.potential);
        drift = fmax(drift, fabs(e.balance - b0));
    }
    assert_true(e.force_work != 0.0 && e.dissipated > 0.0);
    sim_free(s);
    model_free(m);
    return drift / peak;
}

static void test_energy_balance(void **state)
{
    (void)state;
    for (int w = 0; w < WAVE_COUNT; w++) {
        double rk4 = balance_drift(INTEGRATOR_RK4, (enum wave)w, 1e-3);
        double ex = balance_drift(INTEGRATOR_EXACT, (enum wave)w, 0.01);
        printf("# %s: balance drift / peak: rk4 %.2e, exact %.2e\n",
               motor_wave_name((enum wave)w), rk4, ex);
        assert_true(rk4 <= 1e-6);
        assert_true(ex <= 1e-6);
    }
    const enum integrator low[3] = {INTEGRATOR_EULER, INTEGRATOR_SEMI_IMPLICIT,
                                    INTEGRATOR_VERLET};
    const double ratio[3] = {1.8, 1.8, 3.5};
    for (int i = 0; i < 3; i++) {
        double a = balance_drift(low[i], WAVE_SINE, 2e-4), b = balance_drift(low[i], WAVE_SINE, 1e-4);
        printf("# %s: drift %.2e at dt 2e-4, %.2e at 1e-4\n", integrator_name(low[i]), a, b);
        assert_true(a / b >= ratio[i]);
    }
}

/* A force that presses a mass on the left wall rests it there, alone or with a neighbour
 * swinging beside it: while it presses harder than the springs pull (16 to 20 s), v = 0
 * and x stays on the limit, and the contacts are as many at every dt (the rest test once left the force out: the mass chattered,
 * 25164, 51153 and 96974 contacts at dt 0.01, 0.005, 0.0025). A wall does no work. */
static void test_force_presses_to_rest(void **state)
{
    (void)state;
    for (int pair = 0; pair < 2; pair++) {
        struct model *m = model_new(1 + pair);
        assert_non_null(m);
        for (int j = 0; j <= m->n; j++)
            m->k[j] = pair ? 1.0 : 2.0;
        for (int i = 0; i < m->n; i++)
            m->c[i] = 1.0;
        m->boundary = pair ? BOUNDARY_WALL : BOUNDARY_FREE;
        m->motor = (struct motor){WAVE_SQUARE, 0.0, 0.05, 0.0};
        m->force = pair ? 40.0 : 30.0;
        int counts[3];
        for (int d = 0; d < 3; d++) {
            double dt = 0.01 / (1 << d);
            struct sim *s = run_sim(m, INTEGRATOR_RK4, dt, NULL, NULL);
            struct energy e;
            sim_energy(s, &e);
            double b0 = e.balance, peak = 0.0, worst = 0.0, held_x = NAN;
            counts[d] = 0;
            int steps = (int)lround(20.0 / dt);
            for (int j = 1; j <= steps; j++) {
                assert_int_equal(sim_step(s), SIM_OK);
                counts[d] += sim_last_contacts(s);
                sim_energy(s, &e);
                peak = fmax(peak, e.kinetic + e.potential);
                worst = fmax(worst, fabs(e.balance - b0));
                double t = j * dt;
                /* From 16 s to the force's turn at 20 s it holds mass 1 on the wall. */
                if (t >= 16.0 && t <= 19.9) {
                    assert_true(sim_v(s)[0] == 0.0);
                    if (isnan(held_x))
                        held_x = sim_x(s)[0];
                    assert_true(sim_x(s)[0] == held_x);
                }
            }
            printf("# %s, dt %g: %d contacts, balance within %.1e of the peak, motor work "
                   "%.1e J\n", pair ? "mass 1 of two on the left wall" : "a mass on the left wall", dt,
                   counts[d], worst / peak, e.motor_work);
            assert_true(worst <= 1e-6 * peak);
            assert_true(fabs(e.motor_work) <= 1e-9);
            sim_free(s);
        }
        assert_int_equal(counts[1], counts[0]);
        assert_int_equal(counts[2], counts[0]);
        assert_true(counts[0] <= 300);
        model_free(m);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_wall_damper_closed_form),
        cmocka_unit_test(test_free_pair),
        cmocka_unit_test(test_steady_state_against_complex_solve),
        cmocka_unit_test(test_energy_balance),
        cmocka_unit_test(test_force_presses_to_rest),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
