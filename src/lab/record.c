/* record.c: --record, the session written as a lesson file (record.h). */
#include "record.h"

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "../core/preset.h"
#include "../app/app.h"
#include "../app/clock.h"
#include "../app/command.h"
#include "../app/cost.h"
#include "lesson.h"

#ifndef VERSION
#define VERSION "0.1.0"
#endif

/* "PATH: reason" into err, the path escaped. */
static void say_failed(char *err, size_t errlen, const char *path, const char *why)
{
    char safe[1200];
    config_escape(path, strlen(path), 256, safe, sizeof safe);
    snprintf(err, errlen, "%s: %s", safe, why);
}

/* The settings in force, after a setup line: the chain at the start, or a preset
 * loaded (so that the recording replays from any directory, whatever became of the
 * file since). */
static void put_settings(struct record *r, const struct app *app)
{
    preset_write(r->mem, &app->cfg, app->model);
    fputs("end\n", r->mem);
}

int record_start(struct record *r, const char *path, const struct app *app, char *err,
                 size_t errlen)
{
    memset(r, 0, sizeof *r);
    snprintf(r->path, sizeof r->path, "%s", path);
    int e = output_open(&r->out, path);
    if (e) {
        say_failed(err, errlen, path, strerror(e));
        return -1;
    }
    r->mem = open_memstream(&r->text, &r->size);
    if (!r->mem) {
        say_failed(err, errlen, path, strerror(errno));
        record_abandon(r);
        return -1;
    }
    char when[64];
    time_t now = time(NULL);
    strftime(when, sizeof when, "%Y-%m-%d %H:%M", localtime(&now));
    fprintf(r->mem, "# A session recorded by springsim %s (--record), a lesson file:\n"
            "# springsim --replay FILE plays it back to the state on its last line.\n"
            "title Recorded %s\nsay A session recorded with --record: played back, it "
            "ends where the recording ended.\nsetup\n", VERSION, when);
    put_settings(r, app);
    r->t = sim_time(app->sim);
    r->work0 = app->work;
    r->wall = app_clock_now();
    return 0;
}

/* The shortest decimal that `run` replays as the same steps as d seconds at step dt:
 * within dt / 1e10 of d (the replay stops at the first step past the end less dt / 1e9),
 * so the difference of two times on the grid is written as the user would (1.34, not
 * 1.3399999999999999). */
static void format_run(double d, double dt, char *buf, size_t len)
{
    double tol = fabs(dt) * 1e-10;
    /* Plain decimals where they are short (run 500, run 1.34), exponents past them. */
    for (int places = 0; places <= 6 && fabs(d) < 1e15; places++) {
        snprintf(buf, len, "%.*f", places, d);
        if (fabs(strtod(buf, NULL) - d) <= tol)
            return;
    }
    for (int digits = 1; digits <= 17; digits++) {
        snprintf(buf, len, "%.*g", digits, d);
        if (fabs(strtod(buf, NULL) - d) <= tol)
            return;
    }
    config_format_exact(d, buf, len);
}

/* The time run up to t (on a grid of step dt) at `pace` simulated seconds a wall second,
 * as a run line. */
static void run_to(struct record *r, double t, double dt, double pace)
{
    if (!r->mem || !(t > r->t))
        return;
    char num[32];
    format_run(t - r->t, dt, num, sizeof num);
    fprintf(r->mem, "run %s\n", num);
    r->replay_runs = false;
    r->seconds += strtod(num, NULL);
    r->run_wall += (t - r->t) / (pace > 0.0 ? pace : 1.0);
    r->t = t;
}

/* The wall-clock time since the last command that the runs since do not account for,
 * as a wait line (before a command, after its runs). */
static void wait_now(struct record *r)
{
    double now = app_clock_now(), idle = now - r->wall - r->run_wall;
    /* A long idleness as several waits, each one a lesson allows. */
    for (; r->mem && idle >= RECORD_WAIT_MIN; idle -= LESSON_MAX_WAIT)
        fprintf(r->mem, "wait %.2f\n", idle < LESSON_MAX_WAIT ? idle : LESSON_MAX_WAIT);
    r->wall = now;
    r->run_wall = 0.0;
}

