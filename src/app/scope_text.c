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

double scope_theory_zeta(const struct app *app, const struct measure *m, int *mode)
{
    *mode = scope_nearest_mode(app, m->frequency);
    return *mode >= 0 && app->damping_ok ? app->damping_ratio[*mode] : NAN;
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
    struct measure m;
    scope_view(app, &v);
    scope_measure(&v, i, &m);
    int d = app_time_decimals(app->cfg.dt);
    size_t used = (size_t)snprintf(buf, len, "measure: mass %d, %.*f to %.*f s, %d samples: "
                                   "peak-to-peak %.6g m, rms %.6g m", i + 1, d,
                                   fmax(v.start, scope_oldest(app)), d, v.end, m.samples,
                                   m.p2p, m.rms);
    if (used >= len)
        return true;
    if (m.peaks < 2) {
        snprintf(buf + used, len - used, ", not enough peaks (%d) for a period or a decrement",
                 m.peaks);
        return true;
    }
    used += (size_t)snprintf(buf + used, len - used, ", %d peaks, period %.6g s, frequency "
                             "%.6g Hz", m.peaks, m.period, m.frequency);
    if (used >= len)
        return true;
    if (isnan(m.delta)) {
        snprintf(buf + used, len - used, ", no decrement (a peak at or below 0)");
        return true;
    }
    int mode;
    double z = scope_theory_zeta(app, &m, &mode);
    used += (size_t)snprintf(buf + used, len - used, ", delta %.6g, zeta %.6g", m.delta,
                             m.zeta);
    if (used < len && mode >= 0 && !isnan(z))
        snprintf(buf + used, len - used, " (theory, mode %d: zeta %.6g)", mode + 1, z);
    return true;
}
