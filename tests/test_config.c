/* test_config.c: the settings table and what is made from it: the defaults, the
 * "expected ..." of every error, the interactive program's limits, the run-length bound,
 * and the escaping every message quotes user text through (issue 11). */
#include "testutil.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/config.h"

/* config_init puts every row's default in place, and the model gets the lists'. */
static void defaults_from_the_table(void **state)
{
    (void)state;
    static struct config c;
    config_init(&c);
    assert_int_equal(c.masses, (int)config_options[CFG_MASSES].def);
    assert_true(c.dt == config_options[CFG_DT].def && c.dt == 0.01);
    assert_true(c.amplitude == config_options[CFG_AMPLITUDE].def);
    assert_true(c.frequency == config_options[CFG_FREQUENCY].def);
    assert_true(c.duration == 10.0 && c.sample == 0.0);
    assert_int_equal(c.fps, 30);
    assert_int_equal(c.integrator, INTEGRATOR_RK4);
    assert_int_equal(c.boundary, BOUNDARY_MOTOR);
    assert_int_equal(c.wave, WAVE_SINE);
    int bad;
    char err[256];
    struct model *m = config_model(&c, &bad, err, sizeof err);
    assert_non_null(m);
    assert_true(m->m[1] == config_options[CFG_MASS].def);
    assert_true(m->k[2] == config_options[CFG_SPRING].def);
    assert_true(m->c[0] == config_options[CFG_DAMPING].def);
    model_free(m);
}

/* Every error's "expected ..." is made from the row. */
static void expected_texts(void **state)
{
    (void)state;
    static const struct {
        int key;
        const char *text;
    } cases[] = {
        {CFG_DT, "0 < dt <= 0.05"},
        {CFG_MASSES, "1 <= N <= 1000"},
        {CFG_FREQUENCY, "0 < frequency <= 1e6"},
        {CFG_AMPLITUDE, "0 <= amplitude <= 10"},
        {CFG_SAMPLE, "sample > 0 s"},
        {CFG_MASS, "masses > 0 kg: one value, or one per mass"},
        {CFG_SPRING, "springs >= 0 N/m: one value, or N+1"},
        {CFG_X0, "-10 <= displacements <= 10 m: one value, or one per mass"},
        {CFG_V0, "-50 <= velocities <= 50 m/s: one value, or one per mass"},
        {CFG_WAVE, "sine, square, triangle or sawtooth"},
        {CFG_SEED, "0 <= seed < 2^64"},
        {CFG_ENERGY, "true or false"},
        {CFG_WINDOW, "1 <= window <= 60"},
    };
    char buf[256];
    for (size_t i = 0; i < sizeof cases / sizeof *cases; i++) {
        config_expected(cases[i].key, buf, sizeof buf);
        if (strcmp(buf, cases[i].text) != 0)
            fail_msg("%s: '%s', expected '%s'", config_options[cases[i].key].name, buf,
                     cases[i].text);
    }
    /* Every key has a name config_find finds, and modes are no preset keys. */
    for (int k = 0; k < CFG_KEY_COUNT; k++) {
        assert_int_equal(config_find(config_options[k].name), k);
        if (config_options[k].kind == CONFIG_MODE)
            assert_null(config_options[k].section);
        config_help(k, buf, sizeof buf);
        assert_true(strlen(buf) > 0);
    }
}

/* The interactive program's N <= 10 and dt >= 0.001 come from the rows. */
/* --window: 1 to 60 s (the coarse samples reach 66 s back), 10 unless given; a bad value
 * says what was wrong and what is allowed, and changes nothing. */
static void window_range(void **state)
{
    (void)state;
    static struct config c;
    char err[256];
    config_init(&c);
    assert_true(c.window == 10.0);
    static const char *const good[] = {"1", "33", "60", "2.5"};
    for (size_t i = 0; i < sizeof good / sizeof *good; i++) {
        assert_int_equal(config_set(&c, CFG_WINDOW, good[i], err, sizeof err), 0);
        assert_true(c.window == strtod(good[i], NULL));
    }
    static const struct {
        const char *value, *err;
    } bad[] = {
        {"0.99", "'0.99' is out of range (expected 1 <= window <= 60)"},
        {"60.5", "'60.5' is out of range (expected 1 <= window <= 60)"},
        {"-33", "'-33' is out of range (expected 1 <= window <= 60)"},
        {"33s", "'33s' is not a number (expected 1 <= window <= 60)"},
        {"inf", "'inf' is not a finite number (expected 1 <= window <= 60)"},
    };
    for (size_t i = 0; i < sizeof bad / sizeof *bad; i++) {
        assert_int_equal(config_set(&c, CFG_WINDOW, bad[i].value, err, sizeof err), -1);
        assert_string_equal(err, bad[i].err);
        assert_true(c.window == 2.5);
    }
    /* The longest window is what the interactive program's coarse samples cover. */
    assert_true(config_options[CFG_WINDOW].hi == CONFIG_WINDOW_MAX);
}

