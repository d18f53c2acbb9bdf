/* test_app.c: the interactive program's actions without a terminal: per-element
 * editing, the frequency control's mode marker and the nearest-mode key, a saved
 * preset that reloads to the same chain, export in the --headless CSV format, and
 * branching from history. */
#include "testutil.h"

#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "core/preset.h"
#include "app/app.h"

static struct app app;
static struct config cfg;

static int setup(void **state)
{
    (void)state;
    config_init(&cfg);
    cfg.masses = 3;
    cfg.frequency = 0.9;
    return app_init(&app, &cfg, SRCDIR);
}

static int teardown(void **state)
{
    (void)state;
    app_free(&app);
    return 0;
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
    app_set_element(&app, 'm', 0, "4");
    assert_true(app.modes[0] < f0);
}

static void mode_marker_and_nearest(void **state)
{
    (void)state;
    char buf[64];
    app_control_value(&app, CTL_FREQUENCY, buf, sizeof buf);
    assert_null(strstr(buf, "◆")); /* 0.9 Hz is no mode of this chain */
    double t_before = sim_time(app.sim);
    double u_before = sim_end_position(app.sim);
    app_nearest_mode(&app);
    assert_close(app.model->motor.frequency, app.modes[2], 1e-12); /* 0.930 Hz */
    app_control_value(&app, CTL_FREQUENCY, buf, sizeof buf);
    assert_non_null(strstr(buf, "◆ f3"));
    /* Retuned without a jump of the piston. */
    assert_close(sim_end_position(app.sim), u_before, 1e-12);
    assert_close(sim_time(app.sim), t_before, 0.0);
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
    double x[3], v[3];
    config_initial(&back, m, x, v);
    assert_close(x[0], 0.3, 1e-12);
    model_free(m);
    unlink(path);
    snprintf(path, sizeof path, "%s/springsim/presets", dir);
    rmdir(path);
    snprintf(path, sizeof path, "%s/springsim", dir);
    rmdir(path);
    rmdir(dir);
}

static void export_csv(void **state)
{
    (void)state;
    app_reset(&app);
    for (int i = 0; i < 150; i++)
        app_step(&app);
    char dir[] = "/tmp/springsim-exp-XXXXXX", path[512];
    assert_non_null(mkdtemp(dir));
    assert_true(app_export(&app, dir, path, sizeof path));
    FILE *f = fopen(path, "r");
    assert_non_null(f);
    char line[4096];
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
    rmdir(dir);
}

/* Step back, change a parameter, go on: the run continues from the earlier state and
 * the later states are gone. */
static void branch_from_history(void **state)
{
    (void)state;
    app_reset(&app);
    for (int i = 0; i < 200; i++)
        app_step(&app);
    for (int i = 0; i < 50; i++)
        assert_true(app_back(&app));
    double t = sim_time(app.sim);
    assert_close(t, 1.5, 1e-9);
    assert_int_equal(history_count(app.hist), 150);
    /* The plots forget what came after too. */
    const double *last = trail_first(app.trail) + (size_t)(app.trail->count - 1) *
                                                      app.trail->width;
    assert_true(last[TRAIL_T] <= t + 1e-9);
    app_adjust(&app, CTL_AMPLITUDE, 1, false);
    app_step(&app);
    assert_close(sim_time(app.sim), 1.51, 1e-9);
    assert_int_equal(history_count(app.hist), 151);
    app.running = true;
    assert_false(app_back(&app)); /* not while running */
    app.running = false;
}

/* Stepping back across a change of frequency: the piston is where it was then, and the
 * drive goes on at the new frequency from there (no jump). */
static void back_across_retune(void **state)
{
    (void)state;
    app_reset(&app);
    for (int i = 0; i < 100; i++)
        app_step(&app);
    double u_then = sim_end_position(app.sim);
    for (int i = 0; i < 25; i++)
        app_step(&app);
    assert_true(app_set_text(&app, CTL_FREQUENCY, "2"));
    for (int i = 0; i < 25; i++)
        assert_true(app_back(&app));
    assert_close(sim_time(app.sim), 1.0, 1e-9);
    assert_close(sim_end_position(app.sim), u_then, 1e-9);
    assert_close(app.model->motor.frequency, 2.0, 0.0);
    /* And one step on, the piston has moved as a 2 Hz drive moves in 0.01 s, no more. */
    app_step(&app);
    assert_true(fabs(sim_end_position(app.sim) - u_then) <=
                2 * M_PI * 2.0 * app.model->motor.amplitude * 0.01 + 1e-9);
}

/* Anything that rebuilds the chain ends a sweep and gives the drive back. */
static void sweep_ends_with_the_chain(void **state)
{
    (void)state;
    app_reset(&app);
    double f = app.model->motor.frequency;
    app_toggle_sweep(&app);
    assert_true(app.sweep->active);
    assert_true(app.model->motor.frequency != f);
    app.masses_pending = 2;
    app_apply_masses(&app);
    assert_false(app.sweep->active);
    assert_close(app.model->motor.frequency, f, 0.0);
    assert_close(app.cfg.frequency, f, 0.0);
    app_toggle_sweep(&app);
    app_adjust(&app, CTL_BOUNDARY, 1, false); /* to wall: no drive to sweep */
    assert_false(app.sweep->active);
    assert_close(app.model->motor.frequency, f, 0.0);
    app_adjust(&app, CTL_BOUNDARY, -1, false);
    app.running = false;
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(element_editing),
        cmocka_unit_test(mode_marker_and_nearest),
        cmocka_unit_test(save_and_reload),
        cmocka_unit_test(export_csv),
        cmocka_unit_test(branch_from_history),
        cmocka_unit_test(back_across_retune),
        cmocka_unit_test(sweep_ends_with_the_chain),
    };
    return cmocka_run_group_tests_name("app", tests, setup, teardown);
}
