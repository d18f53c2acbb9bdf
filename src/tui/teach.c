/* teach.c: a lesson, or a demo, in the interactive program (teach.h). */
#include "teach.h"

#include <stdio.h>
#include <string.h>

#include <curses.h>

#include "../lab/caption.h"
#include "../app/clock.h"
#include "../app/command.h"
#include "draw.h"
#include "term.h"

#define RUN_WINDOW_MAX 60.0 /* a run longer than this is shown by its last 60 s */
#define PANEL_LINES 96      /* caption lines kept, at most */

/* Whether k stops what the program computes at once. */
static bool stops(int k)
{
    return k == 27 || k == 'q' || k == 3;
}

/* Esc, q or Ctrl+C typed (or a signal that ends the program) while the program computes
 * at once: the lesson's check, a step back, a run finished. What the terminal sent goes
 * through the answers' scanner (answer.h), as every key does, so that an answer arriving
 * now is no Esc; the keys typed meanwhile stay there, in their order, for when it is done
 * (space pressed four times goes on four times), but the one that stopped it. */
static bool key_stop(void *ctx)
{
    struct teach *t = ctx;
    struct answer_scan *s = &t->gfx->answers;
    int ch;
    timeout(0);
    while ((ch = getch()) != ERR)
        if (answer_feed(s, ch, app_clock_now()))
            graphics_heard(t->gfx, s->answer);
    if (graphics_awaiting(t->gfx))
        answer_idle_awaiting(s, app_clock_now());
    else
        answer_idle(s, app_clock_now());
    for (int i = s->key_at; i < s->nkeys; i++)
        if (stops(s->keys[i])) {
            memmove(s->keys + i, s->keys + i + 1,
                    (size_t)(s->nkeys - i - 1) * sizeof *s->keys);
            s->nkeys--;
            return true;
        }
    return term_quit_signal() != 0;
}

/* A run begins, played: the time plots' window takes the whole run, or its last
 * RUN_WINDOW_MAX seconds, and the plots fit their scales to it anew. A demo keeps the
 * window its recording had. */
static void play_run(struct teach *t, struct app *app, double seconds)
{
    t->run_end = sim_time(app->sim) + seconds;
    t->playing = true;
    app->running = true; /* as lesson_run_to: the chain runs, nothing said */
    if (!t->demo) {
        double w = seconds < 1.0 ? 1.0 : seconds > RUN_WINDOW_MAX ? RUN_WINDOW_MAX : seconds;
        app->cfg.window = w;
        t->fit = true;
    }
    if (t->held)
        app->running = false;
}

/* One command of the lesson, done as the plain mode does it; a run plays (at_once: is
 * stepped at once, the same steps, until at_once says stop), a view is handed to the
 * caller, a query's answer (modes) goes to the status line. */
static void do_command(struct teach *t, struct app *app, const char *line,
                       struct lesson_stop *at_once)
{
    static struct command_result res; /* one command at a time */
    enum command_reply r = command_do(app, line, &res);
    if (r == REPLY_RUN && at_once)
        lesson_run_to(app, sim_time(app->sim) + res.seconds, at_once);
    else if (r == REPLY_RUN)
        play_run(t, app, res.seconds);
    else if (r == REPLY_VIEW)
        t->view = res.view;
    else if (r == REPLY_ERROR)
        app_say(app, SAID_ERROR, "%s: %s", t->lesson->name, res.answer);
    else if (r == REPLY_OK && !app->message[0])
        app_say(app, SAID_NOTE, "%s", res.answer);
}

static void do_item(struct teach *t, struct app *app, const struct lesson_item *it,
                    struct lesson_stop *at_once)
{
    switch (it->kind) {
    case LESSON_COMMAND:
        do_command(t, app, it->text, at_once);
        break;
    case LESSON_SETUP:
        lesson_setup(app, t->lesson, it);
        break;
    case LESSON_WAIT:
        if (!at_once)
            t->wait_end = app_clock_now() + it->value;
        break;
    case LESSON_EXPECT:
        if (lesson_state_is(app, it->text))
            app_say(app, SAID_NOTE, "replayed: the state at t = %.*f s is the one recorded, bit "
                    "for bit", app_time_decimals(sim_dt(app->sim)), sim_time(app->sim));
        else
            app_say(app, SAID_ERROR, "replayed, but the state differs from the one recorded");
        break;
    default:
        break;
    }
}

/* Plays on to the next pause, question, played run or wait, or to the end. */
static void play_on(struct teach *t, struct app *app)
{
    const struct lesson_item *it;
    while (!t->playing && !t->wait_end && (it = lesson_next(&t->play))) {
        if (it->kind == LESSON_SAY || it->kind == LESSON_PAUSE || it->kind == LESSON_ASK)
            t->scroll = 0;
        do_item(t, app, it, NULL);
    }
    if (!t->playing && !t->wait_end && t->play.waiting < 0)
        t->done = true;
}

