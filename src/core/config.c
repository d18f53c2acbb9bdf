/* config.c: the one settings table shared by the command line, presets and the
 * interactive controls, and what is made from it: the checks every value goes through
 * whichever way it came in, the defaults and the interactive program's limits (the words
 * made from a row, --help's lines and every error's "expected ...": config_text.c). */
#include "config.h"

#include <ctype.h>
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include <unistr.h>

static const char *integrator_choice(int i) { return integrator_name((enum integrator)i); }
static const char *boundary_choice(int i) { return model_boundary_name((enum boundary)i); }
static const char *wave_choice(int i) { return motor_wave_name((enum wave)i); }
static const char *color_choice(int i)
{
    static const char *const names[CONFIG_COLOR_COUNT] = {"auto", "always", "never"};
    return names[i];
}
static const char *glyphs_choice(int i)
{
    static const char *const names[CONFIG_GLYPHS_COUNT] = {"braille", "blocks", "ascii"};
    return names[i];
}

static const char *graphics_choice(int i)
{
    static const char *const names[CONFIG_GRAPHICS_COUNT] = {"auto", "sixel", "kitty",
                                                             "braille"};
    return names[i];
}

#define AT(field) offsetof(struct config, field)

const struct config_option config_options[CFG_KEY_COUNT] = {
    [CFG_PRESET] = {.name = "preset", .short_name = 'p', .kind = CONFIG_TEXT,
                    .arg = "NAME|FILE", .expect = "a preset name or file",
                    .help = "load a preset by name or file path (applied before other options)"},
    [CFG_MASSES] = {.name = "masses", .short_name = 'n', .section = "system", .saved = true,
                    .kind = CONFIG_WHOLE, .arg = "N", .help = "number of masses",
                    .symbol = "N", .lo = 1, .hi = MODEL_MAX_MASSES,
                    .ihi = CONFIG_INTERACTIVE_MAX_MASSES, .def = 2, .offset = AT(masses)},
    [CFG_MASS] = {.name = "mass", .section = "system", .saved = true, .kind = CONFIG_LIST, .arg = "LIST",
                  .help = "masses", .symbol = "masses", .lo = 0, .lo_open = true, .hi = INFINITY,
                  .def = MODEL_DEFAULT_MASS, .unit = "kg", .digits = 2, .offset = AT(mass)},
    [CFG_SPRING] = {.name = "spring", .section = "system", .saved = true, .kind = CONFIG_LIST, .arg = "LIST",
                    .help = "springs, the walls' included (0: no spring there)",
                    .symbol = "springs", .lo = 0, .hi = INFINITY, .def = MODEL_DEFAULT_SPRING, .per = CONFIG_PER_SPRING,
                    .unit = "N/m",
                    .digits = 1, .offset = AT(spring)},
    [CFG_SPRING_CUBIC] = {.name = "spring-cubic", .section = "system", .saved = true,
                          .kind = CONFIG_LIST, .arg = "LIST",
                          .help = "cubic constants k3 of the springs, the walls' included: a "
                                  "spring's force k s + k3 s^3",
                          .symbol = "k3", .lo = -INFINITY, .hi = INFINITY, .def = 0,
                          .per = CONFIG_PER_SPRING, .unit = "N/m³", .digits = 1,
                          .offset = AT(spring_cubic)},
    [CFG_DAMPING] = {.name = "damping", .section = "system", .saved = true, .kind = CONFIG_LIST,
                     .arg = "LIST", .help = "damping of each mass",
                     .symbol = "damping", .lo = 0, .hi = INFINITY, .def = MODEL_DEFAULT_DAMPING, .unit = "N·s/m",
                     .digits = 2,
                     .offset = AT(damping)},
    [CFG_SPRING_DAMPING] = {.name = "spring-damping", .section = "system", .saved = true,
                            .kind = CONFIG_LIST, .arg = "LIST",
                            .help = "a damper beside each spring, on the rate of its stretch "
                                    "(the walls' included)",
                            .symbol = "spring dampers", .lo = 0, .hi = INFINITY, .def = 0,
                            .per = CONFIG_PER_SPRING, .unit = "N·s/m", .digits = 2,
                            .offset = AT(spring_damping)},
    [CFG_DT] = {.name = "dt", .section = "system", .saved = true, .kind = CONFIG_NUMBER, .arg = "SECONDS",
                .help = "time step", .symbol = "dt", .lo = 0, .lo_open = true, .hi = 0.05,
                .ilo = 0.001, .def = 0.01, .unit = "s", .digits = 3, .offset = AT(dt)},
    [CFG_INTEGRATOR] = {.name = "integrator", .section = "system", .saved = true, .kind = CONFIG_CHOICE,
                        .help = "how each step is taken", .def = INTEGRATOR_RK4,
                        .choice_name = integrator_choice, .choices = INTEGRATOR_COUNT,
                        .symbol = "an integrator", .offset = AT(integrator)},
    [CFG_BOUNDARY] = {.name = "boundary", .section = "motor", .saved = true, .kind = CONFIG_CHOICE,
                      .help = "right end", .def = BOUNDARY_MOTOR,
                      .choice_name = boundary_choice, .choices = BOUNDARY_COUNT,
                      .symbol = "a right end", .offset = AT(boundary)},
    [CFG_WAVE] = {.name = "wave", .section = "motor", .saved = true, .kind = CONFIG_CHOICE,
                  .help = "motor waveform", .def = WAVE_SINE, .choice_name = wave_choice,
                  .choices = WAVE_COUNT, .symbol = "a waveform", .offset = AT(wave)},
    [CFG_AMPLITUDE] = {.name = "amplitude", .section = "motor", .saved = true, .kind = CONFIG_NUMBER,
                       .arg = "METRES", .help = "motor amplitude", .symbol = "amplitude",
                       .lo = 0, .hi = MODEL_LENGTH, /* the walls are 10 m apart */ .def = MODEL_DEFAULT_AMPLITUDE, .unit = "m",
                       .digits = 2,
                       .offset = AT(amplitude)},
    /* A bound well past any mechanical drive: a square wave at f makes 2 f dt sub-steps
     * a step, so an unbounded f could make one step last forever. */
    [CFG_FREQUENCY] = {.name = "frequency", .section = "motor", .saved = true, .kind = CONFIG_NUMBER,
                       .arg = "HZ", .help = "motor frequency", .symbol = "frequency", .lo = 0,
                       .lo_open = true, .hi = 1e6, .def = MODEL_DEFAULT_FREQUENCY, .unit = "Hz",
                       .digits = 3,
                       .offset = AT(frequency)},
    [CFG_FORCE] = {.name = "force", .section = "motor", .saved = true, .kind = CONFIG_NUMBER,
                   .arg = "NEWTONS", .help = "a force F w(2 pi f t) on mass --force-on, the "
                   "motor's waveform and frequency", .symbol = "force", .lo = 0, .hi = 1e9,
                   .def = 0, .unit = "N", .digits = 2, .offset = AT(force)},
    /* Checked against N in config_model. */
    [CFG_FORCE_ON] = {.name = "force-on", .section = "motor", .saved = true, .kind = CONFIG_WHOLE,
                      .arg = "K", .help = "the mass the force acts on", .symbol = "K",
                      .lo = 1, .hi = MODEL_MAX_MASSES, .def = 1, .offset = AT(force_on)},
    /* Bounded by what the model can hold: the walls are MODEL_LENGTH apart, and no
     * velocity outlives the cap (a state past these only makes inf and nan). */
    [CFG_X0] = {.name = "x0", .section = "initial", .saved = true, .kind = CONFIG_LIST, .arg = "LIST",
                .help = "initial displacements", .symbol = "displacements",
                .lo = -MODEL_LENGTH, .hi = MODEL_LENGTH, .def = 0, .unit = "m", .offset = AT(x0)},
    [CFG_V0] = {.name = "v0", .section = "initial", .saved = true, .kind = CONFIG_LIST, .arg = "LIST",
                .help = "initial velocities", .symbol = "velocities", .lo = -MODEL_VMAX,
                .hi = MODEL_VMAX, .def = 0, .unit = "m/s", .offset = AT(v0)},
    [CFG_RANDOM] = {.name = "random", .section = "initial", .saved = true, .kind = CONFIG_FLAG,
                    .help = "random initial positions (minimum separation kept)",
                    .offset = AT(random)},
    [CFG_SEED] = {.name = "seed", .section = "initial", .saved = true, .kind = CONFIG_WHOLE, .arg = "N",
                  .help = "seed for --random", .symbol = "seed",
                  .lo = 0, .hi = 0x1p64, .hi_open = true, .def = NAN,
                  .offset = AT(seed)},
    /* Checked against N in config_model; the later of x0, v0, random and this wins. */
    [CFG_START_MODE] = {.name = "start-mode", .section = "initial", .saved = true, .kind = CONFIG_TEXT,
                        .arg = "K[:AMP]", .offset = AT(start_mode),
                        .expect = "K[:AMP]: a mode 1 <= K <= N, 0 <= AMP <= 10 m, default 0.5",
                        .help = "start along mode K's shape, largest |x| = AMP m (0 to 10, "
                                "default 0.5), at rest"},
    [CFG_NO_COLLISIONS] = {.name = "no-collisions", .section = "system", .saved = true, .kind = CONFIG_FLAG,
                           .help = "turn collisions off (the velocity cap stays)",
                           .offset = AT(no_collisions)},
    [CFG_DURATION] = {.name = "duration", .section = "run", .kind = CONFIG_NUMBER,
                      .arg = "SECONDS", .help = "headless run length", .symbol = "duration",
                      .lo = 0, .hi = INFINITY, .def = 10, .unit = "s",
                      .offset = AT(duration)},
    [CFG_SAMPLE] = {.name = "sample", .section = "run", .kind = CONFIG_NUMBER,
                    .arg = "SECONDS", .help = "headless output interval, rounded to whole steps",
                    .symbol = "sample", .lo = 0, .lo_open = true, .hi = INFINITY, .def = 0,
                    .def_text = "every step", .unit = "s", .offset = AT(sample)},
    [CFG_OUTPUT] = {.name = "output", .short_name = 'o', .kind = CONFIG_TEXT, .arg = "FILE",
                    .expect = "a file name", .offset = AT(output),
                    .help = "headless/modes/sweep output to FILE instead of standard output"},
    [CFG_ENERGY] = {.name = "energy", .section = "run", .kind = CONFIG_FLAG,
                    .help = "headless CSV gains kinetic,potential,dissipated,motor_work,contact,force_work",
                    .offset = AT(energy)},
    [CFG_META] = {.name = "meta", .kind = CONFIG_FLAG, .offset = AT(meta),
                  .help = "headless/modes/sweep CSV begins with '#' lines: the version and the "
                          "command line that repeats the run"},
    [CFG_FIGURE] = {.name = "figure", .kind = CONFIG_TEXT, .arg = "FILE", .offset = AT(figure),
                    .expect = "a file name ending in .png, .svg or .pdf",
                    .help = "headless/modes/sweep: also a figure of the run for a report; the "
                            "extension chooses PNG, SVG or PDF"},
    [CFG_FIGURE_SIZE] = {.name = "figure-size", .kind = CONFIG_TEXT, .arg = "WxH",
                         .offset = AT(figure_w),
                         .expect = "WxH in millimetres, each 50 to 1000, e.g. 160x100",
                         .help = "--figure's size in millimetres (default 160 wide, 100 high a "
                                 "panel; the PNG at 300 dpi)"},
    [CFG_FIGURE_TITLE] = {.name = "figure-title", .kind = CONFIG_TEXT, .arg = "TEXT",
                          .expect = "a title", .offset = AT(figure_title),
                          .help = "--figure's title in place of the one saying what it shows"},
    [CFG_FPS] = {.name = "fps", .section = "run", .kind = CONFIG_WHOLE, .arg = "N",
                 .help = "interactive frames per second", .symbol = "fps", .lo = 1, .hi = 60,
                 .def = 30, .offset = AT(fps)},
    [CFG_WINDOW] = {.name = "window", .section = "run", .saved = true, .kind = CONFIG_NUMBER,
                    .arg = "SECONDS", .help = "interactive: the time plots' window at start (< and > "
                    "change it)", .symbol = "window",
                    .lo = 1, .hi = CONFIG_WINDOW_MAX, .def = 10, .unit = "s", .digits = 0,
                    .offset = AT(window)},
    [CFG_LOW_BANDWIDTH] = {.name = "low-bandwidth", .section = "run", .kind = CONFIG_FLAG,
                           .help = "interactive: fewer frames and plot refreshes (slow links)",
                           .offset = AT(low_bandwidth)},
    [CFG_COLOR] = {.name = "color", .section = "run", .kind = CONFIG_CHOICE,
                   .help = "interactive: colour (auto: unless NO_COLOR is set or the terminal "
                           "has none; always: even with NO_COLOR)",
                   .def = CONFIG_COLOR_AUTO, .choice_name = color_choice,
                   .choices = CONFIG_COLOR_COUNT, .symbol = "a colour setting",
                   .offset = AT(color)},
    [CFG_GLYPHS] = {.name = "glyphs", .section = "run", .kind = CONFIG_CHOICE,
                    .help = "interactive: braille plots and box drawing (ASCII without a "
                            "UTF-8 locale), block characters instead of braille, or ASCII only",
                    .def = CONFIG_GLYPHS_BRAILLE, .choice_name = glyphs_choice,
                    .choices = CONFIG_GLYPHS_COUNT, .symbol = "a glyph set",
                    .offset = AT(glyphs)},
    [CFG_GRAPHICS] = {.name = "graphics", .section = "run", .kind = CONFIG_CHOICE,
                      .help = "interactive: the charts' drawing areas as images (sixel or "
                              "kitty's protocol) where the terminal says it can show them "
                              "(auto), or braille; braille inside tmux or screen and with low "
                              "bandwidth; the Graphics control changes it",
                      .def = CONFIG_GRAPHICS_AUTO, .choice_name = graphics_choice,
                      .choices = CONFIG_GRAPHICS_COUNT, .symbol = "a graphics setting",
                      .offset = AT(graphics)},
    [CFG_SUMMARY] = {.name = "summary", .kind = CONFIG_FLAG, .offset = AT(summary),
                     .help = "headless (implied): a header and one row of settings and per-run "
                             "figures instead of the series"},
    [CFG_PLAIN_EVERY] = {.name = "plain-every", .kind = CONFIG_NUMBER, .arg = "SECONDS",
                         .help = "--plain: simulated time between status lines",
                         .symbol = "plain-every", .lo = 0, .lo_open = true, .hi = INFINITY,
                         .def = 1, .unit = "s", .offset = AT(plain_every)},
    [CFG_LESSON] = {.name = "lesson", .kind = CONFIG_TEXT, .arg = "NAME|FILE",
                    .expect = "a lesson's name or file", .offset = AT(lesson),
                    .help = "play a lesson (names: --list-lessons; L in the program)"},
    [CFG_RECORD] = {.name = "record", .kind = CONFIG_TEXT, .arg = "FILE",
                    .expect = "a file name", .offset = AT(record),
                    .help = "write what is done (commands, simulated times) as a lesson file"},
    [CFG_REPLAY] = {.name = "replay", .kind = CONFIG_TEXT, .arg = "FILE",
                    .expect = "a file name", .offset = AT(replay),
                    .help = "play a recording back, to the same final state bit for bit"},
    [CFG_HEADLESS] = {.name = "headless", .kind = CONFIG_MODE,
                      .help = "run without a terminal; CSV to standard output"},
    [CFG_MODES] = {.name = "modes", .kind = CONFIG_MODE,
                   .help = "natural frequencies, mode shapes and damping, CSV"},
    [CFG_SWEEP] = {.name = "sweep", .kind = CONFIG_MODE, .arg = "FMIN:FMAX:COUNT",
                   .help = "steady-state amplitude and phase against motor frequency, CSV; "
                           "with cubic springs every branch by harmonic balance: "
                           "frequency_hz,branch,stable,amp1..,phase1.."},
    [CFG_SWEEP_RUN] = {.name = "sweep-run", .kind = CONFIG_MODE,
                       .arg = "up|down FMIN:FMAX:COUNT",
                       .help = "a simulated sweep up or down, each point from the last one's "
                               "state, run until steady to 0.1 %; CSV frequency_hz,branch "
                               "(empty),stable,amp1..,phase1.."},
    [CFG_BATCH] = {.name = "batch", .kind = CONFIG_MODE, .arg = "FILE|-",
                   .help = "a parameter study: a CSV whose header names settings "
                           "(masses,damping,frequency,...) and whose rows are runs; one "
                           "--summary row per run, in order"},
    [CFG_PLAIN] = {.name = "plain", .kind = CONFIG_MODE,
                   .help = "the interactive program as lines of text, commands on standard "
                           "input: no escape sequences (also when TERM=dumb)"},
    [CFG_LIST_PRESETS] = {.name = "list-presets", .kind = CONFIG_MODE,
                          .help = "one line per preset: its name, then its description"},
    [CFG_LIST_LESSONS] = {.name = "list-lessons", .kind = CONFIG_MODE,
                          .help = "one line per lesson: its name, then its title"},
    [CFG_KEYS] = {.name = "keys", .kind = CONFIG_MODE,
                  .help = "list the interactive program's keys"},
    [CFG_HELP] = {.name = "help", .short_name = 'h', .kind = CONFIG_MODE,
                  .help = "show this help and exit"},
    [CFG_VERSION] = {.name = "version", .kind = CONFIG_MODE, .help = "show the version and exit"},
};

