/* test_app_window.c: the interactive program's time window without a terminal: its
 * steps and limits, the window from the settings, the two trails (the coarse one covers
 * 60 s), the digits time is shown with, the extremes shown. The app under test comes from
 * tests/app_fixture.c; every test starts from its own fresh app. */
#include "app_fixture.h"

#include <stdlib.h>
#include <string.h>

/* ---- the time window and its trails ---- */

static void window_steps_and_clamps(void **state)
{
    (void)state;
    assert_close(app_window(&app), 10.0, 0.0);
    assert_ptr_equal(app_trail(&app), app.trail);
    assert_int_equal(app_window_step(&app, 0), 0);
    static const double down[] = {5, 2, 1};
    for (int i = 0; i < 3; i++) {
        assert_int_equal(app_window_step(&app, -1), APP_CHANGED_WINDOW);
        assert_close(app_window(&app), down[i], 0.0);
        assert_ptr_equal(app_trail(&app), app.trail);
    }
    assert_int_equal(app_window_step(&app, -1), APP_CHANGED_MESSAGE);
    assert_close(app_window(&app), 1.0, 0.0);
    assert_non_null(strstr(app.message, "1 s at least"));
    static const double up[] = {2, 5, 10, 20, 30, 60};
    for (int i = 0; i < 6; i++) {
        assert_int_equal(app_window_step(&app, 1), APP_CHANGED_WINDOW);
        assert_close(app_window(&app), up[i], 0.0);
        assert_ptr_equal(app_trail(&app), up[i] <= 10 ? app.trail : app.coarse);
    }
    assert_int_equal(app_window_step(&app, 1), APP_CHANGED_MESSAGE);
    assert_close(app_window(&app), 60.0, 0.0);
    assert_non_null(strstr(app.message, "60 s at most"));
    /* Several places at once, clamped. */
    assert_int_equal(app_window_step(&app, -10), APP_CHANGED_WINDOW | APP_CHANGED_MESSAGE);
    assert_close(app_window(&app), 1.0, 0.0);
    /* The window belongs to the app, not the chain. */
    app_window_step(&app, 5);
    new_n();
    preset();
    app_reset(&app);
    assert_close(app_window(&app), 30.0, 0.0);
    assert_ptr_equal(app_trail(&app), app.coarse);
}

/* A window between the list's (--window, a preset) starts there; < and > go on to the
 * list's nearest on either side; a preset that names one sets it, one that does not
 * keeps the user's; set window checks --window's range. */
static void window_from_settings(void **state)
{
    (void)state;
    static struct config c;
    c = cfg;
    c.window = 33.0;
    app_free(&app);
    assert_int_equal(app_init(&app, &c, NULL), 0);
    assert_close(app_window(&app), 33.0, 0.0);
    assert_ptr_equal(app_trail(&app), app.coarse); /* the fine samples reach 11 s */
    assert_int_equal(app_window_step(&app, -1), APP_CHANGED_WINDOW);
    assert_close(app_window(&app), 30.0, 0.0);
    app.cfg.window = 33.0;
    assert_int_equal(app_window_step(&app, 1), APP_CHANGED_WINDOW);
    assert_close(app_window(&app), 60.0, 0.0);
    app.cfg.window = 33.0;
    assert_int_equal(app_window_step(&app, -2), APP_CHANGED_WINDOW);
    assert_close(app_window(&app), 20.0, 0.0);

    assert_int_equal(preset_text("p", "[run]\nwindow = 5\n") & APP_CHANGED_WINDOW,
                     APP_CHANGED_WINDOW);
    assert_close(app_window(&app), 5.0, 0.0);
    unsigned w = preset(); /* 3-mass-chain says no window */
    assert_true(w && !(w & APP_CHANGED_WINDOW));
    assert_close(app_window(&app), 5.0, 0.0);

    assert_int_equal(app_set_window(&app, "61"), 0);
    assert_int_equal(app.said, SAID_ERROR);
    assert_string_equal(app.message, "window: '61' is out of range (expected 1 <= window <= 60)");
    assert_close(app_window(&app), 5.0, 0.0);
    assert_int_equal(app_set_window(&app, "12.5"), APP_CHANGED_WINDOW | APP_CHANGED_MESSAGE);
    assert_close(app_window(&app), 12.5, 0.0);
    assert_string_equal(app.message, "window 12.5 s");
}

/* Checks a trail is in time order, spaced min to max apart, and covers t0..t1 (its last
 * sample less than max before t1). */
static void covers(const struct trail *tr, double min, double max, double t0, double t1)
{
    const double *r = trail_first(tr);
    assert_true(tr->count > 1);
    if (!(r[TRAIL_T] <= t0 + 1e-9))
        fail_msg("the trail starts at t = %g s, after %g s", r[TRAIL_T], t0);
    for (int k = 1; k < tr->count; k++) {
        double gap = r[k * tr->width + TRAIL_T] - r[(k - 1) * tr->width + TRAIL_T];
        if (!(gap >= min - 1e-9 && gap <= max + 1e-9))
            fail_msg("samples %g s apart at t = %g s", gap, r[k * tr->width + TRAIL_T]);
    }
    double last = r[(tr->count - 1) * tr->width + TRAIL_T];
    assert_true(last <= t1 + 1e-9 && last > t1 - max);
}

