/* tui.c: the interactive program's paced loop: it steps the app to follow the wall
 * clock, draws a frame (erase, then everything from the state, one doupdate), and turns
 * keys and the mouse into the app's changes. */
#include "tui.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/ioctl.h>
#include <unistd.h>

#include <curses.h>

#include "../app/clock.h"
#include "../app/ghost.h"
#include "../app/layout.h"
#include "../app/record.h"
#include "../app/scope.h"
#include "../app/select.h"
#include "../fig/save.h"
#include "draw.h"
#include "graphics.h"
#include "input.h"
#include "overlay.h"
#include "panel.h"
#include "plots.h"
#include "readout.h"
#include "scene.h"
#include "teach.h"
#include "term.h"
#include "views.h"

#define PLOT_HZ 10.0      /* plots, while running, at most */
#define PLOT_CELL_HZ 2.4e4 /* plot cells redrawn a second, at most: large plots refresh less
                            * often, so output stays under 100 KB/s at any size */
#define LOW_FRAME_HZ 10.0 /* low bandwidth: scene and status */
#define LOW_PLOT_HZ 0.5   /* low bandwidth: plots, every 2 s */
#define BACKLOG 8192      /* bytes waiting for the terminal that mean it cannot keep up */

struct tui {
    struct app app;
    struct layout layout;
    struct selection sel;
    struct scene scene;
    struct plots plots;
    struct views views;
    struct overlay overlay;
    int enlarged;         /* the plot enlarged, or -1 for the grid */
    double plot_due;      /* wall time of the next plot refresh */
    bool plots_dirty;     /* refresh the plots at the next frame */
    struct app_clock clock; /* simulated time following the wall clock */
    int backlog_frames;   /* frames in a row with output piling up unread */
    bool dragging;        /* a mass is being dragged with the mouse */
    struct teach teach;   /* a lesson being played, its caption panel */
    struct record rec;    /* --record: the session being written */
    char said[64];        /* the command the key being handled stands for, or "" */
    struct graphics gfx;  /* the charts as images, where the terminal shows them */
};

/* True while time cursors are shown on the plots: their keys come first. */
static bool cursors_shown(const struct tui *t)
{
    return t->app.scope.cursors > 0 && t->views.shown == VIEW_PLOTS;
}

/* Lays the screen out again for its size and what is shown. */
static void relayout(struct tui *t)
{
    int rows, cols;
    getmaxyx(stdscr, rows, cols);
    layout_compute(&t->layout, cols, rows, t->enlarged, t->views.shown != VIEW_PLOTS);
    if (cursors_shown(t))
        layout_scope(&t->layout, t->enlarged);
    if (teach_shown(&t->teach))
        layout_caption(&t->layout, layout_caption_rows(rows), t->enlarged,
                       t->views.shown != VIEW_PLOTS);
    if (!t->layout.too_small) {
        scene_place(&t->scene, &t->layout);
        plots_place(&t->plots, &t->layout);
        views_place(&t->views, &t->layout);
    }
    graphics_invalidate(&t->gfx);
    t->plots_dirty = true;
}

/* The charts on the screen (the plots, or the analysis view's): into out (room for
 * GRAPHICS_SLOTS), how many; with images, the modes view's shapes too, which are drawn
 * as charts' areas are but are not charts in a picture of the view (X). */
static int shown_charts(struct tui *t, struct chart **out, bool images)
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