void config_init(struct config *c)
{
    memset(c, 0, sizeof *c);
    for (int k = 0; k < CFG_KEY_COUNT; k++) {
        const struct config_option *o = &config_options[k];
        char *at = (char *)c + o->offset;
        if (!isfinite(o->def) || o->kind == CONFIG_LIST)
            continue; /* lists start empty: the default fills them in config_model */
        if (o->kind == CONFIG_NUMBER)
            *(double *)at = o->def;
        else if (o->kind == CONFIG_WHOLE)
            *(int *)at = (int)o->def;
        else if (o->kind == CONFIG_CHOICE)
            memcpy(at, &(int){(int)o->def}, sizeof(int));
    }
}

int config_find(const char *name)
{
    for (int k = 0; k < CFG_KEY_COUNT; k++)
        if (strcmp(name, config_options[k].name) == 0)
            return k;
    return -1;
}

bool config_takes_value(int key)
{
    const struct config_option *o = &config_options[key];
    return o->kind != CONFIG_FLAG && (o->kind != CONFIG_MODE || o->arg);
}

static int fail_span(int key, const char *value, size_t n, const char *why, char *err,
                     size_t errlen)
{
    char q[4 * CONFIG_QUOTE_MAX + 48], want[160];
    config_quote(value, n, q, sizeof q);
    config_expected(key, want, sizeof want);
    snprintf(err, errlen, "%s %s (expected %s)", q, why, want);
    return -1;
}

