/* test_export.c: what the exports say about themselves (issue 22, items 11 and 12). The
 * samples' CSV starts with --meta's lines (the version, the --headless command line of
 * the settings, what the file holds) and its message counts the rows it wrote and says
 * when the start has gone from the recording; the sweep's CSV holds each measured point
 * beside the linear theory's, which the closed form (modes_response_phase) gives
 * independently, and the --sweep command line that makes that theory. */
#include "app_fixture.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "core/modes.h"

/* The lines of file path into lines[] (at most max), each without its newline. */
static int read_lines(const char *path, char lines[][4096], int max)
{
    FILE *f = fopen(path, "r");
    assert_non_null(f);
    int n = 0;
    while (n < max && fgets(lines[n], sizeof lines[n], f)) {
        lines[n][strcspn(lines[n], "\n")] = '\0';
        n++;
    }
    fclose(f);
    return n;
}

static char lines[5200][4096];

static void samples_have_meta_lines(void **state)
{
    (void)state;
    run(150);
    char dir[] = "/tmp/springsim-exp-XXXXXX", path[512];
    assert_non_null(mkdtemp(dir));
    assert_int_equal(app_export(&app, dir, path, sizeof path), APP_CHANGED_MESSAGE);
    int n = read_lines(path, lines, 5200);
    assert_int_equal(n, 3 + 1 + 151);
    assert_string_equal(lines[0], "# springsim " VERSION);
    assert_non_null(strstr(lines[1], "# springsim --headless --sample 0.01 --masses 3 "));
    assert_non_null(strstr(lines[1], " --frequency 0.9 "));
    assert_non_null(strstr(lines[1], " --duration 1.5 "));
    assert_non_null(strstr(lines[2], "at t = 1.50 s: 151 rows from t = 0.00 s, every 0.01 s"));
    assert_null(strstr(lines[2], "keeps the last"));
    assert_string_equal(lines[3], "t,x1,x2,x3,v1,v2,v3,a1,a2,a3,motor");
    /* The message counts what was written. */
    assert_non_null(strstr(app.message, "exported 151 rows (t = 0 to 1.50 s) to "));
    unlink(path);
    rmdir(dir);
}

/* Past the recording's 4400 samples the start is gone: the message and the file say so. */
static void samples_say_what_is_kept(void **state)
{
    (void)state;
    run(5000); /* 5001 samples, t = 0 to 50 s */
    char dir[] = "/tmp/springsim-exp-XXXXXX", path[512];
    assert_non_null(mkdtemp(dir));
    assert_int_equal(app_export(&app, dir, path, sizeof path), APP_CHANGED_MESSAGE);
    assert_int_equal(app.trail->capacity, 4400);
    assert_non_null(strstr(app.message, "exported 4400 rows, the last 43.99 s (t = 6.01 to "
                                        "50.00 s) to "));
    int n = read_lines(path, lines, 5200);
    assert_int_equal(n, 3 + 1 + 4400);
    assert_non_null(strstr(lines[2], ": 4400 rows from t = 6.01 s, every 0.01 s (the recording "
                                     "keeps the last 4400 samples)"));
    assert_close(strtod(lines[4], NULL), 6.01, 1e-9);
    assert_close(strtod(lines[n - 1], NULL), 50.0, 1e-9);
    unlink(path);
    rmdir(dir);
}

/* Starts the app's sweep and steps it to its end: every point measured. */
static void sweep_to_its_end(void)
{
    start_sweep();
    int steps = 0;
    while (app.sweep->active && steps++ < 200000)
        app_step(&app);
    assert_int_equal(sweep_measured(app.sweep), APP_SWEEP_POINTS);
}

/* A sweep run to its end (stiff, well damped: points settle fast), written out: every
 * point measured, each beside the closed form's amplitude and phase. */
