/* collision.c: contacts as the page describes them, made precise.
 *
 * Mass centres live at X_i = x_eq,i + d_i. Walls: X_i >= w/2 on the left, and for a
 * motor or wall end X_i <= L + u - w/2; on contact the velocity relative to the wall is
 * reversed and scaled by e. Neighbours: X_{i+1} - X_i >= w; if they approach, they take
 * the 1-D restitution result
 *   v1' = (m1 v1 + m2 v2 + m2 e (v2 - v1)) / (m1 + m2),
 *   v2' = (m1 v1 + m2 v2 + m1 e (v1 - v2)) / (m1 + m2),
 * which keeps momentum, makes v2' - v1' = e (v1 - v2) and takes the energy
 * 1/2 mu (1 - e^2) (v1 - v2)^2, mu = m1 m2 / (m1 + m2). Below COLLISION_V_REST the
 * contact is resting: e = 0, the two move on together. */
#include "collision.h"

#include <math.h>

/* Sweeps of pairwise resolution at the end of a step: isolated contacts settle in one
 * or two; a pile-up that has not settled after these is resolved in one pass over the
 * whole chain (unpile), so a step costs O(N) whatever the pile-up. */
#define MAX_SWEEPS 3
/* Contacts closer than this to their limit count as touching (rounding of x_eq + d). */
#define SLACK 1e-12

void collision_limits(struct collision_limits *l, const struct model *m)
{
    l->n = m->n;
    l->count = m->n + (m->boundary != BOUNDARY_FREE);
    l->on = m->collisions;
    l->w = model_block_width(m);
    l->spacing = MODEL_LENGTH / (m->n + 1);
    l->wall = l->spacing - 0.5 * l->w;
    l->pair = l->spacing - l->w;
    l->face = MODEL_LENGTH - 0.5 * l->w - m->n * l->spacing;
}

double collision_gap(const struct collision_limits *l, int k, const double *x, double u)
{
    if (k == 0)
        return l->spacing + x[0] - 0.5 * l->w;
    if (k < l->n)
        return l->spacing + x[k] - x[k - 1] - l->w;
    return MODEL_LENGTH + u - 0.5 * l->w - (l->n * l->spacing + x[l->n - 1]);
}

double collision_rate(const struct collision_limits *l, int k, const double *v, double du)
{
    if (k == 0)
        return v[0];
    if (k < l->n)
        return v[k] - v[k - 1];
    return du - v[l->n - 1];
}

/* The coefficient of restitution for a contact closing at speed `closing` (> 0). */
static double restitution(double closing)
{
    return closing < COLLISION_V_REST ? 0.0 : MODEL_RESTITUTION;
}

int collision_hit(const struct collision_limits *l, const struct model *m, int k, double *v,
                  double du, struct collision_books *b)
{
    double closing = -collision_rate(l, k, v, du);
    if (closing <= 0.0)
        return 0;
    double e = restitution(closing);
    if (k == 0) {
        b->lost += 0.5 * m->m[0] * (1.0 - e * e) * v[0] * v[0];
        v[0] = -e * v[0];
    } else if (k < l->n) {
        double m1 = m->m[k - 1], m2 = m->m[k], mt = m1 + m2;
        double v1 = v[k - 1], v2 = v[k], p = m1 * v1 + m2 * v2;
        b->lost += 0.5 * m1 * m2 / mt * (1.0 - e * e) * closing * closing;
        v[k - 1] = (p + m2 * e * (v2 - v1)) / mt;
        v[k] = (p + m1 * e * (v1 - v2)) / mt;
    } else {
        /* The piston is a moving wall: relative to it the speed is reversed and scaled.
         * It does the work that changes the mass's kinetic energy plus what is lost. */
        int i = l->n - 1;
        double mi = m->m[i], before = v[i], loss = 0.5 * mi * (1.0 - e * e) * closing * closing;
        v[i] = du - e * closing;
        b->lost += loss;
        b->piston += 0.5 * mi * (v[i] * v[i] - before * before) + loss;
    }
    return 1;
}

