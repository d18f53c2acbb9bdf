/* keys.c: keys and the mouse in the terminal program (keys.h). */
#include "keys.h"

#include <math.h>
#include <time.h>

#include <curses.h>

#include "../app/scope.h"
#include "../app/verb.h"
#include "../fig/lib.h"
#include "input.h"

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
    screen_relayout(t);
}

/* Enlarges plot p, or goes back to the grid (p < 0, or p already enlarged). */
static void enlarge(struct tui *t, int p)
{
    t->enlarged = p < 0 || p == t->enlarged ? -1 : p;
    t->views.shown = VIEW_PLOTS;
    if (t->sel.focus == FOCUS_MODES)
        t->sel.focus = FOCUS_CONTROLS;
    screen_relayout(t);
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
    screen_relayout(t);
    return changed;
}

/* X: asks for the figure's file name, the default one springsim-YYYYmmdd-HHMMSS. */
static void ask_figure(struct tui *t)
{
    time_t now = time(NULL);
    struct tm tm;
    char name[40];
    localtime_r(&now, &tm);
    strftime(name, sizeof name, "springsim-%Y%m%d-%H%M%S", &tm);
    overlay_figure(&t->overlay, name);
}

/* The charts on the screen (the plots, or the analysis view's) as a report figure in
 * file name (SVG and PNG, or the one format its extension names). */
static void save_view(struct tui *t, const char *name)
{
    struct chart *charts[GRAPHICS_SLOTS];
    struct fig_chart pics[GRAPHICS_SLOTS];
    const struct fig_lib *lib;
    char why[600];
    if (t->layout.too_small) {
        app_say(&t->app, SAID_ERROR, "figure: the terminal is too small to show the view");
        return;
    }
    if (!(lib = fig_lib(why, sizeof why))) {
        app_say(&t->app, SAID_ERROR, "figure: %s", why);
        return;
    }
    /* The charts drawn again with their strokes kept (braille keeps none), as the next
     * frame will draw them. */
    chart_keep_for_figure(true);
    screen_draw_charts(t, true);
    int n = screen_charts(t, charts, false);
    for (int i = 0; i < n; i++)
        chart_picture(charts[i], &pics[i]);
    lib->save_view(&t->app, pics, n, name);
    chart_keep_for_figure(false);
    t->plots_dirty = true;
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
        screen_relayout(t);
    } else if (t->views.shown != views[v]) {
        toggle_view(t, views[v]);
    }
}

/* After the lesson took a key or started: the view it asked for, and the screen laid out
 * again when its panel came or went. */
