/* save.h: X in the program: the view on the screen saved as SVG and PNG beside the CSV
 * exports (springsim-YYYYmmdd-HHMMSS.svg and .png in the working directory), and said
 * where in the status line. */
#ifndef SPRINGSIM_SAVE_H
#define SPRINGSIM_SAVE_H

#include "app/app.h"
#include "view_picture.h"

/* Saves the n charts as one picture; with n == 0 (the modes view, whose cells are not
 * charts) the modes' shapes as --modes --figure draws them. dir NULL is ".". Returns the
 * app's change mask (the message). */
unsigned fig_save_view(struct app *app, const struct fig_chart *c, int n, const char *dir);

#endif
