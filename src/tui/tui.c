/* tui.c: the interactive program's paced loop: it steps the app to follow the wall
 * clock, draws a frame (erase, then everything from the state, one doupdate) and hands
 * keys and the mouse to keys.c. */
#include "tui.h"

#include <stdlib.h>
#include <string.h>
#include <sys/ioctl.h>
#include <unistd.h>

#include <curses.h>

#include "input.h"
#include "keys.h"
#include "panel.h"
#include "readout.h"
#include "screen.h"
#include "term.h"

#define PLOT_HZ 10.0      /* plots, while running, at most */
#define PLOT_CELL_HZ 2.4e4 /* plot cells redrawn a second, at most: large plots refresh less
                            * often, so output stays under 100 KB/s at any size */
#define LOW_FRAME_HZ 10.0 /* low bandwidth: scene and status */
#define LOW_PLOT_HZ 0.5   /* low bandwidth: plots, every 2 s */
#define BACKLOG 8192      /* bytes waiting for the terminal that mean it cannot keep up */
#define BLOCKED_S 0.25    /* a frame whose writes blocked this long: the link is behind */
#define BACKLOG_S 2.0     /* a backlog sustained this long steps the refresh down */
#define KEEP_UP_S 10.0    /* the link keeping up this long steps it back up (doubled after
                           * each step down) */

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
        screen_draw_charts(t, refresh);
        if (screen_cursors_shown(t))
            readout_draw(l, &t->app);
        else
            panel_controls(l, &t->app, &t->sel);
        struct hint_state h = {t->enlarged, t->views.shown != VIEW_PLOTS,
                               t->sel.focus == FOCUS_MODES, screen_cursors_shown(t), NULL,
                               NULL, NULL, NULL};
        teach_keys(&t->teach, &h.space_key, &h.space, &h.dot, &h.comma);
        panel_hints(l, &t->app, &h);
        teach_draw(&t->teach, l);
        overlay_draw(&t->overlay, &t->app, l, &t->sel);
    }
    term_park_cursor();
    wnoutrefresh(stdscr);
    double start = app_clock_now();
    doupdate();
    struct chart *charts[GRAPHICS_SLOTS];
    graphics_frame(&t->gfx, charts, screen_charts(t, charts, true),
                   t->overlay.kind != OVERLAY_NONE);
    return app_clock_now() - start;
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

/* After a frame that took `spent` seconds to hand to the terminal: on a real backlog
 * (bytes queued unread, or writes blocking) at every frame for BACKLOG_S seconds, step
 * down to the low refresh on its own and say so; a busy machine's slow frame is not one.
 * Stepped down, once the link has kept up for up_after seconds (10 s, twice as long after
 * each step down, so a link that only keeps up at the low refresh is not flipped back and
 * forth), step back up and say so. The user's own Refresh control is never overruled. */
static void watch_backlog(struct tui *t, double spent)
{
    int queued = 0;
    double now = app_clock_now();
    if (ioctl(STDOUT_FILENO, TIOCOUTQ, &queued) != 0)
        queued = 0;
    bool backlog = queued > BACKLOG || spent > BLOCKED_S;
    if (t->stepped_down && !t->app.cfg.low_bandwidth)
        t->stepped_down = false; /* the user turned it back */
    if (!t->app.cfg.low_bandwidth) {
        /* A frame whose writes blocked began the backlog when it began writing. */
        double began = now - spent;
        t->backlog_since = !backlog ? 0.0 : t->backlog_since > 0.0 ? t->backlog_since : began;
        if (t->backlog_since > 0.0 && now - t->backlog_since >= BACKLOG_S) {
            t->app.cfg.low_bandwidth = true; /* braille too: follow_graphics */
            t->stepped_down = true;
            t->backlog_since = t->keeping_since = 0.0;
            t->up_after = t->up_after > 0.0 ? 2.0 * t->up_after : KEEP_UP_S;
            app_say(&t->app, SAID_ERROR, "the terminal is not keeping up: refresh low (the "
                    "Refresh control turns it back)");
        }
        return;
    }
    if (!t->stepped_down)
        return;
    t->keeping_since = backlog ? 0.0 : t->keeping_since > 0.0 ? t->keeping_since : now;
    if (t->keeping_since > 0.0 && now - t->keeping_since >= t->up_after) {
        t->app.cfg.low_bandwidth = false;
        t->stepped_down = false;
        t->keeping_since = 0.0;
        app_say(&t->app, SAID_NOTE, "the terminal keeps up again: refresh normal");
    }
}

