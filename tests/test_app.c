/* test_app.c: the interactive program's state without a terminal. Its rules on every
 * route: a running sweep ends when the chain or the drive's frequency changes, however
 * it changes, and gives the user's frequency back, but goes on through its own retunes;
 * the modes are computed once per change; a new chain is built whole or not at all (the
 * allocations are made to fail one by one: the Makefile links this program with
 * --wrap for them); the masks returned say what changed and a refused input changes
 * nothing. Also: the time window and its two trails, per-element editing, the mode
 * marker, a saved preset that reloads to the same chain, export, branching from history.
 * Every test starts from its own fresh app. */
#include "testutil.h"

#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "core/modes.h"
#include "core/preset.h"
#include "app/app.h"

static struct app app;
static struct config cfg;

/* ---- the wrapped functions: allocations that fail on demand, modes that count ---- */

static int alloc_calls; /* wrapped allocations since fail_at was set */
static int fail_at;     /* the one of them that fails (1 = the next), 0 for none */
static int modes_calls; /* modes_compute calls */
static int limit_calls; /* modes_stable_dt calls */

static bool fail_now(void)
{
    return fail_at > 0 && ++alloc_calls == fail_at;
}

/* Makes the k-th wrapped allocation from now fail (0: none). */
static void fail_allocation(int k)
{
    fail_at = k;
    alloc_calls = 0;
}

struct model *__real_config_model(const struct config *c, int *bad_key, char *err, size_t len);
struct model *__wrap_config_model(const struct config *c, int *bad_key, char *err, size_t len);
struct sim *__real_sim_new(const struct model *model, double dt);
struct sim *__wrap_sim_new(const struct model *model, double dt);
struct history *__real_history_new(const struct sim *s, int capacity);
struct history *__wrap_history_new(const struct sim *s, int capacity);
struct trail *__real_trail_new(int n, int capacity);
struct trail *__wrap_trail_new(int n, int capacity);
struct sweep *__real_sweep_new(int n, int points);
struct sweep *__wrap_sweep_new(int n, int points);
int __real_modes_compute(const struct model *m, double *freq, double *shapes);
int __wrap_modes_compute(const struct model *m, double *freq, double *shapes);
double __real_modes_stable_dt(const struct model *m);
double __wrap_modes_stable_dt(const struct model *m);

struct model *__wrap_config_model(const struct config *c, int *bad_key, char *err, size_t len)
{
    if (fail_now()) {
        *bad_key = -1;
        snprintf(err, len, "out of memory");
        return NULL;
    }
    return __real_config_model(c, bad_key, err, len);
}

struct sim *__wrap_sim_new(const struct model *model, double dt)
{
    return fail_now() ? NULL : __real_sim_new(model, dt);
}

struct history *__wrap_history_new(const struct sim *s, int capacity)
{
    return fail_now() ? NULL : __real_history_new(s, capacity);
}

struct trail *__wrap_trail_new(int n, int capacity)
{
    return fail_now() ? NULL : __real_trail_new(n, capacity);
}

struct sweep *__wrap_sweep_new(int n, int points)
{
    return fail_now() ? NULL : __real_sweep_new(n, points);
}

int __wrap_modes_compute(const struct model *m, double *freq, double *shapes)
{
    modes_calls++;
    return __real_modes_compute(m, freq, shapes);
}

double __wrap_modes_stable_dt(const struct model *m)
{
    limit_calls++;
    return __real_modes_stable_dt(m);
}

/* ---- set-up: three masses driven at 0.9 Hz, no mode of theirs ---- */

static int setup(void **state)
{
    (void)state;
    fail_allocation(0);
    config_init(&cfg);
    cfg.masses = 3;
    cfg.frequency = 0.9;
    int e = app_init(&app, &cfg, SRCDIR);
    modes_calls = limit_calls = 0;
    return e;
}

static int teardown(void **state)
{
    (void)state;
    fail_allocation(0);
    app_free(&app);
    return 0;
}

