/* views.h: the analysis views that can take the plot area: the modes (view_modes.h),
 * the frequency response with its phase (view_response.h), the energy balance and the
 * spectrum (view_spectrum.h). Each view keeps its own state in its own struct. */
#ifndef SPRINGSIM_VIEWS_H
#define SPRINGSIM_VIEWS_H

#include <stdbool.h>

#include "../app/app.h"
#include "../chart/layout.h"
#include "../app/select.h"
#include "chart.h"
#include "view_modes.h"
#include "view_response.h"
#include "view_spectrum.h"

enum view { VIEW_PLOTS, VIEW_MODES, VIEW_RESPONSE, VIEW_ENERGY, VIEW_SPECTRUM };

struct energy_view {
    struct chart chart;
    double peak;        /* largest kinetic or potential energy in the window */
};

struct views {
    enum view shown;
    struct modes_view modes;
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
 * data (and the modes view's animation moves on). sel says the mode selected. */
void views_draw(struct views *v, const struct app *app, const struct selection *sel,
                bool refresh);

/* The charts of the view shown, for its picture (X): into out (room for max), how many;
 * 0 for the modes view, whose cells are not charts. */
int views_charts(struct views *v, struct chart **out, int max);

#endif
