/* test_model.c: the equation of motion written out by hand for a 3-mass chain with
 * each right end, energies, geometry, and the parameter copy. */
#include "testutil.h"

#include <string.h>

#include "core/model.h"

static struct model *three(enum boundary b)
{
    struct model *m = model_new(3);
    const double mm[3] = {1.0, 2.0, 0.5}, k[4] = {3.0, 5.0, 7.0, 11.0}, c[3] = {0.1, 0.2, 0.3};
    for (int i = 0; i < 3; i++)
        m->m[i] = mm[i], m->c[i] = c[i];
    for (int j = 0; j < 4; j++)
        m->k[j] = k[j];
    m->boundary = b;
    return m;
}

static void equation_of_motion(void **state)
{
    (void)state;
    const double x[3] = {0.1, -0.2, 0.3}, v[3] = {1.0, -1.0, 0.5}, u = 0.7;
    double a[3];
    for (int b = 0; b < BOUNDARY_COUNT; b++) {
        struct model *m = three((enum boundary)b);
        model_accel(m, x, v, u, a);
        /* m_i a_i = -k_i (x_i - x_{i-1}) - k_{i+1} (x_i - x_{i+1}) - c_i v_i */
        double right = b == BOUNDARY_FREE ? 0.0 : -11.0 * (0.3 - u);
        assert_close(a[0], (-3.0 * 0.1 - 5.0 * (0.1 + 0.2) - 0.1 * 1.0) / 1.0, 1e-15);
        assert_close(a[1], (-5.0 * (-0.2 - 0.1) - 7.0 * (-0.2 - 0.3) + 0.2) / 2.0, 1e-15);
        assert_close(a[2], (-7.0 * (0.3 + 0.2) + right - 0.3 * 0.5) / 0.5, 1e-14);
        double pe = 0.5 * (3.0 * 0.01 + 5.0 * 0.09 + 7.0 * 0.25) +
                    (b == BOUNDARY_FREE ? 0.0 : 0.5 * 11.0 * 0.16);
        assert_close(model_potential(m, x, u), pe, 1e-15);
        assert_close(model_kinetic(m, v), 0.5 * (1.0 + 2.0 + 0.125), 1e-15);
        model_free(m);
    }
}

/* model_accel_span gives each mass of its span the same bits as model_rates, on random
 * chains of every kind (cubic springs, spring dampers, each end, zeros whose sign a stray
 * + 0.0 would change), and leaves the values outside it alone. */
static void span_is_rates(void **state)
{
    (void)state;
    uint64_t seed = 0x5eedf00dULL;
    for (int trial = 0; trial < 400; trial++) {
        int n = 1 + (int)test_uniform(&seed, 0.0, 12.0);
        struct model *m = model_new(n);
        m->boundary = (enum boundary)(trial % BOUNDARY_COUNT);
        bool cubic = trial / 3 % 3 == 1, damped = trial % 4 >= 2; /* apart from the end */
        for (int j = 0; j <= n; j++) {
            m->k[j] = test_uniform(&seed, 0.0, 60.0);
            m->k3[j] = cubic ? test_uniform(&seed, -20.0, 200.0) : 0.0;
            m->cs[j] = damped ? test_uniform(&seed, 0.0, 2.0) : 0.0;
        }
        model_sync(m);
        double x[12], v[12], full[12], span[12];
        for (int i = 0; i < n; i++) {
            m->m[i] = test_uniform(&seed, 0.1, 3.0);
            m->c[i] = trial % 5 == 0 ? 0.0 : test_uniform(&seed, 0.0, 1.5);
            x[i] = trial % 7 == 0 ? (i % 2 ? -0.0 : 0.0) : test_uniform(&seed, -0.5, 0.5);
            v[i] = trial % 7 == 0 ? (i % 3 ? -0.0 : 0.0) : test_uniform(&seed, -3.0, 3.0);
        }
        double u = trial % 7 == 0 ? -0.0 : test_uniform(&seed, -1.0, 1.0);
        double du = test_uniform(&seed, -2.0, 2.0);
        model_rates(m, NULL, x, v, u, du, full, NULL, NULL);
        int lo = (int)test_uniform(&seed, 0.0, n), hi = lo + (int)test_uniform(&seed, 0.0, n - lo);
        for (int i = 0; i < n; i++)
            span[i] = 12345.0;
        model_accel_span(m, x, v, u, du, lo, hi, span);
        for (int i = 0; i < n; i++) {
            double want = i >= lo && i <= hi ? full[i] : 12345.0;
            if (memcmp(&span[i], &want, sizeof want) != 0)
                fail_msg("trial %d, n %d, span %d..%d: a[%d] = %.17g, model_rates %.17g", trial,
                         n, lo, hi, i, span[i], want);
        }
        model_free(m);
    }
}

static void geometry(void **state)
{
    (void)state;
    struct model *m = model_new(4);
    for (int i = 0; i < 4; i++)
        assert_close(model_equilibrium(m, i), (i + 1) * 2.0, 1e-15);
    assert_close(model_block_width(m), 0.4, 0.0);
    model_free(m);
    m = model_new(24); /* spacing 0.4: half of it, 0.2, is smaller than 0.4 */
    assert_close(model_block_width(m), 0.2, 1e-15);
    model_free(m);
    assert_null(model_new(0));
    assert_null(model_new(1001));
}

static void defaults_and_copy(void **state)
{
    (void)state;
    struct model *a = model_new(2), *b = three(BOUNDARY_FREE), *c = model_new(3);
    assert_close(a->m[1], 1.0, 0.0);
    assert_close(a->k[2], 10.0, 0.0);
    assert_close(a->c[0], 0.1, 0.0);
    assert_int_equal(a->boundary, BOUNDARY_MOTOR);
    assert_int_equal(a->motor.wave, WAVE_SINE);
    assert_close(a->motor.amplitude, 0.1, 0.0);
    assert_close(a->motor.frequency, 1.0, 0.0);
    model_copy(c, b);
    assert_memory_equal(c->k, b->k, 4 * sizeof(double));
    assert_int_equal(c->boundary, BOUNDARY_FREE);
    assert_close(model_end_position(c, 0.25), 0.0, 0.0);
    /* A sin(2 pi f t) a quarter period in: A */
    assert_close(model_end_position(a, 0.25), 0.1, 1e-16);
    assert_int_equal(model_boundary_parse("wall"), BOUNDARY_WALL);
    assert_int_equal(model_boundary_parse("open"), -1);
    model_free(a);
    model_free(b);
    model_free(c);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(equation_of_motion),
        cmocka_unit_test(span_is_rates),
        cmocka_unit_test(geometry),
        cmocka_unit_test(defaults_and_copy),
    };
    return cmocka_run_group_tests_name("model", tests, NULL, NULL);
}
