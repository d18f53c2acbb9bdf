/* controls.c: the controls panel's table (labels, ranges, steps, units) and what
 * adjusting or typing a control, editing one element of the chain or choosing the
 * nearest mode does; every parameter change goes through app_change (app.c). */
#include "change.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../core/modes.h"

/* One row per control, the one place a control is described: what the panel calls it,
 * the name `set` takes (NULL: its setting's), the setting it shows and sets (NONE: the
 * app's own, the speed), what a change of it ends a sweep with (NULL: none), whether it
 * is the front end's alone (set in place, the chain untouched), and a numeric control's
 * arrows: their range inside the setting's, fine and coarse steps. Units, decimals,
 * ranges, choices and the checks of a typed value come from the setting's row (config.c). */
#define NONE (-1)
static const struct control_row {
    const char *label;
    const char *name;
    int key;
    const char *why;
    bool front;
    double lo, hi, fine, coarse;
} rows[CTL_COUNT] = {
    [CTL_PRESET] = {"Preset", NULL, CFG_PRESET, NULL, false, 0, 0, 0, 0},
    [CTL_MASSES] = {"Masses", NULL, CFG_MASSES, "the new number of masses", false, 0, 0, 0, 0},
    [CTL_DT] = {"dt", NULL, CFG_DT, "the change of dt", false, 0.0, INFINITY, 0.001, 0.005},
    [CTL_INTEGRATOR] = {"Integrator", NULL, CFG_INTEGRATOR, NULL, false, 0, 0, 0, 0},
    [CTL_DAMPING] = {"Damping", NULL, CFG_DAMPING, "the change of damping", false, 0.0, 2.0,
                     0.01, 0.1},
    [CTL_SPRING] = {"Spring k", NULL, CFG_SPRING, "the change of springs", false, 1.0, 50.0,
                    0.5, 5.0},
    [CTL_MASS] = {"Mass", NULL, CFG_MASS, "the change of masses", false, 0.1, 10.0, 0.1, 1.0},
    [CTL_BOUNDARY] = {"Right end", NULL, CFG_BOUNDARY, "the change of right end", false, 0, 0,
                      0, 0},
    [CTL_WAVE] = {"Waveform", NULL, CFG_WAVE, "the change of waveform", false, 0, 0, 0, 0},
    [CTL_AMPLITUDE] = {"Amplitude", NULL, CFG_AMPLITUDE, "the change of amplitude", false, 0.0,
                       3.0, 0.05, 0.5},
    [CTL_FREQUENCY] = {"Frequency", NULL, CFG_FREQUENCY, "the change of frequency", false,
                       APP_FMIN, APP_FMAX, 0.01, 0.1},
    [CTL_FORCE] = {"Force", NULL, CFG_FORCE, "the change of force", false, 0.0, 100.0, 0.1,
                   1.0},
    [CTL_FORCE_ON] = {"Force on", NULL, CFG_FORCE_ON, "the change of the forced mass", false,
                      0, 0, 0, 0},
    [CTL_SPEED] = {"Speed", "speed", NONE, NULL, true, 0, 0, 0, 0},
    [CTL_BANDWIDTH] = {"Refresh", "bandwidth", CFG_LOW_BANDWIDTH, NULL, true, 0, 0, 0, 0},
    [CTL_GRAPHICS] = {"Graphics", NULL, CFG_GRAPHICS, NULL, true, 0, 0, 0, 0},
};

/* Playback speeds offered by the Speed control. */
static const double speeds[] = {0.1, 0.2, 0.25, 0.5, 1.0, 2.0, 4.0, 5.0, 10.0};
#define NSPEEDS (int)(sizeof speeds / sizeof *speeds)

/* Whether a control is numeric: arrows that step its value. */
static bool numeric(enum control ctl)
{
    return rows[ctl].fine > 0.0;
}

/* The setting of a control that has one. */
static const struct config_option *setting(enum control ctl)
{
    return &config_options[rows[ctl].key];
}

/* The arrows' range of a numeric control, inside its setting's (interactive) range. */
static double arrow_lo(enum control ctl)
{
    const struct config_option *o = setting(ctl);
    return fmax(rows[ctl].lo, fmax(o->lo, o->ilo));
}

static double arrow_hi(enum control ctl)
{
    const struct config_option *o = setting(ctl);
    /* A list's row has a lower bound only (its hi is left 0). */
    double hi = o->ihi > 0.0 ? o->ihi : o->hi > o->lo ? o->hi : INFINITY;
    return fmin(rows[ctl].hi, hi);
}

