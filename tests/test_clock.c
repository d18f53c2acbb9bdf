/* test_clock.c: the chain following the wall clock (app/clock.c), the one catch-up both
 * front ends use: as many steps of dt as the wall time times the speed owes, the rest
 * kept for later; nothing owed while paused; a step that fails stops it; a budget
 * spent leaves the chain behind, and a large debt is let go; a sweep plays faster. */
#include "testutil.h"

#include "app/app.h"
#include "app/clock.h"

static struct app app;

static int setup(void **state)
{
    (void)state;
    static struct config c;
    config_init(&c);
    c.masses = 2;
    c.dt = 0.001;
    return app_init(&app, &c, SRCDIR);
}

static int teardown(void **state)
{
    (void)state;
    app_free(&app);
    return 0;
}

static int calls;   /* steps the counting stepper was asked for */
static int fail_at; /* the call that fails (0: none) */

static bool counting_step(void *ctx)
{
    struct app *a = ctx;
    if (++calls == fail_at)
        return false;
    return app_step(a) != 0;
}

/* 10.5 ms of wall time at speed 1 owes ten and a half steps of 1 ms: ten are taken, half
 * a step is kept, and the next 0.5 ms makes it whole. */
static void steps_what_the_clock_owes(void **state)
{
    (void)state;
    struct app_clock c = {0};
    app_set_running(&app, true);
    app.speed = 1.0;
    app_clock_follow(&c, &app, 0.0105, 10.0, NULL, NULL);
    assert_close(sim_time(app.sim), 0.010, 1e-12);
    assert_close(c.debt, 0.0005, 1e-12);
    assert_false(c.behind);
    app_clock_follow(&c, &app, 0.0005, 10.0, NULL, NULL);
    assert_close(sim_time(app.sim), 0.011, 1e-12);
    /* At speed 0.5 the same wall time owes half as many steps. */
    app.speed = 0.5;
    app_clock_follow(&c, &app, 0.010, 10.0, NULL, NULL);
    assert_close(sim_time(app.sim), 0.016, 1e-12);
}

static void owes_nothing_while_paused(void **state)
{
    (void)state;
    struct app_clock c = {.debt = 0.5, .behind = true};
    app_set_running(&app, false);
    app_clock_follow(&c, &app, 1.0, 10.0, NULL, NULL);
    assert_close(sim_time(app.sim), 0.0, 0.0);
    assert_close(c.debt, 0.0, 0.0);
    assert_false(c.behind);
}

/* The caller's stepper is the one used, and its false stops the catch-up there. */
static void a_failed_step_stops_it(void **state)
{
    (void)state;
    struct app_clock c = {0};
    app_set_running(&app, true);
    app.speed = 1.0;
    calls = 0;
    fail_at = 4;
    app_clock_follow(&c, &app, 0.010, 10.0, counting_step, &app);
    assert_int_equal(calls, 4);
    assert_close(sim_time(app.sim), 0.003, 1e-12);
    assert_false(c.behind);
}

/* No time to spend: one step, then the chain is behind; a debt of more than a quarter
 * second of playback is let go, a smaller one kept. */
static void a_spent_budget_leaves_it_behind(void **state)
{
    (void)state;
    struct app_clock c = {0};
    app_set_running(&app, true);
    app.speed = 1.0;
    app_clock_follow(&c, &app, 1.0, -1.0, NULL, NULL);
    assert_close(sim_time(app.sim), 0.001, 1e-12);
    assert_true(c.behind);
    assert_close(c.debt, 0.0, 0.0);
    app_clock_follow(&c, &app, 0.1, -1.0, NULL, NULL);
    assert_close(sim_time(app.sim), 0.002, 1e-12);
    assert_true(c.behind);
    assert_close(c.debt, 0.099, 1e-12);
    /* With time to spend, the debt is paid down to less than a step (what is stepped and
     * what is owed add up to what the clock gave) and the chain is no longer behind. */
    app_clock_follow(&c, &app, 0.0, 10.0, NULL, NULL);
    assert_true(c.debt < 0.001);
    assert_close(sim_time(app.sim) + c.debt, 0.101, 1e-9);
    assert_false(c.behind);
}

/* A running sweep plays 50 times the Speed control's rate, so that the defaults' sweep
 * of some 4100 simulated seconds ends within two minutes; stopped, the rate is the
 * control's again. */
static void a_sweep_plays_faster(void **state)
{
    (void)state;
    struct app_clock c = {0};
    app.speed = 1.0;
    app_toggle_sweep(&app);
    assert_true(app.sweep->active && app.running);
    assert_close(app_clock_pace(&app), 50.0, 0.0);
    /* 10 ms of wall time owe 0.5 s: what is stepped (1 ms at a time) and what is owed
     * add up to it, less than a step owed. */
    app_clock_follow(&c, &app, 0.010, 10.0, NULL, NULL);
    assert_close(sim_time(app.sim) + c.debt, 0.5, 1e-9);
    assert_true(c.debt < 0.001);
    app.speed = 0.5;
    assert_close(app_clock_pace(&app), 25.0, 0.0);
    app_clock_follow(&c, &app, 0.010, 10.0, NULL, NULL);
    assert_close(sim_time(app.sim) + c.debt, 0.75, 1e-9);
    app_toggle_sweep(&app);
    assert_false(app.sweep->active);
    assert_close(app_clock_pace(&app), 0.5, 0.0);
    app_clock_follow(&c, &app, 0.010, 10.0, NULL, NULL);
    assert_close(sim_time(app.sim) + c.debt, 0.755, 1e-9);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup_teardown(steps_what_the_clock_owes, setup, teardown),
        cmocka_unit_test_setup_teardown(owes_nothing_while_paused, setup, teardown),
        cmocka_unit_test_setup_teardown(a_failed_step_stops_it, setup, teardown),
        cmocka_unit_test_setup_teardown(a_spent_budget_leaves_it_behind, setup, teardown),
        cmocka_unit_test_setup_teardown(a_sweep_plays_faster, setup, teardown),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
