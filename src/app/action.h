/* action.h: what the user can do, by name: the keys' table maps keys to these, the table
 * of user verbs (command.c: the row naming the action) and the screen's (tui/keys.c) map
 * them to the functions that do them, and the app's messages name them (app_key) as the
 * front end showing them calls them. */
#ifndef SPRINGSIM_ACTION_H
#define SPRINGSIM_ACTION_H

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

#endif
