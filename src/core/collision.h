/* collision.h: contacts with the left wall, the piston or right wall, and between
 * neighbouring masses, plus the velocity cap. The limits are computed
 * once per model and shared by the checks, the event location in sim_step.c and the
 * resolution; every change of energy a contact makes is booked. */
#ifndef SPRINGSIM_COLLISION_H
#define SPRINGSIM_COLLISION_H

#include <stdbool.h>

#include "model.h"

/* Relative speeds below this (m/s) make a contact resting: no bounce, the pair (or the
 * mass and the wall) stays together, so a mass held against a wall does not bounce
 * endlessly in ever smaller hops. */
#define COLLISION_V_REST 1e-3

/* Where the constraints are. Constraint 0 is mass 1 and the left wall, constraint k
 * (1 <= k < N) masses k and k+1, constraint N the last mass and the piston or right wall
 * (absent for a free end). A gap is >= 0 when the constraint holds. */
struct collision_limits {
    int n;          /* masses */
    int count;      /* constraints: N + 1, or N for a free end */
    bool on;        /* collisions on */
    double w;       /* block width */
    double spacing; /* equilibrium spacing L/(N+1) */
    double wall;    /* spacing - w/2: the wall's gap is this + x_1 */
    double pair;    /* spacing - w: a pair's gap is this + x_k+1 - x_k */
    double face;    /* L - w/2 - N spacing: the piston's gap is this + u - x_N */
};

/* What contacts did to the energy: lost (restitution, the cap, resting contacts) and
 * the work the piston did through contacts (part of the motor's work). */
struct collision_books {
    double lost;
    double piston;
};

/* The limits of model m. */
void collision_limits(struct collision_limits *l, const struct model *m);

/* Gap of constraint k (m) at displacements x with the right end at u. */
double collision_gap(const struct collision_limits *l, int k, const double *x, double u);

/* Rate of change of that gap (m/s) at velocities v with the right end moving at du:
 * negative when closing. */
double collision_rate(const struct collision_limits *l, int k, const double *v, double du);

/* A contact on constraint k at this instant: if it is closing, the restitution rule (e = 0.8,
 * momentum kept between masses, relative to the piston for the piston), or no bounce at
 * all below COLLISION_V_REST. Positions are not moved. Returns 1 if velocities changed. */
int collision_hit(const struct collision_limits *l, const struct model *m, int k, double *v,
                  double du, struct collision_books *b);

/* Resolves every contact left at the end of a step: positions put back on their limits
 * and closing pairs given the contact rule, sweep after sweep; a pile-up the sweeps do
 * not clear is put apart in one pass and each cluster left touching moves as one, so no
 * contact is left closing and momentum is kept. Returns the contacts resolved. */
int collision_settle(const struct collision_limits *l, const struct model *m, double *x,
                     double *v, double u, double du, struct collision_books *b);

/* At an instant of contact, after a few sweeps of collision_hit: each run of touching
 * masses with a contact still closing moves as one (momentum kept, walls and piston
 * holding it), the energy booked. Returns 1 if velocities changed. */
int collision_merge(const struct collision_limits *l, const struct model *m, const double *x,
                    double *v, double u, double du, struct collision_books *b);

/* collision_settle with limits made on the spot and the books thrown away. */
int collision_apply(const struct model *m, double *x, double *v, double u, double du);

/* Whether any constraint is violated by more than rounding, or a velocity is over the
 * cap: a read-only pass, so the common step with no contact pays for nothing else. */
int collision_needed(const struct collision_limits *l, const double *x, const double *v,
                     double u);

/* Clamps every |v_i| to MODEL_VMAX, the energy taken booked as lost; returns how many
 * were clamped. */
int collision_cap(const struct model *m, double *v, struct collision_books *b);

#endif
