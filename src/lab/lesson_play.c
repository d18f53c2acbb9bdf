/* lesson_play.c: playing a lesson, without a terminal: where the player is (a caption
 * gathered, a pause or a question waited on), the dry run that checks every command
 * before anything runs, the runs stepped at once, a setup block put in force and the
 * exact state an expect line holds. The front ends (plain/, tui/) do each item their own
 * way: a command through command_do, as they do the user's. */
#include "lesson.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../core/model.h"
#include "../core/preset.h"
#include "../app/cost.h"
#include "../app/app.h"
#include "../app/clock.h"
#include "../app/command.h"

bool lesson_run_over(const struct app *app, double end)
{
    return !(sim_time(app->sim) < end - 1e-9 * app->cfg.dt);
}

/* Whether stop says to stop, asked at most every LESSON_POLL wall seconds (*next: when
 * it is asked next). */
static bool stopped(struct lesson_stop *stop, double *next)
{
    if (!stop || !stop->fn)
        return false;
    if (stop->said)
        return true;
    double now = app_clock_now();
    if (now < *next)
        return false;
    *next = now + LESSON_POLL;
    stop->said = stop->fn(stop->ctx);
    return stop->said;
}

bool lesson_run_to(struct app *app, double end, struct lesson_stop *stop)
{
    bool ok = true;
    double next = 0.0;
    app->running = true;
    for (long k = 0; !lesson_run_over(app, end); k++)
        if (!app_step(app) || ((k & 255) == 255 && stopped(stop, &next)) ||
            (app->work_limit > 0.0 && app->work > app->work_limit)) {
            ok = false;
            break;
        }
    app_set_running(app, false);
    return ok;
}

bool lesson_run(struct app *app, double seconds)
{
    return lesson_run_to(app, sim_time(app->sim) + seconds, NULL);
}

void lesson_state(const struct app *app, char *buf, size_t len)
{
    const struct sim *s = app->sim;
    const double *x = sim_x(s), *v = sim_v(s);
    size_t used = (size_t)snprintf(buf, len, "t=%a", sim_time(s));
    for (int i = 0; i < sim_model(s)->n && used < len; i++)
        used += (size_t)snprintf(buf + used, len - used, " x%d=%a v%d=%a", i + 1, x[i], i + 1,
                                 v[i]);
}

/* Whether the number text starts with (up to its end, a blank or the end of text) is a,
 * bit for bit; *text moves past it. */
static bool same_number(const char **text, double a)
{
    char *end;
    double b = strtod(*text, &end);
    bool same = end != *text && (*end == ' ' || *end == '\0') &&
                memcmp(&a, &b, sizeof a) == 0;
    *text = end;
    return same;
}

bool lesson_state_is(const struct app *app, const char *text)
{
    const struct sim *s = app->sim;
    const double *x = sim_x(s), *v = sim_v(s);
    const char *p = text;
    if (strncmp(p, "t=", 2) != 0 || (p += 2, !same_number(&p, sim_time(s))))
        return false;
    for (int i = 0; i < sim_model(s)->n; i++) {
        char name[2][16];
        snprintf(name[0], sizeof name[0], " x%d=", i + 1);
        snprintf(name[1], sizeof name[1], " v%d=", i + 1);
        for (int k = 0; k < 2; k++) {
            size_t len = strlen(name[k]);
            if (strncmp(p, name[k], len) != 0)
                return false;
            p += len;
            if (!same_number(&p, k ? v[i] : x[i]))
                return false;
        }
    }
    return *p == '\0';
}

int lesson_setup(struct app *app, const struct lesson *l, const struct lesson_item *it)
{
    const char *name = l->title[0] ? l->name : "setup";
    return app_load_preset_text(app, l->path, it->text, strlen(it->text), name) ? 0 : -1;
}

/* A setup block's preset: valid, and within the interactive program's ranges; 0, or -1
 * with "PATH:LINE: what" in err. */
static int setup_check(const struct lesson *l, const struct lesson_item *it, char *err,
                       size_t errlen)
{
    static struct config c; /* large */
    char why[600];
    config_init(&c);
    if (preset_parse(l->path, it->text, strlen(it->text), &c, err, errlen) != PRESET_OK)
        return -1;
    int key = config_check_interactive(&c, why, sizeof why);
    if (key < 0) {
        /* The settings together (an amplitude that leaves the blocks no room, exact with
         * cubic springs): said at the line of the one named. */
        struct model *m = config_model(&c, &key, why, sizeof why);
        model_free(m);
        if (m || key < 0)
            return 0;
    }
    const struct config_origin *o = &c.origin[key];
    snprintf(err, errlen, "%s:%d: %s: %s", l->path, o->file ? o->line : it->line,
             config_options[key].name, why);
    return -1;
}

