/* main.c: reads the command line (options.c) and runs one of the modes: the
 * interactive program (or its plain mode), --headless, --modes, --sweep, --list-presets
 * (SPEC section 2).
 * This is the only file that knows both the core and the terminal front end. */
#include <errno.h>
#include <getopt.h>
#include <limits.h>
#include <locale.h>
#include <math.h>
#include <signal.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "core/config.h"
#include "core/limits.h"
#include "core/modes.h"
#include "core/output.h"
#include "core/preset.h"
#include "core/sim.h"
#include "core/summary.h"
#include "app/lesson.h"
#include "lessons.h"
#include "fig/report.h"
#include "options.h"
#include "plain/plain.h"
#include "progress.h"
#include "tui/tui.h"

#define SWEEP_MAX 1000000 /* rows a sweep may ask for */

/* The directory holding the running binary, for its presets/ beside it. */
static void find_exe_dir(const char *argv0, char *out, size_t len)
{
    char buf[PATH_MAX];
    ssize_t n = readlink("/proc/self/exe", buf, sizeof buf - 1);
    if (n > 0) {
        buf[n] = '\0';
    } else {
        snprintf(buf, sizeof buf, "%s", argv0);
    }
    char *slash = strrchr(buf, '/');
    if (slash)
        *slash = '\0';
    else
        snprintf(buf, sizeof buf, ".");
    snprintf(out, len, "%s", buf);
}

/* What dt is worth for this run: the stability and accuracy limits (core/limits.c).
 * False when the modes cannot be computed (no memory, numbers that overflow): the run
 * goes on unjudged. */
static bool judge(const struct config *c, const struct model *m, struct limits *l)
{
    struct limits_mode *mode = malloc((size_t)m->n * sizeof *mode);
    bool ok = mode && limits_modes(m, mode) == 0;
    if (ok)
        limits_judge(mode, m->n, m, c->integrator, c->dt, l);
    free(mode);
    return ok;
}

/* The warnings about dt, one line each, before anything runs. */
static void warn_limits(const struct limits *l)
{
    char line[400];
    limits_say_stability(l, false, line, sizeof line);
    if (line[0])
        options_say("warning: %s", line);
    limits_say_modes(l, false, line, sizeof line);
    if (line[0])
        options_say("warning: %s", line);
    limits_say_drive(l, false, line, sizeof line);
    if (line[0])
        options_say("warning: %s", line);
}

/* Says why a run stopped: a non-finite number, or a velocity at the cap past the
 * stability limit. */
static void report_blowup(const struct sim *s, const struct limits *l, bool judged,
                          bool runaway)
{
    const char *name = integrator_name(sim_integrator(s));
    char how[80];
    snprintf(how, sizeof how, sim_last_capped(s) ? "a velocity reached the cap"
                              : runaway ? "the energy passed %g times what it could be"
                                        : "numbers became non-finite", LIMITS_RUNAWAY);
    char why[300];
    if (judged)
        limits_say_stability(l, false, why, sizeof why);
    if (judged && why[0])
        options_say("the simulation blew up at t = %.4g s (%s): %s", sim_time(s), how, why);
    else
        options_say("the simulation blew up at t = %.4g s (%s) with dt = %g s and %s",
            sim_time(s), how, sim_dt(s), name);
}

/* A terminating signal during a run that writes a file: the temporary file goes (where
 * it has a name), then the program dies of the signal as it would have. */
static void on_terminate(int sig)
{
    output_discard_pending();
    signal(sig, SIG_DFL);
    raise(sig); /* delivered when the handler returns */
}

/* Catches SIGINT, SIGTERM and SIGHUP for on_terminate, except where they are ignored
 * (nohup, a background job of a script): those stay ignored. */
static void catch_terminate(void)
{
    static const int sigs[] = {SIGINT, SIGTERM, SIGHUP};
    for (size_t i = 0; i < sizeof sigs / sizeof *sigs; i++) {
        struct sigaction old, sa = {.sa_handler = on_terminate};
        sigemptyset(&sa.sa_mask);
        for (size_t j = 0; j < sizeof sigs / sizeof *sigs; j++)
            sigaddset(&sa.sa_mask, sigs[j]);
        if (sigaction(sigs[i], NULL, &old) == 0 && old.sa_handler != SIG_IGN)
            sigaction(sigs[i], &sa, NULL);
    }
}

