/* axes.h: a figure's axes: the range, the ticks and their labels. Linear axes take 1-2-5
 * steps rounded outward (as the terminal's charts do); logarithmic axes span the data's
 * range and are labelled at 1, 2 and 5 of each decade (only the powers of ten where those
 * crowd, every digit or plain steps where the range lies within a decade). Every label of
 * an axis is in one notation: plain decimals, or all in exponent form. */
#ifndef SPRINGSIM_AXES_H
#define SPRINGSIM_AXES_H

#include <stdbool.h>
#include <stddef.h>

#define FIG_AXIS_TICKS 40 /* labelled ticks an axis has, at most */

struct fig_axis {
    bool log;                     /* logarithmic: lo and hi are log10 of the values */
    double lo, hi;                /* the axis's ends (log10 on a log axis) */
    double a, b;                  /* where lo and hi land on the page */
    int nt;                       /* labelled ticks */
    double tv[FIG_AXIS_TICKS];    /* their values (not log10) */
    bool sci;                     /* labels in exponent form */
    int dec;                      /* plain labels: digits after the point */
};

/* A linear axis over [lo, hi] (pad, a fraction of the span, added each side), its ends
 * rounded out to a 1-2-5 step giving at most max_ticks intervals; whole: ticks on whole
 * numbers only (a step of at least 1). An empty or one-value range is widened. */
void fig_axis_linear(struct fig_axis *x, double lo, double hi, double pad, int max_ticks,
                     bool whole);

/* A linear axis from lo to hi exactly, ticks at step from lo (the caller's round
 * numbers, e.g. phase from -180 to 180 every 90). */
void fig_axis_fixed(struct fig_axis *x, double lo, double hi, double step);

/* A logarithmic axis over [lo, hi] (both > 0; pad decades added each side), labelled as
 * the header says with at most max_ticks labels. */
void fig_axis_log(struct fig_axis *x, double lo, double hi, double pad, int max_ticks);

/* Page coordinate of value v (which must be positive on a log axis). */
double fig_axis_map(const struct fig_axis *x, double v);

/* Whether v can be drawn on x (finite; positive on a log axis). */
bool fig_axis_ok(const struct fig_axis *x, double v);

/* Tick value v's label, in the axis's notation. */
void fig_axis_label(const struct fig_axis *x, double v, char *buf, size_t len);

#endif
