/* test_ghost.c: the ghost (key g, src/app/ghost.c). Unchanged, it is the live chain bit
 * for bit, whatever the integrator, through contacts and the square wave's jumps; after
 * the live damping changes the two part, and the ghost is what an independent run of the
 * core with the old parameters gives; stepping back and resetting move both; g again, a
 * new chain and a blow-up of its own drop it; nothing is allocated while it runs. The app
 * under test comes from tests/app_fixture.c; allocations are counted by tests/alloc_count.c (--wrap). */
#include "app_fixture.h"
#include "alloc_count.h"

#include <stdlib.h>
#include <string.h>

#include "app/ghost.h"

/* ---- helpers ---- */

/* Whether the ghost's state and time are the live chain's, bit for bit. */
static bool ghost_is_live(void)
{
    int n = app.model->n;
    const struct sim *g = app.ghost->sim;
    return sim_time(g) == sim_time(app.sim) &&
           memcmp(sim_x(g), sim_x(app.sim), (size_t)n * sizeof(double)) == 0 &&
           memcmp(sim_v(g), sim_v(app.sim), (size_t)n * sizeof(double)) == 0;
}

/* The largest |x_i| difference between the ghost and the live chain. */
static double parting(void)
{
    double d = 0.0;
    for (int i = 0; i < app.model->n; i++)
        d = fmax(d, fabs(sim_x(app.ghost->sim)[i] - sim_x(app.sim)[i]));
    return d;
}

/* Makes the ghost and checks the mask says so. */
static void make_ghost(void)
{
    assert_null(app.ghost);
    unsigned w = app_toggle_ghost(&app);
    assert_true(w & APP_CHANGED_GHOST);
    assert_non_null(app.ghost);
}

/* Runs steps live steps, checking after each that the ghost is the live chain; returns
 * the contacts the live chain made. */
static long run_in_step(int steps)
{
    long contacts = 0;
    for (int s = 0; s < steps; s++) {
        assert_true(app_step(&app));
        contacts += sim_last_contacts(app.sim);
        if (!ghost_is_live())
            fail_msg("the ghost left the live chain at step %d, t = %.17g", s, sim_time(app.sim));
    }
    return contacts;
}

/* A sim of the core alone, from settings c at t = 0, run `steps` steps of c's dt: the
 * independent answer. */
static struct sim *independent_run(const struct config *c, long steps)
{
    int bad;
    char err[200];
    struct model *m = config_model(c, &bad, err, sizeof err);
    assert_non_null(m);
    struct sim *s = sim_new(m, c->dt);
    assert_non_null(s);
    sim_set_integrator(s, c->integrator);
    double x[APP_MAX_MASSES], v[APP_MAX_MASSES];
    config_initial(c, m, x, v);
    sim_reset(s, x, v);
    for (long k = 0; k < steps; k++)
        assert_int_equal(sim_step(s), SIM_OK);
    model_free(m);
    return s;
}

/* ---- tests ---- */

/* Unchanged, the ghost is the live chain bit for bit: every integrator, made after the
 * live chain has run a while (so the drive's carried sin and cos are copied too), on the
 * sine and on the square wave (breakpoints, jumps). At dt 0.002 s, inside explicit
 * Euler's stability limit on this chain (0.0029 s), so that no integrator blows up. */
static void unchanged_ghost_is_the_live_chain(void **state)
{
    (void)state;
    assert_true(app_set_text(&app, CTL_DT, "0.002"));
    for (int i = 0; i < INTEGRATOR_COUNT; i++) {
        for (int square = 0; square < 2; square++) {
            app_set_text(&app, CTL_INTEGRATOR, integrator_name((enum integrator)i));
            app_set_text(&app, CTL_WAVE, square ? "square" : "sine");
            app_reset(&app);
            run(137);
            make_ghost();
            run_in_step(3000);
            /* A reset takes both to t = 0 and they go on alike. */
            app_reset(&app);
            assert_true(sim_time(app.ghost->sim) == 0.0);
            run_in_step(500);
            app_toggle_ghost(&app);
            assert_null(app.ghost);
        }
    }
}

/* With contacts: the collisions preset bounces mass 1 off the wall from t = 3.8 s. */
static void unchanged_ghost_through_contacts(void **state)
{
    (void)state;
    assert_true(app_load_preset(&app, SRCDIR "/presets/collisions.ini", "collisions"));
    for (int i = 0; i < INTEGRATOR_COUNT; i++) {
        app_set_text(&app, CTL_INTEGRATOR, integrator_name((enum integrator)i));
        app_reset(&app);
        run(50);
        make_ghost();
        assert_true(run_in_step(1500) >= 3);
        app_toggle_ghost(&app);
    }
}

/* After the live damping changes the two part, and the ghost is an independent run of
 * the core with the settings it was made with; the status says what differs. */
