/* progress.h: how far a long headless run has got, on standard error while it runs, for a
 * person at a terminal: nothing for a run that ends within a second, nothing when
 * standard error is not a terminal (a script, a pipe, a file), so the output a program
 * reads never changes. */
#ifndef SPRINGSIM_PROGRESS_H
#define SPRINGSIM_PROGRESS_H

#include <stdbool.h>
#include <stdio.h>

#define PROGRESS_AFTER 1.0  /* seconds of wall time before the line appears */
#define PROGRESS_EVERY 0.25 /* seconds of wall time between updates */

struct progress {
    FILE *out;        /* standard error when it is a terminal, else NULL */
    double start;     /* wall time at the start (s) */
    double last;      /* wall time of the last update, or 0 (s) */
    double end;       /* simulated time at the end of the run (s) */
    int width;        /* characters of the line last written */
};

/* Starts timing a run that ends at simulated time end (s). SPRINGSIM_PROGRESS=1 in the
 * environment shows the line even when standard error is not a terminal (the tests). */
void progress_start(struct progress *p, double end);

/* At simulated time t: the line "springsim: t = 3.2 of 10 s (32 %)" rewritten in place
 * (a carriage return) once the run has taken PROGRESS_AFTER, every PROGRESS_EVERY. */
void progress_tick(struct progress *p, double t);

/* Blanks the line, if one was written, so what comes next starts on a clean line. */
void progress_end(struct progress *p);

#endif
