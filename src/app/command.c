/* command.c: the table of user verbs (command.h), one row each, and each row's functions:
 * the app's (what the key's action does, verb_do calls it) and the command's (do_NAME:
 * its words turned into the verb's argument, its result into the answer). */
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
#include "ghost.h"
#include "scope.h"


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

/* Each row's app function: what its key's action does (verb_do calls it). */

static enum result run(struct app *app, const struct verb_arg *arg, unsigned *changed)
{
    bool on = arg->dir > 0 || (arg->dir == 0 && !app->running);
    *changed = app_set_running(app, on);
    return RESULT_OK; /* running already, paused already: as asked */
}

/* Pauses, and one step: what the step changed (0 for a blow-up: paused, and said why). */
static enum result step(struct app *app, const struct verb_arg *arg, unsigned *changed)
{
    (void)arg;
    app_set_running(app, false);
    *changed = app_step(app);
    return *changed ? RESULT_OK : RESULT_ERROR;
}

static enum result back(struct app *app, const struct verb_arg *arg, unsigned *changed)
{
    (void)arg;
    *changed = app_back(app);
    return *changed ? RESULT_OK : RESULT_ERROR;
}

static enum result reset(struct app *app, const struct verb_arg *arg, unsigned *changed)
{
    (void)arg;
    *changed = app_reset(app) | app_say(app, SAID_NOTE, "reset to t = 0, at the initial "
                                        "conditions");
    return RESULT_OK;
}

static enum result random_start(struct app *app, const struct verb_arg *arg, unsigned *changed)
{
    *changed = arg->seeded ? app_random_seed(app, arg->seed) : app_random(app);
    return verb_result(app, *changed);
}

static enum result nearest(struct app *app, const struct verb_arg *arg, unsigned *changed)
{
    (void)arg;
    *changed = app_nearest_mode(app);
    if (!*changed && !app->message[0])
        *changed = app_say(app, SAID_ERROR, "nearest: the modes are not known");
    return verb_result(app, *changed);
}

/* Playback slower or faster: at either end it stays as it is, and that is no error. */
static enum result speed(struct app *app, int dir, unsigned *changed)
{
    *changed = app_adjust(app, CTL_SPEED, dir, false);
    return RESULT_OK;
}

static enum result slower(struct app *app, const struct verb_arg *arg, unsigned *changed)
{
    (void)arg;
    return speed(app, -1, changed);
}

static enum result faster(struct app *app, const struct verb_arg *arg, unsigned *changed)
{
    (void)arg;
    return speed(app, 1, changed);
}

/* The app's actions that take the verb's argument, their result by verb_result. */

/* The samples, or the sweep's points (its file's path is in the message). */
static unsigned export(struct app *app, const struct verb_arg *arg)
{
    char path[4200];
    return arg->sweep ? app_export_sweep(app, NULL, path, sizeof path)
                      : app_export(app, NULL, path, sizeof path);
}

static unsigned mode(struct app *app, const struct verb_arg *arg)
{
    return app_start_mode(app, arg->index);
}

static unsigned set(struct app *app, const struct verb_arg *arg)
{
    return app_set_text(app, (enum control)arg->index, arg->text);
}

static unsigned element(struct app *app, const struct verb_arg *arg)
{
    return app_set_element(app, arg->what, arg->index, arg->text);
}

static unsigned cubic(struct app *app, const struct verb_arg *arg)
{
    return app_set_cubic(app, arg->index, arg->text);
}

static unsigned spring_damping(struct app *app, const struct verb_arg *arg)
{
    return app_set_spring_damping(app, arg->index, arg->text);
}

static unsigned place(struct app *app, const struct verb_arg *arg)
{
    return app_place_start(app, arg->index, arg->value);
}

static unsigned preset(struct app *app, const struct verb_arg *arg)
{
    return app_load_preset(app, arg->text, arg->name);
}

static unsigned window(struct app *app, const struct verb_arg *arg)
{
    return app_set_window(app, arg->text);
}

