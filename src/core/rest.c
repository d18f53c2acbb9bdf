/* rest.c: resting contacts as constraints (rest.h).
 *
 * A cluster of masses [f, l] joined by resting constraints moves as one body. With F_i =
 * m_i a_i the chain's own force on mass i (springs, dampers, no contact), its
 * acceleration is
 *   free:            A = sum F_i / sum m_i,
 *   on the wall:     A = 0,
 *   on the piston:   A = u'' (the end's acceleration).
 * The force across the cut before mass j of the cluster (j = f for the wall, j = l + 1
 * for the piston) follows from Newton's law on the part left of the cut,
 *   sum_{i<j} F_i + P_wall - lambda_j = sum_{i<j} m_i A,
 * P_wall the wall's push on the cluster, -sum F_i (its whole net force) when it holds it:
 * lambda_j > 0 pushes the two sides apart, as a contact can; lambda_j < 0 would pull, and
 * the contact parts there. */
#include "rest.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

struct rest *rest_new(int n)
{
    struct rest *r = calloc(1, sizeof *r);
    if (!r)
        return NULL;
    r->on = calloc(2 * ((size_t)n + 1), sizeof *r->on);
    r->acc = calloc((size_t)n + 3 * ((size_t)n + 2), sizeof *r->acc);
    r->first = calloc(2 * (size_t)n, sizeof *r->first);
    r->held = calloc((size_t)n, sizeof *r->held);
    if (!r->on || !r->acc || !r->first || !r->held) {
        rest_free(r);
        return NULL;
    }
    r->soft = r->on + n + 1;
    r->pool = r->acc + n;
    r->last = r->first + n;
    r->n = n;
    r->count = n + 1;
    r->v_rest = COLLISION_V_REST;
    return r;
}

void rest_free(struct rest *r)
{
    if (!r)
        return;
    free(r->on);
    free(r->acc);
    free(r->first);
    free(r->held);
    free(r);
}

void rest_clear(struct rest *r, const struct collision_limits *l)
{
    memset(r->on, 0, 2 * ((size_t)r->n + 1));
    r->count = l->count;
    r->active = 0;
    r->clusters = 0;
}

void rest_copy(struct rest *dst, const struct rest *src)
{
    memcpy(dst->on, src->on, (size_t)src->n + 1);
    dst->count = src->count;
    dst->active = src->active;
    dst->clusters = src->clusters;
    memcpy(dst->first, src->first, 2 * (size_t)src->n * sizeof *src->first);
    memcpy(dst->held, src->held, (size_t)src->n * sizeof *src->held);
}

int rest_cluster(const struct rest *r, int n, int i, int *first, int *last)
{
    int f = i, l = i;
    while (f > 0 && r->on[f])
        f--;
    while (l + 1 < n && r->on[l + 1])
        l++;
    *first = f, *last = l;
    if (f == 0 && r->on[0])
        return -1;
    if (l == n - 1 && r->count > n && r->on[n])
        return 1;
    return 0;
}

void rest_set(struct rest *r, int k, bool on)
{
    if (r->on[k] == on)
        return;
    r->on[k] = on;
    r->active += on ? 1 : -1;
    /* The clusters anew: every run of masses joined by resting contacts, and single
     * masses the wall or the piston holds. A run of free single masses is passed over by
     * its flags alone (in a long chain nearly every mass). */
    int n = r->n;
    r->clusters = 0;
    for (int f = 0, l; f < n && r->active; f = l + 1) {
        if (f > 0 && f + 1 < n) {
            /* to the mass before the next resting contact between two masses, or the last */
            const bool *next = memchr(r->on + f + 1, true, (size_t)(n - 1 - f));
            f = next ? (int)(next - r->on) - 1 : n - 1;
        }
        int held = rest_cluster(r, n, f, &f, &l);
        if (f == l && !held)
            continue;
        r->first[r->clusters] = f, r->last[r->clusters] = l;
        r->held[r->clusters++] = (signed char)held;
    }
}

