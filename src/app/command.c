/* command.c: the plain mode's commands, one row each naming its verb (verb.h: what the
 * keys do too), and the line's words turned into the verb's arguments and its result
 * into the answer. */
#include "command.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../core/preset.h"
#include "app.h"
#include "scope_text.h"

const struct command commands[CMD_COUNT] = {
    [CMD_START] = {"start", ACT_RUN, "", "start the simulation; time follows the clock at the "
                                         "Speed control's rate", true},
    [CMD_PAUSE] = {"pause", ACT_RUN, "", "pause it", true},
    [CMD_STEP] = {"step", ACT_STEP, "", "one step of dt forward (pauses)", true},
    [CMD_BACK] = {"back", ACT_BACK, "", "one step back (paused; up to 500 states)"},
    [CMD_RESET] = {"reset", ACT_RESET, "", "back to the initial conditions, t = 0"},
    [CMD_RANDOM] = {"random", ACT_RANDOM, "[SEED]",
                    "random initial positions (from SEED: the same each time), and a reset"},
    [CMD_SET] = {"set", ACT_SET, "CONTROL VALUE",
                 "set a control as typed in the interactive program (controls lists them)"},
    [CMD_PRESET] = {"preset", ACT_PRESET, "NAME", "load a preset by name or file"},
    [CMD_PRESETS] = {"presets", ACT_PRESETS, "", "the presets' names"},
    [CMD_MODES] = {"modes", ACT_MODES, "", "each natural frequency with its damping ratio and Q"},
    [CMD_MODE] = {"mode", ACT_MODE, "K", "start the chain in mode K, at rest, running", true},
    [CMD_PLACE] = {"place", ACT_PLACE, "MASS X0",
                   "start mass MASS displaced by X0 m (kept inside its neighbours), the others "
                   "where they stand, at rest, t = 0 (paused)"},
    [CMD_ELEMENT] = {"element", ACT_ELEMENT, "m|c|k|cs I VALUE",
                     "one element: mass I's mass (m) or damping (c), or spring I's constant "
                     "(k) or the damper beside it (cs; spring 0 is the wall's, spring N the "
                     "motor's)"},
    [CMD_NEAREST] = {"nearest", ACT_NEAREST, "", "drive at the nearest natural frequency"},
    [CMD_SWEEP] = {"sweep", ACT_SWEEP, "", "start / stop a sine-sweep experiment"},
    [CMD_FASTER] = {"faster", ACT_FASTER, "", "playback faster"},
    [CMD_SLOWER] = {"slower", ACT_SLOWER, "", "playback slower"},
    [CMD_SAVE] = {"save", ACT_SAVE, "NAME", "save the set-up as a user preset"},
    [CMD_EXPORT] = {"export", ACT_EXPORT, "", "export the samples as CSV (and a sweep's points)"},
    [CMD_CURSOR] = {"cursor", ACT_CURSOR, "T",
                    "every mass's x, v, a and the motor at the recorded sample nearest to time T"},
    [CMD_MEASURE] = {"measure", ACT_CURSOR, "[MASS]",
                     "period, frequency, peak-to-peak, rms, log decrement and zeta of a mass "
                     "over the time window"},
    [CMD_RUN] = {"run", ACT_NONE, "SECONDS",
                 "run SECONDS of simulated time at once (not in real time), then pause", true},
    [CMD_VIEW] = {"view", ACT_NONE, "NAME",
                  "what the interactive program shows (lessons set the scene with it): plots, "
                  "x, v, a, x-v, x-a, v-a (that plot enlarged), modes, response, energy or "
                  "spectrum; nothing changes here"},
    [CMD_STATUS] = {"status", ACT_NONE, "", "the status line now"},
    [CMD_CONTROLS] = {"controls", ACT_NONE, "", "every control, its name for set and its value"},
    [CMD_HELP] = {"help", ACT_HELP, "[COMMAND]", "the commands, or what one does"},
    [CMD_QUIT] = {"quit", ACT_QUIT, "", "quit (so does the end of input)"},
};

const char *const command_views[CV_COUNT] = {
    [CV_PLOTS] = "plots", [CV_X] = "x",   [CV_V] = "v",     [CV_A] = "a",
    [CV_XV] = "x-v",      [CV_XA] = "x-a", [CV_VA] = "v-a", [CV_MODES] = "modes",
    [CV_RESPONSE] = "response", [CV_ENERGY] = "energy", [CV_SPECTRUM] = "spectrum",
};

