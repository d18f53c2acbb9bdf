/* config.h: every setting of a run, the one table of options, preset keys and modes
 * (name, short option, section, kind, range, default, unit, digits, help), and the checks
 * of their values made from it (springsim(1), OPTIONS and PRESETS). */
#ifndef SPRINGSIM_CONFIG_H
#define SPRINGSIM_CONFIG_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "integrator.h"
#include "model.h"

/* Every option and preset key, and the program's own modes, one row each in
 * config_options. */
enum config_key {
    CFG_PRESET,
    CFG_MASSES,
    CFG_MASS,
    CFG_SPRING,
    CFG_SPRING_CUBIC,
    CFG_DAMPING,
    CFG_SPRING_DAMPING,
    CFG_DT,
    CFG_INTEGRATOR,
    CFG_BOUNDARY,
    CFG_WAVE,
    CFG_AMPLITUDE,
    CFG_FREQUENCY,
    CFG_FORCE,
    CFG_FORCE_ON,
    CFG_X0,
    CFG_V0,
    CFG_RANDOM,
    CFG_SEED,
    CFG_START_MODE,
    CFG_NO_COLLISIONS,
    CFG_DURATION,
    CFG_SAMPLE,
    CFG_OUTPUT,
    CFG_ENERGY,
    CFG_META,
    CFG_FIGURE,
    CFG_FIGURE_SIZE,
    CFG_FIGURE_TITLE,
    CFG_FPS,
    CFG_WINDOW,
    CFG_LOW_BANDWIDTH,
    CFG_COLOR,
    CFG_GLYPHS,
    CFG_GRAPHICS,
    CFG_SUMMARY,
    CFG_PLAIN_EVERY,
    CFG_LESSON,
    CFG_RECORD,
    CFG_REPLAY,
    CFG_HEADLESS, /* the modes and the help-type options: command line only */
    CFG_MODES,
    CFG_SWEEP,
    CFG_BATCH,
    CFG_SWEEP_RUN,
    CFG_PLAIN,
    CFG_LIST_PRESETS,
    CFG_LIST_LESSONS,
    CFG_KEYS,
    CFG_HELP,
    CFG_VERSION,
    CFG_KEY_COUNT
};

/* What a key's value is, and so how it is read, checked and stored. */
enum config_kind {
    CONFIG_TEXT,   /* a string kept as given (a file, a preset, a mode's argument) */
    CONFIG_FLAG,   /* true or false; alone on the command line it means true */
    CONFIG_WHOLE,  /* a whole number in [lo, hi] */
    CONFIG_NUMBER, /* a finite number in its range */
    CONFIG_LIST,   /* one number for all, or one per mass (or per spring) */
    CONFIG_CHOICE, /* one of the names choice_name(0 .. choices-1) */
    CONFIG_MODE    /* what to do (--headless, --help, ...), no value */
};

/* --color: colour where the terminal has it and NO_COLOR is not set, wherever the
 * terminal has it, or never. */
enum config_color { CONFIG_COLOR_AUTO, CONFIG_COLOR_ALWAYS, CONFIG_COLOR_NEVER, CONFIG_COLOR_COUNT };

/* --glyphs: braille dots and box drawing (ASCII where the locale is not UTF-8), block
 * characters in place of braille, or ASCII only. */
enum config_glyphs {
    CONFIG_GLYPHS_BRAILLE,
    CONFIG_GLYPHS_BLOCKS,
    CONFIG_GLYPHS_ASCII,
    CONFIG_GLYPHS_COUNT
};

/* --graphics: the charts' drawing areas as images where the terminal says it shows them
 * (auto), in sixel or kitty's protocol, or braille always. */
enum config_graphics {
    CONFIG_GRAPHICS_AUTO,
    CONFIG_GRAPHICS_SIXEL,
    CONFIG_GRAPHICS_KITTY,
    CONFIG_GRAPHICS_BRAILLE,
    CONFIG_GRAPHICS_COUNT
};

#define CONFIG_PER_MASS 0   /* a list of N values */
#define CONFIG_PER_SPRING 1 /* a list of N+1 values */
#define CONFIG_INTERACTIVE_MAX_MASSES 10 /* N the interactive program takes */

/* One setting: everything about it the program knows outside the physics that uses it.
 * --help, every error's "expected ...", the checks, the defaults and the interactive
 * program's limits are made from these rows. */
struct config_option {
    const char *name;    /* long option and preset key */
    char short_name;     /* short option, or 0 */
    const char *section; /* preset section, or NULL for the command line only */
    enum config_kind kind;
    const char *arg;     /* argument for --help (choices: made from their names) */
    const char *help;    /* for --help; the range and default are added to it */
    const char *symbol;  /* what a range calls it: "dt", "N", "masses" */
    double lo, hi;       /* the range (whole numbers, numbers; lists: lo only) */
    bool lo_open;        /* lo itself is out of range */
    bool hi_open;        /* hi itself is out of range */
    double ilo, ihi;     /* the interactive program's range, where narrower (0: none) */
    double def;          /* the default (NAN: none to state) */
    const char *def_text; /* the default in words, where a number does not say it */
    int per;             /* lists: CONFIG_PER_MASS or CONFIG_PER_SPRING */
    const char *unit;    /* SI unit, or "" */
    int digits;          /* decimals the interactive controls show */
    const char *(*choice_name)(int i); /* choices: the name of value i */
    int choices;         /* choices: how many */
    const char *expect;  /* text keys: what is expected */
    size_t offset;       /* where the value lives in struct config */
    bool saved;          /* a saved preset writes it (preset_write), where in force */
};

