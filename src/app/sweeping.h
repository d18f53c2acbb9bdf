/* sweeping.h: the app's sine sweep, worked out before it starts: the frequencies it
 * drives, how long each point must stay steady before it is measured, and the motor
 * amplitude above which the chain's steady swing at one of them makes contacts. */
#ifndef SPRINGSIM_SWEEPING_H
#define SPRINGSIM_SWEEPING_H

#include <stddef.h>

#include "app.h"

struct sweep_plan {
    double lo, hi;  /* the first and the last frequency (Hz) */
    double hold;    /* every swing level within 1 % this long before a point is measured:
                     * the slowest mode's decay time 1/(zeta w), at most
                     * SWEEPING_HOLD_MAX (s) */
    double most;    /* a point not steady after this long is measured anyway (s) */
    double contact; /* the least motor amplitude (m) at which the linear steady state at
                     * one of the points closes a gap; INFINITY when none does, or when
                     * a force drives too */
    double scale;   /* the least factor of the whole drive (motor and force) that does:
                     * at most 1, contacts are expected; INFINITY when none does */
};

/* What plan's contacts say in a few words (form 0 the longest, up to 3), empty when none
 * are expected at app's drive: "contacts expected above 0.12 m", "... above 2.5 N", "...
 * at this drive". */
void sweeping_contact_words(const struct app *app, const struct sweep_plan *plan, int form,
                            char *buf, size_t len);

#define SWEEPING_HOLD_MAX 30.0 /* s: a point's hold, whatever the damping */
#define SWEEPING_MOST 10.0     /* a point settles at most this many holds */

/* The plan of a sweep of app's chain as it stands: 0; or -1 when it cannot sweep, with
 * the reason in why (a sentence for the status line). */
int sweeping_plan(const struct app *app, struct sweep_plan *plan, char *why, size_t len);

#endif
