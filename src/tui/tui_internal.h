/* tui_internal.h: what the terminal front end's files share: the screen state, colour
 * pairs and the small drawing helpers. Not for the core. */
#ifndef SPRINGSIM_TUI_INTERNAL_H
#define SPRINGSIM_TUI_INTERNAL_H

#include <stdbool.h>

#include <curses.h>

#include "../core/preset.h"
#include "../app/app.h"
#include "../app/braille.h"
#include "../app/plot.h"

/* Colour pairs. */
enum { PAIR_MASS = 1, PAIR_MOTOR = 11, PAIR_SPRING, PAIR_DIM, PAIR_TITLE, PAIR_WARN,
       PAIR_WALL, PAIR_SELECT, PAIR_COUNT };

struct rect {
    int y, x, h, w;
};

enum focus { FOCUS_CONTROLS, FOCUS_CHAIN };
enum overlay { OVERLAY_NONE, OVERLAY_HELP, OVERLAY_PRESETS, OVERLAY_EDIT, OVERLAY_CONFIRM };
enum view { VIEW_PLOTS, VIEW_MODES, VIEW_RESPONSE, VIEW_ENERGY };

/* What the text being typed is for. */
enum edit_target { EDIT_CONTROL, EDIT_MASS, EDIT_DAMPING, EDIT_SPRING, EDIT_SAVE };

struct plotview {
    const char *title;  /* centred on the top border */
    int xq, yq;         /* quantities: 0 time, 1 x, 2 v, 3 a */
    struct scale xs, ys; /* axis scales (xs unused for time plots) */
    struct canvas *canvas;
    struct rect r;       /* frame */
};

struct tui {
    struct app app;
    bool utf8;              /* braille and box drawing allowed */
    bool color;             /* colours in use */
    int rows, cols;         /* terminal size */
    bool too_small;         /* below MIN_COLS x MIN_ROWS */
    struct rect status, scene, controls, hints;
    struct plotview plots[6];
    struct canvas *scene_canvas;
    enum focus focus;
    int control;            /* selected control */
    int elem;               /* selected element in the chain: 2j spring j, 2i+1 mass i */
    enum overlay overlay;
    enum view view;         /* what the plot area shows */
    struct rect area;       /* the plot area */
    struct canvas *view_canvas; /* the analysis views' dots */
    struct scale view_ys;   /* the energy view's scale (the response view's decades) */
    double view_peak;       /* the energy view's largest kinetic or potential energy */
    enum edit_target edit_target;
    char save_name[256];    /* name waiting for the replace confirmation */
    struct preset_entry *presets; /* the menu's entries */
    int npresets, preset_sel;
    char edit[256];         /* text being typed */
    int edit_len;
    double plot_due;        /* wall time of the next plot refresh */
    bool plots_dirty;       /* redraw the plots at the next frame */
    bool behind;            /* the core could not keep up */
    int backlog_frames;     /* frames in a row with output piling up unread */
    bool dragging;          /* a mass is being dragged with the mouse */
    int scene_x0;           /* first column of the chain's metres */
    double scene_cpm;       /* columns per metre */
};

/* Line-drawing characters: the terminal's own where the locale is UTF-8, plain ASCII
 * otherwise. */
enum line { L_H, L_V, L_UL, L_UR, L_LL, L_LR, L_RTEE, L_TTEE };

/* Attribute for colour pair p (or a mono stand-in). */
attr_t tui_pair_attr(const struct tui *t, int p);

/* Attribute for mass i's colour. */
attr_t tui_mass_attr(const struct tui *t, int i);

/* Writes text s at (y, x). */
void tui_put(int y, int x, int w, const char *s);

/* Writes at most w columns of UTF-8 text s, spelled in ASCII outside UTF-8. */
void tui_putn(int y, int x, int w, const char *s);

/* tui_putn with printf formatting. */
void tui_printf(int y, int x, int w, const char *fmt, ...) __attribute__((format(printf, 4, 5)));

/* Columns that UTF-8 text s takes. */
int tui_text_width(const char *s);

/* A line-drawing character, ASCII outside UTF-8. */
chtype tui_line(enum line l);

/* A box with an optional title, near the left or centred. */
void tui_frame(const struct tui *t, struct rect r, const char *title, bool centre);

/* Draws a braille canvas with its top-left cell at (y, x). */
void tui_canvas(const struct tui *t, const struct canvas *c, int y, int x);

/* The selected mass in the chain, or -1 when a spring (or nothing) is selected. */
int tui_selected_mass(const struct tui *t);

/* Draws the analysis view chosen (modes, response, energy) over the plot area; with
 * refresh, recomputes what it shows first. */
void views_draw(struct tui *t, bool refresh);

#endif