/* Leaves the lesson, the chain as it is. */
static void leave(struct teach *t, struct app *app, bool said)
{
    if (said)
        app_say(app, SAID_NOTE, "left the %s %s: the chain is as it is",
                t->demo ? "replay of" : "lesson", t->lesson->name);
    if (t->playing)
        app_set_running(app, false);
    t->lesson = NULL;
    t->done = t->playing = t->held = false;
    t->wait_end = 0.0;
}

/* The run playing ends at once, by the steps it would have taken played; false when
 * Esc, q or Ctrl+C left the lesson meanwhile (a long run of a heavy chain). */
static bool finish_run(struct teach *t, struct app *app)
{
    struct lesson_stop stop = {.fn = key_stop, .ctx = t};
    if (t->playing)
        lesson_run_to(app, t->run_end, &stop);
    t->playing = false;
    t->wait_end = 0.0;
    if (stop.said)
        leave(t, app, true);
    return !stop.said;
}

void teach_start(struct teach *t, const struct lesson *l, struct app *app, bool demo)
{
    t->lesson = l;
    t->done = t->playing = t->held = false;
    t->demo = demo;
    t->wait_end = 0.0;
    t->note[0] = '\0';
    t->view = -1;
    t->scroll = 0;
    app->speed = 1.0; /* the lesson's speed, until it says another */
    app_quiet(app);
    lesson_play_start(&t->play, l);
    play_on(t, app);
}

void teach_open(struct teach *t, const char *path, struct app *app)
{
    static struct config base; /* large */
    char err[2048];
    if (t->lesson == &t->own)
        t->lesson = NULL;
    lesson_free(&t->own);
    int st = lesson_read(path, &t->own, err, sizeof err);
    if (st == 0) {
        struct lesson_stop stop = {.fn = key_stop, .ctx = t};
        config_init(&base);
        base.color = app->cfg.color;
        base.glyphs = app->cfg.glyphs;
        st = lesson_check(&t->own, &base, app->exe_dir, &stop, err, sizeof err);
    }
    if (st != 0) {
        lesson_free(&t->own);
        app_say(app, st == LESSON_LEFT ? SAID_NOTE : SAID_ERROR, "%s", err);
        return;
    }
    teach_start(t, &t->own, app, false);
}

bool teach_shown(const struct teach *t)
{
    return t->lesson != NULL;
}

bool teach_tick(struct teach *t, struct app *app, double now)
{
    if (!t->lesson || t->held)
        return false;
    if (t->wait_end) {
        if (now < t->wait_end)
            return false;
        t->wait_end = 0.0;
    } else if (t->playing) {
        /* Its end, or a blow-up that paused the chain (lesson_run_to stops there too). */
        if (!lesson_run_over(app, t->run_end) && app->running)
            return false;
        app_set_running(app, false);
        t->playing = false;
    } else {
        return false;
    }
    play_on(t, app);
    return true;
}

bool teach_step(struct teach *t, struct app *app)
{
    if (!t->playing || lesson_run_over(app, t->run_end))
        return false;
    return app_step(app) != 0;
}

/* The lesson's parts as its title counts them: its steps, and what follows the last. */
static int parts(const struct lesson *l)
{
    int last = l->steps ? lesson_step_end(l, l->steps - 1) : -1;
    for (int i = last + 1; i < l->count; i++)
        if (l->items[i].kind != LESSON_EXPECT)
            return l->steps + 1;
    return l->steps;
}

/* Back to the end of the step before this one: the lesson played again from its start
 * to there, at once (the same commands, the same state); Esc, q or Ctrl+C leave it. */
static void back(struct teach *t, struct app *app)
{
    int target = t->play.step - (t->done ? 0 : 1);
    if (target < 0) {
        app_say(app, SAID_NOTE, "the first step: space goes on");
        return;
    }
    int end = lesson_step_end(t->lesson, target);
    const struct lesson_item *it;
    struct lesson_stop stop = {.fn = key_stop, .ctx = t};
    double next = 0.0;
    t->playing = false;
    t->wait_end = 0.0;
    lesson_play_start(&t->play, t->lesson);
    while ((it = lesson_next(&t->play))) {
        if (it->kind == LESSON_COMMAND && app_clock_now() >= next) {
            next = app_clock_now() + LESSON_POLL;
            if (key_stop(t)) {
                leave(t, app, true);
                return;
            }
        }
        do_item(t, app, it, &stop);
        if (stop.said) {
            leave(t, app, true);
            return;
        }
        if (t->play.waiting >= 0 && t->play.waiting != end)
            lesson_go_on(&t->play);
    }
    t->done = false;
    t->note[0] = '\0';
    t->scroll = 0;
    t->fit = true;
    app_say(app, SAID_NOTE, "back to step %d of %d", target + 1, parts(t->lesson));
}

