/* app.c: the interactive program's state changes, independent of the terminal. */
#include "app.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include <errno.h>
#include <sys/stat.h>

#include "../core/modes.h"
#include "../core/output.h"
#include "../core/preset.h"

/* Plots keep a sample at least this often (s), at most TRAIL_RECORDS in the window. */
#define SAMPLE_SPACING 0.0025
#define TRAIL_RECORDS 4400

static const char *const labels[CTL_COUNT] = {
    [CTL_PRESET] = "Preset",      [CTL_MASSES] = "Masses",     [CTL_DT] = "dt",
    [CTL_DAMPING] = "Damping",    [CTL_SPRING] = "Spring k",   [CTL_MASS] = "Mass",
    [CTL_BOUNDARY] = "Right end", [CTL_WAVE] = "Waveform",     [CTL_AMPLITUDE] = "Amplitude",
    [CTL_FREQUENCY] = "Frequency", [CTL_SPEED] = "Speed",   [CTL_BANDWIDTH] = "Bandwidth",
};

/* Playback speeds offered by the Speed control. */
static const double speeds[] = {0.1, 0.2, 0.25, 0.5, 1.0, 2.0, 4.0, 5.0, 10.0};
#define NSPEEDS (int)(sizeof speeds / sizeof *speeds)

/* Numeric controls: range of the arrows, fine and coarse steps, unit, decimals shown. */
static const struct {
    double lo, hi, fine, coarse;
    const char *unit;
    int decimals;
} ranges[CTL_COUNT] = {
    [CTL_DT] = {0.001, 0.05, 0.001, 0.005, "s", 3},
    [CTL_DAMPING] = {0.0, 2.0, 0.01, 0.1, "N·s/m", 2},
    [CTL_SPRING] = {1.0, 50.0, 0.5, 5.0, "N/m", 1},
    [CTL_MASS] = {0.1, 10.0, 0.1, 1.0, "kg", 2},
    [CTL_AMPLITUDE] = {0.0, 3.0, 0.05, 0.5, "m", 2},
    [CTL_FREQUENCY] = {0.1, 5.0, 0.01, 0.1, "Hz", 3},
};

void app_say(struct app *app, bool error, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(app->message, sizeof app->message, fmt, ap);
    va_end(ap);
    app->message_is_error = error;
}

const char *app_control_label(enum control ctl)
{
    return (unsigned)ctl < CTL_COUNT ? labels[ctl] : "";
}

/* Frees the chain-sized parts. */
static void drop_chain(struct app *app)
{
    history_free(app->hist);
    trail_free(app->trail);
    sweep_free(app->sweep);
    app->sweep = NULL;
    sim_free(app->sim);
    model_free(app->model);
    app->hist = NULL;
    app->trail = NULL;
    app->sim = NULL;
    app->model = NULL;
}

/* Natural frequencies, shapes and the stability limit of the model as it is now. */
static void update_modes(struct app *app)
{
    if (++app->version == 0)
        app->version = 1;
    app->modes_ok = modes_compute(app->model, app->modes, app->shapes) == 0;
    app->stable_dt = modes_stable_dt(app->model);
}

/* Says so, before anything blows up, when dt is past the RK4 stability limit. */
static void warn_unstable(struct app *app)
{
    if (app->cfg.dt >= app->stable_dt)
        app_say(app, true, "warning: dt = %.3f s is above the stability limit: dt < %.3g s "
                "is stable", app->cfg.dt, app->stable_dt);
}

/* Builds model, sim, history and trail from app->cfg; 0, or -1 on no memory. */
static int build_chain(struct app *app)
{
    int bad;
    char err[256];
    drop_chain(app);
    app->model = config_model(&app->cfg, &bad, err, sizeof err);
    if (!app->model)
        return -1;
    app->sim = sim_new(app->model, app->cfg.dt);
    app->trail = trail_new(app->model->n, TRAIL_RECORDS);
    if (!app->sim || !app->trail)
        return -1;
    app->hist = history_new(app->sim, HISTORY_DEPTH);
    app->sweep = sweep_new(app->model->n, APP_SWEEP_POINTS);
    if (!app->hist || !app->sweep)
        return -1;
    app->masses_pending = app->model->n;
    update_modes(app);
    return 0;
}

/* Steps between trail samples for the current dt. */
static void set_sampling(struct app *app)
{
    app->sample_every = (int)ceil(SAMPLE_SPACING / app->cfg.dt - 1e-9);
    if (app->sample_every < 1)
        app->sample_every = 1;
    app->since_sample = 0;
}

