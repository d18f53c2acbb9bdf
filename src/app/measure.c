/* measure.c: period, frequency, peak-to-peak, rms, logarithmic decrement and damping
 * ratio of a sampled series, in one pass and no memory of its own; its fundamental
 * against a drive's; and the kind of motion these make. */
#include "measure.h"

#include <complex.h>
#include <math.h>

double measure_zeta(double delta)
{
    return delta / sqrt(4.0 * M_PI * M_PI + delta * delta);
}

void measure_vertex(double y0, double y1, double y2, double *at, double *height)
{
    /* y(s) = y1 + (y2 - y0) s / 2 + (y0 - 2 y1 + y2) s^2 / 2, stationary at
     * s = (y0 - y2) / (2 (y0 - 2 y1 + y2)), where y = y1 - (y0 - y2) s / 4. */
    double curve = y0 - 2.0 * y1 + y2;
    double s = curve != 0.0 ? 0.5 * (y0 - y2) / curve : 0.0;
    if (s < -1.0)
        s = -1.0;
    if (s > 1.0)
        s = 1.0;
    *at = s;
    *height = y1 - 0.25 * (y0 - y2) * s;
}

/* Running sums of a least-squares line through (k, v_k), k = 0, 1, ... */
struct line {
    int n;
    double sk, skk, sv, skv;
};

static void line_add(struct line *l, double v)
{
    double k = l->n++;
    l->sk += k, l->skk += k * k, l->sv += v, l->skv += k * v;
}

/* The slope of the line, NAN with fewer than two points. */
static double line_slope(const struct line *l)
{
    double den = l->n * l->skk - l->sk * l->sk;
    return l->n >= 2 && den > 0.0 ? (l->n * l->skv - l->sk * l->sv) / den : NAN;
}

void measure_series(struct measure *m, const double *t, const double *y, int count,
                    size_t stride)
{
    *m = (struct measure){.first = NAN, .last = NAN, .period = NAN, .frequency = NAN,
                          .p2p = NAN, .rms = NAN, .delta = NAN, .zeta = NAN, .high = NAN,
                          .low = NAN, .falling = true, .rising = true};
    double lo = INFINITY, hi = -INFINITY, sq = 0.0, before_peak = NAN;
    struct line times = {0}, logs = {0};
    bool all_up = true;
    for (int k = 0; k < count; k++) {
        double v = y[(size_t)k * stride];
        lo = fmin(lo, v), hi = fmax(hi, v), sq += v * v;
        if (k == 0 || k == count - 1)
            continue;
        double before = y[(size_t)(k - 1) * stride], after = y[(size_t)(k + 1) * stride];
        /* A maximum: rising into it, not rising out of it (a flat top counts once). */
        if (!(v > before && v >= after))
            continue;
        double at, height;
        measure_vertex(before, v, after, &at, &height);
        double tk = t[(size_t)k * stride];
        double h = 0.5 * (t[(size_t)(k + 1) * stride] - t[(size_t)(k - 1) * stride]);
        double tp = tk + at * h;
        if (m->peaks == 0)
            m->first = tp, m->high = m->low = height;
        m->last = tp;
        m->peaks++;
        m->high = fmax(m->high, height), m->low = fmin(m->low, height);
        if (!(height < before_peak) && m->peaks > 1)
            m->falling = false;
        if (!(height > before_peak) && m->peaks > 1)
            m->rising = false;
        before_peak = height;
        line_add(&times, tp);
        if (height > 0.0)
            line_add(&logs, -log(height));
        else
            all_up = false;
    }
    m->samples = count;
    if (count > 0) {
        m->p2p = hi - lo;
        m->rms = sqrt(sq / count);
    }
    m->period = line_slope(&times);
    if (m->period > 0.0)
        m->frequency = 1.0 / m->period;
    if (all_up) {
        m->delta = line_slope(&logs);
        m->zeta = isnan(m->delta) ? NAN : measure_zeta(m->delta);
    }
    m->falling &= m->peaks >= 2 && all_up;
    m->rising &= m->peaks >= 2;
}

/* The extreme (sign +1 the highest, -1 the lowest) of y over samples [from, to), refined
 * by the parabola through the extreme sample and its neighbours where it has both. */