static int open_output(struct output *o, const struct config *c)
{
    int e = output_open(o, c->output);
    if (e) {
        options_say("%s: %s", c->output, strerror(e));
        return EXIT_FAILURE;
    }
    return 0;
}

static int close_output(struct output *o, const struct config *c, int status)
{
    int e = output_close(o, status == EXIT_SUCCESS);
    if (e && status == EXIT_SUCCESS) {
        options_say("%s: %s", c->output ? c->output : "standard output", strerror(e));
        return EXIT_FAILURE;
    }
    return status;
}

/* --figure: opened before the run, so that a path that cannot be written is said before
 * any work (0, or EXIT_FAILURE after "PATH: REASON"); nothing to do without --figure. */
static int open_figure(struct output *o, const struct config *c)
{
    memset(o, 0, sizeof *o);
    if (!c->figure)
        return 0;
    int e = output_open(o, c->figure);
    if (e) {
        options_say("%s: %s", c->figure, strerror(e));
        return EXIT_FAILURE;
    }
    return 0;
}

/* Finishes the figure: draws it (draw is 0, or the errno value drawing it gave) and renames
 * it into place when the run succeeded; discards it otherwise. */
static int close_figure(struct output *o, const struct config *c, int draw, int status)
{
    if (!c->figure || !o->fp)
        return status;
    bool ok = status == EXIT_SUCCESS && draw == 0;
    int e = output_close(o, ok);
    fig_done();
    if (status == EXIT_SUCCESS && (draw || e)) {
        options_say("%s: %s", c->figure, strerror(draw ? draw : e));
        return EXIT_FAILURE;
    }
    return status;
}

/* --meta: '#' lines before the CSV header, which pandas (comment='#'), numpy (loadtxt's
 * comments) and gnuplot skip: the version, and the command line that repeats the run (the
 * mode, then every setting from the table; the seed --random chose is among them). */
static void write_meta(FILE *fp, const struct config *c, const char *mode, const char *arg)
{
    if (!c->meta)
        return;
    fprintf(fp, "# springsim %s\n# springsim --%s", VERSION, mode);
    if (arg)
        fprintf(fp, " %s", arg);
    /* A summary has no series: --energy and --sample (a preset's) would be refused. */
    struct config shown = *c;
    if (strcmp(mode, "summary") == 0) {
        shown.energy = false;
        shown.sample = config_options[CFG_SAMPLE].def;
    }
    config_write_args(fp, &shown);
    fputc('\n', fp);
}

/* Adds the row just written (accelerations in a) to the figure's, if there is one. */
static void figure_row(struct report_data *fig, double *row, const struct sim *s,
                       const double *a)
{
    if (!fig)
        return;
    int n = sim_model(s)->n;
    memcpy(row, sim_x(s), (size_t)n * sizeof *row);
    memcpy(row + n, sim_v(s), (size_t)n * sizeof *row);
    memcpy(row + 2 * n, a, (size_t)n * sizeof *row);
    row[3 * n] = sim_end_position(s);
    report_data_add(fig, sim_time(s), row);
}

