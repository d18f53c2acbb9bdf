/* test_measure.c: the scope's measurements (app/measure.c) against closed forms, and its
 * cursors and scroll-back (app/scope.c) on a chain the program runs. A damped 1-DOF
 * decay x = e^(-zeta w t) cos(w_d t) has its maxima exactly 2 pi / w_d apart and each
 * e^(-2 pi zeta / sqrt(1 - zeta^2)) times the one before, so its period and logarithmic
 * decrement are known in closed form; one mass on a spring k with damping c has
 * zeta = c / (2 sqrt(k m)). Against a drive u = A cos(w t), a steady y = R cos(w t + phi)
 * has ratio R / A and phase phi exactly; one mass between a wall and the motor's spring
 * settles to X / A = k / (2k - m w^2 + i c w). The kind of motion: a decay, a steady
 * state, growth and beats told apart, and no damping ratio said for driven motion. A
 * cursor reads a recorded sample: the exported CSV's row at its time has the same
 * numbers. */
#include "testutil.h"

#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "alloc_count.h"
#include "app/app.h"
#include "app/measure.h"
#include "app/scope.h"
#include "app/scope_text.h"

#define MAXS 20000

/* Samples of e^(-zeta w t) cos(w_d t) every h seconds for span seconds, interleaved
 * (t, x) as the trail keeps records. */
static int decay(double *buf, double zeta, double w, double h, double span)
{
    double wd = w * sqrt(1.0 - zeta * zeta);
    int n = (int)(span / h) + 1;
    for (int k = 0; k < n; k++) {
        double t = k * h;
        buf[2 * k] = t;
        buf[2 * k + 1] = exp(-zeta * w * t) * cos(wd * t);
    }
    return n;
}

static void closed_form_decay(void **state)
{
    (void)state;
    static double buf[2 * MAXS];
    /* The springsim default chain's mode (0.712 Hz) and slower and faster ones, lightly
     * and more damped, sampled as the fine trail (0.01 s) and the coarse (0.02 s). */
    const double hz[] = {0.712, 0.3, 2.0};
    const double zetas[] = {0.005, 0.0112, 0.05};
    const double steps[] = {0.01, 0.02};
    for (size_t a = 0; a < 3; a++)
        for (size_t b = 0; b < 3; b++)
            for (size_t c = 0; c < 2; c++) {
                double w = 2.0 * M_PI * hz[a], z = zetas[b], h = steps[c];
                int n = decay(buf, z, w, h, 10.0);
                struct measure m;
                measure_series(&m, buf, buf + 1, n, 2);
                double wd = w * sqrt(1.0 - z * z);
                double period = 2.0 * M_PI / wd;
                double delta = 2.0 * M_PI * z / sqrt(1.0 - z * z);
                /* the maxima, where tan(w_d t) = -zeta / sqrt(1 - zeta^2), in (0, 10): but
                 * one nearest to t = 10 (the last sample, no neighbour after it) */
                double shift = atan(z / sqrt(1.0 - z * z)) / wd;
                int want = 0;
                while ((want + 1) * period - shift < 10.0 - 0.5 * h)
                    want++;
                assert_int_equal(m.peaks, want);
                assert_close(m.period, period, 0.005 * period);
                assert_close(m.frequency, 1.0 / period, 0.005 / period);
                assert_close(m.delta, delta, 0.005 * delta);
                assert_close(m.zeta, z, 0.005 * z);
            }
}

static void zeta_of_delta_inverts_delta_of_zeta(void **state)
{
    (void)state;
    for (double z = 0.001; z < 0.99; z *= 1.7) {
        double delta = 2.0 * M_PI * z / sqrt(1.0 - z * z);
        assert_close(measure_zeta(delta), z, 1e-12);
    }
}

static void sine_rms_and_peak_to_peak(void **state)
{
    (void)state;
    static double buf[2 * MAXS];
    /* 2 sin(2 pi t) over 5 whole periods at 0.01 s: rms 2 / sqrt 2, peak-to-peak 4, no
     * decay. */
    int n = 501;
    for (int k = 0; k < n; k++)
        buf[2 * k] = k * 0.01, buf[2 * k + 1] = 2.0 * sin(2.0 * M_PI * k * 0.01);
    struct measure m;
    measure_series(&m, buf, buf + 1, n, 2);
    assert_int_equal(m.peaks, 5);
    assert_close(m.p2p, 4.0, 1e-9);
    /* the sum over whole periods of sin^2 is exactly half the count but for the end
     * sample counted twice (it is 0) */
    assert_close(m.rms, 2.0 / sqrt(2.0) * sqrt((n - 1.0) / n), 1e-9);
    assert_close(m.period, 1.0, 1e-6);
    assert_close(m.delta, 0.0, 1e-6);
}

