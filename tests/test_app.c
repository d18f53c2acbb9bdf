/* test_app.c: the interactive program's state without a terminal: what the masks
 * returned say changed, per-element editing, the mode marker, a saved preset that reloads to the same
 * chain, export, branching from history. The rules every route of a change keeps are in
 * test_app_rules.c, the time window in test_app_window.c; the app under test comes from tests/app_fixture.c. Every test starts
 * from its own fresh app. */
#include "app_fixture.h"

#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "app/change.h"
#include "app/ghost.h"
#include "core/preset.h"

/* One value for every element of a list. */
static void set_list(struct config_list *l, double v)
{
    l->count = 1;
    l->v[0] = v;
}

/* Puts next in force as a preset would: a new chain at t = 0. */
static int app_load_config(struct config *next)
{
    unsigned what;
    return app_change(&app, next, CHANGE_REBUILD, "the test", &what);
}

/* ---- what the masks say ---- */

/* The arrows move damping, springs and masses up as well as down, by their fine and
 * coarse steps (0.01 and 0.1 N s/m, 1 and 5 N/m, 0.1 and 0.5 kg: the controls' table). */
static void arrows_move_lists_both_ways(void **state)
{
    (void)state;
    app_set_text(&app, CTL_DAMPING, "0.1");
    app_adjust(&app, CTL_DAMPING, 1, false);
    assert_close(app.model->c[0], 0.11, 1e-12);
    app_adjust(&app, CTL_DAMPING, 1, true);
    assert_close(app.model->c[2], 0.2, 1e-12);
    app_adjust(&app, CTL_DAMPING, -1, false);
    assert_close(app.model->c[1], 0.19, 1e-12);
    double k = app.model->k[0], m = app.model->m[0];
    app_adjust(&app, CTL_SPRING, 1, false);
    assert_true(app.model->k[0] > k);
    app_adjust(&app, CTL_MASS, 1, false);
    assert_true(app.model->m[0] > m);
}

