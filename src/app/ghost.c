/* ghost.c: the ghost, a frozen copy of the chain run beside it (ghost.h says what it
 * does in time). app.c calls in here at each step, step back and reset; this file calls
 * nothing of app.c's. */
#include "ghost.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cost.h"

static void ghost_free(struct ghost *g)
{
    if (!g)
        return;
    trail_free(g->trail);
    trail_free(g->coarse);
    history_free(g->hist);
    sim_free(g->sim);
    free(g);
}

/* Records of a trail sampled every `every` steps of dt that span what the app's trail of
 * capacity records spaced at least spacing apart spans, at most that capacity: the
 * ghost's dt never changes, so at dt = 0.01 its fine samples need a quarter of the room. */
static int records(int capacity, double spacing, int every, double dt)
{
    double need = ceil(capacity * spacing / (every * dt)) + 1.0;
    return need < capacity ? (int)need : capacity;
}

/* A ghost of the app's chain as it is now, or NULL on no memory (nothing kept). */
static struct ghost *ghost_new(const struct app *app)
{
    const struct model *live = sim_model(app->sim);
    double dt = sim_dt(app->sim);
    struct ghost *g = calloc(1, sizeof *g);
    if (!g)
        return NULL;
    g->cfg = app->cfg;
    g->sim = sim_new(live, dt);
    g->hist = g->sim ? history_new(g->sim, HISTORY_DEPTH) : NULL;
    /* No energy plot shows the ghost: its samples keep the motion alone. */
    g->trail = trail_new_motion(live->n, records(TRAIL_FINE_RECORDS, TRAIL_FINE_SPACING,
                                                 app->sample_every, dt));
    g->coarse = trail_new_motion(live->n, records(TRAIL_COARSE_RECORDS, TRAIL_COARSE_SPACING,
                                                  app->coarse_every, dt));
    /* Everything the live chain carries from step to step, so the two step alike. */
    if (!g->hist || !g->trail || !g->coarse || sim_copy(g->sim, app->sim) != 0) {
        ghost_free(g);
        return NULL;
    }
    g->model = sim_model(g->sim);
    g->unstable = limits_unstable(&app->limits);
    g->sample_every = app->sample_every;
    g->since_sample = app->since_sample;
    g->coarse_every = app->coarse_every;
    g->since_coarse = app->since_coarse;
    trail_push(g->trail, g->sim);
    trail_push(g->coarse, g->sim);
    return g;
}

unsigned ghost_drop(struct app *app, const char *why)
{
    if (!app->ghost)
        return 0;
    ghost_free(app->ghost);
    app->ghost = NULL;
    return APP_CHANGED_GHOST | (why ? app_say(app, SAID_NOTE, "ghost dropped %s", why) : 0);
}

unsigned app_toggle_ghost(struct app *app)
{
    if (app->ghost)
        return ghost_drop(app, "(again makes a new one)");
    app->ghost = ghost_new(app);
    if (!app->ghost)
        return app_say(app, SAID_ERROR, "out of memory: no ghost");
    return APP_CHANGED_GHOST |
           app_say(app, SAID_NOTE, "ghost made at t = %.2f s: it keeps these settings; change the "
                   "chain's and watch the two part (again drops it)", sim_time(app->sim));
}

unsigned ghost_follow(struct app *app)
{
    struct ghost *g = app->ghost;
    if (!g)
        return 0;
    history_push(g->hist, g->sim);
    double t = sim_time(app->sim);
    /* Its own steps up to the one nearest the live time. */
    while (sim_time(g->sim) + 0.5 * sim_dt(g->sim) <= t) {
        if (sim_step(g->sim) != SIM_OK || (g->unstable && sim_last_capped(g->sim))) {
            char why[160];
            snprintf(why, sizeof why, "at t = %.2f s: its numbers ran away (%s, dt %g s); "
                     "the chain goes on", sim_time(g->sim), integrator_name(g->cfg.integrator),
                     g->cfg.dt);
            return ghost_drop(app, why);
        }
        app->work += cost_last_step(g->sim); /* a lesson's compute counts the ghost's too */
        trail_tick(g->trail, &g->since_sample, g->sample_every, g->sim);
        trail_tick(g->coarse, &g->since_coarse, g->coarse_every, g->sim);
    }
    return 0;
}

