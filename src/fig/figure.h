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

#define FIG_PAGE_SCALE (300.0 / 72.0) /* pixels a point in a report figure's PNG: 300 dpi */
#define FIG_MM (72.0 / 25.4)          /* points a millimetre */

/* The format path's extension names (.png, .svg, .pdf, any case), or FIG_FORMAT_NONE. */
enum fig_format fig_format_of(const char *path);

/* The colour of energy term i (kinetic, potential, dissipated, motor work, contact, and
 * the balance's error), as the energy view draws them. */
int fig_energy_color(int i);

/* The red, green and blue (0..1) of colour c on a dark or a light background: a report
 * figure's, and an image's where the terminal did not say its own. The motor is the
 * text's colour (as the terminal shows it: its foreground), black on paper. */
void fig_rgb(int c, bool dark, double rgb[3]);

/* The colours an image is drawn in: each fig_color's red, green and blue (0..1). */
struct fig_palette {
    double rgb[FIG_COLOR_COUNT][3];
};

/* fig_rgb's colours into p. */
void fig_palette_default(struct fig_palette *p, bool dark);

/* One line of a panel: count points (x[k * stride], y[k * stride]); a point that is not
 * finite (or not positive on a log axis) breaks the line. */
struct fig_series {
    const double *x, *y;
    size_t stride;     /* doubles from one point to the next */
    int count;         /* points */
    int color;         /* an enum fig_color */
    bool dashed;       /* dashed (the motor, a ghost) */
    bool markers;      /* a small circle at every point, part of the same stroke */
    bool no_line;      /* markers only (points measured), no line between them */
    bool vline;        /* a line across the whole panel at the first point's x (a
                        * frequency marked), not part of the data's range */
    double max_jump;   /* > 0: a step in y larger than this breaks the line (a phase that
                        * wraps at +-180, or turns faster than the points can follow) */
};

struct fig_legend;

#define FIG_MARK_LINES 12

/* A vertical line across a panel at x (a time cursor), dashed, with lines of text beside
 * it, each in its colour (the values read there). */
struct fig_mark {
    double x;
    int nlines;
    const char *line[FIG_MARK_LINES];
    int color[FIG_MARK_LINES];
};

/* One panel: axes, labels and lines, and a legend of its own under it (or none). */
struct fig_panel {
    const char *title;                /* over the panel, or NULL */
    const char *xlabel, *ylabel;      /* with their units, e.g. "t (s)" */
    bool xlog, ylog;                  /* logarithmic axes */
    bool xfixed;                      /* x from xlo to xhi as given (rounded out to ticks) */
    bool xexact;                      /* x from xlo to xhi exactly, ticks inside */
    bool xwhole;                      /* x ticks on whole numbers only (masses) */
    double xlo, xhi;
    double ystep;                     /* > 0: y from ylo to yhi, ticks ystep apart */
    double ylo, yhi;
    const struct fig_series *series;
    int nseries;
    const struct fig_legend *legend;  /* entries for this panel alone, or NULL */
    int nlegend;
    const struct fig_mark *marks;     /* cursors, or NULL */
    int nmarks;
};

/* One legend entry. */
struct fig_legend {
    const char *text;
    int color;
    bool dashed;
    bool dot;      /* a marker, not a stroke (points measured) */
    bool upright;  /* an upright stroke: a line across the panel at one x (the drive's
                    * frequency), told from a curve's level stroke */
};

/* A page: title (and the settings under it, wrapped), legend, panels stacked top to
 * bottom. */
struct fig_page {
    const char *title, *subtitle;
    const struct fig_legend *legend;
    int nlegend;
    const struct fig_panel *panels;
    int npanels;
    double width, height; /* points (PNG: FIG_PAGE_SCALE pixels each) */
};

/* Draws page and writes it to fp in format f. Returns 0, or an errno value (ENOMEM, EIO,
 * or the stream's error). */
int fig_write(FILE *fp, enum fig_format f, const struct fig_page *page);

/* Frees what cairo and fontconfig keep between figures (their font caches), when no
 * figure is being drawn: before the program exits, so that leak checkers see none. */
void fig_done(void);

#endif
