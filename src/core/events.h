/* events.h: contacts as events inside a step: where
 * along a piece a gap closes (grazes included) or a resting contact would start to pull,
 * and what happens at that instant (the contact rule on whole clusters, resting contacts
 * made and parted). sim_step.c steps to the instants these find. */
#ifndef SPRINGSIM_EVENTS_H
#define SPRINGSIM_EVENTS_H

#include "collision.h"
#include "model.h"
#include "rest.h"
#include "stepper.h"

/* Gaps within this of zero (m) touch: the rounding of x_eq + d. */
#define EVENTS_TOUCH 1e-12

/* One piece [a, a + h] of a step from state ya to y (x, v of n masses each), on drive d. */
struct events_piece {
    const struct collision_limits *lim;
    const struct model *m;
    const struct rest *rest;
    const struct drive *d;
    const double *ya, *y;
    double a, h;
    double ua, dua, ub, dub; /* the drive at both ends */
    double ddu_factor;       /* u'' = ddu_factor u on this piece (a sine's -w^2, else 0) */
    double drive_err;        /* how far u strays from its cubic Hermite on the piece (m) */
};

/* The first theta in [0, 1] at which an open constraint's gap closes along the piece's
 * cubic Hermite interpolant, dipping below EVENTS_TOUCH (a graze shorter than the piece
 * included), that constraint in *which, and in *closing how many close in the piece;
 * -1 when all stay open. */
double events_contact(const struct events_piece *p, int *which, int *closing);

/* Whether some gap may close inside the piece by the bound alone (events_contact's first
 * test): false means every gap stays open to its end. */
bool events_may_close(const struct events_piece *p);

/* The first theta in (0, 1] at which a resting contact's force turns to a pull, along the
 * interpolant, and that constraint in *which; -1 when none does. work: 2n doubles,
 * force: count doubles of scratch. */
double events_release(const struct events_piece *p, double *work, double *force, int *which);

/* At an instant of contact on constraint k: the contact rule between the two masses it
 * joins (or a mass and the wall or the piston), then on every touching contact of the row
 * around it still closing, pair by pair, sweeps alternating left to right and back, and
 * a row still closing after that as one. Resting contacts in the row take the same rule
 * as merely touching ones (the impact's impulse is infinite beside their finite force).
 * Books the energy. Returns the contacts. */
int events_hit(const struct collision_limits *l, const struct model *m, struct rest *r, int k,
               const double *x, double *v, double u, double du, struct collision_books *b);

/* After an instant of contact or a release: a contact just hit slower than
 * COLLISION_V_REST (so no longer moving apart) rests while its force pushes; resting ones
 * moving apart or pulling part; the clusters are put exactly on their constraints. u, du,
 * ddu: the end then; f: the force input then. force: count doubles of scratch. */
void events_settle_rest(const struct collision_limits *l, const struct model *m, struct rest *r,
                        double *x, double *v, double u, double du, double ddu, double f,
                        double *force);

#endif
