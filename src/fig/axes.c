/* axes.c: a figure's axes (axes.h). The linear steps come from app/axis.c, so a figure's
 * ticks are the ones the terminal's charts would choose for the same range. */
#include "axes.h"

#include <math.h>
#include <stdio.h>

#include "../chart/axis.h"

/* Puts v among x's ticks if there is room. */
static void add_tick(struct fig_axis *x, double v)
{
    if (x->nt < FIG_AXIS_TICKS)
        x->tv[x->nt++] = v;
}

/* Decides the notation: exponent form for all labels when one would be long in plain
 * decimals (a value of 1e5 or more, or a non-zero one under 0.001). */
static void notation(struct fig_axis *x)
{
    x->sci = false;
    for (int k = 0; k < x->nt; k++) {
        double a = fabs(x->tv[k]);
        if (a >= 1e5 || (a > 0.0 && a < 1e-3 * (1.0 - 1e-9)))
            x->sci = true;
    }
}

/* The ticks from lo (a multiple of step) to hi. */
static void linear_ticks(struct fig_axis *x, double step)
{
    double first = ceil(x->lo / step - 1e-9) * step;
    x->nt = 0;
    for (int k = 0; first + k * step <= x->hi + 1e-9 * step && k < FIG_AXIS_TICKS; k++) {
        double v = first + k * step;
        add_tick(x, fabs(v) < 1e-9 * step ? 0.0 : v); /* no "-0" */
    }
    x->dec = (int)ceil(-log10(step) - 1e-9);
    x->dec = x->dec < 0 ? 0 : x->dec;
    notation(x);
}

void fig_axis_linear(struct fig_axis *x, double lo, double hi, double pad, int max_ticks,
                     bool whole)
{
    x->log = false;
    if (!(lo <= hi)) /* no data */
        lo = -1.0, hi = 1.0;
    double span = hi - lo;
    if (span <= 1e-12 * fmax(1.0, fabs(hi))) { /* one value: a range around it */
        span = fmax(fabs(hi), 1.0);
        lo -= 0.5 * span, hi = lo + span;
    } else {
        lo -= pad * span, hi += pad * span;
    }
    double step = axis_step(lo, hi, max_ticks < 1 ? 1 : max_ticks);
    if (whole && step < 1.0)
        step = 1.0;
    axis_round_out(&lo, &hi, step);
    x->lo = lo, x->hi = hi;
    linear_ticks(x, step);
}

void fig_axis_fixed(struct fig_axis *x, double lo, double hi, double step)
{
    x->log = false;
    x->lo = lo, x->hi = hi;
    linear_ticks(x, step);
}

/* The values m * 10^d (m in mant) within [lo, hi] (not log10); how many there are, with
 * x's ticks set to them when set is true. */
static int decade_ticks(struct fig_axis *x, const int *mant, int nm, int every, bool set)
{
    double vlo = pow(10.0, x->lo), vhi = pow(10.0, x->hi);
    int count = 0;
    if (set)
        x->nt = 0;
    for (int d = (int)floor(x->lo) - 1; d <= (int)ceil(x->hi); d++) {
        if (((d % every) + every) % every != 0)
            continue;
        for (int i = 0; i < nm; i++) {
            double v = mant[i] * pow(10.0, d);
            if (v >= vlo * (1.0 - 1e-9) && v <= vhi * (1.0 + 1e-9)) {
                count++;
                if (set)
                    add_tick(x, v);
            }
        }
    }
    return count;
}

void fig_axis_log(struct fig_axis *x, double lo, double hi, double pad, int max_ticks)
{
    static const int one[] = {1}, three[] = {1, 2, 5}, nine[] = {1, 2, 3, 4, 5, 6, 7, 8, 9};
    x->log = true;
    if (!(lo > 0.0 && lo <= hi)) /* no data */
        lo = 0.1, hi = 10.0;
    if (hi <= lo * (1.0 + 1e-9))
        lo /= 2.0, hi *= 2.0;
    x->lo = log10(lo) - pad, x->hi = log10(hi) + pad;
    if (max_ticks < 2)
        max_ticks = 2;
    x->dec = -1; /* each label with the digits it needs */
    int n125 = decade_ticks(x, three, 3, 1, false), n9 = decade_ticks(x, nine, 9, 1, false);
    if (n125 >= 3 && n125 <= max_ticks) {
        decade_ticks(x, three, 3, 1, true);
    } else if (n125 > max_ticks) {
        /* Only the powers of ten; every second, fifth... where even those crowd. */
        int n1 = decade_ticks(x, one, 1, 1, false), every = 1;
        while (n1 / every > max_ticks)
            every++;
        decade_ticks(x, one, 1, every, true);
    } else if (n9 >= 3 && n9 <= max_ticks) {
        decade_ticks(x, nine, 9, 1, true);
    } else {
        /* Within a decade and too narrow for whole digits: plain steps inside it. */
        double vlo = pow(10.0, x->lo), vhi = pow(10.0, x->hi);
        double step = axis_step(vlo, vhi, max_ticks);
        double first = ceil(vlo / step - 1e-9) * step;
        x->nt = 0;
        for (int k = 0; first + k * step <= vhi * (1.0 + 1e-12); k++)
            add_tick(x, first + k * step);
        x->dec = (int)ceil(-log10(step) - 1e-9);
        x->dec = x->dec < 0 ? 0 : x->dec;
    }
    notation(x);
}

double fig_axis_map(const struct fig_axis *x, double v)
{
    if (x->log)
        v = log10(v);
    return x->a + (v - x->lo) / (x->hi - x->lo) * (x->b - x->a);
}

bool fig_axis_ok(const struct fig_axis *x, double v)
{
    return isfinite(v) && (!x->log || v > 0.0);
}

/* Digits after the point that v needs (at most 6). */
static int digits_of(double v)
{
    for (int d = 0; d < 6; d++) {
        double s = fabs(v) * pow(10.0, d);
        if (fabs(s - round(s)) < 1e-6 * fmax(1.0, s))
            return d;
    }
    return 6;
}

void fig_axis_label(const struct fig_axis *x, double v, char *buf, size_t len)
{
    if (x->sci && v != 0.0) {
        int e = (int)floor(log10(fabs(v)) + 1e-9);
        double m = v / pow(10.0, e);
        snprintf(buf, len, "%.*fe%d", digits_of(m) > 2 ? 2 : digits_of(m), m, e);
        return;
    }
    int dec = x->dec >= 0 ? x->dec : digits_of(v);
    snprintf(buf, len, "%.*f", dec, v);
}
