/* view_branches.h: the response view of a chain with cubic springs under a sine drive:
 * the harmonic-balance branches (stable solid, unstable dashed, the backbone dotted, the
 * folds marked) on a linear frequency axis over the sweep's range, the sweep up's points
 * (▲) and the sweep down's (▼) over them, and where each jumped; the phases below. */
#ifndef SPRINGSIM_VIEW_BRANCHES_H
#define SPRINGSIM_VIEW_BRANCHES_H

#include <stdbool.h>

#include "view_response.h"

#define BRANCHES_PHASE_MIN_ROWS 26 /* the view's height from which the phase shows too */

/* Draws rv for app's chain (jump_two_way); fresh redraws the curves from the newest data.
 * The theory is solved again only when the chain or the drive changes. */
void branches_draw(struct response_view *rv, const struct app *app, bool fresh);

#endif
