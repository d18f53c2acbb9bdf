/* change.h: the one path by which the app's parameters change, kept in app.c for the
 * app's other files (controls.c, files.c); not part of the front end's interface. */
#ifndef SPRINGSIM_CHANGE_H
#define SPRINGSIM_CHANGE_H

#include "app.h"

/* How a change comes about: bits for app_change. */
enum change_how {
    CHANGE_BY_SWEEP = 1u << 0,       /* the sweep's own retune: the sweep goes on */
    CHANGE_SETS_FREQUENCY = 1u << 1, /* next's frequency is the user's new choice */
    CHANGE_REBUILD = 1u << 2,        /* a new chain from next even if nothing differs
                                      * (a preset): at t = 0, paused */
};

/* Puts the settings next in force, keeping the rules (app.h). A change of N rebuilds
 * the chain whatever how says. why names the change for the message when it ends a
 * sweep ("the preset"); NULL when the user stopped the sweep. next may be written (the
 * user's frequency put back). Returns 0 with what changed in *changed (0 when nothing
 * differs); or -1 when next is refused (out of the interactive ranges, lists of the
 * wrong length, no memory), with the reason in the message, *changed 0 and nothing else
 * changed. */
int app_change(struct app *app, struct config *next, unsigned how, const char *why,
               unsigned *changed);

/* Ends a running sweep, giving the drive the user's frequency back (why as app_change). */
unsigned app_end_sweep(struct app *app, const char *why);

/* Drives at frequency f from now on, phase continuous: the sweep's own retune. */
unsigned app_retune(struct app *app, double f);

#endif