static void masks_say_what_changed(void **state)
{
    (void)state;
    modes_calls = 0;
    unsigned w = app_set_text(&app, CTL_FREQUENCY, "1.3");
    assert_true(w & APP_CHANGED_DRIVE);
    assert_false(w & (APP_CHANGED_SIZE | APP_CHANGED_CHAIN | APP_CHANGED_STATE));
    assert_int_equal(modes_calls, 0);
    w = app_adjust(&app, CTL_FREQUENCY, 1, false);
    assert_int_equal(w, APP_CHANGED_DRIVE);
    w = app_adjust(&app, CTL_SPRING, 1, false);
    assert_true(w & APP_CHANGED_CHAIN);
    assert_false(w & (APP_CHANGED_DRIVE | APP_CHANGED_SIZE | APP_CHANGED_STATE));
    w = app_adjust(&app, CTL_BOUNDARY, 1, false);
    assert_int_equal(w & (APP_CHANGED_CHAIN | APP_CHANGED_DRIVE | APP_CHANGED_SIZE),
                     APP_CHANGED_CHAIN | APP_CHANGED_DRIVE);
    w = app_adjust(&app, CTL_DT, 1, false);
    assert_int_equal(w & ~APP_CHANGED_MESSAGE, APP_CHANGED_DT);
    /* A dt past the stability limit says so, and so do springs that make it so. */
    w = app_set_text(&app, CTL_DT, "0.05");
    assert_int_equal(app.said, SAID_NOTE);
    w = app_set_text(&app, CTL_SPRING, "5000");
    assert_true(w & APP_CHANGED_CHAIN);
    assert_int_equal(app.said, SAID_WARNING);
    assert_non_null(strstr(app.message, "stability limit"));
    w = app_set_text(&app, CTL_SPRING, "10");
    assert_int_equal(app.said, SAID_NOTE);
    w = app_set_text(&app, CTL_SPRING, "5000");
    w = app_set_text(&app, CTL_DT, "0.001"); /* at 0.01 its top mode is only roughly right */
    assert_true(w & APP_CHANGED_DT);
    assert_int_equal(app.said, SAID_NOTE);
    w = app_set_text(&app, CTL_DT, "0.05");
    assert_true(w & APP_CHANGED_DT);
    assert_int_equal(app.said, SAID_WARNING);
    assert_non_null(strstr(app.message, "stability limit"));
    assert_true(app_set_text(&app, CTL_DT, "0.01"));
    assert_true(app_set_text(&app, CTL_SPRING, "10"));
    /* Only the pending N moves until it is applied. */
    w = app_adjust(&app, CTL_MASSES, 1, false);
    assert_int_equal(w, APP_CHANGED_PENDING | APP_CHANGED_MESSAGE);
    assert_int_equal(app.model->n, 3);
    app.running = true;
    w = app_apply_masses(&app);
    unsigned rebuilt = APP_CHANGED_SIZE | APP_CHANGED_CHAIN | APP_CHANGED_STATE;
    assert_int_equal(w & rebuilt, rebuilt);
    assert_true(w & APP_CHANGED_PLAYBACK); /* paused */
    assert_false(app.running);
    assert_false(w & (APP_CHANGED_WINDOW | APP_CHANGED_DRIVE));
    assert_int_equal(app.model->n, 4);
    assert_int_equal(app_apply_masses(&app), 0); /* nothing pending */
    assert_int_equal(app_step(&app), APP_CHANGED_STATE);
    assert_int_equal(app_back(&app), APP_CHANGED_STATE);
    assert_int_equal(app_back(&app), 0); /* at t = 0 */
    assert_int_equal(app_adjust(&app, CTL_SPEED, 1, false), APP_CHANGED_PLAYBACK);
    assert_int_equal(app_set_running(&app, true), APP_CHANGED_PLAYBACK);
    assert_int_equal(app_set_running(&app, true), 0);
    app.running = false;
    assert_int_equal(app_reset(&app), APP_CHANGED_STATE);
    /* Nothing to change: 0, and the arrows stop at their ends. */
    assert_true(app_set_text(&app, CTL_FREQUENCY, "5"));
    assert_int_equal(app_adjust(&app, CTL_FREQUENCY, 1, false), 0);
    assert_int_equal(app_adjust(&app, CTL_WAVE, 4, false), 0);
    /* A value typed again succeeds (truthy) and changes nothing but the message. */
    unsigned version = app.version;
    assert_int_equal(app_set_text(&app, CTL_FREQUENCY, "5"), APP_CHANGED_MESSAGE);
    assert_int_equal(app_set_element(&app, 'm', 0, "1"), APP_CHANGED_MESSAGE);
    assert_int_equal(app.version, version);
}

/* Playback settings are the user's: a preset that does not name them keeps them. */
static void preset_keeps_playback(void **state)
{
    (void)state;
    assert_int_equal(app_set_text(&app, CTL_BANDWIDTH, "low"),
                     APP_CHANGED_PLAYBACK | APP_CHANGED_MESSAGE);
    app.cfg.fps = 12;
    app.speed = 4.0;
    unsigned w = preset();
    assert_true(w);
    assert_false(w & APP_CHANGED_PLAYBACK);
    assert_true(app.cfg.low_bandwidth);
    assert_int_equal(app.cfg.fps, 12);
    assert_close(app.speed, 4.0, 0.0);
    /* One that does, changes them. */
    app.cfg.color = CONFIG_COLOR_ALWAYS;
    app.cfg.glyphs = CONFIG_GLYPHS_BLOCKS;
    w = preset_text("p", "[run]\nfps = 20\ncolor = never\nglyphs = ascii\n");
    assert_true(w & APP_CHANGED_PLAYBACK);
    assert_int_equal(app.cfg.fps, 20);
    assert_true(app.cfg.low_bandwidth);
    /* The terminal was set up at start: its colour and glyphs stay as they were. */
    assert_int_equal(app.cfg.color, CONFIG_COLOR_ALWAYS);
    assert_int_equal(app.cfg.glyphs, CONFIG_GLYPHS_BLOCKS);
}