unsigned ghost_back(struct app *app)
{
    struct ghost *g = app->ghost;
    if (!g)
        return 0;
    if (history_pop(g->hist, g->sim) != 0)
        return ghost_drop(app, "(stepped back past the instant it was made)");
    trail_follow(g->trail, g->sim);
    trail_follow(g->coarse, g->sim);
    return 0;
}

void ghost_restart(struct app *app)
{
    struct ghost *g = app->ghost;
    if (!g)
        return;
    sim_set_phase(g->sim, 0.0);
    sim_set_dt(g->sim, g->cfg.dt);
    sim_reset(g->sim, g->cfg.x0.v, g->cfg.v0.v);
    history_clear(g->hist);
    trail_clear(g->trail);
    trail_clear(g->coarse);
    g->since_sample = g->since_coarse = 0;
    trail_push(g->trail, g->sim);
    trail_push(g->coarse, g->sim);
}

/* Appends printf-style text to buf, which holds *used characters, as far as it fits. */
static void add(char *buf, size_t len, size_t *used, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));

static void add(char *buf, size_t len, size_t *used, const char *fmt, ...)
{
    if (*used >= len)
        return;
    va_list ap;
    va_start(ap, fmt);
    int k = vsnprintf(buf + *used, len - *used, fmt, ap);
    va_end(ap);
    if (k > 0)
        *used += (size_t)k;
}

/* Appends " name value" for the ghost's list g (n values) where it differs from the
 * live one l: the value when all of g's are the same, else "per element". */
static void add_list(char *buf, size_t len, size_t *used, const char *name, const double *g,
                     const double *l, int n)
{
    bool differ = false, uniform = true;
    for (int i = 0; i < n; i++) {
        differ |= g[i] != l[i];
        uniform &= g[i] == g[0];
    }
    if (!differ)
        return;
    if (uniform)
        add(buf, len, used, " %s %.3g", name, g[0]);
    else
        add(buf, len, used, " %s per element", name);
}

void ghost_describe(const struct app *app, char *buf, size_t len)
{
    const struct ghost *g = app->ghost;
    size_t used = 0;
    buf[0] = '\0';
    add(buf, len, &used, "ghost");
    if (!g)
        return;
    const struct model *a = g->model, *b = app->model;
    size_t bare = used;
    add_list(buf, len, &used, "c", a->c, b->c, a->n);
    add_list(buf, len, &used, "k", a->k, b->k, a->n + 1);
    add_list(buf, len, &used, "m", a->m, b->m, a->n);
    if (a->collisions != b->collisions)
        add(buf, len, &used, " collisions %s", a->collisions ? "on" : "off");
    if (a->boundary != b->boundary)
        add(buf, len, &used, " %s end", model_boundary_name(a->boundary));
    else if (a->boundary == BOUNDARY_MOTOR) {
        if (a->motor.wave != b->motor.wave)
            add(buf, len, &used, " %s", motor_wave_name(a->motor.wave));
        if (a->motor.frequency != b->motor.frequency)
            add(buf, len, &used, " %.3g Hz", a->motor.frequency);
        if (a->motor.amplitude != b->motor.amplitude)
            add(buf, len, &used, " A %.3g m", a->motor.amplitude);
    }
    if (g->cfg.dt != app->cfg.dt)
        add(buf, len, &used, " dt %g", g->cfg.dt);
    if (g->cfg.integrator != app->cfg.integrator)
        add(buf, len, &used, " %s", integrator_name(g->cfg.integrator));
    int n = a->n;
    if (memcmp(g->cfg.x0.v, app->cfg.x0.v, (size_t)n * sizeof(double)) != 0 ||
        memcmp(g->cfg.v0.v, app->cfg.v0.v, (size_t)n * sizeof(double)) != 0)
        add(buf, len, &used, " own start");
    if (used == bare)
        add(buf, len, &used, " = live");
}
