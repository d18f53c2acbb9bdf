/* test_watch.c: the plain mode's events (app/watch.c) against closed forms. One undamped
 * mass between two springs (k = 10 N/m each, m = 1 kg) swings at w = sqrt(2k/m): from
 * x0 = 0.3 m at rest its one peak is 0.3 m at T/2; thrown at the left wall it touches it
 * when (v0/w) sin(wt) = -(L/2 - b/2); driven at resonance with damping c, its swing grows
 * to kA/(cw) and the peaks told stop growing there; the drive is on the natural frequency
 * within 2 % and not at 3 %. Released from 0.5 m with damping c, its turning points are
 * at t = k pi / w_d with |x| = 0.5 e^(-zeta w t): the peaks told fall, none the largest.
 * And the commands of the plain mode (app/command.c): a refused
 * one changes nothing and says why in one line. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>

#include <cmocka.h>

#include "app/app.h"
#include "app/command.h"
#include "app/watch.h"
#include "core/collision.h"

#define K 10.0
#define M 1.0
#define OMEGA sqrt(2.0 * K / M)

/* What the events said. */
struct heard {
    int peaks, contacts, resonances;
    int falling, largest;                   /* peaks told as falling, as the largest */
    double peak_t[64], peak_x[64];
    double contact_t[16];
    char contact[16][80];
    char last[200];
    const struct app *app;
};

static void hear(void *ctx, const char *event)
{
    struct heard *h = ctx;
    double t = sim_time(h->app->sim);
    snprintf(h->last, sizeof h->last, "%s", event);
    double x;
    if (sscanf(event, "peak: mass 1 |x| = %lf m", &x) == 1 && h->peaks < 64) {
        h->peak_t[h->peaks] = t;
        h->peak_x[h->peaks++] = x;
        h->falling += strstr(event, ", falling from ") != NULL;
        h->largest += strstr(event, ", the largest since t = 0") != NULL;
    } else if (strncmp(event, "contact: ", 9) == 0 && h->contacts < 16) {
        h->contact_t[h->contacts] = t;
        snprintf(h->contact[h->contacts++], sizeof h->contact[0], "%s", event + 9);
    } else if (strncmp(event, "resonance: ", 11) == 0) {
        h->resonances++;
    }
}

/* One mass, k = 10 on both sides, m = 1, at dt 0.01; set up by the caller's options. */
static void one_mass(struct app *app, const char *const *opts)
{
    struct config c;
    char err[300];
    config_init(&c);
    for (const char *const *o = opts; *o; o += 2)
        assert_int_equal(config_set(&c, config_find(o[0]), o[1], err, sizeof err), 0);
    assert_int_equal(app_init(app, &c, SRCDIR), 0);
}

static void run(struct app *app, struct watch *w, struct heard *h, double seconds)
{
    double end = sim_time(app->sim) + seconds;
    while (sim_time(app->sim) < end - 1e-9) {
        assert_true(app_step(app) != 0);
        watch_step(w, app, hear, h);
    }
}

static void one_peak_in_free_vibration(void **state)
{
    (void)state;
    static struct app app;
    static const char *const opts[] = {"masses", "1", "damping", "0", "amplitude", "0",
                                       "x0", "0.3", "no-collisions", NULL, NULL};
    one_mass(&app, opts);
    struct watch w;
    struct heard h = {.app = &app};
    watch_init(&w, &app);
    run(&app, &w, &h, 10.0);
    assert_int_equal(h.peaks, 1);
    double half = M_PI / OMEGA; /* T/2 = 0.7025 s */
    assert_true(h.peak_t[0] >= half && h.peak_t[0] <= half + 0.01 + 1e-9);
    /* the larger |x| of the two steps around the turn: within 0.3 (1 - cos(w dt / 2)) */
    assert_true(fabs(h.peak_x[0] - 0.3) <= 0.3 * (1.0 - cos(OMEGA * 0.005)) + 5e-5);
    /* a reset forgets it: the same peak is told again */
    app_reset(&app);
    watch_look(&w, &app, hear, &h);
    run(&app, &w, &h, 1.0);
    assert_int_equal(h.peaks, 2);
    app_free(&app);
}

/* A free decay from 0.5 m (c = 0.1: zeta = c / (2 sqrt(2k m)) = 0.0112): its falling
 * peaks are told, each 5 % or more below the one before (the start the first), on the
 * envelope 0.5 e^(-zeta w t); none is "the largest since t = 0" (it said so of 0.46 m). */