const char *app_control_label(enum control ctl)
{
    return (unsigned)ctl < CTL_COUNT ? rows[ctl].label : "";
}

const char *app_control_name(enum control ctl)
{
    if ((unsigned)ctl >= CTL_COUNT)
        return "";
    return rows[ctl].name ? rows[ctl].name : setting(ctl)->name;
}

double app_freq_fraction(double f)
{
    return log(f / APP_FMIN) / log(APP_FMAX / APP_FMIN);
}

/* v with the control's decimals when they show it to 1 part in 1000 and it is under a
 * million, else in as few significant digits (up to 6) as show it as closely: 1e+308,
 * 1e-320, 0.125, never a long run of digits or a misleading 0.00; never -0. */
static void format_value(double v, int decimals, char *buf, size_t len)
{
    v += 0.0; /* -0 becomes 0 */
    snprintf(buf, len, "%.*f", decimals, v);
    if (v == 0.0 || (fabs(v) < 1e6 && fabs(strtod(buf, NULL) - v) <= 1e-3 * fabs(v)))
        return;
    for (int digits = 1; digits <= 6; digits++) {
        snprintf(buf, len, "%.*g", digits, v);
        if (fabs(strtod(buf, NULL) - v) <= 1e-3 * fabs(v))
            return;
    }
}

/* The common value of a per-element list, or NAN when they differ. */
static double common(const double *v, int n)
{
    for (int i = 1; i < n; i++)
        if (v[i] != v[0])
            return NAN;
    return v[0];
}

/* Sets one value for every element of a list. */
static void set_all(struct config_list *l, double v)
{
    l->count = 1;
    l->v[0] = v;
}

/* The values of a numeric control's setting in force (a list's one per element); a free
 * right end's last spring holds nothing and is left out. */
static void numeric_values(const struct app *app, enum control ctl, struct config_value *v)
{
    config_get(rows[ctl].key, &app->cfg, app->model, v);
    if (ctl == CTL_SPRING && app->model->boundary == BOUNDARY_FREE)
        v->count = app->model->n;
}

/* The current value of a numeric control (NAN for mixed per-element values). */
static double numeric_value(const struct app *app, enum control ctl)
{
    if (!numeric(ctl))
        return NAN;
    struct config_value v;
    numeric_values(app, ctl, &v);
    return common(v.v, v.count);
}

/* Puts a numeric control's value into the settings next: one value for every element of
 * a list. */
static void set_numeric(struct config *next, enum control ctl, double v)
{
    const struct config_option *o = setting(ctl);
    char *at = (char *)next + o->offset;
    if (o->kind == CONFIG_LIST)
        set_all((struct config_list *)(void *)at, v);
    else
        memcpy(at, &v, sizeof v);
}

/* Puts next in force for control ctl; what changed, 0 if refused. */
static unsigned change_control(struct app *app, struct config *next, enum control ctl)
{
    unsigned what = 0;
    unsigned how = ctl == CTL_FREQUENCY ? CHANGE_SETS_FREQUENCY : 0;
    app_change(app, next, how, rows[ctl].why, &what);
    return what;
}

/* n masses, every element taking the first one's values, at rest in equilibrium (the
 * page's "Apply Config"); -1 when refused. */
static int new_masses(struct app *app, int n, unsigned *what)
{
    *what = 0;
    if (n == app->model->n) {
        if (app->masses_pending != n)
            *what |= APP_CHANGED_PENDING;
        app->masses_pending = n;
        return 0;
    }
    struct config next = app->cfg;
    set_all(&next.mass, app->model->m[0]);
    set_all(&next.spring, app->model->k[0]);
    set_all(&next.spring_cubic, app->model->k3[0]);
    set_all(&next.damping, app->model->c[0]);
    next.masses = n;
    next.x0.count = next.v0.count = 0;
    next.random = false;
    bool moved = next.force_on > n; /* the force goes with the chain's end, to its last mass */
    next.force_on = moved ? n : next.force_on;
    bool ghost = app->ghost != NULL; /* a new chain drops it: said, or it vanishes unseen */
    if (app_change(app, &next, CHANGE_REBUILD, rows[CTL_MASSES].why, what) != 0)
        return -1;
    char on[64] = "";
    if (moved)
        snprintf(on, sizeof on, "; force-on %d now, the last mass", n);
    *what |= APP_CHANGED_PENDING |
             app_say(app, SAID_NOTE, "%d mass%s, at rest%s%s", n, n == 1 ? "" : "es", on,
                     ghost ? "; ghost dropped with the old chain" : "");
    return 0;
}

