/* command_say.c: the plain mode's commands that tell rather than do (command_say.h): the
 * status line, the modes, the controls, the presets, a cursor's sample and a measurement,
 * each in one line. */
#include "command_say.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "../core/preset.h"
#include "app.h"
#include "scope_text.h"

void command_status(const struct app *app, char *buf, size_t len)
{
    const struct sim *s = app->sim;
    const double *x = sim_x(s), *v = sim_v(s);
    size_t used = (size_t)snprintf(buf, len, "t=%.*f", app_time_decimals(sim_dt(s)), sim_time(s));
    char a[32], b[32];
    for (int i = 0; i < sim_model(s)->n && used < len; i++)
        used += (size_t)snprintf(buf + used, len - used, " x%d=%s v%d=%s", i + 1,
                                 app_fixed(x[i], 4, a, sizeof a), i + 1,
                                 app_fixed(v[i], 4, b, sizeof b));
    if (used < len)
        snprintf(buf + used, len - used, " drive=%s",
                 app_fixed(sim_end_position(s), 4, a, sizeof a));
}

/* The modes in one line: frequency, damping ratio and Q = 1/(2 zeta) of each. */
enum command_reply say_modes(struct command_call *c)
{
    const struct app *app = c->app;
    char *answer = c->answer;
    size_t len = c->len;
    if (!app->modes_ok) {
        snprintf(answer, len, "modes: the modes of this chain are not known");
        return REPLY_ERROR;
    }
    size_t used = (size_t)snprintf(answer, len, "modes%s:",
                                   app->model->cubic ? " (linearised at rest)" : "");
    for (int j = 0; j < app->model->n && used < len; j++) {
        double z = app->damping_ratio[j];
        char damping[64] = "";
        if (!app->damping_ok)
            snprintf(damping, sizeof damping, ", damping not known");
        else if (isnan(z)) /* damped.c's mark of a rigid-body mode */
            snprintf(damping, sizeof damping, ", a rigid-body mode (no spring holds it)");
        else if (z >= 1.0)
            snprintf(damping, sizeof damping, ", damping ratio %.3g, overdamped", z);
        else if (z > 0.0)
            snprintf(damping, sizeof damping, ", damping ratio %.3g, Q %.3g", z, 0.5 / z);
        else
            snprintf(damping, sizeof damping, ", damping ratio 0, Q unbounded");
        used += (size_t)snprintf(answer + used, len - used, "%s %d: %.4g Hz%s", j ? ";" : "",
                                 j + 1, app->modes[j], damping);
    }
    return REPLY_OK;
}

/* Every control with its name for set and its value, in one line. */
enum command_reply say_controls(struct command_call *c)
{
    const struct app *app = c->app;
    char *answer = c->answer;
    size_t len = c->len;
    size_t used = 0;
    answer[0] = '\0';
    for (int ctl = 0; ctl < CTL_COUNT && used < len; ctl++) {
        char value[96];
        app_control_value(app, (enum control)ctl, value, sizeof value);
        used += (size_t)snprintf(answer + used, len - used, "%s%s %s",
                                 ctl ? "; " : "controls: ", app_control_name((enum control)ctl),
                                 value);
    }
    if (used < len)
        snprintf(answer + used, len - used, "; window %g s", app_window(app));
    return REPLY_OK;
}

/* The presets' names in one line. */
enum command_reply say_presets(struct command_call *c)
{
    const struct app *app = c->app;
    char *answer = c->answer;
    size_t len = c->len;
    struct search_entry *list = NULL;
    int n = preset_scan(app->exe_dir, &list);
    size_t used = (size_t)snprintf(answer, len, "presets:");
    for (int i = 0; i < n && used < len; i++)
        used += (size_t)snprintf(answer + used, len - used, "%s %s", i ? "," : "", list[i].name);
    if (n == 0)
        snprintf(answer + used, len - used, " none found");
    free(list);
    return REPLY_OK;
}

enum command_reply say_status(struct command_call *c)
{
    command_status(c->app, c->answer, c->len);
    return REPLY_OK;
}

enum command_reply say_cursor(struct command_call *c)
{
    return scope_say_cursor(c->app, c->rest, c->answer, c->len) ? REPLY_OK : REPLY_ERROR;
}

enum command_reply say_measure(struct command_call *c)
{
    return scope_say_measure(c->app, c->rest, c->answer, c->len) ? REPLY_OK : REPLY_ERROR;
}