static int run_headless(const struct config *c, const struct model *m)
{
    int n = m->n, status = EXIT_SUCCESS;
    double *x = malloc((size_t)(3 * n) * sizeof *x);
    struct sim *s = sim_new(m, c->dt);
    struct summary *sum = c->summary ? summary_new(n) : NULL;
    struct output o;
    if (!x || !s || (c->summary && !sum)) {
        options_say("out of memory");
        free(x);
        sim_free(s);
        summary_free(sum);
        return EXIT_FAILURE;
    }
    struct limits l;
    bool judged = judge(c, m, &l);
    bool unstable = judged && limits_unstable(&l);
    if (judged)
        warn_limits(&l);
    sim_set_integrator(s, c->integrator);
    if (config_initial(c, m, x, x + n) != 0) {
        options_say("--start-mode: mode %d's shape cannot be computed for these values "
                    "(LAPACK failed, or the numbers overflow)", c->start_mode);
        free(x);
        sim_free(s);
        summary_free(sum);
        return EXIT_FAILURE;
    }
    sim_reset(s, x, x + n);
    /* Steps between rows and steps in all, kept in doubles: whole numbers up to 2^53,
     * and huge values (--sample 1e300) stay huge instead of overflowing an integer. */
    double total = floor(c->duration / c->dt + 1e-9);
    double stride = c->sample > 0.0 ? round(c->sample / c->dt) : 1.0;
    if (stride < 1.0)
        stride = 1.0;
    /* The figure keeps the rows the CSV gets: x1..xN, v1..vN, a1..aN, motor. */
    struct output fo;
    struct report_data *fig = c->figure ? report_data_new(3 * n + 1, floor(total / stride) + 1)
                                        : NULL;
    double *row = c->figure ? malloc((size_t)(3 * n + 1) * sizeof *row) : NULL;
    if (c->figure && (!fig || !row))
        options_say("out of memory");
    if ((c->figure && (!fig || !row)) || open_output(&o, c)) {
        free(x);
        free(row);
        sim_free(s);
        summary_free(sum);
        report_data_free(fig);
        return EXIT_FAILURE;
    }
    if (open_figure(&fo, c)) {
        output_close(&o, false);
        free(x);
        free(row);
        sim_free(s);
        summary_free(sum);
        report_data_free(fig);
        return EXIT_FAILURE;
    }
    /* A summary's '#' lines go out with its header and row, so a run that blows up
     * leaves no '#' lines without them. */
    if (!sum)
        write_meta(o.fp, c, "headless", NULL);
    double capped = 0.0, first_cap = 0.0; /* velocities capped, and when first */
    bool blown = false;
    if (sum) {
        blown = !output_state_finite(s, x + 2 * n);
        summary_add(sum, s, 0.0, total);
    } else {
        output_csv_header(o.fp, n, c->energy);
        blown = output_csv_row(o.fp, s, c->energy, x + 2 * n) != 0;
        figure_row(fig, row, s, x + 2 * n);
    }
    if (blown) {
        report_blowup(s, &l, judged, false);
        status = EXIT_FAILURE;
    }
    struct energy e;
    struct limits_runaway watch;
    sim_energy(s, &e);
    limits_runaway_start(&watch, m, &e);
    /* A run that takes more than a second says how far it has got (a terminal only). */
    struct progress prog;
    progress_start(&prog, total * c->dt);
    for (double step = 1; !blown && step <= total; step++) {
        /* Past the stability limit a capped velocity, or energy made from nothing, means
         * the numbers are running away: stop rather than write nonsense (or a value that
         * is no longer finite). */
        bool bad = sim_step(s) != SIM_OK, runaway = false;
        if (!bad && unstable) {
            sim_energy(s, &e);
            runaway = limits_runaway_check(&watch, &e);
        }
        if (bad || (unstable && (sim_last_capped(s) || runaway))) {
            progress_end(&prog);
            report_blowup(s, &l, judged, runaway);
            status = EXIT_FAILURE;
            capped = 0.0; /* said already */
            break;
        }
        if (sim_last_capped(s)) {
            if (capped == 0.0)
                first_cap = sim_time(s);
            capped += sim_last_capped(s);
        }
        if (sum) {
            summary_add(sum, s, step, total);
        } else if (fmod(step, stride) == 0.0) {
            if (output_csv_row(o.fp, s, c->energy, x + 2 * n) != 0) {
                progress_end(&prog);
                report_blowup(s, &l, judged, false);
                status = EXIT_FAILURE;
                capped = 0.0;
                break;
            }
            figure_row(fig, row, s, x + 2 * n);
            if (ferror(o.fp))
                break;
        }
        /* The clock read every 64 steps, or every step of exact's (each may be slow). */
        if (fmod(step, 64.0) == 0.0 || c->integrator == INTEGRATOR_EXACT)
            progress_tick(&prog, sim_time(s));
    }
    progress_end(&prog);
    if (sum && status == EXIT_SUCCESS && !output_state_finite(s, x + 2 * n)) {
        report_blowup(s, &l, judged, false);
        status = EXIT_FAILURE;
    }
    if (sum && status == EXIT_SUCCESS) {
        write_meta(o.fp, c, "summary", NULL);
        summary_header(o.fp, n);
        summary_row(o.fp, sum, s);
    }
    status = close_output(&o, c, status);
    if (fig) {
        char settings[400];
        report_settings(c, m, settings, sizeof settings);
        int draw = status == EXIT_SUCCESS
                       ? report_headless(fo.fp, fig_format_of(c->figure), fig, n,
                                         m->boundary == BOUNDARY_MOTOR, sim_time(s), settings)
                       : 0;
        status = close_figure(&fo, c, draw, status);
    }
    if (capped > 0.0) {
        char times[32];
        snprintf(times, sizeof times, capped == 1.0 ? "once" : "%.0f times", capped);
        options_say("warning: the velocity cap (%g m/s) acted %s, first at t = %.4g s; the "
            "energy balance includes what it removed", MODEL_VMAX, times, first_cap);
    }
    free(x);
    free(row);
    sim_free(s);
    summary_free(sum);
    report_data_free(fig);
    return status;
}

