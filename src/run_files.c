/* run_files.c: what the file-writing modes (--headless, --modes, --sweep) share: the CSV
 * output and the --figure file opened before any work and closed atomically, the --meta
 * lines, and the signal handling that removes a half-written temporary file. */
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/config.h"
#include "fig/lib.h"
#include "options.h"
#include "run_files.h"

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
void run_catch_terminate(void)
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

int run_open_output(struct output *o, const struct config *c)
{
    int e = output_open(o, c->output);
    if (e) {
        options_say("%s: %s", c->output, strerror(e));
        return EXIT_FAILURE;
    }
    return 0;
}

int run_close_output(struct output *o, const struct config *c, int status)
{
    int e = output_close(o, status == EXIT_SUCCESS);
    if (e && status == EXIT_SUCCESS) {
        options_say("%s: %s", c->output ? c->output : "standard output", strerror(e));
        return EXIT_FAILURE;
    }
    return status;
}

/* --figure: the figure library loaded and the file opened before the run, so that a
 * figure that cannot be drawn or written is said before any work (0, or EXIT_FAILURE
 * after one line); nothing to do without --figure. */
int run_open_figure(struct output *o, const struct config *c)
{
    memset(o, 0, sizeof *o);
    if (!c->figure)
        return 0;
    char why[600];
    if (!fig_lib(why, sizeof why)) {
        options_say("%s: %s", c->figure, why);
        return EXIT_FAILURE;
    }
    int e = output_open(o, c->figure);
    if (e) {
        options_say("%s: %s", c->figure, strerror(e));
        return EXIT_FAILURE;
    }
    return 0;
}

/* Finishes the figure: draws it (draw is 0, or the errno value drawing it gave) and renames
 * it into place when the run succeeded; discards it otherwise. */
int run_close_figure(struct output *o, const struct config *c, int draw, int status)
{
    if (!c->figure || !o->fp)
        return status;
    bool ok = status == EXIT_SUCCESS && draw == 0;
    int e = output_close(o, ok);
    fig_lib_loaded()->done();
    if (status == EXIT_SUCCESS && (draw || e)) {
        options_say("%s: %s", c->figure, strerror(draw ? draw : e));
        return EXIT_FAILURE;
    }
    return status;
}

/* --meta: '#' lines before the CSV header, which pandas (comment='#'), numpy (loadtxt's
 * comments) and gnuplot skip: the version, and the command line that repeats the run (the
 * mode, then every setting from the table; the seed --random chose is among them). */
void run_write_meta(FILE *fp, const struct config *c, const char *mode, const char *arg)
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

