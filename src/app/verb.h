/* verb.h: what the user can do, each verb bound to the one function that does it to the
 * app (htop's Action.c). The key table (tui/input.c) maps keys to these actions and the
 * terminal program hands every action that is not screen-only (overlays, focus, the
 * arrows in the panels, views) to verb_do; the plain mode's commands (command.c) are
 * rows naming one of these actions, and turn their arguments into a verb_arg for the
 * same call. What a verb came to is an enum beside the app's message (tmux's
 * cmd_retval), set where the message is made: nothing is decided on its words. */
#ifndef SPRINGSIM_VERB_H
#define SPRINGSIM_VERB_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

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
    ACT_CURSOR_OFF,   /* no cursors */
    ACT_LESSONS,   /* lesson menu */
    ACT_HIDE,      /* show / hide the selected mass's curves in the plots */
    ACT_CUBIC_KEY, /* chain: the selected spring's own cubic constant k3 */
    /* Verbs with no key of their own: the screen reaches them from a menu, a typed value
     * or the selection (Enter), the plain mode by their commands. */
    ACT_MODE,      /* start the chain in a mode */
    ACT_APPLY,     /* apply the Masses control's pending value */
    ACT_SET,       /* a control from typed text */
    ACT_ELEMENT,   /* one mass's mass or damping, or one spring, from typed text */
    ACT_PLACE,     /* one mass's start displaced */
    ACT_PRESET,    /* load a preset file */
    ACT_WINDOW,    /* the time plots' window from typed text */
    ACT_CUBIC,     /* the springs' cubic constants (index < 0), or one spring's */
    ACT_SPRING_DAMPING, /* the dampers beside the springs (index < 0), or one spring's */
    ACT_COUNT
};

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

/* Whether a is a verb of the table (and not screen-only). */
bool verb_bound(enum action a);

/* Does verb a to app with arg (NULL: none), the message cleared first; what changed
 * (enum app_change) into *changed if not NULL. */
enum result verb_do(struct app *app, enum action a, const struct verb_arg *arg,
                    unsigned *changed);

/* The plain command that does what verb a did (its arg, what it changed, whether the
 * chain runs now) again, for --record: "start", "mode 2"; "" when there is none (a
 * pause, a step that did nothing, a verb with no command). */
void verb_command(enum action a, const struct verb_arg *arg, unsigned changed, bool running,
                  char *out, size_t len);

#endif