static int run_modes(const struct config *c, const struct model *m)
{
    int n = m->n;
    double *f = malloc((size_t)(3 * n) * sizeof *f);
    double *shapes = malloc((size_t)n * (size_t)n * sizeof *shapes);
    struct output o;
    int status = EXIT_SUCCESS;
    double *ratio = f ? f + n : NULL, *damped_hz = f ? f + 2 * n : NULL;
    if (!f || !shapes || modes_compute(m, f, shapes) != 0 ||
        modes_damped(m, shapes, ratio, damped_hz) != 0) {
        options_say(!f || !shapes ? "out of memory"
                                  : "the modes cannot be computed for these values "
                                    "(LAPACK failed, or the numbers overflow)");
        free(f);
        free(shapes);
        return EXIT_FAILURE;
    }
    struct output fo;
    if (open_output(&o, c) == 0 && open_figure(&fo, c) != 0) {
        output_close(&o, false);
        status = EXIT_FAILURE;
    } else if (o.fp) {
        write_meta(o.fp, c, "modes", NULL);
        fputs("mode,frequency_hz", o.fp);
        for (int i = 1; i <= n; i++)
            fprintf(o.fp, ",x%d", i);
        fputs(",damping_ratio,damped_frequency_hz\n", o.fp);
        for (int j = 0; j < n; j++) {
            fprintf(o.fp, "%d,%.12g", j + 1, f[j]);
            for (int i = 0; i < n; i++)
                fprintf(o.fp, ",%.12g", shapes[(size_t)j * n + i]);
            fprintf(o.fp, ",%.12g,%.12g\n", ratio[j], damped_hz[j]);
        }
        status = close_output(&o, c, status);
        if (c->figure) {
            char settings[400];
            report_settings(c, m, settings, sizeof settings);
            int draw = status == EXIT_SUCCESS ? report_modes(fo.fp, fig_format_of(c->figure), m,
                                                             f, shapes, settings)
                                              : 0;
            status = close_figure(&fo, c, draw, status);
        }
    } else {
        status = EXIT_FAILURE;
    }
    free(f);
    free(shapes);
    return status;
}

/* Parses FMIN:FMAX:COUNT, each part a number as every option reads it (no blanks);
 * on error says why and returns -1. */
static int parse_sweep(const char *spec, double *fmin, double *fmax, long *count)
{
    const char *expect = "expected FMIN:FMAX:COUNT with 0 < FMIN < FMAX <= 1e6 and "
                         "2 <= COUNT <= 1000000";
    char buf[128], q[4 * CONFIG_QUOTE_MAX + 48];
    config_quote(spec, strlen(spec), q, sizeof q);
    if (strlen(spec) >= sizeof buf) {
        options_say("--sweep: %s is too long (%s)", q, expect);
        return -1;
    }
    strcpy(buf, spec);
    char *a = buf, *b = strchr(a, ':'), *cnt = b ? strchr(b + 1, ':') : NULL;
    if (!b || !cnt || strchr(cnt + 1, ':')) {
        options_say("--sweep: %s is not three values separated by ':' (%s)", q, expect);
        return -1;
    }
    *b++ = '\0';
    *cnt++ = '\0';
    double c;
    const char *digits = cnt + (cnt[0] == '+');
    if (config_parse_number(a, fmin) || config_parse_number(b, fmax) ||
        config_parse_number(cnt, &c)) {
        options_say("--sweep: %s has a value that is not a number (%s)", q, expect);
        return -1;
    }
    /* A number, but not a count: say which is wrong (-5 is out of range, 1.5 not whole). */
    if (!*digits || strspn(digits, "0123456789") != strlen(digits)) {
        char qc[4 * CONFIG_QUOTE_MAX + 48];
        config_quote(cnt, strlen(cnt), qc, sizeof qc);
        options_say("--sweep: %s has COUNT %s, which %s (%s)", q, qc,
                    c != floor(c) ? "is not a whole number"
                    : c < 2.0     ? "is out of range"
                                  : "is not written in digits", expect);
        return -1;
    }
    *count = c > SWEEP_MAX ? SWEEP_MAX + 1 : (long)c;
    if (!(*fmin > 0.0 && *fmin < *fmax && *fmax <= 1e6 && *count >= 2 && *count <= SWEEP_MAX)) {
        options_say("--sweep: %s is out of range (%s)", q, expect);
        return -1;
    }
    return 0;
}

