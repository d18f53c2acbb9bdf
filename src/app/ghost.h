/* ghost.h: the ghost (key g): a copy of the chain frozen at an instant, its parameters,
 * settings (dt, integrator, initial conditions) and state, that then runs in lockstep
 * with the live chain and keeps its parameters while the user changes the live chain's,
 * so a change can be watched making the two part.
 *
 * Time: the ghost keeps its own dt and integrator. After each live step it takes as many
 * of its own steps as bring its time nearest the live chain's (within half its dt): while
 * the two dt are the same, one step each, to the same instants, and the two are equal bit
 * for bit until something is changed. It keeps its state before each live step, so
 * stepping back takes both back one live step; stepping back past the instant it was made
 * drops it. A reset (r, R, a mass moved) takes it to t = 0 at its own initial conditions.
 * A new chain (a preset, a new N) drops it, and so does a blow-up of its own, the live
 * chain going on. It is made and dropped whole: nothing is allocated while it runs. */
#ifndef SPRINGSIM_GHOST_H
#define SPRINGSIM_GHOST_H

#include <stddef.h>

#include "app.h"

struct ghost {
    struct config cfg;      /* its settings: dt, integrator, initial conditions */
    const struct model *model; /* its parameters, as they were when it was made: its
                                * sim's own (sim_model) */
    struct sim *sim;        /* its chain */
    struct history *hist;   /* its state before each live step since it was made */
    struct trail *trail;    /* fine samples for the plots, as the app's */
    struct trail *coarse;   /* coarse samples for the plots */
    int sample_every;       /* its steps between fine samples */
    int since_sample;       /* its steps since the last fine sample */
    int coarse_every;       /* its steps between coarse samples */
    int since_coarse;       /* its steps since the last coarse sample */
    bool unstable;          /* its dt is beyond its stability limit: a cap is a blow-up */
};

/* Makes a ghost of the chain as it is now, or drops the one there is (key g). */
unsigned app_toggle_ghost(struct app *app);

/* Drops the ghost, if there is one, saying "ghost dropped " why (NULL: silently). */
unsigned ghost_drop(struct app *app, const char *why);

/* After a live step: the ghost keeps its state for stepping back and follows the live
 * time; a blow-up of its own drops it with a message. */
unsigned ghost_follow(struct app *app);

/* After a live step back: the ghost goes back too, or is dropped if it was made since. */
unsigned ghost_back(struct app *app);

/* After a live reset: the ghost at t = 0 at its own initial conditions, samples and
 * history cleared. */
void ghost_restart(struct app *app);

/* "ghost" and what of its set-up differs from the live chain's ("ghost c 0.1 rk4"), for
 * the status line. */
void ghost_describe(const struct app *app, char *buf, size_t len);

#endif
