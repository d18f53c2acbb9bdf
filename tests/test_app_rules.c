/* test_app_rules.c: the app's rules on every route of a change. A running sweep ends
 * when the chain or the drive's frequency changes, however it changes, and gives the
 * user's frequency back, but goes on through its own retunes and ends by itself; the
 * modes are computed once per change; a new chain is built whole or not at all (the
 * allocations are made to fail one by one, through tests/app_fixture.c); a refused input
 * or preset changes nothing; a random start says its seed. Every test starts from its own
 * fresh app. */
#include "app_fixture.h"

#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "core/limits.h"
#include "app/sweeping.h"
#include "core/modes.h"

/* Everything a refused change must leave as it was. */
struct snapshot {
    struct config cfg;     /* byte for byte */
    const struct model *model; /* the same objects */
    struct sim *sim;
    struct history *hist;
    struct trail *trail, *coarse;
    struct sweep *sweep;
    int n;
    double m[APP_MAX_MASSES], k[APP_MAX_MASSES + 1], c[APP_MAX_MASSES];
    struct motor motor;
    enum boundary boundary;
    double t, x[APP_MAX_MASSES], v[APP_MAX_MASSES], u;
    int hist_count, trail_count, coarse_count;
    unsigned version;
    bool sweeping, running;
    double stable_dt, mode1;
};

static void take(struct snapshot *s)
{
    int n = app.model->n;
    memcpy(&s->cfg, &app.cfg, sizeof s->cfg);
    s->model = app.model;
    s->sim = app.sim;
    s->hist = app.hist;
    s->trail = app.trail;
    s->coarse = app.coarse;
    s->sweep = app.sweep;
    s->n = n;
    memcpy(s->m, app.model->m, (size_t)n * sizeof *s->m);
    memcpy(s->k, app.model->k, (size_t)(n + 1) * sizeof *s->k);
    memcpy(s->c, app.model->c, (size_t)n * sizeof *s->c);
    s->motor = app.model->motor;
    s->boundary = app.model->boundary;
    s->t = sim_time(app.sim);
    memcpy(s->x, sim_x(app.sim), (size_t)n * sizeof *s->x);
    memcpy(s->v, sim_v(app.sim), (size_t)n * sizeof *s->v);
    s->u = sim_end_position(app.sim);
    s->hist_count = history_count(app.hist);
    s->trail_count = app.trail->count;
    s->coarse_count = app.coarse->count;
    s->version = app.version;
    s->sweeping = app.sweep->active;
    s->running = app.running;
    s->stable_dt = app.stable_dt;
    s->mode1 = app.modes[0];
}

/* Fails unless the app is as it was at s. */
static void unchanged(const struct snapshot *s)
{
    struct snapshot now;
    take(&now);
    assert_memory_equal(&now.cfg, &s->cfg, sizeof s->cfg);
    assert_ptr_equal(now.model, s->model);
    assert_ptr_equal(now.sim, s->sim);
    assert_ptr_equal(now.hist, s->hist);
    assert_ptr_equal(now.trail, s->trail);
    assert_ptr_equal(now.coarse, s->coarse);
    assert_ptr_equal(now.sweep, s->sweep);
    assert_int_equal(now.n, s->n);
    assert_memory_equal(now.m, s->m, (size_t)s->n * sizeof *s->m);
    assert_memory_equal(now.k, s->k, (size_t)(s->n + 1) * sizeof *s->k);
    assert_memory_equal(now.c, s->c, (size_t)s->n * sizeof *s->c);
    assert_memory_equal(&now.motor, &s->motor, sizeof s->motor);
    assert_memory_equal(&sim_model(app.sim)->motor, &s->motor, sizeof s->motor);
    assert_int_equal(now.boundary, s->boundary);
    assert_true(now.t == s->t && now.u == s->u);
    assert_memory_equal(now.x, s->x, (size_t)s->n * sizeof *s->x);
    assert_memory_equal(now.v, s->v, (size_t)s->n * sizeof *s->v);
    assert_int_equal(now.hist_count, s->hist_count);
    assert_int_equal(now.trail_count, s->trail_count);
    assert_int_equal(now.coarse_count, s->coarse_count);
    assert_int_equal(now.version, s->version);
    assert_int_equal(now.sweeping, s->sweeping);
    assert_int_equal(now.running, s->running);
    assert_true(now.stable_dt == s->stable_dt && now.mode1 == s->mode1);
}