/* Everything a refused change must leave as it was. */
struct snapshot {
    struct config cfg;     /* byte for byte */
    struct model *model;   /* the same objects */
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

/* Runs n steps, each of which must succeed. */
static void run(int n)
{
    for (int i = 0; i < n; i++)
        assert_true(app_step(&app));
}

/* Starts a sweep, paused, and checks it took the drive. */
static void start_sweep(void)
{
    double user = app.model->motor.frequency;
    app_toggle_sweep(&app);
    app.running = false;
    assert_true(app.sweep->active);
    assert_true(app.model->motor.frequency != user);
    assert_close(app.sweep_from, user, 0.0);
}

/* The drive in force, as the app, its settings and the running sim see it. */
static double drive_frequency(void)
{
    assert_close(app.cfg.frequency, app.model->motor.frequency, 0.0);
    assert_close(sim_model(app.sim)->motor.frequency, app.model->motor.frequency, 0.0);
    return app.model->motor.frequency;
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
static unsigned new_n(void)
{
    app_adjust(&app, CTL_MASSES, 5 - app.masses_pending, false); /* 5 masses, pending */
    return app_apply_masses(&app);
}
static unsigned n_typed(void) { return app_set_text(&app, CTL_MASSES, "4"); }
static unsigned preset(void)
{
    return app_load_preset(&app, SRCDIR "/presets/3-mass-chain.ini", "3-mass-chain");
}
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
    assert_close(app.stable_dt, modes_stable_dt(app.model), 0.0);
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
        assert_true(app.message_is_error);
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

/* ---- what the masks say ---- */

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
    assert_false(app.message_is_error);
    w = app_set_text(&app, CTL_SPRING, "5000");
    assert_true(w & APP_CHANGED_CHAIN);
    assert_true(app.message_is_error);
    assert_non_null(strstr(app.message, "stability limit"));
    w = app_set_text(&app, CTL_SPRING, "10");
    assert_false(app.message_is_error);
    w = app_set_text(&app, CTL_SPRING, "5000");
    w = app_set_text(&app, CTL_DT, "0.01");
    assert_true(w & APP_CHANGED_DT);
    assert_false(app.message_is_error);
    w = app_set_text(&app, CTL_DT, "0.05");
    assert_true(w & APP_CHANGED_DT);
    assert_true(app.message_is_error);
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
        if (bad[i].ctl != CTL_PRESET && !(app.message_is_error && app.message[0]))
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
        assert_true(app.message_is_error);
        assert_non_null(strstr(app.message, path));
    }
    unlink(path);
    rmdir(dir);
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
    char dir[] = "/tmp/springsim-pb-XXXXXX", path[512];
    assert_non_null(mkdtemp(dir));
    snprintf(path, sizeof path, "%s/p.ini", dir);
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    fputs("[run]\nfps = 20\n", f);
    fclose(f);
    w = app_load_preset(&app, path, "p");
    assert_true(w & APP_CHANGED_PLAYBACK);
    assert_int_equal(app.cfg.fps, 20);
    assert_true(app.cfg.low_bandwidth);
    unlink(path);
    rmdir(dir);
}

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

/* ---- editing, modes, files, history ---- */

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
    assert_true(app.message_is_error);
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

int main(void)
{
#define T(f) cmocka_unit_test_setup_teardown(f, setup, teardown)
    const struct CMUnitTest tests[] = {
        T(sweep_ends_on_every_route),
        T(sweep_survives_its_own_retunes),
        T(sweep_done_gives_the_drive_back),
        T(modes_once_per_change),
        T(failed_rebuild_keeps_the_old_chain),
        T(failed_init_leaves_nothing),
        T(masks_say_what_changed),
        T(refused_input_changes_nothing),
        T(preset_out_of_range),
        T(preset_keeps_playback),
        T(window_steps_and_clamps),
        T(coarse_trail_covers_60_s),
        T(element_editing),
        T(mode_marker_and_nearest),
        T(save_and_reload),
        T(export_csv),
        T(branch_from_history),
        T(back_across_retune),
        T(back_across_dt),
    };
#undef T
    return cmocka_run_group_tests_name("app", tests, NULL, NULL);
}
