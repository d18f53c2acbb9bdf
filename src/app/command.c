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
#include "command_say.h"
#include "scope_text.h"


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

/* Each command's work: the words after its name in c->rest (blanks trimmed), its answer
 * into c->answer. */

static enum command_reply do_start_pause(struct command_call *c)
{
    struct app *app = c->app;
    bool run = c->cmd == CMD_START, was = app->running;
    int d;
    verb_do(app, ACT_RUN, &(struct verb_arg){.dir = run ? 1 : -1}, NULL);
    double t = now_t(app, &d);
    snprintf(c->answer, c->len, "%s at t = %.*f s", was == run ? run ? "running already" :
             "paused already" : run ? "started" : "paused", d, t);
    return REPLY_OK;
}

static enum command_reply do_step(struct command_call *c)
{
    int d;
    if (verb(c->app, ACT_STEP, NULL, c->answer, c->len) != REPLY_OK)
        return REPLY_ERROR; /* a blow-up: paused, and the message says why */
    double t = now_t(c->app, &d);
    snprintf(c->answer, c->len, "stepped to t = %.*f s, paused", d, t);
    return REPLY_OK;
}

static enum command_reply do_back(struct command_call *c)
{
    int d;
    if (verb_do(c->app, ACT_BACK, NULL, NULL) != RESULT_OK)
        return snprintf(c->answer, c->len, "back: %s", c->app->message), REPLY_ERROR;
    double t = now_t(c->app, &d);
    snprintf(c->answer, c->len, "back to t = %.*f s", d, t);
    return REPLY_OK;
}

static enum command_reply do_reset(struct command_call *c)
{
    return verb(c->app, ACT_RESET, NULL, c->answer, c->len);
}

static enum command_reply do_random(struct command_call *c)
{
    const char *rest = c->rest;
    if (!*rest)
        return verb(c->app, ACT_RANDOM, NULL, c->answer, c->len);
    errno = 0;
    unsigned long long seed = strtoull(rest, NULL, 10);
    if (errno || strlen(rest) > 20 || strspn(rest, "0123456789") != strlen(rest)) {
        char q[4 * CONFIG_QUOTE_MAX + 48];
        config_quote(rest, strlen(rest), q, sizeof q);
        snprintf(c->answer, c->len, "random: %s is not a seed (expected a whole number from 0 "
                 "to 2^64 - 1)", q);
        return REPLY_ERROR;
    }
    return verb(c->app, ACT_RANDOM, &(struct verb_arg){.seeded = true, .seed = seed}, c->answer,
                c->len);
}

/* The next word of *rest, cut off; *rest moves past it and its blanks. */
static char *next_word(char **rest)
{
    char *word = *rest, *after = word + strcspn(word, " \t");
    if (*after)
        *after++ = '\0';
    *rest = after + strspn(after, " \t");
    return word;
}

static enum command_reply do_set(struct command_call *c)
{
    char *value = c->rest, *name = next_word(&value);
    return set_control(c->app, name, value, c->answer, c->len);
}

static enum command_reply do_preset(struct command_call *c)
{
    return load_preset(c->app, c->rest, c->answer, c->len);
}

static enum command_reply do_presets(struct command_call *c)
{
    return say_presets(c->app, c->answer, c->len);
}

static enum command_reply do_modes(struct command_call *c)
{
    return say_modes(c->app, c->answer, c->len);
}

static enum command_reply do_mode(struct command_call *c)
{
    int k = whole(c->rest, c->app->model->n);
    if (!k) {
        char q[4 * CONFIG_QUOTE_MAX + 48];
        config_quote(c->rest, strlen(c->rest), q, sizeof q);
        snprintf(c->answer, c->len, "mode: %s is not a mode of this chain (expected 1 <= K <= "
                 "%d)", q, c->app->model->n);
        return REPLY_ERROR;
    }
    return verb(c->app, ACT_MODE, &(struct verb_arg){.index = k - 1}, c->answer, c->len);
}