/* ---- the sweep ends on every route of a change of the chain or the frequency ---- */

static unsigned freq_fine_up(void) { return app_adjust(&app, CTL_FREQUENCY, 1, false); }
static unsigned freq_fine_down(void) { return app_adjust(&app, CTL_FREQUENCY, -1, false); }
static unsigned freq_coarse_up(void) { return app_adjust(&app, CTL_FREQUENCY, 1, true); }
static unsigned freq_coarse_down(void) { return app_adjust(&app, CTL_FREQUENCY, -1, true); }
static unsigned freq_typed(void) { return app_set_text(&app, CTL_FREQUENCY, "2.5"); }
static unsigned freq_typed_same(void)
{
    char text[32];
    snprintf(text, sizeof text, "%.17g", app.model->motor.frequency);
    return app_set_text(&app, CTL_FREQUENCY, text);
}
static unsigned nearest(void) { return app_nearest_mode(&app); }
static unsigned wave(void) { return app_adjust(&app, CTL_WAVE, 1, false); }
static unsigned wave_typed(void) { return app_set_text(&app, CTL_WAVE, "square"); }
static unsigned amplitude(void) { return app_adjust(&app, CTL_AMPLITUDE, 1, false); }
static unsigned amplitude_typed(void) { return app_set_text(&app, CTL_AMPLITUDE, "0.3"); }
static unsigned boundary(void) { return app_adjust(&app, CTL_BOUNDARY, 1, false); }
static unsigned boundary_typed(void) { return app_set_text(&app, CTL_BOUNDARY, "free"); }
static unsigned spring(void) { return app_adjust(&app, CTL_SPRING, 1, true); }
static unsigned mass_typed(void) { return app_set_text(&app, CTL_MASS, "2"); }
static unsigned damping(void) { return app_adjust(&app, CTL_DAMPING, -1, false); }
static unsigned element(void) { return app_set_element(&app, 'k', 0, "12"); }
static unsigned element_mass(void) { return app_set_element(&app, 'm', 2, "0.5"); }
static unsigned n_typed(void) { return app_set_text(&app, CTL_MASSES, "4"); }
static unsigned reset(void) { return app_reset(&app); }
static unsigned user_stop(void) { return app_toggle_sweep(&app); }

/* The frequency the arrows give: the value shown snapped onto the step grid, moved. */
static double arrow(double step, int dir)
{
    double f = app.model->motor.frequency;
    return fmin(fmax(round(f / step) * step + dir * step, APP_FMIN), APP_FMAX);
}
static double want_fine_up(void) { return arrow(0.01, 1); }
static double want_fine_down(void) { return arrow(0.01, -1); }
static double want_coarse_up(void) { return arrow(0.1, 1); }
static double want_coarse_down(void) { return arrow(0.1, -1); }
static double want_typed(void) { return 2.5; }
static double want_same(void) { return app.model->motor.frequency; }
static double want_nearest(void)
{
    return app.modes[modes_nearest(app.modes, app.model->n, app.model->motor.frequency)];
}
static double want_preset(void) { return 0.711763; }

