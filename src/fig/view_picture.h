/* view_picture.h: a picture of the charts on the screen, as the terminal lays them out (frames,
 * titles, tick labels, gridlines and legends in their cells) with their drawing areas
 * painted sharp from their strokes: what X in the program saves, as SVG and PNG. */
#ifndef SPRINGSIM_VIEW_PICTURE_H
#define SPRINGSIM_VIEW_PICTURE_H

#include <stdbool.h>
#include <stdio.h>

#include "../chart/strokes.h"
#include "figure.h"

#define FIG_VIEW_TICKS 16
#define FIG_VIEW_LEGEND 12
#define FIG_CELL_W 8.0  /* points a cell is wide in the picture */
#define FIG_CELL_H 16.0 /* and high */

/* One axis's ticks: cells from the axis's start (x: the left, y: the bottom). */
struct fig_ticks {
    int n;
    int cell[FIG_VIEW_TICKS];
    char label[FIG_VIEW_TICKS][12];
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
};

/* Writes the n charts as one picture (the box around them) to fp in format f (PNG: 2
 * pixels a point). Returns 0 or an errno value. */
int fig_view_write(FILE *fp, enum fig_format f, const struct fig_chart *c, int n);

#endif
