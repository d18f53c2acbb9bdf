/* run_tables.c: the modes that write a table computed, not stepped: --modes (the natural
 * frequencies and shapes) and --sweep (the steady response over a range of frequencies),
 * each with --figure's plot of it. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "core/config.h"
#include "core/modes.h"
#include "core/output.h"
#include "fig/lib.h"
#include "options.h"
#include "run.h"
#include "run_files.h"

#define SWEEP_MAX 1000000 /* rows a sweep may ask for */
#define DAMPED_TELL 200   /* masses from which the damped modes' solve is announced */

/* The damped modes; a dense eigen-solve of a long chain takes a while (dgeev on 2N: about
 * 1 s at N = 300, 30 s at N = 1000), so a terminal is told while it runs. */
static int damped_modes(const struct model *m, const double *shapes, double *ratio,
                        double *damped_hz, double *eigen)
{
    bool tell = m->n >= DAMPED_TELL && !model_rayleigh(m) && isatty(STDERR_FILENO);
    if (tell) {
        double s = 30.0 * pow(m->n / 1000.0, 3.0);
        fprintf(stderr, "springsim: the damped modes of %d masses: LAPACK's dense eigen-solve "
                "of a %d x %d matrix, about %.0f s with the reference BLAS...", m->n, 2 * m->n,
                2 * m->n, s < 1.0 ? 1.0 : s);
        fflush(stderr);
    }
    int e = modes_damped_all(m, shapes, ratio, damped_hz, eigen);
    if (tell)
        fputs("\r\033[K", stderr);
    return e;
}

