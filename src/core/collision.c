/* collision.c: contacts as the page describes them, made precise.
 *
 * Mass centres live at X_i = x_eq,i + d_i. Walls: X_i >= w/2 on the left, and for a
 * motor or wall end X_i <= L + u - w/2; on contact the centre is put on the limit and,
 * if it moved into the wall, the velocity relative to the wall is reversed and scaled
 * by e. Neighbours: X_{i+1} - X_i >= w; overlap is removed by moving both equally and,
 * if they approach, they take the 1-D restitution result
 *   v1' = (m1 v1 + m2 v2 + m2 e (v2 - v1)) / (m1 + m2),
 *   v2' = (m1 v1 + m2 v2 + m1 e (v1 - v2)) / (m1 + m2),
 * which keeps momentum and makes v2' - v1' = e (v1 - v2). */
#include "collision.h"

#include <math.h>

/* Separating one pair can push a mass into its other neighbour or a wall; a few
 * sweeps settle any real configuration (the chain's blocks fill at most half of L). */
#define MAX_SWEEPS 64
/* Contacts closer than this to their limit count as resolved (rounding of x_eq + d). */
#define SLACK 1e-12

static int pair_contact(const struct model *m, double *x, double *v, int i, double w,
                        double spacing)
{
    /* Centres differ by the equilibrium spacing plus the displacements'. */
    double gap = spacing + x[i + 1] - x[i];
    if (gap >= w - SLACK)
        return 0;
    double half = 0.5 * (w - gap);
    x[i] -= half;
    x[i + 1] += half;
    double v1 = v[i], v2 = v[i + 1];
    if (v1 > v2) {
        double m1 = m->m[i], m2 = m->m[i + 1];
        double p = m1 * v1 + m2 * v2, mt = m1 + m2;
        v[i] = (p + m2 * MODEL_RESTITUTION * (v2 - v1)) / mt;
        v[i + 1] = (p + m1 * MODEL_RESTITUTION * (v1 - v2)) / mt;
    }
    return 1;
}

static int left_wall(const struct model *m, double *x, double *v, double w)
{
    double lim = 0.5 * w - model_equilibrium(m, 0);
    if (x[0] >= lim - SLACK)
        return 0;
    x[0] = lim;
    if (v[0] < 0.0)
        v[0] = -MODEL_RESTITUTION * v[0];
    return 1;
}

static int right_wall(const struct model *m, double *x, double *v, double u, double du, double w)
{
    int i = m->n - 1;
    double lim = MODEL_LENGTH + u - 0.5 * w - model_equilibrium(m, i);
    if (x[i] <= lim + SLACK)
        return 0;
    x[i] = lim;
    double rel = v[i] - du;
    if (rel > 0.0)
        v[i] = du - MODEL_RESTITUTION * rel;
    return 1;
}

/* Last resort for a pile-up the sweeps did not clear (say every mass started at the
 * same place): push centres right until each clears its left neighbour, then left from
 * the right end. Positions only; it is never reached in ordinary motion. */
static void unpile(const struct model *m, double *x, double u, double w)
{
    int n = m->n;
    double lo = 0.5 * w;
    for (int i = 0; i < n; i++) {
        double c = model_equilibrium(m, i) + x[i];
        if (c < lo)
            x[i] = lo - model_equilibrium(m, i);
        lo = model_equilibrium(m, i) + x[i] + w;
    }
    if (m->boundary == BOUNDARY_FREE)
        return;
    double hi = MODEL_LENGTH + u - 0.5 * w;
    for (int i = n - 1; i >= 0; i--) {
        double c = model_equilibrium(m, i) + x[i];
        if (c > hi)
            x[i] = hi - model_equilibrium(m, i);
        hi = model_equilibrium(m, i) + x[i] - w;
    }
}

int collision_apply(const struct model *m, double *x, double *v, double u, double du)
{
    if (!m->collisions)
        return 0;
    double w = model_block_width(m);
    double spacing = MODEL_LENGTH / (m->n + 1);
    int total = 0, found = 0;
    for (int sweep = 0; sweep < MAX_SWEEPS; sweep++) {
        found = 0;
        for (int i = 0; i + 1 < m->n; i++)
            found += pair_contact(m, x, v, i, w, spacing);
        found += left_wall(m, x, v, w);
        if (m->boundary != BOUNDARY_FREE)
            found += right_wall(m, x, v, u, du, w);
        total += found;
        if (!found)
            break;
    }
    if (found)
        unpile(m, x, u, w);
    return total;
}

int collision_cap(int n, double *v)
{
    int capped = 0;
    for (int i = 0; i < n; i++) {
        if (v[i] > MODEL_VMAX) {
            v[i] = MODEL_VMAX;
            capped++;
        } else if (v[i] < -MODEL_VMAX) {
            v[i] = -MODEL_VMAX;
            capped++;
        }
    }
    return capped;
}

int collision_needed(const struct model *m, const double *x, const double *v, double u)
{
    int n = m->n;
    for (int i = 0; i < n; i++)
        if (fabs(v[i]) > MODEL_VMAX)
            return 1;
    if (!m->collisions)
        return 0;
    double w = model_block_width(m), spacing = MODEL_LENGTH / (n + 1);
    if (spacing + x[0] < 0.5 * w - SLACK)
        return 1;
    for (int i = 0; i + 1 < n; i++)
        if (spacing + x[i + 1] - x[i] < w - SLACK)
            return 1;
    return m->boundary != BOUNDARY_FREE &&
           n * spacing + x[n - 1] > MODEL_LENGTH + u - 0.5 * w + SLACK;
}
