/* chart.h: the one chart widget: frame, title, axes, ticks, gridlines, legend and the
 * scan of a time window, drawn around a braille canvas. The six plots and every
 * analysis view are charts. */
#ifndef SPRINGSIM_CHART_H
#define SPRINGSIM_CHART_H

#include <stdbool.h>

#include "../chart/axis.h"
#include "../chart/braille.h"
#include "../chart/layout.h"
#include "../chart/plot_canvas.h"
#include "../chart/trail.h"
#include "../fig/view_picture.h"

#define CHART_MAX_TICKS 16

/* Where an axis's ticks are and what they say. */
struct chart_ticks {
    int n;
    int cell[CHART_MAX_TICKS];       /* from the axis's start: the left for x, the bottom for y */
    char label[CHART_MAX_TICKS][12]; /* at most AXIS_LABEL_MAX columns */
    bool kept;                       /* these are the ticks of axis `of` */
    struct axis of;                  /* so an axis laid as before is not labelled again */
};

/* One legend entry: text in a colour pair (a mass's, the motor's, ...). */
struct legend_item {
    const char *text;
    int pair;
};

struct chart {
    struct rect frame, area;   /* the frame, and the drawing area inside it */
    struct canvas *canvas;     /* the drawing area's dots */
    struct scale xs, ys;       /* autoscaling memory (grows at once, shrinks after a while) */
    bool still;                /* the data stands still (paused): the scales do not shrink */
    struct axis xa, ya;        /* the axes as last fitted */
    struct chart_ticks xt, yt; /* what the axes show */
    bool zero_line;            /* the y = 0 gridline drawn solid */
    /* What chart_draw drew last, for X's figure of the view and pixel output. */
    char title[160];           /* the title shown */
    char xunit[16];
    int nlegend;
    char legend[12][24];
    int legend_pair[12];
    bool drawn;                /* drawn with its axes */
    struct fig_report report;  /* what X's report figure says of it (chart_report) */
};

/* Places the chart in frame, header rows of text between the frame's top and the drawing
 * area; the canvas follows the size and the scales start afresh. Returns false on no
 * memory (the chart then draws its frame only). */
bool chart_place(struct chart *c, struct rect frame, int header_rows);

/* Charts' drawing areas as images (tui/graphics.c sends them): chart_draw leaves the
 * area blank (no braille, no gridline dots) for the image to show. */
void chart_use_pixels(bool on);

/* Whether the charts' strokes are kept for a report figure (X) from their next refresh on,
 * images or not. */
void chart_keep_for_figure(bool on);

/* Whether they are (what is drawn around a canvas of its own leaves it blank too). */
bool chart_pixels(void);

/* Frees the canvas. */
void chart_free(struct chart *c);

/* Fits the y axis to data in [lo, hi] (autoscaled, ticks evenly spaced on the rows). */
void chart_fit_y(struct chart *c, double lo, double hi);

/* As chart_fit_y, but the ticks laid inside the scale's range when that shows the data
 * larger (axis_fit_inside): for plots whose data may fill every row, the time plots. */
void chart_fit_y_inside(struct chart *c, double lo, double hi);

/* Fits the x axis to data in [lo, hi] (autoscaled, ticks evenly spaced on the columns). */
void chart_fit_x(struct chart *c, double lo, double hi);

/* Fits the x axis to a rolling time window in absolute time (axis_fit_rolling): the
 * window ending at end (s), the latest time on the last cell; 0 .. window until then. */
void chart_fit_time(struct chart *c, double end, double window);

/* The time at the left edge of a time chart's drawing area (s): a window's scan starts
 * there. */
double chart_left_time(const struct chart *c);

/* Fits the x (or y) axis to exactly [lo, hi] rounded out to its ticks, with no
 * autoscaling memory and no margin: an axis whose ends are chosen, not found in data. */
void chart_fix_x(struct chart *c, double lo, double hi);
void chart_fix_y(struct chart *c, double lo, double hi);

/* Ticks of axis a. */
void chart_ticks_from_axis(struct chart_ticks *t, const struct axis *a);

/* Canvas dot row (from the top) of y value v. */
int chart_dot_y(const struct chart *c, double v);

/* The same unrounded: where a stroke in pixels goes through. */
double chart_dot_yf(const struct chart *c, double v);

/* Draws the frame with title (short_title where the long one does not fit), the axes
 * with their ticks and labels (xunit at the left of the x labels), the gridlines, the
 * canvas and the legend on the bottom border; keeps the title, unit and legend shown. */
void chart_draw(struct chart *c, const char *title, const char *short_title,
                const char *xunit, const struct legend_item *legend, int nlegend);

/* What a report figure of the chart says (X): title, axis titles with units; the names
 * of its colours and its cursors emptied, for the view to give. */
void chart_report(struct chart *c, const char *title, const char *xlabel, const char *ylabel);

/* The chart as last drawn, for X's figure and the images: frame, area, ticks, title, legend
 * and the drawing's strokes. */
void chart_picture(const struct chart *c, struct fig_chart *out);

/* The window scan: the first record of tr at or after time t0 (records are in time
 * order); *count gets how many records follow from there, it included. */
const double *chart_window(const struct trail *tr, double t0, int *count);

#endif