static enum command_reply do_place(struct command_call *c)
{
    char *x = c->rest, *mass = next_word(&x);
    int k = whole(mass, c->app->model->n);
    double x0;
    if (!k || !*x || config_parse_number(x, &x0)) {
        char q[4 * CONFIG_QUOTE_MAX + 48];
        config_quote(k ? x : mass, strlen(k ? x : mass), q, sizeof q);
        snprintf(c->answer, c->len, "place: %s is not %s (expected place MASS X0, 1 <= MASS <= "
                 "%d, X0 in m)", q, k ? "a displacement" : "a mass of this chain",
                 c->app->model->n);
        return REPLY_ERROR;
    }
    return verb(c->app, ACT_PLACE, &(struct verb_arg){.index = k - 1, .value = x0}, c->answer,
                c->len);
}

static enum command_reply do_element(struct command_call *c)
{
    char *v = c->rest, *what = next_word(&v), *i = next_word(&v);
    int n = c->app->model->n;
    char kind = strlen(what) == 1 ? what[0] : strcmp(what, "cs") == 0 ? 's' : 0;
    double idx;
    bool spring = kind == 'k' || kind == 's';
    if ((kind != 'm' && kind != 'c' && !spring) || config_parse_number(i, &idx) ||
        idx != floor(idx) || idx < (spring ? 0 : 1) || idx > n || !*v) {
        snprintf(c->answer, c->len, "element: expected element m|c|k|cs I VALUE (mass I from 1 "
                 "to %d: m its mass, c its damping; spring I from 0 to %d: k its constant, cs "
                 "its damper)", n, n);
        return REPLY_ERROR;
    }
    if (kind == 's')
        return verb(c->app, ACT_SPRING_DAMPING, &(struct verb_arg){.index = (int)idx, .text = v},
                    c->answer, c->len);
    return verb(c->app, ACT_ELEMENT, &(struct verb_arg){.what = kind,
                .index = (int)idx - !spring, .text = v}, c->answer, c->len);
}

static enum command_reply do_nearest(struct command_call *c)
{
    return verb(c->app, ACT_NEAREST, NULL, c->answer, c->len);
}

static enum command_reply do_sweep(struct command_call *c)
{
    return verb(c->app, ACT_SWEEP, NULL, c->answer, c->len);
}

static enum command_reply do_speed(struct command_call *c)
{
    bool faster = c->cmd == CMD_FASTER;
    unsigned changed;
    verb_do(c->app, faster ? ACT_FASTER : ACT_SLOWER, NULL, &changed);
    char value[32];
    app_control_value(c->app, CTL_SPEED, value, sizeof value);
    snprintf(c->answer, c->len, "Speed %s%s", value,
             changed ? "" : faster ? " (the fastest)" : " (the slowest)");
    return REPLY_OK;
}

static enum command_reply do_save(struct command_call *c)
{
    char *how = c->rest, *name = next_word(&how);
    if (*how && strcmp(how, "replace") != 0) {
        char q[4 * CONFIG_QUOTE_MAX + 48];
        config_quote(how, strlen(how), q, sizeof q);
        snprintf(c->answer, c->len, "save: %s is not 'replace' (expected save NAME [replace])",
                 q);
        return REPLY_ERROR;
    }
    enum app_save st = app_save(c->app, name, *how != '\0');
    if (st == SAVE_EXISTS) {
        snprintf(c->answer, c->len, "save: preset %s exists (save %s replace replaces it)", name,
                 name);
        return REPLY_ERROR;
    }
    snprintf(c->answer, c->len, "%s", c->app->message);
    return st == SAVE_OK ? REPLY_OK : REPLY_ERROR;
}

/* The samples; after a sweep, its points beside the theory too. */
static enum command_reply do_export(struct command_call *c)
{
    enum command_reply r = verb(c->app, ACT_EXPORT, NULL, c->answer, c->len);
    if (r != REPLY_OK || sweep_measured(c->app->sweep) == 0)
        return r;
    size_t used = strlen(c->answer);
    r = reply_of(verb_do(c->app, ACT_EXPORT, &(struct verb_arg){.sweep = true}, NULL));
    snprintf(c->answer + used, c->len - used, "; %s", c->app->message);
    return r;
}

static enum command_reply do_cursor(struct command_call *c)
{
    return scope_say_cursor(c->app, c->rest, c->answer, c->len) ? REPLY_OK : REPLY_ERROR;
}

static enum command_reply do_measure(struct command_call *c)
{
    return scope_say_measure(c->app, c->rest, c->answer, c->len) ? REPLY_OK : REPLY_ERROR;
}

