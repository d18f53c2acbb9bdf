/* rest.h: resting contacts. A constraint that closed slower
 * than COLLISION_V_REST while the forces press it shut holds as a constraint: the two
 * masses move as one, a mass on the wall stays there, a mass on the piston moves with
 * it, for as long as the constraint force pushes (it never pulls). The masses joined by
 * resting constraints form clusters; each cluster is one rigid body: free, held by the
 * wall (at rest) or carried by the piston. */
#ifndef SPRINGSIM_REST_H
#define SPRINGSIM_REST_H

#include <stdbool.h>

#include "collision.h"
#include "model.h"

/* Below this (N) a constraint force counts as zero: a pull weaker than this does not
 * part a resting contact (the forces of the chain are rounded to about 1e-15 N). */
#define REST_PULL 1e-9

struct rest {
    int n;      /* masses */
    int count;  /* constraints, as in struct collision_limits */
    int active; /* how many hold now: 0 is the common case and costs nothing */
    bool enabled; /* contacts may come to rest (sim.c turns it on for every chain) */
    double v_rest; /* a contact closing slower than this (m/s) is inelastic and may rest */
    bool *on;   /* count flags: constraint k rests */
    bool *soft; /* count flags: constraint k was just hit slower than COLLISION_V_REST */
    double *acc; /* n: scratch for the chain's own accelerations */
    double *pool; /* 3 (n + 2): scratch for an impact's pooled limit (events.c) */
    int clusters;      /* clusters of two or more masses, or held by the wall or piston */
    int *first, *last; /* each one's masses */
    signed char *held; /* -1 the wall holds it, 1 the piston, 0 nothing */
};

/* Makes constraint k rest (on) or not, the clusters made anew. */
void rest_set(struct rest *r, int k, bool on);

/* A set of n masses' constraints, all open; NULL on no memory. */
struct rest *rest_new(int n);

/* Frees it. */
void rest_free(struct rest *r);

/* Opens every constraint; the set then matches limits l (count may differ by the end). */
void rest_clear(struct rest *r, const struct collision_limits *l);

/* Makes dst (same n) hold what src holds. */
void rest_copy(struct rest *dst, const struct rest *src);

/* The accelerations a (from model_rates: the chain's forces over each mass, no contact
 * force) made the constrained ones: a free cluster's is its net force over its mass, a
 * wall's cluster's 0, the piston's ddu (the end's acceleration). Returns the force the
 * piston pushes its cluster with (N, towards the left; 0 when it holds none). */
double rest_project(const struct rest *r, const struct model *m, double *a, double ddu);

/* The contact force of every resting constraint, at state x, v with the end at u, du,
 * ddu and the force input at fin (N, on mass force_on): force[k] >= 0 pushes, < 0 would
 * pull (force has count values; only the resting ones are written). Returns the index of
 * the weakest, or -1 when none rests. */
int rest_forces(const struct rest *r, const struct model *m, const double *x, const double *v,
                double u, double du, double ddu, double fin, double *force);

/* Puts each cluster exactly on its constraints: a wall's cluster at its limits and at
 * rest, the piston's on its face moving at du, a free one about its centre of mass with
 * one velocity (its momentum kept). */
void rest_snap(const struct rest *r, const struct collision_limits *l, const struct model *m,
               double *x, double *v, double u, double du);

/* The masses [first, last] of the cluster mass i belongs to, and what holds it: -1 the
 * wall, 1 the piston, 0 nothing (both: the wall). */
int rest_cluster(const struct rest *r, int n, int i, int *first, int *last);

#endif
