/* app.h: the interactive program's state and what its actions do to it, with no
 * terminal in sight: the chain being run, its initial conditions, history, the plots'
 * samples and their time window, playback, and the controls' values. The terminal front
 * end drives this.
 *
 * Every action returns what it changed, a mask of enum app_change (0: nothing; htop's
 * Htop_Reaction): the one change path (change.h) recomputes by it only what a change
 * needs, a verb's result (verb.h) tells a change made from nothing done by it, --record
 * writes a command only for a change, and the terminal program refreshes the plots'
 * canvases (the costly part of a frame) after a key only when something they draw
 * changed (APP_CHANGED_DRAWN); the rest of the screen is drawn whole from the state each
 * frame, curses sending only the cells that differ. A rejected input returns 0 and
 * leaves everything as it was but the message, which says why. Every change of the
 * chain's or the drive's parameters, by any route, goes through one path that keeps the
 * rules: a running sweep ends (but for its own retunes) and gives the user's frequency
 * back; the modes and the damped modes behind the limits of dt are recomputed once; a
 * new chain (new N, a preset) is built whole before the old one is let go, or not at
 * all; a change that leaves dt unstable or inaccurate says so. */
#ifndef SPRINGSIM_APP_H
#define SPRINGSIM_APP_H

#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>

#include "../core/config.h"
#include "../core/history.h"
#include "../core/limits.h"
#include "../core/sim.h"
#include "../core/sweep.h"
#include "scope.h"
#include "../chart/trail.h"

#define APP_MAX_MASSES CONFIG_INTERACTIVE_MAX_MASSES /* the interactive program's N */
#define APP_FMIN 0.1         /* the frequency control's range (Hz) */
#define APP_FMAX 5.0
#define APP_SWEEP_POINTS 40  /* frequencies in a sine-sweep experiment */
#define APP_SWEEP_PACE 50.0  /* a running sweep plays this many times the Speed control's
                              * rate: the defaults' sweep, about 4100 s, in 82 s */
#define APP_MODE_AMPLITUDE 0.5 /* largest |x| when the chain starts in a mode (m) */

/* What an action changed: bits of the unsigned it returns. */
enum app_change {
    APP_CHANGED_CHAIN = 1u << 0,    /* masses, springs, damping, right end: modes and
                                     * stability limit recomputed, version bumped */
    APP_CHANGED_DRIVE = 1u << 1,    /* frequency, amplitude, waveform, right end */
    APP_CHANGED_SIZE = 1u << 2,     /* the number of masses: what is sized by N follows */
    APP_CHANGED_STATE = 1u << 3,    /* the state moved or jumped: step, back, reset, a
                                     * mass moved; plots and history follow */
    APP_CHANGED_PLAYBACK = 1u << 4, /* running, speed, bandwidth, graphics */
    APP_CHANGED_WINDOW = 1u << 5,   /* the time plots' window */
    APP_CHANGED_MESSAGE = 1u << 6,  /* the status message */
    APP_CHANGED_DT = 1u << 7,       /* the time step (and so the plots' sampling) */
    APP_CHANGED_PENDING = 1u << 8,  /* the Masses control's value waiting for Enter */
    APP_CHANGED_INTEGRATOR = 1u << 9, /* the integrator (and so the limits of dt) */
    APP_CHANGED_GHOST = 1u << 10,   /* the ghost came or went (ghost.h) */
};

/* What the plots and the analysis views draw: every change but the message and a number
 * of masses waiting for Enter. */
#define APP_CHANGED_DRAWN (~(unsigned)(APP_CHANGED_MESSAGE | APP_CHANGED_PENDING))

/* Digits after the point that time step dt needs (2 at least): t and dt are shown with
 * them, so t = 0.003 s after three steps of 0.001 s and dt 0.0075 s reads whole. */
int app_time_decimals(double dt);

/* v with this many decimals while |v| < 1e6, in exponent form (at most 3 decimals) from
 * there, and a word for a value that is not finite: never wider than about 12 characters
 * (no 300-digit numbers, no inf or nan on the screen). Returns buf. */
const char *app_fixed(double v, int decimals, char *buf, size_t len);

/* Position of frequency f on the control's range drawn on a log scale, 0 to 1. */
double app_freq_fraction(double f);

