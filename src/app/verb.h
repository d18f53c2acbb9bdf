/* verb.h: an action done to the app through its row of the one table of user verbs
 * (command.h; htop's Action.c). The key table (tui/input.c) maps keys to actions and the
 * terminal program hands every action that is not screen-only (overlays, focus, the
 * arrows in the panels, views) to verb_do, which finds the row; the plain mode's
 * commands turn their words into a verb_arg for the same call. What a verb came to is an
 * enum beside the app's message (tmux's cmd_retval), set where the message is made:
 * nothing is decided on its words. */
#ifndef SPRINGSIM_VERB_H
#define SPRINGSIM_VERB_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "action.h"

struct app;


/* What a verb came to; the message beside it is the app's (app->message). */
enum result {
    RESULT_OK,      /* done; the message, if any, says what */
    RESULT_WARNING, /* done, with a caveat the message says (dt past a limit now) */
    RESULT_ERROR,   /* refused or failed, nothing changed; the message says why (or
                     * there is none: nothing to do) */
};

/* A verb's arguments: what the screen's selection or the command's words say. */
struct verb_arg {
    int dir;          /* run: +1 start, -1 pause, 0 the other; the cursor's moves: -1
                       * earlier, +1 later */
    int index;        /* mode (0 the lowest), mass (0 the first), spring (0 the wall's),
                       * control (enum control) */
    char what;        /* element: 'm' mass, 'c' damping, 'k' spring */
    double value;     /* place: the displacement (m) */
    const char *text; /* set, element, window: the value typed; preset: the file */
    const char *name; /* preset: its name */
    bool seeded;      /* random: from seed, not a fresh one */
    uint64_t seed;
    bool sweep;       /* export: the sweep's points, not the samples */
};

/* A verb's function for a key's action (a row of command.h's table): what it changed
 * into *changed, what it came to returned. */
typedef enum result (*verb_fn)(struct app *app, const struct verb_arg *arg, unsigned *changed);

/* What an app action came to, from the kind of the message it made: a change made with a
 * warning; an error made (or the cap's note), or nothing done and nothing said; else
 * done. */
enum result verb_result(const struct app *app, unsigned changed);

/* Whether a is a verb of the table (and not screen-only). */
bool verb_bound(enum action a);

/* Does verb a to app with arg (NULL: none), the message cleared first; what changed
 * (enum app_change) into *changed if not NULL. */
enum result verb_do(struct app *app, enum action a, const struct verb_arg *arg,
                    unsigned *changed);

/* The plain command of verb a ("start" for ACT_RUN), or NULL: how the plain mode names
 * the action in the app's messages. */
const char *verb_command_name(int a);

/* The plain command that does what verb a did (its arg, what it changed, whether the
 * chain runs now) again, for --record: "start", "mode 2"; "" when there is none (a
 * pause, a step that did nothing, a verb with no command). */
void verb_command(enum action a, const struct verb_arg *arg, unsigned changed, bool running,
                  char *out, size_t len);

#endif
