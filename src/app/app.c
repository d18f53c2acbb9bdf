/* app.c: the interactive program's state, independent of the terminal: its lifecycle,
 * the one path by which its parameters change (app_change, for controls.c and files.c),
 * and time: steps forward and back, resets, the initial positions, the sweep's points
 * (its plan and start: sweeping.c), and the plots' samples (their window: window.c).
 * The ghost (ghost.c) follows each of these moves in time. */
#include "change.h"

#include <math.h>
#include <stdio.h>
#include <string.h>
#include <time.h>

#include "../core/limits.h"
#include "../core/modes.h"
#include "ghost.h"
#include "jump.h"
#include "action.h"
#include "cost.h"

/* The chain-sized parts, made together and swapped in together. The parameters are the
 * sim's own: the app reads them through app->model, a pointer to them. */
struct parts {
    struct sim *sim;
    struct history *hist;
    struct trail *trail;
    struct trail *coarse;
    struct sweep *sweep;
    struct sweep *sweep_up;
};

static void parts_free(struct parts *p)
{
    history_free(p->hist);
    trail_free(p->trail);
    trail_free(p->coarse);
    sweep_free(p->sweep);
    sweep_free(p->sweep_up);
    sim_free(p->sim);
    *p = (struct parts){0};
}

/* Builds the parts around model m, which the sim copies (m is freed, on failure too); 0,
 * or -1 on no memory with nothing left allocated. */
static int parts_new(struct parts *p, struct model *m, const struct config *next)
{
    *p = (struct parts){0};
    p->sim = sim_new(m, next->dt);
    if (p->sim)
        sim_set_integrator(p->sim, next->integrator);
    p->hist = p->sim ? history_new(p->sim, HISTORY_DEPTH) : NULL;
    p->trail = trail_new(m->n, TRAIL_FINE_RECORDS);
    p->coarse = trail_new(m->n, TRAIL_COARSE_RECORDS);
    p->sweep = sweep_new(m->n, APP_SWEEP_POINTS);
    p->sweep_up = sweep_new(m->n, APP_SWEEP_POINTS);
    model_free(m);
    if (p->sim && p->hist && p->trail && p->coarse && p->sweep && p->sweep_up)
        return 0;
    parts_free(p);
    return -1;
}

/* Puts p's parts into the app and the app's old ones into p. */
static void parts_swap(struct app *app, struct parts *p)
{
    struct parts old = {app->sim, app->hist, app->trail, app->coarse, app->sweep,
                        app->sweep_up};
    app->sim = p->sim;
    app->model = app->sim ? sim_model(app->sim) : NULL;
    app->hist = p->hist;
    app->trail = p->trail;
    app->coarse = p->coarse;
    app->sweep = p->sweep;
    app->sweep_up = p->sweep_up;
    *p = old;
}

/* Natural frequencies, shapes and the damped modes of the model as it is now. */
static void compute_modes(struct app *app)
{
    app->modes_ok = modes_compute(app->model, app->modes, app->shapes) == 0;
    app->damping_ok = app->modes_ok && modes_damped(app->model, app->shapes, app->damping_ratio,
                                                    app->damped_hz) == 0;
    app->limits_ok = limits_modes(app->model, app->limit_modes) == 0;
}

/* What dt is worth with the chain, drive and integrator in force. */
static void judge(struct app *app)
{
    if (app->limits_ok)
        limits_judge(app->limit_modes, app->model->n, app->model, app->cfg.integrator,
                     app->cfg.dt, &app->limits);
    else
        app->limits = (struct limits){.integrator = app->cfg.integrator, .dt = app->cfg.dt,
                                      .stable_dt = INFINITY, .accurate_dt = INFINITY,
                                      .worst = -1, .drive_steps = INFINITY,
                                      .drive_dt = INFINITY};
    app->stable_dt = app->limits.stable_dt;
    app->runaway_base_ok = false;
    app->work += COST_CHANGE * app->model->n; /* what working it out cost (cost.h) */
}

/* Says what is wrong with dt after a change, if anything. A change of the chain, dt or
 * the integrator says the first of: unstable, a mode inaccurate, the drive short of
 * steps; one of the drive alone says only that the drive has just become short of them
 * (a sweep's retunes cross it once, not at every point). */