/* The panel's lines at w columns into lines: the note, the caption, then the question
 * and its choices (from *question on); returns their count. */
static int panel_lines(const struct teach *t, int w, char (*lines)[CAPTION_LINE], int *question)
{
    static char text[4 * LESSON_CAPTION + 64], safe[4 * LESSON_CAPTION + 64];
    const struct lesson *les = t->lesson;
    bool utf8 = term_utf8();
    int n = 0;
    if (t->note[0]) {
        caption_text(t->note, utf8, safe, sizeof safe);
        n = caption_wrap(safe, w, lines, n, PANEL_LINES);
    }
    /* The step's say lines are one paragraph. */
    snprintf(text, sizeof text, "%s", t->play.new_caption ? "" : t->play.caption);
    for (char *c = text; *c; c++)
        if (*c == '\n')
            *c = ' ';
    caption_text(text, utf8, safe, sizeof safe);
    n = caption_wrap(safe, w, lines, n, PANEL_LINES);
    const struct lesson_item *it = t->play.waiting >= 0 ? &les->items[t->play.waiting] : NULL;
    *question = it && it->kind == LESSON_ASK ? n : PANEL_LINES;
    if (!it || it->kind != LESSON_ASK)
        return n;
    caption_text(it->text, utf8, safe, sizeof safe);
    n = caption_wrap(safe, w, lines, n, PANEL_LINES);
    /* A choice a line (↓ scrolls to those that do not fit). */
    for (int k = 0; k < it->nchoices; k++) {
        snprintf(text, sizeof text, "  %d) %s", k + 1, it->choice[k]);
        caption_text(text, utf8, safe, sizeof safe);
        n = caption_wrap(safe, w, lines, n, PANEL_LINES);
    }
    return n;
}

/* The most the caption can scroll in the panel of l: lines past its rows. */
static int scroll_max(const struct teach *t, const struct layout *l)
{
    static char lines[PANEL_LINES][CAPTION_LINE];
    int question, rows = l->caption.h - 2;
    if (rows < 1)
        return 0;
    int n = panel_lines(t, l->caption.w - 4, lines, &question);
    return n > rows ? n - rows : 0;
}

/* Space, '.' and Esc in a demo: pause and play on, skip to the next command, leave. A
 * '.' more than the commands left does nothing: the chain stays where the recording
 * ended, and its verdict stays on the screen. */
static bool demo_key(struct teach *t, struct app *app, int ch)
{
    if (ch == ' ' && t->done) {
        leave(t, app, false);
        return true;
    }
    if (ch == '.' && t->done)
        return true;
    if (ch == ' ' && !t->held) {
        t->held = true;
        t->held_at = app_clock_now();
        if (t->playing)
            app->running = false;
        app_say(app, SAID_NOTE, "replay paused: space plays on, . the next command");
    } else if (ch == ' ') {
        t->held = false;
        if (t->wait_end)
            t->wait_end += app_clock_now() - t->held_at;
        if (t->playing)
            app->running = true;
        app_quiet(app);
    } else if (ch == '.' && !t->done) {
        if (!finish_run(t, app))
            return true;
        play_on(t, app);
        if (t->held && t->playing)
            app->running = false;
    } else {
        return false;
    }
    return true;
}

/* A digit that answers the question asked. */
static void answer(struct teach *t, struct app *app, const struct lesson_item *ask, int k)
{
    if (ask->answer == k)
        snprintf(t->note, sizeof t->note, "You chose %d: right.", k);
    else if (ask->answer)
        snprintf(t->note, sizeof t->note, "You chose %d; the answer is %d: watch why.", k,
                 ask->answer);
    else
        snprintf(t->note, sizeof t->note, "You chose %d.", k);
    app_quiet(app);
    lesson_go_on(&t->play);
    play_on(t, app);
}

