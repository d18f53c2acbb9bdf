/* screen.h: the terminal program's state (what keys.c changes and tui.c draws and
 * paces), and the screen laid out for it. */
#ifndef SPRINGSIM_SCREEN_H
#define SPRINGSIM_SCREEN_H

#include <stdbool.h>

#include "../app/app.h"
#include "../app/clock.h"
#include "../chart/layout.h"
#include "../lab/record.h"
#include "../app/select.h"
#include "chart.h"
#include "graphics.h"
#include "overlay.h"
#include "plots.h"
#include "scene.h"
#include "teach.h"
#include "views.h"

struct tui {
    struct app app;
    struct layout layout;
    struct selection sel;
    struct scene scene;
    struct plots plots;
    struct views views;
    struct overlay overlay;
    int enlarged;         /* the plot enlarged, or -1 for the grid */
    double plot_due;      /* wall time of the next plot refresh */
    bool plots_dirty;     /* refresh the plots at the next frame */
    struct app_clock clock; /* simulated time following the wall clock */
    double backlog_since; /* wall time since when output has piled up unread at every
                           * frame (0: it does not) */
    double keeping_since; /* after a step down: since when the link has kept up (0: not) */
    double up_after;      /* seconds it must keep up before the refresh steps back up */
    bool stepped_down;    /* the low refresh is the program's own (a slow link), not the
                           * user's */
    bool dragging;        /* a mass is being dragged with the mouse */
    struct teach teach;   /* a lesson being played, its caption panel */
    struct record rec;    /* --record: the session being written */
    char said[64];        /* the command the key being handled stands for, or "" */
    struct graphics gfx;  /* the charts as images, where the terminal shows them */
    bool gfx_start;       /* its answers awaited are to the queries at start (--graphics) */
};

/* True while time cursors are shown on the plots: their keys come first. */
bool screen_cursors_shown(const struct tui *t);

/* Lays the screen out again for its size and what is shown; the plots refresh. */
void screen_relayout(struct tui *t);

/* Draws the charts (the plots, or the analysis view's) into curses' screen; with refresh,
 * from the data as it is now. */
void screen_draw_charts(struct tui *t, bool refresh);

/* The charts on the screen (the plots, or the analysis view's): into out (room for
 * GRAPHICS_SLOTS), how many; with images, the modes view's shapes too, which are drawn
 * as charts' areas are but are not charts in X's figure of the view. */
int screen_charts(struct tui *t, struct chart **out, bool images);

#endif
