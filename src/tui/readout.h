/* readout.h: the time cursors' readout and the measurements, in the column the controls
 * take when no cursor is shown. */
#ifndef SPRINGSIM_READOUT_H
#define SPRINGSIM_READOUT_H

#include "../app/app.h"
#include "../chart/layout.h"

/* Draws the readout of app's cursors, and the measurements of the mass measured over
 * the window, in the controls' rectangle. */
void readout_draw(const struct layout *l, const struct app *app);

#endif
