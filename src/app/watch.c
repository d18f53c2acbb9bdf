/* watch.c: the plain mode's events (watch.h says what each one is and why it is not
 * noisy). */
#include "watch.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "../core/collision.h"
#include "../core/modes.h"

int watch_on_mode(const struct app *app)
{
    const struct model *m = app->model;
    if (!app->modes_ok || !model_driven(m))
        return -1;
    int j = modes_nearest(app->modes, m->n, m->motor.frequency);
    return fabs(m->motor.frequency - app->modes[j]) <= WATCH_ON_MODE * app->modes[j] ? j : -1;
}

/* The state as it is now, the peaks forgotten if clear. */
static void take(struct watch *w, const struct app *app, bool clear)
{
    const struct sim *s = app->sim;
    int n = sim_model(s)->n;
    if (n != w->n)
        clear = true;
    w->n = n;
    w->t = sim_time(s);
    memcpy(w->x, sim_x(s), (size_t)n * sizeof *w->x);
    memcpy(w->v, sim_v(s), (size_t)n * sizeof *w->v);
    if (clear) {
        /* The start's displacement is the first peak to beat. */
        for (int i = 0; i < n; i++)
            w->largest[i] = fabs(w->x[i]);
        memset(w->peak, 0, sizeof w->peak);
        memset(w->touching, 0, sizeof w->touching);
        w->second = w->t;
        w->told = w->held = 0;
    }
}

void watch_init(struct watch *w, const struct app *app)
{
    memset(w, 0, sizeof *w);
    w->burst = WATCH_CONTACT_BURST;
    take(w, app, true);
    w->on_mode = watch_on_mode(app);
}

/* Reports the drive coming onto a natural frequency. */
static void look_drive(struct watch *w, const struct app *app, watch_say *say, void *ctx)
{
    int j = watch_on_mode(app);
    if (j >= 0 && j != w->on_mode) {
        char line[160];
        snprintf(line, sizeof line, "resonance: the drive at %.4g Hz is on natural frequency "
                 "%d (%.4g Hz, within %g %%)", app->model->motor.frequency, j + 1,
                 app->modes[j], 100.0 * WATCH_ON_MODE);
        say(ctx, line);
    }
    w->on_mode = j;
}

/* At the end of a second of simulated time: the contacts held back in it, in one line. */
static void close_second(struct watch *w, double t, watch_say *say, void *ctx)
{
    if (t < w->second + 1.0)
        return;
    if (w->held > 0) {
        char line[120];
        snprintf(line, sizeof line, "contact: %d more from t = %.2f to %.2f s", w->held,
                 w->second, w->second + 1.0);
        say(ctx, line);
    }
    w->second += floor(t - w->second);
    w->told = w->held = 0;
}

/* The constraint of a step's contacts: the one nearest to touching at its end. */
static void look_contacts(struct watch *w, const struct app *app, watch_say *say, void *ctx)
{
    const struct sim *s = app->sim;
    close_second(w, sim_time(s), say, ctx);
    const struct model *m = sim_model(s);
    const struct collision_limits *l = sim_limits(s);
    bool now[APP_MAX_MASSES + 1] = {false};
    if (l->on && sim_last_contacts(s) > sim_last_capped(s)) {
        int k = 0;
        double least = INFINITY, u = sim_end_position(s);
        for (int c = 0; c < l->count; c++) {
            double g = collision_gap(l, c, sim_x(s), u);
            if (g < least)
                least = g, k = c;
            now[c] = g <= 1e-9;
        }
        now[k] = true;
        if (!w->touching[k] && w->told >= w->burst) {
            w->held++;
        } else if (!w->touching[k]) {
            w->told++;
            char line[120];
            if (k == 0)
                snprintf(line, sizeof line, "contact: mass 1 and the left wall");
            else if (k < m->n)
                snprintf(line, sizeof line, "contact: masses %d and %d", k, k + 1);
            else
                snprintf(line, sizeof line, "contact: mass %d and the %s", m->n,
                         m->boundary == BOUNDARY_MOTOR ? "piston" : "right wall");
            say(ctx, line);
        }
    }
    memcpy(w->touching, now, sizeof now);
}

/* Turning points whose |x| is a peak worth saying: a new largest one, or, with no drive,
 * one WATCH_PEAK_RISE below (or above) the last one said (or the start). */
static void look_peaks(struct watch *w, const struct app *app, watch_say *say, void *ctx)
{
    const struct model *m = app->model;
    bool free = !model_driven(m);
    const double *x = sim_x(app->sim), *v = sim_v(app->sim);
    for (int i = 0; i < w->n; i++) {
        bool turned = (w->v[i] > 0.0 && v[i] <= 0.0) || (w->v[i] < 0.0 && v[i] >= 0.0);
        double a = fmax(fabs(x[i]), fabs(w->x[i]));
        if (!turned || a < WATCH_PEAK_MIN)
            continue;
        double last = w->peak[i] > 0.0 ? w->peak[i] : w->largest[i];
        char line[160];
        /* The first swing back from a release reaches the start's |x| only to within the
         * sampling: that is still the largest. */
        if (a >= w->largest[i] * (1.0 + WATCH_PEAK_RISE) ||
            (w->peak[i] == 0.0 && a >= w->largest[i] * (1.0 - WATCH_PEAK_SAME)))
            snprintf(line, sizeof line, "peak: mass %d |x| = %.4f m, the largest since t = 0",
                     i + 1, a);
        else if (free && a <= last * (1.0 - WATCH_PEAK_RISE))
            snprintf(line, sizeof line, "peak: mass %d |x| = %.4f m, falling from %.4f m", i + 1,
                     a, last);
        else if (free && a >= last * (1.0 + WATCH_PEAK_RISE))
            snprintf(line, sizeof line, "peak: mass %d |x| = %.4f m, growing from %.4f m", i + 1,
                     a, last);
        else
            continue;
        say(ctx, line);
        w->peak[i] = a;
        w->largest[i] = fmax(w->largest[i], a);
    }
}

void watch_step(struct watch *w, const struct app *app, watch_say *say, void *ctx)
{
    if (sim_model(app->sim)->n != w->n) {
        watch_look(w, app, say, ctx);
        return;
    }
    look_contacts(w, app, say, ctx);
    look_peaks(w, app, say, ctx);
    take(w, app, false);
    look_drive(w, app, say, ctx);
}

void watch_look(struct watch *w, const struct app *app, watch_say *say, void *ctx)
{
    double t = sim_time(app->sim);
    take(w, app, t <= 0.0 && t != w->t);
    look_drive(w, app, say, ctx);
}
