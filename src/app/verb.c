/* verb.c: an action done through its row of the table of user verbs (verb.h; the rows
 * and their functions are command.c's). */
#include "verb.h"

#include <stdio.h>

#include "app.h"
#include "command.h"

enum result verb_result(const struct app *app, unsigned changed)
{
    if ((changed & ~(unsigned)APP_CHANGED_MESSAGE) && app->said == SAID_WARNING)
        return RESULT_WARNING;
    if (app->said != SAID_NOTE || (!changed && !app->message[0]))
        return RESULT_ERROR;
    return RESULT_OK;
}

bool verb_bound(enum action a)
{
    return a > ACT_NONE && a < ACT_COUNT && command_of_action(a) != NULL;
}

enum result verb_do(struct app *app, enum action a, const struct verb_arg *arg,
                    unsigned *changed)
{
    static const struct verb_arg none;
    const struct command *row = verb_bound(a) ? command_of_action(a) : NULL;
    unsigned what = 0;
    enum result r;
    app_quiet(app);
    arg = arg ? arg : &none;
    if (!row) {
        r = RESULT_ERROR;
    } else if (row->fn) {
        r = row->fn(app, arg, &what);
    } else {
        what = row->with  ? row->with(app, arg)
               : row->act ? row->act(app)
                          : row->go(app, row->way ? row->way : arg->dir);
        r = verb_result(app, what);
    }
    if (changed)
        *changed = what;
    return r;
}

const char *verb_command_name(int a)
{
    const struct command *row = verb_bound((enum action)a) ? command_of_action(a) : NULL;
    return row ? row->name : NULL;
}

void verb_command(enum action a, const struct verb_arg *arg, unsigned changed, bool running,
                  char *out, size_t len)
{
    const struct command *row = verb_bound(a) ? command_of_action(a) : NULL;
    out[0] = '\0';
    changed &= ~(unsigned)APP_CHANGED_MESSAGE;
    /* A pause is not written: in a lesson it waits for the user (a run ends paused). */
    if (!row || !(row->flags & COMMAND_BY_KEY) || !changed || (a == ACT_RUN && !running))
        return;
    if (row->args[0] && row->args[0] != '[') /* the number the key chose: mode K */
        snprintf(out, len, "%s %d", row->name, (arg ? arg->index : 0) + 1);
    else
        snprintf(out, len, "%s", row->name);
}
