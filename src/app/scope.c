/* scope.c: time cursors on the recorded samples, the window scrolled back while paused,
 * and the measurements over it. A cursor is kept as its distance before the window's
 * right edge and read from the recorded sample nearest to where that puts it, so it keeps
 * its place on the plot while the chain runs and always reads a sample as recorded. */
#include "scope.h"

#include <math.h>

#include "../core/modes.h"
#include "app.h"
#include "action.h"

#define EPS 1e-9 /* s: times closer than this are the same sample's */

/* Seconds between the samples of tr. */
static double spacing(const struct app *app, const struct trail *tr)
{
    return (tr == app->trail ? app->sample_every : app->coarse_every) * app->cfg.dt;
}

double scope_oldest(const struct app *app)
{
    double t = sim_time(app->sim);
    if (app->coarse->count > 0)
        t = fmin(t, trail_time(app->coarse, 0));
    if (app->trail->count > 0)
        t = fmin(t, trail_time(app->trail, 0));
    return t;
}

/* How far back the window's right edge may go: the window's left edge at the oldest
 * sample recorded. */
static double max_back(const struct app *app)
{
    double b = sim_time(app->sim) - app_window(app) - scope_oldest(app);
    return b > 0.0 ? b : 0.0;
}

/* The samples for a window starting at start: the fine ones where they reach back that
 * far (or have dropped nothing yet) and the window is one they serve, else the coarse. */
static const struct trail *trail_for(const struct app *app, double start)
{
    const struct trail *f = app->trail;
    if (app_trail(app) != f)
        return app->coarse;
    if (f->count < f->capacity || (f->count > 0 && start >= trail_time(f, 0) - EPS))
        return f;
    return app->coarse;
}

/* The window's right edge, scope.back held to what is recorded (0 while running). */
static double held_back(const struct app *app)
{
    double b = app->running ? 0.0 : app->scope.back;
    double m = max_back(app);
    return b < 0.0 ? 0.0 : b > m ? m : b;
}

void scope_view(const struct app *app, struct scope_view *v)
{
    double back = held_back(app);
    v->window = app_window(app);
    v->end = sim_time(app->sim) - back;
    v->start = v->end - v->window;
    v->live = back == 0.0;
    v->trail = trail_for(app, v->start);
    int i = trail_index(v->trail, v->start - EPS), j = trail_index(v->trail, v->end + EPS);
    v->rec = trail_first(v->trail) + (size_t)i * v->trail->width;
    v->count = j - i;
}

/* Index in v's trail of the record cursor k sits on, or -1. */
static int cursor_index(const struct app *app, const struct scope_view *v, int k)
{
    if (k < 0 || k >= app->scope.cursors || v->count == 0)
        return -1;
    double t = v->end - app->scope.at[k];
    int first = (int)((v->rec - trail_first(v->trail)) / v->trail->width);
    int i = trail_nearest(v->trail, t);
    /* Inside the window: the nearest of the records the plot shows. */
    if (i < first)
        i = first;
    if (i > first + v->count - 1)
        i = first + v->count - 1;
    return i;
}

const double *scope_record(const struct app *app, const struct scope_view *v, int k)
{
    int i = cursor_index(app, v, k);
    return i < 0 ? NULL : trail_first(v->trail) + (size_t)i * v->trail->width;
}

/* Puts the active cursor at time t, the window following it while paused (within what
 * is recorded), held inside the window while running. */
static unsigned place(struct app *app, double t)
{
    struct scope *s = &app->scope;
    double now = sim_time(app->sim), w = app_window(app);
    double back = held_back(app), end = now - back;
    if (!app->running && t > end + EPS)
        back = now - t;
    else if (!app->running && t < end - w - EPS)
        back = now - t - w;
    double m = max_back(app);
    back = back < 0.0 ? 0.0 : back > m ? m : back;
    end = now - back;
    double at = end - t;
    at = at < 0.0 ? 0.0 : at > w ? w : at;
    unsigned what = back != s->back ? APP_CHANGED_WINDOW : 0;
    if (at != s->at[s->active])
        what |= APP_CHANGED_WINDOW;
    s->back = back;
    s->at[s->active] = at;
    return what;
}

unsigned scope_move(struct app *app, int n)
{
    struct scope_view v;
    scope_view(app, &v);
    int i = cursor_index(app, &v, app->scope.active);
    if (i < 0)
        return 0;
    const struct trail *tr = v.trail;
    int j = i + n;
    if (j < 0 && tr == app->trail && app->coarse->count > 0) {
        /* Older than the fine samples: on along the coarse ones. */
        double t = trail_time(tr, i);
        tr = app->coarse;
        j = trail_nearest(tr, t) + n;
        while (j > 0 && trail_time(tr, j) >= t - EPS)
            j--;
    }
    if (j < 0)
        j = 0;
    if (j > tr->count - 1)
        j = tr->count - 1;
    unsigned what = place(app, trail_time(tr, j));
    if (!what)
        what = app_say(app, SAID_NOTE, n < 0 ? "the cursor is at the oldest sample the window "
                       "can show" : "the cursor is at the newest sample");
    return what;
}