static void interactive_limits(void **state)
{
    (void)state;
    static struct config c;
    char err[256];
    config_init(&c);
    assert_int_equal(config_check_interactive(&c, err, sizeof err), -1);
    c.dt = 0.0009;
    assert_int_equal(config_check_interactive(&c, err, sizeof err), CFG_DT);
    assert_non_null(strstr(err, "0.001 <= dt <= 0.05"));
    c.dt = 0.001;
    assert_int_equal(config_check_interactive(&c, err, sizeof err), -1);
    c.masses = CONFIG_INTERACTIVE_MAX_MASSES + 1;
    assert_int_equal(config_check_interactive(&c, err, sizeof err), CFG_MASSES);
    assert_non_null(strstr(err, "1 <= N <= 10"));
}

/* Runs over 1e12 steps are refused, whichever of duration and dt makes them so. */
static void run_length(void **state)
{
    (void)state;
    static struct config c;
    char err[256];
    config_init(&c);
    assert_int_equal(config_check_steps(&c, err, sizeof err), -1);
    c.duration = 1e300;
    assert_int_equal(config_check_steps(&c, err, sizeof err), CFG_DURATION);
    assert_non_null(strstr(err, "steps"));
    c.duration = 10.0;
    c.dt = 1e-320;
    assert_int_equal(config_check_steps(&c, err, sizeof err), CFG_DT);
    assert_null(strstr(err, "inf"));
}

/* Control bytes escaped, UTF-8 kept, invalid bytes and C1 controls as \xNN, long values
 * cut. */
static void escaping(void **state)
{
    (void)state;
    char buf[512];
    config_quote("\033]0;X\a", 6, buf, sizeof buf);
    assert_string_equal(buf, "'\\x1b]0;X\\a'");
    config_quote("a\nb\tc\x7f", 6, buf, sizeof buf);
    assert_string_equal(buf, "'a\\nb\\tc\\x7f'");
    config_quote("N·s/m \xc2\x9b \xff", 11, buf, sizeof buf);
    assert_string_equal(buf, "'N·s/m \\xc2\\x9b \\xff'");
    char big[200];
    memset(big, 'x', sizeof big - 1);
    big[sizeof big - 1] = '\0';
    config_quote(big, strlen(big), buf, sizeof buf);
    assert_true(strlen(buf) < CONFIG_QUOTE_MAX + 40);
    assert_non_null(strstr(buf, "...' (199 characters)"));
    double v;
    assert_null(config_parse_number("-0", &v));
    assert_false(signbit(v));
    assert_non_null(config_parse_number(" 1", &v));
    assert_non_null(config_parse_number("\n1", &v));
    assert_non_null(config_parse_number("1\n", &v));
}

/* Reads back a command line as config_write_args writes it (" --name value" or " --name"
 * for a flag, no blank inside a value) into c, which starts at the defaults. */
static void read_args(char *line, struct config *c)
{
    char err[256];
    config_init(c);
    for (char *w = strtok(line, " "); w; w = strtok(NULL, " ")) {
        assert_true(w[0] == '-' && w[1] == '-');
        int k = config_find(w + 2);
        assert_true(k >= 0);
        const char *value = config_takes_value(k) ? strtok(NULL, " ") : NULL;
        if (config_set(c, k, value, err, sizeof err) != 0)
            fail_msg("--%s %s: %s", w + 2, value ? value : "", err);
    }
}