static unsigned say_limits(struct app *app, unsigned what, bool drive_was_rough)
{
    const struct limits *l = &app->limits;
    char line[sizeof app->message];
    line[0] = '\0';
    if (what & (APP_CHANGED_CHAIN | APP_CHANGED_DT | APP_CHANGED_INTEGRATOR)) {
        limits_say_stability(l, true, line, sizeof line);
        if (!line[0])
            limits_say_modes(l, true, line, sizeof line);
        if (!line[0])
            limits_say_drive(l, true, line, sizeof line);
    } else if ((what & APP_CHANGED_DRIVE) && !drive_was_rough && !limits_unstable(l)) {
        limits_say_drive(l, true, line, sizeof line);
    }
    if (what & (APP_CHANGED_CHAIN | APP_CHANGED_DT | APP_CHANGED_INTEGRATOR))
        app_say_nonlinear(app->model, line, sizeof line);
    return line[0] ? app_say(app, SAID_WARNING, "%s", line) : 0;
}

/* Steps between samples for the current dt, fine and coarse. */
static void set_sampling(struct app *app)
{
    app->sample_every = trail_every(TRAIL_FINE_SPACING, app->cfg.dt);
    app->coarse_every = trail_every(TRAIL_COARSE_SPACING, app->cfg.dt);
    app->since_sample = 0;
    app->since_coarse = 0;
}

/* Initial conditions as full per-mass lists in cfg, so later edits keep them. */
static void fix_initial(struct app *app)
{
    int n = app->model->n;
    double x[APP_MAX_MASSES], v[APP_MAX_MASSES];
    config_initial(&app->cfg, app->model, x, v); /* on failure at rest in equilibrium */
    app->cfg.random = false;
    app->cfg.start_mode = 0;
    app->cfg.x0.count = n;
    app->cfg.v0.count = n;
    memcpy(app->cfg.x0.v, x, (size_t)n * sizeof *x);
    memcpy(app->cfg.v0.v, v, (size_t)n * sizeof *v);
}

/* t = 0 at the initial conditions, the drive from its start; history and samples
 * cleared. */
static void restart(struct app *app)
{
    sim_set_phase(app->sim, 0.0);
    sim_set_dt(app->sim, app->cfg.dt);
    sim_reset(app->sim, app->cfg.x0.v, app->cfg.v0.v);
    sim_set_dt(app->sim, app->cfg.dt);
    app->runaway_base_ok = false;
    history_clear(app->hist);
    trail_clear(app->trail);
    trail_clear(app->coarse);
    set_sampling(app);
    trail_push(app->trail, app->sim);
    trail_push(app->coarse, app->sim);
    app->scope.back = 0.0;
    struct energy e;
    sim_energy(app->sim, &e);
    app->energy0 = e.balance;
    app->capped = 0;
    ghost_restart(app);
}

/* Whether any of the n values differ. */
static bool differ(const double *a, const double *b, int n)
{
    for (int i = 0; i < n; i++)
        if (a[i] != b[i])
            return true;
    return false;
}

/* What putting next (and m, the model made from it) in force would change. */
static unsigned compare(const struct app *app, const struct config *next, const struct model *m)
{
    const struct model *o = app->model;
    if (!o)
        return APP_CHANGED_SIZE | APP_CHANGED_CHAIN | APP_CHANGED_DRIVE | APP_CHANGED_DT;
    unsigned what = 0;
    int n = m->n;
    if (n != o->n)
        what |= APP_CHANGED_SIZE | APP_CHANGED_CHAIN;
    else if (differ(m->m, o->m, n) || differ(m->k, o->k, n + 1) || differ(m->c, o->c, n) ||
             differ(m->k3, o->k3, n + 1) || differ(m->cs, o->cs, n + 1) ||
             m->collisions != o->collisions)
        what |= APP_CHANGED_CHAIN;
    if (m->boundary != o->boundary)
        what |= APP_CHANGED_CHAIN | APP_CHANGED_DRIVE;
    if (m->motor.wave != o->motor.wave || m->motor.amplitude != o->motor.amplitude ||
        m->motor.frequency != o->motor.frequency || m->force != o->force ||
        m->force_on != o->force_on)
        what |= APP_CHANGED_DRIVE;
    if (next->dt != app->cfg.dt)
        what |= APP_CHANGED_DT;
    if (next->integrator != app->cfg.integrator)
        what |= APP_CHANGED_INTEGRATOR;
    if (next->low_bandwidth != app->cfg.low_bandwidth || next->fps != app->cfg.fps)
        what |= APP_CHANGED_PLAYBACK;
    if (next->window != app->cfg.window)
        what |= APP_CHANGED_WINDOW;
    return what;
}

