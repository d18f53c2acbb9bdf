/* views.h: the analysis views that can take the plot area: the modes (every natural
 * frequency with its shape), the frequency response (theory on log-log axes with the
 * sine-sweep experiment's measured peaks over it), the energy balance and the spectrum
 * (view_spectrum.h). Each view keeps its own state here. */
#ifndef SPRINGSIM_VIEWS_H
#define SPRINGSIM_VIEWS_H

#include <stdbool.h>

#include "../app/app.h"
#include "../app/layout.h"
#include "chart.h"
#include "view_spectrum.h"

enum view { VIEW_PLOTS, VIEW_MODES, VIEW_RESPONSE, VIEW_ENERGY, VIEW_SPECTRUM };

/* The response view's theory curve, solved again only when the chain or the width
 * changes. */
struct response_view {
    struct chart chart;
    unsigned version;   /* app version the curve belongs to (0: none) */
    int width;          /* dot columns it was solved for */
    double top;         /* its largest finite amplitude */
    double *curve;      /* width x N amplitudes */
};

struct energy_view {
    struct chart chart;
    double peak;        /* largest kinetic or potential energy in the window */
};

struct views {
    enum view shown;
    struct chart modes;        /* the modes view's frame */
    struct response_view response;
    struct energy_view energy;
    struct spectrum_view spectrum; /* view_spectrum.c */
};

/* Places the views in the layout's plot area; false on no memory. */
bool views_place(struct views *v, const struct layout *l);

/* Frees what the views hold. */
void views_free(struct views *v);

/* Shows view w, or the plots again if w is already shown. */
void views_toggle(struct views *v, enum view w);

/* Draws the view shown (nothing for VIEW_PLOTS); with refresh, it first takes the newest
 * data. */
void views_draw(struct views *v, const struct app *app, bool refresh);

#endif