static void element_editing(void **state)
{
    (void)state;
    assert_true(app_set_element(&app, 'm', 1, "2.5"));
    assert_close(app.model->m[1], 2.5, 0.0);
    assert_close(app.model->m[0], 1.0, 0.0);
    assert_true(app_set_element(&app, 'k', 3, "22"));
    assert_close(app.model->k[3], 22.0, 0.0);
    assert_true(app_set_element(&app, 'c', 2, "0"));
    assert_close(app.model->c[2], 0.0, 0.0);
    assert_close(sim_model(app.sim)->c[2], 0.0, 0.0);
    /* Bad values change nothing and say why. */
    assert_false(app_set_element(&app, 'm', 0, "-1"));
    assert_non_null(strstr(app.message, "out of range"));
    assert_false(app_set_element(&app, 'k', 0, "1,2"));
    assert_close(app.model->m[0], 1.0, 0.0);
    char buf[64];
    app_control_value(&app, CTL_MASS, buf, sizeof buf);
    assert_string_equal(buf, "mixed kg");
    /* The modes follow the edit. */
    double f0 = app.modes[0];
    assert_true(app_set_element(&app, 'm', 0, "4"));
    assert_true(app.modes[0] < f0);
    assert_string_equal(app.message, "mass 1: m = 4 kg");
}

static void mode_marker_and_nearest(void **state)
{
    (void)state;
    char buf[64];
    app_control_value(&app, CTL_FREQUENCY, buf, sizeof buf);
    assert_null(strstr(buf, "◆")); /* 0.9 Hz is no mode of this chain */
    double t_before = sim_time(app.sim);
    double u_before = sim_end_position(app.sim);
    assert_true(app_nearest_mode(&app) & APP_CHANGED_DRIVE);
    assert_close(drive_frequency(), app.modes[2], 1e-12); /* 0.930 Hz */
    app_control_value(&app, CTL_FREQUENCY, buf, sizeof buf);
    assert_non_null(strstr(buf, "◆ f3"));
    /* Retuned without a jump of the piston. */
    assert_close(sim_end_position(app.sim), u_before, 1e-12);
    assert_close(sim_time(app.sim), t_before, 0.0);
    /* Already there: nothing to change. */
    assert_int_equal(app_nearest_mode(&app) & ~APP_CHANGED_MESSAGE, 0);
}

static void save_and_reload(void **state)
{
    (void)state;
    char dir[] = "/tmp/springsim-app-XXXXXX";
    assert_non_null(mkdtemp(dir));
    setenv("XDG_CONFIG_HOME", dir, 1);
    app_set_element(&app, 'm', 2, "1.75");
    app_set_element(&app, 'k', 0, "12.5");
    app_move_mass(&app, 0, 0.3);
    assert_int_equal(app_save(&app, "../evil", false), SAVE_BAD_NAME);
    assert_int_equal(app_save(&app, "", false), SAVE_BAD_NAME);
    assert_int_equal(app_save(&app, "a/b", false), SAVE_BAD_NAME);
    /* During a sweep, the user's frequency is saved, not the sweep's. */
    start_sweep();
    assert_int_equal(app_save(&app, "mine", false), SAVE_OK);
    assert_int_equal(app_save(&app, "mine", false), SAVE_EXISTS);
    assert_int_equal(app_save(&app, "mine", true), SAVE_OK);
    char path[512];
    snprintf(path, sizeof path, "%s/springsim/presets/mine.ini", dir);
    static struct config back;
    char err[512];
    int bad;
    config_init(&back);
    assert_int_equal(preset_load(path, &back, err, sizeof err), PRESET_OK);
    struct model *m = config_model(&back, &bad, err, sizeof err);
    assert_non_null(m);
    assert_memory_equal(m->m, app.model->m, 3 * sizeof(double));
    assert_memory_equal(m->k, app.model->k, 4 * sizeof(double));
    assert_memory_equal(m->c, app.model->c, 3 * sizeof(double));
    assert_close(m->motor.frequency, 0.9, 0.0);
    double x[3], v[3];
    config_initial(&back, m, x, v);
    assert_close(x[0], 0.3, 1e-12);
    model_free(m);
    /* And it loads back as the chain in force. */
    assert_true(app_load_preset(&app, path, "mine"));
    assert_string_equal(app.preset, "mine");
    assert_close(app.model->m[2], 1.75, 0.0);
    assert_close(sim_x(app.sim)[0], 0.3, 1e-12);
    unlink(path);
    snprintf(path, sizeof path, "%s/springsim/presets", dir);
    rmdir(path);
    snprintf(path, sizeof path, "%s/springsim", dir);
    rmdir(path);
    rmdir(dir);
    unsetenv("XDG_CONFIG_HOME");
}