static int fail(int key, const char *value, const char *why, char *err, size_t errlen)
{
    return fail_span(key, value, strlen(value), why, err, errlen);
}

/* Parses the n characters at s as one whole finite number, nothing before or after it
 * (no blanks either); returns a reason on failure. -0 reads as 0. */
static const char *parse_span(const char *s, size_t n, double *out)
{
    char *end;
    if (n == 0)
        return "is empty";
    if (isspace((unsigned char)s[0]))
        return "is not a number (it starts with a blank)";
    errno = 0;
    double v = strtod(s, &end);
    if (end == s || end != s + n)
        return isspace((unsigned char)s[n - 1]) ? "is not a number (it ends with a blank)"
                                                : "is not a number";
    /* ERANGE with a tiny result is an underflow: a valid, very small number. */
    if (!isfinite(v) || (errno == ERANGE && fabs(v) >= 1.0))
        return "is not a finite number";
    *out = v + 0.0;
    return NULL;
}

const char *config_parse_number(const char *s, double *out)
{
    return parse_span(s, strlen(s), out);
}

static const char *parse_number(const char *s, double *out)
{
    return config_parse_number(s, out);
}

bool config_in_range(int key, double v)
{
    const struct config_option *o = &config_options[key];
    if (o->lo_open ? !(v > o->lo) : !(v >= o->lo))
        return 0;
    return o->hi_open ? v < o->hi : v <= o->hi;
}