/* The coarse trail covers the longest window at the smallest dt (the most samples). */
static void coarse_trail_covers_60_s(void **state)
{
    (void)state;
    assert_true(app_set_text(&app, CTL_DT, "0.001"));
    app_reset(&app);
    while (sim_time(app.sim) < 60.5)
        assert_true(app_step(&app));
    double now = sim_time(app.sim);
    covers(app.coarse, 0.015, 0.015, now - 60.0, now);
    covers(app.trail, 0.003, 0.003, now - 10.0, now);
    /* And the fine one is no longer than it must be: about 11 s, not 60. */
    assert_true(trail_first(app.trail)[TRAIL_T] > now - 15.0);
    /* At the largest dt, every step is a fine sample: still more than 10 s. */
    app_set_text(&app, CTL_DT, "0.05");
    app_set_text(&app, CTL_SPRING, "1"); /* stable at 0.05 */
    app_reset(&app);
    for (int i = 0; i < 1400; i++)
        assert_true(app_step(&app));
    now = sim_time(app.sim);
    covers(app.coarse, 0.05, 0.05, now - 60.0, now);
    covers(app.trail, 0.05, 0.05, now - 10.0, now);
    /* Both go back in time together, and are cleared together. */
    for (int i = 0; i < 100; i++)
        assert_true(app_back(&app));
    now = sim_time(app.sim);
    covers(app.coarse, 0.05, 0.05, now - 60.0, now);
    covers(app.trail, 0.05, 0.05, now - 10.0, now);
    assert_close(trail_first(app.trail)[(app.trail->count - 1) * app.trail->width], now, 1e-9);
    app_reset(&app);
    assert_int_equal(app.trail->count, 1);
    assert_int_equal(app.coarse->count, 1);
}

/* ---- the digits time is shown with ---- */

/* t and dt are shown with the digits dt needs, 2 at least, so a fine or odd step never
 * reads rounded. 0.0175 and 0.0215 times 10^4 come out a hair above and below a whole
 * number in binary: the test for one must allow for it both ways. */
static void time_decimals(void **state)
{
    (void)state;
    static const struct {
        double dt;
        int decimals;
    } cases[] = {
        {0.01, 2},   {0.001, 3},   {0.0075, 4}, {0.05, 2},
        {0.0125, 4}, {0.00001, 5}, {0.0175, 4}, {0.0215, 4},
    };
    for (size_t i = 0; i < sizeof cases / sizeof *cases; i++) {
        int d = app_time_decimals(cases[i].dt);
        if (d != cases[i].decimals)
            fail_msg("dt = %g s: %d decimals, expected %d", cases[i].dt, d, cases[i].decimals);
    }
    char buf[64];
    snprintf(buf, sizeof buf, "%.*f", app_time_decimals(0.001), 3 * 0.001);
    assert_string_equal(buf, "0.003");
    /* So it reads after three steps of 0.001 s, and dt 0.0075 s reads whole. */
    assert_true(app_set_text(&app, CTL_DT, "0.001"));
    run(3);
    snprintf(buf, sizeof buf, "%.*f", app_time_decimals(app.cfg.dt), sim_time(app.sim));
    assert_string_equal(buf, "0.003");
    assert_true(app_set_text(&app, CTL_DT, "0.0075"));
    app_control_value(&app, CTL_DT, buf, sizeof buf);
    assert_string_equal(buf, "0.0075 s");
}

/* Typed extremes read as what they are (issue 11, defect 16): no run of digits that cuts
 * the unit, no 0.00 for a value that is not 0, never -0. */
static void extremes_shown(void **state)
{
    (void)state;
    static const struct {
        enum control ctl;
        const char *text, *shown;
    } cases[] = {
        {CTL_SPRING, "1e308", "1e+308 N/m"},
        {CTL_MASS, "1e-320", "1e-320 kg"},
        {CTL_DAMPING, "1e-300", "1e-300 N·s/m"},
        {CTL_AMPLITUDE, "-0", "0.00 m"},
        {CTL_MASS, "0.125", "0.125 kg"},
        {CTL_SPRING, "12.5", "12.5 N/m"},
        {CTL_AMPLITUDE, "0.3", "0.30 m"},
    };
    char buf[64];
    for (size_t i = 0; i < sizeof cases / sizeof *cases; i++) {
        app_set_text(&app, cases[i].ctl, cases[i].text);
        app_control_value(&app, cases[i].ctl, buf, sizeof buf);
        if (strcmp(buf, cases[i].shown) != 0)
            fail_msg("%s typed '%s' shows '%s', expected '%s'", app_control_label(cases[i].ctl),
                     cases[i].text, buf, cases[i].shown);
    }
    /* A typed control byte is said escaped, never sent to the terminal (defect 10). */
    app_set_text(&app, CTL_SPEED, "\033]0;X\a");
    assert_non_null(strstr(app.message, "'\\x1b]0;X\\a'"));
    app_set_text(&app, CTL_DT, "1\n2");
    assert_non_null(strstr(app.message, "'1\\n2'"));
    assert_null(strchr(app.message, '\n'));
}

/* ---- editing, modes, files, history ---- */

int main(void)
{
#define T(f) cmocka_unit_test_setup_teardown(f, setup, teardown)
    const struct CMUnitTest tests[] = {
        T(window_steps_and_clamps),
        T(window_from_settings),
        T(coarse_trail_covers_60_s),
        T(time_decimals),
        T(extremes_shown),
    };
#undef T
    return cmocka_run_group_tests_name("app window", tests, NULL, NULL);
}