/* "PATH:LINE: WHAT: the lesson's KIND pass here the mass-steps..." into err. */
static void past_work(const struct lesson *l, const struct lesson_item *it, const char *what,
                      const char *kind, char *err, size_t errlen)
{
    snprintf(err, errlen, "%s:%d: %s: the lesson's %s pass here the %.3g mass-steps a lesson "
             "may compute (steps times masses, more for a drive's sub-steps and for contacts, "
             "%.0f a mass for each change of the chain or the drive)", l->path, it->line, what,
             kind, LESSON_MAX_WORK, COST_CHANGE);
}

int lesson_check(const struct lesson *l, const struct config *base, const char *exe_dir,
                 struct lesson_stop *stop, char *err, size_t errlen)
{
    static struct app app; /* large; one check at a time */
    static struct command_result res;
    if (app_init(&app, base, exe_dir) != 0) {
        snprintf(err, errlen, "%s: out of memory", l->path);
        return 1;
    }
    int st = 0;
    double next = 0.0;
    app.work_limit = LESSON_MAX_WORK;
    for (int i = 0; i < l->count && !st; i++) {
        const struct lesson_item *it = &l->items[i];
        if (stopped(stop, &next))
            break;
        if (it->kind == LESSON_SETUP) {
            if (setup_check(l, it, err, errlen) != 0) {
                st = 2;
            } else if (lesson_setup(&app, l, it) != 0) {
                /* The preset's own message names the file and its line already. */
                snprintf(err, errlen, "%s", app.message);
                st = 2;
            } else if (app.work > LESSON_MAX_WORK) {
                past_work(l, it, "setup", "changes", err, errlen);
                st = 2;
            }
            continue;
        }
        if (it->kind != LESSON_COMMAND)
            continue;
        enum command_reply r = command_do(&app, it->text, &res);
        if (r == REPLY_ERROR) {
            snprintf(err, errlen, "%s:%d: %s", l->path, it->line, res.answer);
            st = 2;
        } else if (r == REPLY_RUN) {
            lesson_run_to(&app, sim_time(app.sim) + res.seconds, stop);
            if (app.work > LESSON_MAX_WORK) {
                past_work(l, it, it->text, "runs", err, errlen);
                st = 2;
            }
        } else if (app.work > LESSON_MAX_WORK) {
            past_work(l, it, it->text, "changes", err, errlen);
            st = 2;
        }
    }
    if (!st && stop && stop->said) {
        snprintf(err, errlen, "%s: the check was left before its end (nothing ran)", l->path);
        st = LESSON_LEFT;
    }
    app_free(&app);
    return st;
}

void lesson_play_start(struct lesson_play *p, const struct lesson *l)
{
    memset(p, 0, sizeof *p);
    p->lesson = l;
    p->waiting = -1;
    p->new_caption = true;
}

const struct lesson_item *lesson_next(struct lesson_play *p)
{
    const struct lesson *l = p->lesson;
    if (p->waiting >= 0 || p->next >= l->count)
        return NULL;
    const struct lesson_item *it = &l->items[p->next++];
    if (it->kind == LESSON_SAY) {
        size_t used = p->new_caption ? 0 : strlen(p->caption);
        snprintf(p->caption + used, sizeof p->caption - used, "%s%s", used ? "\n" : "",
                 it->text);
        p->new_caption = false;
    } else if (it->kind == LESSON_PAUSE || it->kind == LESSON_ASK) {
        p->waiting = (int)(it - l->items);
    }
    return it;
}

void lesson_go_on(struct lesson_play *p)
{
    if (p->waiting < 0)
        return;
    p->waiting = -1;
    p->step++;
    p->new_caption = true;
}

int lesson_step_end(const struct lesson *l, int step)
{
    for (int i = 0, k = 0; i < l->count; i++)
        if (l->items[i].kind == LESSON_PAUSE || l->items[i].kind == LESSON_ASK)
            if (k++ == step)
                return i;
    return -1;
}
