/* test_sweep.c: the stepped-sine experiment's bookkeeping, and that on a linear chain
 * without collisions its measured peaks land on the steady-state theory. */
#include "testutil.h"

#include <stdlib.h>

#include "core/collision.h"
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
    assert_int_equal(sweep_update(s, 17.9, (double[]){0.1, -0.8}, 0.0), SWEEP_SAME);
    assert_true(isnan(s->peak[0]));
    /* Measuring: 4 periods = 4 s; the largest |x| is kept (no sample is a turn, so none
     * is moved to a parabola's vertex). */
    assert_int_equal(sweep_update(s, 18.5, (double[]){0.2, -0.7}, 0.25), SWEEP_SAME);
    assert_int_equal(sweep_update(s, 20.0, (double[]){0.3, -0.5}, 0.5), SWEEP_SAME);
    assert_int_equal(sweep_update(s, 22.0, (double[]){0.4, -0.1}, 0.0), SWEEP_RETUNE);
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

/* The largest |x| of a period lies between samples: the parabola through the largest
 * sample and its neighbours finds it. A cosine sampled 16 times a period, the samples
 * half a step either side of its crests: the largest sample is cos(pi/16) = 1.9 % short,
 * the parabola's vertex within 6e-4 (its error is fourth order in the step). */
static void peak_between_samples(void **state)
{
    (void)state;
    struct sweep *s = sweep_new(1, 1);
    sweep_start(s, 1.0, 1.0, 0.0, 0.0);
    double h = 1.0 / 16.0, a = 0.3;
    enum sweep_event ev = SWEEP_SAME;
    for (int k = 1; k < 400 && ev == SWEEP_SAME; k++) {
        double t = k * h, x = a * cos(2.0 * M_PI * (t - 0.5 * h));
        ev = sweep_update(s, t, &x, t);
    }
    assert_int_equal(ev, SWEEP_DONE);
    assert_close(s->peak[0], a, 1e-3 * a);
    assert_true(s->peak[0] > a * cos(M_PI / 16.0) + 0.01 * a);
    sweep_free(s);
}

/* The default chain (model_new(2)) swept as the program does: 40 points from half its
 * first mode to 1.5 times its second, dt 0.01, settling `settle` s and, with hold > 0,
 * also until steady for hold s (ten holds at most); run to its end, the simulated time
 * it took in *took, the chain in *md. */
static struct sweep *sweep_default(struct model **md, double settle, double hold, double *took)
{
    *md = model_new(2);
    double f[2];
    assert_int_equal(modes_compute(*md, f, NULL), 0);
    struct sim *sm = sim_new(*md, 0.01);
    struct sweep *sw = sweep_new(2, 40);
    sweep_start(sw, 0.5 * f[0], 1.5 * f[1], settle, 0.0);
    if (hold > 0.0)
        sweep_until_steady(sw, hold, 10.0 * hold);
    assert_int_equal(run_sweep(*md, sm, sw, 2000000), SWEEP_DONE);
    *took = sim_time(sm);
    sim_free(sm);
    return sw;
}

/* The default chain (two masses, 1 kg, 10 N/m, c = 0.1: its modes decay in 20 s) at the
 * default 0.1 m, collisions on, swept as the program does (half the first mode to 1.5
 * times the second, 40 points), each point once its swings are level for 20 s: every
 * point is steady, no contact is made, and each mass's peak lies within 1 % of the
 * largest steady amplitude at that point of the closed-form X = (K - w^2 M + i w C)^-1
 * k_N A e_N, its phase within asin(0.01 top / X_i). */
static void steady_points_match_theory(void **state)
{
    (void)state;
    struct model *md;
    double took;
    /* Every mode's zeta w is c/(2m) (dampers proportional to the masses): 1/(zeta w) = 20 s. */
    struct sweep *sw = sweep_default(&md, 0.0, 2.0 * 1.0 / 0.1, &took);
    assert_close(md->motor.amplitude, 0.1, 0.0);
    printf("  40 points in %.0f s simulated\n", took);
    assert_int_equal(sw->unsteady, 0);
    assert_int_equal(sw->contacts, 0);
    double worst = 0.0;
    for (int p = 0; p < 40; p++) {
        double amp[2], ph[2];
        assert_int_equal(modes_response_phase(md, sw->freq[p], amp, ph), 0);
        double top = fmax(amp[0], amp[1]);
        for (int i = 0; i < 2; i++) {
            double got = sw->peak[p * 2 + i];
            worst = fmax(worst, fabs(got - amp[i]) / top);
            assert_close(got, amp[i], 0.01 * top);
            double dphi = fabs(remainder(sw->phase[p * 2 + i] - ph[i], 360.0));
            if (!(dphi <= asin(fmin(1.0, 0.01 * top / amp[i])) * 180.0 / M_PI))
                fail_msg("point %d (%.4f Hz), mass %d: phase %.2f, theory %.2f", p,
                         sw->freq[p], i + 1, sw->phase[p * 2 + i], ph[i]);
        }
    }
    printf("  largest error %.2f %% of the point's largest amplitude\n", 100.0 * worst);
    sweep_free(sw);
    model_free(md);
}

