/* options.c: the command line read into a config (getopt_long over the one option
 * table in core/config.c): help, version and the key list, the preset applied first
 * wherever it stands, then every other option in order, the first bad one reported in
 * one line. Kept apart from main.c so the fuzz target can drive it. */
#include "options.h"

#include <errno.h>
#include <getopt.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "core/preset.h"
#include "core/search.h"
#include "tui/input.h"

#ifndef VERSION
#define VERSION "0.1.0"
#endif

static const char *progname = "springsim";

static FILE *errors; /* where error lines go; NULL: standard error */
static const char *context; /* what every line is about (a --batch row), or NULL */

void options_set_errors(FILE *f)
{
    errors = f;
}

void options_set_context(const char *what)
{
    context = what;
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
    if (context) {
        char where[4 * sizeof line];
        config_escape(context, strlen(context), sizeof line, where, sizeof where);
        fprintf(out, "%s: %s: %s\n", progname, where, safe);
    } else {
        fprintf(out, "%s: %s\n", progname, safe);
    }
}

int options_finish_stdout(bool close)
{
    /* The error flag may have been set by an earlier write whose errno is gone. */
    errno = 0;
    int bad = fflush(stdout) != 0 || ferror(stdout);
    int e = errno;
    if (close && fclose(stdout) != 0 && !bad) {
        bad = 1;
        e = errno;
    }
    if (!bad)
        return EXIT_SUCCESS;
    options_say("standard output: %s", strerror(e ? e : EIO));
    return EXIT_FAILURE;
}

/* Help-type output is held whole until options_finish_stdout flushes it, so that a failed
 * write (a full disk) happens there, with its reason, and not half-way through the text,
 * whose reason the later writes lose. */
static void hold_stdout(void)
{
    static char buf[1 << 16];
    setvbuf(stdout, buf, _IOFBF, sizeof buf);
}

/* Writes text from column indent, words wrapped before column width, later lines indented. */
static void wrap(FILE *out, const char *text, int indent, int width)
{
    int col = indent;
    const char *p = text;
    while (*p) {
        size_t w = strcspn(p, " ");
        if (col > indent && col + 1 + (int)w > width) {
            fprintf(out, "\n%*s", indent, "");
            col = indent;
        } else if (col > indent) {
            fputc(' ', out);
            col++;
        }
        fwrite(p, 1, w, out);
        col += (int)w;
        p += w;
        while (*p == ' ')
            p++;
    }
    fputc('\n', out);
}

static void usage(FILE *out)
{
    fprintf(out,
            "Usage: springsim [OPTIONS]                     interactive program\n"
            "       springsim --headless [OPTIONS]          CSV of the motion to standard "
            "output\n"
            "       springsim --modes [OPTIONS]             natural frequencies, shapes, "
            "damping, CSV\n"
            "       springsim --sweep FMIN:FMAX:COUNT [OPTIONS]\n"
            "                                               steady-state amplitude and phase, "
            "CSV\n"
            "       springsim --plain [OPTIONS]             the interactive program as lines, "
            "commands\n"
            "                                               on standard input\n"
            "       springsim --lesson NAME|FILE [--plain]  a guided lesson (L in the program)\n"
            "       springsim --list-presets | --list-lessons | --keys | --help | --version\n\n"
            "A chain of masses joined by springs, with damping, driven at its right end by "
            "a\nlinear motor. A preset is applied first; every other option overrides it.\n\n"
            "Options:\n");
    for (int k = 0; k < CFG_KEY_COUNT; k++) {
        const struct config_option *o = &config_options[k];
        char arg[128], help[256], left[160];
        config_arg(k, arg, sizeof arg);
        config_help(k, help, sizeof help);
        snprintf(left, sizeof left, "%c%c%c --%s%s%s", o->short_name ? '-' : ' ',
                 o->short_name ? o->short_name : ' ', o->short_name ? ',' : ' ', o->name,
                 arg[0] ? " " : "", arg);
        if (strlen(left) > 27)
            fprintf(out, "  %s\n  %27s  ", left, "");
        else
            fprintf(out, "  %-27s  ", left);
        wrap(out, help, 31, 79);
    }
    fprintf(out,
            "\nLists are comma-separated (--mass 1,2,1.5). Negative values work in both "
            "spellings:\n--x0 -0.5 and --x0=-0.5.\n\n"
            "Presets are searched in $XDG_CONFIG_HOME/springsim/presets, $SPRINGSIM_PRESETS,\n"
            "%s and presets/ beside the program; lessons likewise in\n"
            "$XDG_CONFIG_HOME/springsim/lessons, $SPRINGSIM_LESSONS,\n%s and lessons/.\n\n"
            "Exit status: 0 success, 1 a file could not be read or written or the run blew "
            "up,\n2 a bad option, value, preset or lesson.\n",
            preset_installed_dir, search_installed_dir(SEARCH_LESSONS));
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
    char *s = shortopts;
    *s++ = ':'; /* report missing arguments as ':' */
    for (int k = 0; k < CFG_KEY_COUNT; k++) {
        const struct config_option *o = &config_options[k];
        bool arg = config_takes_value(k);
        lo[k] = (struct option){o->name, arg ? required_argument : no_argument, NULL, 256 + k};
        if (o->short_name) {
            *s++ = o->short_name;
            if (arg)
                *s++ = ':';
        }
    }
    lo[CFG_KEY_COUNT] = (struct option){0, 0, 0, 0};
    *s = '\0';
}

