/* test_sweep.c: the stepped-sine experiment's bookkeeping, and that on a linear chain
 * without collisions its measured peaks land on the steady-state theory. */
#include "testutil.h"

#include <stdlib.h>

#include "core/modes.h"
#include "core/sim.h"
#include "core/sweep.h"

static void bookkeeping(void **state)
{
    (void)state;
    struct sweep *s = sweep_new(2, 3);
    assert_int_equal(sweep_update(s, 0.0, (double[]){0, 0}, 0.0), SWEEP_IDLE);
    sweep_start(s, 1.0, 2.0, 5.0, 10.0);
    assert_close(sweep_frequency(s), 1.0, 0.0);
    assert_close(s->freq[1], 1.5, 1e-15);
    /* Settling: max(5 s, 8 periods = 8 s) at 1 Hz; nothing recorded yet. */
    assert_int_equal(sweep_update(s, 17.9, (double[]){3, 3}, 0.0), SWEEP_SAME);
    assert_true(isnan(s->peak[0]));
    /* Measuring: 4 periods = 4 s; the largest |x| is kept. */
    assert_int_equal(sweep_update(s, 18.5, (double[]){0.2, -0.7}, 0.25), SWEEP_SAME);
    assert_int_equal(sweep_update(s, 20.0, (double[]){-0.4, 0.1}, 0.5), SWEEP_SAME);
    assert_int_equal(sweep_update(s, 22.0, (double[]){0.1, 0.1}, 0.0), SWEEP_RETUNE);
    assert_close(s->peak[0], 0.4, 0.0);
    assert_close(s->peak[1], 0.7, 0.0);
    assert_int_equal(sweep_measured(s), 1);
    assert_close(sweep_frequency(s), 1.5, 1e-15);
    sweep_stop(s);
    assert_int_equal(sweep_update(s, 99.0, (double[]){0, 0}, 0.0), SWEEP_IDLE);
    assert_close(s->peak[0], 0.4, 0.0); /* kept */
    sweep_free(s);
}

/* Runs sweep sw on chain md in sm, as the app does: the drive at the sweep's frequency,
 * retuned phase-continuous when it says so, for at most max steps; the last event. */
static enum sweep_event run_sweep(struct model *md, struct sim *sm, struct sweep *sw, int max)
{
    md->motor.frequency = sweep_frequency(sw);
    sim_set_model(sm, md);
    enum sweep_event ev = SWEEP_SAME;
    for (int n = 0; n < max && ev != SWEEP_DONE; n++) {
        sim_step(sm);
        ev = sweep_update(sw, sim_time(sm), sim_x(sm),
                          md->motor.frequency * sim_time(sm) + md->motor.phase);
        if (ev == SWEEP_RETUNE) {
            motor_retune(&md->motor, sweep_frequency(sw), sim_time(sm));
            sim_set_model(sm, md);
        }
    }
    return ev;
}

/* A 2-mass chain with c = 1 (transients die within a few seconds): the sweep's peaks
 * are the theory's steady-state amplitudes. */
static void matches_theory(void **state)
{
    (void)state;
    struct model *md = model_new(2);
    md->c[0] = md->c[1] = 1.0;
    md->motor.amplitude = 0.05;
    md->collisions = false;
    struct sim *sm = sim_new(md, 0.005);
    struct sweep *sw = sweep_new(2, 5);
    sweep_start(sw, 0.3, 1.1, 12.0, 0.0);
    assert_int_equal(run_sweep(md, sm, sw, 400000), SWEEP_DONE);
    assert_int_equal(sweep_measured(sw), 5);
    for (int p = 0; p < 5; p++) {
        double amp[2];
        modes_response(md, sw->freq[p], amp);
        for (int i = 0; i < 2; i++)
            assert_close(sw->peak[p * 2 + i], amp[i], 0.02 * amp[i]);
    }
    sweep_free(sw);
    sim_free(sm);
    model_free(md);
}

