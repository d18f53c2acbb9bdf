/* summary.h: the one-row summary of a headless run (--summary), for parameter studies:
 * the settings a study varies, then per mass the largest |x|, the rms of x over the last
 * half of the run and the largest |v|, then the contacts and the energy books. Rows of
 * runs with the same N share one header, so they concatenate into one table. */
#ifndef SPRINGSIM_SUMMARY_H
#define SPRINGSIM_SUMMARY_H

#include <stdio.h>

#include "sim.h"

struct summary;

/* An empty summary for n masses, or NULL on no memory. */
struct summary *summary_new(int n);

/* Frees a summary. */
void summary_free(struct summary *s);

/* Takes in the state of sim after step `step` of a run of `total` steps (step 0: the
 * state it starts from): the peaks, the rms over the steps with t > T/2 (the only state
 * of a run of no steps), and the contacts the step resolved (the cap's clamps apart). */
void summary_add(struct summary *s, const struct sim *sim, double step, double total);

/* The header for n masses: masses,mass,spring,damping,frequency,amplitude,wave,dt,
 * integrator, max_abs_x1..N, rms_x1..N, max_abs_v1..N, contacts,dissipated,motor_work. */
void summary_header(FILE *fp, int n);

/* The row: the settings of sim's model as the command line spells them (a list is one
 * value when all its values are equal, else every value, comma-separated inside double
 * quotes), then the figures taken in and sim's energy books now. */
void summary_row(FILE *fp, const struct summary *s, const struct sim *sim);

/* The figures, for tests: contacts counted, and mass i's largest |x|, rms x and
 * largest |v|. */
double summary_contacts(const struct summary *s);
void summary_mass(const struct summary *s, int i, double *max_x, double *rms_x, double *max_v);

#endif