static const struct route {
    const char *name;
    unsigned (*act)(void);
    double (*want)(void); /* the frequency after, NULL: the user's, given back */
    bool chain;           /* the chain changes: its modes are computed (once) */
} routes[] = {
    {"arrow: frequency up", freq_fine_up, want_fine_up, false},
    {"arrow: frequency down", freq_fine_down, want_fine_down, false},
    {"coarse arrow: frequency up", freq_coarse_up, want_coarse_up, false},
    {"coarse arrow: frequency down", freq_coarse_down, want_coarse_down, false},
    {"typed frequency", freq_typed, want_typed, false},
    {"typed the sweep's own frequency", freq_typed_same, want_same, false},
    {"nearest mode", nearest, want_nearest, false},
    {"arrow: waveform", wave, NULL, false},
    {"typed waveform", wave_typed, NULL, false},
    {"arrow: amplitude", amplitude, NULL, false},
    {"typed amplitude", amplitude_typed, NULL, false},
    {"arrow: right end", boundary, NULL, true},
    {"typed right end", boundary_typed, NULL, true},
    {"coarse arrow: springs", spring, NULL, true},
    {"typed masses' mass", mass_typed, NULL, true},
    {"arrow: damping", damping, NULL, true},
    {"one spring typed", element, NULL, true},
    {"one mass typed", element_mass, NULL, true},
    {"new N applied", new_n, NULL, true},
    {"typed N", n_typed, NULL, true},
    {"preset loaded", preset, want_preset, true},
    {"reset", reset, NULL, false},
    {"w again", user_stop, NULL, false},
};

static void sweep_ends_on_every_route(void **state)
{
    (void)state;
    for (size_t r = 0; r < sizeof routes / sizeof *routes; r++) {
        const struct route *rt = &routes[r];
        /* A fresh app for each route. */
        app_free(&app);
        assert_int_equal(app_init(&app, &cfg, SRCDIR), 0);
        double user = app.model->motor.frequency;
        run(10);
        start_sweep();
        run(10);
        double want = rt->want ? rt->want() : user;
        unsigned version = app.version;
        modes_calls = limit_calls = 0;
        unsigned what = rt->act();
        if (app.sweep->active)
            fail_msg("%s: the sweep goes on", rt->name);
        if (drive_frequency() != want)
            fail_msg("%s: driving at %.15g Hz, expected %.15g", rt->name, drive_frequency(), want);
        if (!(what & APP_CHANGED_DRIVE))
            fail_msg("%s: returned %#x, without APP_CHANGED_DRIVE", rt->name, what);
        if (modes_calls != rt->chain || limit_calls != rt->chain)
            fail_msg("%s: modes computed %d times, the limit %d times, expected %d", rt->name,
                     modes_calls, limit_calls, rt->chain);
        if (app.version != version + 1)
            fail_msg("%s: version moved by %u, expected 1", rt->name, app.version - version);
        /* And the chain goes on from there. */
        assert_true(app_step(&app));
    }
}

/* The sweep retunes the drive by the same path, without ending itself; the time step,
 * the speed and the window are no change of the chain or the drive. */
static void sweep_survives_its_own_retunes(void **state)
{
    (void)state;
    double user = app.model->motor.frequency;
    start_sweep();
    double first = drive_frequency();
    unsigned version = app.version, what = 0;
    int steps = 0;
    while (drive_frequency() == first && steps++ < 20000)
        what = app_step(&app);
    assert_true(drive_frequency() > first); /* the second point */
    assert_true(app.sweep->active);
    assert_int_equal(app.sweep->index, 1);
    assert_close(app.sweep_from, user, 0.0);
    assert_int_equal(what & (APP_CHANGED_DRIVE | APP_CHANGED_CHAIN | APP_CHANGED_SIZE),
                     APP_CHANGED_DRIVE);
    assert_int_equal(app.version, version + 1);
    assert_int_equal(modes_calls, 0);
    double f = drive_frequency();
    assert_int_equal(app_adjust(&app, CTL_DT, 1, false) & ~APP_CHANGED_MESSAGE, APP_CHANGED_DT);
    assert_true(app_adjust(&app, CTL_SPEED, 1, false) & APP_CHANGED_PLAYBACK);
    assert_true(app_window_step(&app, 1) & APP_CHANGED_WINDOW);
    assert_true(app_step(&app) & APP_CHANGED_STATE);
    assert_true(app_back(&app) & APP_CHANGED_STATE);
    assert_true(app.sweep->active);
    assert_close(drive_frequency(), f, 0.0);
    /* A refused frequency is no change either. */
    assert_int_equal(app_set_text(&app, CTL_FREQUENCY, "fast"), 0);
    assert_true(app.sweep->active);
}

