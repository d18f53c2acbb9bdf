/* lesson.h: lessons, plain-text files of steps (man springsim, LESSONS): a caption
 * (`say`), the plain mode's commands that set the scene, and a `pause` or an `ask` with
 * its choices ending each step. They are found like presets (core/search.h), read and
 * checked line by line here, and every command is tried on a scratch chain before
 * anything runs (lesson_check), so a bad lesson is refused with its file and line. The
 * front ends play them item by item (lesson_next), each command through the one path of
 * the plain mode's commands (command.h). --record writes the same format. */
#ifndef SPRINGSIM_LESSON_H
#define SPRINGSIM_LESSON_H

#include <stdbool.h>
#include <stddef.h>

#include "../core/config.h"
#include "../core/search.h"

#define LESSON_EXT ".lesson"          /* a lesson file's name ends so */
#define LESSON_MAX_BYTES (256 * 1024) /* larger files are refused */
#define LESSON_MAX_LINE 1024          /* longest line */
#define LESSON_MAX_CHOICES 6          /* choices of one question, at most */
#define LESSON_CAPTION 2048           /* bytes of one step's caption */
#define LESSON_MAX_SECONDS 1800.0     /* simulated seconds of all a lesson's runs, at most
                                       * (and LESSON_MAX_WORK below: the check and every
                                       * run done at once stop on Esc, q or Ctrl+C) */
#define LESSON_MAX_WORK 3.6e7         /* mass-steps of all its runs, at most (app.h's
                                       * work, app/cost.h: each step's masses, again for
                                       * each of a drive's sub-steps and each contact,
                                       * and the drive's half-cycles): twice ten masses'
                                       * 1800 s at dt 0.001 (a check of about 1.5 s), so
                                       * that no lesson's check or step back takes more
                                       * than a few seconds, whatever its chain */
#define LESSON_MAX_WAIT 600.0         /* wall seconds of one wait line, at most */

struct app;

/* What one item of a lesson is. */
enum lesson_kind {
    LESSON_SAY,     /* a line of the step's caption */
    LESSON_COMMAND, /* a command of the plain mode */
    LESSON_PAUSE,   /* the end of a step: wait for the user */
    LESSON_ASK,     /* the end of a step: a question, its choices, wait for an answer */
    LESSON_SETUP,   /* a chain given in the lesson itself, as a preset's text */
    LESSON_EXPECT,  /* the state the lesson must end in, exactly (a recording's last line) */
    LESSON_WAIT,    /* wall seconds the interactive program waits (a recording's pauses);
                     * text the number, value it read */
};

struct lesson_item {
    enum lesson_kind kind;
    int line;                             /* where it is in the file */
    char *text;                           /* caption, command, question, preset, state */
    int nchoices;                         /* ask: its choices */
    char *choice[LESSON_MAX_CHOICES];     /* ask: their text */
    int answer;                           /* ask: the right choice, 1-based, or 0 */
    double value;                         /* wait: its seconds */
};

struct lesson {
    char path[4400];           /* its file */
    char name[256];            /* the word --lesson takes, or the file's name */
    char title[200];           /* its title line */
    struct lesson_item *items; /* in order */
    int count;                 /* items */
    int steps;                 /* pauses and questions */
    double seconds;            /* simulated seconds of all its runs */
};

/* Reads and checks the lesson at path (its lines' form, every command's name): 0, 1 when
 * it cannot be read ("PATH: reason" in err), 2 when it is not a valid lesson
 * ("PATH:LINE: what is wrong"). l is then empty (lesson_free is still safe). */
int lesson_read(const char *path, struct lesson *l, char *err, size_t errlen);

/* Frees what l holds. */
void lesson_free(struct lesson *l);

/* The file a lesson name or path stands for (a value with a '/' or ending in .lesson is
 * a path; a name is looked for on the search path): 0 with the path in out, or -1 with
 * a message in out. */
int lesson_find(const char *name, const char *exe_dir, char *out, size_t len);

/* Every lesson on the search path (search_scan: sorted by name, each name once, the first
 * found shadowing later ones), each one's about its title with control bytes made
 * spaces; *out is malloc'ed (free it); returns the count. */
int lesson_scan(const char *exe_dir, struct search_entry **out);

/* A way to leave a long computation: fn(ctx) is asked every LESSON_POLL wall seconds
 * and true stops it (a key, a signal). A NULL one never stops. */
struct lesson_stop {
    bool (*fn)(void *ctx);
    void *ctx;
    bool said; /* fn said to stop */
};

#define LESSON_POLL 0.05 /* wall seconds between two questions to a lesson_stop */
#define LESSON_LEFT 3    /* lesson_check's status when its stop said so */

/* Plays every item of l on a scratch chain made from base (commands through command_do,
 * runs stepped at once): 0, or 2 with "PATH:LINE: what is wrong" in err (the command's
 * own answer), 1 on no memory, LESSON_LEFT when
 * stop said to (err says so). Nothing is shown or written. */
int lesson_check(const struct lesson *l, const struct config *base, const char *exe_dir,
                 struct lesson_stop *stop, char *err, size_t errlen);

/* Steps app for `seconds` of simulated time at once, then pauses it, as the plain
 * mode's `run` does; false when a blow-up stopped it. */
bool lesson_run(struct app *app, double seconds);

/* Steps app at once up to simulated time `end` (the steps lesson_run would take from
 * here), then pauses it; false when a blow-up or stop (may be NULL) ended it first. */
bool lesson_run_to(struct app *app, double end, struct lesson_stop *stop);

/* Whether app has reached simulated time `end` of a run (no step of lesson_run_to left):
 * a run played step by step ends there, bit for bit where lesson_run_to ends. */
bool lesson_run_over(const struct app *app, double end);

/* The chain's state exactly, "t=HEX x1=HEX v1=HEX ..." in C99 hexadecimal floats, as
 * an expect line holds it. */
void lesson_state(const struct app *app, char *buf, size_t len);

/* Whether the chain's state is the one text (an expect line's, as lesson_state writes it)
 * holds, bit for bit: the same masses, each number the same double, however it is
 * written (0 and 0x0p+0 are one; -0 and 0 are not). */
bool lesson_state_is(const struct app *app, const char *text);

/* Puts a setup item's chain in force on app; 0, or -1 with the reason in app's message. */
int lesson_setup(struct app *app, const struct lesson *l, const struct lesson_item *it);

/* Where a lesson being played is. */
struct lesson_play {
    const struct lesson *lesson;
    int next;                       /* the item to do next */
    int step;                       /* the step being played, 0-based */
    int waiting;                    /* the pause or question waited on, or -1 */
    bool new_caption;               /* the next caption line starts a new caption */
    char caption[LESSON_CAPTION];   /* the step's caption so far */
};

/* Starts playing l from its first item. */
void lesson_play_start(struct lesson_play *p, const struct lesson *l);

/* The next item to do, or NULL at the end; a caption line is added to p->caption, a
 * pause or a question becomes p->waiting (the caller waits, then calls lesson_go_on). */
const struct lesson_item *lesson_next(struct lesson_play *p);

/* Goes on past the pause or question waited on. */
void lesson_go_on(struct lesson_play *p);

/* The item of the pause or question that ends step `step` (0-based), or -1 for none. */
int lesson_step_end(const struct lesson *l, int step);

/* Answers a question from text ("2", or its letter "b"): the choice, 1-based, or 0 when
 * it is not one of them. */
int lesson_choice(const struct lesson_item *ask, const char *text);

#endif
