/* window.c: the time plots' window (app.h): its length, moved along a list, and the
 * samples that cover it. */
#include "app.h"

#include "ghost.h"

/* The time plots' windows (s) that < and > step through; --window may start between. */
static const double windows[] = {1.0, 2.0, 5.0, 10.0, 20.0, 30.0, 60.0};
#define NWINDOWS (int)(sizeof windows / sizeof *windows)

double app_window(const struct app *app)
{
    return app->cfg.window;
}

unsigned app_window_step(struct app *app, int dir)
{
    /* Place by place to the next window of the list past the one shown, which may lie
     * between two of them (--window 33); a move past an end of the list stops there. */
    double w = app->cfg.window;
    int places = dir < 0 ? -dir : dir, moved = 0;
    for (; moved < places; moved++) {
        double to = w;
        for (int i = 0; i < NWINDOWS; i++)
            if (dir > 0 ? windows[i] > w && to == w : windows[i] < w)
                to = windows[i];
        if (to == w)
            break;
        w = to;
    }
    unsigned what = w != app->cfg.window ? APP_CHANGED_WINDOW : 0;
    app->cfg.window = w;
    if (moved < places)
        what |= app_say(app, SAID_NOTE, "the time window is %g s at %s", w,
                        dir < 0 ? "least" : "most");
    return what;
}

const struct trail *app_trail(const struct app *app)
{
    /* The fine samples serve every window they span. */
    return app_window(app) < TRAIL_FINE_RECORDS * TRAIL_FINE_SPACING ? app->trail : app->coarse;
}

const struct trail *app_ghost_trail(const struct app *app)
{
    if (!app->ghost)
        return NULL;
    return app_trail(app) == app->trail ? app->ghost->trail : app->ghost->coarse;
}
