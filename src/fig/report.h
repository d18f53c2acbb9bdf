/* report.h: the figures of --headless (displacement, velocity and acceleration against
 * time, the motor dashed), --modes (the shapes) and --sweep (amplitude log-log over
 * phase), from the rows the CSV gets. */
#ifndef SPRINGSIM_REPORT_H
#define SPRINGSIM_REPORT_H

#include <stdbool.h>
#include <stddef.h>
#include <stdio.h>

#include "core/config.h"
#include "core/model.h"
#include "core/sim.h"
#include "figure.h"

/* The energy terms a --headless --energy figure keeps: kinetic, potential, dissipated,
 * motor work, the force's work, contact, and the balance's error. */
#define REPORT_E_TERMS 7
#define REPORT_POINTS 2000000 /* (x, y) pairs a run's figure keeps in all, at most */

/* Series of rows kept for a figure: every row while they are few, else per bucket of
 * consecutive rows the one with the smallest and the one with the largest y of each
 * series (so an oscillation keeps its envelope), each a row the CSV has too. */
struct report_data;

/* Room for nseries series of rows (expected) rows: NULL on no memory. */
struct report_data *report_data_new(int nseries, double rows);

/* Adds one row: x, and y[s] for each series. */
void report_data_add(struct report_data *d, double x, const double *y);

/* Frees d. */
void report_data_free(struct report_data *d);

/* Rows a bucket takes: 1 while every row is kept. */
long report_data_bucket(const struct report_data *d);

/* After the last row: closes the last bucket and ends each series on the last row (the
 * figures call it). */
void report_data_finish(struct report_data *d);

/* The points kept of series s: (x, y) pairs at *xy; returns how many. */
int report_data_points(const struct report_data *d, int s, const double **xy);

/* How a figure looks beyond its data: its title (NULL: the one saying what it shows),
 * the settings under it, and its size (0: 160 mm wide, 100 mm high for one panel and 50
 * mm more for each panel stacked under it). */
struct report_look {
    const char *title;
    const char *subtitle;
    double w_mm, h_mm;
    const char *xfreq; /* a sweep's frequency axis title (NULL: the drive's) */
};

/* The look --figure, --figure-title and --figure-size ask for, with subtitle. */
struct report_look report_look_of(const struct config *c, const char *subtitle);

/* The settings of a run in one line, for a figure's second title line: the masses,
 * springs (cubic terms too), dampers to the ground and beside the springs, the right
 * end, the force and where it acts, the integrator. */
void report_settings(const struct config *c, const struct model *m, char *buf, size_t len);

/* The title of a frequency axis for m: what the frequency drives ("motor frequency f
 * (Hz)", "force frequency ...", or "drive frequency ..." for both). */
const char *report_frequency_label(const struct model *m);

/* Series a --headless figure's rows hold for n masses, with energy or not. */
int report_headless_series(int n, bool energy);

/* The figure's row for the state of s (accelerations a) into row (report_headless_series
 * doubles): x1..xN, v1..vN, a1..aN, motor and with energy the five terms and the
 * balance's change since the start (start_balance). */
void report_headless_row(const struct sim *s, const double *a, bool energy,
                         double start_balance, double *row);

/* A --headless figure from d (the rows above) over [t0, t_end]: the motor only where
 * it moves, the energy panel with energy. Returns 0 or an errno value. */
int report_headless(FILE *fp, enum fig_format f, struct report_data *d, int n, bool motor,
                    bool energy, double t0, double t_end, const struct report_look *look);

/* A --modes figure: the lowest modes' shapes (freq[j] Hz, shapes[j * n + i]) over the
 * masses, the left wall's zero (and the right end's, where it is fixed) included. */
int report_modes(FILE *fp, enum fig_format f, const struct model *m, const double *freq,
                 const double *shapes, const struct report_look *look);

/* A --sweep figure from d (series amp1..ampN, phase1..phaseN against frequency): the
 * phase's line broken where it wraps at +-180 or turns by more than 90 degrees between
 * two points. */
int report_sweep(FILE *fp, enum fig_format f, struct report_data *d, int n,
                 const struct report_look *look);

#endif