static void sweep_points_beside_the_theory(void **state)
{
    (void)state;
    char dir[] = "/tmp/springsim-exp-XXXXXX", path[512];
    assert_non_null(mkdtemp(dir));
    /* Nothing measured yet: said, nothing written. */
    assert_int_equal(app_export_sweep(&app, dir, path, sizeof path), APP_CHANGED_MESSAGE);
    assert_int_equal(app.said, SAID_ERROR);
    assert_non_null(strstr(app.message, "no sweep measured yet"));
    assert_true(app_set_text(&app, CTL_SPRING, "50"));
    assert_true(app_set_text(&app, CTL_DAMPING, "5"));
    sweep_to_its_end();
    assert_int_equal(app_export_sweep(&app, dir, path, sizeof path), APP_CHANGED_MESSAGE);
    assert_int_equal(app.said, SAID_NOTE);
    assert_non_null(strstr(app.message, "exported the sweep's 40 points beside the theory to "));
    assert_non_null(strstr(path, "/springsim-sweep-"));
    int n = read_lines(path, lines, 5200);
    assert_int_equal(n, 3 + 1 + APP_SWEEP_POINTS);
    assert_string_equal(lines[0], "# springsim " VERSION);
    /* the --sweep line over the same frequencies, given exactly */
    double lo = 0.0, hi = 0.0;
    int points = 0;
    assert_int_equal(sscanf(lines[1], "# springsim --sweep %lf:%lf:%d --masses 3 ", &lo, &hi,
                            &points), 3);
    assert_true(lo == app.sweep->freq[0] && hi == app.sweep->freq[APP_SWEEP_POINTS - 1]);
    assert_int_equal(points, APP_SWEEP_POINTS);
    assert_non_null(strstr(lines[1], " --frequency 0.9 ")); /* the user's, not the sweep's */
    assert_non_null(strstr(lines[2], "# measured by springsim's sweep experiment: "));
    assert_string_equal(lines[3], "frequency_hz,amp1,amp2,amp3,phase1,phase2,phase3,theory_amp1,"
                                  "theory_amp2,theory_amp3,theory_phase1,theory_phase2,"
                                  "theory_phase3");
    double amp[3], ph[3];
    for (int p = 0; p < APP_SWEEP_POINTS; p++) {
        double v[13];
        char *s = lines[4 + p];
        for (int k = 0; k < 13; k++) {
            char *end;
            v[k] = strtod(s, &end);
            assert_true(end != s);
            s = *end == ',' ? end + 1 : end;
        }
        assert_close(v[0], app.sweep->freq[p], 1e-9 * v[0]);
        assert_int_equal(modes_response_phase(app.model, v[0], amp, ph), 0);
        for (int i = 0; i < 3; i++) {
            assert_close(v[1 + i], app.sweep->peak[p * 3 + i], 1e-9 * v[1 + i]);
            assert_close(v[7 + i], amp[i], 1e-9 * amp[i]);
            assert_close(v[10 + i], ph[i], 1e-8);
            /* measured beside the theory: the experiment agrees with it (2 %, 3 degrees) */
            assert_close(v[1 + i], amp[i], 0.02 * amp[i]);
            double d = fmod(fabs(v[4 + i] - ph[i]), 360.0);
            assert_true(fmin(d, 360.0 - d) < 3.0);
        }
    }
    unlink(path);
    rmdir(dir);
}

/* A force is a drive: a chain with a free right end and a force on a mass has its theory
 * (modes_response_phase with the force), and its sweep is exported beside it; with the
 * force taken off nothing drives, and that is said. */
static void force_is_a_drive_for_the_sweep(void **state)
{
    (void)state;
    char dir[] = "/tmp/springsim-exp-XXXXXX", path[512];
    assert_non_null(mkdtemp(dir));
    assert_true(app_set_text(&app, CTL_DAMPING, "5"));
    sweep_to_its_end();
    assert_true(app_set_text(&app, CTL_BOUNDARY, "free"));
    assert_true(app_set_text(&app, CTL_FORCE, "0.5"));
    assert_int_equal(sweep_measured(app.sweep), APP_SWEEP_POINTS);
    assert_int_equal(app_export_sweep(&app, dir, path, sizeof path), APP_CHANGED_MESSAGE);
    assert_int_equal(app.said, SAID_NOTE);
    assert_non_null(strstr(app.message, "exported the sweep's 40 points beside the theory to "));
    int n = read_lines(path, lines, 5200);
    assert_int_equal(n, 3 + 1 + APP_SWEEP_POINTS);
    unlink(path);
    assert_true(app_set_text(&app, CTL_FORCE, "0"));
    assert_int_equal(app_export_sweep(&app, dir, path, sizeof path), APP_CHANGED_MESSAGE);
    assert_int_equal(app.said, SAID_ERROR);
    assert_non_null(strstr(app.message, "no drive"));
    rmdir(dir);
}

int main(void)
{
#define T(f) cmocka_unit_test_setup_teardown(f, setup, teardown)
    const struct CMUnitTest tests[] = {
        T(samples_have_meta_lines),
        T(samples_say_what_is_kept),
        T(sweep_points_beside_the_theory),
        T(force_is_a_drive_for_the_sweep),
    };
#undef T
    return cmocka_run_group_tests_name("export", tests, NULL, NULL);
}