bool teach_key(struct teach *t, struct app *app, const struct layout *l, int ch)
{
    if (!t->lesson)
        return false;
    const struct lesson_item *ask =
        t->play.waiting >= 0 && t->lesson->items[t->play.waiting].kind == LESSON_ASK
            ? &t->lesson->items[t->play.waiting] : NULL;
    if (ch == 27) {
        leave(t, app, !t->done);
        return true;
    }
    if (ch == KEY_DOWN || ch == KEY_UP) {
        int most = scroll_max(t, l), s = t->scroll + (ch == KEY_DOWN ? 1 : -1);
        if (most == 0)
            return false; /* the arrows' own work: nothing is cut */
        t->scroll = s < 0 ? 0 : s > most ? most : s;
        return true;
    }
    if (t->demo)
        return demo_key(t, app, ch);
    if (ch == ',') {
        back(t, app);
        return true;
    }
    if (ask && ch >= '1' && ch <= '0' + ask->nchoices) {
        answer(t, app, ask, ch - '0');
        return true;
    }
    if (ch != ' ')
        return false;
    if (t->playing || t->wait_end) {
        if (finish_run(t, app))
            play_on(t, app);
    } else if (t->done) {
        leave(t, app, false);
        app_say(app, SAID_NOTE, "end of the lesson: the chain is yours (? lists every key)");
    } else if (ask) {
        app_say(app, SAID_NOTE, "answer first: a digit from 1 to %d", ask->nchoices);
    } else {
        t->note[0] = '\0';
        app_quiet(app);
        lesson_go_on(&t->play);
        play_on(t, app);
    }
    return true;
}

void teach_keys(const struct teach *t, const char **space_key, const char **space,
                const char **dot, const char **comma)
{
    static char digits[8];
    *space_key = "space";
    *space = *dot = *comma = NULL;
    if (!t->lesson)
        return;
    bool ask = t->play.waiting >= 0 && t->lesson->items[t->play.waiting].kind == LESSON_ASK;
    if (t->done)
        *space = "close";
    else if (t->demo)
        *space = t->held ? "play on" : "pause";
    else if (t->playing || t->wait_end)
        *space = "end the run";
    else if (ask) {
        snprintf(digits, sizeof digits, "1-%d", t->lesson->items[t->play.waiting].nchoices);
        *space_key = digits;
        *space = "answer";
    } else
        *space = "go on";
    if (t->demo)
        *dot = "next";
    else
        *comma = "back a step";
}

/* The keys that work now, as the panel's footer says them. */
static void footer(const struct teach *t, char *keys, size_t len)
{
    const struct lesson_item *it =
        t->play.waiting >= 0 ? &t->lesson->items[t->play.waiting] : NULL;
    if (t->done)
        snprintf(keys, len, " space or Esc closes ");
    else if (t->demo)
        snprintf(keys, len, " space %s  . next  Esc leaves ", t->held ? "plays on" : "pauses");
    else if (t->playing || t->wait_end)
        snprintf(keys, len, " space ends the run  , back  Esc leaves ");
    else if (it && it->kind == LESSON_ASK)
        snprintf(keys, len, " 1-%d answers  , back  Esc leaves ", it->nchoices);
    else
        snprintf(keys, len, " space goes on  , back  Esc leaves ");
}

void teach_draw(const struct teach *t, const struct layout *l)
{
    static char lines[PANEL_LINES][CAPTION_LINE];
    struct rect r = l->caption;
    if (!t->lesson || r.h < 3)
        return;
    const struct lesson *les = t->lesson;
    char title[1000], name[4 * 200 + 8], keys[80];
    caption_text(les->title, term_utf8(), name, sizeof name);
    if (t->done)
        snprintf(title, sizeof title, " %s %s: the end ", t->demo ? "Replay" : "Lesson", name);
    else if (t->demo)
        snprintf(title, sizeof title, " Replay%s: %s ", t->held ? " (paused)" : "", name);
    else
        snprintf(title, sizeof title, " Lesson %d/%d: %s ", t->play.step + 1, parts(les), name);
    draw_clear(r);
    draw_frame(r, title, false);
    int w = r.w - 4, rows = r.h - 2, question;
    int n = panel_lines(t, w, lines, &question);
    int first = t->scroll > n - rows ? n - rows : t->scroll;
    if (first < 0)
        first = 0;
    for (int i = first; i < n && i < first + rows; i++)
        draw_text_attr(r.y + 1 + i - first, r.x + 2, w, i >= question ? A_BOLD : A_NORMAL,
                       lines[i]);
    /* What is cut, said on the frame: ↓ more below, ↑ above. */
    const char *more = first + rows < n ? (first > 0 ? " ↑↓ more " : " ↓ more ")
                                        : first > 0 ? " ↑ more " : NULL;
    if (more)
        draw_text_attr(r.y + r.h - 1, r.x + 2, draw_width(more), term_attr(PAIR_TITLE) | A_BOLD,
                       more);
    footer(t, keys, sizeof keys);
    int kw = draw_width(keys), mw = more ? draw_width(more) + 2 : 0;
    if (kw < r.w - 2 - mw)
        draw_text_attr(r.y + r.h - 1, r.x + r.w - 1 - kw, kw, term_attr(PAIR_TITLE), keys);
}

void teach_free(struct teach *t)
{
    lesson_free(&t->own);
    t->lesson = NULL;
}