/* Says why a sweep ended and where the drive is now. */
static unsigned say_sweep_end(struct app *app, const char *why, int measured, int points)
{
    double f = app->model->motor.frequency;
    if (!why)
        return app_say(app, SAID_NOTE, "sweep stopped after %d of %d frequencies; back at %.3f Hz",
                       measured, points, f);
    return app_say(app, SAID_NOTE, "sweep stopped by %s; %s %.3f Hz", why,
                   f == app->sweep_from ? "back at" : "now", f);
}

/* A new chain from next and m (taken over), at t = 0: all or nothing, every part of it
 * made before the old one is let go. 0, or -1 (no memory) with the old chain as it was. */
static int rebuild_from(struct app *app, const struct config *next, struct model *m)
{
    struct parts p;
    if (parts_new(&p, m, next) != 0) {
        app_say(app, SAID_ERROR, "out of memory: the chain is as it was");
        return -1;
    }
    parts_swap(app, &p);
    parts_free(&p);
    app->cfg = *next;
    fix_initial(app);
    restart(app);
    return 0;
}

/* The same chain goes on with next's parameters and m's values (m is freed). */
static void apply_in_place(struct app *app, const struct config *next, struct model *m,
                           unsigned what)
{
    /* The drive keeps its phase through a change of frequency: no jump in u. */
    struct motor keep = app->model->motor;
    motor_retune(&keep, m->motor.frequency, sim_time(app->sim));
    m->motor.phase = keep.phase;
    sim_set_model(app->sim, m);
    model_free(m);
    app->cfg = *next;
    if (what & APP_CHANGED_DT) {
        sim_set_dt(app->sim, app->cfg.dt);
        set_sampling(app);
    }
    if (what & APP_CHANGED_INTEGRATOR)
        sim_set_integrator(app->sim, app->cfg.integrator);
}