/* Initial conditions as full per-mass lists in cfg, so later edits keep them. */
static void fix_initial(struct app *app)
{
    int n = app->model->n;
    double *x = malloc(2 * (size_t)n * sizeof *x);
    if (!x)
        return;
    config_initial(&app->cfg, app->model, x, x + n);
    app->cfg.random = false;
    app->cfg.x0.count = n;
    app->cfg.v0.count = n;
    memcpy(app->cfg.x0.v, x, (size_t)n * sizeof *x);
    memcpy(app->cfg.v0.v, x + n, (size_t)n * sizeof *x);
    free(x);
}

int app_init(struct app *app, const struct config *cfg, const char *exe_dir)
{
    memset(app, 0, sizeof *app);
    app->cfg = *cfg;
    app->exe_dir = exe_dir;
    app->speed = 1.0;
    if (build_chain(app) != 0)
        return -1;
    fix_initial(app);
    snprintf(app->preset, sizeof app->preset, "%s", cfg->name);
    app_reset(app);
    warn_unstable(app);
    return 0;
}

void app_free(struct app *app)
{
    drop_chain(app);
}

/* Ends a running sweep and gives the drive its frequency back; says why (NULL: the
 * user stopped it). */
static void stop_sweep(struct app *app, const char *why)
{
    if (!app->sweep || !app->sweep->active)
        return;
    sweep_stop(app->sweep);
    app->cfg.frequency = app->sweep_from;
    motor_retune(&app->model->motor, app->sweep_from, sim_time(app->sim));
    sim_set_model(app->sim, app->model);
    if (why)
        app_say(app, false, "sweep stopped by %s; back at %.3f Hz", why, app->sweep_from);
    else
        app_say(app, false, "sweep stopped after %d of %d frequencies; back at %.3f Hz",
                sweep_measured(app->sweep), app->sweep->points, app->sweep_from);
}

void app_reset(struct app *app)
{
    stop_sweep(app, "the reset");
    app->model->motor.phase = 0.0; /* t = 0 again: the drive starts from its start */
    sim_set_model(app->sim, app->model);
    sim_set_dt(app->sim, app->cfg.dt);
    sim_reset(app->sim, app->cfg.x0.v, app->cfg.v0.v);
    sim_set_dt(app->sim, app->cfg.dt);
    history_clear(app->hist);
    trail_clear(app->trail);
    set_sampling(app);
    trail_push(app->trail, app->sim);
    struct energy e;
    sim_energy(app->sim, &e);
    app->energy0 = e.balance;
}

double app_energy_drift(const struct app *app)
{
    struct energy e;
    sim_energy(app->sim, &e);
    return e.balance - app->energy0;
}

static void retune(struct app *app, double f);

/* Puts the chain back on its last finite state after a blow-up and says why. */
static void recover(struct app *app)
{
    app->running = false;
    if (app->cfg.dt >= app->stable_dt)
        app_say(app, true, "unstable: dt too large for these springs; dt < %.3g s is stable",
                app->stable_dt);
    else
        app_say(app, true, "unstable: the numbers ran away; paused at t = %.2f s",
                sim_time(app->sim));
}

bool app_step(struct app *app)
{
    history_push(app->hist, app->sim);
    if (sim_step(app->sim) != SIM_OK ||
        (app->cfg.dt >= app->stable_dt && sim_last_capped(app->sim))) {
        /* Back to the state before this step: the last one known to be sound. */
        history_pop(app->hist, app->sim);
        trail_drop_after(app->trail, sim_time(app->sim));
        recover(app);
        return false;
    }
    if (++app->since_sample >= app->sample_every) {
        app->since_sample = 0;
        trail_push(app->trail, app->sim);
    }
    switch (sweep_update(app->sweep, sim_time(app->sim), sim_x(app->sim))) {
    case SWEEP_RETUNE:
        retune(app, sweep_frequency(app->sweep));
        break;
    case SWEEP_DONE:
        retune(app, app->sweep_from);
        app_say(app, false, "sweep done: %d frequencies measured (f shows them); back at "
                "%.3f Hz", app->sweep->points, app->sweep_from);
        break;
    default:
        break;
    }
    return true;
}