/* What the status message is, set where it is made. */
enum app_said {
    SAID_NOTE,    /* what was done, or a hint */
    SAID_WARNING, /* done, with a caveat: dt is past a limit of the chain as it is now */
    SAID_ERROR,   /* refused, or failed: nothing changed but the message */
    SAID_CAP,     /* the velocity cap's count, said anew at every step it acts (a line
                   * mode tells it at most once a second of simulated time) */
};

/* What a save of a preset came to. */
enum app_save { SAVE_OK, SAVE_EXISTS, SAVE_BAD_NAME, SAVE_FAILED };

/* The controls, top to bottom. */
enum control {
    CTL_PRESET,
    CTL_MASSES,
    CTL_DT,
    CTL_INTEGRATOR,
    CTL_DAMPING,
    CTL_SPRING,
    CTL_MASS,
    CTL_BOUNDARY,
    CTL_WAVE,
    CTL_AMPLITUDE,
    CTL_FREQUENCY,
    CTL_FORCE,
    CTL_FORCE_ON,
    CTL_SPEED,
    CTL_BANDWIDTH,
    CTL_GRAPHICS,
    CTL_COUNT
};

struct app {
    struct config cfg;       /* settings in force; cfg.x0/v0 are the initial conditions */
    const struct model *model; /* parameters in force: the sim's own (sim_model), the one
                                * copy; they change through app_change alone */
    struct sim *sim;         /* the running chain */
    struct history *hist;    /* states to step back to */
    struct trail *trail;     /* fine samples for the plots (about 11 s), and for export */
    struct trail *coarse;    /* coarse samples for the plots (over 60 s) */
    int sample_every;        /* steps between fine samples */
    int since_sample;        /* steps since the last fine sample */
    int coarse_every;        /* steps between coarse samples */
    int since_coarse;        /* steps since the last coarse sample */
    bool running;            /* playing, not paused */
    double speed;            /* simulated seconds per wall-clock second */
    int masses_pending;      /* the Masses control before it is applied */
    double stable_dt;        /* the integrator's stability limit on this chain (s) */
    struct limits limits;    /* what dt is worth: stability, accuracy, the drive's steps */
    struct limits_mode limit_modes[APP_MAX_MASSES]; /* the damped chain's modes */
    bool limits_ok;          /* limit_modes[] and limits are those of the model */
    struct limits_runaway runaway; /* past the stability limit: the watch for a blow-up */
    bool runaway_base_ok;    /* runaway is of this run since the last change */
    double work;             /* mass-steps done so far (cost.h: each step's masses, again
                              * for each of the drive's breakpoints in it and each contact,
                              * and the drive's half-cycles in it; each change's judging) */
    double step_work;        /* the last step's */
    double work_limit;       /* lesson_run_to stops past it (a lesson's check), or 0 */
    long capped;             /* velocities the cap has acted on since t = 0 */
    double first_cap;        /* when it first did (s) */
    char preset[64];         /* name of the preset loaded, or "" */
    char preset_file[4400];  /* the file it was loaded from (app_load_preset), or "" */
    unsigned loads;          /* presets loaded from files so far */
    char message[200];       /* one line for the status bar, "" for none */
    enum app_said said;      /* what the message is, set with it (app_say): what is decided
                              * on it is decided on this, never on its words */
    unsigned says;           /* messages said so far (app_say): a new one moves it */
    const char *exe_dir;     /* for the preset search path */
    /* How the front end showing the messages names an action (enum action): its key in
     * the terminal program ("space", "]"), its command in the plain mode ("start",
     * "faster"); NULL for none. With keys, a message may name one in brackets ("pause
     * first (space)"), which a command word would only repeat. Unset: no names. */
    const char *(*name_of)(int action);
    bool keys;
    double modes[APP_MAX_MASSES];                  /* natural frequencies (Hz) */
    double shapes[APP_MAX_MASSES * APP_MAX_MASSES]; /* mode shapes, mode-major */
    bool modes_ok;           /* modes[] and shapes[] are those of the model */
    double damping_ratio[APP_MAX_MASSES]; /* each mode's damping ratio zeta */
    double damped_hz[APP_MAX_MASSES];     /* each mode's damped frequency (Hz, 0: overdamped) */
    bool damping_ok;         /* damping_ratio[] and damped_hz[] are those of the model */
    unsigned version;        /* counts changes of the chain's or the drive's parameters
                              * (never 0): what is computed from the model is stale when
                              * it moves */
    struct sweep *sweep;     /* the sine-sweep experiment */
    struct sweep *sweep_up;  /* a chain with cubic springs: its sweep up, kept while the
                              * sweep down runs in sweep, and after (jump.c) */
    double sweep_from;       /* the user's frequency during a sweep, given back after */
    double energy0;          /* the energy balance at t = 0 */
    struct ghost *ghost;     /* a frozen copy run beside the chain (ghost.h), or NULL */
    struct scope scope;      /* time cursors, scroll-back, the mass measured (scope.h) */
    enum config_graphics graphics_now; /* what the front end draws the charts with now
                                        * (sixel, kitty or braille; AUTO: no charts, the
                                        * line mode): the Graphics control shows it */
};

