/* clock.h: simulated time following the wall clock at the Speed control's rate, the one
 * way both front ends (tui/, plain/) play the chain while it runs. */
#ifndef SPRINGSIM_CLOCK_H
#define SPRINGSIM_CLOCK_H

#include <stdbool.h>

struct app;

struct app_clock {
    double debt;  /* simulated seconds the chain owes the clock (less than a step, but
                   * for a chain that cannot keep up) */
    bool behind;  /* the last catch-up ran out of time with more than two steps owed */
};

/* Simulated seconds per wall second: the Speed control's rate, APP_SWEEP_PACE times
 * that while a sweep runs. */
double app_clock_pace(const struct app *app);

/* Wall-clock seconds from a fixed start (monotonic). */
double app_clock_now(void);

/* Brings app's simulated time up to `elapsed` more wall seconds times its pace, a step
 * of dt at a time through step(ctx) (app_step when step is NULL; false stops: a blow-up,
 * or the caller wants to stop). Spends at most `budget` wall seconds: past it the chain
 * falls behind the clock (behind says so when more than two steps are owed) and a debt
 * of more than a quarter second of playback is let go rather than caught up later.
 * While paused the debt is let go. */
void app_clock_follow(struct app_clock *c, struct app *app, double elapsed, double budget,
                      bool (*step)(void *ctx), void *ctx);

#endif