/* What the steady rule is for: the same sweep with a fixed settling time of 30 s (1.5
 * decay times) misses the theory by more than 1 % at some point. */
static void fixed_settling_misses(void **state)
{
    (void)state;
    struct model *md;
    double took, worst = 0.0;
    struct sweep *sw = sweep_default(&md, 30.0, 0.0, &took);
    for (int p = 0; p < 40; p++) {
        double amp[2];
        assert_int_equal(modes_response(md, sw->freq[p], amp), 0);
        for (int i = 0; i < 2; i++)
            worst = fmax(worst, fabs(sw->peak[p * 2 + i] - amp[i]) / fmax(amp[0], amp[1]));
    }
    printf("  settled a fixed 30 s: largest error %.1f %% (%.0f s simulated)\n", 100.0 * worst,
           took);
    assert_true(worst > 0.01);
    sweep_free(sw);
    model_free(md);
}

/* Undamped, the start-up's free swing never dies and the swings beat forever: every
 * point ends unsteady, after `most` seconds, or twice the least a point takes when that
 * is longer (8 periods, then a hold of 5 s or 4 periods), then one measuring time. */
static void unsteady_points_counted(void **state)
{
    (void)state;
    const double most[2] = {80.0, 1.0};
    /* At 0.4, 0.8 and 1.2 Hz: 8 periods 20, 10 and 6.67 s, holds 10, 5 and 5 s; the
     * measuring times 3 s or 4 periods: 10, 5 and 3.33 s. */
    const double least[3] = {20.0 + 10.0, 10.0 + 5.0, 8.0 / 1.2 + 5.0};
    const double measure = 10.0 + 5.0 + 4.0 / 1.2;
    for (int k = 0; k < 2; k++) {
        struct model *md = model_new(1);
        md->c[0] = 0.0;
        md->collisions = false;
        struct sim *sm = sim_new(md, 0.01);
        struct sweep *sw = sweep_new(1, 3);
        sweep_start(sw, 0.4, 1.2, 0.0, 0.0); /* the mode is at 0.712 Hz */
        sweep_until_steady(sw, 5.0, most[k]);
        assert_int_equal(run_sweep(md, sm, sw, 2000000), SWEEP_DONE);
        assert_int_equal(sw->unsteady, 3);
        double want = measure;
        for (int p = 0; p < 3; p++)
            want += fmax(most[k], 2.0 * least[p]);
        printf("  3 unsteady points in %.2f s (at most %g s each)\n", sim_time(sm), most[k]);
        /* each of a point's two ends a step late at most */
        assert_close(sim_time(sm), want, 3 * 2 * 0.01);
        sweep_free(sw);
        sim_free(sm);
        model_free(md);
    }
}

/* One mass between springs k1 (wall) and k2 (motor): X = k2 A / (k1 + k2 - m w^2 + i c w).
 * Its gap to the wall (L/2 - w/2 at rest) closes when |X| reaches it, its gap to the
 * piston when |X - A| does: the least amplitude is the smaller of the two, over the
 * frequencies. */