/* The chain paused with no time run since the replay's last start (a blow-up at the
 * first step, a pause before a frame ran): `run 0` pauses the replay there too, nothing
 * stepped, as the blown-up step was undone. (A lesson's `pause` waits for the user.) */
static void pause_to(struct record *r, bool running)
{
    if (!r->mem || !r->replay_runs || running)
        return;
    fputs("run 0\n", r->mem);
    r->replay_runs = false;
}

void record_time(struct record *r, const struct app *app)
{
    run_to(r, sim_time(app->sim), app->cfg.dt, app_clock_pace(app));
    pause_to(r, app->running);
}

void record_line(struct record *r, const struct app *app, const char *line)
{
    if (!r->mem)
        return;
    wait_now(r);
    fprintf(r->mem, "%s\n", line);
    r->t = sim_time(app->sim);
    r->replay_runs = app->running;
    r->lines++;
}

void record_command(struct record *r, const struct app *app, const char *line)
{
    const char *w = line + strspn(line, " \t");
    size_t n = strcspn(w, " \t");
    const struct command *cmd = command_find(w, n);
    if (!r->mem || !cmd || !(cmd->flags & COMMAND_RECORDED))
        return;
    char text[2100];
    if (cmd->flags & COMMAND_LOADS) {
        record_line(r, app, "setup");
        put_settings(r, app);
        return;
    }
    if (cmd->flags & COMMAND_SEEDED) {
        /* the seed it drew, so that the replay draws the same positions */
        snprintf(text, sizeof text, "%s %llu", cmd->name, (unsigned long long)app->cfg.seed);
    } else {
        /* the words as typed, their blanks made one */
        size_t o = 0;
        for (const char *s = w; *s && o + 1 < sizeof text;) {
            size_t k = strcspn(s, " \t");
            if (k == 0) {
                s += strspn(s, " \t");
                continue;
            }
            o += (size_t)snprintf(text + o, sizeof text - o, "%s%.*s", o ? " " : "", (int)k, s);
            s += k;
        }
        text[o < sizeof text ? o : sizeof text - 1] = '\0';
    }
    record_line(r, app, text);
}

void record_mark(struct record *r, const struct app *app)
{
    struct record_mark *k = &r->mark;
    const struct model *m = app->model;
    if (!r->mem)
        return;
    k->t = sim_time(app->sim);
    k->n = m->n;
    k->dt = app->cfg.dt;
    k->amplitude = m->motor.amplitude;
    k->frequency = m->motor.frequency;
    k->speed = app->speed;
    k->pace = app_clock_pace(app);
    k->window = app_window(app);
    k->running = app->running;
    k->force = app->cfg.force;
    k->force_on = app->cfg.force_on;
    k->integrator = (int)app->cfg.integrator;
    k->boundary = (int)m->boundary;
    k->wave = (int)m->motor.wave;
    k->low_bandwidth = app->cfg.low_bandwidth;
    k->graphics = (int)app->cfg.graphics;
    k->sweeping = app->sweep->active;
    k->mass = app->cfg.mass;
    k->damping = app->cfg.damping;
    k->spring = app->cfg.spring;
    k->spring_cubic = app->cfg.spring_cubic;
    k->spring_damping = app->cfg.spring_damping;
    for (int i = 0; i <= m->n && i <= CONFIG_INTERACTIVE_MAX_MASSES; i++)
        k->k[i] = m->k[i];
    for (int i = 0; i < m->n && i < CONFIG_INTERACTIVE_MAX_MASSES; i++) {
        k->m[i] = m->m[i];
        k->c[i] = m->c[i];
        k->x[i] = sim_x(app->sim)[i];
        k->x0[i] = app->cfg.x0.count ? app->cfg.x0.v[app->cfg.x0.count == 1 ? 0 : i] : 0.0;
    }
    k->loads = app->loads;
}

