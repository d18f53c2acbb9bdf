/* app_fixture.h: what test_app.c and test_app_rules.c share (tests/app_fixture.c): the
 * one app under test, a fresh one per test, and the chain's allocations and the modes'
 * computations watched. Both programs are linked with --wrap for those (the Makefile's
 * APP_WRAPPED); the wrappers live in app_fixture.c. */
#ifndef SPRINGSIM_APP_FIXTURE_H
#define SPRINGSIM_APP_FIXTURE_H

#include "testutil.h"

#include "app/app.h"

extern struct app app;    /* the app under test */
extern struct config cfg; /* what setup built it from: three masses at 0.9 Hz */

extern int modes_calls; /* modes_compute calls since they were last zeroed */
extern int limit_calls; /* limits_modes calls since they were last zeroed */

/* Makes the k-th wrapped allocation from now fail (0: none). */
void fail_allocation(int k);

/* A fresh app of three masses driven at 0.9 Hz (no mode of theirs), counters zeroed. */
int setup(void **state);

/* Frees it, and no allocation is set to fail. */
int teardown(void **state);

/* Runs n steps, each of which must succeed. */
void run(int n);

/* Starts a sweep, paused, and checks it took the drive. */
void start_sweep(void);

/* The drive in force, checked to be the same for the app, its settings and the sim. */
double drive_frequency(void);

/* Five masses by the Masses control and Enter. */
unsigned new_n(void);

/* Loads presets/3-mass-chain.ini. */
unsigned preset(void);

/* Loads the preset text (INI) as name, from a temporary file removed after. */
unsigned preset_text(const char *name, const char *text);

#endif
