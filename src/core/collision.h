/* collision.h: contacts with the left wall, the piston or right wall, and between
 * neighbouring masses, plus the velocity cap (SPEC section 1). */
#ifndef SPRINGSIM_COLLISION_H
#define SPRINGSIM_COLLISION_H

#include "model.h"

/* Resolves every contact of displacements x and velocities v in place, with the right
 * end at u moving at du. Returns the number of contacts resolved (0 if none, or if
 * the model has collisions off). */
int collision_apply(const struct model *m, double *x, double *v, double u, double du);

/* Whether collision_apply or collision_cap would change anything: a read-only pass, so
 * the common step with no contact pays for nothing else. */
int collision_needed(const struct model *m, const double *x, const double *v, double u);

/* Clamps every |v_i| to MODEL_VMAX; returns how many were clamped. */
int collision_cap(int n, double *v);

#endif
