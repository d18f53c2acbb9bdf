/* plot_canvas.h: what a plot needs that is not drawing: autoscaling that grows at once and
 * shrinks only after a while, and series rasterised onto a braille canvas on axes
 * (min-max per dot column). No curses here. */
#ifndef SPRINGSIM_PLOT_CANVAS_H
#define SPRINGSIM_PLOT_CANVAS_H

#include <stdbool.h>
#include <stddef.h>

#include "axis.h"
#include "braille.h"

/* An axis range kept on tick multiples. */
struct scale {
    double lo, hi;   /* shown range */
    double step;     /* tick step */
    int quiet;       /* updates in a row that the data would fit a much smaller range */
    bool set;        /* has a range */
    bool fitted;     /* the range came from data that was not flat */
};

/* Updates s with the data's range [dmin, dmax]: grows at once to cover it, shrinks to
 * a range less than half as wide only after shrink_after quiet updates. */
void plot_scale_update(struct scale *s, double dmin, double dmax, int max_ticks,
                       int shrink_after);

/* Rasterises y(t) onto c on axes: each dot column shows the span from the smallest to the
 * largest sample in it, joined to the neighbouring columns, so fast oscillations draw as
 * a band. t is mapped by xa after subtracting t_ref (a rolling window passes t_ref = now),
 * y by ya (its dots counted from the canvas's bottom). Samples off the canvas are not
 * drawn but still join to those on it. With dash, every other pair of columns is left
 * out. Samples are in time order; stride steps through interleaved data; samples that
 * are not finite are skipped. */
void plot_trace(struct canvas *c, const double *t, const double *y, int count, size_t stride,
                double t_ref, const struct axis *xa, const struct axis *ya, bool dash,
                unsigned char color);

/* Rasterises the path (x_k, y_k) as joined segments onto c, x by xa, y by ya, clipped
 * to the canvas; a sample that is not finite breaks the path. */
void plot_path(struct canvas *c, const double *x, const double *y, int count, size_t stride,
               const struct axis *xa, const struct axis *ya, unsigned char color);

/* plot_path in dashes along its length (canvas_stroke), for a second trace drawn beside a
 * solid one. */
void plot_dashed_path(struct canvas *c, const double *x, const double *y, int count,
                      size_t stride, const struct axis *xa, const struct axis *ya,
                      unsigned char color);

#endif
