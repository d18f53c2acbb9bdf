/* teach.h: a lesson played in the interactive program, and a recording replayed as a
 * demo (--replay). Its items are done one by one, each command through command_do; a
 * `run` plays in real time at the playback speed (the chain moves, the plots scroll)
 * and a `wait` waits on the wall clock. The caption panel below the plots and the
 * controls shows the step's text wrapped in screen columns (↓/↑ scroll it when it does
 * not fit) and the keys that work now. A lesson: space finishes a playing run at once
 * (the same steps, the same state) or goes on, ',' goes back a step, a digit answers a
 * question. A demo: space pauses and plays on, '.' skips to the next command. Esc
 * leaves either with the chain as it is. */
#ifndef SPRINGSIM_TEACH_H
#define SPRINGSIM_TEACH_H

#include <stdbool.h>

#include "../app/app.h"
#include "../chart/layout.h"
#include "../lab/lesson.h"
#include "graphics.h"

struct teach {
    struct lesson own;           /* a lesson chosen from the menu (L), read here */
    const struct lesson *lesson; /* the lesson playing, or NULL */
    struct lesson_play play;     /* where it is */
    bool done;                   /* its end reached: the panel stays until space or Esc */
    bool demo;                   /* a recording replayed: its keys are a player's */
    bool playing;                /* a run plays: the chain runs on to run_end */
    double run_end;              /* that run's end, simulated seconds */
    double wait_end;             /* a wait's end on the wall clock (app_clock_now), or 0 */
    bool held;                   /* a demo paused (space) */
    double held_at;              /* since when, wall clock */
    bool fit;                    /* a run began: the plots fit it anew (the caller clears) */
    int scroll;                  /* the caption's first line shown */
    int view;                    /* a view a `view` command asked for (enum command_view), or
                                  * -1: the caller shows it and sets -1 */
    char note[160];              /* the answer to the question, shown below it */
    struct graphics *gfx;        /* the terminal's answers (set by the caller): what is
                                  * typed while computing is read through its scanner */
};

/* Starts playing l (checked already) on app to its first pause, question, run or wait;
 * demo: as a recording replayed. */
void teach_start(struct teach *t, const struct lesson *l, struct app *app, bool demo);

/* Reads, checks and starts the lesson at path (chosen from the menu); on a bad lesson the
 * app's message says why (FILE:LINE: what) and nothing changes. Esc, q or Ctrl+C leave
 * its check. */
void teach_open(struct teach *t, const char *path, struct app *app);

/* Whether the caption panel is up. */
bool teach_shown(const struct teach *t);

/* Once a frame, at wall time now: a run that reached its end (or was stopped by a
 * blow-up) or a wait that is over lets the lesson go on. True when items were done. */
bool teach_tick(struct teach *t, struct app *app, double now);

/* One step of a playing run, for the clock (app_clock_follow): false, taking none, at
 * the run's end. */
bool teach_step(struct teach *t, struct app *app);

/* Takes key ch if the lesson wants it (see above; ↓/↑ when the caption is cut, in the
 * panel laid out in l); false for any other key, which does what it always does. */
bool teach_key(struct teach *t, struct app *app, const struct layout *l, int ch);

/* What space, '.' and ',' do now, in the hints' words (NULL: what they always do); at a
 * question, the digits' answer takes space's place (*space_key "1-3"). */
void teach_keys(const struct teach *t, const char **space_key, const char **space,
                const char **dot, const char **comma);

/* Draws the caption panel in l->caption. */
void teach_draw(const struct teach *t, const struct layout *l);

/* Frees a lesson read from the menu. */
void teach_free(struct teach *t);

#endif
