/* export.c: what the CSV exports say about themselves (the '#' lines --meta writes: the
 * version and the command line that makes the data again) and the sine sweep's measured
 * points written beside the theory's. */
#include "change.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>

#include "../core/modes.h"
#include "../core/output.h"

/* "# springsim VERSION" and "# springsim --MODE [ARG] SETTINGS...", as --meta writes them,
 * for the settings c. */
static void meta_lines(FILE *fp, const struct config *c, const char *mode, const char *arg)
{
    fprintf(fp, "# springsim %s\n# springsim --%s", VERSION, mode);
    if (arg)
        fprintf(fp, " %s", arg);
    config_write_args(fp, c);
    fputc('\n', fp);
}

void app_export_meta(FILE *fp, const struct app *app)
{
    const struct trail *tr = app->trail;
    double t = sim_time(app->sim), every = app->sample_every * app->cfg.dt;
    double from = tr->count ? trail_time(tr, 0) : t;
    struct config c = app->cfg;
    c.duration = t > c.dt ? t : c.dt;
    c.frequency = app->sweep->active ? app->sweep_from : c.frequency;
    char sample[64];
    snprintf(sample, sizeof sample, "--sample %.6g", every);
    meta_lines(fp, &c, "headless", sample);
    fprintf(fp, "# exported from the interactive program at t = %.*f s: %d row%s from t = %.*f s, "
            "every %.6g s", app_time_decimals(c.dt), t, tr->count, tr->count == 1 ? "" : "s",
            app_time_decimals(c.dt), from, every);
    if (tr->count >= tr->capacity)
        fprintf(fp, " (the recording keeps the last %d samples)", tr->capacity);
    fputs("; the line above repeats the run if no setting changed during it\n", fp);
}

void app_export_summary(const struct app *app, char *buf, size_t len)
{
    const struct trail *tr = app->trail;
    int d = app_time_decimals(app->cfg.dt);
    double t0 = tr->count ? trail_time(tr, 0) : 0.0, t1 = tr->count ? trail_time(tr, tr->count - 1) : 0.0;
    if (t0 > 0.5 * app->cfg.dt) /* the start has gone: say what is kept */
        snprintf(buf, len, "%d rows, the last %.*f s (t = %.*f to %.*f s)", tr->count, d, t1 - t0,
                 d, t0, d, t1);
    else
        snprintf(buf, len, "%d row%s (t = 0 to %.*f s)", tr->count, tr->count == 1 ? "" : "s",
                 d, t1);
}

/* A file name springsim-sweep-STAMP.csv in dir that is not there yet, into path. */
static void sweep_name(const char *dir, char *path, size_t len)
{
    time_t now = time(NULL);
    struct tm tm;
    char stamp[32];
    localtime_r(&now, &tm);
    strftime(stamp, sizeof stamp, "%Y%m%d-%H%M%S", &tm);
    struct stat st;
    snprintf(path, len, "%s/springsim-sweep-%s.csv", dir ? dir : ".", stamp);
    for (int k = 2; lstat(path, &st) == 0 && k < 1000; k++)
        snprintf(path, len, "%s/springsim-sweep-%s-%d.csv", dir ? dir : ".", stamp, k);
}

/* The header of the sweep's rows for n masses, with a direction column after the
 * frequency when there are two sweeps (legs). */
static void sweep_header(FILE *fp, int n, bool legs)
{
    fputs(legs ? "frequency_hz,direction" : "frequency_hz", fp);
    static const char *const cols[] = {"amp", "phase", "theory_amp", "theory_phase"};
    for (int c = 0; c < 4; c++)
        for (int i = 1; i <= n; i++)
            fprintf(fp, ",%s%d", cols[c], i);
    fputc('\n', fp);
}

/* The rows of sweep s: each measured point's frequency (and leg, the direction, unless
 * NULL), amplitudes and phases, then the linear theory's at that frequency for the chain
 * as it is. Returns the rows. */