bool app_back(struct app *app)
{
    if (app->running) {
        app_say(app, false, "pause first (space) to step back");
        return false;
    }
    if (history_pop(app->hist, app->sim) != 0) {
        app_say(app, false, sim_time(app->sim) <= 0.0 ? "at t = 0: nothing before it"
                                                       : "no earlier state kept (%d at most)",
                HISTORY_DEPTH);
        return false;
    }
    /* The state carries the drive's angle it had; the sim re-anchored the phase for the
     * frequency in force now, and the app's copy of the model follows. */
    app->model->motor.phase = sim_model(app->sim)->motor.phase;
    if (sim_dt(app->sim) != app->cfg.dt) {
        /* Stepped back past a change of dt: the state carries the dt it was made with. */
        app->cfg.dt = sim_dt(app->sim);
        set_sampling(app);
    }
    trail_drop_after(app->trail, sim_time(app->sim));
    if (app->trail->count == 0)
        trail_push(app->trail, app->sim);
    return true;
}

void app_random(struct app *app)
{
    uint64_t seed = (uint64_t)time(NULL) * 6364136223846793005ULL + (uint64_t)clock();
    seed ^= app->cfg.seed * 0x9E3779B97F4A7C15ULL + 1;
    app->cfg.seed = seed;
    app->cfg.random = true;
    fix_initial(app);
    for (int i = 0; i < app->model->n; i++)
        app->cfg.v0.v[i] = 0.0;
    app_reset(app);
    app_say(app, false, "random initial positions");
}

void app_place_mass(struct app *app, int i, double X)
{
    const struct model *m = app->model;
    int n = m->n;
    if (i < 0 || i >= n)
        return;
    if (app->running) {
        app_say(app, false, "pause first (space) to move a mass");
        return;
    }
    double w = model_block_width(m);
    const double *x = sim_x(app->sim);
    double lo = 0.5 * w, hi = MODEL_LENGTH - 0.5 * w;
    if (i > 0)
        lo = model_equilibrium(m, i - 1) + x[i - 1] + w;
    if (i < n - 1)
        hi = model_equilibrium(m, i + 1) + x[i + 1] - w;
    else if (m->boundary == BOUNDARY_FREE)
        hi = MODEL_LENGTH + 2.0;
    if (hi < lo)
        return;
    X = fmin(fmax(X, lo), hi);
    /* The chain as it stands becomes the initial condition, at rest, at t = 0. */
    memcpy(app->cfg.x0.v, x, (size_t)n * sizeof *x);
    app->cfg.x0.v[i] = X - model_equilibrium(m, i);
    app->cfg.x0.count = n;
    for (int j = 0; j < n; j++)
        app->cfg.v0.v[j] = 0.0;
    app->cfg.v0.count = n;
    app->cfg.random = false;
    app_reset(app);
    app_say(app, false, "mass %d starts at %+.2f m", i + 1, app->cfg.x0.v[i]);
}

void app_move_mass(struct app *app, int i, double dx)
{
    if (i < 0 || i >= app->model->n)
        return;
    app_place_mass(app, i, model_equilibrium(app->model, i) + sim_x(app->sim)[i] + dx);
}

/* The common value of a per-element list, or NAN when they differ. */
static double common(const double *v, int n)
{
    for (int i = 1; i < n; i++)
        if (v[i] != v[0])
            return NAN;
    return v[0];
}

/* Applies the config's parameters to the running chain (same N). */
static void apply_params(struct app *app)
{
    int bad;
    char err[256];
    struct model *m = config_model(&app->cfg, &bad, err, sizeof err);
    if (!m) {
        app_say(app, true, "%s", err);
        return;
    }
    /* The drive keeps its phase through a change of frequency: no jump in u. */
    struct motor keep = app->model->motor;
    motor_retune(&keep, m->motor.frequency, sim_time(app->sim));
    m->motor.phase = keep.phase;
    model_copy(app->model, m);
    model_free(m);
    sim_set_model(app->sim, app->model);
    if (app->cfg.dt != sim_dt(app->sim)) {
        sim_set_dt(app->sim, app->cfg.dt);
        set_sampling(app);
    }
    update_modes(app);
    warn_unstable(app);
}

/* Sets one value for every element of a list. */
static void set_all(struct config_list *l, double v)
{
    l->count = 1;
    l->v[0] = v;
}

