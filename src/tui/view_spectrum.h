/* view_spectrum.h: the spectrum view (key F): the amplitude spectrum in dB of one mass's
 * displacement over the last 60 s, Hann-windowed, against frequency in Hz, with the
 * natural frequencies and the drive's harmonics marked, and the ghost's spectrum dashed
 * when there is one. */
#ifndef SPRINGSIM_VIEW_SPECTRUM_H
#define SPRINGSIM_VIEW_SPECTRUM_H

#include <stdbool.h>

#include "../app/app.h"
#include "../chart/layout.h"
#include "../core/spectrum.h"
#include "chart.h"

#define SPECTRUM_VIEW_SECONDS 60.0 /* the span analysed: the longest time window */
#define SPECTRUM_VIEW_RANGE_DB 80.0 /* the axis shows this far below its top */

struct spectrum_view {
    struct chart chart;
    struct spectrum *fft; /* the transform, planned again only when its length changes */
    int size;             /* its length (0: none yet) */
    struct spectrum *ghost_fft; /* the ghost's, with its own length (its dt may differ) */
    int ghost_size;
    bool ghost_shown;     /* the canvas shows the ghost's spectrum too, dashed */
    int mass;             /* the mass to analyse: the last one selected in the chain */
    int shown;            /* the mass the canvas shows (-1: nothing computed) */
    double span;          /* seconds the samples shown cover */
    double top;           /* dB at the top of the axis */
    double peak_hz, peak_db; /* the highest level on the axis */
    bool no_memory;       /* the transform could not be made */
    bool still;           /* the mass has not moved: every level at the floor */
    double need;          /* seconds of record the axis needs, while there are fewer */
    bool since_ghost;     /* the ghost's record, younger than the live one, sets the span */
};

/* Places the view in the plot area; false on no memory. */
bool spectrum_view_place(struct spectrum_view *sv, struct rect area);

/* Frees what the view holds. */
void spectrum_view_free(struct spectrum_view *sv);

/* Draws the view; with fresh, it first takes the newest samples. */
void spectrum_view_draw(struct spectrum_view *sv, const struct app *app, bool fresh);

#endif
