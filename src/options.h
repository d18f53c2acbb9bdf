/* options.h: reading the command line (springsim(1), OPTIONS). */
#ifndef SPRINGSIM_OPTIONS_H
#define SPRINGSIM_OPTIONS_H

#include <limits.h>
#include <stdbool.h>
#include <stdio.h>

#include "core/config.h"

#define EXIT_USAGE 2 /* a bad option, value or preset */

/* What the command line asks for. */
enum mode {
    MODE_INTERACTIVE,
    MODE_HEADLESS,
    MODE_MODES,
    MODE_SWEEP,
    MODE_SWEEP_RUN,
    MODE_LIST,
    MODE_PLAIN,
    MODE_LIST_LESSONS,
    MODE_BATCH
};

struct cli {
    enum mode mode;             /* what to do */
    const char *sweep;          /* --sweep or --sweep-run's FMIN:FMAX:COUNT */
    const char *sweep_dir;      /* --sweep-run's up or down */
    const char *batch;          /* --batch FILE|- */
    char preset_path[PATH_MAX]; /* the preset file applied, if any */
};

/* Reads argv into c (set up with config_init) and cli, loading a preset first.
 * Returns -1 to go on, or an exit status: 0 after --help, --version or --keys, 1 for
 * an unreadable preset, 2 for bad input (one line on standard error said why). */
int options_parse(int argc, char **argv, struct config *c, struct cli *cli,
                  const char *exe_dir);

/* Sends the error lines to f instead of standard error (NULL: back to it). */
void options_set_errors(FILE *f);

/* Names what every later line is about (a --batch row, "FILE:LINE"), or NULL for none. */
void options_set_context(const char *what);

/* One line on standard error, prefixed "springsim: " (and the context, if one is set). */
void options_say(const char *fmt, ...) __attribute__((format(printf, 1, 2)));

/* Flushes standard output after help-type output, and closes it if close (the program
 * is about to exit): EXIT_SUCCESS, or EXIT_FAILURE after "springsim: standard output:
 * REASON". options_parse flushes only, so the fuzz target can call it again. */
int options_finish_stdout(bool close);

/* Reports a bad value of key, naming where it came from: "--dt: why" on the command
 * line, "FILE:LINE: dt: why" from a preset. */
void options_report_key(const struct config *c, int key, const char *why);

#endif
