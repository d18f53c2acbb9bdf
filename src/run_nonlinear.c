/* run_nonlinear.c: the sweeps of a chain with cubic springs: --sweep by harmonic balance
 * (every branch at each frequency, its stability, the folds), and --sweep-run, the
 * simulated sweep up or down, each point from the last one's state. Both
 * write frequency_hz,branch,stable,amp1..ampN,phase1..phaseN. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/config.h"
#include "core/harmonic.h"
#include "core/output.h"
#include "core/sim.h"
#include "core/sweeprun.h"
#include "options.h"
#include "run.h"
#include "run_files.h"

static void header(FILE *fp, int n)
{
    fputs("frequency_hz,branch,stable", fp);
    for (int i = 1; i <= n; i++)
        fprintf(fp, ",amp%d", i);
    for (int i = 1; i <= n; i++)
        fprintf(fp, ",phase%d", i);
    fputc('\n', fp);
}

static void row(FILE *fp, double f, int branch, bool stable, int n, const double *amp,
                const double *phase)
{
    fprintf(fp, "%.12g,", f);
    if (branch > 0)
        fprintf(fp, "%d", branch);
    fprintf(fp, ",%d", stable ? 1 : 0);
    for (int i = 0; i < n; i++)
        fprintf(fp, ",%.12g", amp[i]);
    for (int i = 0; i < n; i++)
        fprintf(fp, ",%.12g", phase[i]);
    fputc('\n', fp);
}

/* The sweep's frequency r of count. */
static double grid(double fmin, double fmax, long count, long r)
{
    return r == count - 1 ? fmax : fmin + (fmax - fmin) * ((double)r / (double)(count - 1));
}

/* Opens the output, refusing --figure (not drawn for these sweeps); 0 or the status. */
static int open_out(struct output *o, const struct config *c, const char *option)
{
    if (c->figure) {
        options_say("%s: --figure draws the linear chain's sweep only, not a chain with "
                    "cubic springs (expected no --figure)", option);
        return EXIT_USAGE;
    }
    return run_open_output(o, c) != 0 ? EXIT_FAILURE : 0;
}

int run_sweep_run(const struct config *c, const struct model *m, bool up, double fmin,
                  double fmax, long count, const char *arg)
{
    int n = m->n, status = EXIT_SUCCESS, capped = 0;
    double top = fmin > fmax ? fmin : fmax;
    if (top * c->dt > 0.5) {
        /* Fewer than two steps a period: no first harmonic to measure. */
        options_say("--sweep-run: %g Hz is %.3g steps a period at dt = %g s, too few to measure "
                    "(expected frequencies up to %.6g Hz, or a smaller --dt)", top,
                    1.0 / (top * c->dt), c->dt, 0.5 / c->dt);
        return EXIT_USAGE;
    }
    /* The dt warnings --headless gives, for the highest frequency (the fewest steps a
     * period). */
    struct model *hi = model_new(n);
    bool unstable = false;
    if (hi) {
        struct limits l;
        model_copy(hi, m);
        hi->motor.frequency = top;
        if (run_judge(c, hi, &l)) {
            run_warn_limits(&l, hi);
            unstable = limits_unstable(&l);
        }
        model_free(hi);
    }
    struct output o;
    double *amp = malloc((size_t)(2 * n) * sizeof *amp);
    double *x = calloc((size_t)(2 * n), sizeof *x);
    struct sim *s = sim_new(m, c->dt);
    if (!amp || !x || !s) {
        options_say("out of memory");
        status = EXIT_FAILURE;
    } else if ((status = open_out(&o, c, "--sweep-run")) == 0) {
        sim_set_integrator(s, c->integrator);
        config_initial(c, m, x, x + n);
        sim_reset(s, x, x + n);
        run_write_meta(o.fp, c, "sweep-run", arg);
        if (c->meta)
            fprintf(o.fp, "# each point from the last one's state, run until every "
                    "amplitude is steady to %g %% (at most %d periods or %g s)\n",
                    100.0 * SWEEPRUN_STEADY, SWEEPRUN_MAX_PERIODS, SWEEPRUN_MAX_SECONDS);
        header(o.fp, n);
        struct limits_runaway watch;
        struct energy e;
        sim_energy(s, &e);
        limits_runaway_start(&watch, m, &e);
        for (long r = 0; r < count && !ferror(o.fp); r++) {
            double f = grid(fmin, fmax, count, up ? r : count - 1 - r);
            struct sweeprun_point p = sweeprun_point(s, f, amp, amp + n);
            sim_energy(s, &e);
            /* Past the stability limit, a velocity at the cap or energy made from nothing
             * (the cap keeps the numbers finite) is the run blowing up, as --headless
             * says it. */
            if (unstable && !p.diverged && (p.capped || limits_runaway_check(&watch, &e))) {
                options_say("--sweep-run: the simulation blew up at %.6g Hz (dt = %g s is past "
                            "the stability limit said above)", f, c->dt);
                status = EXIT_FAILURE;
                break;
            }
            if (p.diverged) {
                int spring;
                if (isfinite(model_turnover(m, &spring)))
                    options_say("--sweep-run: the motion ran away at %.6g Hz (spring %d softens: "
                                "past its turnover it pulls no more; less drive, or a smaller "
                                "--dt)", f, spring + 1);
                else
                    options_say("--sweep-run: the motion ran away at %.6g Hz (a smaller --dt, "
                                "or less drive)", f);
                status = EXIT_FAILURE;
                break;
            }
            capped += !p.settled;
            row(o.fp, f, 0, p.settled, n, amp, amp + n);
        }
        status = run_close_output(&o, c, status);
        if (capped && status == EXIT_SUCCESS)
            options_say("--sweep-run: %d point%s not steady to %g %% within the cap (stable "
                        "column 0)", capped, capped == 1 ? " was" : "s were",
                        100.0 * SWEEPRUN_STEADY);
    }
    sim_free(s);
    free(x);
    free(amp);
    return status;
}