void keys_after_teach(struct tui *t, bool was_shown)
{
    if (t->teach.view >= 0 && t->teach.view < CV_COUNT)
        show_view(t, t->teach.view);
    t->teach.view = -1;
    if (teach_shown(&t->teach) != was_shown)
        screen_relayout(t);
    if (t->teach.fit)
        plots_refit(&t->plots);
    t->teach.fit = false;
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

/* What Enter does where the selection is: start the mode chosen in the modes view, or
 * apply a pending number of masses (verbs, with their argument into arg); else Enter as
 * it is, which opens what the selection asks for. */
static enum action enter_verb(const struct tui *t, struct verb_arg *arg)
{
    if (t->sel.focus == FOCUS_MODES) {
        arg->index = t->sel.mode;
        return ACT_MODE;
    }
    if (t->sel.focus == FOCUS_CONTROLS && t->sel.control == CTL_MASSES &&
        t->app.masses_pending != t->app.model->n)
        return ACT_APPLY;
    return ACT_ENTER;
}

/* Enter where it is no verb: an overlay to type a value into, or the preset menu. */
static void enter(struct tui *t)
{
    if (t->sel.focus == FOCUS_CHAIN)
        overlay_edit(&t->overlay, select_mass(&t->sel) >= 0 ? EDIT_MASS : EDIT_SPRING);
    else if (t->sel.control == CTL_PRESET)
        overlay_presets(&t->overlay, &t->app);
    else
        overlay_edit(&t->overlay, EDIT_CONTROL);
}

/* What is only the screen's to do: overlays, focus, the arrows in the panels, views,
 * cursors shown or not, a figure of what is shown; one row per action in the table
 * below (the key table names the action, the table of user verbs the app's). */
struct screen_action;
typedef void screen_fn(struct tui *t, const struct screen_action *row, enum action a,
                       int ch, unsigned *changed);

struct screen_action {
    screen_fn *fn;   /* does it */
    enum view view;  /* the analysis view it shows (scr_view) */
    bool shows;      /* it changes what is shown: recorded as `view NAME` */
};

static void scr_presets(struct tui *t, const struct screen_action *row, enum action a,
                        int ch, unsigned *changed)
{
    (void)row, (void)a, (void)ch, (void)changed;
    overlay_presets(&t->overlay, &t->app);
}

static void scr_lessons(struct tui *t, const struct screen_action *row, enum action a,
                        int ch, unsigned *changed)
{
    (void)row, (void)a, (void)ch, (void)changed;
    if (t->rec.mem)
        app_say(&t->app, SAID_NOTE, "no lessons while recording (--record): the recording "
                "would miss their commands");
    else
        overlay_lessons(&t->overlay, &t->app);
}

static void scr_help(struct tui *t, const struct screen_action *row, enum action a,
                     int ch, unsigned *changed)
{
    (void)row, (void)a, (void)ch, (void)changed;
    overlay_help(&t->overlay);
}

static void scr_move(struct tui *t, const struct screen_action *row, enum action a,
                     int ch, unsigned *changed)
{
    (void)row, (void)ch, (void)changed;
    select_move(&t->sel, a == ACT_UP ? -1 : 1, CTL_COUNT, t->app.model);
}

static void scr_adjust(struct tui *t, const struct screen_action *row, enum action a,
                       int ch, unsigned *changed)
{
    (void)row, (void)ch;
    *changed = adjust(t, a == ACT_LEFT || a == ACT_LEFT_BIG ? -1 : 1,
                      a == ACT_LEFT_BIG || a == ACT_RIGHT_BIG);
}

static void scr_enter(struct tui *t, const struct screen_action *row, enum action a,
                      int ch, unsigned *changed)
{
    (void)row, (void)a, (void)ch, (void)changed;
    enter(t);
}

static void scr_damping(struct tui *t, const struct screen_action *row, enum action a,
                        int ch, unsigned *changed)
{
    (void)row, (void)a, (void)ch, (void)changed;
    if (select_mass(&t->sel) >= 0)
        overlay_edit(&t->overlay, EDIT_DAMPING);
    else if (select_spring(&t->sel) >= 0)
        overlay_edit(&t->overlay, EDIT_SPRING_DAMPER);
    else
        app_say(&t->app, SAID_NOTE, "select a mass or a spring in the chain first (Tab, then "
                "↑↓)");
}

static void scr_cubic(struct tui *t, const struct screen_action *row, enum action a,
                      int ch, unsigned *changed)
{
    (void)row, (void)a, (void)ch, (void)changed;
    if (select_spring(&t->sel) >= 0)
        overlay_edit(&t->overlay, EDIT_CUBIC);
    else
        app_say(&t->app, SAID_NOTE, "select a spring in the chain first (Tab, then ↑↓)");
}

static void scr_focus(struct tui *t, const struct screen_action *row, enum action a,
                      int ch, unsigned *changed)
{
    (void)row, (void)a, (void)ch, (void)changed;
    select_toggle_focus(&t->sel, t->app.model, t->views.shown == VIEW_MODES);
}

static void scr_view(struct tui *t, const struct screen_action *row, enum action a,
                     int ch, unsigned *changed)
{
    (void)a, (void)ch, (void)changed;
    toggle_view(t, row->view);
}

static void scr_hide(struct tui *t, const struct screen_action *row, enum action a,
                     int ch, unsigned *changed)
{
    (void)row, (void)a, (void)ch, (void)changed;
    plots_toggle_mass(&t->plots, &t->app, select_mass(&t->sel));
}

static void scr_save(struct tui *t, const struct screen_action *row, enum action a,
                     int ch, unsigned *changed)
{
    (void)row, (void)a, (void)ch, (void)changed;
    overlay_edit(&t->overlay, EDIT_SAVE);
}

static void scr_figure(struct tui *t, const struct screen_action *row, enum action a,
                       int ch, unsigned *changed)
{
    (void)row, (void)a, (void)ch, (void)changed;
    ask_figure(t);
}

static void scr_enlarge(struct tui *t, const struct screen_action *row, enum action a,
                        int ch, unsigned *changed)
{
    (void)row, (void)changed;
    enlarge(t, a == ACT_GRID ? -1 : ch - '1');
}

static void scr_escape(struct tui *t, const struct screen_action *row, enum action a,
                       int ch, unsigned *changed)
{
    (void)row, (void)a, (void)ch, (void)changed;
    t->sel.focus = FOCUS_CONTROLS;
}

static void scr_cursor(struct tui *t, const struct screen_action *row, enum action a,
                       int ch, unsigned *changed)
{
    (void)row, (void)ch;
    *changed = cursor_action(t, a);
}

static void scr_redraw(struct tui *t, const struct screen_action *row, enum action a,
                       int ch, unsigned *changed)
{
    (void)row, (void)a, (void)ch, (void)changed;
    clearok(curscr, TRUE);
    graphics_invalidate(&t->gfx);
}

/* The screen's actions; none where the action is a verb of the app's, or nothing. */
static const struct screen_action screen_actions[ACT_COUNT] = {
    [ACT_PRESETS] = {scr_presets},     [ACT_LESSONS] = {scr_lessons},
    [ACT_HELP] = {scr_help},
    [ACT_UP] = {scr_move},             [ACT_DOWN] = {scr_move},
    [ACT_LEFT] = {scr_adjust},         [ACT_RIGHT] = {scr_adjust},
    [ACT_LEFT_BIG] = {scr_adjust},     [ACT_RIGHT_BIG] = {scr_adjust},
    [ACT_ENTER] = {scr_enter},         [ACT_DAMPING] = {scr_damping},
    [ACT_FOCUS] = {scr_focus},         [ACT_CUBIC_KEY] = {scr_cubic},
    [ACT_MODES] = {scr_view, VIEW_MODES, true},
    [ACT_RESPONSE] = {scr_view, VIEW_RESPONSE, true},
    [ACT_ENERGY] = {scr_view, VIEW_ENERGY, true},
    [ACT_SPECTRUM] = {scr_view, VIEW_SPECTRUM, true},
    [ACT_ENLARGE] = {scr_enlarge, VIEW_PLOTS, true},
    [ACT_GRID] = {scr_enlarge, VIEW_PLOTS, true},
    [ACT_HIDE] = {scr_hide},           [ACT_SAVE] = {scr_save},
    [ACT_FIGURE] = {scr_figure},
    [ACT_ESCAPE] = {scr_escape},       [ACT_CURSOR] = {scr_cursor},
    [ACT_CURSOR_OFF] = {scr_cursor},   [ACT_REDRAW] = {scr_redraw},
};

/* The command action a stood for, for --record, once it has done what it did: a view
 * shown, as `view NAME`; a verb's, as its row says (verb_command). */
static void say_command(struct tui *t, enum action a, const struct verb_arg *arg,
                        unsigned changed)
{
    if (a > ACT_NONE && a < ACT_COUNT && screen_actions[a].shows)
        snprintf(t->said, sizeof t->said, "view %s", view_name(t));
    else
        verb_command(a, arg, changed, t->app.running, t->said, sizeof t->said);
}

/* Acts on a: a verb through its row of the table of user verbs (verb.h), with its
 * argument from the screen; the rest on the screen. False to quit. */
static bool on_action(struct tui *t, enum action a, int ch)
{
    struct app *app = &t->app;
    unsigned changed = 0;
    if (a == ACT_QUIT)
        return false;
    if (a != ACT_NONE && a != ACT_REDRAW)
        app_quiet(app);
    struct verb_arg arg = {0};
    bool verb = false;
    if (a == ACT_ENTER)
        a = enter_verb(t, &arg);
    if (a >= ACT_CURSOR_STEP && a <= ACT_CURSOR_MASS)
        arg.dir = key_direction(ch);
    /* In the response view, the sweep's points; elsewhere the recorded samples. */
    arg.sweep = a == ACT_EXPORT && t->views.shown == VIEW_RESPONSE;
    if (verb_bound(a)) {
        verb = true;
        verb_do(app, a, &arg, &changed);
        if (a == ACT_SWEEP && app->sweep->active && t->views.shown != VIEW_RESPONSE)
            toggle_view(t, VIEW_RESPONSE);
    } else if (a > ACT_NONE && a < ACT_COUNT && screen_actions[a].fn) {
        screen_actions[a].fn(t, &screen_actions[a], a, ch, &changed);
    }
    if (changed & APP_CHANGED_SIZE)
        select_clamp(&t->sel, app->model);
    say_command(t, a, &arg, changed & ~(unsigned)APP_CHANGED_MESSAGE);
    /* A verb that changed nothing they draw (refused; only said something) leaves the
     * plots as their last refresh left them; what the screen does may move the
     * selection they follow, and refreshes them. */
    if (!verb || (changed & APP_CHANGED_DRAWN))
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
    int ctl = screen_cursors_shown(t) ? -1 : layout_control_at(l, ev.y, ev.x, CTL_COUNT, t->sel.control_top);
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
            char hint[32];
            if (t->app.running)
                app_say(&t->app, SAID_NOTE, "pause%s to drag a mass",
                        app_key_hint(&t->app, ACT_RUN, NULL, hint, sizeof hint));
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

/* A key: the mouse, an open overlay, a lesson waiting for it come first. */
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
        if (t->overlay.figure[0]) {
            save_view(t, t->overlay.figure);
            t->overlay.figure[0] = '\0';
        }
        if (t->overlay.chosen[0]) {
            teach_open(&t->teach, t->overlay.chosen, &t->app);
            t->overlay.chosen[0] = '\0';
            keys_after_teach(t, shown);
        }
        return true;
    }
    if (teach_key(&t->teach, &t->app, &t->layout, ch)) {
        keys_after_teach(t, shown);
        return true;
    }
    return on_action(t, input_action(ch, screen_cursors_shown(t)), ch);
}

bool keys_on_key(struct tui *t, int ch)
{
    if (ch == KEY_RESIZE) {
        screen_relayout(t);
        return true;
    }
    t->said[0] = '\0';
    record_mark(&t->rec, &t->app);
    bool go = handle_key(t, ch);
    record_changes(&t->rec, &t->app, t->said[0] ? t->said : NULL);
    /* Keys alone fill a recording too (its bytes: a long paste of ] and [). */
    if (record_full(&t->rec, &t->app, 0.0))
        record_full_finish(&t->rec, &t->app);
    return go;
}