/* Sets up app from cfg (N already checked to be 1..APP_MAX_MASSES); 0, or -1 on no memory. */
int app_init(struct app *app, const struct config *cfg, const char *exe_dir);

/* app_init for a front end that names its actions in the messages (app->name_of, keys). */
int app_init_named(struct app *app, const struct config *cfg, const char *exe_dir,
                   const char *(*name_of)(int action), bool keys);

/* Frees what app holds. */
void app_free(struct app *app);

/* Back to t = 0 at the initial conditions; plots and history cleared; a sweep ends. */
unsigned app_reset(struct app *app);

/* One step forward, history and plots kept. On a non-finite result the chain is
 * paused at its last finite state and the message says why; returns 0 then. */
unsigned app_step(struct app *app);

/* One step back; 0 (with a message) when there is none or it is running. */
unsigned app_back(struct app *app);

/* Plays or pauses. */
unsigned app_set_running(struct app *app, bool running);

/* New random initial positions (a fresh seed), at rest, and a reset. */
unsigned app_random(struct app *app);

/* The same from a given seed (the same seed gives the same positions). */
unsigned app_random_seed(struct app *app, uint64_t seed);

/* Starts mass i displaced by x0 (m) while paused, kept inside its neighbours and the
 * walls; the others start where they stand; everything restarts at t = 0, at rest. */
unsigned app_place_start(struct app *app, int i, double x0);

/* Moves mass i's initial position by dx (m) while paused, keeping it inside its
 * neighbours and the walls; everything restarts at t = 0 from there, at rest. */
unsigned app_move_mass(struct app *app, int i, double dx);

/* Sets mass i's centre to absolute position X (m) while paused, as app_move_mass. */
unsigned app_place_mass(struct app *app, int i, double X);

/* Adjusts a control by steps of its fine (coarse = false) or coarse step; negative
 * steps go down. Takes effect at once, except Masses, which waits for app_apply. */
unsigned app_adjust(struct app *app, enum control ctl, int steps, bool coarse);

/* Sets a control from typed text; 0 with the reason in the message if it is bad. */
unsigned app_set_text(struct app *app, enum control ctl, const char *text);

/* Sets the time plots' window from typed text (seconds, --window's range); 0 with the
 * reason in the message if it is bad. */
unsigned app_set_window(struct app *app, const char *text);

/* Sets the springs' cubic constants k3 from typed text (--spring-cubic's list) when spring
 * is negative, else spring's own (0 the wall's); 0 with the reason in the message if it is
 * bad or refused (the exact integrator steps linear chains only). */
unsigned app_set_cubic(struct app *app, int spring, const char *text);

/* Sets the dampers beside the springs from typed text (--spring-damping's list) when spring
 * is negative, else spring's own (0 the wall's); 0 with the reason in the message if it is
 * bad or refused. */
unsigned app_set_spring_damping(struct app *app, int spring, const char *text);

/* Applies a pending change of the number of masses (a reset). */
unsigned app_apply_masses(struct app *app);

/* Loads the preset at path; 0 with the reason in the message. */
unsigned app_load_preset(struct app *app, const char *path, const char *name);

/* Loads a preset given as text (size bytes), as if read from the file path; as
 * app_load_preset. */
unsigned app_load_preset_text(struct app *app, const char *path, const char *text, size_t size,
                              const char *name);

/* Sets mass i's own mass (what = 'm') or damping ('c'), or spring j's constant
 * ('k'), from typed text; 0 with the reason in the message. */
unsigned app_set_element(struct app *app, char what, int index, const char *text);

