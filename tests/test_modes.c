/* test_modes.c: natural frequencies and shapes against the closed forms of the uniform
 * chain, the eigen-equation itself on a non-uniform chain, the steady state against
 * the 1-DOF formula and against a long simulation. The limits of dt are in
 * test_limits.c. */
#include "testutil.h"

#include <stdlib.h>

#include "core/modes.h"
#include "core/sim.h"

static struct model *uniform(int n, double k, double m, enum boundary b)
{
    struct model *md = model_new(n);
    for (int i = 0; i < n; i++)
        md->m[i] = m;
    for (int j = 0; j <= n; j++)
        md->k[j] = k;
    md->boundary = b;
    return md;
}

/* Fixed-fixed (wall and motor ends): w_j = 2 sqrt(k/m) sin(j pi / (2(N+1))). */
static void uniform_fixed_closed_form(void **state)
{
    (void)state;
    const int sizes[] = {1, 2, 3, 5, 10, 100};
    for (size_t s = 0; s < sizeof sizes / sizeof *sizes; s++) {
        for (int b = BOUNDARY_MOTOR; b <= BOUNDARY_WALL; b++) {
            int n = sizes[s];
            struct model *md = uniform(n, 10.0, 1.0, (enum boundary)b);
            double *f = malloc((size_t)n * sizeof *f);
            assert_int_equal(modes_compute(md, f, NULL), 0);
            for (int j = 1; j <= n; j++) {
                double w = 2.0 * sqrt(10.0) * sin(j * M_PI / (2.0 * (n + 1)));
                double want = w / (2.0 * M_PI);
                assert_close(f[j - 1], want, 1e-9 * want);
            }
            free(f);
            model_free(md);
        }
    }
}

/* Fixed-free: w_j = 2 sqrt(k/m) sin((2j-1) pi / (2(2N+1))). */
static void uniform_free_closed_form(void **state)
{
    (void)state;
    for (int n = 1; n <= 12; n++) {
        struct model *md = uniform(n, 7.0, 2.0, BOUNDARY_FREE);
        double f[12];
        assert_int_equal(modes_compute(md, f, NULL), 0);
        for (int j = 1; j <= n; j++) {
            double want = 2.0 * sqrt(3.5) * sin((2 * j - 1) * M_PI / (2.0 * (2 * n + 1))) /
                          (2.0 * M_PI);
            assert_close(f[j - 1], want, 1e-9 * want);
        }
        model_free(md);
    }
}

/* Uniform fixed-fixed shapes: phi_i = sin(i j pi / (N+1)), scaled to max 1. */
static void uniform_shapes(void **state)
{
    (void)state;
    int n = 4;
    struct model *md = uniform(n, 10.0, 1.0, BOUNDARY_WALL);
    double f[4], sh[16];
    assert_int_equal(modes_compute(md, f, sh), 0);
    for (int j = 1; j <= n; j++) {
        double want[4], top = 0.0;
        int big = -1;
        for (int i = 1; i <= n; i++) {
            want[i - 1] = sin(i * j * M_PI / (n + 1));
            if (fabs(want[i - 1]) > top + 1e-12)
                top = fabs(want[i - 1]), big = i - 1;
        }
        double scale = 1.0 / want[big];
        for (int i = 0; i < n; i++)
            assert_close(sh[(j - 1) * n + i], want[i] * scale, 1e-9);
    }
    model_free(md);
}

