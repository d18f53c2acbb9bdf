/* sweep.c: stepped-sine bookkeeping. At each point the drive runs for a settling time
 * (transients decay), then over a whole number of periods the largest |x_i| is the
 * measured amplitude of mass i, and x_i's correlations with the drive's sine and cosine
 * give its phase; the next point follows at once. */
#include "sweep.h"

#include <math.h>
#include <stdlib.h>

struct sweep *sweep_new(int n, int points)
{
    struct sweep *s = calloc(1, sizeof *s);
    if (!s)
        return NULL;
    s->n = n;
    s->points = points;
    s->freq = malloc((size_t)points * sizeof *s->freq);
    s->peak = malloc((size_t)points * (size_t)n * sizeof *s->peak);
    s->phase = malloc((size_t)points * (size_t)n * sizeof *s->phase);
    s->in = calloc((size_t)n, sizeof *s->in);
    s->quad = calloc((size_t)n, sizeof *s->quad);
    if (!s->freq || !s->peak || !s->phase || !s->in || !s->quad) {
        sweep_free(s);
        return NULL;
    }
    for (int i = 0; i < points * n; i++)
        s->peak[i] = s->phase[i] = NAN;
    return s;
}

void sweep_free(struct sweep *s)
{
    if (!s)
        return;
    free(s->freq);
    free(s->peak);
    free(s->phase);
    free(s->in);
    free(s->quad);
    free(s);
}

/* Times for the current point: settling and measuring, whole periods. */
static void plan_point(struct sweep *s)
{
    double period = 1.0 / s->freq[s->index];
    s->settle = fmax(s->settle_min, 8.0 * period);
    s->measure = ceil(fmax(3.0, 4.0 * period) / period - 1e-9) * period;
}

void sweep_start(struct sweep *s, double fmin, double fmax, double settle, double t)
{
    for (int p = 0; p < s->points; p++) {
        s->freq[p] = s->points > 1 ? fmin + (fmax - fmin) * p / (s->points - 1) : fmin;
        for (int i = 0; i < s->n; i++)
            s->peak[p * s->n + i] = s->phase[p * s->n + i] = NAN;
    }
    s->index = 0;
    s->contacts = 0;
    s->active = true;
    s->measuring = false;
    s->t_point = t;
    s->settle_min = settle;
    plan_point(s);
}

void sweep_stop(struct sweep *s)
{
    s->active = false;
}

double sweep_frequency(const struct sweep *s)
{
    return s->freq[s->index < s->points ? s->index : s->points - 1];
}

double sweep_phase_deg(double in, double quad)
{
    double deg = atan2(quad, in) * (180.0 / M_PI);
    return deg <= -180.0 ? deg + 360.0 : deg;
}

enum sweep_event sweep_update(struct sweep *s, double t, const double *x, double cycles)
{
    if (!s->active)
        return SWEEP_IDLE;
    double since = t - s->t_point;
    if (since < s->settle)
        return SWEEP_SAME;
    double *peak = s->peak + (size_t)s->index * s->n;
    if (!s->measuring) {
        s->measuring = true;
        for (int i = 0; i < s->n; i++)
            peak[i] = s->in[i] = s->quad[i] = 0.0;
    }
    double theta = 2.0 * M_PI * (cycles - floor(cycles));
    double sn = sin(theta), cs = cos(theta);
    for (int i = 0; i < s->n; i++) {
        peak[i] = fmax(peak[i], fabs(x[i]));
        s->in[i] += x[i] * sn;
        s->quad[i] += x[i] * cs;
    }
    if (since < s->settle + s->measure)
        return SWEEP_SAME;
    /* This point is done. */
    for (int i = 0; i < s->n; i++)
        s->phase[(size_t)s->index * s->n + i] = sweep_phase_deg(s->in[i], s->quad[i]);
    s->index++;
    s->measuring = false;
    s->t_point = t;
    if (s->index >= s->points) {
        s->active = false;
        return SWEEP_DONE;
    }
    plan_point(s);
    return SWEEP_RETUNE;
}

void sweep_count_contacts(struct sweep *s, int contacts)
{
    if (s->active && contacts > 0)
        s->contacts += contacts;
}

int sweep_measured(const struct sweep *s)
{
    return s->index < s->points ? s->index : s->points;
}
