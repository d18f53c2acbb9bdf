/* sweep.c: stepped-sine bookkeeping. At each point the drive runs for a settling time
 * (transients decay), or until the swings are steady, then over a whole number of
 * periods the largest |x_i| is the measured amplitude of mass i, and x_i's correlations
 * with the drive's sine and cosine give its phase; the next point follows at once. */
#include "sweep.h"

#include <math.h>
#include <stdlib.h>

#include "collision.h"
#include "modes.h"

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
    s->x1 = calloc((size_t)n, sizeof *s->x1);
    s->x2 = calloc((size_t)n, sizeof *s->x2);
    s->swing = calloc((size_t)n, sizeof *s->swing);
    s->band = calloc(6 * (size_t)n, sizeof *s->band);
    s->lock = calloc(2 * (size_t)n, sizeof *s->lock);
    s->extreme = calloc((size_t)n, sizeof *s->extreme);
    if (!s->freq || !s->peak || !s->phase || !s->in || !s->quad || !s->x1 || !s->x2 ||
        !s->swing || !s->band || !s->lock || !s->extreme) {
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
    free(s->x1);
    free(s->x2);
    free(s->swing);
    free(s->band);
    free(s->lock);
    free(s->extreme);
    free(s);
}

/* Times for the current point: settling and measuring, whole periods; its swings not
 * watched yet. */
static void plan_point(struct sweep *s)
{
    double period = 1.0 / s->freq[s->index];
    s->settle = fmax(s->settle_min, 8.0 * period);
    s->measure = ceil(fmax(3.0, 4.0 * period) / period - 1e-9) * period;
    s->t_level = NAN;
    s->seen = 0;
    s->whole = false;
    s->gram[0] = s->gram[1] = s->gram[2] = 0.0;
    for (int i = 0; i < s->n; i++)
        s->swing[i] = s->lock[2 * i] = s->lock[2 * i + 1] = 0.0;
}

double sweep_point(double fmin, double fmax, int points, int p)
{
    return points > 1 ? fmin + (fmax - fmin) * p / (points - 1) : fmin;
}

void sweep_start(struct sweep *s, double fmin, double fmax, double settle, double t)
{
    for (int p = 0; p < s->points; p++) {
        s->freq[p] = sweep_point(fmin, fmax, s->points, p);
        for (int i = 0; i < s->n; i++)
            s->peak[p * s->n + i] = s->phase[p * s->n + i] = NAN;
    }
    s->index = 0;
    s->contacts = 0;
    s->active = true;
    s->measuring = false;
    s->t_point = t;
    s->settle_min = settle;
    s->hold = 0.0;
    s->unsteady = 0;
    plan_point(s);
}

void sweep_until_steady(struct sweep *s, double hold, double most)
{
    s->hold = hold > 0.0 ? hold : 0.0;
    s->most = most;
}

/* Mass i's phasor in the period just ended, X (cos phi, sin phi) of X sin(theta + phi):
 * the least-squares fit of a sin(theta) + b cos(theta) to the period's samples, exact for
 * a sine at the drive's frequency however the samples fall in the period:
 * [ss sc; sc cc] [a; b] = [sum x sin; sum x cos]. False with too few samples to fit. */
static bool phasor(const struct sweep *s, int i, double *re, double *im)
{
    const double *g = s->gram;
    double det = g[0] * g[2] - g[1] * g[1];
    if (!(det > 1e-9 * g[0] * g[2]))
        return false;
    double xs = s->lock[2 * i], xc = s->lock[2 * i + 1];
    *re = (g[2] * xs - g[1] * xc) / det;
    *im = (g[0] * xc - g[1] * xs) / det;
    return true;
}

/* A drive period has ended at time t: each mass's swing in it, and its phasor, join the
 * band of those since t_level; or, the swings spread past SWEEP_LEVEL of the largest or
 * the phasors as far apart, start it afresh. The phasor catches a transient that turns
 * the phase but hardly the swing (one near the drive's frequency, a quarter turn from
 * it). */
static void close_period(struct sweep *s, double t)
{
    double top = 0.0;
    bool level = !isnan(s->t_level);
    for (int i = 0; i < s->n && level; i++)
        top = fmax(top, fmax(s->band[6 * i + 1], s->swing[i]));
    for (int i = 0; i < s->n; i++) {
        double *band = s->band + 6 * i, now[3] = {s->swing[i], 0.0, 0.0};
        if (!phasor(s, i, &now[1], &now[2]))
            level = false;
        double swing = fmax(band[1], now[0]) - fmin(band[0], now[0]);
        double dre = fmax(band[3], now[1]) - fmin(band[2], now[1]);
        double dim = fmax(band[5], now[2]) - fmin(band[4], now[2]);
        level = level && swing <= SWEEP_LEVEL * top && hypot(dre, dim) <= SWEEP_LEVEL * top;
    }
    for (int i = 0; i < s->n; i++) {
        double *band = s->band + 6 * i, now[3] = {s->swing[i], 0.0, 0.0};
        phasor(s, i, &now[1], &now[2]);
        for (int k = 0; k < 3; k++) {
            band[2 * k] = level ? fmin(band[2 * k], now[k]) : now[k];
            band[2 * k + 1] = level ? fmax(band[2 * k + 1], now[k]) : now[k];
        }
    }
    if (!level)
        s->t_level = t;
}

