/* panel.h: the text around the plots: the status line, the controls with the frequency
 * bar and the natural frequencies, and the footer of hints. */
#ifndef SPRINGSIM_PANEL_H
#define SPRINGSIM_PANEL_H

#include <stdbool.h>

#include "../app/app.h"
#include "../chart/layout.h"
#include "../app/select.h"

/* What the footer's hints depend on besides the app. */
struct hint_state {
    int enlarged;   /* the plot enlarged, or -1 */
    bool view;      /* an analysis view has the plot area */
    bool modes;     /* the arrows choose a mode in the modes view */
    bool cursor;    /* time cursors shown: the arrows are theirs */
    const char *space_key;           /* "space", or the key a lesson has in its place */
    const char *space, *dot, *comma; /* what space, '.' and ',' do while a lesson or a
                                      * replay takes them (teach_keys), or NULL */
};

/* The status line: state, t, the drive, N, dt, history, playback. */
void panel_status(const struct layout *l, const struct app *app, bool behind);

/* The controls with their values, the selected one highlighted. */
void panel_controls(const struct layout *l, const struct app *app, struct selection *sel);

/* The footer: the app's message if there is one, else the keys that fit, by state. */
void panel_hints(const struct layout *l, const struct app *app, const struct hint_state *h);

/* The message below the minimum size, cut to fit any size. */
void panel_too_small(const struct layout *l);

#endif
