/* run_headless.c: --headless, the chain stepped for --duration and written as CSV rows
 * (or one --summary row), with --figure's plot of the same rows (SPEC section 2). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/config.h"
#include "core/limits.h"
#include "core/output.h"
#include "core/sim.h"
#include "core/summary.h"
#include "fig/report.h"
#include "options.h"
#include "progress.h"
#include "run.h"
#include "run_files.h"

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

/* Adds the row just written (accelerations in a) to the figure's, if there is one; the
 * energy balance's change is counted from start (the first row's balance). */
static void figure_row(struct report_data *fig, double *row, const struct sim *s,
                       const double *a, bool energy, double *start)
{
    if (!fig)
        return;
    if (isnan(*start)) {
        struct energy e;
        sim_energy(s, &e);
        *start = e.balance;
    }
    report_headless_row(s, a, energy, *start, row);
    report_data_add(fig, sim_time(s), row);
}

int run_headless(const struct config *c, const struct model *m)
{
    int n = m->n, status = EXIT_FAILURE;
    /* Steps between rows and steps in all, kept in doubles: whole numbers up to 2^53,
     * and huge values (--sample 1e300) stay huge instead of overflowing an integer. */
    double total = floor(c->duration / c->dt + 1e-9);
    double stride = c->sample > 0.0 ? round(c->sample / c->dt) : 1.0;
    if (stride < 1.0)
        stride = 1.0;
    double *x = malloc((size_t)(3 * n) * sizeof *x);
    struct sim *s = sim_new(m, c->dt);
    struct summary *sum = c->summary ? summary_new(n) : NULL;
    /* The figure keeps the rows the CSV gets: x1..xN, v1..vN, a1..aN, motor. */
    int fig_series = report_headless_series(n, c->energy);
    double start_balance = NAN;
    struct report_data *fig = c->figure ? report_data_new(fig_series, floor(total / stride) + 1)
                                        : NULL;
    double *row = c->figure ? malloc((size_t)fig_series * sizeof *row) : NULL;
    struct output o = {0}, fo = {0};
    struct limits l;
    bool judged = false, unstable = false;
    if (!x || !s || (c->summary && !sum) || (c->figure && (!fig || !row))) {
        options_say("out of memory");
        goto done;
    }
    judged = judge(c, m, &l);
    unstable = judged && limits_unstable(&l);
    if (judged)
        warn_limits(&l);
    sim_set_integrator(s, c->integrator);
    if (config_initial(c, m, x, x + n) != 0) {
        options_say("--start-mode: mode %d's shape cannot be computed for these values "
                    "(LAPACK failed, or the numbers overflow)", c->start_mode);
        goto done;
    }
    sim_reset(s, x, x + n);
    if (run_open_output(&o, c))
        goto done;
    if (run_open_figure(&fo, c)) {
        output_close(&o, false);
        goto done;
    }
    status = EXIT_SUCCESS;
    /* A summary's '#' lines go out with its header and row, so a run that blows up
     * leaves no '#' lines without them. */
    if (!sum)
        run_write_meta(o.fp, c, "headless", NULL);
    double capped = 0.0, first_cap = 0.0; /* velocities capped, and when first */
    bool blown = false;
    if (sum) {
        blown = !output_state_finite(s, x + 2 * n);
        summary_add(sum, s, 0.0, total);
    } else {
        output_csv_header(o.fp, n, c->energy);
        blown = output_csv_row(o.fp, s, c->energy, x + 2 * n) != 0;
        figure_row(fig, row, s, x + 2 * n, c->energy, &start_balance);
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
            figure_row(fig, row, s, x + 2 * n, c->energy, &start_balance);
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
        run_write_meta(o.fp, c, "summary", NULL);
        summary_header(o.fp, n);
        summary_row(o.fp, sum, s);
    }
    status = run_close_output(&o, c, status);
    if (fig) {
        char settings[400];
        report_settings(c, m, settings, sizeof settings);
        struct report_look look = report_look_of(c, settings);
        bool moves = m->boundary == BOUNDARY_MOTOR && m->motor.amplitude > 0.0;
        int draw = status == EXIT_SUCCESS
                       ? report_headless(fo.fp, fig_format_of(c->figure), fig, n, moves,
                                         c->energy, 0.0, sim_time(s), &look)
                       : 0;
        status = run_close_figure(&fo, c, draw, status);
    }
    if (capped > 0.0) {
        char times[32];
        snprintf(times, sizeof times, capped == 1.0 ? "once" : "%.0f times", capped);
        options_say("warning: the velocity cap (%g m/s) acted %s, first at t = %.4g s; the "
            "energy balance includes what it removed", MODEL_VMAX, times, first_cap);
    }
done:
    free(x);
    free(row);
    sim_free(s);
    summary_free(sum);
    report_data_free(fig);
    return status;
}
