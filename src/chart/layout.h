/* layout.h: every rectangle of the interactive screen and the scene's metres-to-columns
 * mapping, computed from the terminal's size and what is shown, with no curses: drawing
 * and mouse hit-testing both read it, and nothing else decides where things are. */
#ifndef SPRINGSIM_LAYOUT_H
#define SPRINGSIM_LAYOUT_H

#include <stdbool.h>

#define LAYOUT_MIN_COLS 60 /* below this size only a message is shown */
#define LAYOUT_MIN_ROWS 20
#define LAYOUT_LABEL_COLS 8 /* a chart's y tick labels (7) and its axis line (1) */
#define LAYOUT_XAXIS_ROWS 2 /* a chart's x axis line and its labels */
#define LAYOUT_MIN_PLOT_W 16 /* a grid plot's drawing area must be at least this big */
#define LAYOUT_MIN_PLOT_H 5
#define LAYOUT_SCENE_SPAN 13.0 /* metres the scene shows: 0 .. L + the motor's largest stroke */
#define LAYOUT_WALL_COLS 2     /* the left wall */
#define LAYOUT_HOUSE_COLS 9    /* the motor housing */

struct rect {
    int y, x, h, w;
};

/* The six plots, in the order of the keys 1 to 6. */
enum plot_id { PLOT_X, PLOT_V, PLOT_A, PLOT_XV, PLOT_XA, PLOT_VA, PLOT_COUNT };

struct layout {
    int cols, rows;             /* terminal size */
    bool too_small;             /* below LAYOUT_MIN_COLS x LAYOUT_MIN_ROWS: nothing else set */
    struct rect status, scene, area, controls, hints;
    struct rect caption;        /* a lesson's caption panel (h 0: none) */
    int nplots;                 /* plots on screen (0 while an analysis view has the area) */
    enum plot_id plot_id[PLOT_COUNT]; /* which plot each shown one is */
    struct rect plot[PLOT_COUNT];     /* their frames */
    int scene_x0;               /* column of the left wall's face (x = 0 m) */
    double scene_cpm;           /* scene columns per metre */
};

/* Lays out a cols x rows screen. enlarged is the plot that takes the whole plot area, or
 * -1 for the grid; view is true when an analysis view takes the plot area. */
void layout_compute(struct layout *l, int cols, int rows, int enlarged, bool view);

/* With time cursors shown on the plots: the controls' column, wider, holds the cursors'
 * readout instead, and the plots take what is left (call after layout_compute). */
void layout_scope(struct layout *l, int enlarged);

/* Rows a lesson's caption panel takes on a screen of rows (with its frame): 7, 8 or 9. */
int layout_caption_rows(int rows);

/* Takes rows (layout_caption_rows) across the whole width from the bottom of the plot
 * area and the controls for a lesson's caption panel, so that it covers neither the plots
 * nor the controls, and lays the plots out again in what is left (enlarged and view as
 * layout_compute takes them). */
void layout_caption(struct layout *l, int rows, int enlarged, bool view);

/* The drawing area inside a chart's frame: right of the tick labels, above the x axis. */
struct rect layout_drawing(struct rect frame);

/* Fractional column of physical position X (m) in the scene. */
double layout_scene_col(const struct layout *l, double X);

/* Physical position (m) at the centre of scene column col. */
double layout_scene_metres(const struct layout *l, int col);

/* The rows of the controls' frame the list of ncontrols takes: the whole list where it
 * fits with two rows to spare (the frequency bar, the natural frequencies), else all but
 * those two rows where that hides three controls at most (80x24: the list scrolls, the
 * bar and the frequencies stay), else as many as there are rows (60x20). */
int layout_control_rows(const struct layout *l, int ncontrols);

/* The control drawn at screen cell (y, x), the list shown from control top, or -1. */
int layout_control_at(const struct layout *l, int y, int x, int ncontrols, int top);

/* True when (y, x) is inside r. */
bool rect_contains(struct rect r, int y, int x);

#endif