static void export_csv(void **state)
{
    (void)state;
    run(150);
    app_window_step(&app, 3); /* the coarse trail on the plots: export is still fine */
    char dir[] = "/tmp/springsim-exp-XXXXXX", path[512];
    assert_non_null(mkdtemp(dir));
    assert_int_equal(app_export(&app, dir, path, sizeof path), APP_CHANGED_MESSAGE);
    FILE *f = fopen(path, "r");
    assert_non_null(f);
    char line[4096];
    for (int k = 0; k < 3; k++) { /* --meta's lines first (test_export.c reads them) */
        assert_non_null(fgets(line, sizeof line, f));
        assert_int_equal(line[0], '#');
    }
    assert_non_null(fgets(line, sizeof line, f));
    assert_string_equal(line, "t,x1,x2,x3,v1,v2,v3,a1,a2,a3,motor\n");
    int rows = 0;
    double last = -1.0;
    while (fgets(line, sizeof line, f)) {
        double t = strtod(line, NULL);
        assert_true(t > last);
        last = t;
        int commas = 0;
        for (char *p = line; *p; p++)
            commas += *p == ',';
        assert_int_equal(commas, 10);
        rows++;
    }
    fclose(f);
    assert_int_equal(rows, 151); /* t = 0 and every step */
    assert_close(last, 1.5, 1e-9);
    unlink(path);
    /* Nowhere to write: 0, and why. */
    rmdir(dir);
    assert_int_equal(app_export(&app, dir, path, sizeof path), 0);
    assert_int_equal(app.said, SAID_ERROR);
}

/* Step back, change a parameter, go on: the run continues from the earlier state and
 * the later states are gone. */
static void branch_from_history(void **state)
{
    (void)state;
    run(200);
    for (int i = 0; i < 50; i++)
        assert_true(app_back(&app));
    double t = sim_time(app.sim);
    assert_close(t, 1.5, 1e-9);
    assert_int_equal(history_count(app.hist), 150);
    /* The plots forget what came after too. */
    const double *last = trail_first(app.trail) + (size_t)(app.trail->count - 1) *
                                                      app.trail->width;
    assert_true(last[TRAIL_T] <= t + 1e-9);
    last = trail_first(app.coarse) + (size_t)(app.coarse->count - 1) * app.coarse->width;
    assert_true(last[TRAIL_T] <= t + 1e-9);
    app_adjust(&app, CTL_AMPLITUDE, 1, false);
    run(1);
    assert_close(sim_time(app.sim), 1.51, 1e-9);
    assert_int_equal(history_count(app.hist), 151);
    app.running = true;
    assert_false(app_back(&app)); /* not while running */
}

/* Stepping back across a change of frequency: the piston is where it was then, and the
 * drive goes on at the new frequency from there (no jump). */
static void back_across_retune(void **state)
{
    (void)state;
    run(100);
    double u_then = sim_end_position(app.sim);
    run(25);
    assert_true(app_set_text(&app, CTL_FREQUENCY, "2"));
    for (int i = 0; i < 25; i++)
        assert_true(app_back(&app));
    assert_close(sim_time(app.sim), 1.0, 1e-9);
    assert_close(sim_end_position(app.sim), u_then, 1e-9);
    assert_close(drive_frequency(), 2.0, 0.0);
    /* And one step on, the piston has moved as a 2 Hz drive moves in 0.01 s, no more. */
    run(1);
    assert_true(fabs(sim_end_position(app.sim) - u_then) <=
                2 * M_PI * 2.0 * app.model->motor.amplitude * 0.01 + 1e-9);
}

