/* plain.c: the plain mode's loop. The same struct app as the terminal program, driven
 * by commands read line by line from standard input (app/command.c) and told in lines:
 *
 *   status t=T x1=X v1=V ... drive=U   every --plain-every simulated seconds
 *   event t=T WHAT                     as it happens (app/watch.h says which)
 *   ok WHAT / error WHAT               one answer to each command
 *
 * Simulated time follows the wall clock at the Speed control's rate, as in the terminal
 * program; `run SECONDS` runs at once instead. It waits in poll() on standard input, with
 * a timeout only while running. Nothing it writes holds an escape sequence: control
 * bytes are escaped and, without a UTF-8 locale, so is every byte >= 0x80 (the program's
 * own symbols are spelled in ASCII always). */
#include "plain.h"

#include <errno.h>
#include <langinfo.h>
#include <math.h>
#include <poll.h>
#include <signal.h>
#include <stdarg.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "../app/app.h"
#include "../app/clock.h"
#include "../app/command.h"
#include "../lab/lesson.h"
#include "../lab/record.h"
#include "../app/watch.h"
#include "words.h"

#define TICK_MS 20       /* while running: how often time is brought up to the clock */
#define LINE_MAX_IN 1024 /* longest command line read; longer ones are refused */
#define STEP_BUDGET 0.05 /* wall seconds of stepping before input is looked at again */
#define QUIT_GRACE 2     /* wall seconds a quit signal leaves a blocked write to finish */

struct plain {
    struct app app;
    struct watch watch;
    double every;              /* seconds of simulated time between status lines */
    double next_status;        /* simulated time of the next status line */
    double cap_second;         /* the second of simulated time the cap's note was last told */
    bool utf8;                 /* the locale is UTF-8: valid UTF-8 text may pass */
    bool closed;               /* standard output has gone */
    bool differs;              /* a replay ended in another state than the one recorded */
    int out_error;             /* why a write failed (EPIPE: the reader went), or 0 */
    int in_error;              /* why reading standard input failed, or 0 */
    unsigned seen;             /* the app's messages already told (app->says) */
    char in[LINE_MAX_IN + 1];  /* the command line being read */
    size_t used;               /* bytes of it */
    bool too_long;             /* the line being read is too long: skipped to its end */
    bool nul;                  /* the line being read holds a NUL byte: refused whole */
    const struct lesson *lesson; /* the lesson being played, or NULL */
    struct lesson_play play;   /* where it is */
    bool quiet;                /* a step being rebuilt (previous): nothing is said */
    struct record rec;         /* --record: the session being written */
};

static volatile sig_atomic_t quit_signal;

static void on_signal(int sig)
{
    quit_signal = sig;
    alarm(QUIT_GRACE);
}

/* Its only work is to interrupt a write still blocked QUIT_GRACE after a quit signal. */
static void on_alarm(int sig)
{
    (void)sig;
}

/* SIGINT, SIGTERM and SIGHUP end the loop with a last line (unless they were ignored
 * when the program started: those stay ignored). A write they interrupt goes on (poll()
 * returns at once all the same), for QUIT_GRACE seconds: a reader that reads nothing
 * (a full pipe) would block it for ever, so SIGALRM then interrupts it (EINTR), output is
 * given up and the program dies of the signal. */
static void catch_signals(void)
{
    static const int sigs[] = {SIGINT, SIGTERM, SIGHUP};
    for (size_t i = 0; i < sizeof sigs / sizeof *sigs; i++) {
        struct sigaction old, sa = {.sa_handler = on_signal, .sa_flags = SA_RESTART};
        sigemptyset(&sa.sa_mask);
        if (sigaction(sigs[i], NULL, &old) == 0 && old.sa_handler != SIG_IGN)
            sigaction(sigs[i], &sa, NULL);
    }
    struct sigaction alarm_sa = {.sa_handler = on_alarm}; /* no SA_RESTART */
    sigemptyset(&alarm_sa.sa_mask);
    sigaction(SIGALRM, &alarm_sa, NULL);
}