/* The charts drawn as the Graphics and Refresh controls say, whatever changed them (a
 * key, the mouse, a typed value, a lesson, a slow link), and as the terminal answered
 * once it has; a Graphics control (or --graphics) asking for pixels that cannot be says
 * why. */
static void follow_graphics(struct tui *t)
{
    struct app *app = &t->app;
    bool asked = t->gfx.want != app->cfg.graphics;
    bool followed = graphics_follow(&t->gfx, app->cfg.graphics, app->cfg.low_bandwidth);
    bool settled = graphics_settle(&t->gfx);
    if (!followed && !settled)
        return;
    if (app->graphics_now != graphics_now(&t->gfx))
        t->plots_dirty = true;
    app->graphics_now = graphics_now(&t->gfx);
    if ((asked || settled) && t->gfx.said[0])
        app_say(app, SAID_ERROR, "%s %s: %s", t->gfx_start ? "--graphics" : "Graphics",
                config_options[CFG_GRAPHICS].choice_name((int)app->cfg.graphics), t->gfx.said);
    else if (settled && t->gfx.late_taken && t->gfx.mode != GRAPHICS_BRAILLE)
        app_say(app, SAID_NOTE, "the terminal's answers came late (a slow link): %s charts "
                "now", graphics_name(t->gfx.mode));
    if (settled)
        t->gfx_start = false;
}

/* One step of the chain for the clock: a lesson's run stops at its end. */
static bool lesson_step(void *ctx)
{
    struct tui *t = ctx;
    return teach_step(&t->teach, &t->app);
}

/* A paste that ended (answer.h): its text into the value being typed, else dropped and
 * said, so that pasted text never acts as a flood of keys. */
static void take_paste(struct tui *t, struct answer_scan *s)
{
    if (!s->pastes)
        return;
    s->pastes = 0;
    if (t->overlay.kind == OVERLAY_EDIT)
        answer_paste_keys(s);
    else
        app_say(&t->app, SAID_NOTE, "pasted text ignored (Enter on a control takes a value "
                "pasted)");
}

/* The next key within ms milliseconds, or ERR: what the terminal sends goes through the
 * answers' scanner first (answer.h), so an answer to the start-up queries arriving late is
 * never taken for keys, and keys typed while the queries were out come first. All that
 * has come is read before a key is taken: a paste (bracketed, or a burst of text from a
 * terminal without) is told whole. */