int app_change(struct app *app, struct config *next, unsigned how, const char *why,
               unsigned *changed)
{
    char err[300];
    int bad;
    bool drive_was_rough = app->model && limits_rough_drive(&app->limits);
    *changed = 0;
    /* Every option's range, then the interactive program's narrower ones, whatever the
     * route (a value the program made too: the nearest mode, a sweep's frequency). */
    if ((bad = config_check_ranges(next, err, sizeof err)) >= 0 ||
        (bad = config_check_interactive(next, err, sizeof err)) >= 0) {
        app_say(app, SAID_ERROR, "%s: %s", config_options[bad].name, err);
        return -1;
    }
    struct model *m = config_model(next, &bad, err, sizeof err);
    if (!m) {
        if (bad >= 0)
            app_say(app, SAID_ERROR, "%s: %s", config_options[bad].name, err);
        else
            app_say(app, SAID_ERROR, "%s: the chain is as it was", err);
        return -1;
    }
    bool sweeping = app->sweep && app->sweep->active && !(how & CHANGE_BY_SWEEP);
    bool rebuild = (how & CHANGE_REBUILD) || !app->model || m->n != app->model->n;
    unsigned what = compare(app, next, m);
    if (sweeping && (how & CHANGE_SETS_FREQUENCY))
        what |= APP_CHANGED_DRIVE; /* the user takes the drive, even at the sweep's frequency */
    if (!what && !rebuild) {
        model_free(m);
        return 0;
    }
    /* A sweep ends when the chain or the drive changes, and the drive goes back to the
     * user's frequency unless the change sets a new one. */
    bool ends = sweeping && (rebuild || (what & (APP_CHANGED_CHAIN | APP_CHANGED_DRIVE)));
    int measured = ends ? sweep_measured(app->sweep) : 0, points = ends ? app->sweep->points : 0;
    if (ends && !(how & CHANGE_SETS_FREQUENCY)) {
        next->frequency = m->motor.frequency = app->sweep_from;
        if (app->sweep_from != app->model->motor.frequency)
            what |= APP_CHANGED_DRIVE;
    }
    if (rebuild) {
        if (rebuild_from(app, next, m) != 0)
            return -1;
        what |= APP_CHANGED_CHAIN | APP_CHANGED_STATE | ghost_drop(app, "with the new chain");
        if (app->masses_pending != app->model->n)
            what |= APP_CHANGED_PENDING;
        if (app->running)
            what |= APP_CHANGED_PLAYBACK;
        app->masses_pending = app->model->n;
        app->running = false;
    } else {
        if (ends)
            sweep_stop(app->sweep);
        apply_in_place(app, next, m, what);
    }
    if (what & APP_CHANGED_CHAIN)
        compute_modes(app);
    if (what & (APP_CHANGED_CHAIN | APP_CHANGED_DRIVE | APP_CHANGED_DT | APP_CHANGED_INTEGRATOR))
        judge(app);
    if ((what & (APP_CHANGED_CHAIN | APP_CHANGED_DRIVE)) && ++app->version == 0)
        app->version = 1;
    if (ends)
        what |= say_sweep_end(app, why, measured, points);
    /* Said before anything blows up or goes wrong. */
    what |= say_limits(app, what, drive_was_rough);
    *changed = what;
    return 0;
}

int app_init(struct app *app, const struct config *cfg, const char *exe_dir)
{
    return app_init_named(app, cfg, exe_dir, NULL, false);
}

int app_init_named(struct app *app, const struct config *cfg, const char *exe_dir,
                   const char *(*name_of)(int action), bool keys)
{
    memset(app, 0, sizeof *app);
    app->name_of = name_of;
    app->keys = keys;
    app->exe_dir = exe_dir;
    app->speed = 1.0;
    snprintf(app->preset, sizeof app->preset, "%s", cfg->name);
    struct config next = *cfg;
    unsigned changed;
    if (app_change(app, &next, CHANGE_REBUILD, NULL, &changed) != 0)
        return -1;
    /* The seed --random chose, so that the start can be repeated. */
    if (cfg->random && !cfg->seed_set && app->message[0] == '\0')
        app_say(app, SAID_NOTE, "random positions from seed %llu (--seed repeats them); %s "
                "starts it", (unsigned long long)cfg->seed, app_key(app, ACT_RUN));
    return 0;
}

void app_free(struct app *app)
{
    ghost_drop(app, NULL);
    struct parts p = {0};
    parts_swap(app, &p);
    parts_free(&p);
}

unsigned app_end_sweep(struct app *app, const char *why)
{
    unsigned what = 0;
    if (!app->sweep->active)
        return 0;
    struct config next = app->cfg;
    next.frequency = app->sweep_from;
    app_change(app, &next, CHANGE_SETS_FREQUENCY, why, &what);
    return what;
}

unsigned app_retune(struct app *app, double f)
{
    unsigned what = 0;
    struct config next = app->cfg;
    next.frequency = f;
    app_change(app, &next, CHANGE_BY_SWEEP, NULL, &what);
    return what;
}

unsigned app_reset(struct app *app)
{
    unsigned what = app_end_sweep(app, "the reset");
    restart(app);
    return what | APP_CHANGED_STATE;
}

double app_energy_drift(const struct app *app)
{
    struct energy e;
    sim_energy(app->sim, &e);
    return e.balance - app->energy0;
}

/* The state was put back from history (the sim re-anchored its drive's phase for the
 * frequency in force): the samples follow it. */
static void follow_restored(struct app *app)
{
    trail_follow(app->trail, app->sim);
    trail_follow(app->coarse, app->sim);
    app->runaway_base_ok = false; /* the books went back */
}