/* Writes one line "KIND text"; a failed write means standard output has gone. */
static void put(struct plain *p, const char *kind, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
static void put(struct plain *p, const char *kind, const char *fmt, ...)
{
    char text[2048], safe[4 * sizeof text];
    va_list ap;
    if (p->closed || p->quiet)
        return;
    va_start(ap, fmt);
    vsnprintf(text, sizeof text, fmt, ap);
    va_end(ap);
    plain_text(text, p->utf8, safe, sizeof safe);
    errno = 0;
    if (printf("%s %s\n", kind, safe) < 0 || fflush(stdout) != 0) {
        p->closed = true;
        p->out_error = errno ? errno : EIO;
    }
}

/* t as the status line writes it. */
static void put_event(struct plain *p, const char *what)
{
    const struct sim *s = p->app.sim;
    put(p, "event", "t=%.*f %s", app_time_decimals(sim_dt(s)), sim_time(s), what);
}

static void on_event(void *ctx, const char *what)
{
    put_event(ctx, what);
}

static void put_status(struct plain *p)
{
    char line[1024];
    command_status(&p->app, line, sizeof line);
    put(p, "status", "%s", line);
}

/* The first status time after t. */
static void plan_status(struct plain *p)
{
    double t = sim_time(p->app.sim);
    p->next_status = (floor(t / p->every + 1e-9) + 1.0) * p->every;
}

/* A message of the app not told yet (a note of the velocity cap, the sweep's end), as an
 * event. */
static void tell_message(struct plain *p)
{
    /* The cap's note changes at every step the cap acts (its count): told at most once a
     * second of simulated time, as contacts are, the count in it saying how many since. */
    if (p->app.said == SAID_CAP && p->app.says != p->seen) {
        double second = floor(sim_time(p->app.sim));
        if (second == p->cap_second)
            return; /* told in the next second's first step, or not if something else is */
        p->cap_second = second;
    }
    if (p->app.message[0] && p->app.says != p->seen)
        put_event(p, p->app.message);
    p->seen = p->app.says;
}

/* One step and what it brought: its events, the status line when its time has come. A
 * blow-up (app_step's non-finite handling) pauses the chain; false then. */
static bool step(struct plain *p)
{
    struct app *app = &p->app;
    /* A recording ends before the step that would take its runs past a lesson's bound. */
    if (record_full(&p->rec, app, sim_dt(app->sim))) {
        record_full_finish(&p->rec, app);
        tell_message(p);
    }
    if (!app_step(app)) {
        char line[sizeof app->message + 16];
        snprintf(line, sizeof line, "blow-up: %s", app->message);
        put_event(p, line);
        p->seen = app->says;
        watch_look(&p->watch, app, on_event, p);
        return false;
    }
    watch_step(&p->watch, app, on_event, p);
    tell_message(p);
    if (p->rec.mem && sim_time(app->sim) - p->rec.t >= RECORD_RUN_MAX)
        record_time(&p->rec, app);
    if (sim_time(app->sim) >= p->next_status - 1e-9 * p->every) {
        put_status(p);
        plan_status(p);
    }
    return true;
}

/* One step while following the clock: none once a quit signal came or the reader went. */
static bool clock_step(void *ctx)
{
    struct plain *p = ctx;
    return !quit_signal && !p->closed && step(p);
}

/* run SECONDS: steps at once to that much later, then pauses. */
static void run_for(struct plain *p, double seconds, char *answer, size_t len)
{
    struct app *app = &p->app;
    double end = sim_time(app->sim) + seconds;
    app->running = true;
    while (sim_time(app->sim) < end - 1e-9 * app->cfg.dt && !quit_signal && !p->closed)
        if (!step(p))
            break;
    bool blew = !app->running;
    app_set_running(app, false);
    snprintf(answer, len, "%s to t = %.*f s, paused", blew ? "stopped by the blow-up" :
             quit_signal ? "interrupted" : "ran", app_time_decimals(sim_dt(app->sim)),
             sim_time(app->sim));
}

/* One command line; false to quit. */
static bool command(struct plain *p, const char *line)
{
    struct app *app = &p->app;
    static struct command_result res; /* one command at a time */
    double t0 = sim_time(app->sim);
    bool was_running = app->running;
    record_time(&p->rec, app);
    enum command_reply r = command_do(app, line, &res);
    if (command_done(r)) {
        record_command(&p->rec, app, line);
        /* Commands alone fill a recording too (its bytes). */
        if (record_full(&p->rec, app, 0.0)) {
            record_full_finish(&p->rec, app);
            tell_message(p);
        }
    }
    if (r == REPLY_NONE)
        return true;
    if (r == REPLY_RUN)
        run_for(p, res.seconds, res.answer, sizeof res.answer);
    if (r == REPLY_QUIT)
        put_status(p);
    put(p, r == REPLY_ERROR ? "error" : "ok", "%s", res.answer);
    /* Started or paused as a side effect (a sweep, a preset): said as an event. */
    if (app->running != was_running && !res.says_play)
        put_event(p, app->running ? "started" : "paused");
    p->seen = app->says;
    watch_look(&p->watch, app, on_event, p);
    if (sim_time(app->sim) != t0 && r != REPLY_RUN) {
        /* step, back, reset, a restart: the status follows the jump */
        if (sim_time(app->sim) >= p->next_status - 1e-9 * p->every ||
            sim_time(app->sim) < t0)
            plan_status(p);
    }
    return r != REPLY_QUIT;
}

/* What the lesson waits for, said: the step's end, or the question and its choices. */
static void say_wait(struct plain *p)
{
    const struct lesson *l = p->lesson;
    const struct lesson_item *it = &l->items[p->play.waiting];
    if (it->kind == LESSON_PAUSE) {
        put(p, "lesson", "step %d of %d: a blank line goes on, previous goes back a step, "
            "leave ends the lesson", p->play.step + 1, l->steps);
        return;
    }
    put(p, "ask", "%s", it->text);
    for (int k = 0; k < it->nchoices; k++)
        put(p, "choice", "%d %s", k + 1, it->choice[k]);
    put(p, "lesson", "step %d of %d: answer 1 to %d (previous goes back a step, leave ends "
        "the lesson)", p->play.step + 1, l->steps, it->nchoices);
}

/* One item of the lesson, said or done the plain mode's way. */
static void lesson_item(struct plain *p, const struct lesson_item *it)
{
    struct app *app = &p->app;
    char now[4096];
    switch (it->kind) {
    case LESSON_SAY:
        put(p, "say", "%s", it->text);
        break;
    case LESSON_COMMAND:
        command(p, it->text);
        break;
    case LESSON_SETUP:
        put(p, lesson_setup(app, p->lesson, it) == 0 ? "ok" : "error", "%s", app->message);
        p->seen = app->says;
        plan_status(p);
        break;
    case LESSON_EXPECT:
        lesson_state(app, now, sizeof now);
        if (lesson_state_is(app, it->text))
            put(p, "ok", "replayed: the state at t = %.*f s is the one recorded, bit for bit",
                app_time_decimals(sim_dt(app->sim)), sim_time(app->sim));
        else {
            put(p, "error", "replayed, but the state differs from the one recorded "
                "(expected %s; have %s)", it->text, now);
            p->differs = true;
        }
        break;
    case LESSON_PAUSE:
    case LESSON_ASK:
        say_wait(p);
        break;
    case LESSON_WAIT: /* the interactive program's; the plain mode goes on at once */
        break;
    }
}

/* Plays the lesson on to its next pause or question, or to its end. */
static void lesson_play_on(struct plain *p)
{
    const struct lesson_item *it;
    while (p->lesson && !p->closed && !quit_signal && (it = lesson_next(&p->play)))
        lesson_item(p, it);
    if (p->lesson && p->play.waiting < 0 && p->play.next >= p->lesson->count) {
        put(p, "lesson", "end of %s: the chain is yours (help lists the commands)",
            p->lesson->name);
        p->lesson = NULL;
    }
}

/* Back to the end of the step before this one (the state it left, rebuilt from the
 * lesson's start, said nothing of), its caption and what it waits for said again. */
static void lesson_back(struct plain *p)
{
    const struct lesson *l = p->lesson;
    int target = p->play.step - 1;
    if (target < 0) {
        put(p, "error", "previous: this is the first step (a blank line goes on)");
        return;
    }
    int end = lesson_step_end(l, target);
    const struct lesson_item *it;
    p->quiet = true;
    lesson_play_start(&p->play, l);
    while ((it = lesson_next(&p->play))) {
        lesson_item(p, it);
        if (p->play.waiting >= 0 && p->play.waiting != end)
            lesson_go_on(&p->play);
    }
    p->quiet = false;
    p->seen = p->app.says;
    plan_status(p);
    put(p, "lesson", "back to step %d of %d", target + 1, l->steps);
    for (const char *c = p->play.caption; *c && !p->play.new_caption;) {
        size_t n = strcspn(c, "\n");
        put(p, "say", "%.*s", (int)n, c);
        c += n + (c[n] == '\n');
    }
    say_wait(p);
}

/* A line typed while the lesson waits: a blank line (or next) goes on, previous goes
 * back a step, leave ends the lesson, a choice answers the question; true when it was
 * one of those. Any other line is a command as ever (look around before going on). */
static bool lesson_line(struct plain *p, const char *line)
{
    if (!p->lesson || p->play.waiting < 0)
        return false;
    char w[64];
    const char *s = line + strspn(line, " \t");
    size_t n = strlen(s);
    while (n && (s[n - 1] == ' ' || s[n - 1] == '\t'))
        n--;
    if (n >= sizeof w)
        return false;
    memcpy(w, s, n);
    w[n] = '\0';
    const struct lesson_item *it = &p->lesson->items[p->play.waiting];
    if (strcmp(w, "leave") == 0) {
        put(p, "lesson", "left %s at step %d of %d: the chain is as it is", p->lesson->name,
            p->play.step + 1, p->lesson->steps);
        p->lesson = NULL;
        return true;
    }
    if (strcmp(w, "previous") == 0) {
        lesson_back(p);
        return true;
    }
    bool next = !*w || strcmp(w, "next") == 0;
    if (it->kind == LESSON_ASK) {
        int k = lesson_choice(it, w);
        if (!k && !next)
            return false;
        if (!k) {
            put(p, "error", "the question waits for an answer: 1 to %d (or leave)", it->nchoices);
            return true;
        }
        if (it->answer == k)
            put(p, "lesson", "you chose %d: %s; right", k, it->choice[k - 1]);
        else if (it->answer)
            put(p, "lesson", "you chose %d: %s; the answer is %d: %s", k, it->choice[k - 1],
                it->answer, it->choice[it->answer - 1]);
        else
            put(p, "lesson", "you chose %d: %s", k, it->choice[k - 1]);
    } else if (!next) {
        return false;
    }
    lesson_go_on(&p->play);
    lesson_play_on(p);
    return true;
}

/* The line read so far, ended (by its newline, or the end of input): refused when too
 * long or holding a NUL, else a command. False to quit. */
static bool end_line(struct plain *p)
{
    bool too_long = p->too_long, nul = p->nul;
    p->in[p->used] = '\0';
    p->used = 0;
    p->too_long = p->nul = false;
    if (too_long) {
        put(p, "error", "a line of more than %d bytes is not a command", LINE_MAX_IN);
        return true;
    }
    if (nul) {
        put(p, "error", "a line holding a NUL byte (\\x00) is not a command");
        return true;
    }
    size_t n = strlen(p->in);
    if (n && p->in[n - 1] == '\r')
        p->in[n - 1] = '\0'; /* a CRLF line */
    return lesson_line(p, p->in) || command(p, p->in);
}

/* Reads what standard input has; each whole line is a command. False to quit: a quit
 * command, or the end of input (a last line without a newline is still a command). */
static bool read_input(struct plain *p)
{
    char buf[4096];
    ssize_t got = read(STDIN_FILENO, buf, sizeof buf);
    if (got < 0 && (errno == EINTR || errno == EAGAIN))
        return true;
    if (got < 0) {
        /* Standard input closed or unreadable: the end of input, said with its reason. */
        char why[160];
        p->in_error = errno;
        snprintf(why, sizeof why, "standard input: %s: quit", strerror(errno));
        put_status(p);
        put_event(p, why);
        return false;
    }
    if (got == 0) {
        bool go = !(p->used || p->too_long) || end_line(p);
        if (go) {
            put_status(p);
            put_event(p, "end of input: quit");
        }
        return false;
    }
    for (ssize_t i = 0; i < got; i++) {
        if (buf[i] != '\n') {
            /* A NUL would end the command where it stands: "quit\0x" is not quit. */
            if (buf[i] == '\0')
                p->nul = true;
            if (p->used < LINE_MAX_IN)
                p->in[p->used++] = buf[i];
            else
                p->too_long = true;
            continue;
        }
        if (!end_line(p))
            return false;
    }
    return true;
}

/* The line that opens the session. */
static void put_ready(struct plain *p)
{
    const struct app *app = &p->app;
    const struct model *m = app->model;
    char drive[160];
    if (m->boundary == BOUNDARY_MOTOR)
        snprintf(drive, sizeof drive, "%s drive, %.4g m at %.4g Hz", motor_wave_name(m->motor.wave),
                 m->motor.amplitude, m->motor.frequency);
    else
        snprintf(drive, sizeof drive, "right end %s", model_boundary_name(m->boundary));
    if (model_forced(m)) /* a drive too, the motor's waveform and frequency */
        snprintf(drive + strlen(drive), sizeof drive - strlen(drive), ", %s force %.4g N on "
                 "mass %d at %.4g Hz", motor_wave_name(m->motor.wave), m->force,
                 m->force_on + 1, m->motor.frequency);
    int j = watch_on_mode(app);
    char on[64] = "";
    if (j >= 0)
        snprintf(on, sizeof on, " (on natural frequency %d)", j + 1);
    char line[600];
    snprintf(line, sizeof line, "ready: %s%s%s%d mass%s, %s%s, paused; help lists the commands",
             app->preset[0] ? "preset " : "", app->preset, app->preset[0] ? ", " : "", m->n,
             m->n == 1 ? "" : "es", drive, on);
    put_event(p, line);
}

int plain_run(const struct config *cfg, const char *exe_dir, const struct lesson *lesson)
{
    static struct plain p;
    memset(&p, 0, sizeof p);
    p.cap_second = -1.0;
    if (app_init_named(&p.app, cfg, exe_dir, verb_command_name, false) != 0) {
        fprintf(stderr, "springsim: out of memory\n");
        return EXIT_FAILURE;
    }
    p.utf8 = strcmp(nl_langinfo(CODESET), "UTF-8") == 0;
    char why[4600];
    if (cfg->record && record_start(&p.rec, cfg->record, &p.app, why, sizeof why) != 0) {
        fprintf(stderr, "springsim: --record: %s\n", why);
        app_free(&p.app);
        return EXIT_FAILURE;
    }
    p.every = cfg->plain_every;
    catch_signals();
    watch_init(&p.watch, &p.app);
    put_ready(&p);
    tell_message(&p);
    put_status(&p);
    plan_status(&p);
    if (lesson) {
        p.lesson = lesson;
        lesson_play_start(&p.play, lesson);
        put(&p, "lesson", "%s: %s; %d step%s", lesson->name, lesson->title, lesson->steps,
            lesson->steps == 1 ? "" : "s");
        lesson_play_on(&p);
    }
    double last = app_clock_now();
    struct app_clock clock = {0};
    bool go = true;
    while (go && !quit_signal && !p.closed) {
        double now = app_clock_now();
        /* At most STEP_BUDGET at a time: a chain too slow to follow falls behind rather
         * than stop listening. */
        app_clock_follow(&clock, &p.app, now - last, STEP_BUDGET, clock_step, &p);
        last = now;
        /* Standard output is watched too: a reader that went (POLLERR on a pipe) ends
         * the session even while nothing is being written. */
        struct pollfd fds[2] = {{STDIN_FILENO, POLLIN, 0}, {STDOUT_FILENO, 0, 0}};
        int n = poll(fds, 2, p.app.running ? TICK_MS : -1);
        if (n < 0)
            continue; /* EINTR: a signal, looked at above */
        if (fds[1].revents & (POLLERR | POLLHUP | POLLNVAL)) {
            p.closed = true;
            if (fds[1].revents & POLLNVAL)
                p.out_error = EBADF;
        }
        else if (fds[0].revents & (POLLIN | POLLHUP | POLLERR | POLLNVAL))
            go = read_input(&p);
    }
    if (quit_signal && !p.closed) {
        put_status(&p);
        char line[64];
        snprintf(line, sizeof line, "%s: quit", quit_signal == SIGINT    ? "SIGINT"
                                                : quit_signal == SIGTERM ? "SIGTERM"
                                                                         : "SIGHUP");
        put_event(&p, line);
    }
    int recorded = 0;
    if (p.rec.mem && (recorded = record_finish(&p.rec, &p.app, why, sizeof why)) != 0)
        fprintf(stderr, "springsim: --record: %s\n", why);
    app_free(&p.app);
    /* A write that failed for another reason than a reader gone (a full disk, a closed
     * descriptor), or standard input unreadable: said, status 1. */
    int e = p.out_error && p.out_error != EPIPE ? p.out_error : 0;
    if (!quit_signal && (e || p.in_error)) {
        fprintf(stderr, "springsim: standard %s: %s\n", e ? "output" : "input",
                strerror(e ? e : p.in_error));
        return EXIT_FAILURE;
    }
    /* Die of the signal, as the terminal program does; a reader gone ends as a write to
     * it would have (SIGPIPE, or status 1 where SIGPIPE is ignored). */
    int sig = quit_signal ? quit_signal : p.closed ? SIGPIPE : 0;
    if (sig == SIGPIPE)
        raise(sig);
    else if (sig) {
        signal(sig, SIG_DFL);
        raise(sig);
    }
    if (p.differs)
        fprintf(stderr, "springsim: the replay ended in another state than the one recorded\n");
    return p.closed || recorded || p.differs ? EXIT_FAILURE : EXIT_SUCCESS;
}
