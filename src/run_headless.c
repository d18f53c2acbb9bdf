/* run_headless.c: --headless, the chain stepped for --duration and written as CSV rows
 * (or one --summary row), with --figure's plot of the same rows. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "app/app.h"
#include "core/config.h"
#include "core/limits.h"
#include "core/output.h"
#include "core/sim.h"
#include "core/summary.h"
#include "fig/lib.h"
#include "options.h"
#include "progress.h"
#include "run.h"
#include "run_files.h"

bool run_judge(const struct config *c, const struct model *m, struct limits *l)
{
    struct limits_mode *mode = malloc((size_t)m->n * sizeof *mode);
    bool ok = mode && limits_modes(m, mode) == 0;
    if (ok)
        limits_judge(mode, m->n, m, c->integrator, c->dt, l);
    free(mode);
    return ok;
}

/* (A chain with cubic springs told that they are its linearised chain's.) */
void run_warn_limits(const struct limits *l, const struct model *m)
{
    char line[400];
    const char *note = limits_linearised_note(m);
    limits_say_stability(l, false, line, sizeof line);
    if (line[0])
        options_say("warning: %s%s", line, note);
    limits_say_modes(l, false, line, sizeof line);
    if (line[0])
        options_say("warning: %s%s", line, note);
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
    char why[300], spring[48];
    int j;
    double turn = model_turnover(sim_model(s), &j);
    if (judged && !limits_unstable(l) && isfinite(turn)) {
        /* A stable step, a softening spring: the motion ran away, not the method. */
        app_spring_name(sim_model(s), j, spring, sizeof spring);
        options_say("the simulation blew up at t = %.4g s (%s): %s softens, and past a "
                    "stretch of %.3g m its force turns over and the chain runs away (less "
                    "drive, or a smaller start)", sim_time(s), how, spring, turn);
        return;
    }
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

/* One headless run as it goes: the chain, what dt is worth for it, what the cap did. */
struct run {
    const struct config *c;
    struct sim *s;
    double *x;           /* 3N: the start's x and v, then each row's accelerations */
    struct summary *sum; /* --summary's figures, or NULL for the series */
    struct limits l;     /* dt judged, where judged */
    bool judged;         /* the limits are known */
    bool unstable;       /* dt is past the stability limit */
    double total;        /* steps in all */
    double stride;       /* steps between rows */
    double capped;       /* velocities capped, not yet said */
    double first_cap;    /* when first (s) */
    double fig_start;    /* the figure's first energy balance (NAN: none yet) */
};

/* Frees what run_begin made. */
static void run_end(struct run *r)
{
    free(r->x);
    sim_free(r->s);
    summary_free(r->sum);
}

/* Sets the run up: the chain at its start, dt judged (and its warnings said). Returns
 * EXIT_SUCCESS, or EXIT_FAILURE after one line saying why (run_end frees either way). */
static int run_begin(struct run *r, const struct config *c, const struct model *m)
{
    int n = m->n;
    *r = (struct run){.c = c, .fig_start = NAN};
    /* Steps between rows and steps in all, kept in doubles: whole numbers up to 2^53,
     * and huge values (--sample 1e300) stay huge instead of overflowing an integer. */
    r->total = floor(c->duration / c->dt + 1e-9);
    r->stride = c->sample > 0.0 ? round(c->sample / c->dt) : 1.0;
    if (r->stride < 1.0)
        r->stride = 1.0;
    r->x = malloc((size_t)(3 * n) * sizeof *r->x);
    r->s = sim_new(m, c->dt);
    r->sum = c->summary ? summary_new(n) : NULL;
    if (!r->x || !r->s || (c->summary && !r->sum)) {
        options_say("out of memory");
        return EXIT_FAILURE;
    }
    r->judged = run_judge(c, m, &r->l);
    r->unstable = r->judged && limits_unstable(&r->l);
    if (r->judged)
        run_warn_limits(&r->l, m);
    int j;
    double turn = model_turnover(m, &j);
    if (isfinite(turn)) {
        char name[48];
        app_spring_name(m, j, name, sizeof name);
        options_say("warning: %s softens: its force turns over at a stretch of %.3g m, and "
                    "past it the chain runs away", name, turn);
    }
    sim_set_integrator(r->s, c->integrator);
    if (config_initial(c, m, r->x, r->x + n) != 0) {
        options_say("--start-mode: mode %d's shape cannot be computed for these values "
                    "(LAPACK failed, or the numbers overflow)", c->start_mode);
        return EXIT_FAILURE;
    }
    sim_reset(r->s, r->x, r->x + n);
    return EXIT_SUCCESS;
}

/* Steps the run to its end: a summary takes in each step, the series writes a CSV row
 * to fp every stride steps (and adds it to fig, if there is one). Returns EXIT_SUCCESS,
 * or EXIT_FAILURE when the run blew up (said) or a row could not be written. */
static int run_steps(struct run *r, FILE *fp, struct report_data *fig, double *row)
{
    struct sim *s = r->s;
    const struct config *c = r->c;
    double *a = r->x + 2 * sim_model(s)->n;
    int status = EXIT_SUCCESS;
    bool blown = false;
    if (r->sum) {
        blown = !output_state_finite(s, a);
        summary_add(r->sum, s, 0.0, r->total);
    } else {
        output_csv_header(fp, sim_model(s)->n, c->energy);
        blown = output_csv_row(fp, s, c->energy, a) != 0;
        figure_row(fig, row, s, a, c->energy, &r->fig_start);
    }
    if (blown) {
        report_blowup(s, &r->l, r->judged, false);
        status = EXIT_FAILURE;
    }
    struct energy e;
    struct limits_runaway watch;
    sim_energy(s, &e);
    limits_runaway_start(&watch, sim_model(s), &e);
    /* A run that takes more than a second says how far it has got (a terminal only). */
    struct progress prog;
    progress_start(&prog, r->total * c->dt);
    /* Steps to the next row and the next look at the clock, counted down (whole numbers,
     * exact in a double; a huge stride is never reached, as it should be). */
    double row_left = r->stride, tick_left = 64.0;
    for (double step = 1; !blown && step <= r->total; step++) {
        /* Past the stability limit a capped velocity, or energy made from nothing, means
         * the numbers are running away: stop rather than write nonsense (or a value that
         * is no longer finite). */
        bool bad = sim_step(s) != SIM_OK, runaway = false;
        if (!bad && r->unstable) {
            sim_energy(s, &e);
            runaway = limits_runaway_check(&watch, &e);
        }
        if (bad || (r->unstable && (sim_last_capped(s) || runaway))) {
            progress_end(&prog);
            report_blowup(s, &r->l, r->judged, runaway);
            status = EXIT_FAILURE;
            r->capped = 0.0; /* said already */
            break;
        }
        if (sim_last_capped(s)) {
            if (r->capped == 0.0)
                r->first_cap = sim_time(s);
            r->capped += sim_last_capped(s);
        }
        if (r->sum) {
            summary_add(r->sum, s, step, r->total);
        } else if (--row_left == 0.0) {
            row_left = r->stride;
            if (output_csv_row(fp, s, c->energy, a) != 0) {
                progress_end(&prog);
                report_blowup(s, &r->l, r->judged, false);
                status = EXIT_FAILURE;
                r->capped = 0.0;
                break;
            }
            figure_row(fig, row, s, a, c->energy, &r->fig_start);
            if (ferror(fp))
                break;
        }
        /* The clock read every 64 steps, or every step of exact's (each may be slow). */
        if (--tick_left == 0.0 || c->integrator == INTEGRATOR_EXACT) {
            tick_left = 64.0;
            progress_tick(&prog, sim_time(s));
        }
    }
    progress_end(&prog);
    if (r->sum && status == EXIT_SUCCESS && !output_state_finite(s, a)) {
        report_blowup(s, &r->l, r->judged, false);
        status = EXIT_FAILURE;
    }
    return status;
}

/* The warning that the velocity cap acted, if it did and the run did not stop for it. */
static void say_capped(const struct run *r)
{
    if (r->capped <= 0.0)
        return;
    char times[32];
    snprintf(times, sizeof times, r->capped == 1.0 ? "once" : "%.0f times", r->capped);
    options_say("warning: the velocity cap (%g m/s) acted %s, first at t = %.4g s; the "
        "energy balance includes what it removed", MODEL_VMAX, times, r->first_cap);
}

/* A summary's '#' lines go out with its header and row, so a run that blows up leaves
 * no '#' lines without them. */
static void write_summary(FILE *fp, const struct run *r, bool header)
{
    run_write_meta(fp, r->c, "summary", NULL);
    if (header)
        summary_header(fp, sim_model(r->s)->n);
    summary_row(fp, r->sum, r->s);
}

int run_summary(const struct config *c, const struct model *m, FILE *fp, bool header)
{
    struct run r;
    int status = run_begin(&r, c, m);
    if (status == EXIT_SUCCESS)
        status = run_steps(&r, fp, NULL, NULL);
    if (status == EXIT_SUCCESS) {
        write_summary(fp, &r, header);
        say_capped(&r);
    }
    run_end(&r);
    return status;
}

int run_headless(const struct config *c, const struct model *m)
{
    int n = m->n;
    struct run r;
    int status = run_begin(&r, c, m);
    /* The figure keeps the rows the CSV gets: x1..xN, v1..vN, a1..aN, motor. */
    int fig_series = report_headless_series(n, c->energy);
    struct report_data *fig = c->figure ? report_data_new(fig_series,
                                                          floor(r.total / r.stride) + 1)
                                        : NULL;
    double *row = c->figure ? malloc((size_t)fig_series * sizeof *row) : NULL;
    struct output o = {0}, fo = {0};
    if (status == EXIT_SUCCESS && c->figure && (!fig || !row)) {
        options_say("out of memory");
        status = EXIT_FAILURE;
    }
    if (status != EXIT_SUCCESS)
        goto done;
    if (run_open_output(&o, c)) {
        status = EXIT_FAILURE;
        goto done;
    }
    if (run_open_figure(&fo, c)) {
        output_close(&o, false);
        status = EXIT_FAILURE;
        goto done;
    }
    if (!r.sum)
        run_write_meta(o.fp, c, "headless", NULL);
    status = run_steps(&r, o.fp, fig, row);
    if (r.sum && status == EXIT_SUCCESS)
        write_summary(o.fp, &r, true);
    status = run_close_output(&o, c, status);
    if (fig) {
        char settings[400];
        report_settings(c, m, settings, sizeof settings);
        struct report_look look = report_look_of(c, settings);
        bool moves = model_motor_moves(m);
        int draw = status == EXIT_SUCCESS
                       ? fig_lib_loaded()->headless(fo.fp, fig_format_of(c->figure), fig, n,
                                                    moves, c->energy, 0.0, sim_time(r.s), &look)
                       : 0;
        status = run_close_figure(&fo, c, draw, status);
    }
    say_capped(&r);
done:
    free(row);
    run_end(&r);
    report_data_free(fig);
    return status;
}