static double extreme(const double *y, int count, size_t stride, int from, int to, int sign)
{
    int at = from;
    for (int k = from; k < to; k++)
        if (sign * y[(size_t)k * stride] > sign * y[(size_t)at * stride])
            at = k;
    double v = y[(size_t)at * stride];
    if (at > 0 && at < count - 1) {
        double s, h;
        measure_vertex(sign * y[(size_t)(at - 1) * stride], sign * v,
                       sign * y[(size_t)(at + 1) * stride], &s, &h);
        v = sign * h;
    }
    return v;
}

/* measure_drive and measure_drive_at: the drive sampled in u, or computed by drive(ctx, t)
 * where u is NULL. */
static void drive_measure(struct measure_drive *d, const double *t, const double *y,
                          const double *u, double (*drive)(const void *ctx, double t),
                          const void *ctx, int count, size_t stride, double hz)
{
    *d = (struct measure_drive){.level = NAN, .amplitude = NAN, .drive = NAN, .ratio = NAN,
                                .phase = NAN};
    if (count < 3 || !(hz > 0.0) || !isfinite(hz))
        return;
    double t0 = t[0], t1 = t[(size_t)(count - 1) * stride], period = 1.0 / hz;
    double h = (t1 - t0) / (count - 1);
    int periods = (int)floor((t1 - t0) / period + 1e-9);
    if (!(h > 0.0) || periods < 1)
        return;
    d->periods = periods;
    /* Each period's swing, from its last sample back: (t1 - (p + 1) T, t1 - p T]. */
    double hmax = -INFINITY, hmin = INFINITY, lmax = -INFINITY, lmin = INFINITY, swing = 0.0;
    int end = count;
    for (int p = 0; p < periods; p++) {
        int from = end;
        while (from > 0 && t[(size_t)(from - 1) * stride] > t1 - (p + 1) * period + 0.5 * h)
            from--;
        if (from == end)
            return;
        double hi = extreme(y, count, stride, from, end, +1);
        double lo = extreme(y, count, stride, from, end, -1);
        hmax = fmax(hmax, hi), hmin = fmin(hmin, hi), lmax = fmax(lmax, lo), lmin = fmin(lmin, lo);
        swing += 0.5 * (hi - lo) / periods;
        end = from;
    }
    if (swing > 0.0)
        d->level = fmax(hmax - hmin, lmax - lmin) / swing;
    /* Y = sum y e^(-i w t), U likewise, over the samples spanning the whole periods: the
     * rectangle rule, exact for a periodic series sampled evenly over whole periods. */
    int n = (int)lround(periods * period / h);
    n = n < 1 ? 1 : n > count ? count : n;
    double complex ys = 0.0, us = 0.0;
    for (int k = count - n; k < count; k++) {
        double complex e = cexp(-2.0 * M_PI * I * hz * t[(size_t)k * stride]);
        ys += y[(size_t)k * stride] * e;
        us += (u ? u[(size_t)k * stride] : drive(ctx, t[(size_t)k * stride])) * e;
    }
    d->amplitude = 2.0 * cabs(ys) / n;
    d->drive = 2.0 * cabs(us) / n;
    if (d->drive > 0.0) {
        d->ratio = d->amplitude / d->drive;
        d->phase = carg(ys * conj(us)) * 180.0 / M_PI;
        if (d->phase <= -180.0)
            d->phase += 360.0;
    }
}

void measure_drive(struct measure_drive *d, const double *t, const double *y, const double *u,
                   int count, size_t stride, double hz)
{
    drive_measure(d, t, y, u, NULL, NULL, count, stride, hz);
}

void measure_drive_at(struct measure_drive *d, const double *t, const double *y,
                      double (*drive)(const void *ctx, double t), const void *ctx, int count,
                      size_t stride, double hz)
{
    drive_measure(d, t, y, NULL, drive, ctx, count, stride, hz);
}

enum motion measure_motion(const struct measure *m, const struct measure_drive *d)
{
    if (d) {
        if (d->periods < 2 || isnan(d->level))
            return MOTION_UNKNOWN;
        return d->level <= MEASURE_LEVEL ? MOTION_STEADY : MOTION_TRANSIENT;
    }
    if (m->peaks < 2)
        return MOTION_UNKNOWN;
    /* Level first: peaks within rounding of each other may happen to fall in a row. */
    if (m->high > 0.0 && m->high - m->low <= MEASURE_LEVEL * m->high)
        return MOTION_STEADY;
    if (m->falling && m->delta > 0.0)
        return MOTION_DECAY;
    return MOTION_TRANSIENT;
}