/* The current value of a numeric control (NAN for mixed per-element values). */
static double numeric_value(const struct app *app, enum control ctl)
{
    const struct model *m = app->model;
    switch (ctl) {
    case CTL_DT:
        return app->cfg.dt;
    case CTL_DAMPING:
        return common(m->c, m->n);
    case CTL_SPRING:
        return common(m->k, m->boundary == BOUNDARY_FREE ? m->n : m->n + 1);
    case CTL_MASS:
        return common(m->m, m->n);
    case CTL_AMPLITUDE:
        return m->motor.amplitude;
    case CTL_FREQUENCY:
        return m->motor.frequency;
    default:
        return NAN;
    }
}

/* Stores a numeric control's value (already checked) and applies it. */
static void set_numeric(struct app *app, enum control ctl, double v)
{
    switch (ctl) {
    case CTL_DT:
        app->cfg.dt = v;
        break;
    case CTL_DAMPING:
        set_all(&app->cfg.damping, v);
        break;
    case CTL_SPRING:
        set_all(&app->cfg.spring, v);
        break;
    case CTL_MASS:
        set_all(&app->cfg.mass, v);
        break;
    case CTL_AMPLITUDE:
        app->cfg.amplitude = v;
        break;
    case CTL_FREQUENCY:
        app->cfg.frequency = v;
        break;
    default:
        return;
    }
    apply_params(app);
}

void app_adjust(struct app *app, enum control ctl, int steps, bool coarse)
{
    switch (ctl) {
    case CTL_PRESET:
        return;
    case CTL_MASSES: {
        int n = app->masses_pending + steps * (coarse ? 5 : 1);
        app->masses_pending = n < 1 ? 1 : n > APP_MAX_MASSES ? APP_MAX_MASSES : n;
        if (app->masses_pending != app->model->n)
            app_say(app, false, "Enter applies %d masses (a reset)", app->masses_pending);
        return;
    }
    case CTL_BOUNDARY:
        stop_sweep(app, "the change of right end");
        app->cfg.boundary = (enum boundary)(((int)app->cfg.boundary + steps % BOUNDARY_COUNT +
                                             BOUNDARY_COUNT) % BOUNDARY_COUNT);
        apply_params(app);
        return;
    case CTL_WAVE:
        app->cfg.wave = (enum wave)(((int)app->cfg.wave + steps % WAVE_COUNT + WAVE_COUNT) %
                                    WAVE_COUNT);
        apply_params(app);
        return;
    case CTL_BANDWIDTH:
        app->cfg.low_bandwidth = !app->cfg.low_bandwidth;
        return;
    case CTL_SPEED: {
        int i = 0;
        while (i < NSPEEDS - 1 && speeds[i] < app->speed - 1e-9)
            i++;
        i += steps * (coarse ? 2 : 1);
        app->speed = speeds[i < 0 ? 0 : i >= NSPEEDS ? NSPEEDS - 1 : i];
        return;
    }
    default:
        break;
    }
    double step = coarse ? ranges[ctl].coarse : ranges[ctl].fine;
    double v = numeric_value(app, ctl);
    if (isnan(v))
        v = ctl == CTL_SPRING ? app->model->k[0] : ctl == CTL_MASS ? app->model->m[0]
                                                                   : app->model->c[0];
    /* Snap onto the step grid, then move. */
    v = round(v / step) * step + steps * step;
    v = fmin(fmax(v, ranges[ctl].lo), ranges[ctl].hi);
    set_numeric(app, ctl, v);
}