/* Puts next, which may differ from the settings in force in control ctl, one of the front
 * end's alone (refresh, graphics), in force: the chain is not touched. */
static unsigned set_front(struct app *app, enum control ctl, const struct config *next)
{
    struct config_value was, now;
    config_get(rows[ctl].key, &app->cfg, NULL, &was);
    config_get(rows[ctl].key, next, NULL, &now);
    if (strcmp(was.str, now.str) == 0)
        return 0;
    app->cfg = *next;
    return APP_CHANGED_PLAYBACK;
}

unsigned app_adjust(struct app *app, enum control ctl, int steps, bool coarse)
{
    struct config next = app->cfg;
    switch (ctl) {
    case CTL_MASSES: {
        int n = app->masses_pending + steps * (coarse ? 5 : 1);
        n = n < 1 ? 1 : n > APP_MAX_MASSES ? APP_MAX_MASSES : n; /* the table's ihi */
        if (n == app->masses_pending)
            return 0;
        app->masses_pending = n;
        if (n == app->model->n)
            return APP_CHANGED_PENDING;
        return APP_CHANGED_PENDING |
               app_say(app, SAID_NOTE, "Enter applies %d masses (a reset)", app->masses_pending);
    }
    case CTL_FORCE_ON: { /* a mass: 1 .. N, the arrows stop at the ends */
        int k = next.force_on + steps * (coarse ? 5 : 1);
        k = k < 1 ? 1 : k > app->model->n ? app->model->n : k;
        if (k == next.force_on)
            return 0;
        next.force_on = k;
        return change_control(app, &next, ctl);
    }
    case CTL_SPEED: {
        int i = 0;
        while (i < NSPEEDS - 1 && speeds[i] < app->speed - 1e-9)
            i++;
        i += steps * (coarse ? 2 : 1);
        double v = speeds[i < 0 ? 0 : i >= NSPEEDS ? NSPEEDS - 1 : i];
        if (v == app->speed)
            return 0;
        app->speed = v;
        return APP_CHANGED_PLAYBACK;
    }
    default:
        break;
    }
    if ((unsigned)ctl >= CTL_COUNT || rows[ctl].key == NONE)
        return 0;
    const struct config_option *o = setting(ctl);
    char *at = (char *)&next + o->offset;
    if (o->kind == CONFIG_CHOICE || o->kind == CONFIG_FLAG) {
        /* Round the choices (a flag: on and off), steps places. */
        int count = o->kind == CONFIG_FLAG ? 2 : o->choices, i;
        if (o->kind == CONFIG_FLAG)
            i = *(bool *)(void *)at;
        else
            memcpy(&i, at, sizeof i);
        i = (i + steps % count + count) % count;
        if (ctl == CTL_INTEGRATOR && i == INTEGRATOR_EXACT && app->model->cubic)
            i = (i + (steps < 0 ? -1 : 1) + count) % count; /* exact steps linear chains only */
        if (o->kind == CONFIG_FLAG)
            *(bool *)(void *)at = i;
        else
            memcpy(at, &i, sizeof i);
        return rows[ctl].front ? set_front(app, ctl, &next) : change_control(app, &next, ctl);
    }
    if (!numeric(ctl))
        return 0;
    double step = coarse ? rows[ctl].coarse : rows[ctl].fine;
    double v = numeric_value(app, ctl);
    if (isnan(v)) { /* mixed values: from the first element's */
        struct config_value first;
        numeric_values(app, ctl, &first);
        v = first.v[0];
    }
    /* Snap onto the step grid, then move. */
    v = round(v / step) * step + steps * step;
    v = fmin(fmax(v, arrow_lo(ctl)), arrow_hi(ctl));
    set_numeric(&next, ctl, v);
    return change_control(app, &next, ctl);
}

/* Says what a control was set to, unless the change had more to say. */
static unsigned say_set(struct app *app, enum control ctl, unsigned what)
{
    if (what & APP_CHANGED_MESSAGE)
        return what;
    char value[64];
    app_control_value(app, ctl, value, sizeof value);
    return what | app_say(app, SAID_NOTE, "%s %s", rows[ctl].label, value);
}