/* Non-uniform chain: K phi = w^2 M phi, phi_i' M phi_j = 0, and the scaling rule. */
static void eigen_equation_holds(void **state)
{
    (void)state;
    int n = 5;
    struct model *md = model_new(n);
    const double m[5] = {1.0, 2.5, 0.7, 1.2, 3.0}, k[6] = {10, 3, 25, 7, 12, 4};
    for (int i = 0; i < n; i++)
        md->m[i] = m[i];
    for (int j = 0; j <= n; j++)
        md->k[j] = k[j];
    for (int b = 0; b < BOUNDARY_COUNT; b++) {
        md->boundary = (enum boundary)b;
        double f[5], sh[25];
        assert_int_equal(modes_compute(md, f, sh), 0);
        for (int j = 0; j < n; j++) {
            const double *p = sh + j * n;
            double w2 = pow(2 * M_PI * f[j], 2), top = 0.0;
            for (int i = 0; i < n; i++) {
                double kp = (k[i] + (i < n - 1 || b != BOUNDARY_FREE ? k[i + 1] : 0)) * p[i];
                if (i > 0)
                    kp -= k[i] * p[i - 1];
                if (i < n - 1)
                    kp -= k[i + 1] * p[i + 1];
                assert_close(kp, w2 * m[i] * p[i], 1e-9 * w2 * m[i]);
                top = fmax(top, fabs(p[i]));
            }
            assert_close(top, 1.0, 1e-12);
            if (j > 0)
                assert_true(f[j] > f[j - 1]);
            for (int l = 0; l < j; l++) {
                double dot = 0.0;
                for (int i = 0; i < n; i++)
                    dot += p[i] * m[i] * sh[l * n + i];
                assert_close(dot, 0.0, 1e-9);
            }
        }
    }
    model_free(md);
}

/* One mass between springs k0, k1 with the motor: X = k1 A / |2k - m w^2 + i c w|. */
static void one_dof_response(void **state)
{
    (void)state;
    struct model *md = model_new(1);
    md->m[0] = 1.3, md->k[0] = 9.0, md->k[1] = 11.0, md->c[0] = 0.25;
    md->motor.amplitude = 0.4;
    for (double f = 0.05; f < 3.0; f += 0.0137) {
        double w = 2 * M_PI * f, amp;
        assert_int_equal(modes_response(md, f, &amp), 0);
        double want = 11.0 * 0.4 / hypot(20.0 - 1.3 * w * w, 0.25 * w);
        assert_close(amp, want, 1e-9 * want);
    }
    md->boundary = BOUNDARY_WALL;
    double amp = 1.0;
    assert_int_equal(modes_response(md, 0.5, &amp), 0);
    assert_close(amp, 0.0, 0.0);
    model_free(md);
}

/* The steady state a long simulation settles into has the predicted amplitudes. */
static void response_matches_simulation(void **state)
{
    (void)state;
    struct model *md = model_new(3);
    md->m[1] = 1.5, md->k[2] = 14.0, md->c[0] = 0.6, md->c[1] = 0.4, md->c[2] = 0.5;
    md->motor.amplitude = 0.2, md->motor.frequency = 0.6;
    md->collisions = false;
    double amp[3], peak[3] = {0, 0, 0};
    assert_int_equal(modes_response(md, 0.6, amp), 0);
    struct sim *s = sim_new(md, 0.002);
    for (int n = 0; n < 200000; n++) { /* 400 s: transients decay as exp(-c t / 2m) */
        sim_step(s);
        if (n >= 190000)
            for (int i = 0; i < 3; i++)
                peak[i] = fmax(peak[i], fabs(sim_x(s)[i]));
    }
    /* Peaks of a sampled sine fall short by at most 1 - cos(w dt / 2). */
    for (int i = 0; i < 3; i++)
        assert_close(peak[i], amp[i], 1e-5 * amp[i] + amp[i] * (1 - cos(2 * M_PI * 0.6 * 0.001)));
    sim_free(s);
    model_free(md);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(uniform_fixed_closed_form),
        cmocka_unit_test(uniform_free_closed_form),
        cmocka_unit_test(uniform_shapes),
        cmocka_unit_test(eigen_equation_holds),
        cmocka_unit_test(one_dof_response),
        cmocka_unit_test(response_matches_simulation),
    };
    return cmocka_run_group_tests_name("modes", tests, NULL, NULL);
}