int command_find(const char *name, size_t n)
{
    for (int i = 0; i < CMD_COUNT; i++)
        if (strlen(commands[i].name) == n && strncmp(commands[i].name, name, n) == 0)
            return i;
    return -1;
}

#define RUN_MAX 1000.0 /* simulated seconds one run may take */

const char *command_control_name(int ctl)
{
    return app_control_name((enum control)ctl);
}

/* The control named by word (its name, or its label in lower case with '-' for a
 * blank: "right-end"), or -1. */
static int find_control(const char *word)
{
    for (int c = 0; c < CTL_COUNT; c++) {
        const char *l = app_control_label((enum control)c);
        char label[32];
        size_t i;
        for (i = 0; l[i] && i < sizeof label - 1; i++)
            label[i] = l[i] == ' ' ? '-' : (char)tolower((unsigned char)l[i]);
        label[i] = '\0';
        if (strcmp(word, app_control_name((enum control)c)) == 0 || strcmp(word, label) == 0)
            return c;
    }
    return -1;
}

/* The commands' names with their arguments, "start, pause, ..., set CONTROL VALUE, ...". */
static void command_list(char *buf, size_t len)
{
    size_t used = 0;
    buf[0] = '\0';
    for (int i = 0; i < CMD_COUNT && used < len; i++)
        used += (size_t)snprintf(buf + used, len - used, "%s%s%s%s", i ? ", " : "",
                                 commands[i].name, commands[i].args[0] ? " " : "",
                                 commands[i].args);
}

