/* record.h: --record FILE: what the user does, written as a lesson file that --replay
 * plays back to the same state bit for bit. It opens with the chain as it was (a setup
 * block: the settings in force, every number exact), then one line per command done (a
 * key of the interactive program in its plain-mode words, or a command typed; a preset
 * loaded as a setup block of the settings it put in force), each
 * preceded by `run SECONDS` for the simulated time that passed since the line before
 * and by `wait SECONDS` for the wall-clock time those runs do not account for (the chain
 * paused while the user looked), so that a replay in the program keeps the pace, and
 * ends with an `expect` line holding the state exactly. The file is opened at the start
 * as every output file is (core/output.h: a device or a FIFO written in place, a
 * symbolic link followed, a new file made with the umask, an old one keeping its mode)
 * and written whole at the end: never half-written, nothing left behind if the program
 * is killed. */
#ifndef SPRINGSIM_RECORD_H
#define SPRINGSIM_RECORD_H

#include <stdbool.h>
#include <stdio.h>

#include "../core/config.h"
#include "../core/output.h"

struct app;

#define RECORD_RUN_MAX 500.0 /* simulated seconds of one run line, at most */
#define RECORD_WAIT_MIN 0.05 /* wall seconds of idleness written as a wait line, at least */
#define RECORD_ROOM 16384    /* bytes kept free below a lesson's LESSON_MAX_BYTES: more than
                              * one key's lines (a setup block) and the expect line need */

/* The chain's settings just before a key, to tell what the key changed. */
struct record_mark {
    double t;                            /* the simulated time then */
    int n;                               /* masses */
    double dt, amplitude, frequency, speed;
    double pace;                         /* simulated seconds per wall second then */
    double window;                       /* the time plots' window (s) */
    bool running;                        /* whether the chain ran then */
    double force;                        /* the force input's amplitude (N) */
    int force_on;                        /* and its mass, 1-based as the settings hold it */
    int integrator, boundary, wave;
    bool low_bandwidth, sweeping;
    int graphics; /* the Graphics control (enum config_graphics) */
    struct config_list mass, damping, spring, spring_cubic, spring_damping; /* as the
                                           settings hold them */
    double m[CONFIG_INTERACTIVE_MAX_MASSES];  /* the values in force: the masses, */
    double c[CONFIG_INTERACTIVE_MAX_MASSES];  /* the dampers */
    double k[CONFIG_INTERACTIVE_MAX_MASSES + 1]; /* and the springs */
    double x[CONFIG_INTERACTIVE_MAX_MASSES];  /* the chain's displacements */
    double x0[CONFIG_INTERACTIVE_MAX_MASSES]; /* its initial ones */
    unsigned loads;                      /* presets loaded so far */
};

struct record {
    char path[4400];  /* the file written at the end */
    struct output out; /* open on it from the start */
    FILE *mem;        /* the text so far */
    char *text;       /* its buffer (open_memstream) */
    size_t size;      /* its bytes */
    double t;         /* the simulated time the text has reached */
    int lines;        /* commands written */
    double wall;      /* the wall clock (app_clock_now) at the last command written */
    double run_wall;  /* the wall seconds the runs written since took at their speed */
    double seconds;   /* the simulated seconds of the run lines written, all added */
    double work0;     /* the app's work (mass-steps) when the recording began */
    bool replay_runs; /* whether a replay's chain runs after the lines written (a start,
                       * a mode; a run line ends paused) */
    struct record_mark mark; /* before the key being handled (record_mark) */
};

/* Whether the recording is full: its runs and the time run since, with `ahead` more
 * simulated seconds, would pass the LESSON_MAX_SECONDS a lesson (and so a replay) may
 * run, or their steps the LESSON_MAX_WORK it may compute, or its text comes within
 * RECORD_ROOM of the LESSON_MAX_BYTES a lesson file may hold. The caller then finishes it
 * (record_full_finish), so that it always replays. */
bool record_full(const struct record *r, const struct app *app, double ahead);

/* Finishes a full recording now (record_finish) and says so through the app's message:
 * where it went, or why it could not be written. */
void record_full_finish(struct record *r, struct app *app);

/* Starts recording app, its chain as it is now, for path: 0, or -1 with "PATH: reason"
 * in err (path cannot be written: output_open's refusals). */
int record_start(struct record *r, const char *path, const struct app *app, char *err,
                 size_t errlen);

/* The simulated time run since the last line, as run lines (before a command; and while
 * running, whenever RECORD_RUN_MAX has passed). */
void record_time(struct record *r, const struct app *app);

/* A command done (a line of the plain mode, without its newline; record_time was called
 * before it was done); the recording is then at the chain's time. */
void record_line(struct record *r, const struct app *app, const char *line);

/* A command line of the plain mode done (its answer ok), recorded if its row says
 * (COMMAND_RECORDED): random with the seed it drew, a preset's name as typed, the rest
 * with their blanks made one. */
void record_command(struct record *r, const struct app *app, const char *line);

/* Before a key or a mouse event of the interactive program: what the chain is now. */
void record_mark(struct record *r, const struct app *app);

/* After it: cmd, the command the key stands for (start, step, mode 2, view modes, ...),
 * if it did something; or, for NULL, every setting it changed, as the commands that
 * change them the same way (set, element, place, preset), each after the time run before
 * the key. */
void record_changes(struct record *r, const struct app *app, const char *cmd);

/* Ends it: the time run, the expect line, the file written whole. 0, or -1 with "PATH:
 * reason" in err (the old file, if any, left as it was). */
int record_finish(struct record *r, const struct app *app, char *err, size_t errlen);

/* Gives it up: the temporary file removed, nothing written. */
void record_abandon(struct record *r);

#endif