static int next_key(struct tui *t, int ms)
{
    struct answer_scan *s = &t->gfx.answers;
    for (;;) {
        take_paste(t, s);
        int k = answer_key(s);
        if (k >= 0)
            return k;
        /* A lone Esc waits the rest of its hold for what may follow it (a link can part
         * an answer right after its Esc: longer while answers are due). */
        bool due = graphics_awaiting(&t->gfx);
        int wait = ms;
        if (s->nheld == 1) {
            double hold = due ? ANSWER_ESC_HOLD : ANSWER_ESC_WAIT;
            int left = (int)((hold - (app_clock_now() - s->last)) * 1000.0) + 1;
            wait = left < 0 ? 0 : left < ms ? left : ms;
        }
        timeout(wait);
        int ch = getch();
        double now = app_clock_now();
        if (ch == ERR) {
            if (due)
                answer_idle_awaiting(s, now);
            else
                answer_idle(s, now);
            k = answer_key(s);
            return k >= 0 ? k : ERR;
        }
        do { /* no key was waiting: the keys now are those read at once */
            if (answer_feed(s, ch, now))
                graphics_heard(&t->gfx, s->answer);
            timeout(0);
        } while ((ch = getch()) != ERR);
        if (t->overlay.kind != OVERLAY_EDIT) /* there every character is the value's */
            answer_burst(s);
    }
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

/* The key of action a as this terminal shows it: how the app's messages name it. */
static const char *action_key(int a)
{
    return input_key_name(a, term_utf8());
}

/* Sets t up: the app, the recording, the terminal, the graphics' queries, a lesson and
 * the first message. False when it cannot (said on stderr, what was set up undone). */
static bool tui_start(struct tui *t, const struct config *cfg, const char *exe_dir,
                      const struct lesson *lesson)
{
    memset(t, 0, sizeof *t);
    t->enlarged = -1;
    if (app_init_named(&t->app, cfg, exe_dir, action_key, true) != 0) {
        fprintf(stderr, "springsim: out of memory\n");
        return false;
    }
    t->sel.elem = 1;
    char why[4600];
    if (cfg->record && record_start(&t->rec, cfg->record, &t->app, why, sizeof why) != 0) {
        fprintf(stderr, "springsim: --record: %s\n", why);
        app_free(&t->app);
        return false;
    }
    if (!term_start(cfg->color, cfg->glyphs)) {
        record_abandon(&t->rec);
        app_free(&t->app);
        return false;
    }
    /* Asked once curses has the terminal (no echo, no line buffering): the answers come in
     * with the keys, and the first frames are braille until they have. */
    graphics_detect(&t->gfx, cfg);
    t->gfx_start = t->gfx.waiting;
    t->app.graphics_now = graphics_now(&t->gfx);
    t->teach.view = -1;
    t->teach.gfx = &t->gfx;
    screen_relayout(t);
    if (lesson) {
        teach_start(&t->teach, lesson, &t->app, cfg->replay != NULL);
        keys_after_teach(t, false);
    }
    if (t->gfx.said[0])
        app_say(&t->app, SAID_ERROR, "--graphics %s: %s",
                config_options[CFG_GRAPHICS].choice_name((int)cfg->graphics), t->gfx.said);
    if (t->app.message[0] == '\0' && !lesson) /* a lesson's panel says what space does */
        app_say(&t->app, SAID_NOTE, "%s starts; %s lists every key", app_key(&t->app, ACT_RUN),
                app_key(&t->app, ACT_HELP));
    return true;
}

/* One frame at now (the last at *last): a lesson's next items, the chain stepped for the
 * time gone, the recording kept within its bounds, and the screen drawn, the plots
 * refreshed when they are due. */
static void frame(struct tui *t, double now, double *last)
{
    /* A lesson's run that ended, or its wait, goes on to its next items. */
    if (teach_tick(&t->teach, &t->app, now))
        keys_after_teach(t, true);
    /* Never spend more than half a frame computing: fall behind and say so. */
    /* A replay's chain moves in its runs alone: its waits were paused. */
    bool run = t->teach.playing || (t->teach.demo && teach_shown(&t->teach) && !t->teach.done);
    app_clock_follow(&t->clock, &t->app, now - *last, 0.5 / frame_hz(t),
                     run ? lesson_step : NULL, run ? t : NULL);
    follow_graphics(t);
    *last = now;
    if (t->rec.mem && sim_time(t->app.sim) - t->rec.t >= RECORD_RUN_MAX)
        record_time(&t->rec, &t->app);
    /* Ended (and written) while a second of motion at this pace still fits a
     * lesson's bound: a frame runs far less than that. */
    if (record_full(&t->rec, &t->app, app_clock_pace(&t->app) + sim_dt(t->app.sim)))
        record_full_finish(&t->rec, &t->app);
    /* Plots refresh at plot_hz() while running (the modes view's shapes swing even
     * while paused), as images no faster than they can be sent, and at once after
     * anything else. */
    bool moving = t->app.running || t->views.shown == VIEW_MODES;
    bool refresh = t->plots_dirty || (moving && now >= t->plot_due && graphics_ready(&t->gfx));
    if (refresh) {
        t->plot_due = now + 1.0 / plot_hz(t);
        t->plots_dirty = false;
    }
    watch_backlog(t, draw(t, refresh));
}

/* Waits for input until the next frame, taking every key that is there; false to quit. */
static bool take_keys(struct tui *t, double next_frame)
{
    for (;;) {
        int ms = (int)((next_frame - app_clock_now()) * 1000.0);
        int ch = next_key(t, ms > 0 ? ms : 0);
        if (ch == ERR) {
            /* No key, or no terminal: a hung-up one gives ERR at once, for ever, and
             * SIGHUP may never come (it was ignored, or this is not the controlling
             * terminal). */
            term_check_hangup();
            return true;
        }
        if (!keys_on_key(t, ch))
            return false;
        if (term_quit_signal())
            return true;
    }
}

int tui_run(const struct config *cfg, const char *exe_dir, const struct lesson *lesson)
{
    static struct tui t;
    if (!tui_start(&t, cfg, exe_dir, lesson))
        return EXIT_FAILURE;
    double last = app_clock_now(), next_frame = last;
    bool go = true;
    while (go && !term_quit_signal()) {
        double now = app_clock_now();
        frame(&t, now, &last);
        double hz = frame_hz(&t);
        next_frame += 1.0 / hz;
        if (next_frame < now)
            next_frame = now + 1.0 / hz;
        go = take_keys(&t, next_frame);
    }
    term_stop();
    int status = EXIT_SUCCESS;
    char why[4600];
    if (t.rec.mem && record_finish(&t.rec, &t.app, why, sizeof why) != 0) {
        fprintf(stderr, "springsim: --record: %s\n", why);
        status = EXIT_FAILURE;
    }
    term_die_of_signal();
    tui_free(&t);
    return status;
}
