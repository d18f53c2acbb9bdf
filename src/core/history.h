/* history.h: a ring buffer of saved simulation states, for stepping back. */
#ifndef SPRINGSIM_HISTORY_H
#define SPRINGSIM_HISTORY_H

#include "sim.h"

#define HISTORY_DEPTH 500 /* states kept, as on the page */

struct history;

/* A history of up to capacity states of simulations shaped like s; NULL on no memory. */
struct history *history_new(const struct sim *s, int capacity);

/* Frees a history. */
void history_free(struct history *h);

/* Saves the state of s, dropping the oldest when full. */
void history_push(struct history *h, const struct sim *s);

/* Restores the newest saved state into s and drops it; returns 0, or -1 when empty. */
int history_pop(struct history *h, struct sim *s);

/* Number of states saved. */
int history_count(const struct history *h);

/* Drops every saved state. */
void history_clear(struct history *h);

#endif
