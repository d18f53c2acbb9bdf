/* sweeping.c: the app's sine sweep planned and started (sweeping.h); its points are
 * taken in app_step, its bookkeeping is the core's sweep.c; on a chain with cubic springs
 * it goes up, then down (jump.c). */
#include "sweeping.h"

#include <math.h>
#include <stdio.h>

#include "action.h"
#include "change.h"
#include "jump.h"

int sweeping_plan(const struct app *app, struct sweep_plan *plan, char *why, size_t len)
{
    const struct model *m = app->model;
    int n = m->n;
    *plan = (struct sweep_plan){.contact = INFINITY};
    if (m->boundary != BOUNDARY_MOTOR && !model_forced(m)) {
        snprintf(why, len, "a sweep needs a drive: the motor at the right end, or a force on "
                 "a mass");
        return -1;
    }
    if (!app->modes_ok) {
        snprintf(why, len, "a sweep needs the modes, and those of this chain are not known");
        return -1;
    }
    /* Half the first mode to 1.5 times the last, as far as the drive goes (0.1 Hz up to
     * the frequency's limit, 1e6 Hz). */
    plan->lo = fmax(APP_FMIN, 0.5 * app->modes[0]);
    plan->hi = fmin(config_options[CFG_FREQUENCY].hi, 1.5 * app->modes[n - 1]);
    if (!(plan->lo < plan->hi)) {
        char range[64];
        config_expected(CFG_FREQUENCY, range, sizeof range);
        snprintf(why, len, "a sweep needs a mode the drive reaches: the first is at %.4g Hz "
                 "(the drive: %s Hz)", app->modes[0], range);
        return -1;
    }
    /* A transient decays as exp(-zeta w t): over one decay time of the slowest mode a
     * swing still settling moves by 63 % of what is left of it, so swings level within
     * 1 % for that long leave less than 1.6 % to settle at the start of that time, and
     * under 0.6 % at its end, when the point is measured. */
    double rate = INFINITY;
    for (int j = 0; j < n && app->damping_ok; j++)
        rate = fmin(rate, app->damping_ratio[j] * 2.0 * M_PI * app->modes[j]);
    plan->hold = app->damping_ok && rate > 0.0 ? fmin(SWEEPING_HOLD_MAX, 1.0 / rate)
                                               : SWEEPING_HOLD_MAX;
    plan->most = SWEEPING_MOST * plan->hold;
    double freq[APP_SWEEP_POINTS];
    for (int p = 0; p < APP_SWEEP_POINTS; p++)
        freq[p] = sweep_point(plan->lo, plan->hi, APP_SWEEP_POINTS, p);
    plan->scale = sweep_contact_scale(m, freq, APP_SWEEP_POINTS);
    bool motor_only = m->boundary == BOUNDARY_MOTOR && !model_forced(m);
    plan->contact = motor_only ? plan->scale * m->motor.amplitude : INFINITY;
    return 0;
}

void sweeping_contact_words(const struct app *app, const struct sweep_plan *plan, int form,
                            char *buf, size_t len)
{
    const struct model *m = app->model;
    bool motor = model_motor_moves(m), force = model_forced(m);
    buf[0] = '\0';
    if (!(plan->scale <= 1.0))
        return;
    static const char *const lead[4] = {"contacts expected above ", "contacts expected above ",
                                        "contacts above ", "> "};
    if (motor != force) {
        snprintf(buf, len, "%s%.2g %s", lead[form < 0 || form > 3 ? 0 : form],
                 plan->scale * (motor ? m->motor.amplitude : fabs(m->force)), motor ? "m" : "N");
        return;
    }
    static const char *const both[4] = {"contacts expected at this drive",
                                        "contacts expected at this drive", "contacts expected",
                                        "contacts"};
    snprintf(buf, len, "%s", both[form < 0 || form > 3 ? 0 : form]);
}

unsigned app_toggle_sweep(struct app *app)
{
    if (app->sweep->active)
        return app_end_sweep(app, NULL);
    struct sweep_plan plan;
    char why[200];
    if (sweeping_plan(app, &plan, why, sizeof why) != 0)
        return app_say(app, SAID_ERROR, "%s", why);
    app->sweep_from = app->model->motor.frequency;
    /* The last sweep up is let go: its points are not this sweep's. */
    sweep_start(app->sweep_up, plan.lo, plan.hi, 0.0, sim_time(app->sim));
    sweep_stop(app->sweep_up);
    sweep_start(app->sweep, plan.lo, plan.hi, 0.0, sim_time(app->sim));
    sweep_until_steady(app->sweep, plan.hold, plan.most);
    unsigned what = app_retune(app, sweep_frequency(app->sweep)) | app_set_running(app, true);
    char a[32], b[32], pace[32];
    snprintf(pace, sizeof pace, "%gx", app->speed * APP_SWEEP_PACE);
    if (plan.scale <= 1.0) {
        char words[80];
        bool force = model_forced(app->model), motor = model_motor_moves(app->model);
        sweeping_contact_words(app, &plan, 0, words, sizeof words);
        return what | app_say(app, SAID_WARNING, "%s: lower the %s; sweeping, %s stops it",
                              words, force && motor ? "amplitude or the force"
                                     : force        ? "force"
                                                    : "amplitude",
                              app_key(app, ACT_SWEEP));
    }
    if (jump_two_way(app->model))
        return what | app_say(app, SAID_NOTE, "sweeping up %s..%s Hz at %s, then down, each "
                              "point from the last one's state; %s stops it",
                              app_fixed(plan.lo, 2, a, sizeof a),
                              app_fixed(plan.hi, 2, b, sizeof b), pace, app_key(app, ACT_SWEEP));
    return what | app_say(app, SAID_NOTE, "sweeping %s..%s Hz at %s, each point once steady to "
                          "1 %%; %s stops it", app_fixed(plan.lo, 2, a, sizeof a),
                          app_fixed(plan.hi, 2, b, sizeof b), pace, app_key(app, ACT_SWEEP));
}