static void fewer_than_two_peaks(void **state)
{
    (void)state;
    static double buf[2 * MAXS];
    /* one hump, then a ramp, then a chain at rest */
    for (int k = 0; k < 100; k++)
        buf[2 * k] = k * 0.01, buf[2 * k + 1] = sin(M_PI * k / 99.0);
    struct measure m;
    measure_series(&m, buf, buf + 1, 100, 2);
    assert_int_equal(m.peaks, 1);
    assert_true(isnan(m.period) && isnan(m.frequency) && isnan(m.delta) && isnan(m.zeta));
    for (int k = 0; k < 100; k++)
        buf[2 * k + 1] = k;
    measure_series(&m, buf, buf + 1, 100, 2);
    assert_int_equal(m.peaks, 0);
    assert_close(m.p2p, 99.0, 0.0);
    for (int k = 0; k < 100; k++)
        buf[2 * k + 1] = 0.0;
    measure_series(&m, buf, buf + 1, 100, 2);
    assert_int_equal(m.peaks, 0);
    assert_close(m.rms, 0.0, 0.0);
    /* peaks below 0 give a period but no decrement */
    for (int k = 0; k < 500; k++)
        buf[2 * k] = k * 0.01, buf[2 * k + 1] = -3.0 + cos(2.0 * M_PI * k * 0.01);
    measure_series(&m, buf, buf + 1, 500, 2);
    assert_int_equal(m.peaks, 4);
    assert_close(m.period, 1.0, 1e-6);
    assert_true(isnan(m.delta) && isnan(m.zeta));
}

/* One mass: k = 10 N/m, m = 1 kg, c = 0.1 N s/m, released from 0.5 m, no drive. */
static void one_mass(struct app *app, const char *boundary)
{
    struct config c;
    char err[300];
    const char *const opts[] = {"masses", "1", "spring", "10", "mass", "1", "damping", "0.1",
                                "boundary", boundary, "x0", "0.5", "no-collisions", NULL,
                                NULL};
    config_init(&c);
    for (const char *const *o = opts; *o; o += 2)
        assert_int_equal(config_set(&c, config_find(o[0]), o[1], err, sizeof err), 0);
    assert_int_equal(app_init(app, &c, SRCDIR), 0);
}

static void run(struct app *app, double seconds)
{
    double end = sim_time(app->sim) + seconds;
    while (sim_time(app->sim) < end - 1e-9)
        assert_true(app_step(app) != 0);
}

/* zeta from the decrement on the window a lightly damped mass decays in, against
 * c / (2 sqrt(k_eff m)): k_eff = k with a free right end, 2k between a wall and the
 * motor's spring; and against the modes' own zeta. */
static void zeta_of_a_simulated_decay(void **state)
{
    (void)state;
    static struct app app;
    const char *ends[] = {"free", "wall"};
    const double keff[] = {10.0, 20.0};
    for (int e = 0; e < 2; e++) {
        one_mass(&app, ends[e]);
        run(&app, 20.0);
        struct scope_view v;
        scope_view(&app, &v);
        assert_close(v.end, 20.0, 1e-9);
        assert_close(v.window, 10.0, 0.0);
        struct measure m;
        scope_measure(&v, 0, &m);
        double want = 0.1 / (2.0 * sqrt(keff[e] * 1.0));
        double fd = sqrt(keff[e]) * sqrt(1.0 - want * want) / (2.0 * M_PI);
        assert_true(m.peaks >= 2);
        assert_close(m.zeta, want, 0.02 * want);
        assert_close(m.frequency, fd, 0.005 * fd);
        int j = scope_nearest_mode(&app, m.frequency);
        assert_int_equal(j, 0);
        assert_close(app.damping_ratio[j], want, 1e-9);
        app_free(&app);
    }
}