/* The height of the parabola through (-1, y0), (0, y1), (1, y2) at its vertex. */
static double vertex(double y0, double y1, double y2)
{
    double curve = y0 - 2.0 * y1 + y2;
    return curve != 0.0 ? y1 - (y0 - y2) * (y0 - y2) / (8.0 * curve) : y1;
}

/* Takes sample x at time t, the drive at cycles: each mass's extremes, placed by the
 * parabola through the sample before and its neighbours, make its swing in this period
 * (the first period of a point, a part of one, is not counted); refined[i] gets the
 * largest |x_i| found at this sample. */
static void watch_swings(struct sweep *s, double t, const double *x, double cycles,
                         double *refined)
{
    long cycle = (long)floor(cycles);
    if (s->seen > 0 && cycle != s->cycle) {
        if (s->whole)
            close_period(s, t);
        for (int i = 0; i < s->n; i++)
            s->swing[i] = s->lock[2 * i] = s->lock[2 * i + 1] = 0.0;
        s->gram[0] = s->gram[1] = s->gram[2] = 0.0;
        s->whole = true;
    }
    s->cycle = cycle;
    double theta = 2.0 * M_PI * (cycles - floor(cycles));
    double sn = sin(theta), cs = cos(theta);
    for (int i = 0; i < s->n; i++) {
        double a = s->x2[i], b = s->x1[i], c = x[i];
        refined[i] = fabs(c);
        if (s->seen >= 2 && ((b > a && b >= c) || (b < a && b <= c)))
            refined[i] = fmax(refined[i], fabs(vertex(a, b, c)));
        s->swing[i] = fmax(s->swing[i], refined[i]);
        s->lock[2 * i] += c * sn;
        s->lock[2 * i + 1] += c * cs;
        s->x2[i] = b, s->x1[i] = c;
    }
    s->gram[0] += sn * sn, s->gram[1] += sn * cs, s->gram[2] += cs * cs;
    s->seen++;
}

/* Whether the point at time t (since its start) has settled. */
static bool settled(struct sweep *s, double t, double since)
{
    if (since < s->settle)
        return false;
    if (s->hold <= 0.0)
        return true;
    double period = 1.0 / s->freq[s->index], hold = fmax(s->hold, 4.0 * period);
    if (!isnan(s->t_level) && t - s->t_level >= hold - 1e-9)
        return true;
    /* Never given up before twice the least a point can take. */
    if (since < fmax(s->most, 2.0 * (s->settle + hold)))
        return false;
    s->unsteady++;
    return true;
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
    double *refined = s->extreme;
    watch_swings(s, t, x, cycles, refined);
    double *peak = s->peak + (size_t)s->index * s->n;
    if (!s->measuring) {
        if (!settled(s, t, since))
            return SWEEP_SAME;
        s->measuring = true;
        /* From where a fixed settling time ends, or from now. */
        s->t_measure = s->hold > 0.0 ? t : s->t_point + s->settle;
        for (int i = 0; i < s->n; i++)
            peak[i] = s->in[i] = s->quad[i] = 0.0;
    }
    double theta = 2.0 * M_PI * (cycles - floor(cycles));
    double sn = sin(theta), cs = cos(theta);
    for (int i = 0; i < s->n; i++) {
        peak[i] = fmax(peak[i], refined[i]);
        s->in[i] += x[i] * sn;
        s->quad[i] += x[i] * cs;
    }
    if (t < s->t_measure + s->measure)
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

double sweep_contact_scale(const struct model *m, const double *freq, int count)
{
    struct collision_limits l;
    collision_limits(&l, m);
    int n = m->n;
    if (!l.on || !model_driven(m))
        return INFINITY;
    double *amp = calloc(5 * (size_t)n, sizeof *amp);
    if (!amp)
        return INFINITY;
    double *phase = amp + n, *re = phase + n, *im = re + n, *rest = im + n;
    double least = INFINITY, a = m->boundary == BOUNDARY_MOTOR ? m->motor.amplitude : 0.0;
    for (int f = 0; f < count; f++) {
        if (modes_response_phase(m, freq[f], amp, phase) != 0)
            continue;
        for (int i = 0; i < n; i++) {
            re[i] = amp[i] * cos(phase[i] * (M_PI / 180.0));
            im[i] = amp[i] * sin(phase[i] * (M_PI / 180.0));
        }
        /* A gap is affine in x and u: its swing is the gap at the complex amplitudes less
         * the gap at rest, the motor's u = A (phase 0). */
        for (int k = 0; k < l.count; k++) {
            double g0 = collision_gap(&l, k, rest, 0.0);
            double sr = collision_gap(&l, k, re, a) - g0, si = collision_gap(&l, k, im, 0.0) - g0;
            double swing = hypot(sr, si);
            if (swing > 0.0)
                least = fmin(least, g0 / swing);
        }
    }
    free(amp);
    return least;
}

double sweep_contact_amplitude(const struct model *m, const double *freq, int count)
{
    if (m->boundary != BOUNDARY_MOTOR || !(m->motor.amplitude > 0.0) || model_forced(m))
        return INFINITY;
    return sweep_contact_scale(m, freq, count) * m->motor.amplitude;
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
