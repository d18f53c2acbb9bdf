/* plot_canvas.c: steady autoscaling on 1-2-5 ticks (axis.c), and series onto a braille canvas
 * on axes. */
#include "plot_canvas.h"

#include <math.h>
#include <stdlib.h>
#include <stdio.h>
#include <string.h>

#include "strokes.h"

/* The nice range the data [dmin, dmax] asks for. */
static void nice_range(double dmin, double dmax, int max_ticks, double *lo, double *hi,
                       double *step)
{
    double span = dmax - dmin;
    double pad = span > 1e-12 ? 0.05 * span : fmax(0.1 * fabs(dmax), 1.0);
    *lo = dmin - pad;
    *hi = dmax + pad;
    *step = axis_step(*lo, *hi, max_ticks);
    axis_round_out(lo, hi, *step);
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
    else if (!s->set)
        s->fitted = false; /* a range anew (set cleared) from flat data: a placeholder */
    if (!s->set || dmin < s->lo || dmax > s->hi) {
        /* Grow at once, to the union so nothing shown before falls off. */
        if (s->set) {
            lo = fmin(lo, s->lo);
            hi = fmax(hi, s->hi);
            step = axis_step(lo, hi, max_ticks);
            axis_round_out(&lo, &hi, step);
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

/* Dots this far off the canvas are as good as infinitely far: a bound for the maths. */
#define DOT_FAR 1e9

static double dot_clamp(double d)
{
    return d < -DOT_FAR ? -DOT_FAR : d > DOT_FAR ? DOT_FAR : d;
}

/* The dot column of x and the dot row of y (from the top) in dot coordinates. A value
 * half way between two dots goes to the right and up, as it would rounding half up on
 * the axes (which count y from the bottom). floor(x + 0.5) and ceil(y - 0.5), by a
 * conversion and a compare rather than libm's calls (a third of a dot's cost): every
 * coordinate here is held within DOT_FAR, far inside an int. */
static int dot_x(double x)
{
    double s = x + 0.5;
    int i = (int)s;
    return i - (s < (double)i);
}

static int dot_y(double y)
{
    double s = y - 0.5;
    int i = (int)s;
    return i + (s > (double)i);
}

/* fmin(fmax(v, lo), hi) for a finite v and lo < hi, without libm's calls. */
static double held(double v, double lo, double hi)
{
    return v < lo ? lo : v > hi ? hi : v;
}

/* Clips the segment to [xmin, xmax] x [ymin, ymax] (Liang-Barsky); false when nothing of
 * it is inside. */
static bool clip(double *x0, double *y0, double *x1, double *y1, double xmin, double xmax,
                 double ymin, double ymax)
{
    double dx = *x1 - *x0, dy = *y1 - *y0, t0 = 0.0, t1 = 1.0;
    const double p[4] = {-dx, dx, -dy, dy};
    const double q[4] = {*x0 - xmin, xmax - *x0, *y0 - ymin, ymax - *y0};
    for (int i = 0; i < 4; i++) {
        if (p[i] == 0.0) {
            if (q[i] < 0.0)
                return false;
            continue;
        }
        double r = q[i] / p[i];
        if (p[i] < 0.0) {
            if (r > t1)
                return false;
            if (r > t0)
                t0 = r;
        } else {
            if (r < t0)
                return false;
            if (r < t1)
                t1 = r;
        }
    }
    double ax = *x0, ay = *y0;
    *x0 = ax + t0 * dx, *y0 = ay + t0 * dy;
    *x1 = ax + t1 * dx, *y1 = ay + t1 * dy;
    return true;
}

/* The dot the last segment of a path ended on, drawn as its walk left it: a segment of
 * that one dot again would change nothing. */
struct pen {
    int x, y;
    bool at; /* false: no segment has ended on a known dot */
};

/* The segment between two points in dot coordinates (y from the top), clipped to the
 * canvas and drawn with Bresenham; dash leaves out columns as plot_trace does, run (if
 * not NULL) makes it a stroke of canvas_stroke's dashes. pen (if not NULL) is the dot
 * the path's last segment ended on: a segment of that dot alone is left out, since the
 * same dot in the same colour (on or off by the same run) was just set. */
static void segment(struct canvas *c, double fx0, double fy0, double fx1, double fy1, bool dash,
                    int *run, unsigned char color, struct pen *pen)
{
    /* Just inside the outer dots, so that rounding keeps the ends on the canvas. */
    double xmin = -0.5, xmax = 2 * c->cols - 0.5 - 1e-6, ymin = -0.5 + 1e-6,
           ymax = 4 * c->rows - 0.5;
    if (fx0 >= xmin && fx0 <= xmax && fx1 >= xmin && fx1 <= xmax && fy0 >= ymin &&
        fy0 <= ymax && fy1 >= ymin && fy1 <= ymax) {
        /* Both ends inside: clip would keep t0 = 0 and t1 = 1, its ends these. */
        fx1 = fx0 + (fx1 - fx0);
        fy1 = fy0 + (fy1 - fy0);
    } else if (!clip(&fx0, &fy0, &fx1, &fy1, xmin, xmax, ymin, ymax)) {
        return;
    }
    int x0 = dot_x(fx0), y0 = dot_y(fy0), x1 = dot_x(fx1), y1 = dot_y(fy1);
    if (pen) {
        if (pen->at && x0 == pen->x && y0 == pen->y && x1 == x0 && y1 == y0)
            return;
        *pen = (struct pen){x1, y1, true};
    }
    if (run)
        canvas_stroke(c, x0, y0, x1, y1, color, run);
    else
        canvas_dashed_line(c, x0, y0, x1, y1, color, dash);
}

/* One dot column of a trace: the span of its samples, its first and last sample. */
struct column {
    int x;         /* dot column */
    int lo, hi;    /* dot rows spanned, held to -1 .. h */
    double fx, fy; /* first sample, dot coordinates */
    double lx, ly; /* last sample */
};

/* Dots of a dashed trace on, then off, along its length. */
#define TRACE_DASH 4

/* Draws column k, joined to column p (the one before it, if have_p). Dashed, run counts
 * the dots along the trace (a step across one, each dot down one), and the dots are on
 * and off by TRACE_DASH along it, so a steep stretch is dashed along its length too. */
static void column_draw(struct canvas *c, struct column *k, const struct column *p, bool have_p,
                        bool dash, int *run, unsigned char color)
{
    int h = 4 * c->rows;
    if (have_p && p->x == k->x - 1) {
        /* Neighbours: this column's span reaches to the row next to the last one before,
         * so a line is continuous and a shallow one stays one dot thick. */
        int join = dot_y(held(p->ly, -1.0, (double)h));
        if (join < k->lo - 1)
            k->lo = join + 1;
        if (join > k->hi + 1)
            k->hi = join - 1;
    } else if (have_p) {
        segment(c, p->lx, p->ly, k->fx, k->fy, dash, NULL, color, NULL);
    }
    if (k->x < 0 || k->x >= 2 * c->cols)
        return;
    if (!dash) {
        canvas_vspan(c, k->x, k->lo, k->hi, color);
        return;
    }
    /* From the end next to where the trace came in, to the other. */
    bool up = have_p && p->ly > k->ly;
    for (int i = 0; i <= k->hi - k->lo; i++) {
        int y = up ? k->hi - i : k->lo + i;
        if (y >= 0 && y < h && (*run / TRACE_DASH) % 2 == 0)
            canvas_set(c, k->x, y, color);
        if (i < k->hi - k->lo)
            ++*run;
    }
    ++*run; /* the step across to the next column */
}

void plot_trace(struct canvas *c, const double *t, const double *y, int count, size_t stride,
                double t_ref, const struct axis *xa, const struct axis *ya, bool dash,
                unsigned char color)
{
    int w = 2 * c->cols, h = 4 * c->rows;
    struct column cur = {0}, prev = {0};
    bool have_cur = false, have_prev = false;
    int run = 0;
    /* The strokes keep every sample at full precision: pixels have room for them. */
    struct strokes *keep = c->mute ? NULL : c->strokes;
    if (keep)
        strokes_begin(keep, color, dash ? STROKE_DASHED : STROKE_LINE);
    c->mute++;
    for (int k = 0; k < count; k++) {
        double tk = t[(size_t)k * stride], yk = y[(size_t)k * stride];
        if (!isfinite(tk) || !isfinite(yk))
            continue;
        double fx = dot_clamp(axis_dot(xa, tk - t_ref));
        double fy = dot_clamp(h - 1 - axis_dot(ya, yk));
        if (keep)
            strokes_point(keep, fx, fy);
        /* Columns off the canvas are never drawn: all of them on a side share one. */
        int x = dot_x(held(fx, -2.0, w + 1.0));
        int r = dot_y(held(fy, -1.0, (double)h));
        if (!have_cur || x != cur.x) {
            if (have_cur) {
                column_draw(c, &cur, &prev, have_prev, dash, &run, color);
                prev = cur, have_prev = true;
            }
            cur = (struct column){x, r, r, fx, fy, fx, fy};
            have_cur = true;
        }
        if (r < cur.lo)
            cur.lo = r;
        if (r > cur.hi)
            cur.hi = r;
        cur.lx = fx, cur.ly = fy;
    }
    if (have_cur)
        column_draw(c, &cur, &prev, have_prev, dash, &run, color);
    c->mute--;
}

/* plot_path, solid (run NULL) or dashed along its length. */
static void path(struct canvas *c, const double *x, const double *y, int count, size_t stride,
                 const struct axis *xa, const struct axis *ya, int *run, unsigned char color)
{
    int h = 4 * c->rows;
    double px = 0.0, py = 0.0;
    bool have = false;
    struct pen pen = {0, 0, false};
    struct strokes *keep = c->mute ? NULL : c->strokes;
    if (keep)
        strokes_begin(keep, color, run ? STROKE_DASHED : STROKE_LINE);
    c->mute++;
    for (int k = 0; k < count; k++) {
        double xk = x[(size_t)k * stride], yk = y[(size_t)k * stride];
        if (!isfinite(xk) || !isfinite(yk)) {
            have = false;
            if (keep)
                strokes_point(keep, NAN, NAN);
            continue;
        }
        double fx = dot_clamp(axis_dot(xa, xk)), fy = dot_clamp(h - 1 - axis_dot(ya, yk));
        if (keep)
            strokes_point(keep, fx, fy);
        segment(c, have ? px : fx, have ? py : fy, fx, fy, false, run, color, &pen);
        px = fx, py = fy, have = true;
    }
    c->mute--;
}

void plot_path(struct canvas *c, const double *x, const double *y, int count, size_t stride,
               const struct axis *xa, const struct axis *ya, unsigned char color)
{
    path(c, x, y, count, stride, xa, ya, NULL, color);
}

void plot_dashed_path(struct canvas *c, const double *x, const double *y, int count,
                      size_t stride, const struct axis *xa, const struct axis *ya,
                      unsigned char color)
{
    int run = 0;
    path(c, x, y, count, stride, xa, ya, &run, color);
}