bool app_set_text(struct app *app, enum control ctl, const char *text)
{
    static const enum config_key keys[CTL_COUNT] = {
        [CTL_PRESET] = CFG_PRESET,     [CTL_MASSES] = CFG_MASSES,   [CTL_DT] = CFG_DT,
        [CTL_DAMPING] = CFG_DAMPING,   [CTL_SPRING] = CFG_SPRING,   [CTL_MASS] = CFG_MASS,
        [CTL_BOUNDARY] = CFG_BOUNDARY, [CTL_WAVE] = CFG_WAVE,       [CTL_AMPLITUDE] = CFG_AMPLITUDE,
        [CTL_FREQUENCY] = CFG_FREQUENCY,
    };
    char err[300];
    if (ctl == CTL_SPEED) {
        char *end;
        double v = strtod(text, &end);
        if (end != text && (*end == 'x' || *end == '\0') && (end[0] == '\0' || end[1] == '\0') &&
            v >= 0.1 && v <= 10.0) {
            app->speed = v;
            return true;
        }
        app_say(app, true, "speed: '%.40s' is not a number from 0.1 to 10", text);
        return false;
    }
    if (ctl == CTL_PRESET)
        return false;
    if (ctl == CTL_BANDWIDTH) {
        if (strcmp(text, "low") == 0 || strcmp(text, "normal") == 0) {
            app->cfg.low_bandwidth = text[0] == 'l';
            return true;
        }
        app_say(app, true, "bandwidth: '%.40s' is not low or normal", text);
        return false;
    }
    /* Checked on a copy, so a bad value changes nothing. */
    static struct config trial;
    trial = app->cfg;
    if (config_set(&trial, (int)keys[ctl], text, err, sizeof err) != 0) {
        app_say(app, true, "%s: %s", config_options[keys[ctl]].name, err);
        return false;
    }
    if (ctl == CTL_MASSES) {
        if (trial.masses > APP_MAX_MASSES) {
            app_say(app, true, "masses: '%s' is out of range (expected 1 <= N <= %d here)", text,
                    APP_MAX_MASSES);
            return false;
        }
        app->masses_pending = trial.masses;
        app_apply_masses(app);
        return true;
    }
    if (ctl == CTL_DT && trial.dt < 0.001) {
        app_say(app, true, "dt: '%.40s' is out of range (expected 0.001 <= dt <= 0.05 here)",
                text);
        return false;
    }
    int bad;
    struct model *m = config_model(&trial, &bad, err, sizeof err);
    if (!m) {
        app_say(app, true, "%s: %s", config_options[keys[ctl]].name, err);
        return false;
    }
    model_free(m);
    if (ctl == CTL_BOUNDARY || ctl == CTL_FREQUENCY)
        stop_sweep(app, "the change");
    app->cfg = trial;
    apply_params(app);
    return true;
}

void app_apply_masses(struct app *app)
{
    int n = app->masses_pending;
    if (n == app->model->n)
        return;
    stop_sweep(app, "the new number of masses");
    /* Every element takes the first element's values; the chain starts again at rest
     * in equilibrium, as the page's "Apply Config". */
    set_all(&app->cfg.mass, app->model->m[0]);
    set_all(&app->cfg.spring, app->model->k[0]);
    set_all(&app->cfg.damping, app->model->c[0]);
    app->cfg.masses = n;
    app->cfg.x0.count = app->cfg.v0.count = 0;
    app->cfg.random = false;
    struct config keep = app->cfg;
    if (build_chain(app) != 0) {
        app->cfg = keep;
        app_say(app, true, "out of memory");
        return;
    }
    fix_initial(app);
    app->running = false;
    app_reset(app);
    app_say(app, false, "%d mass%s, at rest", n, n == 1 ? "" : "es");
}

bool app_load_preset(struct app *app, const char *path, const char *name)
{
    static struct config c;
    char err[600];
    int bad;
    config_init(&c);
    if (preset_load(path, &c, err, sizeof err) != PRESET_OK) {
        app_say(app, true, "%s", err);
        return false;
    }
    if (c.masses > APP_MAX_MASSES) {
        app_say(app, true, "%s has %d masses; the interactive program takes 1 to %d", name,
                c.masses, APP_MAX_MASSES);
        return false;
    }
    struct model *m = config_model(&c, &bad, err, sizeof err);
    if (!m) {
        app_say(app, true, "%s: %s: %s", path, config_options[bad < 0 ? 0 : bad].name, err);
        return false;
    }
    model_free(m);
    stop_sweep(app, "the preset");
    struct config keep = app->cfg;
    app->cfg = c;
    if (c.random && !c.seed_set)
        app->cfg.seed = (uint64_t)time(NULL);
    if (build_chain(app) != 0) {
        app->cfg = keep;
        build_chain(app);
        app_say(app, true, "out of memory");
        return false;
    }
    fix_initial(app);
    snprintf(app->preset, sizeof app->preset, "%s", c.name[0] ? c.name : name);
    app->running = false;
    app_reset(app);
    app_say(app, false, "preset %s: %s", app->preset, c.description);
    return true;
}

