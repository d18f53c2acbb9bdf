/* test_preset.c: the value checks shared by options and presets, every built-in preset
 * loading and really showing what its name says (checked against the model's own
 * natural frequencies), and a written preset reading back to the same model. */
#include "testutil.h"

#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "core/modes.h"
#include "core/preset.h"

#define PRESETS SRCDIR "/presets/"

static void value_checks(void **state)
{
    (void)state;
    static struct config c;
    char err[512];
    config_init(&c);
    assert_int_equal(config_set(&c, CFG_DT, "abc", err, sizeof err), -1);
    assert_string_equal(err, "'abc' is not a number (expected 0 < dt <= 0.05)");
    assert_int_equal(config_set(&c, CFG_DT, "0.01x", err, sizeof err), -1);
    assert_int_equal(config_set(&c, CFG_DT, "nan", err, sizeof err), -1);
    assert_non_null(strstr(err, "not a finite number"));
    assert_int_equal(config_set(&c, CFG_DT, "0.06", err, sizeof err), -1);
    assert_non_null(strstr(err, "out of range"));
    assert_int_equal(config_set(&c, CFG_DT, "0.05", err, sizeof err), 0);
    assert_close(c.dt, 0.05, 0.0);
    assert_int_equal(config_set(&c, CFG_MASSES, "2.5", err, sizeof err), -1);
    assert_non_null(strstr(err, "not a whole number"));
    assert_int_equal(config_set(&c, CFG_MASS, "1,,2", err, sizeof err), -1);
    assert_int_equal(config_set(&c, CFG_MASS, "1, 2 ,3", err, sizeof err), 0);
    assert_int_equal(c.mass.count, 3);
    assert_close(c.mass.v[1], 2.0, 0.0);
    assert_int_equal(config_set(&c, CFG_DAMPING, "0", err, sizeof err), 0);
    assert_int_equal(config_set(&c, CFG_SPRING, "0", err, sizeof err), -1);
    assert_int_equal(config_set(&c, CFG_X0, "-0.5", err, sizeof err), 0);
    assert_int_equal(config_set(&c, CFG_WAVE, "Square", err, sizeof err), -1);
    assert_string_equal(err, "'Square' is not a waveform (expected sine, square, triangle "
                             "or sawtooth)");
    /* A failed set leaves the old value. */
    assert_close(c.dt, 0.05, 0.0);
    /* Long values are cut so the message stays one line. */
    char big[300];
    memset(big, '7', sizeof big - 1);
    big[sizeof big - 1] = '\0';
    big[5] = 'x';
    assert_int_equal(config_set(&c, CFG_AMPLITUDE, big, err, sizeof err), -1);
    assert_true(strlen(err) < 120);
    /* List lengths are checked once N is known. */
    config_init(&c);
    config_set(&c, CFG_MASSES, "3", err, sizeof err);
    config_set(&c, CFG_SPRING, "1,2,3", err, sizeof err);
    int bad;
    assert_null(config_model(&c, &bad, err, sizeof err));
    assert_int_equal(bad, CFG_SPRING);
    assert_string_equal(err, "'1,2,3' has 3 values for 4 springs (expected 1 or 4)");
}

static struct model *load(const char *name, struct config *c)
{
    char err[512], path[4096];
    int bad;
    snprintf(path, sizeof path, PRESETS "%s.ini", name);
    config_init(c);
    enum preset_status st = preset_load(path, c, err, sizeof err);
    if (st != PRESET_OK)
        fail_msg("%s", err);
    struct model *m = config_model(c, &bad, err, sizeof err);
    if (!m)
        fail_msg("%s: %s", name, err);
    return m;
}

static double first_mode(const struct model *m)
{
    double f[16];
    assert_int_equal(modes_compute(m, f, NULL), 0);
    return f[0];
}

static double last_mode(const struct model *m)
{
    double f[16];
    assert_int_equal(modes_compute(m, f, NULL), 0);
    return f[m->n - 1];
}

/* Each of the page's eleven presets, and collisions, exists, loads, describes itself and
 * shows its phenomenon by the model's own numbers. */