unsigned app_set_text(struct app *app, enum control ctl, const char *text)
{
    char err[300];
    if ((unsigned)ctl >= CTL_COUNT || ctl == CTL_PRESET)
        return 0;
    if (ctl == CTL_SPEED) {
        char *end;
        double v = strtod(text, &end);
        if (end != text && (*end == 'x' || *end == '\0') && (end[0] == '\0' || end[1] == '\0') &&
            v >= 0.1 && v <= 10.0) {
            unsigned what = v != app->speed ? APP_CHANGED_PLAYBACK : 0;
            app->speed = v;
            return say_set(app, ctl, what);
        }
        char q[4 * CONFIG_QUOTE_MAX + 48];
        config_quote(text, strlen(text), q, sizeof q);
        app_say(app, SAID_ERROR, "speed: %s is not a number from 0.1 to 10", q);
        return 0;
    }
    if (ctl == CTL_BANDWIDTH) {
        if (strcmp(text, "low") == 0 || strcmp(text, "normal") == 0) {
            bool low = text[0] == 'l';
            unsigned what = low != app->cfg.low_bandwidth ? APP_CHANGED_PLAYBACK : 0;
            app->cfg.low_bandwidth = low;
            return say_set(app, ctl, what);
        }
        char q[4 * CONFIG_QUOTE_MAX + 48];
        config_quote(text, strlen(text), q, sizeof q);
        app_say(app, SAID_ERROR, "refresh: %s is not low or normal", q);
        return 0;
    }
    /* Checked on a copy, so a bad value changes nothing. */
    struct config next = app->cfg;
    if (config_set(&next, rows[ctl].key, text, err, sizeof err) != 0) {
        app_say(app, SAID_ERROR, "%s: %s", setting(ctl)->name, err);
        return 0;
    }
    unsigned what = 0;
    if (rows[ctl].front) /* the front end follows it (tui.c); the chain is not touched */
        return say_set(app, ctl, set_front(app, ctl, &next));
    if (ctl == CTL_MASSES ? new_masses(app, next.masses, &what)
                          : app_change(app, &next, ctl == CTL_FREQUENCY ? CHANGE_SETS_FREQUENCY : 0,
                                       rows[ctl].why, &what))
        return 0;
    return say_set(app, ctl, what);
}

unsigned app_set_window(struct app *app, const char *text)
{
    struct config next = app->cfg;
    char err[300];
    if (config_set(&next, CFG_WINDOW, text, err, sizeof err) != 0) {
        app_say(app, SAID_ERROR, "window: %s", err);
        return 0;
    }
    unsigned what = next.window != app->cfg.window ? APP_CHANGED_WINDOW : 0;
    app->cfg.window = next.window;
    return what | app_say(app, SAID_NOTE, "window %g s", next.window);
}

/* A per-spring list with no panel row (the cubic constants, the spring dampers) from typed
 * text: the whole list (spring < 0), or spring's own value, every spring spelled out. */
static unsigned set_spring_list(struct app *app, enum config_key key, int spring,
                                const char *text, const char *symbol, const char *why)
{
    const struct model *m = app->model;
    const struct config_option *o = &config_options[key];
    const double *now = key == CFG_SPRING_CUBIC ? m->k3 : m->cs;
    struct config next = app->cfg;
    struct config_list *l = (struct config_list *)(void *)((char *)&next + o->offset);
    char err[300], noun[48];
    if (spring > m->n)
        return 0;
    snprintf(noun, sizeof noun, "%s", o->name);
    if (spring >= 0)
        app_spring_name(m, spring, noun, sizeof noun);
    bool bad = config_set(&next, key, text, err, sizeof err) != 0; /* count: the old list's */
    if (!bad && spring >= 0 && l->count != 1) {
        char q[4 * CONFIG_QUOTE_MAX + 48];
        config_quote(text, strlen(text), q, sizeof q);
        snprintf(err, sizeof err, "%s is more than one value", q);
        bad = true;
    }
    if (bad) {
        app_say(app, SAID_ERROR, "%s: %s", noun, err);
        return 0;
    }
    if (spring >= 0) { /* every spring spelled out, one changed */
        double v = l->v[0];
        l->count = m->n + 1;
        memcpy(l->v, now, (size_t)(m->n + 1) * sizeof *now);
        l->v[spring] = v;
    }
    unsigned changed = 0;
    if (app_change(app, &next, 0, why, &changed) != 0)
        return 0;
    if (changed & APP_CHANGED_MESSAGE)
        return changed;
    now = key == CFG_SPRING_CUBIC ? app->model->k3 : app->model->cs; /* the model rebuilt */
    if (spring >= 0)
        return changed | app_say(app, SAID_NOTE, "%s: %s = %g %s", noun, symbol, now[spring],
                                 o->unit);
    return changed | app_say(app, SAID_NOTE, "%s %s %s", o->name, text, o->unit);
}

