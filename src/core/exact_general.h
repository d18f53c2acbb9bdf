/* exact_general.h: exact.c's propagator for the chains its other two cannot take: spring
 * dampers (a damping matrix that is not diagonal), a force input on a mass, springs of
 * k = 0 (rigid-body modes, where the factor exact.c's coordinates need does not exist).
 * The dense matrix exponential of the chain's first-order system in its own coordinates,
 * the drive's two states beside it, and the three energy books (dampers, motor, force) as
 * quadratic forms integrated along the step. Internal to exact.c. */
#ifndef SPRINGSIM_EXACT_GENERAL_H
#define SPRINGSIM_EXACT_GENERAL_H

#include "exact.h"
#include "model.h"

struct general;

/* Workspace for chains of n masses (the matrices made when first stepped), or NULL on no
 * memory. */
struct general *general_new(int n);

/* Frees it. */
void general_free(struct general *g);

/* Makes dst (same n) step as src does, its cached steps included. 0, or -1 on no memory
 * (dst then steps afresh). */
int general_copy(struct general *dst, const struct general *src);

/* Advances x, v (n each) of model m from a to b > a on drive d (NULL: none), adding the
 * piece's dissipation (ground and spring dampers), the motor's work and the force's work
 * to *diss, *work and *fwork. 0, or -1 (a parameter out of range, no memory, an
 * exponential failed or a result not finite: nothing is changed). */
int general_advance(struct general *g, const struct model *m, const struct exact_drive *d,
                    double a, double b, double *x, double *v, double *diss, double *work,
                    double *fwork);

#endif