/* Draws a frame; returns the seconds it took to hand it to the terminal. */
static double draw(struct tui *t, bool refresh)
{
    const struct layout *l = &t->layout;
    erase();
    if (l->too_small) {
        panel_too_small(l);
    } else {
        panel_status(l, &t->app, t->clock.behind);
        scene_draw(&t->scene, l, &t->app, &t->sel);
        /* The spectrum follows the mass last selected in the chain. */
        if (select_mass(&t->sel) >= 0)
            t->views.spectrum.mass = select_mass(&t->sel);
        t->plots.top = select_mass(&t->sel); /* the selected mass over the others */
        if (t->views.shown == VIEW_PLOTS)
            plots_draw(&t->plots, l, &t->app, refresh);
        else
            views_draw(&t->views, &t->app, &t->sel, refresh);
        if (cursors_shown(t))
            readout_draw(l, &t->app);
        else
            panel_controls(l, &t->app, &t->sel);
        struct hint_state h = {t->enlarged, t->views.shown != VIEW_PLOTS,
                               t->sel.focus == FOCUS_MODES, cursors_shown(t)};
        panel_hints(l, &t->app, &h);
        teach_draw(&t->teach, l);
        overlay_draw(&t->overlay, &t->app, l, &t->sel);
    }
    term_park_cursor();
    wnoutrefresh(stdscr);
    double start = app_clock_now();
    doupdate();
    struct chart *charts[GRAPHICS_SLOTS];
    graphics_frame(&t->gfx, charts, shown_charts(t, charts, true),
                   t->overlay.kind != OVERLAY_NONE);
    return app_clock_now() - start;
}

/* An arrow's adjustment: +-1, fine or coarse, on the control or the chain's mass; in
 * the modes view, the next or the previous mode. */
static unsigned adjust(struct tui *t, int dir, bool coarse)
{
    if (t->sel.focus == FOCUS_MODES) {
        select_move(&t->sel, dir, CTL_COUNT, t->app.model);
        return 0;
    }
    if (t->sel.focus != FOCUS_CHAIN)
        return app_adjust(&t->app, (enum control)t->sel.control, dir, coarse);
    int i = select_mass(&t->sel);
    if (i >= 0)
        return app_move_mass(&t->app, i, dir * (coarse ? 0.5 : 0.05));
    app_say(&t->app, SAID_NOTE, "a spring is selected: ↑↓ to a mass to move it");
    return APP_CHANGED_MESSAGE;
}

/* Shows analysis view v (or the plots again) and lays the area out for it. The modes
 * view takes the arrows (a mode to choose); leaving it gives them back to the controls. */
static void toggle_view(struct tui *t, enum view v)
{
    views_toggle(&t->views, v);
    if (t->views.shown == VIEW_MODES)
        t->sel.focus = FOCUS_MODES;
    else if (t->sel.focus == FOCUS_MODES)
        t->sel.focus = FOCUS_CONTROLS;
    relayout(t);
}

/* Enlarges plot p, or goes back to the grid (p < 0, or p already enlarged). */
static void enlarge(struct tui *t, int p)
{
    t->enlarged = p < 0 || p == t->enlarged ? -1 : p;
    t->views.shown = VIEW_PLOTS;
    if (t->sel.focus == FOCUS_MODES)
        t->sel.focus = FOCUS_CONTROLS;
    relayout(t);
}

/* The direction of a cursor key: -1 earlier (left, back, up), +1 later. */
static int key_direction(int ch)
{
    bool back = ch == 'h' || ch == 'H' || ch == 'k' || ch == KEY_LEFT || ch == KEY_SLEFT ||
                ch == KEY_PPAGE || ch == KEY_UP;
    return back ? -1 : 1;
}

/* `|` (one cursor, two, none) and Esc (none) on the time plots. The readout takes the
 * controls' column while a cursor is shown. */
static unsigned cursor_action(struct tui *t, enum action a)
{
    struct app *app = &t->app;
    if (t->views.shown != VIEW_PLOTS) {
        app_say(app, SAID_NOTE, "the cursors are on the plots: 0 shows them");
        return APP_CHANGED_MESSAGE;
    }
    /* The mass measured: the one selected in the chain, else the one last measured. */
    unsigned changed = a == ACT_CURSOR_OFF ? scope_clear(app)
                                           : scope_toggle(app, select_mass(&t->sel));
    relayout(t);
    return changed;
}