unsigned app_set_cubic(struct app *app, int spring, const char *text)
{
    return set_spring_list(app, CFG_SPRING_CUBIC, spring, text, "k3",
                           "the change of cubic springs");
}

unsigned app_set_spring_damping(struct app *app, int spring, const char *text)
{
    return set_spring_list(app, CFG_SPRING_DAMPING, spring, text, "c",
                           "the change of spring dampers");
}

unsigned app_apply_masses(struct app *app)
{
    unsigned what = 0;
    if (app->masses_pending == app->model->n)
        return 0;
    new_masses(app, app->masses_pending, &what);
    return what;
}

unsigned app_set_element(struct app *app, char what, int index, const char *text)
{
    const struct model *m = app->model;
    int n = m->n, count = what == 'k' ? n + 1 : n;
    enum config_key key = what == 'm' ? CFG_MASS : what == 'c' ? CFG_DAMPING : CFG_SPRING;
    if (index < 0 || index >= count)
        return 0;
    char noun[48];
    if (what == 'k')
        app_spring_name(m, index, noun, sizeof noun);
    else
        snprintf(noun, sizeof noun, "mass %d", index + 1);
    /* Check the one value with the key's own rules, on a scratch config. */
    struct config next;
    char err[300];
    config_init(&next);
    if (config_set(&next, key, text, err, sizeof err) != 0 ||
        (next.mass.count + next.spring.count + next.damping.count) != 1) {
        if (next.mass.count + next.spring.count + next.damping.count > 1) {
            char q[4 * CONFIG_QUOTE_MAX + 48];
            config_quote(text, strlen(text), q, sizeof q);
            snprintf(err, sizeof err, "%s is more than one value", q);
        }
        app_say(app, SAID_ERROR, "%s: %s", noun, err);
        return 0;
    }
    double v = (what == 'm' ? next.mass : what == 'c' ? next.damping : next.spring).v[0];
    /* The settings in force with every element of that list spelled out, one changed. */
    next = app->cfg;
    struct config_list *l = what == 'm' ? &next.mass : what == 'c' ? &next.damping : &next.spring;
    const double *cur = what == 'm' ? m->m : what == 'c' ? m->c : m->k;
    l->count = count;
    for (int i = 0; i < count; i++)
        l->v[i] = cur[i];
    l->v[index] = v;
    char why[64];
    snprintf(why, sizeof why, "the change of %s", noun);
    unsigned changed = 0;
    if (app_change(app, &next, 0, why, &changed) != 0)
        return 0;
    if (changed & APP_CHANGED_MESSAGE)
        return changed;
    const char *symbol = what == 'm' ? "m" : what == 'c' ? "c" : "k";
    const char *unit = config_options[key].unit;
    return changed | app_say(app, SAID_NOTE, "%s: %s = %g %s", noun, symbol, v, unit);
}

unsigned app_nearest_mode(struct app *app)
{
    if (!app->modes_ok)
        return 0;
    int j = modes_nearest(app->modes, app->model->n, app->model->motor.frequency);
    struct config next = app->cfg;
    unsigned what = 0;
    if (app->modes[j] > config_options[CFG_FREQUENCY].hi) {
        char range[64];
        config_expected(CFG_FREQUENCY, range, sizeof range);
        return app_say(app, SAID_ERROR, "mode %d is at %.4g Hz, past the drive's range (%s Hz); the "
                                  "drive is as it was", j + 1, app->modes[j], range);
    }
    next.frequency = app->modes[j];
    if (app_change(app, &next, CHANGE_SETS_FREQUENCY, "the nearest mode", &what) != 0)
        return 0;
    return what | app_say(app, SAID_NOTE, "%sdriving at mode %d, %.3f Hz",
                          what & APP_CHANGED_MESSAGE ? "sweep stopped; " : "", j + 1,
                          app->modes[j]);
}

/* The largest amplitude up to APP_MODE_AMPLITUDE at which shape phi moves no two
 * neighbours (nor a mass and the wall or the right end) closer than a fifth of the gap
 * between them at rest. */