/* Samples (t, y, u) every h seconds for span seconds of u = a cos(w t) and y = y(t). */
static int driven(double *buf, double (*y)(double t), double a, double hz, double h,
                  double span)
{
    int n = (int)lround(span / h) + 1;
    for (int k = 0; k < n; k++) {
        double t = k * h;
        buf[3 * k] = t;
        buf[3 * k + 1] = y(t);
        buf[3 * k + 2] = a * cos(2.0 * M_PI * hz * t);
    }
    return n;
}

static double ratio_, phase_, hz_; /* the steady series's R, phi (rad) and f */
static double steady(double t)
{
    return ratio_ * 0.3 * cos(2.0 * M_PI * hz_ * t + phase_);
}

/* A steady y = R A cos(w t + phi) against u = A cos(w t): ratio R, phase phi, amplitude
 * R A, the drive's A, swings level, so steady. With the sample spacing dividing the
 * period the sums are over whole periods (exact to rounding); with 0.712 Hz they span
 * the whole periods to within half a sample, which leaks at most about h / (P T). */
static void driven_steady_closed_form(void **state)
{
    (void)state;
    static double buf[3 * MAXS];
    const double phases[] = {-170.0, -90.0, -5.0, 0.0, 45.0, 179.0};
    const double hzs[] = {0.5, 0.712};
    for (size_t f = 0; f < 2; f++)
        for (size_t p = 0; p < sizeof phases / sizeof *phases; p++) {
            ratio_ = 2.5, phase_ = phases[p] * M_PI / 180.0, hz_ = hzs[f];
            int n = driven(buf, steady, 0.3, hz_, 0.01, 10.0);
            struct measure m;
            struct measure_drive d;
            measure_series(&m, buf, buf + 1, n, 3);
            measure_drive(&d, buf, buf + 1, buf + 2, n, 3, hz_);
            int periods = (int)floor(10.0 * hz_ + 1e-9);
            double tol = f == 0 ? 1e-9 : 0.01 / (periods / hz_);
            assert_int_equal(d.periods, periods);
            assert_close(d.ratio, 2.5, 2.5 * tol);
            assert_close(d.amplitude, 0.75, 0.75 * tol);
            assert_close(d.drive, 0.3, 0.3 * tol);
            assert_close(d.phase, phases[p], 180.0 / M_PI * tol + 1e-9);
            assert_true(d.level < 1e-4);
            assert_int_equal(measure_motion(&m, &d), MOTION_STEADY);
        }
}

static double growing(double t)
{
    return (1.0 - exp(-t / 8.0)) * cos(2.0 * M_PI * 0.712 * t);
}

static double beats(double t)
{
    return cos(2.0 * M_PI * 0.62 * t) - cos(2.0 * M_PI * 0.712 * t);
}

static double decaying(double t)
{
    return exp(-0.05 * 2.0 * M_PI * 0.712 * t) * cos(2.0 * M_PI * 0.712 * t);
}

static double level(double t)
{
    return 0.4 * cos(2.0 * M_PI * 0.712 * t);
}

/* Growth, beats and a start-up's settling are transient, driven or not; a decay is one
 * only without a drive; free swings level within 1 % are steady; too few periods or
 * peaks tell nothing. */
static void kinds_of_motion(void **state)
{
    (void)state;
    static double buf[3 * MAXS];
    struct measure m;
    struct measure_drive d;
    struct {
        double (*y)(double);
        enum motion free_kind, driven_kind;
    } cases[] = {
        {growing, MOTION_TRANSIENT, MOTION_TRANSIENT},
        {beats, MOTION_TRANSIENT, MOTION_TRANSIENT},
        {decaying, MOTION_DECAY, MOTION_TRANSIENT},
        {level, MOTION_STEADY, MOTION_STEADY},
    };
    for (size_t c = 0; c < sizeof cases / sizeof *cases; c++) {
        int n = driven(buf, cases[c].y, 0.5, 0.712, 0.01, 10.0);
        measure_series(&m, buf, buf + 1, n, 3);
        measure_drive(&d, buf, buf + 1, buf + 2, n, 3, 0.712);
        assert_int_equal(measure_motion(&m, NULL), cases[c].free_kind);
        assert_int_equal(measure_motion(&m, &d), cases[c].driven_kind);
    }
    int n = driven(buf, growing, 0.5, 0.712, 0.01, 10.0);
    measure_series(&m, buf, buf + 1, n, 3);
    assert_true(m.rising && !m.falling);
    n = driven(buf, decaying, 0.5, 0.712, 0.01, 10.0);
    measure_series(&m, buf, buf + 1, n, 3);
    assert_true(m.falling && !m.rising && m.delta > 0.0);
    /* 2.5 s of a 0.5 Hz drive: one whole period, not enough to call it steady */
    n = driven(buf, level, 0.5, 0.5, 0.01, 2.5);
    measure_series(&m, buf, buf + 1, n, 3);
    measure_drive(&d, buf, buf + 1, buf + 2, n, 3, 0.5);
    assert_int_equal(d.periods, 1);
    assert_int_equal(measure_motion(&m, &d), MOTION_UNKNOWN);
    n = driven(buf, level, 0.5, 0.712, 0.01, 1.0);
    measure_series(&m, buf, buf + 1, n, 3);
    assert_int_equal(measure_motion(&m, NULL), MOTION_UNKNOWN);
}