/* X: the charts on the screen (the plots, or the analysis view's) as SVG and PNG. */
static void save_view(struct tui *t)
{
    struct chart *charts[GRAPHICS_SLOTS];
    struct fig_chart pics[GRAPHICS_SLOTS];
    int n = shown_charts(t, charts, false);
    for (int i = 0; i < n; i++)
        chart_picture(charts[i], &pics[i]);
    if (t->layout.too_small)
        app_say(&t->app, SAID_ERROR, "figure: the terminal is too small to show the view");
    else
        fig_save_view(&t->app, pics, n, NULL);
}

/* What a lesson's `view` asked for, shown (the plots' grid, one enlarged, a view). */
static void show_view(struct tui *t, int v)
{
    static const enum view views[CV_COUNT] = {
        [CV_MODES] = VIEW_MODES, [CV_RESPONSE] = VIEW_RESPONSE, [CV_ENERGY] = VIEW_ENERGY,
        [CV_SPECTRUM] = VIEW_SPECTRUM};
    if (v < CV_MODES) {
        t->enlarged = v == CV_PLOTS ? -1 : v - CV_X;
        t->views.shown = VIEW_PLOTS;
        if (t->sel.focus == FOCUS_MODES)
            t->sel.focus = FOCUS_CONTROLS;
        relayout(t);
    } else if (t->views.shown != views[v]) {
        toggle_view(t, views[v]);
    }
}

/* After the lesson took a key or started: the view it asked for, and the screen laid out
 * again when its panel came or went. */
static void after_teach(struct tui *t, bool was_shown)
{
    if (t->teach.view >= 0 && t->teach.view < CV_COUNT)
        show_view(t, t->teach.view);
    t->teach.view = -1;
    if (teach_shown(&t->teach) != was_shown)
        relayout(t);
    select_clamp(&t->sel, t->app.model);
    t->plots_dirty = true;
}

/* What is shown, as the view command names it. */
static const char *view_name(const struct tui *t)
{
    static const int of[] = {[VIEW_PLOTS] = CV_PLOTS, [VIEW_MODES] = CV_MODES,
                             [VIEW_RESPONSE] = CV_RESPONSE, [VIEW_ENERGY] = CV_ENERGY,
                             [VIEW_SPECTRUM] = CV_SPECTRUM};
    if (t->views.shown == VIEW_PLOTS && t->enlarged >= 0)
        return command_views[CV_X + t->enlarged];
    return command_views[of[t->views.shown]];
}

/* The command action a stood for, for --record, once it has done what it did. */
static void say_command(struct tui *t, enum action a, unsigned changed)
{
    int mode = t->sel.focus == FOCUS_MODES ? t->sel.mode + 1 : 0;
    record_key(t->said, sizeof t->said, a, changed, t->app.running, mode, view_name(t));
}