/* Counts the velocities the cap took in the last step and says so. */
static unsigned note_cap(struct app *app)
{
    int capped = sim_last_capped(app->sim);
    if (!capped)
        return 0;
    if (app->capped == 0)
        app->first_cap = sim_time(app->sim);
    app->capped += capped;
    return app_say(app, SAID_CAP, "the velocity cap (%g m/s) acted %ld time%s, first at "
                   "t = %.*f s", MODEL_VMAX, app->capped, app->capped == 1 ? "" : "s",
                   app_time_decimals(app->cfg.dt), app->first_cap);
}

unsigned app_step(struct app *app)
{
    bool unstable = limits_unstable(&app->limits), runaway = false;
    if (unstable && !app->runaway_base_ok) {
        struct energy e0;
        sim_energy(app->sim, &e0);
        limits_runaway_start(&app->runaway, app->model, &e0);
        app->runaway_base_ok = true;
    }
    history_push(app->hist, app->sim);
    bool bad = sim_step(app->sim) != SIM_OK;
    if (!bad && unstable) {
        struct energy e;
        sim_energy(app->sim, &e);
        runaway = limits_runaway_check(&app->runaway, &e);
    }
    /* Past the stability limit a capped velocity, or energy made from nothing, means the
     * numbers are running away (contacts can keep them from the cap). */
    if (bad || (unstable && (sim_last_capped(app->sim) || runaway))) {
        /* Back to the state before this step: the last one known to be sound. */
        history_pop(app->hist, app->sim);
        follow_restored(app);
        app->running = false;
        if (unstable && isfinite(app->stable_dt))
            app_say(app, SAID_ERROR, "unstable with %s: dt < %.3g s is stable; paused at t = %.2f s",
                    integrator_name(app->cfg.integrator), limits_round_down(app->stable_dt),
                    sim_time(app->sim));
        else
            app_say(app, SAID_ERROR, "unstable: the numbers ran away; paused at t = %.2f s",
                    sim_time(app->sim));
        return 0;
    }
    app->step_work = cost_last_step(app->sim); /* what the step cost (cost.h) */
    app->work += app->step_work;
    trail_tick(app->trail, &app->since_sample, app->sample_every, app->sim);
    trail_tick(app->coarse, &app->since_coarse, app->coarse_every, app->sim);
    unsigned what = APP_CHANGED_STATE | note_cap(app) | ghost_follow(app);
    const struct motor *drive = &sim_model(app->sim)->motor;
    double t = sim_time(app->sim);
    sweep_count_contacts(app->sweep, sim_last_contacts(app->sim) - sim_last_capped(app->sim));
    switch (sweep_update(app->sweep, t, sim_x(app->sim), drive->frequency * t + drive->phase)) {
    case SWEEP_RETUNE:
        what |= app_retune(app, sweep_frequency(app->sweep));
        break;
    case SWEEP_DONE:
        if (jump_two_way(app->model) && jump_turn(&app->sweep, &app->sweep_up, t)) {
            char a[32], b[32];
            what |= app_retune(app, sweep_frequency(app->sweep));
            what |= app_say(app, SAID_NOTE, "sweeping down %s..%s Hz, from the state the "
                            "sweep up ended in; %s stops it",
                            app_fixed(app->sweep->freq[0], 2, a, sizeof a),
                            app_fixed(app->sweep_up->freq[0], 2, b, sizeof b),
                            app_key(app, ACT_SWEEP));
            break;
        }
        what |= app_retune(app, app->sweep_from);
        char hint[64];
        if (app->sweep->unsteady > 0)
            what |= app_say(app, SAID_NOTE, "sweep done: %d frequencies, %d not steady in %.0f s; "
                            "back at %.3f Hz", app->sweep->points, app->sweep->unsteady,
                            app->sweep->most, app->sweep_from);
        else
            what |= app_say(app, SAID_NOTE, "sweep done: %d frequencies measured%s%s; back at "
                            "%.3f Hz", app->sweep->points,
                            sweep_measured(app->sweep_up) > 0 ? " up and down" : "",
                            app_key_hint(app, ACT_RESPONSE, "shows them", hint, sizeof hint),
                            app->sweep_from);
        break;
    default:
        break;
    }
    return what;
}

