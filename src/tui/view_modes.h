/* view_modes.h: the modes view, alive. Every natural mode of the chain in a cell of its
 * own: its shape drawn large and swinging at its own frequency (all slowed by one factor,
 * so their ratios stay true and the fastest can be followed), its frequency, damping
 * ratio, Q and -3 dB bandwidth, and a bar of its share of the energy of the motion now,
 * so "this is all mode 2" can be seen. The driven mode is marked; the selected one is
 * what Enter starts the chain in. */
#ifndef SPRINGSIM_VIEW_MODES_H
#define SPRINGSIM_VIEW_MODES_H

#include <stdbool.h>

#include "../app/app.h"
#include "../chart/braille.h"
#include "chart.h"

#define MODES_VIEW_FASTEST 0.6 /* the fastest mode swings at most this often on screen (Hz) */

struct modes_view {
    struct chart chart;       /* the frame (no axes) */
    struct chart cell[APP_MAX_MASSES]; /* each mode's shape: its area, canvas and strokes
                                        * (as an image where the charts are pixels) */
    double clock0;            /* wall time the animation counts from (s) */
    double shown_t;           /* the animation's time in the frame on screen (s, slowed) */
    double share[APP_MAX_MASSES]; /* each mode's share of the energy, as last refreshed */
    double total;             /* the modes' energy in all (J), as last refreshed */
};

/* Places the view in area; false on no memory. */
bool modes_view_place(struct modes_view *v, struct rect area);

/* Frees what it holds. */
void modes_view_free(struct modes_view *v);

/* The modes' shapes as last drawn, as charts without axes for images (tui/graphics.c):
 * into out, at most max; how many. */
int modes_view_cells(struct modes_view *v, struct chart **out, int max);

/* Draws it; with refresh, the animation moves on and the energies are taken anew.
 * selected is the mode Enter would start (-1: none). */
void modes_view_draw(struct modes_view *v, const struct app *app, int selected, bool refresh);

#endif