/* Acts on a; false to quit. */
static bool on_action(struct tui *t, enum action a, int ch)
{
    struct app *app = &t->app;
    unsigned changed = 0;
    if (a != ACT_NONE && a != ACT_REDRAW)
        app_quiet(app);
    switch (a) {
    case ACT_QUIT:
        return false;
    case ACT_RUN:
        changed = app_set_running(app, !app->running);
        break;
    case ACT_STEP:
        app_set_running(app, false);
        changed = app_step(app);
        break;
    case ACT_BACK:
        changed = app_back(app);
        break;
    case ACT_RESET:
        changed = app_reset(app);
        app_say(app, SAID_NOTE, "reset to t = 0");
        break;
    case ACT_RANDOM:
        changed = app_random(app);
        break;
    case ACT_PRESETS:
        overlay_presets(&t->overlay, app);
        break;
    case ACT_LESSONS:
        if (t->rec.mem)
            app_say(app, SAID_NOTE, "no lessons while recording (--record): the recording would "
                    "miss their commands");
        else
            overlay_lessons(&t->overlay, app);
        break;
    case ACT_HELP:
        overlay_help(&t->overlay);
        break;
    case ACT_UP:
    case ACT_DOWN:
        select_move(&t->sel, a == ACT_UP ? -1 : 1, CTL_COUNT, app->model);
        break;
    case ACT_LEFT:
    case ACT_RIGHT:
    case ACT_LEFT_BIG:
    case ACT_RIGHT_BIG:
        changed = adjust(t, a == ACT_LEFT || a == ACT_LEFT_BIG ? -1 : 1,
                         a == ACT_LEFT_BIG || a == ACT_RIGHT_BIG);
        break;
    case ACT_ENTER:
        if (t->sel.focus == FOCUS_MODES)
            changed = app_start_mode(app, t->sel.mode);
        else if (t->sel.focus == FOCUS_CHAIN)
            overlay_edit(&t->overlay, select_mass(&t->sel) >= 0 ? EDIT_MASS : EDIT_SPRING);
        else if (t->sel.control == CTL_PRESET)
            overlay_presets(&t->overlay, app);
        else if (t->sel.control == CTL_MASSES && app->masses_pending != app->model->n)
            changed = app_apply_masses(app);
        else
            overlay_edit(&t->overlay, EDIT_CONTROL);
        break;
    case ACT_DAMPING:
        if (select_mass(&t->sel) >= 0)
            overlay_edit(&t->overlay, EDIT_DAMPING);
        else
            app_say(app, SAID_NOTE, "select a mass in the chain first (Tab, then ↑↓)");
        break;
    case ACT_FOCUS:
        select_toggle_focus(&t->sel, app->model, t->views.shown == VIEW_MODES);
        break;
    case ACT_MODES:
        toggle_view(t, VIEW_MODES);
        break;
    case ACT_RESPONSE:
        toggle_view(t, VIEW_RESPONSE);
        break;
    case ACT_ENERGY:
        toggle_view(t, VIEW_ENERGY);
        break;
    case ACT_SPECTRUM:
        toggle_view(t, VIEW_SPECTRUM);
        break;
    case ACT_NEAREST:
        changed = app_nearest_mode(app);
        break;
    case ACT_GHOST:
        changed = app_toggle_ghost(app);
        break;
    case ACT_HIDE:
        plots_toggle_mass(&t->plots, app, select_mass(&t->sel));
        break;
    case ACT_SWEEP:
        changed = app_toggle_sweep(app);
        if (app->sweep->active && t->views.shown != VIEW_RESPONSE)
            toggle_view(t, VIEW_RESPONSE);
        break;
    case ACT_SAVE:
        overlay_edit(&t->overlay, EDIT_SAVE);
        break;
    case ACT_EXPORT: {
        /* In the response view, the sweep's points; elsewhere the recorded samples. */
        char path[4200];
        if (t->views.shown == VIEW_RESPONSE)
            app_export_sweep(app, NULL, path, sizeof path);
        else
            app_export(app, NULL, path, sizeof path);
        break;
    }
    case ACT_FIGURE:
        save_view(t);
        break;
    case ACT_SLOWER:
    case ACT_FASTER:
        changed = app_adjust(app, CTL_SPEED, a == ACT_SLOWER ? -1 : 1, false);
        break;
    case ACT_ENLARGE:
        enlarge(t, ch - '1');
        break;
    case ACT_GRID:
        enlarge(t, -1);
        break;
    case ACT_NARROWER:
    case ACT_WIDER:
        changed = app_window_step(app, a == ACT_WIDER ? 1 : -1);
        break;
    case ACT_ESCAPE:
        t->sel.focus = FOCUS_CONTROLS;
        break;
    case ACT_CURSOR:
    case ACT_CURSOR_OFF:
        changed = cursor_action(t, a);
        break;
    case ACT_CURSOR_STEP:
        changed = scope_move(app, key_direction(ch));
        break;
    case ACT_CURSOR_JUMP:
        changed = scope_jump(app, key_direction(ch));
        break;
    case ACT_CURSOR_PAGE:
        changed = scope_page(app, key_direction(ch));
        break;
    case ACT_CURSOR_MASS:
        changed = scope_select(app, key_direction(ch));
        break;
    case ACT_REDRAW:
        clearok(curscr, TRUE);
        graphics_invalidate(&t->gfx);
        break;
    case ACT_NONE:
        break;
    }
    if (changed & APP_CHANGED_SIZE)
        select_clamp(&t->sel, app->model);
    say_command(t, a, changed & ~(unsigned)APP_CHANGED_MESSAGE);
    t->plots_dirty = true;
    return true;
}

