/* main.c: the command line. Reads options and presets into a config, then runs one
 * of the modes: --headless, --modes, --sweep, --list-presets (SPEC section 2). This is
 * the only file that would know both the core and the terminal front end. */
#include <errno.h>
#include <getopt.h>
#include <limits.h>
#include <locale.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "core/config.h"
#include "core/modes.h"
#include "core/output.h"
#include "core/preset.h"
#include "core/sim.h"
#include "ui/input.h"
#include "ui/tui.h"

#ifndef VERSION
#define VERSION "0.1.0"
#endif

#define EXIT_USAGE 2
#define SWEEP_MAX 1000000 /* rows a sweep may ask for */

enum mode { MODE_INTERACTIVE, MODE_HEADLESS, MODE_MODES, MODE_SWEEP, MODE_LIST };

/* Options that choose what to do rather than set something; after the config keys. */
enum { OPT_HEADLESS = CFG_KEY_COUNT, OPT_MODES, OPT_SWEEP, OPT_LIST, OPT_KEYS, OPT_HELP,
       OPT_VERSION, OPT_COUNT };

static const struct {
    const char *name, *arg, *help;
} mode_options[] = {
    [OPT_HEADLESS - CFG_KEY_COUNT] = {"headless", NULL, "run without a terminal; CSV to "
                                      "standard output"},
    [OPT_MODES - CFG_KEY_COUNT] = {"modes", NULL, "natural frequencies and mode shapes, CSV"},
    [OPT_SWEEP - CFG_KEY_COUNT] = {"sweep", "FMIN:FMAX:COUNT", "steady-state amplitude "
                                   "against motor frequency, CSV"},
    [OPT_LIST - CFG_KEY_COUNT] = {"list-presets", NULL, "one line per preset: its name, "
                                  "then its description"},
    [OPT_KEYS - CFG_KEY_COUNT] = {"keys", NULL, "list the interactive program's keys"},
    [OPT_HELP - CFG_KEY_COUNT] = {"help", NULL, "show this help and exit"},
    [OPT_VERSION - CFG_KEY_COUNT] = {"version", NULL, "show the version and exit"},
};

static const char *progname = "springsim";

/* One line on standard error, prefixed with the program's name. */
static void say(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    fprintf(stderr, "%s: ", progname);
    vfprintf(stderr, fmt, ap);
    fputc('\n', stderr);
    va_end(ap);
}

static void usage(FILE *out)
{
    fprintf(out,
            "Usage: springsim [OPTIONS]                     interactive program\n"
            "       springsim --headless [OPTIONS]          CSV of the motion to standard "
            "output\n"
            "       springsim --modes [OPTIONS]             natural frequencies and mode "
            "shapes, CSV\n"
            "       springsim --sweep FMIN:FMAX:COUNT [OPTIONS]\n"
            "                                               steady-state amplitude against "
            "frequency, CSV\n"
            "       springsim --list-presets | --keys | --help | --version\n\n"
            "A chain of masses joined by springs, with damping, driven at its right end by "
            "a\nlinear motor. A preset is applied first; every other option overrides it.\n\n"
            "Options:\n");
    for (int k = 0; k < OPT_COUNT; k++) {
        const char *name, *arg, *help;
        char shortopt = 0, left[64];
        if (k < CFG_KEY_COUNT) {
            name = config_options[k].name, arg = config_options[k].arg;
            help = config_options[k].help, shortopt = config_options[k].short_name;
        } else {
            name = mode_options[k - CFG_KEY_COUNT].name;
            arg = mode_options[k - CFG_KEY_COUNT].arg;
            help = mode_options[k - CFG_KEY_COUNT].help;
        }
        snprintf(left, sizeof left, "%c%c%c --%s%s%s", shortopt ? '-' : ' ',
                 shortopt ? shortopt : ' ', shortopt ? ',' : ' ', name, arg ? " " : "",
                 arg ? arg : "");
        if (strlen(left) > 27)
            fprintf(out, "  %s\n  %27s  %s\n", left, "", help);
        else
            fprintf(out, "  %-27s  %s\n", left, help);
    }
    fprintf(out,
            "\nLists are comma-separated (--mass 1,2,1.5). Negative values work in both "
            "spellings:\n--x0 -0.5 and --x0=-0.5.\n\n"
            "Presets are searched in $XDG_CONFIG_HOME/springsim/presets, $SPRINGSIM_PRESETS,\n"
            "%s and presets/ beside the program.\n\n"
            "Exit status: 0 success, 1 a file could not be read or written or the run blew "
            "up,\n2 a bad option, value or preset.\n",
            preset_installed_dir);
}

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

/* Reports a bad value of key, naming where it came from: "--dt: ..." on the command
 * line, "FILE:LINE: dt: ..." from a preset. */