int run_modes(const struct config *c, const struct model *m)
{
    int n = m->n;
    double *f = malloc((size_t)(4 * n) * sizeof *f);
    double *shapes = malloc((size_t)n * (size_t)n * sizeof *shapes);
    struct output o;
    int status = EXIT_SUCCESS;
    double *ratio = f ? f + n : NULL, *damped_hz = f ? f + 2 * n : NULL;
    double *eigen = f ? f + 3 * n : NULL;
    if (!f || !shapes || modes_compute(m, f, shapes) != 0 ||
        damped_modes(m, shapes, ratio, damped_hz, eigen) != 0) {
        options_say(!f || !shapes ? "out of memory"
                                  : "the modes cannot be computed for these values "
                                    "(LAPACK failed, or the numbers overflow)");
        free(f);
        free(shapes);
        return EXIT_FAILURE;
    }
    struct output fo;
    if (run_open_output(&o, c) == 0 && run_open_figure(&fo, c) != 0) {
        output_close(&o, false);
        status = EXIT_FAILURE;
    } else if (o.fp) {
        run_write_meta(o.fp, c, "modes", NULL);
        fputs("mode,frequency_hz", o.fp);
        for (int i = 1; i <= n; i++)
            fprintf(o.fp, ",x%d", i);
        fputs(",damping_ratio,damped_frequency_hz,eigen_frequency_hz\n", o.fp);
        for (int j = 0; j < n; j++) {
            fprintf(o.fp, "%d,%.12g", j + 1, f[j]);
            for (int i = 0; i < n; i++)
                fprintf(o.fp, ",%.12g", shapes[(size_t)j * n + i]);
            /* a rigid-body mode has no damping ratio: the field is left empty */
            if (isnan(ratio[j]))
                fputc(',', o.fp);
            else
                fprintf(o.fp, ",%.12g", ratio[j]);
            fprintf(o.fp, ",%.12g,%.12g\n", damped_hz[j], eigen[j]);
        }
        if (m->cubic)
            options_say("note: the modes of the chain linearised at rest (its cubic springs "
                        "at zero stretch, k3 left out)");
        int rigid = model_rigid_modes(m);
        if (rigid > 0)
            options_say("note: %d rigid-body mode%s at 0 Hz (a group of masses no spring ties "
                        "to a wall or the motor): no damping ratio, left empty", rigid,
                        rigid > 1 ? "s" : "");
        status = run_close_output(&o, c, status);
        if (c->figure) {
            char settings[400];
            report_settings(c, m, settings, sizeof settings);
            struct report_look look = report_look_of(c, settings);
            int draw = status == EXIT_SUCCESS
                           ? fig_lib_loaded()->modes(fo.fp, fig_format_of(c->figure), m, f,
                                                     shapes, &look)
                           : 0;
            status = run_close_figure(&fo, c, draw, status);
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
static int parse_sweep(const char *opt, const char *spec, double *fmin, double *fmax,
                       long *count)
{
    const char *expect = "expected FMIN:FMAX:COUNT with 0 < FMIN < FMAX <= 1e6 and "
                         "2 <= COUNT <= 1000000";
    char buf[128], q[4 * CONFIG_QUOTE_MAX + 48];
    config_quote(spec, strlen(spec), q, sizeof q);
    if (strlen(spec) >= sizeof buf) {
        options_say("%s: %s is too long (%s)", opt, q, expect);
        return -1;
    }
    strcpy(buf, spec);
    char *a = buf, *b = strchr(a, ':'), *cnt = b ? strchr(b + 1, ':') : NULL;
    if (!b || !cnt || strchr(cnt + 1, ':')) {
        options_say("%s: %s is not three values separated by ':' (%s)", opt, q, expect);
        return -1;
    }
    *b++ = '\0';
    *cnt++ = '\0';
    double c;
    const char *digits = cnt + (cnt[0] == '+');
    if (config_parse_number(a, fmin) || config_parse_number(b, fmax) ||
        config_parse_number(cnt, &c)) {
        options_say("%s: %s has a value that is not a number (%s)", opt, q, expect);
        return -1;
    }
    /* A number, but not a count: say which is wrong (-5 is out of range, 1.5 not whole). */
    if (!*digits || strspn(digits, "0123456789") != strlen(digits)) {
        char qc[4 * CONFIG_QUOTE_MAX + 48];
        config_quote(cnt, strlen(cnt), qc, sizeof qc);
        options_say("%s: %s has COUNT %s, which %s (%s)", opt, q, qc,
                    c != floor(c) ? "is not a whole number"
                    : c < 2.0     ? "is out of range"
                                  : "is not written in digits", expect);
        return -1;
    }
    *count = c > SWEEP_MAX ? SWEEP_MAX + 1 : (long)c;
    if (!(*fmin > 0.0 && *fmin < *fmax && *fmax <= 1e6 && *count >= 2 && *count <= SWEEP_MAX)) {
        options_say("%s: %s is out of range (%s)", opt, q, expect);
        return -1;
    }
    return 0;
}

int run_sweep(const struct config *c, const struct model *m, const char *spec)
{
    double fmin, fmax;
    long count;
    if (parse_sweep("--sweep", spec, &fmin, &fmax, &count) != 0)
        return EXIT_USAGE;
    if (m->boundary != BOUNDARY_MOTOR && !model_forced(m)) {
        options_say("--sweep: the right end is '%s', which does not drive the chain, and there "
            "is no force (expected --boundary motor, or --force F on a mass)",
            model_boundary_name(m->boundary));
        return EXIT_USAGE;
    }
    if (!model_driven(m)) { /* the motor standing still drives no more than a wall */
        options_say("--sweep: the motor's amplitude is 0, which does not drive the chain, and "
            "there is no force (expected --amplitude A > 0, or --force F on a mass)");
        return EXIT_USAGE;
    }
    if (m->cubic)
        return run_sweep_hb(c, m, fmin, fmax, count, spec);
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
    if (run_open_output(&o, c) != 0) {
        free(amp);
        report_data_free(fig);
        return EXIT_FAILURE;
    }
    if (run_open_figure(&fo, c) != 0) {
        output_close(&o, false);
        free(amp);
        report_data_free(fig);
        return EXIT_FAILURE;
    }
    run_write_meta(o.fp, c, "sweep", spec);
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
    status = run_close_output(&o, c, status);
    if (fig) {
        char settings[400];
        report_settings(c, m, settings, sizeof settings);
        struct report_look look = report_look_of(c, settings);
        look.xfreq = report_frequency_label(m);
        int draw = status == EXIT_SUCCESS
                       ? fig_lib_loaded()->sweep(fo.fp, fig_format_of(c->figure), fig, n, &look)
                       : 0;
        status = run_close_figure(&fo, c, draw, status);
    }
    report_data_free(fig);
    free(amp);
    return status;
}


int run_sweep_run_cli(const struct config *c, const struct model *m, const char *dir,
                      const char *spec)
{
    double fmin, fmax;
    long count;
    bool up = strcmp(dir, "up") == 0;
    if (!up && strcmp(dir, "down") != 0) {
        char q[4 * CONFIG_QUOTE_MAX + 48];
        config_quote(dir, strlen(dir), q, sizeof q);
        options_say("--sweep-run: %s is not a direction (expected up or down)", q);
        return EXIT_USAGE;
    }
    if (parse_sweep("--sweep-run", spec, &fmin, &fmax, &count) != 0)
        return EXIT_USAGE;
    if (!model_driven(m)) {
        options_say("--sweep-run: nothing drives the chain: the right end is '%s'%s and there "
                    "is no force (expected --boundary motor with an amplitude, or --force F "
                    "on a mass)", model_boundary_name(m->boundary),
                    m->boundary == BOUNDARY_MOTOR ? " at amplitude 0" : "");
        return EXIT_USAGE;
    }
    char arg[200];
    snprintf(arg, sizeof arg, "%s %s", dir, spec);
    return run_sweep_run(c, m, up, fmin, fmax, count, arg);
}