/* The mass nearest to column x of the scene, with its distance (m). */
static int mass_near(const struct tui *t, double X, double *dist)
{
    const struct model *m = t->app.model;
    int pick = -1;
    *dist = INFINITY;
    for (int i = 0; i < m->n; i++) {
        double d = fabs(model_equilibrium(m, i) + sim_x(t->app.sim)[i] - X);
        if (d < *dist)
            *dist = d, pick = i;
    }
    return pick;
}

/* Mouse: click a control, wheel on it, drag a mass while paused. */
static void on_mouse(struct tui *t)
{
    MEVENT ev;
    const struct layout *l = &t->layout;
    if (getmouse(&ev) != OK || l->too_small)
        return;
    t->plots_dirty = true;
    /* The readout has the controls' place while a cursor is shown. */
    int ctl = cursors_shown(t) ? -1 : layout_control_at(l, ev.y, ev.x, CTL_COUNT, t->sel.control_top);
    if (ctl >= 0) {
        t->sel.focus = FOCUS_CONTROLS;
        t->sel.control = ctl;
        if (ev.bstate & BUTTON4_PRESSED)
            app_adjust(&t->app, (enum control)ctl, 1, false);
#ifdef BUTTON5_PRESSED
        else if (ev.bstate & BUTTON5_PRESSED)
            app_adjust(&t->app, (enum control)ctl, -1, false);
#endif
        return;
    }
    struct rect s = l->scene;
    double X = layout_scene_metres(l, ev.x);
    if (ev.y > s.y && ev.y < s.y + s.h - 1 && (ev.bstate & BUTTON1_PRESSED)) {
        const struct model *m = t->app.model;
        double dist;
        int pick = mass_near(t, X, &dist);
        t->sel.focus = FOCUS_CHAIN;
        if (pick >= 0 && dist < model_block_width(m) + 1.0 / l->scene_cpm) {
            t->sel.elem = 2 * pick + 1;
            t->dragging = !t->app.running;
            if (t->app.running)
                app_say(&t->app, SAID_NOTE, "pause (space) to drag a mass");
        } else {
            /* Between masses: the spring there (spring j lies left of mass j+1). */
            int j = 0;
            while (j < m->n && model_equilibrium(m, j) + sim_x(t->app.sim)[j] < X)
                j++;
            if (2 * j < select_elements(m))
                t->sel.elem = 2 * j;
        }
        return;
    }
    if (t->dragging && (ev.bstate & (REPORT_MOUSE_POSITION | BUTTON1_RELEASED))) {
        app_place_mass(&t->app, t->sel.elem / 2, X);
        if (ev.bstate & BUTTON1_RELEASED)
            t->dragging = false;
    }
}

static bool handle_key(struct tui *t, int ch);

/* A key or a mouse event, and what it did written to the recording (--record). */
static bool on_key(struct tui *t, int ch)
{
    if (ch == KEY_RESIZE) {
        relayout(t);
        return true;
    }
    t->said[0] = '\0';
    record_mark(&t->rec, &t->app);
    bool go = handle_key(t, ch);
    record_changes(&t->rec, &t->app, t->said[0] ? t->said : NULL);
    return go;
}