static void builtin_presets_show_their_names(void **state)
{
    (void)state;
    static struct config c;
    struct model *m;

    m = load("resonance", &c);
    assert_int_equal(m->n, 1);
    assert_close(m->motor.frequency, first_mode(m), 1e-5); /* 0.712 Hz, not 0.50 */
    assert_close(m->motor.frequency, sqrt(2 * m->k[0] / m->m[0]) / (2 * M_PI), 1e-5);
    assert_true(c.name[0] && c.description[0]);
    model_free(m);

    m = load("beating", &c);
    double off = fabs(m->motor.frequency - first_mode(m)) / first_mode(m);
    assert_true(off > 0.02 && off < 0.25); /* close, not equal: beats of a few seconds */
    assert_true(m->c[0] < 0.05);           /* little damping, so the beats persist */
    model_free(m);

    m = load("low-frequency", &c);
    assert_true(m->motor.frequency < first_mode(m) / 3.0);
    model_free(m);

    m = load("high-frequency", &c);
    assert_true(m->motor.frequency > 2.0 * last_mode(m));
    double amp[16];
    modes_response(m, m->motor.frequency, amp);
    assert_true(amp[m->n - 1] < 0.1 * m->motor.amplitude); /* attenuated */
    model_free(m);

    m = load("heavy-damping", &c);
    assert_true(m->c[0] >= 1.0);
    model_free(m);

    m = load("no-damping", &c);
    for (int i = 0; i < m->n; i++)
        assert_close(m->c[i], 0.0, 0.0);
    assert_int_equal(m->boundary, BOUNDARY_WALL); /* nothing gives or takes energy */
    model_free(m);

    m = load("square-wave", &c);
    assert_int_equal(m->motor.wave, WAVE_SQUARE);
    model_free(m);

    m = load("triangle-wave", &c);
    assert_int_equal(m->motor.wave, WAVE_TRIANGLE);
    assert_true(m->motor.frequency < first_mode(m) / 5.0); /* far below mode 1 */
    /* corners that do not ring: mode 1's damping ratio c / (2 m w1) at least 0.5 */
    assert_true(m->c[0] / (2 * m->m[0] * 2 * M_PI * first_mode(m)) >= 0.5);
    model_free(m);

    m = load("3-mass-chain", &c);
    assert_int_equal(m->n, 3);
    model_free(m);

    m = load("soft-springs", &c);
    assert_true(m->k[0] < 10.0);
    model_free(m);

    m = load("stiff-springs", &c);
    assert_true(m->k[0] > 10.0);
    model_free(m);

    m = load("collisions", &c);
    assert_true(m->collisions);
    assert_int_equal(m->boundary, BOUNDARY_MOTOR);
    assert_close(m->motor.frequency, first_mode(m), 1e-5); /* driven at mode 1 */
    assert_true(c.name[0] && c.description[0]);
    model_free(m);
}

/* A config with per-element values written out and read back gives the same model. */
static void write_read_round_trip(void **state)
{
    (void)state;
    static struct config c, back;
    char err[512];
    int bad;
    config_init(&c);
    strcpy(c.name, "Round trip");
    strcpy(c.description, "per-element values");
    config_set(&c, CFG_MASSES, "40", err, sizeof err);
    char list[2048] = "";
    for (int i = 0; i < 41; i++)
        snprintf(list + strlen(list), sizeof list - strlen(list), "%s%.17g", i ? "," : "",
                 1.0 / 3.0 + i * 0.1);
    assert_int_equal(config_set(&c, CFG_SPRING, list, err, sizeof err), 0);
    assert_int_equal(config_set(&c, CFG_MASS, "2.5", err, sizeof err), 0);
    list[0] = '\0';
    for (int i = 0; i < 40; i++)
        snprintf(list + strlen(list), sizeof list - strlen(list), "%s%g", i ? "," : "",
                 -0.01 * i);
    assert_int_equal(config_set(&c, CFG_X0, list, err, sizeof err), 0);
    config_set(&c, CFG_WAVE, "sawtooth", err, sizeof err);
    config_set(&c, CFG_BOUNDARY, "free", err, sizeof err);
    config_set(&c, CFG_NO_COLLISIONS, NULL, err, sizeof err);
    config_set(&c, CFG_DT, "0.0125", err, sizeof err);
    struct model *m = config_model(&c, &bad, err, sizeof err);
    assert_non_null(m);

    char path[] = "/tmp/springsim-test-XXXXXX";
    int fd = mkstemp(path);
    FILE *f = fdopen(fd, "w");
    assert_int_equal(preset_write(f, &c, m), 0);
    fclose(f);
    config_init(&back);
    enum preset_status st = preset_load(path, &back, err, sizeof err);
    if (st != PRESET_OK)
        fail_msg("%s", err);
    unlink(path);
    struct model *m2 = config_model(&back, &bad, err, sizeof err);
    assert_non_null(m2);
    assert_int_equal(m2->n, 40);
    assert_memory_equal(m->m, m2->m, 40 * sizeof(double));
    assert_memory_equal(m->k, m2->k, 41 * sizeof(double));
    assert_memory_equal(m->c, m2->c, 40 * sizeof(double));
    assert_int_equal(m2->boundary, BOUNDARY_FREE);
    assert_int_equal(m2->motor.wave, WAVE_SAWTOOTH);
    assert_false(m2->collisions);
    assert_close(back.dt, 0.0125, 0.0);
    assert_string_equal(back.name, "Round trip");
    double x[40], v[40], x2[40], v2[40];
    config_initial(&c, m, x, v);
    config_initial(&back, m2, x2, v2);
    assert_memory_equal(x, x2, sizeof x);
    model_free(m);
    model_free(m2);
}

/* Random positions: reproducible from the seed, inside the walls, blocks apart. */
static void random_positions(void **state)
{
    (void)state;
    for (int n = 1; n <= 10; n++) {
        struct model *m = model_new(n);
        double a[10], b[10], w = model_block_width(m);
        config_random_positions(m, 42, a);
        config_random_positions(m, 42, b);
        assert_memory_equal(a, b, (size_t)n * sizeof *a);
        config_random_positions(m, 43, b);
        assert_true(memcmp(a, b, (size_t)n * sizeof *a) != 0);
        for (int i = 0; i < n; i++) {
            double X = model_equilibrium(m, i) + a[i];
            assert_true(X >= 0.5 * w && X <= 10.0 - 0.5 * w);
            if (i)
                assert_true(X - (model_equilibrium(m, i - 1) + a[i - 1]) >= 1.5 * w - 1e-12);
        }
        model_free(m);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(value_checks),
        cmocka_unit_test(builtin_presets_show_their_names),
        cmocka_unit_test(write_read_round_trip),
        cmocka_unit_test(random_positions),
    };
    return cmocka_run_group_tests_name("preset", tests, NULL, NULL);
}
