/* plot.c: ticks (1, 2, 5 x 10^k with the axis ends rounded outward, as gnuplot's
 * axis.c does), steady autoscaling, and series onto a braille canvas. */
#include "plot.h"

#include <math.h>
#include <stdlib.h>
#include <stdio.h>
#include <string.h>

double plot_tick_step(double lo, double hi, int max_ticks)
{
    double span = hi - lo;
    if (!(span > 0.0) || !isfinite(span))
        return 1.0;
    if (max_ticks < 1)
        max_ticks = 1;
    double raw = span / max_ticks;
    double mag = pow(10.0, floor(log10(raw)));
    static const double nice[] = {1.0, 2.0, 5.0, 10.0};
    for (int i = 0; i < 4; i++)
        if (nice[i] * mag >= raw * (1.0 - 1e-9))
            return nice[i] * mag;
    return 10.0 * mag;
}

void plot_round_out(double *lo, double *hi, double step)
{
    *lo = floor(*lo / step + 1e-9) * step;
    *hi = ceil(*hi / step - 1e-9) * step;
    if (*hi <= *lo)
        *hi = *lo + step;
}

/* The nice range the data [dmin, dmax] asks for. */
static void nice_range(double dmin, double dmax, int max_ticks, double *lo, double *hi,
                       double *step)
{
    double span = dmax - dmin;
    double pad = span > 1e-12 ? 0.05 * span : fmax(0.1 * fabs(dmax), 1.0);
    *lo = dmin - pad;
    *hi = dmax + pad;
    *step = plot_tick_step(*lo, *hi, max_ticks);
    plot_round_out(lo, hi, *step);
}

void plot_scale_update(struct scale *s, double dmin, double dmax, int max_ticks,
                       int shrink_after)
{
    if (!isfinite(dmin) || !isfinite(dmax) || dmax < dmin)
        return;
    /* Flat data (a chain at rest) says nothing about the scale: keep the one there is. */
    bool flat = dmax - dmin <= 1e-12 * fmax(1.0, fabs(dmax));
    if (s->set && flat && dmin >= s->lo && dmax <= s->hi)
        return;
    double lo, hi, step;
    nice_range(dmin, dmax, max_ticks, &lo, &hi, &step);
    if (s->set && !s->fitted && !flat) {
        /* The first real data replaces a range that was only a placeholder. */
        s->lo = lo, s->hi = hi, s->step = step, s->fitted = true, s->quiet = 0;
        return;
    }
    if (!flat)
        s->fitted = true;
    if (!s->set || dmin < s->lo || dmax > s->hi) {
        /* Grow at once, to the union so nothing shown before falls off. */
        if (s->set) {
            lo = fmin(lo, s->lo);
            hi = fmax(hi, s->hi);
            step = plot_tick_step(lo, hi, max_ticks);
            plot_round_out(&lo, &hi, step);
        }
        s->lo = lo, s->hi = hi, s->step = step, s->set = true, s->quiet = 0;
        return;
    }
    if (hi - lo < 0.5 * (s->hi - s->lo)) {
        if (++s->quiet >= shrink_after)
            s->lo = lo, s->hi = hi, s->step = step, s->quiet = 0;
    } else {
        s->quiet = 0;
    }
}

void plot_tick_label(double v, double step, char *buf, size_t len)
{
    if (fabs(v) < 1e-9 * step)
        v = 0.0; /* no "-0" */
    double a = fmax(fabs(v), step);
    if (a >= 1e5 || step < 1e-4) {
        snprintf(buf, len, "%.0e", v);
        return;
    }
    int decimals = step >= 1.0 ? 0 : (int)ceil(-log10(step) - 1e-9);
    snprintf(buf, len, "%.*f", decimals, v);
}

/* Dot row of value v on a canvas of h dots (row 0 at the top). */
static int dot_row(double v, const struct scale *s, int h)
{
    double f = (v - s->lo) / (s->hi - s->lo);
    double r = (1.0 - f) * (h - 1);
    if (r < -1.0)
        r = -1.0;
    if (r > h)
        r = h;
    return (int)lround(r);
}

void plot_series(struct canvas *c, const double *t, const double *y, int count, size_t stride,
                 double t0, double t1, const struct scale *ys, bool dash, unsigned char color)
{
    int w = 2 * c->cols, h = 4 * c->rows;
    int col = -1, lo = 0, hi = 0, prev_last = 0, have_prev = 0, last = 0;
    double per = (t1 - t0) / w;
    for (int k = 0; k <= count; k++) {
        int x = -1, r = 0;
        if (k < count) {
            double tk = t[k * stride];
            if (tk < t0 || tk > t1)
                continue;
            x = (int)((tk - t0) / per);
            if (x >= w)
                x = w - 1;
            r = dot_row(y[k * stride], ys, h);
        }
        if (x != col) {
            if (col >= 0 && !(dash && (col / 2) % 2)) {
                /* Join to the previous column, then draw this one's span. */
                if (have_prev)
                    canvas_vspan(c, col, prev_last, lo < prev_last ? lo : hi, color);
                canvas_vspan(c, col, lo, hi, color);
            }
            if (col >= 0) {
                prev_last = last;
                have_prev = x == col + 1;
            }
            col = x;
            lo = hi = r;
        }
        if (k < count) {
            if (r < lo)
                lo = r;
            if (r > hi)
                hi = r;
            last = r;
        }
    }
}

void plot_curve(struct canvas *c, const double *x, const double *y, int count, size_t stride,
                const struct scale *xs, const struct scale *ys, unsigned char color)
{
    int w = 2 * c->cols, h = 4 * c->rows;
    int px = 0, py = 0;
    for (int k = 0; k < count; k++) {
        double fx = (x[k * stride] - xs->lo) / (xs->hi - xs->lo);
        int cx = (int)lround(fx * (w - 1));
        int cy = dot_row(y[k * stride], ys, h);
        if (k > 0 && abs(cx - px) + abs(cy - py) < 4 * (w + h))
            canvas_line(c, px, py, cx, cy, color);
        else
            canvas_set(c, cx, cy, color);
        px = cx, py = cy;
    }
}