static int sweep_rows(FILE *fp, const struct app *app, const struct sweep *s, const char *leg,
                      double *amp, double *phase)
{
    int n = s->n, rows = 0;
    struct model m = *app->model; /* shares the arrays, only read */
    for (int p = 0; p < s->points; p++) {
        const double *pk = s->peak + (size_t)p * n, *ph = s->phase + (size_t)p * n;
        if (isnan(pk[0]))
            continue; /* not measured */
        m.motor.frequency = s->freq[p];
        if (modes_response_phase(&m, s->freq[p], amp, phase) != 0)
            for (int i = 0; i < n; i++)
                amp[i] = INFINITY, phase[i] = NAN;
        fprintf(fp, "%.12g", s->freq[p]);
        if (leg)
            fprintf(fp, ",%s", leg);
        for (int i = 0; i < n; i++)
            fprintf(fp, ",%.12g", pk[i]);
        for (int i = 0; i < n; i++)
            fprintf(fp, isnan(ph[i]) ? ",nan" : ",%.12g", ph[i]);
        for (int i = 0; i < 2 * n; i++)
            fprintf(fp, isfinite(amp[i]) ? ",%.12g" : isnan(amp[i]) ? ",nan" : ",inf", amp[i]);
        fputc('\n', fp);
        rows++;
    }
    return rows;
}

unsigned app_export_sweep(struct app *app, const char *dir, char *path, size_t len)
{
    const struct sweep *s = app->sweep;
    int measured = sweep_measured(s);
    if (measured == 0)
        return app_say(app, SAID_ERROR, "export: no sweep measured yet (w runs one)");
    if (app->model->boundary != BOUNDARY_MOTOR && !model_forced(app->model))
        return app_say(app, SAID_ERROR, "export: the right end is '%s' now and no force is on: "
                       "no drive, no theory to set beside the sweep",
                       model_boundary_name(app->model->boundary));
    double *amp = malloc((size_t)(2 * s->n) * sizeof *amp);
    if (!amp)
        return app_say(app, SAID_ERROR, "export: out of memory");
    sweep_name(dir, path, len);
    struct config c = app->cfg;
    c.frequency = s->active ? app->sweep_from : c.frequency;
    /* A chain with cubic springs swept up, then down (jump.c): both, the up one first. */
    const struct sweep *up = sweep_measured(app->sweep_up) > 0 ? app->sweep_up : NULL;
    const struct sweep *first = up ? up : s;
    char spec[96], lo[32], hi[32];
    config_format_exact(first->freq[0], lo, sizeof lo);
    config_format_exact(first->freq[first->points - 1], hi, sizeof hi);
    snprintf(spec, sizeof spec, "%s:%s:%d", lo, hi, s->points);
    struct output o;
    int e = output_open(&o, path), rows = 0;
    if (e == 0) {
        meta_lines(o.fp, &c, "sweep", spec);
        char settle[160];
        if (s->hold > 0.0)
            snprintf(settle, sizeof settle, "once steady (8 periods at least, then every swing "
                     "and phasor level within 1 %% of the largest for %.3g s and 4 periods; "
                     "%d not steady after %.3g s)", s->hold, s->unsteady, s->most);
        else
            snprintf(settle, sizeof settle, "after settling at least %.3g s and 8 periods",
                     s->settle_min);
        fprintf(o.fp, "# measured by springsim's sweep experiment: a stepped sine, each point %s, "
                "over "
                "3 s or 4 periods; amp: peak |x| (m), phase: x to the drive (degrees); "
                "theory_: the linear steady state, as the line above gives it%s\n", settle,
                s->active ? "; the sweep was still running" : "");
        if (s->contacts > 0)
            fprintf(o.fp, "# %ld contact%s during the sweep: off the linear theory\n",
                    s->contacts, s->contacts == 1 ? "" : "s");
        if (up)
            fprintf(o.fp, "# the sweep up, then the sweep down from the state it ended in "
                    "(direction); theory_: the chain linearised at rest; --sweep with the "
                    "line above gives the harmonic balance\n");
        sweep_header(o.fp, s->n, up != NULL);
        rows = up ? sweep_rows(o.fp, app, up, "up", amp, amp + s->n) : 0;
        rows += sweep_rows(o.fp, app, s, up ? "down" : NULL, amp, amp + s->n);
        e = output_close(&o, true);
    }
    free(amp);
    char shown[128];
    if (e)
        return app_say(app, SAID_ERROR, "export: %s: %s",
                       app_path_shown(path, shown, sizeof shown), strerror(e));
    return app_say(app, SAID_NOTE, "exported the sweep's %d point%s beside the theory to %s", rows,
                   rows == 1 ? "" : "s", path);
}