/* The parameters have one owner, the sim: app.model is a pointer to them through every
 * kind of change (in place, a rebuild, a preset, a step back across a retune that moved
 * the drive's phase, a reset), so no copy can lag behind it; the ghost's likewise. */
static void parameters_have_one_owner(void **state)
{
    (void)state;
    assert_ptr_equal(app.model, sim_model(app.sim));
    run(30);
    assert_true(app_set_text(&app, CTL_FREQUENCY, "1.7"));
    run(30);
    assert_ptr_equal(app.model, sim_model(app.sim));
    for (int i = 0; i < 40; i++)
        assert_true(app_back(&app));
    assert_ptr_equal(app.model, sim_model(app.sim));
    assert_true(app.model->motor.frequency == 1.7); /* the drive in force, re-anchored */
    assert_true(app_toggle_ghost(&app) & APP_CHANGED_GHOST);
    assert_ptr_equal(app.ghost->model, sim_model(app.ghost->sim));
    app_reset(&app);
    assert_ptr_equal(app.model, sim_model(app.sim));
    assert_true(app.model->motor.phase == 0.0 && app.ghost->model->motor.phase == 0.0);
    new_n();
    assert_ptr_equal(app.model, sim_model(app.sim));
    assert_int_equal(app.model->n, 5);
    preset();
    assert_ptr_equal(app.model, sim_model(app.sim));
}

/* Stepping back across a change of dt takes the dt of the state, by the change path. */
static void back_across_dt(void **state)
{
    (void)state;
    run(10);
    assert_true(app_set_text(&app, CTL_DT, "0.002"));
    run(10);
    for (int i = 0; i < 10; i++)
        assert_int_equal(app_back(&app), APP_CHANGED_STATE);
    unsigned w = app_back(&app);
    assert_int_equal(w & (APP_CHANGED_STATE | APP_CHANGED_DT), APP_CHANGED_STATE | APP_CHANGED_DT);
    assert_close(app.cfg.dt, 0.01, 0.0);
    assert_close(sim_dt(app.sim), 0.01, 0.0);
    assert_close(sim_time(app.sim), 0.09, 1e-12);
}

/* ---- the integrator and the limits of dt ---- */

/* The Integrator control cycles with the arrows and takes typed names; the sim follows,
 * the limits follow (no modes recomputed), and what dt is worth is said: unstable,
 * a mode inaccurate, the drive short of steps, the velocity cap when it acts. */
