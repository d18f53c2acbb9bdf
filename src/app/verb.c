/* verb.c: the verb table (verb.h): each action bound to the one function that does it. */
#include "verb.h"

#include <stdio.h>

#include "app.h"
#include "ghost.h"
#include "scope.h"

/* A verb's function: what it changed into *changed, what it came to returned. */
typedef enum result (*verb_fn)(struct app *app, const struct verb_arg *arg, unsigned *changed);

/* What an app action came to, from the kind of the message it made: a change made with a
 * warning; an error made (or the cap's note), or nothing done and nothing said; else
 * done. */
static enum result result_of(const struct app *app, unsigned changed)
{
    if ((changed & ~(unsigned)APP_CHANGED_MESSAGE) && app->said == SAID_WARNING)
        return RESULT_WARNING;
    if (app->said != SAID_NOTE || (!changed && !app->message[0]))
        return RESULT_ERROR;
    return RESULT_OK;
}

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
    return result_of(app, *changed);
}

static enum result nearest(struct app *app, const struct verb_arg *arg, unsigned *changed)
{
    (void)arg;
    *changed = app_nearest_mode(app);
    if (!*changed && !app->message[0])
        *changed = app_say(app, SAID_ERROR, "nearest: the modes are not known");
    return result_of(app, *changed);
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

/* The app's actions that take the verb's argument, their result by result_of. */

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

/* The verbs: the function of each action that is one (a verb with rules of its own; or
 * an app action taken as it is, its result by result_of: with the verb's argument, with
 * none, or with a way to go: a fixed one, or the argument's when way is 0), and the
 * plain command that does the same (for --record; NULL for none). */
static const struct {
    verb_fn fn;
    unsigned (*with)(struct app *app, const struct verb_arg *arg);
    unsigned (*act)(struct app *app);
    unsigned (*go)(struct app *app, int way);
    int way;
    const char *command;
} verbs[ACT_COUNT] = {
    [ACT_RUN] = {.fn = run, .command = "start"},
    [ACT_STEP] = {.fn = step, .command = "step"},
    [ACT_BACK] = {.fn = back, .command = "back"},
    [ACT_RESET] = {.fn = reset, .command = "reset"},
    [ACT_RANDOM] = {.fn = random_start, .command = "random"},
    [ACT_NEAREST] = {.fn = nearest, .command = "nearest"},
    [ACT_SWEEP] = {.act = app_toggle_sweep, .command = "sweep"},
    [ACT_SLOWER] = {.fn = slower, .command = "slower"},
    [ACT_FASTER] = {.fn = faster, .command = "faster"},
    [ACT_NARROWER] = {.go = app_window_step, .way = -1},
    [ACT_WIDER] = {.go = app_window_step, .way = 1},
    [ACT_GHOST] = {.act = app_toggle_ghost},
    [ACT_EXPORT] = {.with = export},
    [ACT_CURSOR_STEP] = {.go = scope_move},
    [ACT_CURSOR_JUMP] = {.go = scope_jump},
    [ACT_CURSOR_PAGE] = {.go = scope_page},
    [ACT_CURSOR_MASS] = {.go = scope_select},
    [ACT_MODE] = {.with = mode, .command = "mode"},
    [ACT_APPLY] = {.act = app_apply_masses},
    [ACT_SET] = {.with = set},
    [ACT_ELEMENT] = {.with = element},
    [ACT_PLACE] = {.with = place},
    [ACT_PRESET] = {.with = preset},
    [ACT_WINDOW] = {.with = window},
    [ACT_CUBIC] = {.with = cubic},
    [ACT_SPRING_DAMPING] = {.with = spring_damping},
};

bool verb_bound(enum action a)
{
    return a > ACT_NONE && a < ACT_COUNT &&
           (verbs[a].fn || verbs[a].with || verbs[a].act || verbs[a].go);
}

enum result verb_do(struct app *app, enum action a, const struct verb_arg *arg,
                    unsigned *changed)
{
    static const struct verb_arg none;
    unsigned what = 0;
    enum result r;
    app_quiet(app);
    arg = arg ? arg : &none;
    if (!verb_bound(a)) {
        r = RESULT_ERROR;
    } else if (verbs[a].fn) {
        r = verbs[a].fn(app, arg, &what);
    } else {
        what = verbs[a].with  ? verbs[a].with(app, arg)
               : verbs[a].act ? verbs[a].act(app)
                              : verbs[a].go(app, verbs[a].way ? verbs[a].way : arg->dir);
        r = result_of(app, what);
    }
    if (changed)
        *changed = what;
    return r;
}

const char *verb_command_name(int a)
{
    return verb_bound((enum action)a) ? verbs[a].command : NULL;
}

void verb_command(enum action a, const struct verb_arg *arg, unsigned changed, bool running,
                  char *out, size_t len)
{
    out[0] = '\0';
    changed &= ~(unsigned)APP_CHANGED_MESSAGE;
    /* A pause is not written: in a lesson it waits for the user (a run ends paused). */
    if (!verb_bound(a) || !verbs[a].command || !changed || (a == ACT_RUN && !running))
        return;
    if (a == ACT_MODE)
        snprintf(out, len, "mode %d", (arg ? arg->index : 0) + 1);
    else
        snprintf(out, len, "%s", verbs[a].command);
}