/* Run to the end, the sweep gives the drive back by itself. */
static void sweep_done_gives_the_drive_back(void **state)
{
    (void)state;
    /* Stiff springs and strong damping: points settle fast. */
    assert_true(app_set_text(&app, CTL_SPRING, "50"));
    assert_true(app_set_text(&app, CTL_DAMPING, "5"));
    double user = drive_frequency();
    start_sweep();
    unsigned what = 0;
    int steps = 0;
    while (app.sweep->active && steps++ < 200000)
        what = app_step(&app);
    assert_false(app.sweep->active);
    assert_int_equal(sweep_measured(app.sweep), APP_SWEEP_POINTS);
    assert_close(drive_frequency(), user, 0.0);
    assert_true(what & APP_CHANGED_DRIVE);
    assert_true(what & APP_CHANGED_MESSAGE);
    assert_non_null(strstr(app.message, "sweep done"));
}

/* The sweep's plan for the fixture's chain (three masses, 1 kg, c = 0.1: every mode
 * decays as exp(-c t / 2m)): a point holds level for 2m/c = 20 s, at most ten times
 * that; 1 % below the amplitude from which contacts are expected the sweep just starts,
 * 1 % above it it starts with a warning that says that amplitude. */
static void sweep_warns_of_contacts(void **state)
{
    (void)state;
    struct sweep_plan plan;
    char why[200];
    assert_int_equal(sweeping_plan(&app, &plan, why, sizeof why), 0);
    assert_close(plan.hold, 2.0 * 1.0 / 0.1, 1e-9);
    assert_close(plan.most, 10.0 * plan.hold, 1e-9);
    assert_close(plan.lo, 0.5 * app.modes[0], 0.0);
    assert_close(plan.hi, 1.5 * app.modes[2], 0.0);
    assert_true(plan.contact > app.model->motor.amplitude && isfinite(plan.contact));
    char text[32], want[96];
    snprintf(text, sizeof text, "%.17g", 0.99 * plan.contact);
    assert_true(app_set_text(&app, CTL_AMPLITUDE, text));
    assert_true(app_toggle_sweep(&app) & APP_CHANGED_MESSAGE);
    assert_true(app.sweep->active);
    assert_int_equal(app.said, SAID_NOTE);
    assert_non_null(strstr(app.message, "sweeping "));
    assert_null(strstr(app.message, "contact"));
    app_toggle_sweep(&app);
    snprintf(text, sizeof text, "%.17g", 1.01 * plan.contact);
    assert_true(app_set_text(&app, CTL_AMPLITUDE, text));
    assert_true(app_toggle_sweep(&app) & APP_CHANGED_MESSAGE);
    assert_true(app.sweep->active);
    assert_int_equal(app.said, SAID_WARNING);
    snprintf(want, sizeof want, "contacts expected above %.2g m: lower the amplitude",
             plan.contact);
    assert_non_null(strstr(app.message, want));
    /* A chain neither the motor nor a force drives has no plan. */
    app_toggle_sweep(&app);
    assert_true(app_set_text(&app, CTL_BOUNDARY, "wall"));
    assert_int_equal(sweeping_plan(&app, &plan, why, sizeof why), -1);
    assert_non_null(strstr(why, "needs a drive: the motor at the right end, or a force"));
}

/* ---- once per change ---- */