/* The controls' names, for help's set: "controls: preset, masses, ...". */
static void controls_more(char *buf, size_t len)
{
    char names[200];
    control_list(names, sizeof names);
    snprintf(buf, len, "controls: %s", names);
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

/* start (run) or pause. */
static enum command_reply start_pause(struct command_call *c, bool run)
{
    struct app *app = c->app;
    bool was = app->running;
    int d;
    verb_do(app, ACT_RUN, &(struct verb_arg){.dir = run ? 1 : -1}, NULL);
    double t = now_t(app, &d);
    snprintf(c->answer, c->len, "%s at t = %.*f s", was == run ? run ? "running already" :
             "paused already" : run ? "started" : "paused", d, t);
    return REPLY_OK;
}

static enum command_reply do_start(struct command_call *c)
{
    return start_pause(c, true);
}

static enum command_reply do_pause(struct command_call *c)
{
    return start_pause(c, false);
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
    enum command_reply r;
    if (kind == 's')
        r = verb(c->app, ACT_SPRING_DAMPING, &(struct verb_arg){.index = (int)idx, .text = v},
                 c->answer, c->len);
    else
        r = verb(c->app, ACT_ELEMENT, &(struct verb_arg){.what = kind,
                 .index = (int)idx - !spring, .text = v}, c->answer, c->len);
    /* Springs are numbered from 0 here, from 1 in their labels (spring 1 (wall–1)): the
     * reply names both, so neither is mistaken for the other. */
    if (spring && strncmp(c->answer, "spring ", 7) == 0) {
        char said[sizeof c->app->message];
        snprintf(said, sizeof said, "%s", c->answer);
        snprintf(c->answer, c->len, "element %s %d is %s", what, (int)idx, said);
    }
    return r;
}

static enum command_reply do_nearest(struct command_call *c)
{
    return verb(c->app, ACT_NEAREST, NULL, c->answer, c->len);
}

static enum command_reply do_sweep(struct command_call *c)
{
    return verb(c->app, ACT_SWEEP, NULL, c->answer, c->len);
}

static enum command_reply do_ghost(struct command_call *c)
{
    return verb(c->app, ACT_GHOST, NULL, c->answer, c->len);
}

/* faster or slower: the speed now, and whether it is at its end. */
static enum command_reply speed_to(struct command_call *c, bool faster)
{
    unsigned changed;
    verb_do(c->app, faster ? ACT_FASTER : ACT_SLOWER, NULL, &changed);
    char value[32];
    app_control_value(c->app, CTL_SPEED, value, sizeof value);
    snprintf(c->answer, c->len, "Speed %s%s", value,
             changed ? "" : faster ? " (the fastest)" : " (the slowest)");
    return REPLY_OK;
}

static enum command_reply do_faster(struct command_call *c)
{
    return speed_to(c, true);
}

static enum command_reply do_slower(struct command_call *c)
{
    return speed_to(c, false);
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

static enum command_reply do_run(struct command_call *c)
{
    const char *why = config_parse_number(c->rest, c->value);
    if (why || !(*c->value >= 0.0 && *c->value <= RUN_MAX)) {
        char q[4 * CONFIG_QUOTE_MAX + 48];
        config_quote(c->rest, strlen(c->rest), q, sizeof q);
        snprintf(c->answer, c->len, "run: %s %s (expected 0 <= SECONDS <= %g)", q,
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

static enum command_reply do_quit(struct command_call *c)
{
    int d;
    double t = now_t(c->app, &d);
    snprintf(c->answer, c->len, "quit at t = %.*f s", d, t);
    return REPLY_QUIT;
}

/* Recorded (R): a recording replays it (not pause: in a lesson it waits for the user,
 * and every run ends paused anyway); by key (K): a key doing it is recorded as it. Not
 * in a lesson: it writes files (W) or ends the program (E). Says play (P): its answer
 * says whether the chain runs now. */
#define R COMMAND_RECORDED
#define K COMMAND_BY_KEY
#define W COMMAND_WRITES
#define E COMMAND_ENDS
#define P COMMAND_SAYS_PLAY
const struct command commands[] = {
    {"start", "", "start the simulation; time follows the clock at the Speed control's rate",
     do_start, .action = ACT_RUN, .fn = run, .flags = R | K | P},
    {"pause", "", "pause it", do_pause, .flags = P},
    {"step", "", "one step of dt forward (pauses)", do_step, .action = ACT_STEP, .fn = step,
     .flags = R | K | P},
    {"back", "", "one step back (paused; up to 500 states)", do_back, .action = ACT_BACK,
     .fn = back, .flags = R | K},
    {"reset", "", "back to the initial conditions, t = 0", do_reset, .action = ACT_RESET,
     .fn = reset, .flags = R | K},
    {"random", "[SEED]", "random initial positions (from SEED: the same each time), and a "
     "reset", do_random, .action = ACT_RANDOM, .fn = random_start,
     .flags = R | K | COMMAND_SEEDED},
    {"set", "CONTROL VALUE", "set a control as typed in the interactive program (controls "
     "lists them)", do_set, controls_more, .action = ACT_SET, .with = set,
     .flags = R | COMMAND_OWN_WORDS},
    {"preset", "NAME", "load a preset by name or file", do_preset, .action = ACT_PRESET,
     .with = preset, .flags = R | COMMAND_LOADS | COMMAND_WHOLE},
    {"presets", "", "the presets' names", say_presets, .flags = 0},
    {"modes", "", "each natural frequency with its damping ratio and Q", say_modes, .flags = 0},
    {"mode", "K", "start the chain in mode K, at rest, running", do_mode, .action = ACT_MODE,
     .with = mode, .flags = R | K | P},
    {"place", "MASS X0", "start mass MASS displaced by X0 m (kept inside its neighbours), the "
     "others where they stand, at rest, t = 0 (paused)", do_place, .action = ACT_PLACE,
     .with = place, .flags = R},
    {"element", "m|c|k|cs I VALUE", "one element: mass I's mass (m) or damping (c), or spring "
     "I's constant (k) or the damper beside it (cs; spring 0 is the wall's, spring N the "
     "motor's)", do_element, .action = ACT_ELEMENT, .with = element, .flags = R},
    {"nearest", "", "drive at the nearest natural frequency", do_nearest,
     .action = ACT_NEAREST, .fn = nearest, .flags = R | K},
    {"sweep", "", "start / stop a sine-sweep experiment", do_sweep, .action = ACT_SWEEP,
     .act = app_toggle_sweep, .flags = R | K},
    {"ghost", "", "a frozen copy run beside the chain, its settings kept; the interactive "
     "program shows it (again: drop it)",
     do_ghost, .action = ACT_GHOST, .act = app_toggle_ghost, .flags = R | K},
    {"faster", "", "playback faster", do_faster, .action = ACT_FASTER, .fn = faster,
     .flags = R | K},
    {"slower", "", "playback slower", do_slower, .action = ACT_SLOWER, .fn = slower,
     .flags = R | K},
    {"save", "NAME", "save the set-up as a user preset", do_save, .flags = W},
    {"export", "", "export the samples as CSV (and a sweep's points)", do_export,
     .action = ACT_EXPORT, .with = export, .flags = W},
    {"cursor", "T", "every mass's x, v, a and the motor at the recorded sample nearest to "
     "time T", say_cursor, .flags = 0},
    {"measure", "[MASS]", "period, frequency, peak-to-peak, rms, log decrement and zeta of a "
     "mass over the time window", say_measure, .flags = 0},
    {"run", "SECONDS", "run SECONDS of simulated time at once (not in real time), then "
     "pause (run 0: pause, nothing run)", do_run, .flags = P | COMMAND_RUNS},
    {"view", "NAME", "what the interactive program shows (lessons set the scene with it): "
     "plots, x, v, a, x-v, x-a, v-a (that plot enlarged), modes, response, energy or "
     "spectrum; nothing changes here", do_view, .flags = R},
    {"status", "", "the status line now", say_status, .flags = 0},
    {"controls", "", "every control, its name for set and its value", say_controls, .flags = 0},
    {"help", "[COMMAND]", "the commands, or what one does", command_help, .flags = 0},
    {"quit", "", "quit (so does the end of input)", do_quit, .flags = E},
    /* Verbs with no command of their own: a key's, or reached from a menu, a typed value
     * (Enter) or another command's words (set window, element cs). */
    {.action = ACT_NARROWER, .go = app_window_step, .way = -1},
    {.action = ACT_WIDER, .go = app_window_step, .way = 1},
    {.action = ACT_CURSOR_STEP, .go = scope_move},
    {.action = ACT_CURSOR_JUMP, .go = scope_jump},
    {.action = ACT_CURSOR_PAGE, .go = scope_page},
    {.action = ACT_CURSOR_MASS, .go = scope_select},
    {.action = ACT_APPLY, .act = app_apply_masses},
    {.action = ACT_WINDOW, .with = window},
    {.action = ACT_CUBIC, .with = cubic},
    {.action = ACT_SPRING_DAMPING, .with = spring_damping},
};
#undef R
#undef K
#undef W
#undef E
#undef P

const int command_rows = (int)(sizeof commands / sizeof *commands);