/* The settings, indexed by enum config_key. */
extern const struct config_option config_options[CFG_KEY_COUNT];

/* A list value as given: one value for all elements, or one per element. */
struct config_list {
    int count;                        /* values given, 0 if the key was never set */
    double v[MODEL_MAX_MASSES + 1];   /* the values */
};

/* Where a setting was last set, for error messages. */
struct config_origin {
    const char *file; /* preset file, or NULL for the command line */
    int line;         /* line in that file */
};

struct config {
    int masses;                         /* N */
    struct config_list mass;            /* kg */
    struct config_list spring;          /* N/m */
    struct config_list spring_cubic;    /* N/m^3: each spring's k3 (force k s + k3 s^3) */
    struct config_list damping;         /* N s/m */
    struct config_list spring_damping;  /* N s/m, beside each spring */
    double dt;                          /* s */
    enum integrator integrator;         /* the stepper (rk4 unless set) */
    enum boundary boundary;             /* right end */
    enum wave wave;                     /* drive waveform */
    double amplitude;                   /* m */
    double frequency;                   /* Hz */
    double force;                       /* the force input's amplitude F (N) */
    int force_on;                       /* the mass it acts on (1-based) */
    struct config_list x0;              /* initial displacements (m) */
    struct config_list v0;              /* initial velocities (m/s) */
    bool random;                        /* random initial positions */
    uint64_t seed;                      /* seed for random */
    bool seed_set;                      /* seed given */
    int start_mode;                     /* start along this mode (1-based), 0: not */
    double start_amp;                   /* its largest |displacement| (m) */
    bool no_collisions;                 /* collisions off */
    double duration;                    /* headless run length (s) */
    double sample;                      /* headless output interval (s), 0 = every step */
    const char *output;                 /* output file, NULL for standard output */
    const char *lesson;                 /* --lesson: a lesson's name or file, or NULL */
    const char *record;                 /* --record: the file the session is written to */
    const char *replay;                 /* --replay: a recording played back */
    bool energy;                        /* energy columns in the headless CSV */
    bool meta;                          /* '#' lines before a CSV: version, command line */
    const char *figure;                 /* --figure: a figure of the run (.png, .svg, .pdf) */
    double figure_w, figure_h;          /* --figure-size in mm, 0: the figure's own */
    const char *figure_title;           /* --figure-title: the figure's title, or NULL */
    int fps;                            /* interactive frames per second */
    double window;                      /* interactive: the time plots' window (s) */
    bool low_bandwidth;                 /* interactive: keep terminal output small */
    enum config_color color;            /* interactive: when to use colour */
    enum config_glyphs glyphs;          /* interactive: which characters draw */
    enum config_graphics graphics;      /* interactive: images for the charts, or braille */
    bool summary;                       /* headless: one row of figures, not the series */
    double plain_every;                 /* --plain: simulated seconds between status lines */
    char name[64];                      /* preset's display name */
    char description[256];              /* preset's description */
    struct config_origin origin[CFG_KEY_COUNT]; /* where each key was set */
};

#define CONFIG_QUOTE_MAX 40  /* characters of a value quoted in a message */
#define CONFIG_FIGURE_MM_MIN 50.0   /* --figure-size's smallest side (mm) */
#define CONFIG_FIGURE_MM_MAX 1000.0 /* and largest */
#define CONFIG_START_AMP 0.5 /* --start-mode's AMP unless given (m) */
#define CONFIG_MAX_STEPS 1e12 /* steps a headless run may take */
/* The interactive program's longest time window (s): its coarse samples reach 66 s back
 * (app/trail.h). */
#define CONFIG_WINDOW_MAX 60.0

/* Writes the n bytes of text into buf (room for len) with every control byte escaped
 * (\n, \t, \x1b, ...; invalid UTF-8 and C1 controls as \xNN too), at most max of them,
 * then "..." if there were more: what every message quoting user text goes through. */
void config_escape(const char *text, size_t n, size_t max, char *buf, size_t len);

/* The n bytes of value as a message quotes them: escaped, in single quotes, cut after
 * CONFIG_QUOTE_MAX with its length said. */
void config_quote(const char *value, size_t n, char *buf, size_t len);

/* Parses s as one whole finite number, no blank before, after or inside it (-0 reads
 * as 0). NULL, or the reason it is not one ("is not a number", ...). */
const char *config_parse_number(const char *s, double *out);