static enum command_reply do_run(struct command_call *c)
{
    const char *why = config_parse_number(c->rest, c->value);
    if (why || !(*c->value > 0.0 && *c->value <= RUN_MAX)) {
        char q[4 * CONFIG_QUOTE_MAX + 48];
        config_quote(c->rest, strlen(c->rest), q, sizeof q);
        snprintf(c->answer, c->len, "run: %s %s (expected 0 < SECONDS <= %g)", q,
                 why ? why : "is out of range", RUN_MAX);
        return REPLY_ERROR;
    }
    return REPLY_RUN;
}

static enum command_reply do_view(struct command_call *c)
{
    for (int v = 0; v < CV_COUNT; v++)
        if (strcmp(c->rest, command_views[v]) == 0) {
            *c->value = v;
            snprintf(c->answer, c->len, "view %s (the interactive program shows it)", c->rest);
            return REPLY_VIEW;
        }
    char q[4 * CONFIG_QUOTE_MAX + 48];
    config_quote(c->rest, strlen(c->rest), q, sizeof q);
    snprintf(c->answer, c->len, "view: %s is not a view (expected plots, x, v, a, x-v, x-a, "
             "v-a, modes, response, energy or spectrum)", q);
    return REPLY_ERROR;
}

static enum command_reply do_status(struct command_call *c)
{
    command_status(c->app, c->answer, c->len);
    return REPLY_OK;
}

static enum command_reply do_controls(struct command_call *c)
{
    return say_controls(c->app, c->answer, c->len);
}

/* "PREFIX'WORD' is not a command (expected ...)": what dispatch and help both say. */
static enum command_reply not_a_command(const char *prefix, const char *word, char *answer,
                                        size_t len)
{
    char q[4 * CONFIG_QUOTE_MAX + 48], list[600];
    command_list(list, sizeof list);
    config_quote(word, strlen(word), q, sizeof q);
    snprintf(answer, len, "%s%s is not a command (expected %s)", prefix, q, list);
    return REPLY_ERROR;
}

static enum command_reply do_help(struct command_call *c)
{
    char list[600];
    if (!*c->rest) {
        command_list(list, sizeof list);
        snprintf(c->answer, c->len, "commands: %s (help COMMAND says what one does)", list);
        return REPLY_OK;
    }
    int h = command_find(c->rest, strlen(c->rest));
    if (h < 0)
        return not_a_command("help: ", c->rest, c->answer, c->len);
    const struct command *row = &commands[h];
    if (h == CMD_SET) {
        control_list(list, sizeof list);
        snprintf(c->answer, c->len, "set CONTROL VALUE: %s; controls: %s", row->help, list);
    } else {
        snprintf(c->answer, c->len, "%s%s%s: %s", row->name, row->args[0] ? " " : "", row->args,
                 row->help);
    }
    return REPLY_OK;
}

static enum command_reply do_quit(struct command_call *c)
{
    int d;
    double t = now_t(c->app, &d);
    snprintf(c->answer, c->len, "quit at t = %.*f s", d, t);
    return REPLY_QUIT;
}

/* Recorded (R): a recording replays it (not pause: in a lesson it waits for the user,
 * and every run ends paused anyway). Not in a lesson (N): it writes files or ends the
 * program. Says play (P): its answer says whether the chain runs now. */