static int set_number(int key, const char *value, double *out, char *err, size_t errlen)
{
    double v;
    const char *why = parse_number(value, &v);
    if (why)
        return fail(key, value, why, err, errlen);
    if (!config_in_range(key, v))
        return fail(key, value, "is out of range", err, errlen);
    *out = v;
    return 0;
}

/* Parses a comma-separated list: numbers as parse_span reads them, with spaces or tabs
 * allowed on either side of a comma and nowhere else. Items of any length are read in
 * place. */
static int set_list(int key, const char *value, struct config_list *out, char *err,
                    size_t errlen)
{
    static struct config_list tmp; /* large; the parser is not reentrant anyway */
    char msg[4 * CONFIG_QUOTE_MAX + 96], q[4 * CONFIG_QUOTE_MAX + 48];
    const char *p = value;

    tmp.count = 0;
    for (;;) {
        if (tmp.count > 0)
            while (*p == ' ' || *p == '\t')
                p++;
        const char *end = strchr(p, ',');
        if (!end)
            end = p + strlen(p);
        const char *stop = end;
        if (*end == ',')
            while (stop > p && (stop[-1] == ' ' || stop[-1] == '\t'))
                stop--;
        size_t len = (size_t)(stop - p);
        if (tmp.count > MODEL_MAX_MASSES)
            return fail(key, value, "has more than 1001 values", err, errlen);
        if (len == 0 && (tmp.count > 0 || *end == ',')) {
            snprintf(msg, sizeof msg, "has an empty item (item %d)", tmp.count + 1);
            return fail(key, value, msg, err, errlen);
        }
        double v;
        const char *why = parse_span(p, len, &v);
        if (!why && !config_in_range(key, v))
            why = "is out of range";
        if (why) {
            if (p == value && *end == '\0')
                return fail(key, value, why, err, errlen);
            config_quote(p, len, q, sizeof q);
            snprintf(msg, sizeof msg, "item %d %s %s", tmp.count + 1, q, why);
            return fail(key, value, msg, err, errlen);
        }
        tmp.v[tmp.count++] = v;
        if (*end == '\0')
            break;
        p = end + 1;
    }
    *out = tmp;
    return 0;
}