static int run_sweep(const struct config *c, const struct model *m, const char *spec)
{
    double fmin, fmax;
    long count;
    if (parse_sweep(spec, &fmin, &fmax, &count) != 0)
        return EXIT_USAGE;
    if (m->boundary != BOUNDARY_MOTOR) {
        options_say("--sweep: the right end is '%s', which does not drive the chain (expected "
            "--boundary motor)", model_boundary_name(m->boundary));
        return EXIT_USAGE;
    }
    int n = m->n, status = EXIT_SUCCESS;
    double *amp = malloc((size_t)(2 * n) * sizeof *amp), *phase = amp ? amp + n : NULL;
    struct output o;
    if (!amp) {
        options_say("out of memory");
        return EXIT_FAILURE;
    }
    struct output fo;
    struct report_data *fig = c->figure ? report_data_new(2 * n, (double)count) : NULL;
    if (c->figure && !fig) {
        options_say("out of memory");
        free(amp);
        return EXIT_FAILURE;
    }
    if (open_output(&o, c) != 0) {
        free(amp);
        report_data_free(fig);
        return EXIT_FAILURE;
    }
    if (open_figure(&fo, c) != 0) {
        output_close(&o, false);
        free(amp);
        report_data_free(fig);
        return EXIT_FAILURE;
    }
    write_meta(o.fp, c, "sweep", spec);
    fputs("frequency_hz", o.fp);
    for (int i = 1; i <= n; i++)
        fprintf(o.fp, ",amp%d", i);
    for (int i = 1; i <= n; i++)
        fprintf(o.fp, ",phase%d", i);
    fputc('\n', o.fp);
    for (long r = 0; r < count; r++) {
        double f = r == count - 1 ? fmax : fmin + (fmax - fmin) * ((double)r / (count - 1));
        if (modes_response_phase(m, f, amp, phase) != 0) {
            /* An undamped chain exactly at a natural frequency has no steady state. */
            for (int i = 0; i < n; i++)
                amp[i] = INFINITY, phase[i] = NAN;
        }
        fprintf(o.fp, "%.12g", f);
        for (int i = 0; i < 2 * n; i++)
            fprintf(o.fp, isfinite(amp[i]) ? ",%.12g" : isnan(amp[i]) ? ",nan" : ",inf", amp[i]);
        fputc('\n', o.fp);
        if (fig)
            report_data_add(fig, f, amp);
        if (ferror(o.fp))
            break;
    }
    status = close_output(&o, c, status);
    if (fig) {
        char settings[400];
        report_settings(c, m, settings, sizeof settings);
        int draw = status == EXIT_SUCCESS
                       ? report_sweep(fo.fp, fig_format_of(c->figure), fig, n, settings)
                       : 0;
        status = close_figure(&fo, c, draw, status);
    }
    report_data_free(fig);
    free(amp);
    return status;
}

/* The interactive program's narrower ranges (from the settings table): EXIT_SUCCESS, or
 * EXIT_USAGE after one line naming the value. */
static int interactive_limits(const struct config *c)
{
    char why[200];
    int key = config_check_interactive(c, why, sizeof why);
    if (key < 0)
        return EXIT_SUCCESS;
    options_report_key(c, key, why);
    return EXIT_USAGE;
}

