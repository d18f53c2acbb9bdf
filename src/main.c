/* main.c: reads the command line (options.c) and runs one of the modes: the
 * interactive program (or its plain mode), --headless (run_headless.c), --modes and
 * --sweep (run_tables.c), --list-presets, --list-lessons (springsim(1), MODES).
 * This is the only file that knows both the core and the terminal front end. */
#include <limits.h>
#include <locale.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "core/config.h"
#include "core/preset.h"
#include "fig/lib.h"
#include "lab/lesson.h"
#include "lessons_cli.h"
#include "options.h"
#include "plain/plain.h"
#include "run.h"
#include "run_files.h"
#include "tui/tui.h"

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

/* --list-presets: preset_list's lines (escaped there). */
static int list_presets(const char *exe_dir)
{
    int found = preset_list(stdout, exe_dir);
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
    fig_lib_where(exe_dir); /* the figure library beside a build tree's program */
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
    /* Each row of a study makes its own chain, and is checked there. */
    if (cli.mode == MODE_BATCH) {
        run_catch_terminate();
        return run_batch(&c, cli.batch);
    }
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
    if (cli.mode == MODE_HEADLESS || cli.mode == MODE_MODES || cli.mode == MODE_SWEEP ||
        cli.mode == MODE_SWEEP_RUN)
        run_catch_terminate();
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
    case MODE_SWEEP_RUN:
        status = run_sweep_run_cli(&c, m, cli.sweep_dir, cli.sweep);
        break;
    default:
        /* A terminal that cannot place the cursor gets the plain mode. */
        static struct lesson lesson;
        status = interactive_limits(&c);
        if (status == EXIT_SUCCESS && (c.lesson || c.replay)) {
            bool keys = cli.mode != MODE_PLAIN && !tui_dumb_terminal();
            int st = lessons_load(&c, exe_dir, keys, &lesson);
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