void app_control_value(const struct app *app, enum control ctl, char *buf, size_t len)
{
    const struct model *m = app->model;
    switch (ctl) {
    case CTL_PRESET:
        snprintf(buf, len, "%s", app->preset[0] ? app->preset : "(none)");
        return;
    case CTL_MASSES:
        if (app->masses_pending != m->n)
            snprintf(buf, len, "%d [Enter: apply]", app->masses_pending);
        else
            snprintf(buf, len, "%d", m->n);
        return;
    case CTL_BOUNDARY:
        snprintf(buf, len, "%s", model_boundary_name(m->boundary));
        return;
    case CTL_WAVE:
        snprintf(buf, len, "%s", motor_wave_name(m->motor.wave));
        return;
    case CTL_SPEED:
        snprintf(buf, len, "%gx", app->speed);
        return;
    case CTL_BANDWIDTH:
        snprintf(buf, len, "%s", app->cfg.low_bandwidth ? "low" : "normal");
        return;
    default:
        break;
    }
    double v = numeric_value(app, ctl);
    if (isnan(v)) {
        snprintf(buf, len, "mixed %s", ranges[ctl].unit);
        return;
    }
    snprintf(buf, len, "%.*f %s", ranges[ctl].decimals, v, ranges[ctl].unit);
    if (ctl == CTL_FREQUENCY && app->modes_ok) {
        /* On a natural frequency (within 0.5 %): say which. */
        int j = modes_nearest(app->modes, m->n, v);
        if (fabs(v - app->modes[j]) <= 0.005 * app->modes[j])
            snprintf(buf + strlen(buf), len - strlen(buf), " ◆ f%d", j + 1);
    }
}

/* Drives at frequency f from now on, phase continuous. */
static void retune(struct app *app, double f)
{
    app->cfg.frequency = f;
    motor_retune(&app->model->motor, f, sim_time(app->sim));
    sim_set_model(app->sim, app->model);
}

void app_nearest_mode(struct app *app)
{
    if (!app->modes_ok)
        return;
    int j = modes_nearest(app->modes, app->model->n, app->model->motor.frequency);
    retune(app, app->modes[j]);
    app_say(app, false, "driving at mode %d, %.3f Hz", j + 1, app->modes[j]);
}

void app_toggle_sweep(struct app *app)
{
    if (app->sweep->active) {
        stop_sweep(app, NULL);
        return;
    }
    if (app->model->boundary != BOUNDARY_MOTOR || !app->modes_ok) {
        app_say(app, true, "a sweep needs the motor at the right end");
        return;
    }
    int n = app->model->n;
    double lo = fmax(APP_FMIN, 0.5 * app->modes[0]);
    double hi = fmin(APP_FMAX, 1.5 * app->modes[n - 1]);
    /* Settle for a few damping times of the slowest-decaying mode, within reason. */
    double cmin = app->model->c[0], mmax = app->model->m[0];
    for (int i = 1; i < n; i++)
        cmin = fmin(cmin, app->model->c[i]), mmax = fmax(mmax, app->model->m[i]);
    double settle = cmin > 0 ? fmin(30.0, fmax(4.0, 3.0 * 2.0 * mmax / cmin)) : 30.0;
    app->sweep_from = app->model->motor.frequency;
    sweep_start(app->sweep, lo, hi, settle, sim_time(app->sim));
    retune(app, sweep_frequency(app->sweep));
    app->running = true;
    app_say(app, false, "sweeping %.2f..%.2f Hz, %d steps of %.0f s or more; ] runs faster, "
            "w stops", lo, hi, app->sweep->points, settle);
}

bool app_set_element(struct app *app, char what, int index, const char *text)
{
    const struct model *m = app->model;
    int n = m->n, count = what == 'k' ? n + 1 : n;
    enum config_key key = what == 'm' ? CFG_MASS : what == 'c' ? CFG_DAMPING : CFG_SPRING;
    if (index < 0 || index >= count)
        return false;
    /* Check the one value with the key's own rules, on a scratch config. */
    static struct config trial;
    char err[300];
    config_init(&trial);
    if (config_set(&trial, key, text, err, sizeof err) != 0 ||
        (trial.mass.count + trial.spring.count + trial.damping.count) != 1) {
        if (trial.mass.count + trial.spring.count + trial.damping.count > 1)
            snprintf(err, sizeof err, "'%.40s' is more than one value", text);
        app_say(app, true, "%s %d: %s", what == 'k' ? "spring" : "mass", index + (what != 'k'),
                err);
        return false;
    }
    double v = (what == 'm' ? trial.mass : what == 'c' ? trial.damping : trial.spring).v[0];
    struct config_list *l = what == 'm' ? &app->cfg.mass
                          : what == 'c' ? &app->cfg.damping : &app->cfg.spring;
    const double *cur = what == 'm' ? m->m : what == 'c' ? m->c : m->k;
    l->count = count;
    for (int i = 0; i < count; i++)
        l->v[i] = cur[i];
    l->v[index] = v;
    apply_params(app);
    return true;
}