static void report_key(const struct config *c, int key, const char *why)
{
    const struct config_origin *o = &c->origin[key];
    if (o->file)
        say("%s:%d: %s: %s", o->file, o->line, config_options[key].name, why);
    else
        say("--%s: %s", config_options[key].name, why);
}

struct cli {
    enum mode mode;
    const char *sweep;     /* FMIN:FMAX:COUNT */
    char preset_path[PATH_MAX];
};

static void build_longopts(struct option *lo, char *shortopts)
{
    int k;
    char *s = shortopts;
    *s++ = ':'; /* report missing arguments as ':' */
    for (k = 0; k < CFG_KEY_COUNT; k++) {
        lo[k] = (struct option){config_options[k].name,
                                config_options[k].arg ? required_argument : no_argument, NULL,
                                256 + k};
        if (config_options[k].short_name) {
            *s++ = config_options[k].short_name;
            *s++ = ':';
        }
    }
    for (; k < OPT_COUNT; k++) {
        const char *arg = mode_options[k - CFG_KEY_COUNT].arg;
        lo[k] = (struct option){mode_options[k - CFG_KEY_COUNT].name,
                                arg ? required_argument : no_argument, NULL, 256 + k};
    }
    lo[k] = (struct option){0, 0, 0, 0};
    *s++ = 'h';
    *s = '\0';
}

/* Maps getopt's return value to a key or option index, or -1. */
static int option_index(int ch)
{
    if (ch >= 256 && ch < 256 + OPT_COUNT)
        return ch - 256;
    if (ch == 'h')
        return OPT_HELP;
    for (int k = 0; k < CFG_KEY_COUNT; k++)
        if (config_options[k].short_name && config_options[k].short_name == ch)
            return k;
    return -1;
}

/* The option as the user wrote it, for messages about it. */
static const char *written(char **argv, int index)
{
    return argv[index] ? argv[index] : "?";
}

/* Parses the command line into c and cli. Returns -1 to go on, or an exit status. */
static int parse_args(int argc, char **argv, struct config *c, struct cli *cli,
                      const char *exe_dir)
{
    struct option lo[OPT_COUNT + 1];
    char shortopts[64], err[512];
    const char *preset = NULL;
    int ch;

    build_longopts(lo, shortopts);
    opterr = 0;
    /* First pass: help, version and the preset, which is applied before the rest. */
    optind = 0;
    while ((ch = getopt_long(argc, argv, shortopts, lo, NULL)) != -1) {
        int k = option_index(ch);
        if (k == OPT_HELP) {
            usage(stdout);
            return fflush(stdout) == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
        }
        if (k == OPT_VERSION) {
            printf("springsim %s\n", VERSION);
            return EXIT_SUCCESS;
        }
        if (k == OPT_KEYS) {
            input_print_keys(stdout);
            return fflush(stdout) == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
        }
        if (k == CFG_PRESET)
            preset = optarg;
    }
    if (preset) {
        enum preset_status st = preset_find(preset, exe_dir, cli->preset_path,
                                            sizeof cli->preset_path);
        if (st == PRESET_NONE) {
            say("--preset: %s", cli->preset_path);
            return EXIT_USAGE;
        }
        st = preset_load(cli->preset_path, c, err, sizeof err);
        if (st != PRESET_OK) {
            say("%s", err);
            return st == PRESET_IO ? EXIT_FAILURE : EXIT_USAGE;
        }
    }
    /* Second pass: everything else, in order; the first bad one is reported. */
    optind = 0;
    int modes = 0;
    for (;;) {
        int before = optind ? optind : 1;
        ch = getopt_long(argc, argv, shortopts, lo, NULL);
        if (ch == -1)
            break;
        if (ch == '?') {
            if (optopt)
                say("'-%c' is not an option (see springsim --help)", optopt);
            else
                say("'%s' is not an option (see springsim --help)", written(argv, before));
            return EXIT_USAGE;
        }
        if (ch == ':') {
            int k = option_index(optopt);
            if (k >= 0 && k < CFG_KEY_COUNT)
                say("--%s: needs a value (%s)", config_options[k].name,
                    config_options[k].arg);
            else if (k >= CFG_KEY_COUNT)
                say("--%s: needs a value (%s)", mode_options[k - CFG_KEY_COUNT].name,
                    mode_options[k - CFG_KEY_COUNT].arg);
            else
                say("'%s' needs a value (see springsim --help)", written(argv, before));
            return EXIT_USAGE;
        }
        int k = option_index(ch);
        if (k < 0)
            continue;
        if (k < CFG_KEY_COUNT) {
            if (k == CFG_PRESET)
                continue;
            if (config_set(c, k, optarg, err, sizeof err) != 0) {
                say("--%s: %s", config_options[k].name, err);
                return EXIT_USAGE;
            }
            c->origin[k] = (struct config_origin){NULL, 0};
            continue;
        }
        enum mode m = MODE_INTERACTIVE;
        switch (k) {
        case OPT_HEADLESS:
            m = MODE_HEADLESS;
            break;
        case OPT_MODES:
            m = MODE_MODES;
            break;
        case OPT_SWEEP:
            m = MODE_SWEEP;
            cli->sweep = optarg;
            break;
        case OPT_LIST:
            m = MODE_LIST;
            break;
        default:
            break;
        }
        if (m != MODE_INTERACTIVE) {
            if (modes++ && cli->mode != m) {
                say("'%s': give only one of --headless, --modes, --sweep and --list-presets",
                    written(argv, before));
                return EXIT_USAGE;
            }
            cli->mode = m;
        }
    }
    if (optind < argc) {
        say("'%s' is not an option (springsim takes no other arguments; see --help)",
            argv[optind]);
        return EXIT_USAGE;
    }
    return -1;
}

