/* run.h: the modes that write a file instead of drawing (springsim(1), MODES). Each returns
 * the exit status, having said on standard error what went wrong. */
#ifndef SPRINGSIM_RUN_H
#define SPRINGSIM_RUN_H

#include <stdbool.h>
#include <stdio.h>

#include "core/config.h"
#include "core/limits.h"
#include "core/model.h"

/* --headless: the run's CSV rows, or its --summary row (run_headless.c). */
int run_headless(const struct config *c, const struct model *m);

/* What dt is worth for a run of c on m: the stability and accuracy limits into *l
 * (core/limits.c). False when the modes cannot be computed (no memory, numbers that
 * overflow): the run goes on unjudged (run_headless.c). */
bool run_judge(const struct config *c, const struct model *m, struct limits *l);

/* The warnings about dt that l holds, one line each, before anything runs. */
void run_warn_limits(const struct limits *l, const struct model *m);

/* --summary's row for one run of c on m, written to fp after its header if header;
 * nothing written if the run fails (said on standard error). Returns the exit status. */
int run_summary(const struct config *c, const struct model *m, FILE *fp, bool header);

/* --batch FILE|-: one --summary row per row of the file, on top of base (run_batch.c). */
int run_batch(const struct config *base, const char *path);

/* --modes: the natural frequencies and shapes (run_tables.c). */
int run_modes(const struct config *c, const struct model *m);

/* --sweep FMIN:FMAX:COUNT, spec as given (run_tables.c). */
int run_sweep(const struct config *c, const struct model *m, const char *spec);

/* --sweep-run up|down FMIN:FMAX:COUNT, dir and spec as given (run_tables.c). */
int run_sweep_run_cli(const struct config *c, const struct model *m, const char *dir,
                      const char *spec);

/* --sweep on a chain with cubic springs: harmonic balance (run_nonlinear.c). */
int run_sweep_hb(const struct config *c, const struct model *m, double fmin, double fmax,
                 long count, const char *arg);

/* The simulated sweep up or down, each point from the last one's state (run_nonlinear.c);
 * arg is what --meta says was asked. */
int run_sweep_run(const struct config *c, const struct model *m, bool up, double fmin,
                  double fmax, long count, const char *arg);

#endif