static void falling_peaks_of_a_free_decay(void **state)
{
    (void)state;
    static struct app app;
    static const char *const opts[] = {"masses", "1", "damping", "0.1", "amplitude", "0",
                                       "x0", "0.5", "no-collisions", NULL, NULL};
    one_mass(&app, opts);
    struct watch w;
    struct heard h = {.app = &app};
    watch_init(&w, &app);
    run(&app, &w, &h, 20.0);
    double zeta = 0.1 / (2.0 * sqrt(2.0 * K * M)), wd = OMEGA * sqrt(1.0 - zeta * zeta);
    assert_true(h.peaks >= 10);
    assert_int_equal(h.falling, h.peaks);
    assert_int_equal(h.largest, 0);
    double before = 0.5;
    for (int i = 0; i < h.peaks; i++) {
        double tk = round(h.peak_t[i] * wd / M_PI) * M_PI / wd;
        assert_true(fabs(h.peak_t[i] - tk) <= 0.01 + 1e-9);
        double env = 0.5 * exp(-zeta * OMEGA * tk);
        assert_true(fabs(h.peak_x[i] - env) <= env * (1.0 - cos(OMEGA * 0.005)) + 5e-5);
        assert_true(h.peak_x[i] <= 0.95 * before);
        before = h.peak_x[i];
    }
    app_free(&app);
}

static void peaks_grow_to_the_steady_state_and_stop(void **state)
{
    (void)state;
    static struct app app;
    char f[32];
    snprintf(f, sizeof f, "%.17g", OMEGA / (2.0 * M_PI));
    const char *const opts[] = {"masses", "1", "damping", "0.1", "amplitude", "0.1",
                                "frequency", f, NULL, NULL};
    one_mass(&app, opts);
    struct watch w;
    struct heard h = {.app = &app};
    watch_init(&w, &app);
    run(&app, &w, &h, 200.0);
    /* |X| = k A / |2k - m w^2 + i c w| = k A / (c w) at resonance: 2.236 m */
    double steady = K * 0.1 / (0.1 * OMEGA);
    assert_true(h.peaks >= 10);
    for (int i = 0; i < h.peaks; i++) {
        assert_true(h.peak_x[i] <= steady * 1.001);
        if (i > 0) {
            assert_true(h.peak_x[i] >= 1.05 * h.peak_x[i - 1] - 5e-5);
            assert_true(h.peak_t[i] - h.peak_t[i - 1] >= 0.5 * M_PI / OMEGA);
        }
    }
    /* 1 - exp(-t zeta w) of the way there: at 7 time constants the last step of 5 % is
     * behind, so the last 60 s tell nothing */
    assert_true(h.peak_t[h.peaks - 1] < 140.0);
    assert_true(h.peak_x[h.peaks - 1] >= steady / 1.05 - 1e-3);
    app_free(&app);
}

static void contact_with_the_left_wall_when_it_is_reached(void **state)
{
    (void)state;
    static struct app app;
    static const char *const opts[] = {"masses", "1", "damping", "0", "boundary", "wall",
                                       "v0", "-25", NULL, NULL};
    one_mass(&app, opts);
    struct watch w;
    struct heard h = {.app = &app};
    watch_init(&w, &app);
    run(&app, &w, &h, 1.5);
    assert_true(h.contacts >= 2);
    /* x = (v0/w) sin(wt) reaches -(L/2 - b/2) = -4.8 m */
    double reach = MODEL_LENGTH / 2.0 - 0.5 * model_block_width(app.model);
    double t1 = asin(reach / (25.0 / OMEGA)) / OMEGA;
    assert_string_equal(h.contact[0], "mass 1 and the left wall");
    assert_true(h.contact_t[0] >= t1 && h.contact_t[0] <= t1 + 0.01 + 1e-9);
    /* bounced at 0.8 of the speed, it still has the energy to reach the right wall */
    assert_string_equal(h.contact[1], "mass 1 and the right wall");
    app_free(&app);
}

/* Contact lines and what they stand for, second by second of simulated time. */
struct tally {
    const struct app *app;
    int lines[64];   /* contact lines said in second k */
    long contacts;   /* contacts they stand for: one each, or the N of "N more" */
};

static void count_contacts(void *ctx, const char *event)
{
    struct tally *y = ctx;
    if (strncmp(event, "contact: ", 9) != 0)
        return;
    int k = (int)floor(sim_time(y->app->sim) - 1e-9);
    if (k >= 0 && k < 64)
        y->lines[k]++;
    int more;
    y->contacts += sscanf(event, "contact: %d more", &more) == 1 ? more : 1;
}

