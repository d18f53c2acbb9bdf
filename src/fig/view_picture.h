/* view_picture.h: a chart of the screen as fig/ takes it: its frame, ticks and legend in
 * cells, the strokes its drawing area was drawn with (painted sharp by pixels.c), and
 * what a report figure of it needs (view_report.c): its words, the values its dots stand
 * for, the names of its colours and its cursors. No curses here. */
#ifndef SPRINGSIM_VIEW_PICTURE_H
#define SPRINGSIM_VIEW_PICTURE_H

#include <stdbool.h>

#include "../chart/axis.h"
#include "../chart/strokes.h"
#include "figure.h"

#define FIG_VIEW_TICKS 16
#define FIG_VIEW_LEGEND 12
#define FIG_CURSORS 2

/* One axis's ticks: cells from the axis's start (x: the left, y: the bottom). */
struct fig_ticks {
    int n;
    int cell[FIG_VIEW_TICKS];
    char label[FIG_VIEW_TICKS][12];
};

/* A time cursor for a report figure: where it is and what it reads there. */
struct fig_cursor {
    double x;                          /* on the x axis (s) */
    int nlines;
    char line[FIG_MARK_LINES][40];     /* "t = 17.25 s", "x1 = 0.0312 m", ... */
    int color[FIG_MARK_LINES];
};

/* What a chart shows, in a report's words and values (empty words: no report of it). */
struct fig_report {
    char title[80];                    /* "Displacement": no key digit, no unit */
    char xlabel[48], ylabel[48];       /* with their units: "time t (s)" */
    char name[FIG_COLOR_COUNT][32];    /* what the curves of each colour are, or "" */
    bool time;                         /* x is time: the axis starts no earlier than 0 */
    bool xfreq;                        /* x dot d is the frequency fmin (fmax/fmin)^(d/(W-1))
                                        * (W the dots across), not the x axis's value */
    double fmin, fmax;
    bool ylog;                         /* the y axis's values are log10 of what is shown */
    bool branches;                     /* harmonic balance: the dashed lines its unstable
                                        * branches, the points two sweeps' (up larger) */
    double ylo, yhi, ystep;            /* ystep > 0: y from ylo to yhi, ticks ystep apart */
    int ncursors;
    struct fig_cursor cursor[FIG_CURSORS];
};

/* One chart as the terminal shows it. */
struct fig_chart {
    int x, y, w, h;          /* the frame, in cells */
    int ax, ay, aw, ah;      /* the drawing area inside it */
    char title[160];
    char xunit[16];          /* at the left of the x labels, or "" */
    struct fig_ticks xt, yt;
    bool axes;               /* ticks and gridlines drawn (false: a frame and its drawing) */
    int nlegend;
    char legend[FIG_VIEW_LEGEND][24];
    int legend_color[FIG_VIEW_LEGEND];
    const struct strokes *strokes; /* the drawing area's, or NULL */
    struct axis xa, ya;      /* the axes the strokes' dots were laid on */
    const struct fig_report *report; /* what a report figure says of it, or NULL */
};

#endif