static void ghost_keeps_the_old_parameters(void **state)
{
    (void)state;
    struct config before = app.cfg;
    run(400);
    make_ghost();
    unsigned w = app_set_text(&app, CTL_DAMPING, "0.8");
    assert_true(w & APP_CHANGED_CHAIN);
    assert_non_null(app.ghost);
    run(3000);
    assert_true(parting() > 1e-2);
    struct sim *ref = independent_run(&before, 3400);
    int n = app.model->n;
    assert_true(sim_time(ref) == sim_time(app.ghost->sim));
    assert_memory_equal(sim_x(ref), sim_x(app.ghost->sim), (size_t)n * sizeof(double));
    assert_memory_equal(sim_v(ref), sim_v(app.ghost->sim), (size_t)n * sizeof(double));
    sim_free(ref);
    char line[200];
    ghost_describe(&app, line, sizeof line);
    char want[40];
    snprintf(want, sizeof want, "ghost c %.3g", before.damping.count ? before.damping.v[0]
                                                                     : app.ghost->model->c[0]);
    assert_string_equal(line, want);
    /* Its dt and integrator too. */
    app_set_text(&app, CTL_INTEGRATOR, "verlet");
    app_set_text(&app, CTL_DAMPING, "0.8");
    ghost_describe(&app, line, sizeof line);
    assert_non_null(strstr(line, " rk4"));
}

/* The ghost keeps its own dt: with the live dt doubled it takes two steps to each live
 * one, on its own grid, and stays the independent run with its dt. */
static void ghost_keeps_its_dt(void **state)
{
    (void)state;
    struct config before = app.cfg;
    make_ghost();
    char dt[32];
    snprintf(dt, sizeof dt, "%g", 2.0 * before.dt);
    app_set_text(&app, CTL_DT, dt);
    run(1000);
    assert_close(sim_time(app.sim), 2000 * before.dt, 1e-9);
    struct sim *ref = independent_run(&before, 2000);
    assert_true(sim_time(ref) == sim_time(app.ghost->sim));
    assert_memory_equal(sim_x(ref), sim_x(app.ghost->sim), (size_t)app.model->n * sizeof(double));
    sim_free(ref);
    char line[200];
    ghost_describe(&app, line, sizeof line);
    assert_non_null(strstr(line, "dt"));
}

/* Stepping back moves both, to the states they had; past the instant the ghost was made
 * it is dropped with a message, the live chain going back as before. */
static void stepping_back_moves_both(void **state)
{
    (void)state;
    run(100);
    make_ghost();
    app_set_text(&app, CTL_DAMPING, "0.8");
    run(100);
    int n = app.model->n;
    double gx[APP_MAX_MASSES], lx[APP_MAX_MASSES], t = sim_time(app.sim);
    memcpy(gx, sim_x(app.ghost->sim), (size_t)n * sizeof(double));
    memcpy(lx, sim_x(app.sim), (size_t)n * sizeof(double));
    run(150);
    for (int k = 0; k < 150; k++)
        assert_true(app_back(&app) & APP_CHANGED_STATE);
    assert_true(sim_time(app.sim) == t);
    assert_true(sim_time(app.ghost->sim) == t);
    assert_memory_equal(sim_x(app.ghost->sim), gx, (size_t)n * sizeof(double));
    assert_memory_equal(sim_x(app.sim), lx, (size_t)n * sizeof(double));
    /* The ghost's samples go back with it. */
    const struct trail *tr = app.ghost->trail;
    assert_true(trail_first(tr)[(size_t)(tr->count - 1) * tr->width + TRAIL_T] <= t + 1e-9);
    for (int k = 0; k < 100; k++)
        assert_true(app_back(&app) & APP_CHANGED_STATE);
    assert_non_null(app.ghost);
    unsigned w = app_back(&app);
    assert_true(w & APP_CHANGED_GHOST);
    assert_null(app.ghost);
    assert_non_null(strstr(app.message, "ghost dropped"));
}

/* A reset takes each to t = 0 at its own initial conditions. */
static void reset_takes_each_to_its_start(void **state)
{
    (void)state;
    int n = app.model->n;
    double x0[APP_MAX_MASSES];
    memcpy(x0, app.cfg.x0.v, (size_t)n * sizeof(double));
    run(200);
    make_ghost();
    app_random(&app); /* new initial positions for the live chain, and a reset */
    assert_non_null(app.ghost);
    assert_true(sim_time(app.ghost->sim) == 0.0 && sim_time(app.sim) == 0.0);
    assert_memory_equal(sim_x(app.ghost->sim), x0, (size_t)n * sizeof(double));
    assert_memory_equal(sim_x(app.sim), app.cfg.x0.v, (size_t)n * sizeof(double));
    assert_true(parting() > 0.0);
    char line[200];
    ghost_describe(&app, line, sizeof line);
    assert_string_equal(line, "ghost own start");
}