/* Ten masses rattling against each other: every contact is accounted for (the lines one
 * by one plus the "N more" lines add up to what a watch without a limit tells), and no
 * second of simulated time gets more than WATCH_CONTACT_BURST + 1 lines. */
static void a_rattling_chain_is_told_in_bursts(void **state)
{
    (void)state;
    static struct app app;
    static const char *const opts[] = {"masses", "10", "random", NULL, "seed", "4",
                                       "amplitude", "1", NULL, NULL};
    one_mass(&app, opts);
    struct watch limited, all;
    struct tally said = {.app = &app}, every = {.app = &app};
    watch_init(&limited, &app);
    watch_init(&all, &app);
    all.burst = 1 << 30;
    while (sim_time(app.sim) < 20.0 + 1e-9) {
        assert_true(app_step(&app) != 0);
        watch_step(&limited, &app, count_contacts, &said);
        watch_step(&all, &app, count_contacts, &every);
    }
    assert_true(every.contacts > 10 * 20 / 2); /* more than the limit lets through */
    assert_int_equal(said.contacts, every.contacts);
    for (int k = 0; k < 20; k++)
        if (said.lines[k] > WATCH_CONTACT_BURST + 1)
            fail_msg("second %d: %d contact lines", k, said.lines[k]);
    app_free(&app);
}

static void drive_on_a_mode_within_two_percent(void **state)
{
    (void)state;
    static struct app app;
    static const char *const opts[] = {"masses", "1", "frequency", "0.5", NULL, NULL};
    one_mass(&app, opts);
    struct watch w;
    struct heard h = {.app = &app};
    double f1 = OMEGA / (2.0 * M_PI);
    char text[32];
    watch_init(&w, &app);
    const double at[] = {1.03, 0.985, 1.01, 0.9, 1.019};
    const int told[] = {0, 1, 1, 1, 2};
    for (int i = 0; i < 5; i++) {
        snprintf(text, sizeof text, "%.6f", at[i] * f1);
        assert_true(app_set_text(&app, CTL_FREQUENCY, text) != 0);
        watch_look(&w, &app, hear, &h);
        assert_int_equal(h.resonances, told[i]);
    }
    assert_non_null(strstr(h.last, "natural frequency 1 (0.7118 Hz"));
    app_free(&app);
}

static void refused_commands_change_nothing(void **state)
{
    (void)state;
    static struct app app;
    static struct config before;
    static const char *const opts[] = {"masses", "2", NULL, NULL};
    one_mass(&app, opts);
    const char *const bad[] = {"bogus", "set", "set nosuch 1", "set frequency abc",
                               "set frequency 0", "set dt 0.2", "set masses 11", "mode 3",
                               "run -0.5", "run 1001", "start now", "help bogus", "preset nosuch",
                               "back", "save"};
    static struct command_result res;
    const char *answer = res.answer;
    for (size_t i = 0; i < sizeof bad / sizeof *bad; i++) {
        memcpy(&before, &app.cfg, sizeof before);
        double t = sim_time(app.sim);
        assert_int_equal(command_do(&app, bad[i], &res), REPLY_ERROR);
        assert_memory_equal(&before, &app.cfg, sizeof before);
        assert_true(sim_time(app.sim) == t);
        assert_null(strchr(answer, '\n'));
        assert_true(strlen(answer) > 10);
    }
    assert_int_equal(command_do(&app, "set frequency 0.712", &res),
                     REPLY_OK);
    assert_true(app.model->motor.frequency == 0.712);
    assert_int_equal(command_do(&app, "  ", &res), REPLY_NONE);
    assert_int_equal(command_do(&app, "run 2.5", &res), REPLY_RUN);
    assert_true(res.seconds == 2.5);
    assert_int_equal(command_do(&app, "run 0", &res), REPLY_RUN); /* pauses, runs nothing */
    assert_true(res.seconds == 0.0);
    assert_int_equal(command_do(&app, "quit", &res), REPLY_QUIT);
    app_free(&app);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(one_peak_in_free_vibration),
        cmocka_unit_test(falling_peaks_of_a_free_decay),
        cmocka_unit_test(peaks_grow_to_the_steady_state_and_stop),
        cmocka_unit_test(contact_with_the_left_wall_when_it_is_reached),
        cmocka_unit_test(a_rattling_chain_is_told_in_bursts),
        cmocka_unit_test(drive_on_a_mode_within_two_percent),
        cmocka_unit_test(refused_commands_change_nothing),
    };
    return cmocka_run_group_tests_name("watch", tests, NULL, NULL);
}
