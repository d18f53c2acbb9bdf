/* jump.c: the two-way sweep of a chain with cubic springs and the harmonic balance drawn
 * under it (jump.h). */
#include "jump.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "../core/hash.h"

bool jump_two_way(const struct model *m)
{
    return m->cubic && m->motor.wave == WAVE_SINE;
}

bool jump_turn(struct sweep **run, struct sweep **up, double t)
{
    struct sweep *s = *run;
    int last = s->points - 1;
    if (last < 1 || !(s->freq[last] > s->freq[0]))
        return false;
    struct sweep *down = *up;
    sweep_start(down, s->freq[last], s->freq[0], s->settle_min, t);
    sweep_until_steady(down, s->hold, s->most);
    *up = s;
    *run = down;
    return true;
}

/* The log of the amplitude ratio from point k to k + 1 of s of the mass whose is the
 * largest in size (0 out of range or unmeasured). */
static double step_log(const struct sweep *s, int k)
{
    int n = s->n;
    double most = 0.0;
    if (k < 0 || k + 1 >= sweep_measured(s))
        return 0.0;
    for (int i = 0; i < n; i++) {
        double a = s->peak[k * n + i], b = s->peak[(k + 1) * n + i];
        if (a > 0.0 && b > 0.0 && fabs(log(b / a)) > fabs(most))
            most = log(b / a);
    }
    return most;
}

static double step_size(const struct sweep *s, int k)
{
    return fabs(step_log(s, k));
}

bool jump_rises(const struct sweep *s, int k)
{
    return step_log(s, k) > 0.0;
}

int jump_find(const struct sweep *s, int from)
{
    for (int k = from > 0 ? from : 0; k + 1 < sweep_measured(s); k++) {
        double d = step_size(s, k);
        if (d >= log(JUMP_RATIO) && d > 2.0 * step_size(s, k - 1) &&
            d > 2.0 * step_size(s, k + 1))
            return k;
    }
    return -1;
}

uint64_t jump_theory_key(const struct model *m)
{
    size_t n = (size_t)m->n;
    double drive[3] = {m->motor.amplitude, m->force, (double)m->force_on};
    int kind[3] = {m->n, (int)m->boundary, (int)m->motor.wave};
    uint64_t h = hash_bytes(HASH_START, kind, sizeof kind);
    h = hash_bytes(h, drive, sizeof drive);
    h = hash_bytes(h, m->m, n * sizeof *m->m);
    h = hash_bytes(h, m->c, n * sizeof *m->c);
    h = hash_bytes(h, m->k, (n + 1) * sizeof *m->k);
    h = hash_bytes(h, m->k3, (n + 1) * sizeof *m->k3);
    return hash_bytes(h, m->cs, (n + 1) * sizeof *m->cs);
}

void jump_theory_free(struct jump_theory *t)
{
    free(t->f); /* the one block */
    *t = (struct jump_theory){0};
}

int jump_theory_solve(struct jump_theory *t, const struct model *m, double lo, double hi,
                      char *why, size_t len)
{
    jump_theory_free(t);
    struct harmonic_curve *c = harmonic_trace(m, lo, hi, why, len);
    if (!c)
        return -1;
    int n = c->n, count = c->count;
    /* One block: f, rate, then the amplitudes and the phases. */
    double *room = malloc((size_t)count * (2 + 2 * (size_t)n) * sizeof *room);
    if (!room || harmonic_curve_rates(m, c, room + count) != 0) {
        free(room);
        harmonic_curve_free(c);
        snprintf(why, len, "out of memory");
        return -1;
    }
    *t = (struct jump_theory){.n = n, .count = count, .lo = lo, .hi = hi, .f = room,
                              .rate = room + count, .folds = c->folds};
    t->amp = t->rate + count;
    t->phase = t->amp + (size_t)count * n;
    for (int k = 0; k < count; k++) {
        t->f[k] = c->f[k];
        for (int i = 0; i < n; i++) {
            /* x = a cos + b sin = X sin(wt + phi): X = hypot(a, b), phi = atan2(a, b). */
            double a = c->ab[(size_t)k * 2 * n + 2 * i], b = c->ab[(size_t)k * 2 * n + 2 * i + 1];
            double deg = atan2(a, b) * 180.0 / M_PI;
            t->amp[(size_t)k * n + i] = hypot(a, b);
            t->phase[(size_t)k * n + i] = deg <= -180.0 ? deg + 360.0 : deg;
            if (c->f[k] >= lo && c->f[k] <= hi)
                t->top = fmax(t->top, t->amp[(size_t)k * n + i]);
        }
    }
    /* The folds in order of frequency (the curve meets them in its own order). */
    for (int k = 0; k < c->folds; k++) {
        int j = k;
        for (; j > 0 && t->fold_f[j - 1] > c->fold_f[k]; j--)
            t->fold_f[j] = t->fold_f[j - 1];
        t->fold_f[j] = c->fold_f[k];
    }
    harmonic_curve_free(c);
    return 0;
}