unsigned app_back(struct app *app)
{
    if (app->running) {
        char hint[32];
        app_say(app, SAID_ERROR, "pause first%s to step back",
                app_key_hint(app, ACT_RUN, NULL, hint, sizeof hint));
        return 0;
    }
    if (history_pop(app->hist, app->sim) != 0) {
        app_say(app, SAID_NOTE, sim_time(app->sim) <= 0.0 ? "at t = 0: nothing before it"
                                                       : "no earlier state kept (%d at most)",
                HISTORY_DEPTH);
        return 0;
    }
    follow_restored(app);
    unsigned what = APP_CHANGED_STATE | ghost_back(app);
    if (sim_dt(app->sim) != app->cfg.dt) {
        /* Stepped back past a change of dt: the state carries the dt it was made with. */
        struct config next = app->cfg;
        unsigned dt_changed = 0;
        next.dt = sim_dt(app->sim);
        app_change(app, &next, 0, NULL, &dt_changed);
        what |= dt_changed;
    }
    return what;
}

unsigned app_set_running(struct app *app, bool running)
{
    if (app->running == running)
        return 0;
    app->running = running;
    /* Running again shows the present. */
    if (running)
        app->scope.back = 0.0;
    return APP_CHANGED_PLAYBACK;
}

unsigned app_random(struct app *app)
{
    uint64_t seed = (uint64_t)time(NULL) * 6364136223846793005ULL + (uint64_t)clock();
    seed ^= app->cfg.seed * 0x9E3779B97F4A7C15ULL + 1;
    return app_random_seed(app, seed);
}

unsigned app_random_seed(struct app *app, uint64_t seed)
{
    app->cfg.seed = seed;
    app->cfg.random = true;
    fix_initial(app);
    for (int i = 0; i < app->model->n; i++)
        app->cfg.v0.v[i] = 0.0;
    unsigned what = app_reset(app);
    return what | app_say(app, SAID_NOTE, "random initial positions (seed %llu)",
                          (unsigned long long)seed);
}

unsigned app_place_mass(struct app *app, int i, double X)
{
    if (i < 0 || i >= app->model->n)
        return 0;
    return app_place_start(app, i, X - model_equilibrium(app->model, i));
}

unsigned app_place_start(struct app *app, int i, double x0)
{
    const struct model *m = app->model;
    int n = m->n;
    if (i < 0 || i >= n)
        return 0;
    if (app->running) {
        char hint[32];
        app_say(app, SAID_ERROR, "pause first%s to move a mass",
                app_key_hint(app, ACT_RUN, NULL, hint, sizeof hint));
        return 0;
    }
    double w = model_block_width(m), eq = model_equilibrium(m, i);
    const double *x = sim_x(app->sim);
    double lo = 0.5 * w, hi = MODEL_LENGTH - 0.5 * w;
    if (i > 0)
        lo = model_equilibrium(m, i - 1) + x[i - 1] + w;
    if (i < n - 1)
        hi = model_equilibrium(m, i + 1) + x[i + 1] - w;
    else if (m->boundary == BOUNDARY_FREE)
        hi = MODEL_LENGTH + 2.0;
    if (hi < lo)
        return 0;
    x0 = fmin(fmax(x0, lo - eq), hi - eq);
    /* The chain as it stands becomes the initial condition, at rest, at t = 0. */
    memcpy(app->cfg.x0.v, x, (size_t)n * sizeof *x);
    app->cfg.x0.v[i] = x0;
    app->cfg.x0.count = n;
    for (int j = 0; j < n; j++)
        app->cfg.v0.v[j] = 0.0;
    app->cfg.v0.count = n;
    app->cfg.random = false;
    unsigned what = app_reset(app);
    return what | app_say(app, SAID_NOTE, "mass %d starts at %+.2f m", i + 1, app->cfg.x0.v[i]);
}

unsigned app_move_mass(struct app *app, int i, double dx)
{
    if (i < 0 || i >= app->model->n)
        return 0;
    return app_place_mass(app, i, model_equilibrium(app->model, i) + sim_x(app->sim)[i] + dx);
}