/* One mass between a wall and the motor (k 10, m 1, c as given), driven at hz with
 * amplitude a from rest. */
static void one_driven(struct app *app, const char *hz, const char *a, const char *c)
{
    struct config cfg;
    char err[300];
    const char *const opts[] = {"masses", "1", "spring", "10", "mass", "1", "damping", c,
                                "frequency", hz, "amplitude", a, "no-collisions", NULL, NULL};
    config_init(&cfg);
    for (const char *const *o = opts; *o; o += 2)
        assert_int_equal(config_set(&cfg, config_find(o[0]), o[1], err, sizeof err), 0);
    assert_int_equal(app_init(app, &cfg, SRCDIR), 0);
}

/* The chain the program runs: driven at 1 Hz it settles (2m/c = 20 s) to the steady
 * state X / A = k / (2k - m w^2 + i c w), measured within 0.1 % and 0.1 degree after
 * 200 s; at resonance after 30 s (-p resonance) and beating (-p beating) it is
 * transient, and `measure` says no damping ratio for either (it said "zeta -0.0545"
 * beside the theory's 0 for the beats). */
static void driven_chain(void **state)
{
    (void)state;
    static struct app app;
    char text[1024];
    one_driven(&app, "1", "0.2", "0.1");
    run(&app, 200.0);
    struct scope_view v;
    struct scope_motion sm;
    scope_view(&app, &v);
    scope_motion(&app, &v, 0, &sm);
    double w = 2.0 * M_PI, re = 20.0 - w * w, im = 0.1 * w;
    double ratio = 10.0 / hypot(re, im), phase = -atan2(im, re) * 180.0 / M_PI;
    assert_true(sm.driven);
    assert_int_equal(sm.kind, MOTION_STEADY);
    assert_close(sm.d.ratio, ratio, 1e-3 * ratio);
    assert_close(sm.d.phase, phase, 0.1);
    assert_close(sm.theory_ratio, ratio, 1e-9 * ratio);
    assert_close(sm.theory_phase, phase, 1e-6);
    assert_true(scope_say_measure(&app, "", text, sizeof text));
    assert_non_null(strstr(text, "driven steady state"));
    assert_null(strstr(text, "zeta"));
    app_free(&app);
    const char *const set_ups[][3] = {{"0.711763", "0.1", "0.1"}, {"0.62", "0.5", "0"}};
    for (int k = 0; k < 2; k++) {
        one_driven(&app, set_ups[k][0], set_ups[k][1], set_ups[k][2]);
        run(&app, 30.0);
        scope_view(&app, &v);
        scope_motion(&app, &v, 0, &sm);
        assert_int_equal(sm.kind, MOTION_TRANSIENT);
        assert_true(scope_say_measure(&app, "", text, sizeof text));
        assert_non_null(strstr(text, "transient: not a free decay, not steady"));
        assert_null(strstr(text, "zeta"));
        app_free(&app);
    }
}

/* A force alone drives it: one mass between two walls (k 10 each side, c 0.1) shaken by
 * F = 1 N at 1 Hz. measure said it was free ("free, peaks level ... no decay to
 * measure" with the theory's zeta beside it); now it is driven by the force, its steady
 * state X / F = 1 / (2k - m w^2 + i c w) m/N measured against the force's own sine. */