static int set_bool(int key, const char *value, bool *out, char *err, size_t errlen)
{
    static const char *const yes[] = {"true", "yes", "on", "1"};
    static const char *const no[] = {"false", "no", "off", "0"};
    if (!value) {
        *out = true;
        return 0;
    }
    for (size_t i = 0; i < sizeof yes / sizeof *yes; i++) {
        if (strcmp(value, yes[i]) == 0) {
            *out = true;
            return 0;
        }
        if (strcmp(value, no[i]) == 0) {
            *out = false;
            return 0;
        }
    }
    return fail(key, value, "is not true or false", err, errlen);
}

/* Whole numbers: digits only, optional sign where negatives are meaningful. */
static const char *parse_whole(const char *s, unsigned long long *out)
{
    char *end;
    if (*s == '\0')
        return "is empty";
    if (s[0] == '+' && s[1] >= '0' && s[1] <= '9')
        s++; /* +3 is 3, as strtod reads +0.01 */
    if (strspn(s, "0123456789") != strlen(s)) {
        double d;
        if (parse_number(s, &d))
            return "is not a number";
        return d < 0.0 && d == floor(d) ? "is out of range" : "is not a whole number";
    }
    errno = 0;
    unsigned long long v = strtoull(s, &end, 10);
    if (errno == ERANGE || *end != '\0')
        return "is out of range";
    *out = v;
    return NULL;
}

