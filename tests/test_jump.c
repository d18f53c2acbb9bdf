/* test_jump.c: the sweep experiment on a chain with cubic springs (src/app/jump.c): the
 * sweep turns from up to down, a jump is found where one is and not on a smooth peak, and
 * the app's sweeps of the duffing preset, up then down, jump between the same points as
 * the headless simulated sweep (sweeprun.c, what --sweep-run writes) over the same
 * frequencies, each side of the harmonic-balance folds, measure the same amplitudes, and
 * are both exported (x). */
#include "testutil.h"

#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "app/app.h"
#include "app/jump.h"
#include "core/config.h"
#include "core/preset.h"
#include "core/sim.h"
#include "core/sweeprun.h"

/* A finished sweep of one mass over lo..hi with amplitudes amp[0 .. points - 1]. */
static struct sweep *measured(double lo, double hi, const double *amp, int points)
{
    struct sweep *s = sweep_new(1, points);
    assert_non_null(s);
    sweep_start(s, lo, hi, 0.0, 0.0);
    for (int p = 0; p < points; p++)
        s->peak[p] = amp[p];
    s->index = points;
    s->active = false;
    return s;
}

static void turns_once(void **state)
{
    (void)state;
    struct sweep *run = measured(1.0, 2.0, (double[]){1, 2, 3}, 3), *up = sweep_new(1, 3);
    struct sweep *was = run;
    sweep_until_steady(run, 4.0, 40.0);
    assert_true(jump_turn(&run, &up, 7.0));
    assert_ptr_equal(up, was);
    assert_true(run->active);
    assert_int_equal(sweep_measured(run), 0);
    assert_close(run->freq[0], 2.0, 0.0);
    assert_close(run->freq[2], 1.0, 0.0);
    assert_close(run->hold, 4.0, 0.0);
    assert_close(run->most, 40.0, 0.0);
    assert_close(run->t_point, 7.0, 0.0);
    assert_close(up->peak[2], 3.0, 0.0); /* the sweep up kept */
    run->index = 3;
    assert_false(jump_turn(&run, &up, 9.0)); /* a sweep down does not turn */
    assert_ptr_equal(up, was);
    sweep_free(run);
    sweep_free(up);
}

static void finds_jumps(void **state)
{
    (void)state;
    /* Up the high branch, then down at the fold: the drop from 4 to 5. */
    struct sweep *s = measured(0.5, 1.1, (double[]){0.3, 0.5, 0.8, 1.1, 1.3, 0.3, 0.25}, 7);
    assert_int_equal(jump_find(s, 0), 4);
    assert_false(jump_rises(s, 4));
    assert_int_equal(jump_find(s, 5), -1); /* the one jump */
    sweep_free(s);
    /* A sharp but smooth peak: every step as large as its neighbours, no jump. */
    s = measured(0.5, 1.1, (double[]){0.1, 0.3, 1.0, 0.3, 0.1}, 5);
    assert_int_equal(jump_find(s, 0), -1);
    sweep_free(s);
    /* Small changes are no jump however they fall. */
    s = measured(0.5, 1.1, (double[]){1.0, 1.0, 1.2, 1.2, 1.2}, 5);
    assert_int_equal(jump_find(s, 0), -1);
    sweep_free(s);
}

/* The headless sweep over the frequencies of s from the state sim ends in, into a sweep of
 * the same points (what --sweep-run writes: each point from the last one's state). */
static struct sweep *headless(struct sim *sim, const struct sweep *s)
{
    double amp[1], phase[1];
    struct sweep *h = measured(s->freq[0], s->freq[s->points - 1],
                               (double[APP_SWEEP_POINTS]){0}, s->points);
    for (int p = 0; p < s->points; p++) {
        struct sweeprun_point r = sweeprun_point(sim, s->freq[p], amp, phase);
        assert_false(r.diverged);
        h->peak[p] = amp[0];
    }
    return h;
}

