/* overlay.h: what comes over the screen and takes the keys while it is up: the help
 * (scrollable), the preset menu, the lesson menu, typing a value, and the replace-it
 * confirmation. */
#ifndef SPRINGSIM_OVERLAY_H
#define SPRINGSIM_OVERLAY_H

#include <stdbool.h>

#include "../app/app.h"
#include "../chart/layout.h"
#include "../lab/lesson.h"
#include "../app/select.h"
#include "../core/preset.h"

enum overlay_kind {
    OVERLAY_NONE,
    OVERLAY_HELP,
    OVERLAY_PRESETS,
    OVERLAY_LESSONS,
    OVERLAY_EDIT,
    OVERLAY_CONFIRM
};

/* What the text being typed is for. */
enum edit_target { EDIT_CONTROL, EDIT_MASS, EDIT_DAMPING, EDIT_SPRING, EDIT_CUBIC,
                   EDIT_SPRING_DAMPER, EDIT_SAVE, EDIT_FIGURE };

struct overlay {
    enum overlay_kind kind;
    int help_top;                  /* first help line shown */
    struct search_entry *presets;  /* the menu's entries */
    int npresets, preset_sel;
    struct search_entry *lessons;  /* the lesson menu's entries */
    int nlessons, lesson_sel;
    char chosen[4400];             /* the lesson chosen (Enter), for the caller to open; "" */
    enum edit_target target;
    char edit[256];                /* text being typed */
    int edit_len;
    char save_name[256];           /* name waiting for the replace confirmation; X's default */
    char figure[300];              /* X's file name typed (Enter), for the caller to write; "" */
};

/* Opens the help. */
void overlay_help(struct overlay *o);

/* Opens the preset menu on the presets found for app, the current one selected. */
void overlay_presets(struct overlay *o, const struct app *app);

/* Opens the lesson menu on the lessons found for app. */
void overlay_lessons(struct overlay *o, const struct app *app);

/* Starts typing a value for target. */
void overlay_edit(struct overlay *o, enum edit_target target);

/* Starts typing X's file name, Enter keeping def. */
void overlay_figure(struct overlay *o, const char *def);

/* Takes key ch while an overlay is up; returns what changed in the app. */
unsigned overlay_key(struct overlay *o, struct app *app, const struct selection *sel,
                     const struct layout *l, int ch);

/* Draws the overlay that is up (typing and the confirmation on the footer's row). */
void overlay_draw(const struct overlay *o, const struct app *app, const struct layout *l,
                  const struct selection *sel);

/* Frees the preset and lesson lists. */
void overlay_free(struct overlay *o);

#endif