/* --start-mode K[:AMP]: K a whole number from 1 (N is checked in config_model), AMP a
 * number >= 0. */
static int set_start_mode(struct config *c, const char *value, char *err, size_t errlen)
{
    char k_text[32], msg[4 * CONFIG_QUOTE_MAX + 96], q[4 * CONFIG_QUOTE_MAX + 48];
    const char *colon = strchr(value, ':'), *why;
    size_t klen = colon ? (size_t)(colon - value) : strlen(value);
    unsigned long long k = 0;
    double amp = CONFIG_START_AMP;
    if (klen >= sizeof k_text)
        return fail(CFG_START_MODE, value, "is not a mode number", err, errlen);
    memcpy(k_text, value, klen);
    k_text[klen] = '\0';
    if ((why = parse_whole(k_text, &k)) || k < 1 || k > MODEL_MAX_MASSES) {
        config_quote(k_text, klen, q, sizeof q);
        snprintf(msg, sizeof msg, "has mode %s, which %s", q, why ? why : "is out of range");
        return fail(CFG_START_MODE, value, colon ? msg : why ? why : "is out of range", err,
                    errlen);
    }
    if (colon) {
        if (!colon[1])
            return fail(CFG_START_MODE, value, "has no amplitude after ':'", err, errlen);
        why = config_parse_number(colon + 1, &amp);
        if (!why && !(amp >= 0.0 && amp <= MODEL_LENGTH))
            why = "is out of range";
        if (why) {
            config_quote(colon + 1, strlen(colon + 1), q, sizeof q);
            snprintf(msg, sizeof msg, "has amplitude %s, which %s", q, why);
            return fail(CFG_START_MODE, value, msg, err, errlen);
        }
    }
    c->start_mode = (int)k;
    c->start_amp = amp;
    c->x0.count = c->v0.count = 0;
    c->random = false;
    return 0;
}

