/* view_response.h: the frequency response view: each mass's steady-state amplitude
 * against the drive's frequency on log-log axes, and under it, on the same frequency
 * axis, its phase to the drive in degrees (a lag is negative), with the natural
 * frequencies and the drive marked and the sine-sweep experiment's measured amplitudes
 * and phases over the theory. */
#ifndef SPRINGSIM_VIEW_RESPONSE_H
#define SPRINGSIM_VIEW_RESPONSE_H

#include <stdbool.h>

#include "../app/app.h"
#include "../app/jump.h"
#include "../app/sweeping.h"
#include "chart.h"

#define RESPONSE_PHASE_MIN_ROWS 17 /* the view's height from which the phase panel shows */
#define RESPONSE_PHASE_ROWS 8      /* the phase panel's height at least (4 rows of data) */

/* The theory curves, solved again only when the chain or the width changes. */
struct response_view {
    struct chart chart;  /* amplitude */
    struct chart phase;  /* phase, below it; its frame is empty where there is no room */
    unsigned version;    /* app version the curves belong to (0: none) */
    int width;           /* dot columns they were solved for */
    double top;          /* the largest finite amplitude */
    double *curve;       /* width x N amplitudes (m) */
    double *phase_curve; /* width x N phases (degrees, (-180, 180]) */
    double drive_phase[APP_MAX_MASSES]; /* each mass's phase at the drive's frequency */
    bool drive_phase_ok; /* drive_phase[] was solved */
    struct sweep_plan plan; /* a sweep's plan, its contacts expected (scale INFINITY:
                             * none, or no sweep) */
    /* A chain with cubic springs (view_branches.c): */
    struct jump_theory hb; /* the harmonic-balance curve over the sweep's range */
    uint64_t hb_key;     /* the chain and drive it belongs to (jump_theory_key) */
    unsigned hb_version; /* app version it was last checked at (0: none) */
    bool hb_ok;          /* it was solved; else hb_why says why not */
    struct rect area;    /* the view's rectangle, as placed */
    bool merged;         /* the amplitude chart takes it all (view_branches.c, when low) */
    char hb_why[160];
};

/* Places the view in area; false on no memory. */
bool response_view_place(struct response_view *rv, struct rect area);

/* Frees what it holds. */
void response_view_free(struct response_view *rv);

/* Draws it; fresh redraws the curves from the newest data. */
void response_view_draw(struct response_view *rv, const struct app *app, bool fresh);

#endif