static void force_driven_chain(void **state)
{
    (void)state;
    static struct app app;
    struct config cfg;
    char err[300], text[1024];
    const char *const opts[] = {"masses", "1", "spring", "10", "mass", "1", "damping", "0.1",
                                "boundary", "wall", "frequency", "1", "force", "1",
                                "force-on", "1", "no-collisions", NULL, NULL};
    config_init(&cfg);
    for (const char *const *o = opts; *o; o += 2)
        assert_int_equal(config_set(&cfg, config_find(o[0]), o[1], err, sizeof err), 0);
    assert_int_equal(app_init(&app, &cfg, SRCDIR), 0);
    run(&app, 200.0);
    struct scope_view v;
    struct scope_motion sm;
    scope_view(&app, &v);
    scope_motion(&app, &v, 0, &sm);
    double w = 2.0 * M_PI, re = 20.0 - w * w, im = 0.1 * w;
    double ratio = 1.0 / hypot(re, im), phase = -atan2(im, re) * 180.0 / M_PI;
    assert_true(sm.driven);
    assert_true(sm.by_force);
    assert_int_equal(sm.kind, MOTION_STEADY);
    assert_close(sm.d.drive, 1.0, 1e-6);
    assert_close(sm.d.ratio, ratio, 1e-3 * ratio);
    assert_close(sm.d.phase, phase, 0.1);
    assert_close(sm.theory_ratio, ratio, 1e-9 * ratio);
    assert_close(sm.theory_phase, phase, 1e-6);
    assert_true(scope_say_measure(&app, "", text, sizeof text));
    assert_non_null(strstr(text, "driven steady state"));
    assert_non_null(strstr(text, "deg to the force"));
    assert_null(strstr(text, "free"));
    assert_null(strstr(text, "zeta"));
    assert_null(strstr(text, "motor"));
    assert_null(strstr(text, "linearised"));
    app_free(&app);
}

/* A chain with a cubic spring: the theory beside the measured steady state is the chain's
 * linearised at rest, and measure says so (the duffing preset's mass at 0.8 Hz swings
 * 0.54 m on its low branch where the linear theory says 0.46 m). */
static void cubic_theory_linearised(void **state)
{
    (void)state;
    static struct app app;
    struct config cfg;
    char err[300], text[1024];
    const char *const opts[] = {"masses", "1", "spring", "10", "spring-cubic", "4,0",
                                "damping", "0.3", "frequency", "0.8", "amplitude", "0.25",
                                "no-collisions", NULL, NULL};
    config_init(&cfg);
    for (const char *const *o = opts; *o; o += 2)
        assert_int_equal(config_set(&cfg, config_find(o[0]), o[1], err, sizeof err), 0);
    assert_int_equal(app_init(&app, &cfg, SRCDIR), 0);
    run(&app, 100.0);
    struct scope_view v;
    struct scope_motion sm;
    scope_view(&app, &v);
    scope_motion(&app, &v, 0, &sm);
    assert_true(sm.linearised);
    assert_int_equal(sm.kind, MOTION_STEADY);
    assert_true(scope_say_measure(&app, "", text, sizeof text));
    assert_non_null(strstr(text, "(linearised theory at 0.8 Hz"));
    app_free(&app);
}

/* The CSV row of the export at dir whose t is t, into row (t, x, v, a, u as text). */
static bool csv_row(const char *path, double t, char fields[][40], int nf)
{
    FILE *f = fopen(path, "r");
    assert_non_null(f);
    char line[1024];
    bool found = false;
    while (!found && fgets(line, sizeof line, f)) {
        if (line[0] == 't' || atof(line) != t)
            continue;
        char *p = line;
        for (int k = 0; k < nf; k++) {
            size_t len = strcspn(p, ",\n");
            snprintf(fields[k], 40, "%.*s", (int)len, p);
            p += len + (p[len] == ',');
        }
        found = true;
    }
    fclose(f);
    return found;
}

/* Each cursor reads a recorded sample: the exported CSV's row at its time holds the same
 * numbers, to the CSV's digits. */
