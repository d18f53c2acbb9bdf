/* measure.c: period, frequency, peak-to-peak, rms, logarithmic decrement and damping
 * ratio of a sampled series, in one pass and no memory of its own. */
#include "measure.h"

#include <math.h>
#include <stdbool.h>

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
                          .p2p = NAN, .rms = NAN, .delta = NAN, .zeta = NAN};
    double lo = INFINITY, hi = -INFINITY, sq = 0.0;
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
            m->first = tp;
        m->last = tp;
        m->peaks++;
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
}