/* g again, a new N and a preset drop it; the mask and the message say so. */
static void ghost_dropped(void **state)
{
    (void)state;
    make_ghost();
    unsigned w = app_toggle_ghost(&app);
    assert_true(w & APP_CHANGED_GHOST);
    assert_null(app.ghost);
    make_ghost();
    w = new_n();
    assert_true(w & APP_CHANGED_GHOST);
    assert_null(app.ghost);
    make_ghost();
    w = preset();
    assert_true(w & APP_CHANGED_GHOST);
    assert_null(app.ghost);
}

/* A ghost that blows up is dropped and the live chain goes on: the ghost is made on
 * stiff springs at a dt past Euler's stability limit, then the live dt is made stable. */
static void ghost_blowing_up_is_dropped(void **state)
{
    (void)state;
    app_set_text(&app, CTL_INTEGRATOR, "euler");
    app_set_text(&app, CTL_SPRING, "200");
    app_set_text(&app, CTL_DT, "0.05");
    app_set_text(&app, CTL_AMPLITUDE, "0.5");
    make_ghost();
    app_set_text(&app, CTL_DT, "0.001");
    app_set_text(&app, CTL_INTEGRATOR, "rk4");
    unsigned dropped = 0;
    for (int s = 0; s < 20000 && app.ghost; s++) {
        unsigned w = app_step(&app);
        assert_true(w & APP_CHANGED_STATE);
        dropped |= w & APP_CHANGED_GHOST;
    }
    assert_null(app.ghost);
    assert_true(dropped);
    assert_non_null(strstr(app.message, "ran away"));
    run(100);
}

/* Out of memory for any part of the ghost: no ghost, the reason said, nothing kept (the
 * sanitizers see a leak), the live chain going on. */
static void ghost_out_of_memory(void **state)
{
    (void)state;
    run(10);
    for (int k = 1; k <= 4; k++) { /* its sim, history and two trails */
        fail_allocation(k);
        unsigned w = app_toggle_ghost(&app);
        fail_allocation(0);
        assert_null(app.ghost);
        assert_false(w & APP_CHANGED_GHOST);
        assert_int_equal(app.said, SAID_ERROR);
        assert_non_null(strstr(app.message, "out of memory"));
        run(10);
    }
    make_ghost();
    run(10);
    assert_true(ghost_is_live());
}

/* The span of a trail's records (s). */
static double span(const struct trail *tr)
{
    const double *r = trail_first(tr);
    return r[(size_t)(tr->count - 1) * tr->width + TRAIL_T] - r[TRAIL_T];
}

/* The ghost's samples, sized for its own dt, cover every time window as the live chain's
 * do: 10 s from the fine ones, 60 s from the coarse ones, the same trail chosen. */
static void ghost_samples_cover_the_windows(void **state)
{
    (void)state;
    for (int k = 0; k < 2; k++) {
        app_set_text(&app, CTL_DT, k ? "0.001" : "0.01");
        app_reset(&app);
        make_ghost();
        run((int)lround(70.0 / app.cfg.dt));
        assert_true(span(app.ghost->trail) >= 10.0);
        assert_true(span(app.ghost->coarse) >= 60.0);
        assert_true(span(app.ghost->trail) >= fmin(span(app.trail), 10.0 + 3 * app.cfg.dt));
        assert_ptr_equal(app_ghost_trail(&app), app.ghost->trail);
        app_window_step(&app, 3); /* 60 s */
        assert_ptr_equal(app_ghost_trail(&app), app.ghost->coarse);
        app_window_step(&app, -3);
        app_toggle_ghost(&app);
    }
}

/* Nothing is allocated while the ghost runs, steps back or resets. */
static void no_allocation_per_step(void **state)
{
    (void)state;
    allocations = 0;
    make_ghost();
    assert_true(allocations >= 6); /* the count sees the app's allocations */
    app_set_text(&app, CTL_DAMPING, "0.8");
    run(10);
    allocations = 0;
    run(2000);
    for (int k = 0; k < 100; k++)
        app_back(&app);
    app_reset(&app);
    run(100);
    assert_int_equal(allocations, 0);
}

int main(void)
{
#define T(f) cmocka_unit_test_setup_teardown(f, setup, teardown)
    const struct CMUnitTest tests[] = {
        T(unchanged_ghost_is_the_live_chain), T(unchanged_ghost_through_contacts),
        T(ghost_keeps_the_old_parameters),    T(ghost_keeps_its_dt),
        T(stepping_back_moves_both),          T(reset_takes_each_to_its_start),
        T(ghost_dropped),                     T(ghost_blowing_up_is_dropped),
        T(ghost_out_of_memory),               T(ghost_samples_cover_the_windows),
        T(no_allocation_per_step),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