/* A preset name: letters, digits, '-', '_' and '.', not starting with '.', at most 64. */
static const char *bad_name(const char *name)
{
    size_t len = strlen(name);
    if (len == 0)
        return "a name is needed";
    if (len > 64)
        return "names are at most 64 characters";
    if (name[0] == '.')
        return "a name may not start with '.'";
    for (const char *p = name; *p; p++)
        if (!((*p >= 'a' && *p <= 'z') || (*p >= 'A' && *p <= 'Z') || (*p >= '0' && *p <= '9') ||
              *p == '-' || *p == '_' || *p == '.'))
            return "use letters, digits, '-', '_' and '.' only";
    return NULL;
}

/* mkdir -p. */
static int make_dirs(const char *path)
{
    char buf[4096];
    snprintf(buf, sizeof buf, "%s", path);
    for (char *p = buf + 1; *p; p++) {
        if (*p != '/')
            continue;
        *p = '\0';
        if (mkdir(buf, 0777) != 0 && errno != EEXIST)
            return -1;
        *p = '/';
    }
    return mkdir(buf, 0777) != 0 && errno != EEXIST ? -1 : 0;
}

enum app_save app_save(struct app *app, const char *name, bool overwrite)
{
    char dir[4096], path[4200];
    const char *why = bad_name(name);
    if (why) {
        app_say(app, true, "save: '%.40s': %s", name, why);
        return SAVE_BAD_NAME;
    }
    if (preset_user_dir(dir, sizeof dir) != 0) {
        app_say(app, true, "save: neither XDG_CONFIG_HOME nor HOME is set");
        return SAVE_FAILED;
    }
    snprintf(path, sizeof path, "%s/%s.ini", dir, name);
    if (!overwrite && access(path, F_OK) == 0) {
        app_say(app, false, "preset %s exists: replace it? (y/n)", name);
        return SAVE_EXISTS;
    }
    if (make_dirs(dir) != 0) {
        app_say(app, true, "save: %s: %s", dir, strerror(errno));
        return SAVE_FAILED;
    }
    /* The set-up as it stands: every element's values, the initial conditions. */
    static struct config c;
    c = app->cfg;
    if (app->sweep->active)
        c.frequency = app->sweep_from; /* the drive as the user set it, not the sweep's */
    snprintf(c.name, sizeof c.name, "%s", name);
    snprintf(c.description, sizeof c.description, "Saved from springsim");
    struct output o;
    int e = output_open(&o, path);
    if (e == 0) {
        preset_write(o.fp, &c, app->model);
        e = output_close(&o, true);
    }
    if (e) {
        app_say(app, true, "save: %s: %s", path, strerror(e));
        return SAVE_FAILED;
    }
    snprintf(app->preset, sizeof app->preset, "%s", name);
    app_say(app, false, "saved %s (springsim -p %s loads it)", path, name);
    return SAVE_OK;
}

bool app_export(struct app *app, const char *dir, char *path, size_t len)
{
    time_t now = time(NULL);
    struct tm tm;
    char stamp[32];
    localtime_r(&now, &tm);
    strftime(stamp, sizeof stamp, "%Y%m%d-%H%M%S", &tm);
    snprintf(path, len, "%s/springsim-%s.csv", dir ? dir : ".", stamp);
    const struct trail *tr = app->trail;
    int n = tr->n;
    struct output o;
    int e = output_open(&o, path);
    if (e == 0) {
        output_csv_header(o.fp, n, false);
        const double *rec = trail_first(tr);
        for (int k = 0; k < tr->count; k++, rec += tr->width)
            output_csv_values(o.fp, n, rec[TRAIL_T], rec + TRAIL_X(tr, 0), rec + TRAIL_V(tr, 0),
                              rec + TRAIL_A(tr, 0), rec[TRAIL_U], NULL);
        e = output_close(&o, true);
    }
    if (e) {
        app_say(app, true, "export: %s: %s", path, strerror(e));
        return false;
    }
    app_say(app, false, "exported %d rows to %s", tr->count, path);
    return true;
}

double app_freq_fraction(double f)
{
    return log(f / APP_FMIN) / log(APP_FMAX / APP_FMIN);
}
