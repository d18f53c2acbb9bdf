/* trail.c: the plots' ring of samples. Each record is stored twice, capacity apart, so
 * records head .. head + count - 1 are always one contiguous run. */
#include "trail.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* A trail whose records take width doubles. */
static struct trail *trail_of(int n, int capacity, int width)
{
    struct trail *tr = calloc(1, sizeof *tr);
    if (!tr)
        return NULL;
    tr->n = n;
    tr->width = width;
    tr->capacity = capacity;
    tr->buf = malloc(2 * (size_t)capacity * (size_t)tr->width * sizeof *tr->buf);
    tr->accel = malloc((size_t)n * sizeof *tr->accel);
    if (!tr->buf || !tr->accel) {
        trail_free(tr);
        return NULL;
    }
    return tr;
}

struct trail *trail_new(int n, int capacity)
{
    return trail_of(n, capacity, 2 + 3 * n + TRAIL_ENERGIES);
}

struct trail *trail_new_motion(int n, int capacity)
{
    return trail_of(n, capacity, 2 + 3 * n);
}

void trail_free(struct trail *tr)
{
    if (!tr)
        return;
    free(tr->buf);
    free(tr->accel);
    free(tr);
}

void trail_push(struct trail *tr, const struct sim *s)
{
    int slot = (tr->head + tr->count) % tr->capacity;
    if (tr->count == tr->capacity) {
        tr->head = (tr->head + 1) % tr->capacity;
        tr->count--;
    }
    double *a = tr->buf + (size_t)slot * tr->width;
    double *b = tr->buf + (size_t)(slot + tr->capacity) * tr->width;
    const double *x = sim_x(s), *v = sim_v(s);
    sim_accel(s, tr->accel);
    a[TRAIL_T] = sim_time(s);
    a[TRAIL_U] = sim_end_position(s);
    for (int i = 0; i < tr->n; i++) {
        a[TRAIL_X(tr, i)] = x[i];
        a[TRAIL_V(tr, i)] = v[i];
        a[TRAIL_A(tr, i)] = tr->accel[i];
    }
    if (tr->width > TRAIL_E(tr, 0)) {
        struct energy e;
        sim_energy(s, &e);
        a[TRAIL_E(tr, TRAIL_KE)] = e.kinetic;
        a[TRAIL_E(tr, TRAIL_PE)] = e.potential;
        a[TRAIL_E(tr, TRAIL_DISS)] = e.dissipated;
        a[TRAIL_E(tr, TRAIL_WORK)] = e.motor_work;
        a[TRAIL_E(tr, TRAIL_CONTACT)] = e.contact;
        a[TRAIL_E(tr, TRAIL_FORCE)] = e.force_work;
    }
    memcpy(b, a, (size_t)tr->width * sizeof *a);
    tr->count++;
}

int trail_every(double spacing, double dt)
{
    int every = (int)ceil(spacing / dt - 1e-9);
    return every < 1 ? 1 : every;
}

void trail_tick(struct trail *tr, int *since, int every, const struct sim *s)
{
    if (++*since < every)
        return;
    *since = 0;
    trail_push(tr, s);
}

void trail_drop_after(struct trail *tr, double t)
{
    const double *first = trail_first(tr);
    while (tr->count > 0 && first[(size_t)(tr->count - 1) * tr->width + TRAIL_T] > t + 1e-6)
        tr->count--;
}

void trail_follow(struct trail *tr, const struct sim *s)
{
    trail_drop_after(tr, sim_time(s));
    if (tr->count == 0)
        trail_push(tr, s);
}

void trail_clear(struct trail *tr)
{
    tr->head = 0;
    tr->count = 0;
}

const double *trail_first(const struct trail *tr)
{
    return tr->buf + (size_t)tr->head * tr->width;
}

double trail_time(const struct trail *tr, int i)
{
    return trail_first(tr)[(size_t)i * tr->width + TRAIL_T];
}

int trail_index(const struct trail *tr, double t)
{
    int lo = 0, hi = tr->count; /* the first record at or after t is in [lo, hi] */
    while (lo < hi) {
        int mid = lo + (hi - lo) / 2;
        if (trail_time(tr, mid) < t)
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo;
}

int trail_nearest(const struct trail *tr, double t)
{
    if (tr->count == 0)
        return -1;
    int i = trail_index(tr, t);
    if (i == tr->count)
        return i - 1;
    if (i > 0 && t - trail_time(tr, i - 1) <= trail_time(tr, i) - t)
        return i - 1;
    return i;
}