static void modes_once_per_change(void **state)
{
    (void)state;
    struct {
        const char *name;
        unsigned (*act)(void);
        int modes;    /* times the modes (and the limit) are computed */
        int versions; /* steps of the version counter */
    } cases[] = {
        {"arrow: frequency", freq_fine_up, 0, 1}, {"typed frequency", freq_typed, 0, 1},
        {"nearest mode", nearest, 0, 1},          {"waveform", wave, 0, 1},
        {"amplitude", amplitude, 0, 1},           {"right end", boundary, 1, 1},
        {"springs", spring, 1, 1},                {"one spring", element, 1, 1},
        {"new N", new_n, 1, 1},                   {"preset", preset, 1, 1},
        {"reset", reset, 0, 0},
    };
    for (size_t i = 0; i < sizeof cases / sizeof *cases; i++) {
        unsigned version = app.version;
        modes_calls = limit_calls = 0;
        assert_true(cases[i].act());
        if (modes_calls != cases[i].modes || limit_calls != cases[i].modes)
            fail_msg("%s: modes computed %d times, the limit %d times, expected %d",
                     cases[i].name, modes_calls, limit_calls, cases[i].modes);
        if (app.version - version != (unsigned)cases[i].versions)
            fail_msg("%s: version moved by %u, expected %d", cases[i].name,
                     app.version - version, cases[i].versions);
    }
    /* The modes are those of the chain in force. */
    double f[APP_MAX_MASSES], shapes[APP_MAX_MASSES * APP_MAX_MASSES];
    assert_int_equal(modes_compute(app.model, f, shapes), 0);
    assert_memory_equal(f, app.modes, (size_t)app.model->n * sizeof *f);
    struct limits_mode lm[APP_MAX_MASSES];
    assert_int_equal(limits_modes(app.model, lm), 0);
    assert_close(app.stable_dt, limits_stable_dt(app.model, lm, app.model->n, app.cfg.integrator), 0.0);
}

/* ---- all or nothing ---- */

/* Fails the 1st, 2nd, ... allocation of a rebuild until none is left to fail: after
 * each failure the old chain is all there and runs on. Returns the failures seen. */
static int rebuild_failing(unsigned (*rebuild)(void), int n_after)
{
    int k;
    for (k = 1; k < 50; k++) {
        struct snapshot before;
        take(&before);
        fail_allocation(k);
        unsigned what = rebuild();
        fail_allocation(0);
        if (what) {
            assert_int_equal(app.model->n, n_after);
            assert_int_equal(sim_model(app.sim)->n, n_after);
            assert_int_equal(app.trail->n, n_after);
            assert_int_equal(app.coarse->n, n_after);
            assert_int_equal(app.sweep->n, n_after);
            assert_false(app.sweep->active);
            run(5);
            return k - 1;
        }
        unchanged(&before);
        assert_int_equal(app.said, SAID_ERROR);
        assert_non_null(strstr(app.message, "out of memory"));
        /* Still a working chain: a step forward, a step back, and the sweep goes on. */
        assert_true(app_step(&app));
        assert_int_equal(history_count(app.hist), before.hist_count + 1);
        assert_true(app.sweep->active);
        assert_true(app_back(&app));
    }
    fail_msg("the rebuild never succeeded");
    return 0;
}

static void failed_rebuild_keeps_the_old_chain(void **state)
{
    (void)state;
    assert_true(app_set_element(&app, 'm', 1, "2.5")); /* something to lose */
    run(100);
    start_sweep();
    run(10);
    /* model, sim, history, two trails and a sweep: each can fail. */
    assert_true(rebuild_failing(new_n, 5) >= 6);
    start_sweep();
    assert_true(rebuild_failing(preset, 3) >= 6);
    /* A change in place needs a model too. */
    start_sweep();
    struct snapshot before;
    take(&before);
    fail_allocation(1);
    assert_int_equal(freq_typed(), 0);
    fail_allocation(0);
    unchanged(&before);
}

