/* figure.h: figures drawn with cairo: a page of stacked panels, each with axes (linear or
 * logarithmic, 1-2-5 ticks), gridlines, axis labels with units and series of points in the
 * masses' colours; a title and a legend. Written as PNG, SVG or PDF to a stream. No
 * curses here: --figure, the program's X and its pixel charts draw through it. */
#ifndef SPRINGSIM_FIGURE_H
#define SPRINGSIM_FIGURE_H

#include <stdbool.h>
#include <stddef.h>
#include <stdio.h>

/* The colours a figure knows, numbered as the terminal's colour pairs are (tui/term.h):
 * masses FIG_MASS + i (ten hues, repeating), the motor, gridlines, titles. */
enum fig_color {
    FIG_MASS = 1,
    FIG_MOTOR = 11,
    FIG_SPRING,
    FIG_GRID,
    FIG_TITLE,
    FIG_WARN,
    FIG_WALL,
    FIG_SELECT,
    FIG_COLOR_COUNT
};

/* File formats, chosen by a file name's extension. */
enum fig_format { FIG_FORMAT_NONE = -1, FIG_PNG, FIG_SVG, FIG_PDF };

#define FIG_PNG_SCALE 2.0 /* pixels a point in a PNG figure */

/* The format path's extension names (.png, .svg, .pdf, any case), or FIG_FORMAT_NONE. */
enum fig_format fig_format_of(const char *path);

/* The red, green and blue (0..1) of colour c on a dark or a light background. */
void fig_rgb(int c, bool dark, double rgb[3]);

/* One line of a panel: count points (x[k * stride], y[k * stride]); a point that is not
 * finite (or not positive on a log axis) breaks the line. */
struct fig_series {
    const double *x, *y;
    size_t stride;     /* doubles from one point to the next */
    int count;         /* points */
    int color;         /* an enum fig_color */
    bool dashed;       /* dashed (the motor, a ghost) */
    bool markers;      /* a small circle at every point, part of the same stroke */
};

/* One panel: axes, labels and lines. */
struct fig_panel {
    const char *xlabel, *ylabel;      /* with their units, e.g. "t (s)" */
    bool xlog, ylog;                  /* logarithmic axes */
    bool xfixed;                      /* x from xlo to xhi as given (rounded out to ticks) */
    double xlo, xhi;
    double ystep;                     /* > 0: y from ylo to yhi, ticks ystep apart */
    double ylo, yhi;
    const struct fig_series *series;
    int nseries;
};

/* One legend entry. */
struct fig_legend {
    const char *text;
    int color;
    bool dashed;
};

/* A page: title (and a second line of settings), legend, panels stacked top to bottom. */
struct fig_page {
    const char *title, *subtitle;
    const struct fig_legend *legend;
    int nlegend;
    const struct fig_panel *panels;
    int npanels;
    double width, height; /* points (PNG: FIG_PNG_SCALE pixels each) */
};

/* Draws page and writes it to fp in format f. Returns 0, or an errno value (ENOMEM, EIO,
 * or the stream's error). */
int fig_write(FILE *fp, enum fig_format f, const struct fig_page *page);

/* Frees what cairo and fontconfig keep between figures (their font caches), when no
 * figure is being drawn: before the program exits, so that leak checkers see none. */
void fig_done(void);

#endif
