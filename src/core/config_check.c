/* config_check.c: whole configurations checked against what the program can do: every
 * value in its option's range (whatever made it), the interactive program's narrower
 * ranges, the exact integrator's reach, and the length of a headless run. */
#include "config.h"

#include "exact.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

/* Says that v, a value of key, is out of range. */
static int out_of_range(int key, double v, char *err, size_t errlen)
{
    char text[40], q[64], want[160];
    config_format_exact(v, text, sizeof text);
    config_quote(text, strlen(text), q, sizeof q);
    config_expected(key, want, sizeof want);
    snprintf(err, errlen, "%s is out of range (expected %s)", q, want);
    return key;
}

int config_check_ranges(const struct config *c, char *err, size_t errlen)
{
    for (int k = 0; k < CFG_KEY_COUNT; k++) {
        const struct config_option *o = &config_options[k];
        const char *at = (const char *)c + o->offset;
        bool physical = o->section && (strcmp(o->section, "system") == 0 ||
                                       strcmp(o->section, "motor") == 0 ||
                                       strcmp(o->section, "initial") == 0);
        if (!physical)
            continue; /* the run's settings (--sample 0 is every step) are not changed here */
        if (o->kind == CONFIG_NUMBER) {
            double v = *(const double *)at;
            if (!config_in_range(k, v))
                return out_of_range(k, v, err, errlen);
        } else if (o->kind == CONFIG_LIST) {
            const struct config_list *l = (const struct config_list *)(const void *)at;
            for (int i = 0; i < l->count; i++)
                if (!config_in_range(k, l->v[i]))
                    return out_of_range(k, l->v[i], err, errlen);
        }
    }
    return -1;
}

int config_check_interactive(const struct config *c, char *err, size_t errlen)
{
    const struct config_option *n = &config_options[CFG_MASSES], *dt = &config_options[CFG_DT];
    if (c->masses > n->ihi)
        snprintf(err, errlen, "'%d' is out of range for the interactive program (expected "
                 "%g <= %s <= %g; --headless takes up to %g)", c->masses, n->lo, n->symbol,
                 n->ihi, n->hi);
    else if (!(c->dt >= dt->ilo)) {
        char v[40];
        config_format_exact(c->dt, v, sizeof v);
        snprintf(err, errlen, "'%s' is out of range for the interactive program (expected "
                 "%g <= %s <= %g)", v, dt->ilo, dt->symbol, dt->hi);
    }
    else
        return -1;
    return c->masses > n->ihi ? CFG_MASSES : CFG_DT;
}

int config_check_exact(const struct config *c, char *err, size_t errlen)
{
    int most = c->no_collisions ? CONFIG_EXACT_MAX_MASSES : CONFIG_EXACT_MAX_MASSES_CONTACTS;
    if (c->integrator != INTEGRATOR_EXACT || c->masses <= most)
        return -1;
    int bad;
    char why[8];
    struct model *m = config_model(c, &bad, why, sizeof why);
    int modes = !m || exact_in_modes(m);
    model_free(m);
    if (modes)
        return -1; /* stepped in its modes at any N (or refused elsewhere) */
    snprintf(err, errlen, "'exact' takes at most %d masses %s when the dampers are not "
             "proportional to the masses and springs (Rayleigh's), not %d: %s (expected "
             "dampers in proportion to the masses and springs, rk4, verlet, semi-implicit "
             "or euler, or fewer masses)", most,
             c->no_collisions ? "without collisions" : "with collisions (100 without)",
             c->masses,
             c->no_collisions ? "its set-up is a matrix exponential of order 2N+2 (0.7 s at "
                                "100 masses, minutes at 300)"
                              : "every contact makes a new step length, each a matrix "
                                "exponential of order 2N+2 (a second of motion takes 0.4 s "
                                "at 20 masses, 13 s at 50)");
    return CFG_INTEGRATOR;
}

int config_check_steps(const struct config *c, char *err, size_t errlen)
{
    double steps = c->duration / c->dt;
    if (steps <= CONFIG_MAX_STEPS)
        return -1;
    char count[32];
    snprintf(count, sizeof count, isfinite(steps) ? "%.3g" : "over 1e308", steps);
    snprintf(err, errlen, "a run of %g s at dt = %g s is %s steps (expected at most %g: "
             "a shorter --duration or a larger --dt)", c->duration, c->dt, count,
             CONFIG_MAX_STEPS);
    return c->dt < 1e-9 ? CFG_DT : CFG_DURATION;
}