/* The cluster's acceleration from the chain's accelerations a over [f, l]. */
static double cluster_accel(const struct model *m, const double *a, int f, int l, int held,
                            double ddu)
{
    if (held < 0)
        return 0.0;
    if (held > 0)
        return ddu;
    double force = 0.0, mass = 0.0;
    for (int i = f; i <= l; i++)
        force += m->m[i] * a[i], mass += m->m[i];
    return force / mass;
}

double rest_project(const struct rest *r, const struct model *m, double *a, double ddu)
{
    if (!r || !r->active)
        return 0.0;
    double push = 0.0;
    for (int c = 0; c < r->clusters; c++) {
        int f = r->first[c], l = r->last[c], held = r->held[c];
        double acc = cluster_accel(m, a, f, l, held, ddu);
        if (held > 0)
            for (int i = f; i <= l; i++)
                push += m->m[i] * (a[i] - acc);
        for (int i = f; i <= l; i++)
            a[i] = acc;
    }
    return push;
}

int rest_forces(const struct rest *r, const struct model *m, const double *x, const double *v,
                double u, double du, double ddu, double fin, double *force)
{
    int n = m->n, weakest = -1;
    if (!r->active)
        return -1;
    double *a = r->acc; /* only the clusters' masses are read */
    for (int c = 0; c < r->clusters; c++)
        model_accel_span(m, x, v, u, du, r->first[c], r->last[c], a);
    if (fin != 0.0) /* the force input presses or pulls as the springs do */
        a[m->force_on] += fin / m->m[m->force_on];
    for (int c = 0; c < r->clusters; c++) {
        int f = r->first[c], l = r->last[c], held = r->held[c];
        double acc = cluster_accel(m, a, f, l, held, ddu);
        /* Walking the cuts left to right: lambda_j = (forces left of j) - (mass left) A. */
        double left = 0.0;
        if (held < 0) {
            for (int i = f; i <= l; i++)
                left -= m->m[i] * a[i]; /* the wall's push */
            force[0] = left;
        }
        for (int j = f + 1; j <= l + 1; j++) {
            left += m->m[j - 1] * (a[j - 1] - acc);
            if (j <= l || (held > 0 && j == n))
                force[j] = left;
        }
    }
    /* Only the resting contacts' forces are set: the weakest among them. */
    for (int c = 0; c < r->clusters; c++) {
        int lo = r->held[c] < 0 ? r->first[c] : r->first[c] + 1;
        int hi = r->held[c] > 0 ? n : r->last[c];
        for (int k = lo; k <= hi; k++)
            if (r->on[k] && (weakest < 0 || force[k] < force[weakest]))
                weakest = k;
    }
    return weakest;
}

void rest_snap(const struct rest *r, const struct collision_limits *l, const struct model *m,
               double *x, double *v, double u, double du)
{
    if (!r->active)
        return;
    int n = m->n;
    /* Mass i's displacement when it touches the wall, its left neighbour, the piston. */
    double wall = 0.5 * l->w - l->spacing, pair = l->w - l->spacing;
    double piston = MODEL_LENGTH + u - 0.5 * l->w - n * l->spacing;
    for (int c = 0; c < r->clusters; c++) {
        int f = r->first[c], last = r->last[c], held = r->held[c];
        double vc, x0;
        if (held < 0) {
            vc = 0.0, x0 = wall;
        } else if (held > 0) {
            vc = du, x0 = piston - (last - f) * pair;
        } else {
            double p = 0.0, mass = 0.0, mx = 0.0;
            for (int i = f; i <= last; i++) {
                p += m->m[i] * v[i], mass += m->m[i];
                mx += m->m[i] * (x[i] - (i - f) * pair);
            }
            vc = p / mass;
            x0 = mx / mass;
        }
        for (int i = f; i <= last; i++) {
            x[i] = x0 + (i - f) * pair;
            v[i] = vc;
        }
    }
}