/* Writes a line of the changes of one key: the time run before the key first. */
static void put(struct record *r, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
static void put(struct record *r, const char *fmt, ...)
{
    va_list ap;
    run_to(r, r->mark.t, r->mark.dt, r->mark.pace);
    pause_to(r, r->mark.running);
    wait_now(r);
    va_start(ap, fmt);
    vfprintf(r->mem, fmt, ap);
    va_end(ap);
    fputc('\n', r->mem);
    r->lines++;
}

/* A per-element list changed: one value for all (the control), or the elements whose
 * values in force changed (was and now: the model's, so that a list never set, which
 * the defaults stand for, compares and is written as the numbers it stands for). */
static void put_list(struct record *r, const struct config_list *before,
                     const struct config_list *after, const double *was, const double *now,
                     int count, const char *control, char kind)
{
    char num[32];
    if (after->count == 1) {
        if (before->count != 1 || before->v[0] != after->v[0]) {
            config_format_exact(after->v[0], num, sizeof num);
            put(r, "set %s %s", control, num);
        }
        return;
    }
    for (int i = 0; i < count; i++) {
        if (was[i] == now[i])
            continue;
        config_format_exact(now[i], num, sizeof num);
        put(r, "element %c %d %s", kind, kind == 'k' ? i : i + 1, num);
    }
}

/* A per-spring list with no panel row (spring-cubic, spring-damping), when it changed: the
 * whole list, as set takes it. */
static void put_springs(struct record *r, const struct config_list *was,
                        const struct config_list *now, const char *name)
{
    if (was->count == now->count &&
        memcmp(was->v, now->v, (size_t)now->count * sizeof *now->v) == 0)
        return;
    char line[4096], num[32];
    size_t used = 0;
    for (int i = 0; i < now->count && used < sizeof line; i++) {
        config_format_exact(now->v[i], num, sizeof num);
        used += (size_t)snprintf(line + used, sizeof line - used, "%s%s", i ? "," : "", num);
    }
    put(r, "set %s %s", name, now->count ? line : "0");
}

void record_changes(struct record *r, const struct app *app, const char *cmd)
{
    const struct record_mark *k = &r->mark;
    const struct model *m = app->model;
    char num[32];
    int lines = r->lines;
    if (!r->mem)
        return;
    if (cmd) {
        if (strcmp(cmd, "random") == 0)
            put(r, "random %llu", (unsigned long long)app->cfg.seed);
        else
            put(r, "%s", cmd);
    } else if (app->loads != k->loads) {
        put(r, "setup");
        put_settings(r, app);
    } else if (m->n != k->n) {
        put(r, "set masses %d", m->n);
    } else {
        if (app->cfg.dt != k->dt) {
            config_format_exact(app->cfg.dt, num, sizeof num);
            put(r, "set dt %s", num);
        }
        if ((int)app->cfg.integrator != k->integrator)
            put(r, "set integrator %s", integrator_name(app->cfg.integrator));
        if ((int)m->boundary != k->boundary)
            put(r, "set boundary %s", model_boundary_name(m->boundary));
        if ((int)m->motor.wave != k->wave)
            put(r, "set wave %s", motor_wave_name(m->motor.wave));
        put_list(r, &k->mass, &app->cfg.mass, k->m, m->m, m->n, "mass", 'm');
        put_list(r, &k->damping, &app->cfg.damping, k->c, m->c, m->n, "damping", 'c');
        put_list(r, &k->spring, &app->cfg.spring, k->k, m->k, m->n + 1, "spring", 'k');
        put_springs(r, &k->spring_cubic, &app->cfg.spring_cubic, "spring-cubic");
        put_springs(r, &k->spring_damping, &app->cfg.spring_damping, "spring-damping");
        if (app->cfg.force != k->force) {
            config_format_exact(app->cfg.force, num, sizeof num);
            put(r, "set force %s", num);
        }
        if (app->cfg.force_on != k->force_on)
            put(r, "set force-on %d", app->cfg.force_on);
        if (m->motor.amplitude != k->amplitude) {
            config_format_exact(m->motor.amplitude, num, sizeof num);
            put(r, "set amplitude %s", num);
        }
        /* A sweep ended by another change gives the user's frequency back by itself. */
        if (m->motor.frequency != k->frequency && !(k->sweeping && !app->sweep->active)) {
            config_format_exact(m->motor.frequency, num, sizeof num);
            put(r, "set frequency %s", num);
        }
        if (app->speed != k->speed) {
            config_format_exact(app->speed, num, sizeof num);
            put(r, "set speed %s", num);
        }
        if (app_window(app) != k->window) {
            config_format_exact(app_window(app), num, sizeof num);
            put(r, "set window %s", num);
        }
        if (app->cfg.low_bandwidth != k->low_bandwidth)
            put(r, "set bandwidth %s", app->cfg.low_bandwidth ? "low" : "normal");
        if ((int)app->cfg.graphics != k->graphics)
            put(r, "set graphics %s",
                config_options[CFG_GRAPHICS].choice_name((int)app->cfg.graphics));
        /* A mass placed (the others start where the chain stood): the one whose start is
         * not where it stood, or the first if it was put back there. */
        bool moved = false;
        for (int i = 0; i < m->n && app->cfg.x0.count == m->n; i++)
            moved |= app->cfg.x0.v[i] != k->x0[i];
        int placed = 0;
        for (int i = 0; moved && i < m->n; i++)
            if (app->cfg.x0.v[i] != k->x[i])
                placed = i;
        if (moved) {
            config_format_exact(app->cfg.x0.v[placed], num, sizeof num);
            put(r, "place %d %s", placed + 1, num);
        }
    }
    if (r->t == k->t)
        r->t = sim_time(app->sim);
    if (r->lines != lines) /* the replay's chain runs as this key left it */
        r->replay_runs = app->running;
}

void record_abandon(struct record *r)
{
    if (r->mem)
        fclose(r->mem);
    r->mem = NULL;
    free(r->text);
    r->text = NULL;
    output_close(&r->out, false);
}

/* The bytes written so far (the memory stream's position). */
static long record_bytes(const struct record *r)
{
    return r->mem ? ftell(r->mem) : 0;
}

bool record_full(const struct record *r, const struct app *app, double ahead)
{
    /* ahead, at the last step's cost, and room for three changes of the largest chain:
     * the next command's (counted once it is done, and recorded) and the replay's two
     * chains built before its first line (the program's and the setup's). */
    double steps = ahead / sim_dt(app->sim) + 1.0;
    double next = steps * app->step_work + 3.0 * COST_CHANGE * APP_MAX_MASSES;
    return r->mem && (record_bytes(r) > LESSON_MAX_BYTES - RECORD_ROOM ||
                      r->seconds + (sim_time(app->sim) - r->t) + ahead > LESSON_MAX_SECONDS ||
                      app->work - r->work0 + next > LESSON_MAX_WORK);
}

void record_full_finish(struct record *r, struct app *app)
{
    char why[1400], safe[1200];
    bool bytes = record_bytes(r) > LESSON_MAX_BYTES - RECORD_ROOM;
    if (record_finish(r, app, why, sizeof why) != 0) {
        app_say(app, SAID_ERROR, "--record: %s", why);
        return;
    }
    config_escape(r->path, strlen(r->path), 256, safe, sizeof safe);
    if (bytes) {
        app_say(app, SAID_NOTE, "recording ended at %d KiB of lines (a lesson file holds "
                "%d KiB at most; so that it replays): written to %s",
                (LESSON_MAX_BYTES - RECORD_ROOM) / 1024, LESSON_MAX_BYTES / 1024, safe);
        return;
    }
    app_say(app, SAID_NOTE, "recording ended at %.0f s of runs (what a lesson may run: %.0f "
            "minutes, %.3g mass-steps; so that it replays): written to %s", r->seconds,
            LESSON_MAX_SECONDS / 60.0, LESSON_MAX_WORK, safe);
}

int record_finish(struct record *r, const struct app *app, char *err, size_t errlen)
{
    char state[4096];
    if (!r->mem) {
        say_failed(err, errlen, r->path, "not recording");
        return -1;
    }
    record_time(r, app);
    wait_now(r);
    lesson_state(app, state, sizeof state);
    fprintf(r->mem, "expect %s\n", state);
    if (fclose(r->mem) != 0) {
        r->mem = NULL;
        say_failed(err, errlen, r->path, strerror(errno));
        record_abandon(r);
        return -1;
    }
    r->mem = NULL;
    int e = 0;
    if (fwrite(r->text, 1, r->size, r->out.fp) != r->size)
        e = errno ? errno : EIO;
    int closed = output_close(&r->out, e == 0);
    e = e ? e : closed;
    if (e) {
        say_failed(err, errlen, r->path, strerror(e));
        record_abandon(r);
        return -1;
    }
    free(r->text);
    r->text = NULL;
    return 0;
}
