/* command.h: what the user can ask for, without a terminal in sight: the actions the
 * key table (tui/input.c) binds keys to, and the plain mode's commands (plain/), each
 * named after one of those actions, with their help. `help` in the plain mode, its
 * man page section and its README table come from this one table. */
#ifndef SPRINGSIM_COMMAND_H
#define SPRINGSIM_COMMAND_H

#include <stdbool.h>
#include <stddef.h>

struct app;

enum action {
    ACT_NONE,
    ACT_RUN,       /* start / pause */
    ACT_STEP,      /* one step forward */
    ACT_BACK,      /* one step back */
    ACT_RESET,     /* back to the initial conditions */
    ACT_RANDOM,    /* random initial positions */
    ACT_PRESETS,   /* preset menu */
    ACT_HELP,      /* help overlay */
    ACT_QUIT,      /* quit */
    ACT_UP,        /* previous control / mass */
    ACT_DOWN,      /* next control / mass */
    ACT_LEFT,      /* decrease, fine */
    ACT_RIGHT,     /* increase, fine */
    ACT_LEFT_BIG,  /* decrease, coarse */
    ACT_RIGHT_BIG, /* increase, coarse */
    ACT_ENTER,     /* type a value / apply / open */
    ACT_FOCUS,     /* switch between the controls and the chain */
    ACT_SLOWER,    /* playback speed down */
    ACT_FASTER,    /* playback speed up */
    ACT_ESCAPE,    /* close / cancel */
    ACT_REDRAW,    /* repaint the whole screen */
    ACT_MODES,     /* modes view */
    ACT_RESPONSE,  /* frequency response view */
    ACT_ENERGY,    /* energy view */
    ACT_SPECTRUM,  /* spectrum view */
    ACT_NEAREST,   /* drive at the nearest natural frequency */
    ACT_SWEEP,     /* start / stop the sine-sweep experiment */
    ACT_SAVE,      /* save the set-up as a preset */
    ACT_EXPORT,    /* export the recorded samples as CSV */
    ACT_FIGURE,    /* save the view as SVG and PNG */
    ACT_DAMPING,   /* chain: the selected mass's own damping */
    ACT_ENLARGE,   /* enlarge the plot of the digit pressed (again: the grid) */
    ACT_GRID,      /* all plots again */
    ACT_NARROWER,  /* shorter time window */
    ACT_WIDER,     /* longer time window */
    ACT_GHOST,     /* ghost on / off */
    ACT_CURSOR,    /* time cursors: one, two, none */
    ACT_CURSOR_STEP,  /* the cursor one sample earlier or later (by the key) */
    ACT_CURSOR_JUMP,  /* a tenth of the window earlier or later */
    ACT_CURSOR_PAGE,  /* the window a window earlier or later (paused) */
    ACT_CURSOR_MASS,  /* measure the mass before or after */
    ACT_CURSOR_OFF,         /* no cursors */
    ACT_LESSONS,   /* lesson menu */
    ACT_HIDE,      /* show / hide the selected mass's curves in the plots */
};

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

struct command {
    const char *name;   /* the word typed */
    enum action action; /* the key table's action it stands for (ACT_NONE: no key) */
    const char *args;   /* its arguments, for help ("" for none) */
    const char *help;   /* what it does */
    bool says_play;     /* its answer says whether the chain runs now (start, pause, step,
                         * run, mode): a start or a pause it made is no event of its own */
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
