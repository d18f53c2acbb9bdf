/* command_line.c: a line of the plain mode read against the table of user verbs
 * (command.h): its first word finds the row, the words after it are checked against the
 * row's arguments, and the row's function answers; help is said from the rows. */
#include "command.h"

#include <stdio.h>
#include <string.h>

#include "../core/config.h"
#include "app.h"

const char *const command_views[CV_COUNT] = {
    [CV_PLOTS] = "plots", [CV_X] = "x",   [CV_V] = "v",     [CV_A] = "a",
    [CV_XV] = "x-v",      [CV_XA] = "x-a", [CV_VA] = "v-a", [CV_MODES] = "modes",
    [CV_RESPONSE] = "response", [CV_ENERGY] = "energy", [CV_SPECTRUM] = "spectrum",
};

const struct command *command_find(const char *name, size_t n)
{
    for (int i = 0; i < command_rows; i++)
        if (commands[i].name && strlen(commands[i].name) == n &&
            strncmp(commands[i].name, name, n) == 0)
            return &commands[i];
    return NULL;
}

const struct command *command_of_action(enum action a)
{
    for (int i = 0; i < command_rows; i++)
        if (a != ACT_NONE && commands[i].action == a)
            return &commands[i];
    return NULL;
}

/* The commands' names with their arguments, "start, pause, ..., set CONTROL VALUE, ...". */
static void command_list(char *buf, size_t len)
{
    size_t used = 0;
    buf[0] = '\0';
    for (int i = 0; i < command_rows && used < len; i++)
        if (commands[i].name)
            used += (size_t)snprintf(buf + used, len - used, "%s%s%s%s", used ? ", " : "",
                                     commands[i].name, commands[i].args[0] ? " " : "",
                                     commands[i].args);
}

/* "PREFIX'WORD' is not a command (expected ...)": what a line and help both say. */
static enum command_reply not_a_command(const char *prefix, const char *word, char *answer,
                                        size_t len)
{
    char q[4 * CONFIG_QUOTE_MAX + 48], list[600];
    command_list(list, sizeof list);
    config_quote(word, strlen(word), q, sizeof q);
    snprintf(answer, len, "%s%s is not a command (expected %s)", prefix, q, list);
    return REPLY_ERROR;
}

enum command_reply command_help(struct command_call *c)
{
    char list[600], more[600] = "";
    if (!*c->rest) {
        command_list(list, sizeof list);
        snprintf(c->answer, c->len, "commands: %s (help COMMAND says what one does)", list);
        return REPLY_OK;
    }
    const struct command *row = command_find(c->rest, strlen(c->rest));
    if (!row)
        return not_a_command("help: ", c->rest, c->answer, c->len);
    if (row->more)
        row->more(more, sizeof more);
    snprintf(c->answer, c->len, "%s%s%s: %s%s%s", row->name, row->args[0] ? " " : "",
             row->args, row->help, more[0] ? "; " : "", more);
    return REPLY_OK;
}

/* The line's first word cut off: the word returned, *rest past it and its blanks, the
 * blanks after the rest trimmed. */
static char *first_word(char *line, char **rest)
{
    char *word = line + strspn(line, " \t"), *after = word + strcspn(word, " \t");
    if (*after)
        *after++ = '\0';
    *rest = after + strspn(after, " \t");
    for (char *end = *rest + strlen(*rest);
         end > *rest && (end[-1] == ' ' || end[-1] == '\t');)
        *--end = '\0';
    return word;
}

/* One line: its reply, the answer into answer, a run's seconds or a view's number into
 * *value, the command's row into *row (NULL for none). */
static enum command_reply dispatch(struct app *app, const char *line, char *answer, size_t len,
                                   double *value, const struct command **row)
{
    char buf[2048], *rest;
    snprintf(buf, sizeof buf, "%s", line);
    char *word = first_word(buf, &rest);
    if (!*word)
        return REPLY_NONE;
    const struct command *c = command_find(word, strlen(word));
    if (!c)
        return not_a_command("", word, answer, len);
    *row = c;
    struct command_call call = {app, rest, answer, len, value};
    bool wants = c->args[0] && c->args[0] != '[';
    if (wants && !*rest && (c->flags & COMMAND_OWN_WORDS))
        return c->run(&call);
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
    return c->run(&call);
}

enum command_reply command_do(struct app *app, const char *line, struct command_result *res)
{
    double value = 0.0;
    const struct command *row = NULL;
    res->answer[0] = '\0';
    res->reply = dispatch(app, line, res->answer, sizeof res->answer, &value, &row);
    res->seconds = res->reply == REPLY_RUN ? value : 0.0;
    res->view = res->reply == REPLY_VIEW ? (int)value : -1;
    res->says_play = row && (row->flags & COMMAND_SAYS_PLAY);
    return res->reply;
}

bool command_done(enum command_reply r)
{
    return r == REPLY_OK || r == REPLY_WARNING || r == REPLY_VIEW;
}
