/* test_config.c: the settings table and what is made from it: the defaults, the
 * "expected ..." of every error, the interactive program's limits, the run-length bound,
 * and the escaping every message quotes user text through (issue 11). */
#include "testutil.h"

#include <math.h>
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
        {CFG_AMPLITUDE, "amplitude >= 0 m"},
        {CFG_SAMPLE, "sample > 0 s"},
        {CFG_MASS, "masses > 0 kg: one value, or one per mass"},
        {CFG_SPRING, "springs > 0 N/m: one value, or N+1"},
        {CFG_X0, "displacements in m: one value, or one per mass"},
        {CFG_WAVE, "sine, square, triangle or sawtooth"},
        {CFG_SEED, "0 <= seed < 2^64"},
        {CFG_ENERGY, "true or false"},
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

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(defaults_from_the_table),
        cmocka_unit_test(expected_texts),
        cmocka_unit_test(interactive_limits),
        cmocka_unit_test(run_length),
        cmocka_unit_test(escaping),
    };
    return cmocka_run_group_tests_name("config", tests, NULL, NULL);
}