/* --figure-size WxH: two numbers in millimetres, each in the allowed range. */
static int set_figure_size(struct config *c, const char *value, char *err, size_t errlen)
{
    char w_text[64];
    const char *x = strpbrk(value, "xX");
    double w, h;
    size_t wlen = x ? (size_t)(x - value) : 0;
    if (!x || wlen == 0 || wlen >= sizeof w_text)
        return fail(CFG_FIGURE_SIZE, value, "is not WxH", err, errlen);
    memcpy(w_text, value, wlen);
    w_text[wlen] = '\0';
    if (config_parse_number(w_text, &w) || config_parse_number(x + 1, &h))
        return fail(CFG_FIGURE_SIZE, value, "is not WxH", err, errlen);
    if (!(w >= CONFIG_FIGURE_MM_MIN && w <= CONFIG_FIGURE_MM_MAX && h >= CONFIG_FIGURE_MM_MIN &&
          h <= CONFIG_FIGURE_MM_MAX))
        return fail(CFG_FIGURE_SIZE, value, "is out of range", err, errlen);
    c->figure_w = w, c->figure_h = h;
    return 0;
}

/* --figure's file name ends in .png, .svg or .pdf (any case). */
static bool figure_extension(const char *path)
{
    const char *dot = strrchr(path, '.');
    return dot && !strchr(dot, '/') &&
           (strcasecmp(dot, ".png") == 0 || strcasecmp(dot, ".svg") == 0 ||
            strcasecmp(dot, ".pdf") == 0);
}