#define R COMMAND_RECORDED
#define N COMMAND_NOT_IN_LESSON
#define P COMMAND_SAYS_PLAY
const struct command commands[CMD_COUNT] = {
    [CMD_START] = {"start", "", "start the simulation; time follows the clock at the Speed "
                                "control's rate", do_start_pause, R | P},
    [CMD_PAUSE] = {"pause", "", "pause it", do_start_pause, P},
    [CMD_STEP] = {"step", "", "one step of dt forward (pauses)", do_step, R | P},
    [CMD_BACK] = {"back", "", "one step back (paused; up to 500 states)", do_back, R},
    [CMD_RESET] = {"reset", "", "back to the initial conditions, t = 0", do_reset, R},
    [CMD_RANDOM] = {"random", "[SEED]",
                    "random initial positions (from SEED: the same each time), and a reset",
                    do_random, R},
    [CMD_SET] = {"set", "CONTROL VALUE",
                 "set a control as typed in the interactive program (controls lists them)",
                 do_set, R},
    [CMD_PRESET] = {"preset", "NAME", "load a preset by name or file", do_preset, R},
    [CMD_PRESETS] = {"presets", "", "the presets' names", do_presets, 0},
    [CMD_MODES] = {"modes", "", "each natural frequency with its damping ratio and Q", do_modes,
                   0},
    [CMD_MODE] = {"mode", "K", "start the chain in mode K, at rest, running", do_mode, R | P},
    [CMD_PLACE] = {"place", "MASS X0",
                   "start mass MASS displaced by X0 m (kept inside its neighbours), the others "
                   "where they stand, at rest, t = 0 (paused)", do_place, R},
    [CMD_ELEMENT] = {"element", "m|c|k|cs I VALUE",
                     "one element: mass I's mass (m) or damping (c), or spring I's constant "
                     "(k) or the damper beside it (cs; spring 0 is the wall's, spring N the "
                     "motor's)", do_element, R},
    [CMD_NEAREST] = {"nearest", "", "drive at the nearest natural frequency", do_nearest, R},
    [CMD_SWEEP] = {"sweep", "", "start / stop a sine-sweep experiment", do_sweep, R},
    [CMD_FASTER] = {"faster", "", "playback faster", do_speed, R},
    [CMD_SLOWER] = {"slower", "", "playback slower", do_speed, R},
    [CMD_SAVE] = {"save", "NAME", "save the set-up as a user preset", do_save, N},
    [CMD_EXPORT] = {"export", "", "export the samples as CSV (and a sweep's points)", do_export,
                    N},
    [CMD_CURSOR] = {"cursor", "T",
                    "every mass's x, v, a and the motor at the recorded sample nearest to time T",
                    do_cursor, 0},
    [CMD_MEASURE] = {"measure", "[MASS]",
                     "period, frequency, peak-to-peak, rms, log decrement and zeta of a mass "
                     "over the time window", do_measure, 0},
    [CMD_RUN] = {"run", "SECONDS",
                 "run SECONDS of simulated time at once (not in real time), then pause", do_run,
                 P},
    [CMD_VIEW] = {"view", "NAME",
                  "what the interactive program shows (lessons set the scene with it): plots, "
                  "x, v, a, x-v, x-a, v-a (that plot enlarged), modes, response, energy or "
                  "spectrum; nothing changes here", do_view, R},
    [CMD_STATUS] = {"status", "", "the status line now", do_status, 0},
    [CMD_CONTROLS] = {"controls", "", "every control, its name for set and its value",
                      do_controls, 0},
    [CMD_HELP] = {"help", "[COMMAND]", "the commands, or what one does", do_help, 0},
    [CMD_QUIT] = {"quit", "", "quit (so does the end of input)", do_quit, N},
};
#undef R
#undef N
#undef P

/* One line: its reply, the answer into answer, a run's seconds or a view's number into
 * *value, the command's row into *row (-1 for none). */
static enum command_reply dispatch(struct app *app, const char *line, char *answer, size_t len,
                                   double *value, int *row)
{
    char buf[2048];
    snprintf(buf, sizeof buf, "%s", line);
    char *rest = buf + strspn(buf, " \t"), *word = next_word(&rest);
    for (char *end = rest + strlen(rest); end > rest && (end[-1] == ' ' || end[-1] == '\t');)
        *--end = '\0';
    if (!*word)
        return REPLY_NONE;
    int cmd = command_find(word, strlen(word));
    if (cmd < 0)
        return not_a_command("", word, answer, len);
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
        char q[4 * CONFIG_QUOTE_MAX + 48];
        config_quote(rest, strlen(rest), q, sizeof q);
        snprintf(answer, len, "%s: takes nothing, but was given %s", c->name, q);
        return REPLY_ERROR;
    }
    app_quiet(app);
    struct command_call call = {app, cmd, rest, answer, len, value};
    return c->run(&call);
}

enum command_reply command_do(struct app *app, const char *line, struct command_result *res)
{
    double value = 0.0;
    int row = -1;
    res->answer[0] = '\0';
    res->reply = dispatch(app, line, res->answer, sizeof res->answer, &value, &row);
    res->seconds = res->reply == REPLY_RUN ? value : 0.0;
    res->view = res->reply == REPLY_VIEW ? (int)value : -1;
    res->says_play = row >= 0 && (commands[row].flags & COMMAND_SAYS_PLAY);
    return res->reply;
}

bool command_done(enum command_reply r)
{
    return r == REPLY_OK || r == REPLY_WARNING || r == REPLY_VIEW;
}