/* Kinetic energy of the last mass and potential energy of its two springs: what a
 * piston contact changes. */
static double last_energy(const struct model *m, const double *x, const double *v, double u)
{
    int i = m->n - 1;
    double e = 0.5 * m->m[i] * v[i] * v[i];
    double left = i > 0 ? x[i] - x[i - 1] : x[i], right = u - x[i];
    return e + model_spring_energy(m, i, left) + model_spring_energy(m, i + 1, right);
}

/* Puts constraint k back on its limit (moving the masses, half each for a pair) and
 * applies the contact rule if it is closing; 1 if anything changed. */
static int resolve(const struct collision_limits *l, const struct model *m, int k, double *x,
                   double *v, double u, double du, struct collision_books *b)
{
    double gap = collision_gap(l, k, x, u);
    if (gap > SLACK || (gap >= -SLACK && collision_rate(l, k, v, du) >= 0.0))
        return 0;
    bool piston = k == l->n;
    double before = piston ? last_energy(m, x, v, u) : 0.0;
    double piston0 = b->piston, lost0 = b->lost;
    if (gap < 0.0) {
        if (k == 0)
            x[0] -= gap;
        else if (k < l->n)
            x[k - 1] += 0.5 * gap, x[k] -= 0.5 * gap;
        else
            x[l->n - 1] += gap;
    }
    collision_hit(l, m, k, v, du, b);
    /* The piston put the mass back and hit it: its work is all the change of the mass's
     * energy and its springs', plus what the hit lost. */
    if (piston)
        b->piston = piston0 + (last_energy(m, x, v, u) - before) + (b->lost - lost0);
    return 1;
}

/* Each run of touching masses that has a contact still closing moves as one: its
 * momentum kept, the walls taking what pushes into them (a perfectly inelastic
 * pile-up). The piston's part is an impulse M (du - vc) on a cluster it stops from
 * outrunning it, whose work, M (du - vc) du, is returned: the cluster's gain of energy
 * from it is that work less the loss 1/2 M (du - vc)^2 of a perfectly inelastic contact
 * in the piston's frame. */
static double merge_clusters(const struct collision_limits *l, const struct model *m,
                             const double *x, double *v, double u, double du)
{
    int n = l->n;
    double work = 0.0;
    for (int first = 0; first < n;) {
        int last = first;
        bool closing = false;
        while (last + 1 < n && collision_gap(l, last + 1, x, u) <= SLACK) {
            closing |= collision_rate(l, last + 1, v, du) < 0.0;
            last++;
        }
        bool left = first == 0 && collision_gap(l, 0, x, u) <= SLACK;
        bool right = last == n - 1 && l->count > n && collision_gap(l, n, x, u) <= SLACK;
        closing |= (left && v[0] < 0.0) || (right && v[n - 1] > du);
        if (closing) {
            double p = 0.0, mt = 0.0;
            for (int i = first; i <= last; i++)
                p += m->m[i] * v[i], mt += m->m[i];
            double vc = p / mt;
            if (left && vc < 0.0)
                vc = 0.0;
            if (right && vc > du) {
                work += mt * (du - vc) * du;
                vc = du;
            }
            for (int i = first; i <= last; i++)
                v[i] = vc;
        }
        first = last + 1;
    }
    return work;
}

int collision_merge(const struct collision_limits *l, const struct model *m, const double *x,
                    double *v, double u, double du, struct collision_books *b)
{
    double e0 = model_kinetic(m, v);
    double work = merge_clusters(l, m, x, v, u, du);
    double e1 = model_kinetic(m, v);
    b->piston += work;
    /* Never negative: rounding's 1e-13 J stays out of the contact book, which never
     * falls, and shows in the balance. */
    b->lost += fmax(0.0, e0 - e1 + work);
    return e1 != e0;
}