/* The folds as '#' lines. */
static void say_folds(FILE *fp, const struct harmonic_curve *hc)
{
    for (int k = 0; k < hc->folds; k++)
        fprintf(fp, "# fold %d: %.12g Hz, where branches %d and %d meet (largest amplitude "
                "%.6g m)\n", k + 1, hc->fold_f[k], k + 1, k + 2, hc->fold_amp[k]);
    if (!hc->complete)
        fprintf(fp, "# the continuation stopped at %.6g Hz (an amplitude past the walls)\n",
                hc->f[hc->count - 1]);
}

int run_sweep_hb(const struct config *c, const struct model *m, double fmin, double fmax,
                 long count, const char *arg)
{
    if (m->motor.wave != WAVE_SINE) {
        options_say("--sweep: harmonic balance is for a sine drive, not '%s': the chain is "
                    "swept by simulation instead (as --sweep-run up)",
                    motor_wave_name(m->motor.wave));
        return run_sweep_run(c, m, true, fmin, fmax, count, arg);
    }
    int n = m->n, status = EXIT_SUCCESS;
    char err[200];
    struct harmonic_curve *hc = harmonic_trace(m, fmin, fmax, err, sizeof err);
    if (!hc) {
        options_say("--sweep: %s", err);
        return EXIT_USAGE;
    }
    enum { MAX_BRANCHES = HARMONIC_MAX_FOLDS + 1 };
    struct harmonic_solution sol[MAX_BRANCHES];
    double *room = malloc((size_t)(2 * n * MAX_BRANCHES) * sizeof *room);
    struct output o;
    if (!room) {
        options_say("out of memory");
        harmonic_curve_free(hc);
        return EXIT_FAILURE;
    }
    for (int b = 0; b < MAX_BRANCHES; b++)
        sol[b].amp = room + (size_t)(2 * n * b), sol[b].phase = sol[b].amp + n;
    if ((status = open_out(&o, c, "--sweep")) == 0) {
        run_write_meta(o.fp, c, "sweep", arg);
        if (c->meta)
            say_folds(o.fp, hc);
        header(o.fp, n);
        for (long r = 0; r < count && !ferror(o.fp); r++) {
            double f = grid(fmin, fmax, count, r);
            int found = harmonic_at(m, hc, f, sol, MAX_BRANCHES);
            for (int b = 0; b < found; b++)
                row(o.fp, f, sol[b].branch, sol[b].stable, n, sol[b].amp, sol[b].phase);
        }
        status = run_close_output(&o, c, status);
        if (!hc->complete && status == EXIT_SUCCESS)
            options_say("--sweep: the continuation stopped at %.6g Hz (an amplitude past the "
                        "walls): no rows above it", hc->f[hc->count - 1]);
    }
    free(room);
    harmonic_curve_free(hc);
    return status;
}
