/* onestep.h: an integrator's own one-step matrix on the chain (the stepper's step on the
 * linear homogeneous system, right end held still), its spectral radius (LAPACK dgeev),
 * the largest stable step found along h, and the error of the steady motion at the
 * drive's frequency ("Every integrator's stability limit comes from its
 * own one-step matrix"). */
#ifndef SPRINGSIM_ONESTEP_H
#define SPRINGSIM_ONESTEP_H

#include <stdbool.h>

#include "integrator.h"
#include "model.h"

#define ONESTEP_MAX 20 /* masses up to which the matrices are taken: 2N x 2N dense */

struct onestep;

/* Workspace for model m's chain (1 <= N <= ONESTEP_MAX; the model is copied), or NULL on
 * no memory or a larger N. */
struct onestep *onestep_new(const struct model *m);

/* Frees it. */
void onestep_free(struct onestep *o);

/* The one-step matrix S of integrator i at step h, (x, v)_{n+1} = S (x, v)_n, built
 * column by column by the stepper itself (stepper.c): 2N x 2N, column-major, into s. */
void onestep_matrix(struct onestep *o, enum integrator i, double h, double *s);

/* S's spectral radius, or NAN when dgeev fails. */
double onestep_radius(struct onestep *o, enum integrator i, double h);

/* The largest h with radius <= 1 at every step from 0 up to it: a scan of h * scale
 * (scale a rate of the chain, 1/s, e.g. its fastest |lambda|) then bisection in the first
 * interval found unstable; INFINITY when none is up to 1e6 / scale. */
double onestep_stable_dt(struct onestep *o, enum integrator i, double scale);

/* The steady motion at the drive's frequency f (a sine of f; another waveform's
 * fundamental): the integrator's at step h, z_n = Re(Z_h e^{i w t_n}), against the exact
 * one, Z = (i w - A)^-1 F; the largest |Z_h - Z| over the masses' positions relative to
 * the largest |Z|. NAN when the step is unstable or a solve fails. */
double onestep_drive_error(struct onestep *o, enum integrator i, double h, double f);

/* The largest h from 0 for which good(ctx, h) holds at every h up to it, by the same scan
 * and bisection; INFINITY when nothing up to 1e6 / scale fails, or scale is not > 0. */
double onestep_search(bool (*good)(void *ctx, double h), void *ctx, double scale);

/* onestep_search's answer where it is below ceiling; INFINITY where it is not (found
 * without finishing the search: a least over many searches skips those that cannot
 * lower it). */
double onestep_search_below(bool (*good)(void *ctx, double h), void *ctx, double scale,
                            double ceiling);

/* onestep_drive_error at a step h already known stable (below onestep_stable_dt): the
 * same number without the spectral radius. */
double onestep_drive_error_stable(struct onestep *o, enum integrator i, double h, double f);

#endif
