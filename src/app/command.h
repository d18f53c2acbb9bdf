/* command.h: the user's verbs, one row each (command.c): the plain mode's command that
 * names it, the key table's action that does it, and the app's function both come to
 * (verb.h). `help` in the plain mode, lessons, recordings and the keys read this one
 * table; command_line.c reads a line of the plain mode against it. */
#ifndef SPRINGSIM_COMMAND_H
#define SPRINGSIM_COMMAND_H

#include <stdbool.h>
#include <stddef.h>

#include "verb.h"

struct app;

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

/* The flags of a row: what a recording, a lesson and the plain mode's reader decide on. */
#define COMMAND_RECORDED 1u     /* a recording writes the command (it changes the chain or
                                 * the view) */
#define COMMAND_BY_KEY 2u       /* a key doing it is recorded as the command, with the
                                 * number the key chose when it takes one (mode K); a key's
                                 * other changes are recorded as the set and place lines of
                                 * what they changed */
#define COMMAND_WRITES 4u       /* it writes a file: a lesson may not hold it */
#define COMMAND_ENDS 8u         /* it ends the program: a lesson may not hold it */
#define COMMAND_NOT_IN_LESSON (COMMAND_WRITES | COMMAND_ENDS)
#define COMMAND_SAYS_PLAY 16u   /* its answer says whether the chain runs now (start, step,
                                 * run, mode): a start or a pause it made is no event of its
                                 * own */
#define COMMAND_RUNS 32u        /* it runs its SECONDS of simulated time at once: a lesson
                                 * counts them against the time it may run */
#define COMMAND_LOADS 64u       /* it loads a known chain: a lesson's first command */
#define COMMAND_WHOLE 128u      /* its argument is the rest of the line, blanks inside kept
                                 * (a file's name): a recording writes it so */
#define COMMAND_SEEDED 256u     /* a recording writes it with the seed it drew, so that the
                                 * replay draws the same */
#define COMMAND_OWN_WORDS 512u  /* its function says itself what is missing when it is
                                 * given no words (set lists the controls) */

/* One row per user verb (tmux's cmd_entry), in the order help lists them: its command
 * (name, arguments, help, the function that reads its words), the key table's action for
 * it and the app's function that does it, and its flags. The plain mode, lessons,
 * recordings, help and the key table (through verb_do) all read it; adding a command is
 * a row and its function. A row without a name is a verb with no command of its own (a
 * key's, or one a menu, a typed value or another command's words reach); a command with
 * no action is the plain mode's alone, or the screen's when a key does it (keys.c). */
struct command {
    const char *name; /* the word typed (NULL: no command) */
    const char *args; /* its arguments, for help ("" for none; "[X]" optional) */
    const char *help; /* what it does */
    enum command_reply (*run)(struct command_call *c); /* reads its words, answers */
    void (*more)(char *buf, size_t len); /* what help says after the help line, or NULL */
    enum action action; /* the key table's action that does it, or ACT_NONE */
    /* The app's function for the action: a verb with rules of its own (fn); or an app
     * action taken as it is, its result by verb_result: with the verb's argument (with),
     * with none (act), or with a way to go (go: way, or the argument's when way is 0). */
    verb_fn fn;
    unsigned (*with)(struct app *app, const struct verb_arg *arg);
    unsigned (*act)(struct app *app);
    unsigned (*go)(struct app *app, int way);
    int way;
    unsigned flags;   /* COMMAND_* */
};

/* What a command's function is given: the words after its name (blanks trimmed; its
 * own to cut up), where its answer goes, and where a run's seconds or a view's number
 * goes. */
struct command_call {
    struct app *app;
    char *rest;
    char *answer;
    size_t len;
    double *value;
};

/* The rows, command_rows of them. */
extern const struct command commands[];
extern const int command_rows;

/* The row of the command named by the n bytes at name, or NULL. */
const struct command *command_find(const char *name, size_t n);

/* The row whose action is a, or NULL. */
const struct command *command_of_action(enum action a);

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


/* help [COMMAND]: the commands, or what one does (the help row's function). */
enum command_reply command_help(struct command_call *c);

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
