/* teach.c: a lesson in the interactive program (teach.h). */
#include "teach.h"

#include <stdio.h>
#include <string.h>

#include <curses.h>

#include "../app/command.h"
#include "draw.h"
#include "term.h"

/* One command of the lesson, done as the plain mode does it; a run is stepped at once
 * (the plots show what it did), a view is handed to the caller, a query's answer (modes)
 * goes to the status line. */
static void do_command(struct teach *t, struct app *app, const char *line)
{
    static struct command_result res; /* one command at a time */
    enum command_reply r = command_do(app, line, &res);
    if (r == REPLY_RUN)
        lesson_run(app, res.seconds);
    else if (r == REPLY_VIEW)
        t->view = res.view;
    else if (r == REPLY_ERROR)
        app_say(app, SAID_ERROR, "%s: %s", t->lesson->name, res.answer);
    else if (r == REPLY_OK && !app->message[0])
        app_say(app, SAID_NOTE, "%s", res.answer);
}

static void do_item(struct teach *t, struct app *app, const struct lesson_item *it)
{
    char now[4096];
    switch (it->kind) {
    case LESSON_COMMAND:
        do_command(t, app, it->text);
        break;
    case LESSON_SETUP:
        lesson_setup(app, t->lesson, it);
        break;
    case LESSON_EXPECT:
        lesson_state(app, now, sizeof now);
        if (strcmp(now, it->text) == 0)
            app_say(app, SAID_NOTE, "replayed: the state at t = %.*f s is the one recorded, bit "
                    "for bit", app_time_decimals(sim_dt(app->sim)), sim_time(app->sim));
        else
            app_say(app, SAID_ERROR, "replayed, but the state differs from the one recorded");
        break;
    default:
        break;
    }
}

/* Plays on to the next pause or question, or to the end. */
static void play_on(struct teach *t, struct app *app)
{
    const struct lesson_item *it;
    while ((it = lesson_next(&t->play)))
        do_item(t, app, it);
    if (t->play.waiting < 0)
        t->done = true;
}

void teach_start(struct teach *t, const struct lesson *l, struct app *app)
{
    t->lesson = l;
    t->done = false;
    t->note[0] = '\0';
    t->view = -1;
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
        config_init(&base);
        base.color = app->cfg.color;
        base.glyphs = app->cfg.glyphs;
        st = lesson_check(&t->own, &base, app->exe_dir, err, sizeof err);
    }
    if (st != 0) {
        lesson_free(&t->own);
        app_say(app, SAID_ERROR, "%s", err);
        return;
    }
    teach_start(t, &t->own, app);
}

bool teach_shown(const struct teach *t)
{
    return t->lesson != NULL;
}

/* Leaves the lesson, the chain as it is. */
static void leave(struct teach *t, struct app *app, bool said)
{
    if (said)
        app_say(app, SAID_NOTE, "left the lesson %s: the chain is as it is", t->lesson->name);
    t->lesson = NULL;
    t->done = false;
}

/* Back to the end of the step before this one: the lesson played again from its start
 * to there, at once (the same commands, the same state). */
static void back(struct teach *t, struct app *app)
{
    int target = t->play.step - (t->done ? 0 : 1);
    if (target < 0) {
        app_say(app, SAID_NOTE, "the first step: space goes on");
        return;
    }
    int end = lesson_step_end(t->lesson, target);
    const struct lesson_item *it;
    lesson_play_start(&t->play, t->lesson);
    while ((it = lesson_next(&t->play))) {
        do_item(t, app, it);
        if (t->play.waiting >= 0 && t->play.waiting != end)
            lesson_go_on(&t->play);
    }
    t->done = false;
    t->note[0] = '\0';
    app_say(app, SAID_NOTE, "back to step %d of %d", target + 1, t->lesson->steps);
}