static void app_sweeps_like_headless(void **state)
{
    (void)state;
    struct config cfg;
    char err[300];
    config_init(&cfg);
    assert_int_equal(preset_load(SRCDIR "/presets/duffing.ini", &cfg, err, sizeof err),
                     PRESET_OK);
    struct app app;
    assert_int_equal(app_init(&app, &cfg, SRCDIR), 0);
    assert_true(jump_two_way(app.model));
    app_toggle_sweep(&app);
    assert_true(app.sweep->active);
    long steps = 0;
    while ((app.sweep->active || sweep_measured(app.sweep_up) == 0) && steps < 5000000) {
        app_step(&app);
        steps++;
    }
    assert_int_equal(sweep_measured(app.sweep_up), APP_SWEEP_POINTS);
    assert_int_equal(sweep_measured(app.sweep), APP_SWEEP_POINTS);
    const struct sweep *up = app.sweep_up, *down = app.sweep;
    assert_true(up->freq[0] < up->freq[APP_SWEEP_POINTS - 1]);
    assert_close(down->freq[0], up->freq[APP_SWEEP_POINTS - 1], 0.0);

    /* The headless sweep from rest over the same points, up then down. */
    int bad;
    struct model *m = config_model(&cfg, &bad, err, sizeof err);
    assert_non_null(m);
    struct sim *sim = sim_new(m, cfg.dt);
    sim_set_integrator(sim, cfg.integrator);
    struct sweep *hu = headless(sim, up), *hd = headless(sim, down);

    /* The theory's folds over the range. */
    struct jump_theory t = {0};
    assert_int_equal(jump_theory_solve(&t, m, up->freq[0], down->freq[0], err, sizeof err), 0);
    assert_int_equal(t.folds, 2);
    assert_true(t.fold_f[0] < t.fold_f[1]);

    int ku = jump_find(up, 0), kd = jump_find(down, 0);
    printf("# jumps: app up %d (%.4f..%.4f Hz), headless up %d; app down %d (%.4f..%.4f Hz), "
           "headless down %d; folds %.4f %.4f Hz\n", ku, up->freq[ku], up->freq[ku + 1],
           jump_find(hu, 0), kd, down->freq[kd], down->freq[kd + 1], jump_find(hd, 0), t.fold_f[0],
           t.fold_f[1]);
    assert_int_equal(ku, jump_find(hu, 0));
    assert_int_equal(kd, jump_find(hd, 0));
    /* Up: the high branch ends at the upper fold; down: the low one at the lower fold. */
    assert_true(up->freq[ku] <= t.fold_f[1] && t.fold_f[1] < up->freq[ku + 1]);
    assert_true(down->freq[kd] >= t.fold_f[0] && t.fold_f[0] > down->freq[kd + 1]);
    assert_false(jump_rises(up, ku));
    assert_true(jump_rises(down, kd));
    assert_int_equal(jump_find(up, ku + 1), -1);
    assert_int_equal(jump_find(down, kd + 1), -1);
    assert_true(up->peak[ku] > 2.0 * up->peak[ku + 1]);
    assert_true(down->peak[kd + 1] > 2.0 * down->peak[kd]);
    /* The same amplitudes, but for the peak's third harmonic the lock-in leaves out. */
    double worst = 0.0;
    for (int p = 0; p < APP_SWEEP_POINTS; p++) {
        worst = fmax(worst, fabs(up->peak[p] / hu->peak[p] - 1.0));
        worst = fmax(worst, fabs(down->peak[p] / hd->peak[p] - 1.0));
    }
    printf("# largest difference of the app's amplitudes from the headless ones: %.2f %%\n",
           100.0 * worst);
    assert_true(worst < 0.03);

    /* The export (x) has both sweeps, the up one first, each point once. */
    char dir[] = "/tmp/test_jump.XXXXXX", path[300], line[4096];
    assert_non_null(mkdtemp(dir));
    app_export_sweep(&app, dir, path, sizeof path);
    FILE *fp = fopen(path, "r");
    assert_non_null(fp);
    int ups = 0, downs = 0, header = 0;
    while (fgets(line, sizeof line, fp)) {
        header += strncmp(line, "frequency_hz,direction,amp1,", 28) == 0;
        if (strstr(line, ",up,"))
            assert_int_equal(downs, 0), ups++;
        downs += strstr(line, ",down,") != NULL;
    }
    fclose(fp);
    remove(path);
    rmdir(dir);
    assert_int_equal(header, 1);
    assert_int_equal(ups, APP_SWEEP_POINTS);
    assert_int_equal(downs, APP_SWEEP_POINTS);

    jump_theory_free(&t);
    sweep_free(hu);
    sweep_free(hd);
    sim_free(sim);
    model_free(m);
    app_free(&app);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(turns_once),
        cmocka_unit_test(finds_jumps),
        cmocka_unit_test(app_sweeps_like_headless),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
