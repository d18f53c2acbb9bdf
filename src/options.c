/* options.c: the command line read into a config (getopt_long over the one option
 * table in core/config.c): help, version and the key list, the preset applied first
 * wherever it stands, then every other option in order, the first bad one reported in
 * one line. Kept apart from main.c so the fuzz target can drive it. */
#include "options.h"

#include <errno.h>
#include <getopt.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/preset.h"
#include "tui/input.h"

#ifndef VERSION
#define VERSION "0.1.0"
#endif

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

static FILE *errors; /* where error lines go; NULL: standard error */

void options_set_errors(FILE *f)
{
    errors = f;
}

void options_say(const char *fmt, ...)
{
    FILE *out = errors ? errors : stderr;
    char line[2048], safe[4 * sizeof line];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(line, sizeof line, fmt, ap);
    va_end(ap);
    /* Whatever went into it, the line reaches the terminal as one line of text. */
    config_escape(line, strlen(line), sizeof line, safe, sizeof safe);
    fprintf(out, "%s: %s\n", progname, safe);
}

int options_finish_stdout(void)
{
    /* The error flag may have been set by an earlier write whose errno is gone. */
    errno = 0;
    int bad = fflush(stdout) != 0 || ferror(stdout);
    int e = errno;
    if (fclose(stdout) != 0 && !bad) {
        bad = 1;
        e = errno;
    }
    if (!bad)
        return EXIT_SUCCESS;
    options_say("standard output: %s", strerror(e ? e : EIO));
    return EXIT_FAILURE;
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


void options_report_key(const struct config *c, int key, const char *why)
{
    const struct config_origin *o = &c->origin[key];
    if (o->file)
        options_say("%s:%d: %s: %s", o->file, o->line, config_options[key].name, why);
    else
        options_say("--%s: %s", config_options[key].name, why);
}

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

/* The option as the user wrote it, quoted for a message about it. */
static const char *written(char **argv, int index, char *buf, size_t len)
{
    const char *w = argv[index] ? argv[index] : "?";
    config_quote(w, strlen(w), buf, len);
    return buf;
}

/* Parses the command line into c and cli. Returns -1 to go on, or an exit status. */
int options_parse(int argc, char **argv, struct config *c, struct cli *cli,
                  const char *exe_dir)
{
    struct option lo[OPT_COUNT + 1];
    char shortopts[64], err[512], q[4 * CONFIG_QUOTE_MAX + 48];
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
            return options_finish_stdout();
        }
        if (k == OPT_VERSION) {
            printf("springsim %s\n", VERSION);
            return options_finish_stdout();
        }
        if (k == OPT_KEYS) {
            input_print_keys(stdout);
            return options_finish_stdout();
        }
        if (k == CFG_PRESET) {
            /* The last one counts, but every one must exist. */
            if (preset_find(optarg, exe_dir, cli->preset_path, sizeof cli->preset_path) ==
                PRESET_NONE) {
                options_say("--preset: %s", cli->preset_path);
                return EXIT_USAGE;
            }
            preset = optarg;
        }
    }
    if (preset) {
        enum preset_status st = preset_find(preset, exe_dir, cli->preset_path,
                                            sizeof cli->preset_path);
        if (st == PRESET_NONE) {
            options_say("--preset: %s", cli->preset_path);
            return EXIT_USAGE;
        }
        st = preset_load(cli->preset_path, c, err, sizeof err);
        if (st != PRESET_OK) {
            options_say("%s", err);
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
                options_say("'-%c' is not an option (see springsim --help)", optopt);
            else
                options_say("%s is not an option (see springsim --help)",
                            written(argv, before, q, sizeof q));
            return EXIT_USAGE;
        }
        if (ch == ':') {
            int k = option_index(optopt);
            if (k >= 0 && k < CFG_KEY_COUNT)
                options_say("--%s: needs a value (%s)", config_options[k].name,
                    config_options[k].arg);
            else if (k >= CFG_KEY_COUNT)
                options_say("--%s: needs a value (%s)", mode_options[k - CFG_KEY_COUNT].name,
                    mode_options[k - CFG_KEY_COUNT].arg);
            else
                options_say("%s needs a value (see springsim --help)",
                            written(argv, before, q, sizeof q));
            return EXIT_USAGE;
        }
        int k = option_index(ch);
        if (k < 0)
            continue;
        if (k < CFG_KEY_COUNT) {
            if (k == CFG_PRESET)
                continue;
            if (config_set(c, k, optarg, err, sizeof err) != 0) {
                options_say("--%s: %s", config_options[k].name, err);
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
                options_say("%s: give only one of --headless, --modes, --sweep and --list-presets",
                    written(argv, before, q, sizeof q));
                return EXIT_USAGE;
            }
            cli->mode = m;
        }
    }
    if (optind < argc) {
        written(argv, optind, q, sizeof q);
        if (optind > 1 && strcmp(argv[optind - 1], "--") == 0)
            options_say("springsim takes no arguments, but %s was given after '--' (see "
                        "--help)", q);
        else
            options_say("%s is not an option (springsim takes no other arguments; see --help)",
                        q);
        return EXIT_USAGE;
    }
    return -1;
}