bool teach_key(struct teach *t, struct app *app, int ch)
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
    if (ch == ',') {
        back(t, app);
        return true;
    }
    if (ask && ch >= '1' && ch <= '0' + ask->nchoices) {
        int k = ch - '0';
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
        return true;
    }
    if (ch != ' ')
        return false;
    if (t->done) {
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

/* Cuts text into lines of at most w columns at blanks (a word longer than w is cut),
 * each line into lines[n++] (at most max); returns n. */
static int wrap(const char *text, int w, char lines[][256], int n, int max)
{
    const char *s = text;
    while (*s && n < max) {
        if (*s == '\n') {
            s++;
            continue;
        }
        int len = 0, fit = 0, cols = 0;
        while (s[len] && s[len] != '\n') {
            if (((unsigned char)s[len] & 0xc0) != 0x80)
                cols++;
            if (cols > w || len >= 250)
                break;
            if (s[len] == ' ')
                fit = len;
            len++;
        }
        if (s[len] && s[len] != '\n' && fit > 0)
            len = fit;
        snprintf(lines[n++], 256, "%.*s", len, s);
        s += len;
        while (*s == ' ')
            s++;
    }
    return n;
}

void teach_draw(const struct teach *t, const struct layout *l)
{
    struct rect r = l->caption;
    if (!t->lesson || r.h < 3)
        return;
    const struct lesson *les = t->lesson;
    char title[300], lines[64][256], text[LESSON_CAPTION + 1024];
    int step = t->play.step + 1;
    if (t->done)
        snprintf(title, sizeof title, " Lesson %s: the end ", les->title);
    else
        snprintf(title, sizeof title, " Lesson %d/%d: %s ", step, les->steps, les->title);
    draw_clear(r);
    draw_frame(r, title, false);
    int w = r.w - 4, rows = r.h - 2, n = 0;
    if (t->note[0])
        n = wrap(t->note, w, lines, n, 64);
    n = wrap(t->play.new_caption ? "" : t->play.caption, w, lines, n, 64);
    const struct lesson_item *it =
        t->play.waiting >= 0 ? &les->items[t->play.waiting] : NULL;
    int question = n; /* the first line of the question */
    if (it && it->kind == LESSON_ASK) {
        n = wrap(it->text, w, lines, n, 64);
        /* A choice a line where they fit, else all of them in one paragraph. */
        if (n + it->nchoices <= rows) {
            for (int k = 0; k < it->nchoices; k++) {
                snprintf(text, sizeof text, "  %d) %s", k + 1, it->choice[k]);
                n = wrap(text, w, lines, n, 64);
            }
        } else {
            size_t used = 0;
            text[0] = '\0';
            for (int k = 0; k < it->nchoices && used < sizeof text; k++)
                used += (size_t)snprintf(text + used, sizeof text - used, "%s%d) %s",
                                         k ? "  " : "", k + 1, it->choice[k]);
            n = wrap(text, w, lines, n, 64);
        }
    }
    /* The last lines when they do not all fit: the question and the newest caption. */
    int first = n > rows ? n - rows : 0;
    for (int i = first; i < n; i++) {
        attr_t a = i >= question && it && it->kind == LESSON_ASK ? A_BOLD : A_NORMAL;
        draw_text_attr(r.y + 1 + i - first, r.x + 2, w, a, lines[i]);
    }
    char keys[80];
    if (t->done)
        snprintf(keys, sizeof keys, " space or Esc closes ");
    else if (it && it->kind == LESSON_ASK)
        snprintf(keys, sizeof keys, " 1-%d answers  , back a step  Esc leaves ", it->nchoices);
    else
        snprintf(keys, sizeof keys, " space goes on  , back a step  Esc leaves ");
    int kw = draw_width(keys);
    if (kw < r.w - 2)
        draw_text_attr(r.y + r.h - 1, r.x + r.w - 1 - kw, kw, term_attr(PAIR_TITLE), keys);
}

void teach_free(struct teach *t)
{
    lesson_free(&t->own);
    t->lesson = NULL;
}