/* The two configurations make the same run: the same chain, drive, start and settings. */
static void assert_same_run(const struct config *a, const struct config *b)
{
    int bad;
    char err[256];
    struct model *ma = config_model(a, &bad, err, sizeof err);
    struct model *mb = config_model(b, &bad, err, sizeof err);
    assert_non_null(ma);
    assert_non_null(mb);
    int n = ma->n;
    assert_int_equal(mb->n, n);
    for (int i = 0; i <= n; i++) {
        assert_true(ma->k[i] == mb->k[i]);
        if (i < n)
            assert_true(ma->m[i] == mb->m[i] && ma->c[i] == mb->c[i]);
    }
    assert_int_equal(ma->boundary, mb->boundary);
    assert_int_equal(ma->collisions, mb->collisions);
    assert_int_equal(ma->motor.wave, mb->motor.wave);
    assert_true(ma->motor.amplitude == mb->motor.amplitude);
    assert_true(ma->motor.frequency == mb->motor.frequency);
    double xa[2 * 8], xb[2 * 8];
    assert_true(n <= 8);
    config_initial(a, ma, xa, xa + n);
    config_initial(b, mb, xb, xb + n);
    assert_memory_equal(xa, xb, 2 * (size_t)n * sizeof *xa);
    assert_true(a->dt == b->dt && a->duration == b->duration && a->sample == b->sample);
    assert_int_equal(a->integrator, b->integrator);
    assert_int_equal(a->energy, b->energy);
    assert_int_equal(a->fps, b->fps);
    assert_int_equal(a->low_bandwidth, b->low_bandwidth);
    assert_int_equal(a->random, b->random);
    assert_int_equal(a->start_mode, b->start_mode);
    if (a->start_mode)
        assert_true(a->start_amp == b->start_amp);
    if (a->random)
        assert_true(a->seed == b->seed);
    model_free(ma);
    model_free(mb);
}

/* --meta's command line: written from the table, read back by the options it names, it
 * makes the same run (numbers exact to the last bit, random positions from the same seed),
 * and it never names the preset, the output or a mode. */
static void args_round_trip(void **state)
{
    (void)state;
    static const char *const cases[][2 * 12 + 1] = {
        {NULL},
        {"masses", "3", "mass", "1,2.5,0.1", "spring", "7.3", "damping", "0,0.3333333333333333,1e-300",
         "dt", "0.003", "integrator", "exact", "boundary", "free", "wave", "sawtooth",
         "amplitude", "0.1", "frequency", "1e-7", "x0", "-0.5,0.25,0.1", "v0", "2", NULL},
        {"masses", "2", "random", NULL, "seed", "18446744073709551615", "no-collisions", NULL,
         "duration", "12.5", "sample", "0.1", "energy", NULL, "fps", "12", "low-bandwidth", NULL,
         "spring", "1,2,3", "v0", "-1,1", NULL},
        {"masses", "4", "x0", "0.3", "random", NULL, NULL}, /* random after x0: random */
        {"masses", "4", "random", NULL, "x0", "0.3", NULL}, /* x0 after random: x0 */
        {"masses", "3", "mass", "1,2,0.5", "random", NULL, "start-mode", "2:0.3", NULL},
        {"masses", "3", "start-mode", "3", "v0", "0.1", NULL}, /* v0 after it: v0 */
    };
    for (size_t t = 0; t < sizeof cases / sizeof *cases; t++) {
        static struct config a, b;
        char err[256];
        config_init(&a);
        for (int i = 0; cases[t][i]; i += 2) {
            int k = config_find(cases[t][i]);
            assert_true(k >= 0);
            if (config_set(&a, k, cases[t][i + 1], err, sizeof err) != 0)
                fail_msg("%s: %s", cases[t][i], err);
        }
        if (a.random && !a.seed_set)
            a.seed = 987654321; /* what main chooses */
        a.output = "out.csv";
        char *line = NULL;
        size_t size = 0;
        FILE *mem = open_memstream(&line, &size);
        assert_non_null(mem);
        assert_int_equal(config_write_args(mem, &a), 0);
        assert_int_equal(fclose(mem), 0);
        assert_null(strstr(line, "--output"));
        assert_null(strstr(line, "--preset"));
        assert_null(strstr(line, "--headless"));
        assert_null(strchr(line, '\n'));
        read_args(line, &b);
        assert_same_run(&a, &b);
        free(line);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(defaults_from_the_table),
        cmocka_unit_test(expected_texts),
        cmocka_unit_test(window_range),
        cmocka_unit_test(interactive_limits),
        cmocka_unit_test(run_length),
        cmocka_unit_test(escaping),
        cmocka_unit_test(args_round_trip),
    };
    return cmocka_run_group_tests_name("config", tests, NULL, NULL);
}
