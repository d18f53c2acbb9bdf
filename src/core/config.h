/* config.h: every setting of a run, the table of options that are both long
 * command-line options and preset keys, and the checks of their values (SPEC 2-3). */
#ifndef SPRINGSIM_CONFIG_H
#define SPRINGSIM_CONFIG_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "integrator.h"
#include "model.h"

enum config_key {
    CFG_PRESET,
    CFG_MASSES,
    CFG_MASS,
    CFG_SPRING,
    CFG_DAMPING,
    CFG_DT,
    CFG_INTEGRATOR,
    CFG_BOUNDARY,
    CFG_WAVE,
    CFG_AMPLITUDE,
    CFG_FREQUENCY,
    CFG_X0,
    CFG_V0,
    CFG_RANDOM,
    CFG_SEED,
    CFG_NO_COLLISIONS,
    CFG_DURATION,
    CFG_SAMPLE,
    CFG_OUTPUT,
    CFG_ENERGY,
    CFG_FPS,
    CFG_LOW_BANDWIDTH,
    CFG_KEY_COUNT
};

/* One setting: its long option, short option, preset section and help. */
struct config_option {
    const char *name;    /* long option and preset key */
    char short_name;     /* short option, or 0 */
    const char *section; /* preset section, or NULL for the command line only */
    const char *arg;     /* argument for --help, or NULL for a flag */
    const char *help;    /* one line for --help */
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
    struct config_list damping;         /* N s/m */
    double dt;                          /* s */
    enum integrator integrator;         /* the stepper (rk4 unless set) */
    enum boundary boundary;             /* right end */
    enum wave wave;                     /* drive waveform */
    double amplitude;                   /* m */
    double frequency;                   /* Hz */
    struct config_list x0;              /* initial displacements (m) */
    struct config_list v0;              /* initial velocities (m/s) */
    bool random;                        /* random initial positions */
    uint64_t seed;                      /* seed for random */
    bool seed_set;                      /* seed given */
    bool no_collisions;                 /* collisions off */
    double duration;                    /* headless run length (s) */
    double sample;                      /* headless output interval (s), 0 = every step */
    const char *output;                 /* output file, NULL for standard output */
    bool energy;                        /* energy columns in the headless CSV */
    int fps;                            /* interactive frames per second */
    bool low_bandwidth;                 /* interactive: keep terminal output small */
    char name[64];                      /* preset's display name */
    char description[256];              /* preset's description */
    struct config_origin origin[CFG_KEY_COUNT]; /* where each key was set */
};

#define CONFIG_QUOTE_MAX 40  /* characters of a value quoted in a message */
#define CONFIG_MAX_STEPS 1e12 /* steps a headless run may take */

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

/* The key to blame when a headless run of c would take more than CONFIG_MAX_STEPS steps
 * (CFG_DURATION or CFG_DT), with the reason in err; -1 when it would not. */
int config_check_steps(const struct config *c, char *err, size_t errlen);

/* The defaults: the page's (2 masses of 1 kg, 10 N/m, 0.1 N s/m, dt 0.01 s, motor,
 * sine, 1 m, 1 Hz, at rest), rk4, duration 10 s, every step sampled. */
void config_init(struct config *c);

/* The key with this long name, or -1. */
int config_find(const char *name);

/* Sets key from its text value (NULL for a command-line flag). On error returns -1
 * and writes into err one phrase naming the value and what is allowed, e.g.
 * "'abc' is not a number (expected 0 < dt <= 0.05)"; the config is unchanged then. */
int config_set(struct config *c, int key, const char *value, char *err, size_t errlen);

/* Builds the model the config describes. On a list whose length does not fit N it
 * returns NULL, sets *bad_key and writes the reason into err; NULL with *bad_key = -1
 * means no memory. */
struct model *config_model(const struct config *c, int *bad_key, char *err, size_t errlen);

/* Initial displacements and velocities for model m (built from c) into x and v. */
void config_initial(const struct config *c, const struct model *m, double *x, double *v);

/* Random displacements for model m from seed: block centres uniformly placed inside
 * the walls (clear of the piston at its furthest), neighbours at least 1.5 block widths
 * apart. The same seed gives the same positions. */
void config_random_positions(const struct model *m, uint64_t seed, double *x);


#endif