/* Says why a run stopped on a non-finite number, with the stability limit. */
static void report_blowup(const struct sim *s)
{
    const struct model *m = sim_model(s);
    double dt = sim_dt(s), limit = modes_stable_dt(m);
    if (dt >= limit)
        say("the simulation blew up at t = %.4g s: dt = %g s is too large for these springs "
            "(RK4 needs omega_max*dt < %.2f: dt < %.4g s)",
            sim_time(s), dt, MODES_RK4_LIMIT, limit);
    else
        say("the simulation blew up at t = %.4g s: numbers became non-finite with dt = %g s "
            "(RK4 stability limit dt < %.4g s)", sim_time(s), dt, limit);
}

static int open_output(struct output *o, const struct config *c)
{
    int e = output_open(o, c->output);
    if (e) {
        say("%s: %s", c->output, strerror(e));
        return EXIT_FAILURE;
    }
    return 0;
}

static int close_output(struct output *o, const struct config *c, int status)
{
    int e = output_close(o, status == EXIT_SUCCESS);
    if (e && status == EXIT_SUCCESS) {
        say("%s: %s", c->output ? c->output : "standard output", strerror(e));
        return EXIT_FAILURE;
    }
    return status;
}

static int run_headless(const struct config *c, const struct model *m)
{
    int n = m->n, status = EXIT_SUCCESS;
    double *x = malloc((size_t)(3 * n) * sizeof *x);
    struct sim *s = sim_new(m, c->dt);
    struct output o;
    if (!x || !s) {
        say("out of memory");
        free(x);
        sim_free(s);
        return EXIT_FAILURE;
    }
    double limit = modes_stable_dt(m);
    if (c->dt >= limit)
        say("warning: dt = %g s is above the RK4 stability limit of this chain, dt < %.4g s "
            "(omega_max*dt < %.2f)", c->dt, limit, MODES_RK4_LIMIT);
    config_initial(c, m, x, x + n);
    sim_reset(s, x, x + n);
    if (open_output(&o, c)) {
        free(x);
        sim_free(s);
        return EXIT_FAILURE;
    }
    long long stride = 1;
    if (c->sample > 0.0) {
        double r = llround(c->sample / c->dt);
        stride = r < 1 ? 1 : (long long)r;
    }
    double total = floor(c->duration / c->dt + 1e-9);
    output_csv_header(o.fp, n, c->energy);
    output_csv_row(o.fp, s, c->energy, x + 2 * n);
    for (double step = 1; step <= total; step++) {
        /* Past the stability limit a capped velocity means the numbers are running away:
         * stop rather than write nonsense. */
        if (sim_step(s) != SIM_OK || (c->dt >= limit && sim_last_capped(s))) {
            report_blowup(s);
            status = EXIT_FAILURE;
            break;
        }
        if (fmod(step, (double)stride) == 0.0) {
            output_csv_row(o.fp, s, c->energy, x + 2 * n);
            if (ferror(o.fp))
                break;
        }
    }
    status = close_output(&o, c, status);
    free(x);
    sim_free(s);
    return status;
}

static int run_modes(const struct config *c, const struct model *m)
{
    int n = m->n;
    double *f = malloc((size_t)n * sizeof *f);
    double *shapes = malloc((size_t)n * (size_t)n * sizeof *shapes);
    struct output o;
    int status = EXIT_SUCCESS;
    if (!f || !shapes || modes_compute(m, f, shapes) != 0) {
        say(!f || !shapes ? "out of memory" : "the eigenvalue solver (LAPACK dstev) failed");
        free(f);
        free(shapes);
        return EXIT_FAILURE;
    }
    if (open_output(&o, c) == 0) {
        fputs("mode,frequency_hz", o.fp);
        for (int i = 1; i <= n; i++)
            fprintf(o.fp, ",x%d", i);
        fputc('\n', o.fp);
        for (int j = 0; j < n; j++) {
            fprintf(o.fp, "%d,%.12g", j + 1, f[j]);
            for (int i = 0; i < n; i++)
                fprintf(o.fp, ",%.12g", shapes[(size_t)j * n + i]);
            fputc('\n', o.fp);
        }
        status = close_output(&o, c, status);
    } else {
        status = EXIT_FAILURE;
    }
    free(f);
    free(shapes);
    return status;
}