unsigned scope_jump(struct app *app, int dir)
{
    struct scope_view v;
    scope_view(app, &v);
    const double *r = scope_record(app, &v, app->scope.active);
    if (!r)
        return 0;
    double t = r[TRAIL_T] + dir * 0.1 * v.window;
    /* Onto a recorded sample: the nearest in the trail the window there will use. */
    const struct trail *tr = trail_for(app, fmin(t, v.start));
    int j = trail_nearest(tr, t);
    return j < 0 ? 0 : place(app, trail_time(tr, j));
}

unsigned scope_page(struct app *app, int dir)
{
    char hint[32];
    if (app->running)
        return app_say(app, SAID_NOTE, "pause%s to scroll back through the recording",
                       app_key_hint(app, ACT_RUN, NULL, hint, sizeof hint));
    double back = held_back(app) - dir * app_window(app), m = max_back(app);
    back = back < 0.0 ? 0.0 : back > m ? m : back;
    if (back == app->scope.back)
        return app_say(app, SAID_NOTE, dir < 0 ? "the window is at the oldest sample recorded"
                       : "the window is at the present");
    app->scope.back = back;
    return APP_CHANGED_WINDOW;
}

unsigned scope_toggle(struct app *app, int mass)
{
    struct scope *s = &app->scope;
    double w = app_window(app);
    if (mass >= 0)
        s->mass = mass;
    if (s->cursors == 0) {
        s->cursors = 1, s->active = 0;
        s->at[0] = 0.5 * w;
    } else if (s->cursors == 1) {
        s->cursors = 2, s->active = 1;
        /* A tenth of the window after the first; before it where there is no room. */
        s->at[1] = s->at[0] >= 0.1 * w ? s->at[0] - 0.1 * w : s->at[0] + 0.1 * w;
    } else {
        s->cursors = 0;
    }
    return APP_CHANGED_WINDOW;
}

unsigned scope_clear(struct app *app)
{
    if (app->scope.cursors == 0)
        return 0;
    app->scope.cursors = 0;
    return APP_CHANGED_WINDOW;
}

int scope_mass(const struct app *app)
{
    int i = app->scope.mass, n = app->model->n;
    return i < 0 ? 0 : i >= n ? n - 1 : i;
}

unsigned scope_select(struct app *app, int dir)
{
    int i = scope_mass(app) + dir;
    if (i < 0 || i >= app->model->n)
        return 0;
    app->scope.mass = i;
    return APP_CHANGED_WINDOW;
}

void scope_measure(const struct scope_view *v, int i, struct measure *m)
{
    const struct trail *tr = v->trail;
    measure_series(m, v->rec + TRAIL_T, v->rec + TRAIL_X(tr, i), v->count, (size_t)tr->width);
}

/* The force input's value at time t: measure_drive_at's drive. */
static double force_at(const void *model, double t)
{
    return model_force(model, t);
}

void scope_motion(const struct app *app, const struct scope_view *v, int i,
                  struct scope_motion *out)
{
    const struct model *model = app->model;
    const struct trail *tr = v->trail;
    *out = (struct scope_motion){.mode = -1, .theory_zeta = NAN, .theory_ratio = NAN,
                                 .theory_phase = NAN};
    scope_measure(v, i, &out->m);
    bool motor = model_motor_moves(model);
    out->driven = model_driven(model);
    out->by_force = out->driven && !motor;
    out->linearised = model->cubic;
    if (out->driven) {
        out->hz = model->motor.frequency;
        const double *t = v->rec + TRAIL_T, *x = v->rec + TRAIL_X(tr, i);
        if (motor)
            measure_drive(&out->d, t, x, v->rec + TRAIL_U, v->count, (size_t)tr->width,
                          out->hz);
        else
            measure_drive_at(&out->d, t, x, force_at, model, v->count, (size_t)tr->width,
                             out->hz);
        double amp[APP_MAX_MASSES], phase[APP_MAX_MASSES];
        if (model->n <= APP_MAX_MASSES && modes_response_phase(model, out->hz, amp, phase) == 0) {
            out->theory_ratio = amp[i] / fabs(motor ? model->motor.amplitude : model->force);
            out->theory_phase = phase[i];
        }
    }
    out->kind = measure_motion(&out->m, out->driven ? &out->d : NULL);
    out->mode = scope_nearest_mode(app, out->m.frequency);
    if (out->mode >= 0 && app->damping_ok)
        out->theory_zeta = app->damping_ratio[out->mode];
}

int scope_nearest_mode(const struct app *app, double hz)
{
    if (!app->modes_ok || !isfinite(hz))
        return -1;
    int best = -1;
    double gap = INFINITY;
    for (int j = 0; j < app->model->n; j++) {
        double f = app->damping_ok && app->damped_hz[j] > 0.0 ? app->damped_hz[j] : app->modes[j];
        if (fabs(f - hz) < gap)
            gap = fabs(f - hz), best = j;
    }
    return best;
}

const double *scope_at_time(const struct app *app, double t, const struct trail **trail)
{
    const struct trail *tr = app->trail;
    if (tr->count == 0 || t < trail_time(tr, 0) - 0.5 * spacing(app, tr) - EPS)
        tr = app->coarse;
    int i = trail_nearest(tr, t);
    if (i < 0 || fabs(trail_time(tr, i) - t) > 0.5 * spacing(app, tr) + EPS)
        return NULL;
    *trail = tr;
    return trail_first(tr) + (size_t)i * tr->width;
}
