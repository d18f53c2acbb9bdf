/* output.h: files written whole or not at all (a temporary file in the same
 * directory, renamed into place), and the CSV rows of --headless. */
#ifndef SPRINGSIM_OUTPUT_H
#define SPRINGSIM_OUTPUT_H

#include <stdbool.h>
#include <stdio.h>
#include <sys/types.h>

#include "sim.h"

struct output {
    FILE *fp;      /* where to write */
    char *tmp;     /* temporary name to rename from, or NULL when writing in place */
    char *path;    /* final path, or NULL for standard output */
    bool unnamed;  /* the file has no name until it is complete (O_TMPFILE) */
    uid_t owner;   /* the replaced file's owner and group, or -1: a new file */
    gid_t group;
};

/* Opens path for writing (NULL or "-": standard output). A regular file or a new one is
 * written through a temporary file in the same directory, unnamed where the system
 * allows (so even kill -9 leaves nothing behind); anything else (a device, a pipe) in
 * place.
 * Returns 0, or an errno value. */
int output_open(struct output *o, const char *path);

/* Finishes: flushes, and with commit renames the temporary file into place; without
 * commit (or on any error) the temporary file is removed and the old file stays.
 * Returns 0, or an errno value. */
int output_close(struct output *o, bool commit);

/* Gives the complete file being written (opened by output_open on a regular or new file)
 * the name path as well, never replacing anything there: path must not exist (a link
 * made exclusively, so of two programs racing for one name one gets it). path must be in
 * the directory output_open was given. Returns 0, EEXIST when path is taken (try another
 * name: the file stays open), or another errno value. Then output_close(o, false) drops
 * the temporary name and keeps path. */
int output_link_new(struct output *o, const char *path);

/* Removes the named temporary file of the output being written, if any: for a handler
 * of a terminating signal (async-signal-safe: unlink only). Where the system has unnamed
 * files (O_TMPFILE) there is nothing to remove until the last moment. */
void output_discard_pending(void);

/* The --headless CSV header for n masses. */
void output_csv_header(FILE *fp, int n, bool energy);

/* One --headless CSV row from values: t, x[n], v[n], a[n], u and, if energy is not
 * NULL, its six values (kinetic, potential, dissipated, motor work, contact, force work). */
void output_csv_values(FILE *fp, int n, double t, const double *x, const double *v,
                       const double *a, double u, const double *energy);

/* Whether the state of s, its accelerations (into scratch, n doubles) and its energy
 * books are all finite: what a --summary run checks where the CSV checks its rows. */
bool output_state_finite(const struct sim *s, double *scratch);

/* One --headless CSV row for the current state of s. scratch holds n doubles. Returns 0,
 * or -1 without writing anything when a value (an acceleration or an energy included)
 * is not finite: the CSV never holds inf or nan. */
int output_csv_row(FILE *fp, const struct sim *s, bool energy, double *scratch);

#endif