/* Parses FMIN:FMAX:COUNT; on error says why and returns -1. */
static int parse_sweep(const char *spec, double *fmin, double *fmax, long *count)
{
    const char *expect = "expected FMIN:FMAX:COUNT with 0 < FMIN < FMAX and 2 <= COUNT <= "
                         "1000000";
    char buf[128], *end;
    if (strlen(spec) >= sizeof buf) {
        say("--sweep: '%.40s...' is too long (%s)", spec, expect);
        return -1;
    }
    strcpy(buf, spec);
    char *a = buf, *b = strchr(a, ':'), *cnt = b ? strchr(b + 1, ':') : NULL;
    if (!b || !cnt || strchr(cnt + 1, ':')) {
        say("--sweep: '%s' is not three values separated by ':' (%s)", spec, expect);
        return -1;
    }
    *b++ = '\0';
    *cnt++ = '\0';
    errno = 0;
    *fmin = strtod(a, &end);
    int bad = end == a || *end || !isfinite(*fmin);
    *fmax = strtod(b, &end);
    bad |= end == b || *end || !isfinite(*fmax);
    *count = strtol(cnt, &end, 10);
    bad |= end == cnt || *end || errno == ERANGE;
    if (bad) {
        say("--sweep: '%s' has a value that is not a number (%s)", spec, expect);
        return -1;
    }
    if (!(*fmin > 0.0 && *fmin < *fmax && *count >= 2 && *count <= SWEEP_MAX)) {
        say("--sweep: '%s' is out of range (%s)", spec, expect);
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
        say("--sweep: the right end is '%s', which does not drive the chain (expected "
            "--boundary motor)", model_boundary_name(m->boundary));
        return EXIT_USAGE;
    }
    int n = m->n, status = EXIT_SUCCESS;
    double *amp = malloc((size_t)n * sizeof *amp);
    struct output o;
    if (!amp) {
        say("out of memory");
        return EXIT_FAILURE;
    }
    if (open_output(&o, c) != 0) {
        free(amp);
        return EXIT_FAILURE;
    }
    fputs("frequency_hz", o.fp);
    for (int i = 1; i <= n; i++)
        fprintf(o.fp, ",amp%d", i);
    fputc('\n', o.fp);
    for (long r = 0; r < count; r++) {
        double f = r == count - 1 ? fmax : fmin + (fmax - fmin) * (double)r / (count - 1);
        if (modes_response(m, f, amp) != 0) {
            /* An undamped chain exactly at a natural frequency has no steady state. */
            for (int i = 0; i < n; i++)
                amp[i] = INFINITY;
        }
        fprintf(o.fp, "%.12g", f);
        for (int i = 0; i < n; i++)
            fprintf(o.fp, isfinite(amp[i]) ? ",%.12g" : ",inf", amp[i]);
        fputc('\n', o.fp);
        if (ferror(o.fp))
            break;
    }
    status = close_output(&o, c, status);
    free(amp);
    return status;
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
    int status = parse_args(argc, argv, &c, &cli, exe_dir);
    if (status >= 0)
        return status;
    if (cli.mode == MODE_LIST) {
        if (preset_list(stdout, exe_dir) == 0)
            say("no presets found (searched the user's directory, $SPRINGSIM_PRESETS, %s "
                "and %s/presets)", preset_installed_dir, exe_dir);
        return fflush(stdout) == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
    }
    int bad_key;
    struct model *m = config_model(&c, &bad_key, err, sizeof err);
    if (!m) {
        if (bad_key < 0) {
            say("%s", err);
            return EXIT_FAILURE;
        }
        report_key(&c, bad_key, err);
        return EXIT_USAGE;
    }
    if (c.random && !c.seed_set)
        c.seed = (uint64_t)time(NULL) ^ ((uint64_t)getpid() << 32);
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
        if (c.masses > 10) {
            char why[160];
            snprintf(why, sizeof why, "'%d' is out of range for the interactive program "
                     "(expected 1 <= N <= 10; --headless takes up to 1000)", c.masses);
            report_key(&c, CFG_MASSES, why);
            status = EXIT_USAGE;
            break;
        }
        status = tui_run(&c, exe_dir);
        break;
    }
    model_free(m);
    return status;
}