static bool handle_key(struct tui *t, int ch)
{
    if (ch == KEY_MOUSE) {
        if (t->overlay.kind == OVERLAY_NONE)
            on_mouse(t);
        return true;
    }
    bool shown = teach_shown(&t->teach);
    if (t->overlay.kind != OVERLAY_NONE) {
        unsigned changed = overlay_key(&t->overlay, &t->app, &t->sel, &t->layout, ch);
        if (changed & APP_CHANGED_SIZE)
            select_clamp(&t->sel, t->app.model);
        t->plots_dirty = true;
        if (t->overlay.chosen[0]) {
            teach_open(&t->teach, t->overlay.chosen, &t->app);
            t->overlay.chosen[0] = '\0';
            after_teach(t, shown);
        }
        return true;
    }
    if (teach_key(&t->teach, &t->app, ch)) {
        after_teach(t, shown);
        return true;
    }
    return on_action(t, input_action(ch, cursors_shown(t)), ch);
}

/* Plot refreshes a second while running: PLOT_HZ, fewer where the plots cover so many
 * cells that redrawing them that often would flood the link. */
static double plot_hz(const struct tui *t)
{
    const struct layout *l = &t->layout;
    if (t->app.cfg.low_bandwidth)
        return LOW_PLOT_HZ;
    double cells = 0.0;
    if (t->views.shown != VIEW_PLOTS) {
        struct rect d = layout_drawing(l->area);
        cells = (double)d.w * d.h;
    }
    for (int k = 0; k < l->nplots; k++) {
        struct rect d = layout_drawing(l->plot[k]);
        cells += (double)d.w * d.h;
    }
    return cells * PLOT_HZ > PLOT_CELL_HZ ? PLOT_CELL_HZ / cells : PLOT_HZ;
}

/* Frames a second for the scene and the status line. */
static double frame_hz(const struct tui *t)
{
    double hz = t->app.cfg.fps;
    return t->app.cfg.low_bandwidth && hz > LOW_FRAME_HZ ? LOW_FRAME_HZ : hz;
}

/* After a frame that took `spent` seconds to hand to the terminal: if output keeps
 * piling up unread (a slow link: bytes queued, or writing blocked), step down to low
 * bandwidth on its own and say so. */
static void watch_backlog(struct tui *t, double spent)
{
    int queued = 0;
    if (t->app.cfg.low_bandwidth)
        return;
    if (ioctl(STDOUT_FILENO, TIOCOUTQ, &queued) != 0)
        queued = 0;
    bool slow = queued > BACKLOG || spent > 0.5 / frame_hz(t);
    t->backlog_frames = slow ? t->backlog_frames + 1 : 0;
    if (t->backlog_frames >= 3 || spent > 1.0) {
        t->app.cfg.low_bandwidth = true; /* braille too: follow_graphics */
        t->backlog_frames = 0;
        app_say(&t->app, SAID_ERROR, "the terminal is not keeping up: refresh low (the Refresh "
                "control turns it back)");
    }
}

/* The charts drawn as the Graphics and Refresh controls say, whatever changed them (a
 * key, the mouse, a typed value, a lesson, a slow link); a Graphics control asking for
 * pixels that cannot be says why. */
static void follow_graphics(struct tui *t)
{
    struct app *app = &t->app;
    bool asked = t->gfx.want != app->cfg.graphics;
    if (!graphics_follow(&t->gfx, app->cfg.graphics, app->cfg.low_bandwidth))
        return;
    if (app->graphics_now != graphics_now(&t->gfx))
        t->plots_dirty = true;
    app->graphics_now = graphics_now(&t->gfx);
    if (asked && t->gfx.said[0])
        app_say(app, SAID_ERROR, "Graphics %s: %s",
                config_options[CFG_GRAPHICS].choice_name((int)app->cfg.graphics), t->gfx.said);
}