static void contact_amplitude_one_mass(void **state)
{
    (void)state;
    struct model *md = model_new(1);
    md->k[0] = 8.0, md->k[1] = 12.0, md->c[0] = 0.3, md->m[0] = 1.5;
    double gap = 0.5 * MODEL_LENGTH - 0.5 * model_block_width(md);
    const double fs[] = {0.2, 0.55, 0.58, 0.9, 2.0};
    for (size_t k = 0; k < sizeof fs / sizeof *fs; k++) {
        double w = 2.0 * M_PI * fs[k];
        double re = md->k[0] + md->k[1] - md->m[0] * w * w, im = md->c[0] * w;
        double h = md->k[1] / hypot(re, im); /* |X| / A */
        /* X / A - 1 = (k2 - re - i im) / (re + i im) */
        double h1 = hypot(md->k[1] - re, im) / hypot(re, im);
        double want = fmin(gap / h, gap / h1);
        assert_close(sweep_contact_amplitude(md, &fs[k], 1), want, 1e-12 * want);
    }
    /* Over all of them: the least, at the resonance near 0.58 Hz. */
    double all = sweep_contact_amplitude(md, fs, 5), one = sweep_contact_amplitude(md, &fs[2], 1);
    assert_close(all, one, 0.0);
    md->collisions = false;
    assert_true(isinf(sweep_contact_amplitude(md, fs, 5)));
    md->collisions = true;
    md->boundary = BOUNDARY_WALL;
    assert_true(isinf(sweep_contact_amplitude(md, fs, 5)));
    model_free(md);
}

/* A force drives one mass, the right end a wall (the tuned-mass damper's kind of drive,
 * once never warned of): |X| = F / |k1 + k2 - m w^2 + i c w|, and a gap of either wall
 * closes when |X| reaches it, so the force's scale is gap / |X|; the motor-amplitude form
 * says nothing for it. */
static void contact_scale_of_a_force(void **state)
{
    (void)state;
    struct model *md = model_new(1);
    md->k[0] = 8.0, md->k[1] = 12.0, md->c[0] = 0.3, md->m[0] = 1.5;
    md->boundary = BOUNDARY_WALL;
    md->force = 2.0;
    double gap = 0.5 * MODEL_LENGTH - 0.5 * model_block_width(md);
    const double fs[] = {0.2, 0.58, 2.0};
    for (size_t k = 0; k < sizeof fs / sizeof *fs; k++) {
        double w = 2.0 * M_PI * fs[k];
        double x = md->force / hypot(md->k[0] + md->k[1] - md->m[0] * w * w, md->c[0] * w);
        double want = gap / x;
        assert_close(sweep_contact_scale(md, &fs[k], 1), want, 1e-12 * want);
    }
    assert_true(isinf(sweep_contact_amplitude(md, fs, 3)));
    md->force = 0.0;
    assert_true(isinf(sweep_contact_scale(md, fs, 3)));
    model_free(md);
}

/* The default chain at its second natural frequency, where the masses swing against
 * each other: driven (collisions off) at the amplitude said to make contacts, its
 * steady swing closes the smallest gap to within 0.5 % of that gap, and not before. */
static void contact_amplitude_by_simulation(void **state)
{
    (void)state;
    struct model *md = model_new(2);
    double f[2];
    assert_int_equal(modes_compute(md, f, NULL), 0);
    md->motor.frequency = f[1];
    double ac = sweep_contact_amplitude(md, &f[1], 1);
    md->motor.amplitude = ac;
    md->collisions = false;
    struct sim *sm = sim_new(md, 0.01);
    struct collision_limits l;
    collision_limits(&l, md);
    double least = INFINITY, rest = INFINITY;
    double zero[2] = {0.0, 0.0};
    for (int k = 0; k <= l.count - 1; k++)
        rest = fmin(rest, collision_gap(&l, k, zero, 0.0));
    /* 400 s = 20 decay times: the start-up is gone to 2e-9 of it. */
    for (int j = 0; j < 40000; j++) {
        sim_step(sm);
        if (sim_time(sm) < 390.0)
            continue;
        double u = model_end_position(md, sim_time(sm));
        for (int k = 0; k < l.count; k++)
            least = fmin(least, collision_gap(&l, k, sim_x(sm), u));
    }
    printf("  contacts from %.4f m at %.4f Hz: the least gap then %.2e m of %.3f m\n", ac,
           f[1], least, rest);
    assert_close(least, 0.0, 0.005 * rest);
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
        cmocka_unit_test(peak_between_samples),
        cmocka_unit_test(steady_points_match_theory),
        cmocka_unit_test(fixed_settling_misses),
        cmocka_unit_test(unsteady_points_counted),
        cmocka_unit_test(contact_amplitude_one_mass),
        cmocka_unit_test(contact_amplitude_by_simulation),
        cmocka_unit_test(phase_of_signals),
        cmocka_unit_test(phase_one_mass),
        cmocka_unit_test(contacts_while_sweeping),
        cmocka_unit_test(nearest_mode),
        cmocka_unit_test(contact_scale_of_a_force),
    };
    return cmocka_run_group_tests_name("sweep", tests, NULL, NULL);
}