/* The exact integrator's reach when the dampers are not proportional to the masses (it
 * then steps by the dense exponential, exact.c): each new step length (every contact
 * makes one) costs the matrix exponential of a (2N+2)-square matrix and its integrals,
 * O(N^3): 0.7 s at 100 masses, and with collisions a second of motion costs 0.4 s at 20,
 * 1.2 s at 30, 13 s at 50 (159 s for one step at 1000). Proportional dampers (the default
 * chain, undamped ones) are stepped in the modes at any N (exact_modal.c). */
#define CONFIG_EXACT_MAX_MASSES 100
#define CONFIG_EXACT_MAX_MASSES_CONTACTS 20

/* CFG_INTEGRATOR when c asks for the exact integrator on more masses than it can step in
 * reasonable time (above: dampers not proportional to the masses), with the reason and
 * what to use instead in err; -1 if not. */
int config_check_exact(const struct config *c, char *err, size_t errlen);

/* The key to blame when a headless run of c would take more than CONFIG_MAX_STEPS steps
 * (CFG_DURATION or CFG_DT), with the reason in err; -1 when it would not. */
int config_check_steps(const struct config *c, char *err, size_t errlen);

/* What key allows, as every error about it says it: "0 < dt <= 0.05",
 * "masses > 0 kg: one value, or one per mass", "sine, square, triangle or sawtooth". */
void config_expected(int key, char *buf, size_t len);

/* Key's argument and help line for --help, with its range and default. */
void config_arg(int key, char *buf, size_t len);
void config_help(int key, char *buf, size_t len);

/* Whether v is inside key's range (a list's every value too). */
bool config_in_range(int key, double v);

/* The key to blame when a number or a list value of c is outside its option's range
 * (a value made by the program, not typed: the nearest mode, a sweep's frequency), with
 * the reason in err; -1 when every one is inside. The one change path checks it. */
int config_check_ranges(const struct config *c, char *err, size_t errlen);

/* The key to blame when c is beyond the interactive program's narrower ranges (N, dt),
 * with the reason in err; -1 when it is within them. */
int config_check_interactive(const struct config *c, char *err, size_t errlen);

/* Every setting at its row's default (lists empty: config_model fills them with it). */
void config_init(struct config *c);

/* The key with this long name, or -1. */
int config_find(const char *name);

/* The shortest text that reads back (strtod) as exactly v. */
void config_format_exact(double v, char *buf, size_t len);

/* A setting's value as config_get reads it: numbers (a list's one per element, or one),
 * or, where count is 0, text (a choice's name, true or false, a whole number, the seed,
 * start-mode's K:AMP, a file name). */
struct config_value {
    int count;        /* numbers in v; 0: the value is str */
    const double *v;  /* the numbers: the model's or the config's, or one */
    double one;       /* where a single number is kept */
    const char *str;  /* the text: text, or a text setting's own string */
    char text[48];
};

/* key's value in force: from model m where the model holds it (N, its lists with one
 * value per element, the right end, the drive, collisions), else from c (a list c never
 * set: its default, once). m may be NULL. The value lives in out, c or m. */
void config_get(int key, const struct config *c, const struct model *m,
                struct config_value *out);

/* Whether key is in force in c: of the initial conditions, start-mode when c starts
 * along a mode, else random and seed when positions are random, else x0 and v0;
 * spring-cubic when some k3 is not 0; every other key always. */
bool config_in_force(int key, const struct config *c);

/* Writes c's settings (every row with a preset section, in the table's order) as command
 * line options, each preceded by a space: " --masses 2 --mass 1 ... --seed 7". Read back
 * by the command line they give c's settings again. 0, or -1 on a write error. */
int config_write_args(FILE *out, const struct config *c);

/* Whether key's option takes a value on the command line (a flag and a mode without an
 * argument do not). */
bool config_takes_value(int key);

/* Sets key from its text value (NULL for a command-line flag). On error returns -1
 * and writes into err one phrase naming the value and what is allowed, e.g.
 * "'abc' is not a number (expected 0 < dt <= 0.05)"; the config is unchanged then. */
int config_set(struct config *c, int key, const char *value, char *err, size_t errlen);

/* Builds the model the config describes. On a list whose length does not fit N it
 * returns NULL, sets *bad_key and writes the reason into err; NULL with *bad_key = -1
 * means no memory. */
struct model *config_model(const struct config *c, int *bad_key, char *err, size_t errlen);

/* Initial displacements and velocities for model m (built from c) into x and v: x0 and
 * v0, random positions, or start_amp times mode start_mode's shape at rest. Returns 0, or
 * modes_start's error with x and v at 0. */
int config_initial(const struct config *c, const struct model *m, double *x, double *v);

/* Random displacements for model m from seed: block centres uniformly placed inside
 * the walls (clear of the piston at its furthest), neighbours at least 1.5 block widths
 * apart. The same seed gives the same positions. */
void config_random_positions(const struct model *m, uint64_t seed, double *x);


#endif