/* Maps getopt's return value to a key, or -1. */
static int option_index(int ch)
{
    if (ch >= 256 && ch < 256 + CFG_KEY_COUNT)
        return ch - 256;
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

/* The file path names once its symbolic links are followed by name (to a file not made
 * yet, too), into out: a link's relative target is taken from the link's directory. */
static void link_target(const char *path, char *out, size_t len)
{
    snprintf(out, len, "%s", path);
    struct stat st;
    for (int hops = 0; hops < 40 && lstat(out, &st) == 0 && S_ISLNK(st.st_mode); hops++) {
        char to[4096], next[4096];
        ssize_t n = readlink(out, to, sizeof to - 1);
        if (n <= 0)
            return;
        to[n] = '\0';
        const char *slash = strrchr(out, '/');
        int dir = to[0] == '/' || !slash ? 0 : (int)(slash - out) + 1;
        int k = snprintf(next, sizeof next, "%.*s%s", dir, out, to);
        if (k < 0 || (size_t)k >= sizeof next || (size_t)k >= len)
            return; /* too long to follow: the name as far as it went */
        memcpy(out, next, (size_t)k + 1);
    }
}

/* Whether paths a and b name one file: the same device and inode where both exist, else
 * the same name in the same directory (its real path), their symbolic links followed, so
 * "out.csv", "./out.csv" and a link to it are one file before any is written. */
static bool same_file(const char *a, const char *b)
{
    char fa[4096], fb[4096];
    link_target(a, fa, sizeof fa);
    link_target(b, fb, sizeof fb);
    a = fa;
    b = fb;
    struct stat sa, sb;
    if (stat(a, &sa) == 0 && stat(b, &sb) == 0)
        return sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
    char da[4096], db[4096];
    const char *na = strrchr(a, '/'), *nb = strrchr(b, '/');
    snprintf(da, sizeof da, "%.*s", na ? (int)(na - a) + 1 : 1, na ? a : ".");
    snprintf(db, sizeof db, "%.*s", nb ? (int)(nb - b) + 1 : 1, nb ? b : ".");
    char *ra = realpath(da, NULL), *rb = realpath(db, NULL);
    bool same = ra && rb && strcmp(ra, rb) == 0 && strcmp(na ? na + 1 : a, nb ? nb + 1 : b) == 0;
    free(ra);
    free(rb);
    return same;
}

/* Says so (one line) and returns true when two outputs (-o, --figure, --record) name one
 * file: the second would replace the first. */
static bool outputs_clash(const struct config *c)
{
    const char *path[3] = {c->output, c->figure, c->record};
    static const char *const name[3] = {"-o", "--figure", "--record"};
    for (int i = 0; i < 3; i++)
        for (int j = i + 1; j < 3; j++)
            if (path[i] && path[j] && strcmp(path[i], "-") != 0 && same_file(path[i], path[j])) {
                char q[4 * CONFIG_QUOTE_MAX + 8];
                config_quote(path[j], strlen(path[j]), q, sizeof q);
                options_say("%s: %s is also %s's file (expected a different file for each "
                            "output)", name[j], q, name[i]);
                return true;
            }
    return false;
}

/* Says so (one line) and returns true when an option that only the command line gives is
 * for another mode than the one asked for: -o and --meta shape the CSV modes' output,
 * --plain-every the plain mode's. Options a preset can set are left alone, since a preset
 * serves every mode. */
static bool mode_mismatch(const bool *given, enum mode mode, bool summary)
{
    bool csv = mode == MODE_HEADLESS || mode == MODE_MODES || mode == MODE_SWEEP ||
               mode == MODE_BATCH || mode == MODE_SWEEP_RUN;
    static const char *const names[] = {[MODE_INTERACTIVE] = "the interactive program",
                                        [MODE_HEADLESS] = "--headless", [MODE_MODES] = "--modes",
                                        [MODE_SWEEP] = "--sweep", [MODE_LIST] = "--list-presets",
                                        [MODE_SWEEP_RUN] = "--sweep-run",
                                        [MODE_PLAIN] = "--plain",
                                        [MODE_LIST_LESSONS] = "--list-lessons",
                                        [MODE_BATCH] = "--batch"};
    static const int csv_only[] = {CFG_OUTPUT, CFG_META, CFG_FIGURE, CFG_FIGURE_SIZE,
                                   CFG_FIGURE_TITLE};
    for (size_t i = 0; i < sizeof csv_only / sizeof *csv_only; i++)
        if (given[csv_only[i]] && !csv) {
            options_say("--%s: applies to the output of --headless%s, --modes or --sweep, not "
                        "to %s (expected one of those modes)", config_options[csv_only[i]].name,
                        csv_only[i] >= CFG_FIGURE ? "" : ", --summary", names[mode]);
            return true;
        }
    static const int session_only[] = {CFG_LESSON, CFG_RECORD, CFG_REPLAY};
    for (size_t i = 0; i < sizeof session_only / sizeof *session_only; i++)
        if (given[session_only[i]] && mode != MODE_INTERACTIVE && mode != MODE_PLAIN) {
            options_say("--%s: applies to the interactive program or --plain, not to %s",
                        config_options[session_only[i]].name, names[mode]);
            return true;
        }
    int sessions = given[CFG_LESSON] + given[CFG_RECORD] + given[CFG_REPLAY];
    if (sessions > 1) {
        options_say("give only one of --lesson, --record and --replay (a lesson or a "
                    "recording plays alone; a recording starts from the chain as it is)");
        return true;
    }
    /* The series' options shape --headless's rows: a summary has none, and --plain
     * runs as long as its commands say. */
    static const int series_only[] = {CFG_ENERGY, CFG_SAMPLE, CFG_DURATION};
    for (size_t i = 0; i < sizeof series_only / sizeof *series_only; i++) {
        int k = series_only[i];
        if (given[k] && (mode == MODE_HEADLESS || mode == MODE_BATCH) && summary &&
            k != CFG_DURATION) {
            options_say("--%s: applies to --headless's rows, and --summary writes one row of "
                        "figures (expected --headless without --summary)", config_options[k].name);
            return true;
        }
        if (given[k] && mode == MODE_PLAIN) {
            options_say("--%s: applies to --headless, not to --plain (expected --headless%s)",
                        config_options[k].name,
                        k == CFG_DURATION ? "; --plain runs as long as its commands say"
                                          : "");
            return true;
        }
    }
    if (given[CFG_PLAIN_EVERY] && mode != MODE_PLAIN) {
        options_say("--plain-every: applies to --plain's status lines, not to %s (expected "
                    "--plain too)", names[mode]);
        return true;
    }
    return false;
}

/* Parses the command line into c and cli. Returns -1 to go on, or an exit status. */
/* The first pass: help, version and the key list answered at once (their exit code), and
 * the preset, applied before the rest wherever it stands. -1 to go on. */
static int first_pass(int argc, char **argv, const char *shortopts, const struct option *lo,
                      struct config *c, struct cli *cli, const char *exe_dir)
{
    const char *preset = NULL;
    char err[512];
    int ch;
    optind = 0;
    while ((ch = getopt_long(argc, argv, shortopts, lo, NULL)) != -1) {
        int k = option_index(ch);
        if (k == CFG_HELP || k == CFG_VERSION || k == CFG_KEYS)
            hold_stdout();
        if (k == CFG_HELP) {
            usage(stdout);
            return options_finish_stdout(false);
        }
        if (k == CFG_VERSION) {
            printf("springsim %s\n", VERSION);
            return options_finish_stdout(false);
        }
        if (k == CFG_KEYS) {
            input_print_keys(stdout);
            return options_finish_stdout(false);
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
    if (!preset)
        return -1;
    if (preset_find(preset, exe_dir, cli->preset_path, sizeof cli->preset_path) ==
        PRESET_NONE) {
        options_say("--preset: %s", cli->preset_path);
        return EXIT_USAGE;
    }
    enum preset_status st = preset_load(cli->preset_path, c, err, sizeof err);
    if (st != PRESET_OK) {
        options_say("%s", err);
        return st == PRESET_IO ? EXIT_FAILURE : EXIT_USAGE;
    }
    return -1;
}

/* getopt_long's complaint ch ('?': not an option or a value given to a switch; ':' a
 * value missing) about the word at argv[before], said in one line. */
static void say_bad_option(int ch, char **argv, int before)
{
    char q[4 * CONFIG_QUOTE_MAX + 48];
    if (ch == '?') {
        if (optopt >= 256 && optopt < 256 + CFG_KEY_COUNT)
            options_say("--%s: takes no value, but was given %s (see springsim --help)",
                        config_options[optopt - 256].name, written(argv, before, q, sizeof q));
        else if (optopt)
            options_say("'-%c' is not an option (see springsim --help)", optopt);
        else
            options_say("%s is not an option (see springsim --help)",
                        written(argv, before, q, sizeof q));
        return;
    }
    int k = option_index(optopt);
    char arg[128];
    if (k >= 0) {
        config_arg(k, arg, sizeof arg);
        options_say("--%s: needs a value (%s)", config_options[k].name, arg);
    } else {
        options_say("%s needs a value (see springsim --help)", written(argv, before, q, sizeof q));
    }
}

/* The modes the options choose, and where each keeps its argument. */
static const struct {
    int key;
    enum mode mode;
    bool kept;  /* the option's value is kept in struct cli, at: */
    size_t at;  /* offsetof that member */
} mode_options[] = {
    {CFG_HEADLESS, MODE_HEADLESS, false, 0},
    {CFG_MODES, MODE_MODES, false, 0},
    {CFG_SWEEP, MODE_SWEEP, true, offsetof(struct cli, sweep)},
    {CFG_BATCH, MODE_BATCH, true, offsetof(struct cli, batch)},
    {CFG_SWEEP_RUN, MODE_SWEEP_RUN, true, offsetof(struct cli, sweep_dir)},
    {CFG_LIST_PRESETS, MODE_LIST, false, 0},
    {CFG_LIST_LESSONS, MODE_LIST_LESSONS, false, 0},
    {CFG_PLAIN, MODE_PLAIN, false, 0},
};

/* Option k, a mode's, chooses its mode (and keeps its value); MODE_INTERACTIVE for one
 * that chooses none. */
static enum mode take_mode(int k, struct cli *cli)
{
    for (size_t i = 0; i < sizeof mode_options / sizeof mode_options[0]; i++)
        if (mode_options[i].key == k) {
            if (mode_options[i].kept)
                *(const char **)((char *)cli + mode_options[i].at) = optarg;
            return mode_options[i].mode;
        }
    return MODE_INTERACTIVE;
}

/* The options that go together only in some ways, once all are read: EXIT_USAGE after
 * one line for the first that does not, else -1. mode_option: the option that chose the
 * mode. */
static int check_together(struct config *c, struct cli *cli, const bool *given,
                          const char *mode_option)
{
    /* --summary is a headless run's: alone it asks for one. --batch writes summaries. */
    if (c->summary && cli->mode == MODE_INTERACTIVE)
        cli->mode = MODE_HEADLESS;
    if (cli->mode == MODE_BATCH)
        c->summary = true;
    if (c->summary && cli->mode != MODE_HEADLESS && cli->mode != MODE_BATCH) {
        options_say("--summary: summarises a --headless run, but %s was given too (expected "
                    "--headless or no other mode)", mode_option);
        return EXIT_USAGE;
    }
    for (int k = CFG_FIGURE_SIZE; k <= CFG_FIGURE_TITLE; k++)
        if (given[k] && !c->figure) {
            options_say("--%s: shapes --figure's file, but no --figure was given (expected "
                        "--figure FILE too)", config_options[k].name);
            return EXIT_USAGE;
        }
    if (c->summary && given[CFG_FIGURE]) {
        options_say("--figure: a --summary run has one row of figures, no series to draw "
                    "(expected --headless without --summary)");
        return EXIT_USAGE;
    }
    if (cli->mode == MODE_BATCH && given[CFG_META]) {
        options_say("--meta: a --batch study's rows share one header, and '#' lines would "
                    "come between them (expected --batch without --meta)");
        return EXIT_USAGE;
    }
    if (mode_mismatch(given, cli->mode, c->summary) || outputs_clash(c))
        return EXIT_USAGE;
    /* The preset's name stands for its settings (a figure's subtitle names it) only while
     * the command line changes none of them. */
    for (int k = 0; k < CFG_KEY_COUNT; k++)
        if (given[k] && config_options[k].section &&
            strcmp(config_options[k].section, "run") != 0)
            c->name[0] = '\0';
    return -1;
}

/* The words left after the options: --sweep-run's FMIN:FMAX:COUNT, and nothing else.
 * EXIT_USAGE after one line, else -1. */
static int check_rest(int argc, char **argv, struct cli *cli)
{
    char q[4 * CONFIG_QUOTE_MAX + 48];
    if (cli->mode == MODE_SWEEP_RUN && optind < argc && (optind == 1 ||
                                                         strcmp(argv[optind - 1], "--") != 0))
        cli->sweep = argv[optind++];
    if (cli->mode == MODE_SWEEP_RUN && !cli->sweep) {
        options_say("--sweep-run: needs up or down and then FMIN:FMAX:COUNT (expected e.g. "
                    "--sweep-run up 0.5:2:61)");
        return EXIT_USAGE;
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

int options_parse(int argc, char **argv, struct config *c, struct cli *cli,
                  const char *exe_dir)
{
    struct option lo[CFG_KEY_COUNT + 1];
    char shortopts[64], err[512], q[4 * CONFIG_QUOTE_MAX + 48];
    build_longopts(lo, shortopts);
    opterr = 0;
    int done = first_pass(argc, argv, shortopts, lo, c, cli, exe_dir);
    if (done >= 0)
        return done;
    /* Second pass: everything else, in order; the first bad one is reported. */
    optind = 0;
    int modes = 0;
    char mode_option[32] = ""; /* the option that chose the mode */
    bool given[CFG_KEY_COUNT] = {false}; /* the options on the command line */
    for (;;) {
        int before = optind ? optind : 1;
        int ch = getopt_long(argc, argv, shortopts, lo, NULL);
        if (ch == -1)
            break;
        if (ch == '?' || ch == ':') {
            say_bad_option(ch, argv, before);
            return EXIT_USAGE;
        }
        int k = option_index(ch);
        if (k < 0)
            continue;
        given[k] = true;
        if (config_options[k].kind != CONFIG_MODE) {
            if (k == CFG_PRESET)
                continue;
            if (config_set(c, k, optarg, err, sizeof err) != 0) {
                options_say("--%s: %s", config_options[k].name, err);
                return EXIT_USAGE;
            }
            c->origin[k] = (struct config_origin){NULL, 0};
            continue;
        }
        enum mode m = take_mode(k, cli);
        if (m == MODE_INTERACTIVE)
            continue;
        if (modes++) {
            options_say("%s: give only one of --headless, --modes, --sweep, --sweep-run, "
                        "--batch, --list-presets, --list-lessons and --plain, once%s",
                        written(argv, before, q, sizeof q),
                        cli->mode == m ? " (it was given twice)" : "");
            return EXIT_USAGE;
        }
        cli->mode = m;
        snprintf(mode_option, sizeof mode_option, "--%s", config_options[k].name);
    }
    if (check_together(c, cli, given, mode_option) >= 0)
        return EXIT_USAGE;
    return check_rest(argc, argv, cli);
}
