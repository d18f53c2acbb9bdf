/* screen.c: the screen laid out for the terminal program's state (screen.h). */
#include "screen.h"

#include <curses.h>

bool screen_cursors_shown(const struct tui *t)
{
    return t->app.scope.cursors > 0 && t->views.shown == VIEW_PLOTS;
}

void screen_relayout(struct tui *t)
{
    int rows, cols;
    getmaxyx(stdscr, rows, cols);
    layout_compute(&t->layout, cols, rows, t->enlarged, t->views.shown != VIEW_PLOTS);
    if (screen_cursors_shown(t))
        layout_scope(&t->layout, t->enlarged);
    if (teach_shown(&t->teach))
        layout_caption(&t->layout, layout_caption_rows(rows), t->enlarged,
                       t->views.shown != VIEW_PLOTS);
    if (!t->layout.too_small) {
        scene_place(&t->scene, &t->layout);
        plots_place(&t->plots, &t->layout);
        views_place(&t->views, &t->layout);
    }
    /* Images where text now goes stay on the screen until something is written over
     * them; curses writes only what changed, so the whole screen is drawn again. */
    if (t->gfx.mode != GRAPHICS_BRAILLE)
        clearok(curscr, TRUE);
    graphics_invalidate(&t->gfx);
    t->plots_dirty = true;
}

void screen_draw_charts(struct tui *t, bool refresh)
{
    /* The spectrum follows the mass last selected in the chain. */
    if (select_mass(&t->sel) >= 0)
        t->views.spectrum.mass = select_mass(&t->sel);
    t->plots.top = select_mass(&t->sel); /* the selected mass over the others */
    if (t->views.shown == VIEW_PLOTS)
        plots_draw(&t->plots, &t->layout, &t->app, refresh);
    else
        views_draw(&t->views, &t->app, &t->sel, refresh);
}

int screen_charts(struct tui *t, struct chart **out, bool images)
{
    int n = 0;
    if (t->layout.too_small)
        return 0;
    if (images && t->views.shown == VIEW_MODES)
        return modes_view_cells(&t->views.modes, out, GRAPHICS_SLOTS);
    if (t->views.shown != VIEW_PLOTS)
        return views_charts(&t->views, out, PLOT_COUNT);
    for (int k = 0; k < t->layout.nplots && n < PLOT_COUNT; k++)
        out[n++] = &t->plots.chart[t->layout.plot_id[k]];
    return n;
}
