/* run_files.h: the files the file-writing modes share (run_files.c). */
#ifndef SPRINGSIM_RUN_FILES_H
#define SPRINGSIM_RUN_FILES_H

#include <stdio.h>

#include "core/config.h"
#include "core/output.h"

/* Catches SIGINT, SIGTERM and SIGHUP so that a temporary file is removed before the
 * program dies of the signal (signals already ignored stay ignored). */
void run_catch_terminate(void);

/* Opens -o's file (or standard output): 0, or EXIT_FAILURE after "PATH: REASON". */
int run_open_output(struct output *o, const struct config *c);

/* Closes it, renaming it into place when status is EXIT_SUCCESS; returns the status,
 * EXIT_FAILURE after "PATH: REASON" when the close failed. */
int run_close_output(struct output *o, const struct config *c, int status);

/* --figure's file, opened before any work: 0 (also without --figure), or EXIT_FAILURE
 * after "PATH: REASON". */
int run_open_figure(struct output *o, const struct config *c);

/* Finishes the figure: draw is 0 or the errno value drawing it gave; renamed into place
 * when the run succeeded, discarded otherwise. Returns the status. */
int run_close_figure(struct output *o, const struct config *c, int draw, int status);

/* --meta's '#' lines for a run of the given mode (and its argument, or NULL). */
void run_write_meta(FILE *fp, const struct config *c, const char *mode, const char *arg);

#endif