/* The controls' names, "preset, masses, ..., bandwidth". */
static void control_list(char *buf, size_t len)
{
    size_t used = 0;
    buf[0] = '\0';
    for (int c = 0; c < CTL_COUNT && used < len; c++)
        used += (size_t)snprintf(buf + used, len - used, "%s%s", c ? ", " : "",
                                 app_control_name((enum control)c));
    if (used < len) /* settings with keys (< and >; K on a spring) but no row of the panel */
        snprintf(buf + used, len - used, ", window, spring-cubic, spring-damping");
}

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
static enum command_reply say_modes(const struct app *app, char *answer, size_t len)
{
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
static enum command_reply say_controls(const struct app *app, char *answer, size_t len)
{
    size_t used = 0;
    answer[0] = '\0';
    for (int c = 0; c < CTL_COUNT && used < len; c++) {
        char value[96];
        app_control_value(app, (enum control)c, value, sizeof value);
        used += (size_t)snprintf(answer + used, len - used, "%s%s %s", c ? "; " : "controls: ",
                                 app_control_name((enum control)c), value);
    }
    if (used < len)
        snprintf(answer + used, len - used, "; window %g s", app_window(app));
    return REPLY_OK;
}

/* The presets' names in one line. */
static enum command_reply say_presets(const struct app *app, char *answer, size_t len)
{
    struct preset_entry *list = NULL;
    int n = preset_scan(app->exe_dir, &list);
    size_t used = (size_t)snprintf(answer, len, "presets:");
    for (int i = 0; i < n && used < len; i++)
        used += (size_t)snprintf(answer + used, len - used, "%s %s", i ? "," : "", list[i].name);
    if (n == 0)
        snprintf(answer + used, len - used, " none found");
    free(list);
    return REPLY_OK;
}

/* What a verb's result is as a reply. */
static enum command_reply reply_of(enum result r)
{
    return r == RESULT_OK ? REPLY_OK : r == RESULT_WARNING ? REPLY_WARNING : REPLY_ERROR;
}

/* Does verb a with arg; the answer is the message it left ("nothing changed" for none). */
static enum command_reply verb(struct app *app, enum action a, const struct verb_arg *arg,
                               char *answer, size_t len)
{
    enum result r = verb_do(app, a, arg, NULL);
    snprintf(answer, len, "%s", app->message[0] ? app->message : "nothing changed");
    return reply_of(r);
}

/* t now, as the status line writes it. */
static double now_t(const struct app *app, int *decimals)
{
    *decimals = app_time_decimals(sim_dt(app->sim));
    return sim_time(app->sim);
}

static enum command_reply load_preset(struct app *app, const char *name, char *answer, size_t len)
{
    char path[4400];
    if (preset_find(name, app->exe_dir, path, sizeof path) != PRESET_OK) {
        snprintf(answer, len, "preset: %.*s", (int)(len > 9 ? len - 9 : 0), path);
        return REPLY_ERROR;
    }
    return verb(app, ACT_PRESET, &(struct verb_arg){.text = path, .name = name}, answer, len);
}

static enum command_reply set_control(struct app *app, const char *name, const char *value,
                                      char *answer, size_t len)
{
    char q[4 * CONFIG_QUOTE_MAX + 48], names[200];
    control_list(names, sizeof names);
    int c = find_control(name);
    bool window = c < 0 && strcmp(name, "window") == 0;
    if (window && *value)
        return verb(app, ACT_WINDOW, &(struct verb_arg){.text = value}, answer, len);
    bool cubic = c < 0 && strcmp(name, "spring-cubic") == 0; /* no panel row either */
    bool dampers = c < 0 && strcmp(name, "spring-damping") == 0;
    window |= cubic || dampers;
    if (window && *value)
        return verb(app, cubic ? ACT_CUBIC : ACT_SPRING_DAMPING,
                    &(struct verb_arg){.index = -1, .text = value}, answer, len);
    if ((c < 0 && !window) || !*value) {
        config_quote(name, strlen(name), q, sizeof q);
        if (!*name)
            snprintf(answer, len, "set: needs a control and a value (controls: %s)", names);
        else if (c < 0 && !window)
            snprintf(answer, len, "set: %s is not a control (expected %s)", q, names);
        else
            snprintf(answer, len, "set: %s needs a value", q);
        return REPLY_ERROR;
    }
    if (c == CTL_PRESET)
        return load_preset(app, value, answer, len);
    enum command_reply r = verb(app, ACT_SET, &(struct verb_arg){.index = c, .text = value},
                                answer, len);
    if (r == REPLY_WARNING) {
        /* The warning took the place of the value set: both are said. */
        char now[96];
        app_control_value(app, (enum control)c, now, sizeof now);
        snprintf(answer, len, "%s %s; %s", app_control_label((enum control)c), now, app->message);
    }
    return r;
}

/* A whole number from 1 to hi, or 0. */
static int whole(const char *text, int hi)
{
    double v;
    if (config_parse_number(text, &v) || v != floor(v) || v < 1 || v > hi)
        return 0;
    return (int)v;
}

/* One line: its reply, the answer into answer, a run's seconds or a view's number into
 * *value, the command's row into *cmd (-1 for none). */
static enum command_reply dispatch(struct app *app, const char *line, char *answer, size_t len,
                                   double *seconds, int *row)
{
    char buf[2048], q[4 * CONFIG_QUOTE_MAX + 48], list[600];
    snprintf(buf, sizeof buf, "%s", line);
    char *word = buf + strspn(buf, " \t");
    char *rest = word + strcspn(word, " \t");
    if (*rest)
        *rest++ = '\0';
    rest += strspn(rest, " \t");
    for (char *end = rest + strlen(rest); end > rest && (end[-1] == ' ' || end[-1] == '\t');)
        *--end = '\0';
    if (!*word)
        return REPLY_NONE;
    int cmd = command_find(word, strlen(word));
    if (cmd < 0) {
        command_list(list, sizeof list);
        config_quote(word, strlen(word), q, sizeof q);
        snprintf(answer, len, "%s is not a command (expected %s)", q, list);
        return REPLY_ERROR;
    }
    const struct command *c = &commands[cmd];
    *row = cmd;
    bool wants = c->args[0] && c->args[0] != '[';
    if (cmd == CMD_SET && !*rest)
        return set_control(app, "", "", answer, len);
    if (wants && !*rest) {
        snprintf(answer, len, "%s: needs %s", c->name, c->args);
        return REPLY_ERROR;
    }
    if (!c->args[0] && *rest) {
        config_quote(rest, strlen(rest), q, sizeof q);
        snprintf(answer, len, "%s: takes nothing, but was given %s", c->name, q);
        return REPLY_ERROR;
    }
    app_quiet(app);
    int d;
    double t;
    unsigned changed;
    switch ((enum command_id)cmd) {
    case CMD_START:
    case CMD_PAUSE: {
        bool run = cmd == CMD_START;
        bool was = app->running;
        verb_do(app, ACT_RUN, &(struct verb_arg){.dir = run ? 1 : -1}, NULL);
        t = now_t(app, &d);
        snprintf(answer, len, "%s at t = %.*f s", was == run ? run ? "running already" :
                 "paused already" : run ? "started" : "paused", d, t);
        return REPLY_OK;
    }
    case CMD_STEP:
        if (verb(app, ACT_STEP, NULL, answer, len) != REPLY_OK)
            return REPLY_ERROR; /* a blow-up: paused, and the message says why */
        t = now_t(app, &d);
        snprintf(answer, len, "stepped to t = %.*f s, paused", d, t);
        return REPLY_OK;
    case CMD_BACK:
        if (verb_do(app, ACT_BACK, NULL, NULL) != RESULT_OK)
            return snprintf(answer, len, "back: %s", app->message), REPLY_ERROR;
        t = now_t(app, &d);
        snprintf(answer, len, "back to t = %.*f s", d, t);
        return REPLY_OK;
    case CMD_RESET:
        return verb(app, ACT_RESET, NULL, answer, len);
    case CMD_RANDOM: {
        if (!*rest)
            return verb(app, ACT_RANDOM, NULL, answer, len);
        errno = 0;
        unsigned long long seed = strtoull(rest, NULL, 10);
        if (errno || strlen(rest) > 20 || strspn(rest, "0123456789") != strlen(rest)) {
            config_quote(rest, strlen(rest), q, sizeof q);
            snprintf(answer, len, "random: %s is not a seed (expected a whole number from 0 "
                     "to 2^64 - 1)", q);
            return REPLY_ERROR;
        }
        return verb(app, ACT_RANDOM, &(struct verb_arg){.seeded = true, .seed = seed}, answer,
                    len);
    }
    case CMD_SET: {
        char *value = rest + strcspn(rest, " \t");
        if (*value)
            *value++ = '\0';
        value += strspn(value, " \t");
        return set_control(app, rest, value, answer, len);
    }
    case CMD_PRESET:
        return load_preset(app, rest, answer, len);
    case CMD_PRESETS:
        return say_presets(app, answer, len);
    case CMD_MODES:
        return say_modes(app, answer, len);
    case CMD_MODE: {
        int k = whole(rest, app->model->n);
        if (!k) {
            config_quote(rest, strlen(rest), q, sizeof q);
            snprintf(answer, len, "mode: %s is not a mode of this chain (expected 1 <= K <= %d)",
                     q, app->model->n);
            return REPLY_ERROR;
        }
        return verb(app, ACT_MODE, &(struct verb_arg){.index = k - 1}, answer, len);
    }
    case CMD_PLACE: {
        char *x = rest + strcspn(rest, " \t");
        if (*x)
            *x++ = '\0';
        x += strspn(x, " \t");
        int k = whole(rest, app->model->n);
        double x0;
        if (!k || !*x || config_parse_number(x, &x0)) {
            config_quote(k ? x : rest, strlen(k ? x : rest), q, sizeof q);
            snprintf(answer, len, "place: %s is not %s (expected place MASS X0, 1 <= MASS <= "
                     "%d, X0 in m)", q, k ? "a displacement" : "a mass of this chain",
                     app->model->n);
            return REPLY_ERROR;
        }
        return verb(app, ACT_PLACE, &(struct verb_arg){.index = k - 1, .value = x0}, answer,
                    len);
    }
    case CMD_ELEMENT: {
        char *i = rest + strcspn(rest, " \t"), *v;
        if (*i)
            *i++ = '\0';
        i += strspn(i, " \t");
        v = i + strcspn(i, " \t");
        if (*v)
            *v++ = '\0';
        v += strspn(v, " \t");
        int n = app->model->n;
        char kind = strlen(rest) == 1 ? rest[0] : strcmp(rest, "cs") == 0 ? 's' : 0;
        double idx;
        bool spring = kind == 'k' || kind == 's';
        if ((kind != 'm' && kind != 'c' && !spring) || config_parse_number(i, &idx) ||
            idx != floor(idx) || idx < (spring ? 0 : 1) || idx > n || !*v) {
            snprintf(answer, len, "element: expected element m|c|k|cs I VALUE (mass I from 1 "
                     "to %d: m its mass, c its damping; spring I from 0 to %d: k its "
                     "constant, cs its damper)", n, n);
            return REPLY_ERROR;
        }
        if (kind == 's')
            return verb(app, ACT_SPRING_DAMPING, &(struct verb_arg){.index = (int)idx, .text = v},
                        answer, len);
        return verb(app, ACT_ELEMENT, &(struct verb_arg){.what = kind, .index = (int)idx - !spring,
                    .text = v}, answer, len);
    }
    case CMD_NEAREST:
        return verb(app, ACT_NEAREST, NULL, answer, len);
    case CMD_SWEEP:
        return verb(app, ACT_SWEEP, NULL, answer, len);
    case CMD_FASTER:
    case CMD_SLOWER: {
        verb_do(app, cmd == CMD_FASTER ? ACT_FASTER : ACT_SLOWER, NULL, &changed);
        char value[32];
        app_control_value(app, CTL_SPEED, value, sizeof value);
        snprintf(answer, len, "Speed %s%s", value,
                 changed ? "" : cmd == CMD_FASTER ? " (the fastest)" : " (the slowest)");
        return REPLY_OK;
    }
    case CMD_SAVE: {
        char *how = rest + strcspn(rest, " \t");
        if (*how)
            *how++ = '\0';
        how += strspn(how, " \t");
        if (*how && strcmp(how, "replace") != 0) {
            config_quote(how, strlen(how), q, sizeof q);
            snprintf(answer, len, "save: %s is not 'replace' (expected save NAME [replace])", q);
            return REPLY_ERROR;
        }
        enum app_save st = app_save(app, rest, *how != '\0');
        if (st == SAVE_EXISTS) {
            snprintf(answer, len, "save: preset %s exists (save %s replace replaces it)", rest,
                     rest);
            return REPLY_ERROR;
        }
        snprintf(answer, len, "%s", app->message);
        return st == SAVE_OK ? REPLY_OK : REPLY_ERROR;
    }
    case CMD_EXPORT: {
        /* The samples; after a sweep, its points beside the theory too. */
        enum command_reply r = verb(app, ACT_EXPORT, NULL, answer, len);
        if (r != REPLY_OK || sweep_measured(app->sweep) == 0)
            return r;
        size_t used = strlen(answer);
        r = reply_of(verb_do(app, ACT_EXPORT, &(struct verb_arg){.sweep = true}, NULL));
        snprintf(answer + used, len - used, "; %s", app->message);
        return r;
    }
    case CMD_CURSOR:
        return scope_say_cursor(app, rest, answer, len) ? REPLY_OK : REPLY_ERROR;
    case CMD_MEASURE:
        return scope_say_measure(app, rest, answer, len) ? REPLY_OK : REPLY_ERROR;
    case CMD_RUN: {
        const char *why = config_parse_number(rest, seconds);
        if (why || !(*seconds > 0.0 && *seconds <= RUN_MAX)) {
            config_quote(rest, strlen(rest), q, sizeof q);
            snprintf(answer, len, "run: %s %s (expected 0 < SECONDS <= %g)", q,
                     why ? why : "is out of range", RUN_MAX);
            return REPLY_ERROR;
        }
        return REPLY_RUN;
    }
    case CMD_VIEW:
        for (int v = 0; v < CV_COUNT; v++)
            if (strcmp(rest, command_views[v]) == 0) {
                *seconds = v;
                snprintf(answer, len, "view %s (the interactive program shows it)", rest);
                return REPLY_VIEW;
            }
        config_quote(rest, strlen(rest), q, sizeof q);
        snprintf(answer, len, "view: %s is not a view (expected plots, x, v, a, x-v, x-a, v-a, "
                 "modes, response, energy or spectrum)", q);
        return REPLY_ERROR;
    case CMD_STATUS:
        command_status(app, answer, len);
        return REPLY_OK;
    case CMD_CONTROLS:
        return say_controls(app, answer, len);
    case CMD_HELP: {
        if (!*rest) {
            command_list(list, sizeof list);
            snprintf(answer, len, "commands: %s (help COMMAND says what one does)", list);
            return REPLY_OK;
        }
        int h = command_find(rest, strlen(rest));
        if (h < 0) {
            command_list(list, sizeof list);
            config_quote(rest, strlen(rest), q, sizeof q);
            snprintf(answer, len, "help: %s is not a command (expected %s)", q, list);
            return REPLY_ERROR;
        }
        if (h == CMD_SET) {
            control_list(list, sizeof list);
            snprintf(answer, len, "set CONTROL VALUE: %s; controls: %s", commands[h].help, list);
        } else {
            snprintf(answer, len, "%s%s%s: %s", commands[h].name, commands[h].args[0] ? " " : "",
                     commands[h].args, commands[h].help);
        }
        return REPLY_OK;
    }
    case CMD_QUIT:
        t = now_t(app, &d);
        snprintf(answer, len, "quit at t = %.*f s", d, t);
        return REPLY_QUIT;
    case CMD_COUNT:
        break;
    }
    return REPLY_NONE;
}

enum command_reply command_do(struct app *app, const char *line, struct command_result *res)
{
    double value = 0.0;
    int row = -1;
    res->answer[0] = '\0';
    res->reply = dispatch(app, line, res->answer, sizeof res->answer, &value, &row);
    res->seconds = res->reply == REPLY_RUN ? value : 0.0;
    res->view = res->reply == REPLY_VIEW ? (int)value : -1;
    res->says_play = row >= 0 && commands[row].says_play;
    return res->reply;
}

bool command_done(enum command_reply r)
{
    return r == REPLY_OK || r == REPLY_WARNING || r == REPLY_VIEW;
}
