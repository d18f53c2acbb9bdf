/* cost.h: what a step of the chain cost to compute, in mass-steps: the unit a lesson's
 * runs are bounded in (lab/lesson.h) and a recording ends at. */
#ifndef SPRINGSIM_COST_H
#define SPRINGSIM_COST_H

#include "../core/sim.h"

/* A sub-step of the exact integrator at a length of its own (a breakpoint of the drive,
 * a contact): a matrix exponential and the drive's solves, some 20 us a mass where a
 * step of rk4 takes some 40 ns (measured at N = 1 to 10). */
#define COST_EXACT_SUBSTEP 500.0

/* A change of the chain, the drive, dt or the integrator: its modes and the limits of dt
 * worked out anew (app.c's judge), some 150 us a mass where a step of rk4 takes some
 * 40 ns, counted a mass (measured at N = 1 to 10). */
#define COST_CHANGE 4000.0

/* The mass-steps of the step s has just taken: its masses, again for each sub-step at
 * the drive's breakpoints and each contact (COST_EXACT_SUBSTEP times that with the exact
 * integrator), and the drive's half-cycles in it (the contact events follow the motor's
 * gap through each): the steppers' and the events' work grows with them. */
double cost_last_step(const struct sim *s);

#endif
