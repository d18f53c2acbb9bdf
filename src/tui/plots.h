/* plots.h: the six live plots (x, v, a against time; x-v, x-a, v-a), as many as the
 * layout shows, each a chart. */
#ifndef SPRINGSIM_PLOTS_H
#define SPRINGSIM_PLOTS_H

#include <stdbool.h>

#include <curses.h>

#include "../app/app.h"
#include "../chart/layout.h"
#include "chart.h"

struct plots {
    struct chart chart[PLOT_COUNT]; /* one per plot, placed when shown */
    /* Each mass's newest point at the last refresh, as a cell of the plot's area (row,
     * column), or -1: where its digit goes when the colours do not tell the masses
     * apart. */
    int end_row[PLOT_COUNT][10], end_col[PLOT_COUNT][10];
    unsigned hidden; /* bit i: mass i's curves left out of the plots (v) */
    int top;         /* the mass drawn last, over the others (the chain's selected), or -1 */
    /* The plots' frames as the last refresh drew them, copied back by the frames in
     * between (which would draw the same again): where, and laid out how. */
    WINDOW *kept;
    bool kept_ok;                 /* kept holds the kept_n plots below */
    struct rect kept_plot[PLOT_COUNT];
    enum plot_id kept_id[PLOT_COUNT];
    int kept_n;
};

/* Shows or hides mass i's curves (key v on a mass of the chain); what the message says. */
void plots_toggle_mass(struct plots *p, struct app *app, int i);

/* Places the plots the layout shows; false on no memory. */
bool plots_place(struct plots *p, const struct layout *l);

/* Forgets the scales: the next refresh fits every axis to its data alone. */
void plots_refit(struct plots *p);

/* Frees the canvases and the copy of the frames. */
void plots_free(struct plots *p);

/* Draws the plots shown; with refresh, they first take the newest samples. Without,
 * the plots are as the last refresh drew them (every key makes one) and are copied back
 * as they were. */
void plots_draw(struct plots *p, const struct layout *l, const struct app *app, bool refresh);

/* The title of plot id (its key first), long or short, UTF-8. */
const char *plots_title(enum plot_id id, bool short_form);

#endif