/* --list-presets: the list written through config_escape line by line, so a preset's
 * description cannot carry control bytes to the terminal. */
static int list_presets(const char *exe_dir)
{
    char *text = NULL;
    size_t size = 0;
    FILE *mem = open_memstream(&text, &size);
    if (!mem) {
        options_say("out of memory");
        return EXIT_FAILURE;
    }
    int found = preset_list(mem, exe_dir);
    if (fclose(mem) != 0) {
        free(text);
        options_say("out of memory");
        return EXIT_FAILURE;
    }
    for (char *line = text; line < text + size;) {
        char *nl = memchr(line, '\n', (size_t)(text + size - line));
        size_t n = nl ? (size_t)(nl - line) : (size_t)(text + size - line);
        char safe[4 * 1024 + 8];
        config_escape(line, n, 1024, safe, sizeof safe);
        printf("%s\n", safe);
        line += n + 1;
    }
    free(text);
    if (found == 0)
        options_say("no presets found (searched the user's directory, $SPRINGSIM_PRESETS, %s "
            "and %s/presets)", preset_installed_dir, exe_dir);
    return options_finish_stdout(true);
}

int main(int argc, char **argv)
{
    static struct config c; /* large: lists of up to 1001 values */
    static struct cli cli;
    char exe_dir[PATH_MAX], err[512];

    /* The user's locale for the terminal (UTF-8 or not), but numbers always read and
     * print with a decimal point. */
    setlocale(LC_ALL, "");
    setlocale(LC_NUMERIC, "C");
    find_exe_dir(argv[0], exe_dir, sizeof exe_dir);
    config_init(&c);
    int status = options_parse(argc, argv, &c, &cli, exe_dir);
    if (status == EXIT_SUCCESS)
        return options_finish_stdout(true); /* after --help, --version, --keys */
    if (status >= 0)
        return status;
    if (cli.mode == MODE_LIST)
        return list_presets(exe_dir);
    if (cli.mode == MODE_LIST_LESSONS)
        return lessons_list(exe_dir);
    int bad_key;
    struct model *m = config_model(&c, &bad_key, err, sizeof err);
    if (!m) {
        if (bad_key < 0) {
            options_say("%s", err);
            return EXIT_FAILURE;
        }
        options_report_key(&c, bad_key, err);
        return EXIT_USAGE;
    }
    if (cli.mode == MODE_HEADLESS && ((bad_key = config_check_steps(&c, err, sizeof err)) >= 0 ||
                                      (bad_key = config_check_exact(&c, err, sizeof err)) >= 0)) {
        options_report_key(&c, bad_key, err);
        model_free(m);
        return EXIT_USAGE;
    }
    if (c.random && !c.seed_set) {
        c.seed = (uint64_t)time(NULL) ^ ((uint64_t)getpid() << 32);
        /* Said so that the run can be repeated (the interactive program's status line
         * says it there). */
        if (cli.mode == MODE_HEADLESS)
            options_say("--random: seed %llu (--seed %llu repeats this run)",
                        (unsigned long long)c.seed, (unsigned long long)c.seed);
    }
    if (cli.mode == MODE_HEADLESS || cli.mode == MODE_MODES || cli.mode == MODE_SWEEP)
        catch_terminate();
    switch (cli.mode) {
    case MODE_HEADLESS:
        status = run_headless(&c, m);
        break;
    case MODE_MODES:
        status = run_modes(&c, m);
        break;
    case MODE_SWEEP:
        status = run_sweep(&c, m, cli.sweep);
        break;
    default:
        /* A terminal that cannot place the cursor gets the plain mode. */
        static struct lesson lesson;
        status = interactive_limits(&c);
        if (status == EXIT_SUCCESS && (c.lesson || c.replay)) {
            int st = lessons_load(&c, exe_dir, &lesson);
            status = st < 0 ? EXIT_SUCCESS : st;
        }
        const struct lesson *play = lesson.count ? &lesson : NULL;
        if (status == EXIT_SUCCESS && (cli.mode == MODE_PLAIN || tui_dumb_terminal()))
            status = plain_run(&c, exe_dir, play);
        else if (status == EXIT_SUCCESS)
            status = tui_run(&c, exe_dir, play);
        lesson_free(&lesson);
        break;
    }
    model_free(m);
    return status;
}
