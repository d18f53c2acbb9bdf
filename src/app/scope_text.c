/* scope_text.c: the scope in words: the plain mode's `cursor T` and `measure`, and
 * numbers cut to a column without losing their magnitude. */
#include "scope_text.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "app.h"
#include "scope.h"

int scope_number(char *buf, size_t len, double v, int width)
{
    if (!isfinite(v)) {
        snprintf(buf, len, "%s", isnan(v) ? "-" : v > 0 ? "inf" : "-inf");
        return 0;
    }
    int d = 6;
    for (; d > 2; d--)
        if (snprintf(buf, len, "%.*g", d, v + 0.0) <= width)
            return d;
    snprintf(buf, len, "%.*g", d, v + 0.0);
    return d;
}

bool scope_say_cursor(const struct app *app, const char *text, char *buf, size_t len)
{
    double t;
    const char *why = config_parse_number(text, &t);
    double oldest = scope_oldest(app), now = sim_time(app->sim);
    int d = app_time_decimals(app->cfg.dt);
    const struct trail *tr = NULL;
    const double *r = why ? NULL : scope_at_time(app, t, &tr);
    if (!r) {
        char q[4 * CONFIG_QUOTE_MAX + 48];
        config_quote(text, strlen(text), q, sizeof q);
        snprintf(buf, len, "cursor: %s %s (expected a time recorded, %.*f <= T <= %.*f s)", q,
                 why ? why : "is not recorded", d, oldest, d, now);
        return false;
    }
    int n = tr->n;
    size_t used = (size_t)snprintf(buf, len, "cursor: t=%.12g", r[TRAIL_T]);
    static const char *const q[3] = {"x", "v", "a"};
    for (int k = 0; k < 3; k++)
        for (int i = 0; i < n && used < len; i++) {
            int at = k == 0 ? TRAIL_X(tr, i) : k == 1 ? TRAIL_V(tr, i) : TRAIL_A(tr, i);
            used += (size_t)snprintf(buf + used, len - used, " %s%d=%.12g", q[k], i + 1,
                                     r[at] + 0.0);
        }
    if (used < len)
        snprintf(buf + used, len - used, " motor=%.12g", r[TRAIL_U] + 0.0);
    return true;
}

const char *scope_motion_name(const struct scope_motion *sm)
{
    switch (sm->kind) {
    case MOTION_DECAY:
        return "free decay";
    case MOTION_STEADY:
        return sm->driven ? "driven steady state" : "free, peaks level";
    case MOTION_TRANSIENT:
        return "transient";
    case MOTION_UNKNOWN:
        break;
    }
    return sm->driven ? "driven, too few drive periods shown" : "too few peaks";
}

const char *scope_peaks_word(const struct measure *m)
{
    return m->rising ? "peaks growing" : m->falling ? "peaks falling" : "peaks uneven";
}

/* The kind of motion and what it measures, after `measure`'s common part. */
static void say_kind(const struct scope_motion *sm, char *buf, size_t len)
{
    const struct measure *m = &sm->m;
    const struct measure_drive *d = &sm->d;
    int pct = (int)lround(100.0 * MEASURE_LEVEL);
    switch (sm->kind) {
    case MOTION_DECAY: {
        size_t used = (size_t)snprintf(buf, len, "; free decay (peaks falling): delta %.6g, "
                                       "zeta %.6g", m->delta, m->zeta);
        if (used < len && sm->mode >= 0 && !isnan(sm->theory_zeta))
            snprintf(buf + used, len - used, " (theory, mode %d: zeta %.6g)", sm->mode + 1,
                     sm->theory_zeta);
        return;
    }
    case MOTION_STEADY:
        if (!sm->driven) {
            size_t used = (size_t)snprintf(buf, len, "; free, peaks level within %d %%: no "
                                           "decay to measure", pct);
            if (used < len && sm->mode >= 0 && !isnan(sm->theory_zeta))
                snprintf(buf + used, len - used, " (theory, mode %d: zeta %.6g)",
                         sm->mode + 1, sm->theory_zeta);
            return;
        }
        snprintf(buf, len, "; driven steady state (swings level within %d %% over %d drive "
                 "periods): amplitude %.6g m, phase %.4g deg to the %s, ratio %.6g%s to the "
                 "%s's (%stheory at %.6g Hz: amplitude %.6g m, phase %.4g deg, ratio %.6g%s)",
                 pct, d->periods, d->amplitude, d->phase, sm->by_force ? "force" : "motor",
                 d->ratio, sm->by_force ? " m/N" : "", sm->by_force ? "force" : "motor",
                 sm->linearised ? "linearised " : "", sm->hz, sm->theory_ratio * d->drive, sm->theory_phase, sm->theory_ratio,
                 sm->by_force ? " m/N" : "");
        return;
    case MOTION_TRANSIENT:
        snprintf(buf, len, "; transient: not a free decay, not steady (%s%s)",
                 scope_peaks_word(m), sm->driven ? ", swings not level" : "");
        return;
    case MOTION_UNKNOWN:
        break;
    }
    if (m->peaks < 2)
        snprintf(buf, len, ", not enough peaks (%d) for a period or a decrement", m->peaks);
    else
        snprintf(buf, len, "; fewer than 2 drive periods in the window: not yet told whether "
                 "steady");
}

bool scope_say_measure(struct app *app, const char *text, char *buf, size_t len)
{
    int n = app->model->n, i = scope_mass(app);
    if (*text) {
        double v;
        if (config_parse_number(text, &v) || v != floor(v) || v < 1 || v > n) {
            char q[4 * CONFIG_QUOTE_MAX + 48];
            config_quote(text, strlen(text), q, sizeof q);
            snprintf(buf, len, "measure: %s is not a mass of this chain (expected 1 <= MASS <= "
                     "%d)", q, n);
            return false;
        }
        i = (int)v - 1;
        app->scope.mass = i;
    }
    struct scope_view v;
    struct scope_motion sm;
    scope_view(app, &v);
    scope_motion(app, &v, i, &sm);
    const struct measure *m = &sm.m;
    int d = app_time_decimals(app->cfg.dt);
    size_t used = (size_t)snprintf(buf, len, "measure: mass %d, %.*f to %.*f s, %d samples: "
                                   "peak-to-peak %.6g m, rms %.6g m", i + 1, d,
                                   fmax(v.start, scope_oldest(app)), d, v.end, m->samples,
                                   m->p2p, m->rms);
    if (used < len && m->peaks >= 2)
        used += (size_t)snprintf(buf + used, len - used, ", %d peaks, period %.6g s, frequency "
                                 "%.6g Hz", m->peaks, m->period, m->frequency);
    if (used < len)
        say_kind(&sm, buf + used, len - used);
    return true;
}