static void tui_free(struct tui *t)
{
    scene_free(&t->scene);
    plots_free(&t->plots);
    views_free(&t->views);
    overlay_free(&t->overlay);
    teach_free(&t->teach);
    graphics_free(&t->gfx);
    app_free(&t->app);
}

bool tui_dumb_terminal(void)
{
    return term_dumb();
}

int tui_run(const struct config *cfg, const char *exe_dir, const struct lesson *lesson)
{
    static struct tui t;
    memset(&t, 0, sizeof t);
    t.enlarged = -1;
    if (app_init(&t.app, cfg, exe_dir) != 0) {
        fprintf(stderr, "springsim: out of memory\n");
        return EXIT_FAILURE;
    }
    t.sel.elem = 1;
    char why[4600];
    if (cfg->record && record_start(&t.rec, cfg->record, &t.app, why, sizeof why) != 0) {
        fprintf(stderr, "springsim: --record: %s\n", why);
        app_free(&t.app);
        return EXIT_FAILURE;
    }
    graphics_detect(&t.gfx, cfg); /* before curses: the terminal is asked directly */
    t.app.graphics_now = graphics_now(&t.gfx);
    if (!term_start(cfg->color, cfg->glyphs)) {
        record_abandon(&t.rec);
        app_free(&t.app);
        return EXIT_FAILURE;
    }
    t.teach.view = -1;
    relayout(&t);
    if (lesson) {
        teach_start(&t.teach, lesson, &t.app);
        after_teach(&t, false);
    }
    if (t.gfx.said[0])
        app_say(&t.app, SAID_ERROR, "--graphics %s: %s",
                config_options[CFG_GRAPHICS].choice_name((int)cfg->graphics), t.gfx.said);
    if (t.app.message[0] == '\0')
        app_say(&t.app, SAID_NOTE, "space starts; ? lists every key");

    double last = app_clock_now(), next_frame = last;
    bool go = true;
    while (go && !term_quit_signal()) {
        double now = app_clock_now();
        /* Never spend more than half a frame computing: fall behind and say so. */
        app_clock_follow(&t.clock, &t.app, now - last, 0.5 / frame_hz(&t), NULL, NULL);
        follow_graphics(&t);
        last = now;
        if (t.rec.mem && sim_time(t.app.sim) - t.rec.t >= RECORD_RUN_MAX)
            record_time(&t.rec, &t.app);
        /* Plots refresh at plot_hz() while running (the modes view's shapes swing even
         * while paused), at once after anything else. */
        bool moving = t.app.running || t.views.shown == VIEW_MODES;
        bool refresh = t.plots_dirty || (moving && now >= t.plot_due);
        if (refresh) {
            t.plot_due = now + 1.0 / plot_hz(&t);
            t.plots_dirty = false;
        }
        watch_backlog(&t, draw(&t, refresh));
        double hz = frame_hz(&t);
        next_frame += 1.0 / hz;
        if (next_frame < now)
            next_frame = now + 1.0 / hz;
        /* Wait for input until the next frame; take every key that is there. */
        for (;;) {
            int ms = (int)((next_frame - app_clock_now()) * 1000.0);
            timeout(ms > 0 ? ms : 0);
            int ch = getch();
            if (ch == ERR) {
                /* No key, or no terminal: a hung-up one gives ERR at once, for ever, and
                 * SIGHUP may never come (it was ignored, or this is not the controlling
                 * terminal). */
                term_check_hangup();
                break;
            }
            if (!on_key(&t, ch)) {
                go = false;
                break;
            }
            if (term_quit_signal())
                break;
        }
    }
    term_stop();
    int status = EXIT_SUCCESS;
    if (t.rec.mem && record_finish(&t.rec, &t.app, why, sizeof why) != 0) {
        fprintf(stderr, "springsim: --record: %s\n", why);
        status = EXIT_FAILURE;
    }
    term_die_of_signal();
    tui_free(&t);
    return status;
}