static double mode_amplitude(const struct model *m, const double *phi)
{
    double w = model_block_width(m), amp = APP_MODE_AMPLITUDE;
    for (int i = 0; i <= m->n; i++) {
        if (i == m->n && m->boundary == BOUNDARY_FREE)
            break;
        double left = i > 0 ? model_equilibrium(m, i - 1) + 0.5 * w : 0.0;
        double right = i < m->n ? model_equilibrium(m, i) - 0.5 * w : MODEL_LENGTH;
        double rel = fabs((i < m->n ? phi[i] : 0.0) - (i > 0 ? phi[i - 1] : 0.0));
        if (rel > 0.0)
            amp = fmin(amp, 0.8 * (right - left) / rel);
    }
    return amp;
}

unsigned app_start_mode(struct app *app, int j)
{
    const struct model *m = app->model;
    int n = m->n;
    if (!app->modes_ok || j < 0 || j >= n)
        return app_say(app, SAID_ERROR, "the modes of this chain are not known"), 0u;
    const double *phi = app->shapes + (size_t)j * n;
    double amp = mode_amplitude(m, phi);
    for (int i = 0; i < n; i++) {
        app->cfg.x0.v[i] = amp * phi[i];
        app->cfg.v0.v[i] = 0.0;
    }
    app->cfg.x0.count = app->cfg.v0.count = n;
    app->cfg.random = false;
    bool sweeping = app->sweep->active;
    unsigned what = app_reset(app) | app_set_running(app, true);
    bool driven = model_motor_moves(m);
    char hz[32];
    return what | app_say(app, SAID_NOTE, "%sstarted in mode %d (%s Hz), largest |x| %.2f m%s",
                          sweeping ? "sweep stopped; " : "", j + 1,
                          app_fixed(app->modes[j], 3, hz, sizeof hz), amp,
                          driven ? "; the motor still drives (Amplitude 0 leaves it alone)"
                          : model_forced(m) ? "; the force still drives (Force 0 leaves it alone)"
                          : amp < APP_MODE_AMPLITUDE ? ", so no two masses touch" : "");
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
    case CTL_SPEED:
        snprintf(buf, len, "%gx", app->speed);
        return;
    case CTL_BANDWIDTH:
        snprintf(buf, len, "%s", app->cfg.low_bandwidth ? "low (slow link)" : "normal");
        return;
    case CTL_FORCE_ON:
        snprintf(buf, len, "mass %d", m->force_on + 1);
        return;
    case CTL_GRAPHICS: {
        /* What it asks for, and what the charts are drawn with where that is not it:
         * "auto (sixel)", "sixel: braille" (the message said why). */
        const char *want = config_options[CFG_GRAPHICS].choice_name((int)app->cfg.graphics);
        const char *now = config_options[CFG_GRAPHICS].choice_name((int)app->graphics_now);
        if (app->graphics_now == CONFIG_GRAPHICS_AUTO || app->graphics_now == app->cfg.graphics)
            snprintf(buf, len, "%s", want);
        else if (app->cfg.graphics == CONFIG_GRAPHICS_AUTO)
            snprintf(buf, len, "%s (%s)", want, now);
        else
            snprintf(buf, len, "%s: %s", want, now);
        return;
    }
    default:
        break;
    }
    if ((unsigned)ctl >= CTL_COUNT || rows[ctl].key == NONE) {
        snprintf(buf, len, "%s", "");
        return;
    }
    if (!numeric(ctl)) { /* a choice: its name */
        struct config_value c;
        config_get(rows[ctl].key, &app->cfg, m, &c);
        snprintf(buf, len, "%s", c.str);
        return;
    }
    double v = numeric_value(app, ctl);
    if (isnan(v)) {
        snprintf(buf, len, "mixed %s", setting(ctl)->unit);
        return;
    }
    int decimals = setting(ctl)->digits;
    if (ctl == CTL_DT && app_time_decimals(v) > decimals)
        decimals = app_time_decimals(v); /* 0.0075 s, not 0.007 */
    char number[32];
    format_value(v, decimals, number, sizeof number);
    snprintf(buf, len, "%s %s", number, setting(ctl)->unit);
    if (ctl == CTL_FREQUENCY && app->modes_ok && m->boundary == BOUNDARY_MOTOR) {
        /* Driving on a natural frequency (within 0.5 %): say which. */
        int j = modes_nearest(app->modes, m->n, v);
        if (fabs(v - app->modes[j]) <= 0.005 * app->modes[j])
            snprintf(buf + strlen(buf), len - strlen(buf), " ◆ f%d", j + 1);
    }
}