static void integrator_and_limits(void **state)
{
    (void)state;
    char buf[64];
    app_control_value(&app, CTL_INTEGRATOR, buf, sizeof buf);
    assert_string_equal(buf, "rk4");
    double rk4_limit = app.stable_dt;
    modes_calls = limit_calls = 0;
    unsigned w = app_adjust(&app, CTL_INTEGRATOR, 1, false);
    assert_int_equal(w & ~APP_CHANGED_MESSAGE, APP_CHANGED_INTEGRATOR);
    assert_int_equal(sim_integrator(app.sim), INTEGRATOR_EXACT);
    assert_true(isinf(app.stable_dt));
    assert_int_equal(modes_calls + limit_calls, 0);
    assert_true(app_adjust(&app, CTL_INTEGRATOR, 1, false)); /* round to euler */
    assert_int_equal(sim_integrator(app.sim), INTEGRATOR_EULER);
    /* Euler on the lightly damped chain at dt = 0.01: unstable, and said so. */
    assert_int_equal(app.said, SAID_WARNING);
    assert_non_null(strstr(app.message, "above the stability limit of euler"));
    assert_true(app.stable_dt < rk4_limit);
    assert_int_equal(app_set_text(&app, CTL_INTEGRATOR, "leapfrog"), 0);
    assert_non_null(strstr(app.message, "'leapfrog' is not an integrator"));
    assert_int_equal(app.cfg.integrator, INTEGRATOR_EULER);
    assert_true(app_set_text(&app, CTL_INTEGRATOR, "verlet"));
    assert_int_equal(sim_integrator(app.sim), INTEGRATOR_VERLET);
    assert_int_equal(app.said, SAID_NOTE);
    /* A new chain keeps it. */
    assert_true(new_n());
    assert_int_equal(sim_integrator(app.sim), INTEGRATOR_VERLET);
    assert_true(app_set_text(&app, CTL_INTEGRATOR, "rk4"));

    /* Ten stiff light masses at dt = 0.05: stable with rk4, but its top mode is damped
     * away; at 0.01 it is fine. */
    struct config next = app.cfg;
    next.masses = 10;
    set_list(&next.spring, 50.0);
    set_list(&next.mass, 0.1);
    set_list(&next.damping, 0.0);
    next.dt = 0.05;
    next.frequency = 0.5;
    next.x0.count = next.v0.count = 0;
    assert_int_equal(app_load_config(&next), 0);
    assert_int_equal(app.said, SAID_WARNING);
    assert_non_null(strstr(app.message, "7.05 Hz mode 82 % off in a period with rk4"));
    assert_true(app_set_text(&app, CTL_DT, "0.01"));
    assert_int_equal(app.said, SAID_NOTE);
    /* A drive too fast for dt is said when it becomes so, not at every change after. */
    assert_true(app_set_text(&app, CTL_DT, "0.014"));
    assert_int_equal(app.said, SAID_NOTE);
    assert_true(app_set_text(&app, CTL_FREQUENCY, "4.6")); /* near a mode, undamped */
    assert_int_equal(app.said, SAID_WARNING);
    assert_non_null(strstr(app.message, "motion at the 4.6 Hz drive 1.77 % off with rk4"));
    assert_true(limits_rough_drive(&app.limits));
    assert_int_equal(app_adjust(&app, CTL_FREQUENCY, 1, false), APP_CHANGED_DRIVE);
    assert_true(limits_rough_drive(&app.limits)); /* still short, and not said again */
}

/* Every time the velocity cap acts, the status says so, with the count and the first
 * time; a reset starts the count again. */
static void cap_is_reported(void **state)
{
    (void)state;
    struct config next = app.cfg;
    next.masses = 1;
    set_list(&next.spring, 1000.0);
    set_list(&next.damping, 0.0);
    set_list(&next.x0, 2.0);
    next.v0.count = 0;
    next.no_collisions = true;
    next.dt = 0.001;
    assert_int_equal(app_load_config(&next), 0);
    assert_int_equal(app.said, SAID_NOTE);
    unsigned w = 0;
    int steps = 0;
    while (!(w & APP_CHANGED_MESSAGE) && steps++ < 100)
        w = app_step(&app);
    assert_true(w & APP_CHANGED_STATE);
    assert_int_equal(app.said, SAID_CAP);
    assert_non_null(strstr(app.message, "velocity cap (50 m/s) acted 1 time, first at t = 0.014 s"));
    while (app.capped < 2 && steps++ < 1000)
        app_step(&app);
    assert_non_null(strstr(app.message, "acted 2 times, first at t = 0.014 s"));
    app_reset(&app);
    assert_int_equal(app.capped, 0);
}

int main(void)
{
#define T(f) cmocka_unit_test_setup_teardown(f, setup, teardown)
    const struct CMUnitTest tests[] = {
        T(masks_say_what_changed),
        T(arrows_move_lists_both_ways),
        T(preset_keeps_playback),
        T(element_editing),
        T(mode_marker_and_nearest),
        T(save_and_reload),
        T(export_csv),
        T(branch_from_history),
        T(back_across_retune),
        T(back_across_dt),
        T(parameters_have_one_owner),
        T(integrator_and_limits),
        T(cap_is_reported),
    };
#undef T
    return cmocka_run_group_tests_name("app", tests, NULL, NULL);
}
