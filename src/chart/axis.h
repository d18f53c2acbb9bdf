/* axis.h: a plot axis laid on whole character cells: 1-2-5 ticks at exactly equal
 * spacing, values mapped linearly onto the dots of every cell, and tick labels that are
 * never cut. No curses here. */
#ifndef SPRINGSIM_AXIS_H
#define SPRINGSIM_AXIS_H

#include <stddef.h>

#define AXIS_LABEL_MAX 7 /* columns a tick label may take, at most */

/* An axis laid along `cells` character cells: tick k (k = 0..intervals) has value
 * lo + k*step and sits at cell first + k*spacing, counted from the axis's start (the
 * left for x, the BOTTOM for y). Values map linearly onto dots across ALL cells, so the
 * cells beyond the outer ticks show values beyond them, and every gap between ticks is
 * exactly `spacing` cells. */
struct axis {
    double lo, step; /* first tick's value, tick step (1, 2 or 5 x 10^k) */
    int intervals;   /* ticks - 1 (>= 1) */
    int first;       /* cell of tick 0 */
    int spacing;     /* cells between ticks (>= 1; >= min_spacing when the cells allow) */
    int cells, dpc;  /* cells along the axis, dots per cell (2 for x, 4 for y) */
};

/* The smallest 1-2-5 x 10^k step that puts at most max_ticks intervals on [lo, hi]. */
double axis_step(double lo, double hi, int max_ticks);

/* Widens [*lo, *hi] outward to multiples of step (gnuplot's axis ends). */
void axis_round_out(double *lo, double *hi, double step);

/* Lays [lo, hi] on `cells` cells of dpc dots, rounded outward to a 1-2-5 step with at
 * most max_ticks intervals (max_ticks + 1 when lo and hi are already on ticks, as a
 * struct scale's range is, so a scale is laid as it is). Ticks end up at least
 * min_spacing cells apart and their labels within AXIS_LABEL_MAX columns: if not, the
 * step is widened (1-2-5) and lo, hi rounded out again. Leftover cells are shared so the
 * ticks are centred. An axis too short for two ticks min_spacing apart gets the fewest
 * ticks the range allows, packed as far apart as the cells let them be. */
void axis_fit(struct axis *a, double lo, double hi, int max_ticks, int cells, int dpc,
              int min_spacing);

/* As axis_fit, but when ticks laid inside [lo, hi] (not rounded out to them: the range
 * shown is [lo, hi] with the leftover cells around it) show less than axis_fit's
 * rounded-out range, those: a short vertical axis then spends its rows on the data, not
 * on a tick step's rounding. At least two ticks, min_spacing cells apart. */
void axis_fit_inside(struct axis *a, double lo, double hi, int max_ticks, int cells, int dpc,
                     int min_spacing);

/* A rolling time axis in absolute time: the window [end - window, end] on the step and
 * spacing of [-window, 0] laid as axis_fit would but with its last tick on the last cell
 * (the leftover cells extending it to the left; the step widened while the absolute
 * labels do not fit), moved so that the last cell holds end (cells counted in whole cells from t = 0:
 * the axis moves a cell at a time) and the ticks are the multiples of the step on the
 * cells. Until time fills the axis, it starts at 0 (on the middle of its first cell). */
void axis_fit_rolling(struct axis *a, double end, double window, int max_ticks, int cells,
                      int dpc, int min_spacing);

/* Dot coordinate (fractional, from the axis start) of value v: tick k's value lands on
 * the middle of its cell, (first + k*spacing)*dpc + (dpc - 1)/2.0. Dot d covers
 * [d - 0.5, d + 0.5), so floor(axis_dot + 0.5) is the dot to set; the axis shows the
 * values from axis_value(a, -0.5) to axis_value(a, cells*dpc - 0.5). */
double axis_dot(const struct axis *a, double v);

/* The value at dot coordinate d: the inverse of axis_dot. */
double axis_value(const struct axis *a, double d);

/* Tick k's label, at most AXIS_LABEL_MAX columns, never cut, and on an axis from
 * axis_fit distinct from every other tick's: plain decimals with as many digits as the
 * step needs ("-0.25", "10", "-20000") where every label of the axis fits, else exponent
 * form with a mantissa of 1 to 9.x ("-2e4", "1.5e-5") for all of them. buf takes
 * AXIS_LABEL_MAX + 1 bytes. */
void axis_label(const struct axis *a, int k, char *buf, size_t len);

/* Widest tick label of the axis, in columns. */
int axis_label_width(const struct axis *a);

#endif
