/* watch.h: what the plain mode reports as it happens, found by looking at the app after
 * each step and each command: contacts, new peaks of a mass, the drive arriving on a
 * natural frequency. No terminal, no output: each event is handed to a callback as one
 * line of text.
 *
 * - A contact: a step in which the chain's contacts acted (sim_last_contacts beyond the
 *   velocity cap's), named by the constraint nearest to touching at its end, reported
 *   only when that constraint was not already in contact at the step before, so a mass
 *   resting against a wall or a neighbour is one contact, not one a step. At most
 *   WATCH_CONTACT_BURST are told one by one in a second of simulated time; the rest of
 *   that second are counted and told in one line when it is over ("contact: 12 more from
 *   t = 5.00 to 6.00 s"), so a chain of ten rattling masses does not flood a reader.
 * - A peak: at a turning point of mass i (its velocity changes sign between two steps;
 *   the larger |x_i| of the two) of at least WATCH_PEAK_MIN, either the largest since
 *   t = 0 (WATCH_PEAK_RISE above the largest |x_i| so far, the start's included; the
 *   first swing back to the start's |x_i| counts as it, within WATCH_PEAK_SAME), or, with
 *   no drive, WATCH_PEAK_RISE below or above the last peak told (the start before any):
 *   a free decay tells its falling peaks. At most one per half swing of that mass, and
 *   one per 5 % of growth or fall.
 * - Resonance: the drive (a motor with an amplitude) within WATCH_ON_MODE of a natural
 *   frequency, as the modes view marks it, reported when it comes onto one (a change of
 *   frequency, a retune of the sweep, or a change of the chain). */
#ifndef SPRINGSIM_WATCH_H
#define SPRINGSIM_WATCH_H

#include <stdbool.h>

#include "app.h"

#define WATCH_PEAK_RISE 0.05 /* a peak reported is this far above the last (relative) */
#define WATCH_PEAK_MIN 1e-3  /* smaller swings make no peaks (m) */
#define WATCH_PEAK_SAME 1e-3 /* a first swing this close below the start's |x| is its equal */
#define WATCH_ON_MODE 0.02   /* the drive is on a natural frequency within this (relative) */
#define WATCH_CONTACT_BURST 3 /* contacts told one by one in a second of simulated time */

struct watch {
    int n;                              /* masses when last looked at */
    double t;                           /* time when last looked at (s) */
    double x[APP_MAX_MASSES];           /* displacements then */
    double v[APP_MAX_MASSES];           /* velocities then */
    double peak[APP_MAX_MASSES];        /* the last peak reported of each mass (m, 0 none) */
    double largest[APP_MAX_MASSES];     /* the largest |x| of each since t = 0 (m) */
    bool touching[APP_MAX_MASSES + 1];  /* constraints in contact at the last step */
    int on_mode;                        /* the natural frequency the drive is on, or -1 */
    int burst;                          /* contacts told one by one a second (watch_init:
                                         * WATCH_CONTACT_BURST) */
    double second;                      /* the start of the second being counted (s) */
    int told;                           /* contacts told one by one in it */
    int held;                           /* contacts in it not told yet */
};

/* Receives one event, a line of text without a newline. */
typedef void watch_say(void *ctx, const char *event);

/* Starts watching app as it is now (nothing reported). */
void watch_init(struct watch *w, const struct app *app);

/* After one step app_step took: its contacts, the peaks it reached, a retune of the
 * sweep onto a natural frequency. */
void watch_step(struct watch *w, const struct app *app, watch_say *say, void *ctx);

/* After anything else (a command): a restart at t = 0 forgets the peaks, a jump of the
 * state is not taken for a turning point, and the drive coming onto a natural frequency
 * is reported. */
void watch_look(struct watch *w, const struct app *app, watch_say *say, void *ctx);

/* The natural frequency (0-based) the drive is on, within WATCH_ON_MODE, or -1. */
int watch_on_mode(const struct app *app);

#endif