static void readout_is_the_export(void **state)
{
    (void)state;
    static struct app app;
    one_mass(&app, "motor");
    run(&app, 6.0);
    scope_toggle(&app, 0);
    scope_move(&app, -37);
    scope_toggle(&app, -1);
    scope_move(&app, 5);
    char dir[] = "/tmp/springsim-measure-XXXXXX", path[4200];
    assert_non_null(mkdtemp(dir));
    assert_true(app_export(&app, dir, path, sizeof path) != 0);
    struct scope_view v;
    scope_view(&app, &v);
    for (int k = 0; k < 2; k++) {
        const double *r = scope_record(&app, &v, k);
        assert_non_null(r);
        char fields[5][40], mine[40];
        assert_true(csv_row(path, r[TRAIL_T], fields, 5));
        const struct trail *tr = v.trail;
        const double want[5] = {r[TRAIL_T], r[TRAIL_X(tr, 0)], r[TRAIL_V(tr, 0)],
                                r[TRAIL_A(tr, 0)], r[TRAIL_U]};
        for (int f = 0; f < 5; f++) {
            snprintf(mine, sizeof mine, "%.12g", want[f]);
            assert_string_equal(mine, fields[f]);
        }
    }
    /* the first cursor 37 samples before the window's middle; the second came a tenth of
     * the window after it and went 5 samples on */
    double t0 = scope_record(&app, &v, 0)[TRAIL_T], t1 = scope_record(&app, &v, 1)[TRAIL_T];
    assert_close(t0, 6.0 - 5.0 - 0.37, 1e-9);
    assert_close(t1 - t0, 1.0 + 0.05, 1e-9);
    /* plain mode's cursor T reads the same sample */
    const struct trail *tr;
    assert_true(scope_at_time(&app, t0 + 0.004, &tr) == scope_record(&app, &v, 0));
    assert_null(scope_at_time(&app, 6.2, &tr));
    unlink(path);
    rmdir(dir);
    app_free(&app);
}

/* Paused, the window scrolls back through everything recorded, at least 60 s, making no
 * allocation; a cursor pushed past the left edge takes the window with it; running again
 * shows the present. */
static void scroll_back(void **state)
{
    (void)state;
    static struct app app;
    one_mass(&app, "motor");
    run(&app, 80.0);
    scope_toggle(&app, 0);
    struct scope_view v;
    long before = allocations;
    int pages = 0;
    do {
        scope_view(&app, &v);
        pages++;
    } while (scope_page(&app, -1) == APP_CHANGED_WINDOW && pages < 100);
    assert_int_equal(allocations, before);
    scope_view(&app, &v);
    assert_true(v.start <= 80.0 - 60.0);
    assert_close(v.start, scope_oldest(&app), 1e-9);
    assert_true(v.count > 0 && v.rec[TRAIL_T] >= v.start - 1e-9);
    assert_true(v.rec[(size_t)(v.count - 1) * v.trail->width + TRAIL_T] <= v.end + 1e-9);
    assert_false(v.live);
    /* back to the present a page at a time */
    while (scope_page(&app, 1) == APP_CHANGED_WINDOW)
        ;
    scope_view(&app, &v);
    assert_true(v.live);
    assert_close(v.end, 80.0, 1e-9);
    /* the cursor, from the middle, 600 samples earlier: 1 s past the left edge */
    scope_move(&app, -600);
    scope_view(&app, &v);
    assert_close(v.end, 79.0, 1e-9);
    assert_close(scope_record(&app, &v, 0)[TRAIL_T], 69.0, 1e-9);
    /* and running again jumps back to the present */
    app_set_running(&app, true);
    scope_view(&app, &v);
    assert_true(v.live);
    assert_close(app.scope.back, 0.0, 0.0);
    app_free(&app);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(closed_form_decay),
        cmocka_unit_test(zeta_of_delta_inverts_delta_of_zeta),
        cmocka_unit_test(sine_rms_and_peak_to_peak),
        cmocka_unit_test(fewer_than_two_peaks),
        cmocka_unit_test(zeta_of_a_simulated_decay),
        cmocka_unit_test(driven_steady_closed_form),
        cmocka_unit_test(kinds_of_motion),
        cmocka_unit_test(driven_chain),
        cmocka_unit_test(force_driven_chain),
        cmocka_unit_test(cubic_theory_linearised),
        cmocka_unit_test(readout_is_the_export),
        cmocka_unit_test(scroll_back),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
