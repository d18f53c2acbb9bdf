/* scope.h: the time plots as an oscilloscope: up to two time cursors on the recorded
 * samples, the window scrolled back through what is recorded while paused, and the
 * automatic measurements of one mass over the window. What the readout says comes from
 * the recorded samples themselves (the fine ones are what `x` exports), never from an
 * interpolation. No curses here. */
#ifndef SPRINGSIM_SCOPE_H
#define SPRINGSIM_SCOPE_H

#include <stdbool.h>
#include <stddef.h>

#include "measure.h"
#include "../chart/trail.h"

struct app;

/* The cursors and the scroll-back: part of struct app. */
struct scope {
    int cursors;  /* cursors shown: 0, 1 or 2 */
    int active;   /* the one the keys move (the last one added) */
    double at[2]; /* each cursor's distance before the window's right edge (s, >= 0): a
                   * cursor keeps its place on the plot while the chain runs */
    double back;  /* the window's right edge, this far before now (s; 0 live, paused only) */
    int mass;     /* the mass measured (0-based) */
};

/* What the time plots show now. */
struct scope_view {
    const struct trail *trail; /* the samples: the fine ones where they cover the window */
    double end, start;         /* the window's right and left edges (s) */
    double window;             /* end - start (s) */
    const double *rec;         /* the first record at or after start */
    int count;                 /* records from rec up to end, inclusive */
    bool live;                 /* end is now */
};

/* The view of app's time plots: the window ending scope.back before now. */
void scope_view(const struct app *app, struct scope_view *v);

/* The record cursor k (0 or 1) sits on in view v, or NULL (no such cursor, no samples). */
const double *scope_record(const struct app *app, const struct scope_view *v, int k);

/* `|`: one cursor (at the window's right edge), two (the second where the first is),
 * none. mass is the mass to measure (the one selected, or -1 to keep the last). */
unsigned scope_toggle(struct app *app, int mass);

/* Removes the cursors; 0 if there were none. */
unsigned scope_clear(struct app *app);

/* Moves the active cursor n samples (negative: earlier). Past the window's edge, paused,
 * the window follows it through the recorded samples; running, it stops at the edge. */
unsigned scope_move(struct app *app, int n);

/* Moves the active cursor by a tenth of the window, dir -1 or +1. */
unsigned scope_jump(struct app *app, int dir);

/* Paused: the window a whole window earlier (dir -1) or later (+1), within what is
 * recorded; running, a message. */
unsigned scope_page(struct app *app, int dir);

/* The mass measured: dir -1 the one before, +1 the one after. */
unsigned scope_select(struct app *app, int dir);

/* The mass measured, held to the chain's masses. */
int scope_mass(const struct app *app);

/* Measures mass i's displacement over view v. */
void scope_measure(const struct scope_view *v, int i, struct measure *m);

/* What the measurements of one mass over a view say, beside the theory's. */
struct scope_motion {
    struct measure m;        /* its peaks, period, decrement */
    struct measure_drive d;  /* against the drive: the motor's, else the force (driven) */
    bool driven;             /* the motor (a motor end, amplitude != 0) or a force drives */
    bool by_force;           /* driven by the force alone: d, ratio and phase are to it */
    bool linearised;         /* the theory is the chain's linearised at rest (cubic springs) */
    double hz;               /* the drive's frequency (Hz; driven only) */
    enum motion kind;        /* measure_motion's */
    int mode;                /* the mode nearest to the measured frequency (0-based), or -1 */
    double theory_zeta;      /* that mode's damping ratio (NAN unknown) */
    double theory_ratio;     /* the steady state's amplitude over the motor's amplitude
                              * (m/m), or over the force's (m/N) by_force, at hz */
    double theory_phase;     /* and its phase to the drive (degrees; NAN unknown) */
};

/* Measures mass i's displacement over view v and says what kind of motion it is, with
 * the theory's damping ratio of the nearest mode and, driven, the linear steady state's
 * ratio and phase at the drive's frequency (modes_response_phase). */
void scope_motion(const struct app *app, const struct scope_view *v, int i,
                  struct scope_motion *out);

/* The mode whose damped frequency (its undamped one where that is unknown) is nearest
 * to hz, or -1 when the modes are not known or hz is not a number. */
int scope_nearest_mode(const struct app *app, double hz);

/* The recorded record nearest to time t (s): a fine one where the fine samples reach,
 * else a coarse one; NULL when t is more than half a sample outside what is recorded.
 * *trail gets the trail it is from. */
const double *scope_at_time(const struct app *app, double t, const struct trail **trail);

/* The earliest recorded time (s). */
double scope_oldest(const struct app *app);

#endif