/* Last resort for a pile-up the sweeps did not clear (say every mass started at the
 * same place): centres pushed right until each clears its left neighbour, then left from
 * the right end; then each run of touching masses that is still closing moves as one.
 * Returns the work the piston did: pushing masses back (what that did to the springs) and
 * stopping clusters. */
static double unpile(const struct collision_limits *l, const struct model *m, double *x,
                     double *v, double u, double du)
{
    int n = l->n;
    double lo = 0.5 * l->w, work = 0.0;
    for (int i = 0; i < n; i++) {
        double c = (i + 1) * l->spacing + x[i];
        if (c < lo)
            x[i] = lo - (i + 1) * l->spacing;
        lo = (i + 1) * l->spacing + x[i] + l->w;
    }
    if (l->count > n) {
        double hi = MODEL_LENGTH + u - 0.5 * l->w, e0 = model_potential(m, x, u);
        bool moved = false;
        for (int i = n - 1; i >= 0; i--) {
            double c = (i + 1) * l->spacing + x[i];
            if (c > hi)
                x[i] = hi - (i + 1) * l->spacing, moved = true;
            hi = (i + 1) * l->spacing + x[i] - l->w;
        }
        if (moved)
            work += model_potential(m, x, u) - e0;
    }
    return work + merge_clusters(l, m, x, v, u, du);
}

int collision_settle(const struct collision_limits *l, const struct model *m, double *x,
                     double *v, double u, double du, struct collision_books *b)
{
    if (!l->on)
        return 0;
    double e0 = model_kinetic(m, v) + model_potential(m, x, u);
    double piston0 = b->piston, lost0 = b->lost;
    int total = 0, found = 0;
    for (int sweep = 0; sweep < MAX_SWEEPS; sweep++) {
        found = 0;
        for (int k = 0; k < l->count; k++)
            found += resolve(l, m, k, x, v, u, du, b);
        total += found;
        if (!found)
            break;
    }
    if (found)
        b->piston += unpile(l, m, x, v, u, du);
    if (total || found) {
        /* Moving masses back onto their limits changes the springs' energy too: what the
         * mechanical energy lost beyond the piston's work is the contacts'. */
        double e1 = model_kinetic(m, v) + model_potential(m, x, u);
        double lost = (e0 - e1) + (b->piston - piston0);
        /* Putting a pair back on its limit moves the springs' energy a little either way;
         * a gain from it (1e-10 J in a pile-up at dt 0.001) is the method's error, not a
         * contact's: it stays out of the contact book, which never falls, and shows in the
         * balance. */
        b->lost = lost0 + (lost > 0.0 ? lost : 0.0);
    }
    return total + found;
}

int collision_apply(const struct model *m, double *x, double *v, double u, double du)
{
    struct collision_limits l;
    struct collision_books b = {0.0, 0.0};
    collision_limits(&l, m);
    return collision_settle(&l, m, x, v, u, du, &b);
}

int collision_cap(const struct model *m, double *v, struct collision_books *b)
{
    int capped = 0;
    for (int i = 0; i < m->n; i++) {
        if (v[i] <= MODEL_VMAX && v[i] >= -MODEL_VMAX)
            continue;
        double c = v[i] > 0.0 ? MODEL_VMAX : -MODEL_VMAX;
        b->lost += 0.5 * m->m[i] * (v[i] * v[i] - c * c);
        v[i] = c;
        capped++;
    }
    return capped;
}

int collision_needed(const struct collision_limits *l, const double *x, const double *v,
                     double u)
{
    for (int i = 0; i < l->n; i++)
        if (fabs(v[i]) > MODEL_VMAX)
            return 1;
    if (!l->on)
        return 0;
    for (int k = 0; k < l->count; k++)
        if (collision_gap(l, k, x, u) < -SLACK)
            return 1;
    return 0;
}