/* Spring j's name for the screen: numbered from 1 as in the --spring list, with what it
 * joins, "spring 1 (wall–1)", "spring 2 (1–2)", "spring 4 (3–motor)". */
void app_spring_name(const struct model *m, int j, char *buf, size_t len);

/* What a chain with cubic springs adds to the warning in line (empty: none): a limit is
 * the chain's linearised at rest, and swings stiffen hardening springs; a softening
 * spring's force turns over past some stretch. */
void app_say_nonlinear(const struct model *m, char *line, size_t len);

/* Sets the motor frequency to the natural frequency nearest to it. */
unsigned app_nearest_mode(struct app *app);

/* Starts the chain in mode j (0 the lowest): displacements along its shape, the largest
 * APP_MODE_AMPLITUDE (less where two masses would come close), at rest, from t = 0,
 * running. With the modes unknown, 0 and a message. */
unsigned app_start_mode(struct app *app, int j);

/* Starts (or stops, if running) the sine-sweep experiment across the modes
 * (sweeping.c), each point measured once its swings are steady. */
unsigned app_toggle_sweep(struct app *app);

/* The time plots' window (s): cfg.window, 10 unless --window or a preset says otherwise. */
double app_window(const struct app *app);

/* Moves to the next window of 1, 2, 5, 10, 20, 30 and 60 s past the one shown, shorter
 * (dir -1) or longer (+1); at an end of the list, a message. */
unsigned app_window_step(struct app *app, int dir);

/* The samples that cover the current window: the fine ones up to 10 s, else coarse. */
const struct trail *app_trail(const struct app *app);

/* The ghost's samples for the same window as app_trail's, or NULL without a ghost. */
const struct trail *app_ghost_trail(const struct app *app);

/* Saves the set-up as user preset name (overwrite an existing one only if asked);
 * the message says what happened. */
enum app_save app_save(struct app *app, const char *name, bool overwrite);

/* Writes the fine samples as --headless CSV to ./springsim-YYYYmmdd-HHMMSS.csv (or into
 * dir if not NULL); the path goes into path. 0 with the reason in the message. */
unsigned app_export(struct app *app, const char *dir, char *path, size_t len);

/* The '#' lines app_export writes before its header, as --meta's: the version, the
 * --headless command line of the settings now (duration the time now, --sample the
 * samples' spacing), and what the file holds (from when, how many, the recording's
 * limit). */
void app_export_meta(FILE *fp, const struct app *app);

/* What app_export writes, for its message: "4400 rows, the last 11.00 s (t = 33.30 to
 * 44.30 s)" or "504 rows (t = 0 to 5.03 s)". */
void app_export_summary(const struct app *app, char *buf, size_t len);

/* Writes the sweep's measured points (amplitude and phase of each mass) beside the
 * linear theory's at each point, as CSV with --meta's lines (the --sweep command line
 * that gives the theory), to ./springsim-sweep-YYYYmmdd-HHMMSS.csv (or into dir); the
 * path into path. 0 with the reason in the message (no sweep measured, no drive). */
unsigned app_export_sweep(struct app *app, const char *dir, char *path, size_t len);

/* The energy balance now, minus its value at t = 0 (J). */
double app_energy_drift(const struct app *app);

/* The control's label and its value with units, for the panel. */
const char *app_control_label(enum control ctl);
/* The name `set` takes for a control: its setting's ("dt", "boundary"), or its own. */
const char *app_control_name(enum control ctl);
void app_control_value(const struct app *app, enum control ctl, char *buf, size_t len);

/* Sets the status message (printf-style) and what it is; returns APP_CHANGED_MESSAGE. */
unsigned app_say(struct app *app, enum app_said said, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));

/* path as a message names it: whole when short, else its start and its end around "..."
 * (whole characters), so that the reason said after it fits the status line. */
const char *app_path_shown(const char *path, char *buf, size_t len);

/* What the front end calls action a (app->name_of), or "" for none. */
const char *app_key(const struct app *app, int a);

/* " (KEY)" and " (KEY what)" where the front end has keys and one for action a: a hint in
 * brackets; "" elsewhere. */
const char *app_key_hint(const struct app *app, int a, const char *what, char *buf,
                         size_t len);

/* No message (a note, so that nothing left of an old one is read as a warning). */
void app_quiet(struct app *app);

#endif
