/* teach.h: a lesson played in the interactive program: its items done one by one (each
 * command through command_do, a run stepped at once), the caption panel below the plots
 * and the controls, and the keys while it waits: space goes on, ',' goes back a step,
 * Esc leaves it with the chain as it is, a digit answers a question. */
#ifndef SPRINGSIM_TEACH_H
#define SPRINGSIM_TEACH_H

#include <stdbool.h>

#include "../app/app.h"
#include "../app/layout.h"
#include "../app/lesson.h"

struct teach {
    struct lesson own;           /* a lesson chosen from the menu (L), read here */
    const struct lesson *lesson; /* the lesson playing, or NULL */
    struct lesson_play play;     /* where it is */
    bool done;                   /* its end reached: the panel stays until space or Esc */
    int view;                    /* a view a `view` command asked for (enum command_view), or
                                  * -1: the caller shows it and sets -1 */
    char note[160];              /* the answer to the question, shown below it */
};

/* Starts playing l (checked already) on app, to its first pause or question. */
void teach_start(struct teach *t, const struct lesson *l, struct app *app);

/* Reads, checks and starts the lesson at path (chosen from the menu); on a bad lesson the
 * app's message says why (FILE:LINE: what) and nothing changes. */
void teach_open(struct teach *t, const char *path, struct app *app);

/* Whether the caption panel is up. */
bool teach_shown(const struct teach *t);

/* Takes key ch if the lesson wants it (space, ',', Esc, a digit at a question); false
 * for any other key, which does what it always does. */
bool teach_key(struct teach *t, struct app *app, int ch);

/* Draws the caption panel in l->caption. */
void teach_draw(const struct teach *t, const struct layout *l);

/* Frees a lesson read from the menu. */
void teach_free(struct teach *t);

#endif
