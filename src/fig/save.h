/* save.h: X in the program: the view on the screen written as a report figure, SVG and
 * PNG (springsim-YYYYmmdd-HHMMSS.svg and .png in the working directory unless named),
 * and said where in the status line. */
#ifndef SPRINGSIM_SAVE_H
#define SPRINGSIM_SAVE_H

#include "app/app.h"
#include "view_picture.h"

/* Saves the n charts as one report figure; with n == 0 (the modes view, whose cells are
 * not charts) the modes' shapes as --modes --figure draws them. name: the file's path,
 * its extension (.svg, .png, .pdf) choosing that format alone, without one the SVG and
 * PNG pair; NULL or "" for ./springsim-YYYYmmdd-HHMMSS. A name taken gets -2, -3, ...
 * Returns the app's change mask (the message). */
unsigned fig_save_view(struct app *app, const struct fig_chart *c, int n, const char *name);

#endif
