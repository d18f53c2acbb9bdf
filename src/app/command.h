/* command.h: the plain mode's commands (plain/), each a row naming the verb it does
 * (verb.h: the same verbs the key table binds keys to) with its help. `help` in the plain
 * mode, its man page section and its README table come from this one table. */
#ifndef SPRINGSIM_COMMAND_H
#define SPRINGSIM_COMMAND_H

#include <stdbool.h>
#include <stddef.h>

#include "verb.h"

struct app;

/* The plain mode's commands. */
enum command_id {
    CMD_START,
    CMD_PAUSE,
    CMD_STEP,
    CMD_BACK,
    CMD_RESET,
    CMD_RANDOM,
    CMD_SET,
    CMD_PRESET,
    CMD_PRESETS,
    CMD_MODES,
    CMD_MODE,
    CMD_PLACE,
    CMD_ELEMENT,
    CMD_NEAREST,
    CMD_SWEEP,
    CMD_FASTER,
    CMD_SLOWER,
    CMD_SAVE,
    CMD_EXPORT,
    CMD_CURSOR,
    CMD_MEASURE,
    CMD_RUN,
    CMD_VIEW,
    CMD_STATUS,
    CMD_CONTROLS,
    CMD_HELP,
    CMD_QUIT,
    CMD_COUNT
};

/* What a command line came to. */
enum command_reply {
    REPLY_NONE,    /* a blank line: nothing to answer */
    REPLY_OK,      /* done; the answer says what it did */
    REPLY_WARNING, /* done, with a caveat the answer carries (dt past a limit of the chain
                    * now): an ok all the same */
    REPLY_ERROR,   /* refused, nothing changed; the answer says what was wrong and what is
                    * allowed */
    REPLY_RUN,   /* run: the caller runs *seconds of simulated time, then pauses */
    REPLY_VIEW,  /* view: the interactive program shows view *seconds (enum command_view);
                  * the answer says so */
    REPLY_QUIT   /* quit */
};

struct command_call;

/* The flags of a command's row. */
#define COMMAND_RECORDED 1u      /* a recording writes it (it changes the chain or the view) */
#define COMMAND_NOT_IN_LESSON 2u /* a lesson may not hold it: it writes files or ends */
#define COMMAND_SAYS_PLAY 4u     /* its answer says whether the chain runs now (start, step,
                                  * run, mode): a start or a pause it made is no event of
                                  * its own */

/* One row per command (tmux's cmd_entry): the plain mode, lessons, recordings and help
 * all read it; adding a command is a row and its function. */
struct command {
    const char *name; /* the word typed */
    const char *args; /* its arguments, for help ("" for none; "[X]" optional) */
    const char *help; /* what it does */
    enum command_reply (*run)(struct command_call *c); /* does it */
    unsigned flags;   /* COMMAND_* */
};

/* What a command's function is given: its row, the words after its name (blanks
 * trimmed; its own to cut up), where its answer goes, and where a run's seconds or a
 * view's number goes. */
struct command_call {
    struct app *app;
    int cmd;
    char *rest;
    char *answer;
    size_t len;
    double *value;
};

/* The commands, indexed by enum command_id. */
extern const struct command commands[CMD_COUNT];

/* The command named by the n bytes at name, or -1. */
int command_find(const char *name, size_t n);

/* What `view NAME` shows in the interactive program: the plots (the grid, or one
 * enlarged) or an analysis view. */
enum command_view {
    CV_PLOTS,
    CV_X, /* plots 1 to 6 enlarged: x, v, a, x-v, x-a, v-a (CV_X + p is plot p) */
    CV_V,
    CV_A,
    CV_XV,
    CV_XA,
    CV_VA,
    CV_MODES,
    CV_RESPONSE,
    CV_ENERGY,
    CV_SPECTRUM,
    CV_COUNT
};

/* Their names, as `view` takes them. */
extern const char *const command_views[CV_COUNT];


/* What a command line came to, its answer beside it (tmux's cmd_retval and the
 * message): what is decided on it is decided on reply and says_play, never on answer's
 * words. */
struct command_result {
    enum command_reply reply;
    char answer[2048]; /* one line without a newline (text of the app's messages and of the
                        * line itself included as they are: the caller escapes what it
                        * prints), "" for REPLY_NONE */
    double seconds;    /* REPLY_RUN: the simulated seconds to run */
    int view;          /* REPLY_VIEW: what to show (enum command_view) */
    bool says_play;    /* the answer says whether the chain runs now (struct command) */
};

/* Does what one line of the plain mode asks of app, going through the same app_*
 * functions as the keys; returns res->reply. */
enum command_reply command_do(struct app *app, const char *line, struct command_result *res);

/* Whether a reply is of a command done (ok, or ok with a warning; a view shown). */
bool command_done(enum command_reply r);

/* The status line: t, each mass's displacement and velocity, the drive's position. */
void command_status(const struct app *app, char *buf, size_t len);

/* The names set takes: one per control of the controls panel (enum control). */
const char *command_control_name(int ctl);

#endif