int config_set(struct config *c, int key, const char *value, char *err, size_t errlen)
{
    const struct config_option *o;
    const char *why;
    unsigned long long whole;

    if (key < 0 || key >= CFG_KEY_COUNT) {
        snprintf(err, errlen, "is not a setting");
        return -1;
    }
    o = &config_options[key];
    char *at = (char *)c + o->offset;
    if (!value && o->kind != CONFIG_FLAG && o->kind != CONFIG_MODE)
        return fail(key, "", "is missing", err, errlen);
    switch (o->kind) {
    case CONFIG_MODE:
        return 0; /* what to do: the caller's business */
    case CONFIG_TEXT:
        if (key == CFG_PRESET)
            return 0; /* applied by the caller, before everything else */
        if (key == CFG_START_MODE)
            return set_start_mode(c, value, err, errlen);
        if (key == CFG_FIGURE_SIZE)
            return set_figure_size(c, value, err, errlen);
        if (*value == '\0')
            return fail(key, value, "is empty", err, errlen);
        if (key == CFG_FIGURE && !figure_extension(value))
            return fail(key, value, "has no extension that names a figure format", err, errlen);
        if (key == CFG_FIGURE_TITLE && u8_check((const uint8_t *)value, strlen(value)))
            return fail(key, value, "is not UTF-8 text (a figure's fonts draw only that)", err,
                        errlen);
        memcpy(at, &value, sizeof value);
        return 0;
    case CONFIG_FLAG:
        if (set_bool(key, value, (bool *)at, err, errlen))
            return -1;
        break;
    case CONFIG_WHOLE:
        if ((why = parse_whole(value, &whole)))
            return fail(key, value, why, err, errlen);
        /* The seed's whole range is what parse_whole reads (below 2^64, which a double
         * cannot tell from 2^64 - 1). */
        if (key != CFG_SEED && !config_in_range(key, (double)whole))
            return fail(key, value, "is out of range", err, errlen);
        if (key == CFG_SEED) {
            c->seed = whole;
            c->seed_set = true;
        } else {
            *(int *)at = (int)whole;
        }
        return 0;
    case CONFIG_NUMBER:
        return set_number(key, value, (double *)at, err, errlen);
    case CONFIG_LIST:
        if (set_list(key, value, (struct config_list *)at, err, errlen))
            return -1;
        break;
    case CONFIG_CHOICE: {
        int i = 0;
        while (i < o->choices && strcmp(value, o->choice_name(i)) != 0)
            i++;
        if (i == o->choices) {
            char why_not[64];
            snprintf(why_not, sizeof why_not, "is not %s", o->symbol);
            return fail(key, value, why_not, err, errlen);
        }
        memcpy(at, &i, sizeof i);
        return 0;
    }
    }
    /* The later of x0 and random wins; either, or v0, replaces a start along a mode
     * (which replaced them: set_start_mode). */
    if (key == CFG_X0)
        c->random = false;
    if (key == CFG_RANDOM && c->random)
        c->x0.count = 0;
    if (key == CFG_X0 || key == CFG_V0 || (key == CFG_RANDOM && c->random))
        c->start_mode = 0;
    return 0;
}
