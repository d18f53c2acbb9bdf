/* input.h: the one table that maps keys to actions. The help overlay, `--keys` and
 * the man page's key list all come from it (a test checks the man page). */
#ifndef SPRINGSIM_INPUT_H
#define SPRINGSIM_INPUT_H

#include <stdio.h>

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
    ACT_DAMPING,   /* chain: the selected mass's own damping */
    ACT_ENLARGE,   /* enlarge the plot of the digit pressed (again: the grid) */
    ACT_GRID,      /* all plots again */
    ACT_NARROWER,  /* shorter time window */
    ACT_WIDER,     /* longer time window */
    ACT_GHOST,     /* ghost on / off */
};

struct binding {
    int key;          /* curses key code or character */
    enum action action;
    const char *name; /* the key as shown, UTF-8 */
    const char *ascii; /* the key as shown without UTF-8 */
    const char *help; /* what it does; NULL for a second key of the same action */
};

/* The bindings, ending with {0, ACT_NONE, ...}. */
extern const struct binding input_bindings[];

/* The action of a key, or ACT_NONE. */
enum action input_action(int key);

/* Prints the key table, one "KEY<TAB>WHAT" line per action (for --keys). */
void input_print_keys(FILE *out);

#endif
