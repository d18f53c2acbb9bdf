/* scope_text.h: the scope's readout and measurements in words, for the plain mode's
 * `cursor T` and `measure`, and the numbers the terminal's readout panel shows. */
#ifndef SPRINGSIM_SCOPE_TEXT_H
#define SPRINGSIM_SCOPE_TEXT_H

#include <stdbool.h>
#include <stddef.h>

#include "measure.h"

struct app;
struct scope_view;
struct scope_motion;

/* v in at most width columns, with as many significant digits as fit (6 at most, 2 at
 * least: "%.*g"); NAN as "-". Returns the digits used. */
int scope_number(char *buf, size_t len, double v, int width);

/* `cursor T`: every mass's x, v, a and the motor at the recorded sample nearest to
 * time text (the CSV's digits). false, with what was wrong and what is allowed, when T
 * is not a number or not recorded. */
bool scope_say_cursor(const struct app *app, const char *text, char *buf, size_t len);

/* `measure [MASS]`: the measurements of mass text (empty: the one last measured) over
 * the time plots' window. false, with what is allowed, for a mass the chain has not. */
bool scope_say_measure(struct app *app, const char *text, char *buf, size_t len);

/* The kind of motion in words: "free decay", "driven steady state", "transient", ... */
const char *scope_motion_name(const struct scope_motion *sm);

/* How the peaks went: "peaks growing", "peaks falling" or "peaks uneven". */
const char *scope_peaks_word(const struct measure *m);

#endif
