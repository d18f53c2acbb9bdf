/* app.h: the interactive program's state and what its actions do to it, with no
 * terminal in sight: the chain being run, its initial conditions, history, the plots'
 * samples, playback, and the controls' values. The terminal front end drives this. */
#ifndef SPRINGSIM_APP_H
#define SPRINGSIM_APP_H

#include <stdbool.h>

#include "../core/config.h"
#include "../core/history.h"
#include "../core/sim.h"
#include "../core/sweep.h"
#include "trail.h"

#define APP_MAX_MASSES 10    /* the interactive program's limit */
#define APP_WINDOW 10.0      /* seconds the time plots show */
#define APP_FMIN 0.1         /* the frequency control's range (Hz) */
#define APP_FMAX 5.0
#define APP_SWEEP_POINTS 40  /* frequencies in a sine-sweep experiment */

/* Position of frequency f on the control's range drawn on a log scale, 0 to 1. */
double app_freq_fraction(double f);

/* What a save of a preset came to. */
enum app_save { SAVE_OK, SAVE_EXISTS, SAVE_BAD_NAME, SAVE_FAILED };

/* The controls, top to bottom. */
enum control {
    CTL_PRESET,
    CTL_MASSES,
    CTL_DT,
    CTL_DAMPING,
    CTL_SPRING,
    CTL_MASS,
    CTL_BOUNDARY,
    CTL_WAVE,
    CTL_AMPLITUDE,
    CTL_FREQUENCY,
    CTL_SPEED,
    CTL_BANDWIDTH,
    CTL_COUNT
};

struct app {
    struct config cfg;       /* settings; cfg.x0/v0 are the initial conditions */
    struct model *model;     /* parameters in force */
    struct sim *sim;         /* the running chain */
    struct history *hist;    /* states to step back to */
    struct trail *trail;     /* samples for the plots */
    int sample_every;        /* steps between trail samples */
    int since_sample;        /* steps since the last sample */
    bool running;            /* playing, not paused */
    double speed;            /* simulated seconds per wall-clock second */
    int masses_pending;      /* the Masses control before it is applied */
    double stable_dt;        /* RK4 stability limit of the current chain */
    char preset[64];         /* name of the preset loaded, or "" */
    char message[200];       /* one line for the status bar, "" for none */
    bool message_is_error;   /* shown as a warning */
    const char *exe_dir;     /* for the preset search path */
    double modes[APP_MAX_MASSES];                  /* natural frequencies (Hz) */
    double shapes[APP_MAX_MASSES * APP_MAX_MASSES]; /* mode shapes, mode-major */
    bool modes_ok;           /* modes[] and shapes[] are those of the model */
    unsigned version;        /* counts changes of the chain's parameters (never 0) */
    struct sweep *sweep;     /* the sine-sweep experiment */
    double sweep_from;       /* the drive's frequency before the sweep, given back after */
    double energy0;          /* the energy balance at t = 0 */
};

/* Sets up app from cfg (N already checked to be 1..APP_MAX_MASSES); 0, or -1 on no memory. */
int app_init(struct app *app, const struct config *cfg, const char *exe_dir);

/* Frees what app holds. */
void app_free(struct app *app);

/* Back to t = 0 at the initial conditions; plots and history cleared. */
void app_reset(struct app *app);

/* One step forward, history and plots kept. On a non-finite result the chain is
 * paused at its last finite state and the message says why; returns false then. */
bool app_step(struct app *app);

/* One step back; false (with a message) when there is none or it is running. */
bool app_back(struct app *app);

/* New random initial positions (a fresh seed), at rest, and a reset. */
void app_random(struct app *app);

/* Moves mass i's initial position by dx (m) while paused, keeping it inside its
 * neighbours and the walls; everything restarts at t = 0 from there, at rest. */
void app_move_mass(struct app *app, int i, double dx);

/* Sets mass i's centre to absolute position X (m) while paused, as app_move_mass. */
void app_place_mass(struct app *app, int i, double X);

/* Adjusts a control by steps of its fine (coarse = false) or coarse step; negative
 * steps go down. Takes effect at once, except Masses, which waits for app_apply. */
void app_adjust(struct app *app, enum control ctl, int steps, bool coarse);

/* Sets a control from typed text; false with the reason in the message if it is bad. */
bool app_set_text(struct app *app, enum control ctl, const char *text);

/* Applies a pending change of the number of masses (a reset). */
void app_apply_masses(struct app *app);

/* Loads the preset at path; false with the reason in the message. */
bool app_load_preset(struct app *app, const char *path, const char *name);

/* Sets mass i's own mass (what = 'm') or damping ('c'), or spring j's constant
 * ('k'), from typed text; false with the reason in the message. */
bool app_set_element(struct app *app, char what, int index, const char *text);

/* Sets the motor frequency to the natural frequency nearest to it. */
void app_nearest_mode(struct app *app);

/* Starts (or stops, if running) the sine-sweep experiment across the modes. */
void app_toggle_sweep(struct app *app);

/* Saves the set-up as user preset name (overwrite an existing one only if asked);
 * the message says what happened. */
enum app_save app_save(struct app *app, const char *name, bool overwrite);

/* Writes the recorded samples as --headless CSV to ./springsim-YYYYmmdd-HHMMSS.csv
 * (or into dir if not NULL); the path goes into path. False with the reason. */
bool app_export(struct app *app, const char *dir, char *path, size_t len);

/* The energy balance now, minus its value at t = 0 (J). */
double app_energy_drift(const struct app *app);

/* The control's label and its value with units, for the panel. */
const char *app_control_label(enum control ctl);
void app_control_value(const struct app *app, enum control ctl, char *buf, size_t len);

/* Sets the status message (printf-style). */
void app_say(struct app *app, bool error, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));

#endif