static void failed_init_leaves_nothing(void **state)
{
    (void)state;
    struct app a;
    int k;
    for (k = 1; k < 50; k++) {
        fail_allocation(k);
        int e = app_init(&a, &cfg, SRCDIR);
        fail_allocation(0);
        app_free(&a); /* nothing leaks: the sanitizer build checks */
        if (e == 0)
            break;
        assert_int_equal(e, -1);
        assert_null(a.model);
        assert_null(a.sim);
    }
    assert_true(k >= 7 && k < 50);
}

static void refused_input_changes_nothing(void **state)
{
    (void)state;
    static const struct {
        enum control ctl;
        const char *text;
    } bad[] = {
        {CTL_FREQUENCY, "abc"}, {CTL_FREQUENCY, "-1"},   {CTL_FREQUENCY, "0"},
        {CTL_MASSES, "0"},      {CTL_MASSES, "12"},      {CTL_MASSES, "2.5"},
        {CTL_DT, "0.0005"},     {CTL_DT, "1"},           {CTL_MASS, "1,2"},
        {CTL_SPRING, "-3"},     {CTL_AMPLITUDE, "x"},    {CTL_BOUNDARY, "sideways"},
        {CTL_WAVE, "zigzag"},   {CTL_SPEED, "11"},       {CTL_BANDWIDTH, "huge"},
        {CTL_PRESET, "resonance"},
    };
    run(20);
    start_sweep(); /* and a refusal does not end it */
    for (size_t i = 0; i < sizeof bad / sizeof *bad; i++) {
        struct snapshot before;
        take(&before);
        double speed = app.speed;
        app.message[0] = '\0';
        if (app_set_text(&app, bad[i].ctl, bad[i].text) != 0)
            fail_msg("%s '%s' was taken", app_control_label(bad[i].ctl), bad[i].text);
        unchanged(&before);
        assert_close(app.speed, speed, 0.0);
        if (bad[i].ctl != CTL_PRESET && !(app.said == SAID_ERROR && app.message[0]))
            fail_msg("%s '%s': no reason given", app_control_label(bad[i].ctl), bad[i].text);
    }
    struct snapshot before;
    take(&before);
    assert_int_equal(app_set_element(&app, 'm', 0, "-1"), 0);
    assert_int_equal(app_set_element(&app, 'k', 0, "1,2"), 0);
    assert_int_equal(app_set_element(&app, 'k', 4, "3"), 0); /* no spring 4 */
    assert_int_equal(app_load_preset(&app, SRCDIR "/presets/nonesuch.ini", "nonesuch"), 0);
    unchanged(&before);
}

/* Presets the interactive program cannot run are refused whole. */
static void preset_out_of_range(void **state)
{
    (void)state;
    char dir[] = "/tmp/springsim-pre-XXXXXX", path[512];
    assert_non_null(mkdtemp(dir));
    snprintf(path, sizeof path, "%s/p.ini", dir);
    static const char *const bodies[] = {
        "[system]\nmasses = 2\ndt = 0.0005\n",
        "[system]\nmasses = 2\ndt = 0.000999\n",
        "[system]\ndt = 1e-320\n",
        "[system]\nmasses = 11\ndt = 0.01\n",
        "[system]\nmasses = 12\n",
        "[system]\nmasses = 2\nmass = 1,2,3\n",
    };
    for (size_t i = 0; i < sizeof bodies / sizeof *bodies; i++) {
        FILE *f = fopen(path, "w");
        assert_non_null(f);
        fputs(bodies[i], f);
        fclose(f);
        struct snapshot before;
        take(&before);
        assert_int_equal(app_load_preset(&app, path, "p"), 0);
        unchanged(&before);
        assert_int_equal(app.said, SAID_ERROR);
        assert_non_null(strstr(app.message, path));
    }
    /* Typed, the same limits hold (issue 11, defect 8). */
    struct snapshot before;
    take(&before);
    assert_int_equal(app_set_text(&app, CTL_DT, "0.0009"), 0);
    assert_non_null(strstr(app.message, "0.001 <= dt"));
    assert_int_equal(app_set_text(&app, CTL_MASSES, "11"), 0);
    assert_non_null(strstr(app.message, "N <= 10"));
    unchanged(&before);
    unlink(path);
    rmdir(dir);
}