/* The phase the lock-in reads, on signals whose phase is known. */
static void phase_of_signals(void **state)
{
    (void)state;
    /* X sin(theta + phi) over whole periods, many samples: in = X cos phi / 2 * count. */
    const double phis[] = {0.0, -30.0, -90.0, -150.0, 180.0, 45.0};
    for (size_t k = 0; k < sizeof phis / sizeof *phis; k++) {
        double in = 0.0, quad = 0.0;
        for (int s = 0; s < 1000; s++) {
            double th = 2.0 * M_PI * s / 250.0;
            double x = 0.3 * sin(th + phis[k] * M_PI / 180.0);
            in += x * sin(th), quad += x * cos(th);
        }
        assert_close(sweep_phase_deg(in, quad), phis[k], 1e-9);
    }
    /* -180 is given as 180: the range is (-180, 180]. */
    assert_close(sweep_phase_deg(-1.0, -0.0), 180.0, 0.0);
}

/* One mass between a wall spring k1 and the motor's spring k2, damper c: the measured
 * phase of x to the drive is that of k2 / (k1 + k2 - m w^2 + i c w), i.e.
 * atan2(-c w, k1 + k2 - m w^2), below, at and above resonance. */
static void phase_one_mass(void **state)
{
    (void)state;
    struct model *md = model_new(1);
    double m = 1.5, k1 = 8.0, k2 = 12.0, c = 0.8;
    md->m[0] = m, md->k[0] = k1, md->k[1] = k2, md->c[0] = c;
    md->motor.amplitude = 0.05;
    md->collisions = false;
    double fn = sqrt((k1 + k2) / m) / (2.0 * M_PI);
    struct sim *sm = sim_new(md, 0.002);
    struct sweep *sw = sweep_new(1, 3);
    sweep_start(sw, 0.5 * fn, 1.5 * fn, 25.0, 0.0);
    assert_int_equal(run_sweep(md, sm, sw, 2000000), SWEEP_DONE);
    for (int p = 0; p < 3; p++) {
        double w = 2.0 * M_PI * sw->freq[p];
        double want = atan2(-c * w, k1 + k2 - m * w * w) * 180.0 / M_PI;
        assert_close(sw->phase[p], want, 0.3);
    }
    assert_close(sw->phase[1], -90.0, 0.5); /* at resonance, a quarter period behind */
    assert_true(sw->phase[0] > -30.0 && sw->phase[2] < -150.0);
    sweep_free(sw);
    sim_free(sm);
    model_free(md);
}

/* Contacts are counted while a sweep runs, from zero at each start, and not otherwise. */
static void contacts_while_sweeping(void **state)
{
    (void)state;
    struct sweep *s = sweep_new(1, 2);
    sweep_count_contacts(s, 5);
    assert_int_equal(s->contacts, 0);
    sweep_start(s, 1.0, 2.0, 1.0, 0.0);
    sweep_count_contacts(s, 2);
    sweep_count_contacts(s, 0);
    sweep_count_contacts(s, 3);
    assert_int_equal(s->contacts, 5);
    sweep_stop(s);
    sweep_count_contacts(s, 4);
    assert_int_equal(s->contacts, 5); /* kept after it stops, for the view to say */
    sweep_start(s, 1.0, 2.0, 1.0, 10.0);
    assert_int_equal(s->contacts, 0);
    sweep_free(s);
}

static void nearest_mode(void **state)
{
    (void)state;
    const double f[3] = {0.385, 0.712, 0.930};
    assert_int_equal(modes_nearest(f, 3, 0.1), 0);
    assert_int_equal(modes_nearest(f, 3, 0.6), 1);
    assert_int_equal(modes_nearest(f, 3, 0.83), 2);
    assert_int_equal(modes_nearest(f, 3, 9.0), 2);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(bookkeeping),
        cmocka_unit_test(matches_theory),
        cmocka_unit_test(phase_of_signals),
        cmocka_unit_test(phase_one_mass),
        cmocka_unit_test(contacts_while_sweeping),
        cmocka_unit_test(nearest_mode),
    };
    return cmocka_run_group_tests_name("sweep", tests, NULL, NULL);
}