/* --start-mode reaches the interactive program through its config, as --x0 does: the
 * chain starts along the mode's shape at rest, and the start is kept as per-mass lists
 * (so a later edit does not recompute it). */
static void starts_along_a_mode(void **state)
{
    (void)state;
    static struct config c;
    char err[256];
    app_free(&app);
    config_init(&c);
    c.masses = 3;
    assert_int_equal(config_set(&c, CFG_MASS, "1,2,0.5", err, sizeof err), 0);
    assert_int_equal(config_set(&c, CFG_START_MODE, "2:0.3", err, sizeof err), 0);
    assert_int_equal(app_init(&app, &c, SRCDIR), 0);
    double want[3];
    assert_int_equal(modes_start(app.model, 2, 0.3, want), 0);
    for (int i = 0; i < 3; i++) {
        assert_close(sim_x(app.sim)[i], want[i], 0.0);
        assert_close(sim_v(app.sim)[i], 0.0, 0.0);
    }
    assert_int_equal(app.cfg.start_mode, 0);
    assert_int_equal(app.cfg.x0.count, 3);
    assert_memory_equal(app.cfg.x0.v, want, sizeof want);
}

/* The seed of random positions chosen for the user is said in the status line, at the
 * start (--random without --seed), on 'R' and on loading a preset with random positions,
 * and it is the seed the positions came from. */
static void random_seed_said(void **state)
{
    (void)state;
    static struct app a;
    double x[APP_MAX_MASSES];
    struct config c = app.cfg;
    c.random = true;
    c.seed_set = false;
    c.seed = 1234567890123ULL;
    c.x0.count = 0;
    assert_int_equal(app_init(&a, &c, SRCDIR), 0);
    assert_non_null(strstr(a.message, "seed 1234567890123 "));
    config_random_positions(a.model, 1234567890123ULL, x);
    assert_memory_equal(sim_x(a.sim), x, (size_t)a.model->n * sizeof *x);
    app_free(&a);

    app_random(&app);
    char want[64];
    snprintf(want, sizeof want, "(seed %llu)", (unsigned long long)app.cfg.seed);
    assert_non_null(strstr(app.message, want));
    config_random_positions(app.model, app.cfg.seed, x);
    assert_memory_equal(sim_x(app.sim), x, (size_t)app.model->n * sizeof *x);

    /* A preset asking for random positions without a seed. */
    assert_true(preset_text("r", "[system]\nmasses = 3\n[initial]\nrandom = true\n") != 0);
    snprintf(want, sizeof want, "(random positions, seed %llu)",
             (unsigned long long)app.cfg.seed);
    assert_non_null(strstr(app.message, want));
    config_random_positions(app.model, app.cfg.seed, x);
    assert_memory_equal(sim_x(app.sim), x, (size_t)app.model->n * sizeof *x);
}

int main(void)
{
#define T(f) cmocka_unit_test_setup_teardown(f, setup, teardown)
    const struct CMUnitTest tests[] = {
        T(sweep_ends_on_every_route),
        T(sweep_survives_its_own_retunes),
        T(sweep_done_gives_the_drive_back),
        T(sweep_warns_of_contacts),
        T(modes_once_per_change),
        T(failed_rebuild_keeps_the_old_chain),
        T(failed_init_leaves_nothing),
        T(refused_input_changes_nothing),
        T(preset_out_of_range),
        T(starts_along_a_mode),
        T(random_seed_said),
    };
#undef T
    return cmocka_run_group_tests_name("app rules", tests, NULL, NULL);
}
