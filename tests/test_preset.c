/* test_preset.c: the value checks shared by options and presets, every built-in preset
 * loading and really showing what its name says (checked against the model's own
 * natural frequencies), a written preset reading back to the same model, the syntax the
 * parser refuses, what the search path reads, and the names presets and exports are
 * saved under. */
#include "testutil.h"

#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "app/app.h"
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
    assert_int_equal(config_set(&c, CFG_SPRING, "-1", err, sizeof err), -1);
    assert_int_equal(config_set(&c, CFG_SPRING, "0", err, sizeof err), 0); /* no spring */
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
    /* It opens on a window of three whole beats (of 1 / |f - f1| each), not a fourth. */
    double beat = 1.0 / fabs(m->motor.frequency - first_mode(m));
    assert_true(c.window >= 3.0 * beat && c.window < 3.5 * beat);
    model_free(m);
    m = load("resonance", &c);
    assert_true(c.window == config_options[CFG_WINDOW].def); /* a preset without one: 10 s */
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

/* Writes c (and m, made from it) as a preset file and reads it back into back. */
static void write_and_read(const struct config *c, const struct model *m, struct config *back)
{
    char path[] = "/tmp/springsim-test-XXXXXX", err[512];
    int fd = mkstemp(path);
    FILE *f = fdopen(fd, "w");
    assert_int_equal(preset_write(f, c, m), 0);
    fclose(f);
    config_init(back);
    enum preset_status st = preset_load(path, back, err, sizeof err);
    unlink(path);
    if (st != PRESET_OK)
        fail_msg("%s", err);
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
    assert_int_equal(config_set(&c, CFG_WINDOW, "32.5", err, sizeof err), 0);
    struct model *m = config_model(&c, &bad, err, sizeof err);
    assert_non_null(m);

    write_and_read(&c, m, &back);
    assert_true(back.window == 32.5);
    assert_int_not_equal(back.origin[CFG_WINDOW].line, 0); /* written, not the default */
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

/* A value of key's other than its default, inside its range (a list: one per element,
 * all different), as text config_set takes. */
static void other_value(int key, int n, char *buf, size_t len)
{
    const struct config_option *o = &config_options[key];
    double lo = isfinite(o->lo) ? o->lo : -1.0, hi = isfinite(o->hi) ? o->hi : lo + 10.0;
    switch (o->kind) {
    case CONFIG_NUMBER:
        snprintf(buf, len, "%.17g", lo + 0.37 * (hi - lo));
        return;
    case CONFIG_WHOLE:
        snprintf(buf, len, "%s", key == CFG_SEED ? "18446744073709551557" : "3");
        return;
    case CONFIG_LIST: {
        size_t used = 0;
        int count = o->per == CONFIG_PER_SPRING ? n + 1 : n;
        for (int i = 0; i < count; i++)
            used += (size_t)snprintf(buf + used, len - used, "%s%.17g", i ? "," : "",
                                     fmax(lo, 0.0) + 0.3 + 0.25 * i);
        return;
    }
    case CONFIG_CHOICE:
        snprintf(buf, len, "%s", o->choice_name(((int)o->def + 1) % o->choices));
        return;
    case CONFIG_FLAG:
        snprintf(buf, len, "true");
        return;
    default: /* start-mode, the one text row saved */
        snprintf(buf, len, "2:0.25");
        return;
    }
}

/* Whether c and back (and the models made of them) have the same value for key. */
static bool same_value(int key, const struct config *c, const struct model *m,
                       const struct config *back, const struct model *m2)
{
    struct config_value a, b;
    config_get(key, c, m, &a);
    config_get(key, back, m2, &b);
    if (a.count != b.count)
        return false;
    if (a.count == 0)
        return strcmp(a.str, b.str) == 0;
    return memcmp(a.v, b.v, (size_t)a.count * sizeof *a.v) == 0;
}

/* Every row of the table a saved preset writes reads back the same, each set in turn to
 * a value other than its default, and every other row in force with it: a row added to
 * the table is saved with no more code. */
static void every_saved_row_round_trips(void **state)
{
    (void)state;
    static struct config c, back;
    char err[512], value[512];
    int bad, rows = 0;
    for (int k = 0; k < CFG_KEY_COUNT; k++) {
        if (!config_options[k].saved)
            continue;
        assert_non_null(config_options[k].section); /* a preset key */
        rows++;
        config_init(&c);
        config_set(&c, CFG_MASSES, "3", err, sizeof err);
        other_value(k, 3, value, sizeof value);
        if (k == CFG_SEED) /* in force with random positions */
            config_set(&c, CFG_RANDOM, NULL, err, sizeof err);
        if (config_set(&c, k, value, err, sizeof err) != 0)
            fail_msg("%s = %s: %s", config_options[k].name, value, err);
        assert_true(config_in_force(k, &c));
        struct model *m = config_model(&c, &bad, err, sizeof err);
        if (!m)
            fail_msg("%s = %s: %s", config_options[k].name, value, err);
        write_and_read(&c, m, &back);
        struct model *m2 = config_model(&back, &bad, err, sizeof err);
        assert_non_null(m2);
        struct config_value was;
        config_init(&back); /* what the default would read: the value set is not it */
        config_get(k, &back, NULL, &was);
        write_and_read(&c, m, &back);
        for (int j = 0; j < CFG_KEY_COUNT; j++)
            if (config_options[j].saved && config_in_force(j, &c)) {
                assert_true(config_in_force(j, &back));
                if (!same_value(j, &c, m, &back, m2))
                    fail_msg("%s set to %s: %s does not read back the same",
                             config_options[k].name, value, config_options[j].name);
            }
        struct config_value now;
        config_get(k, &back, NULL, &now);
        assert_false(now.count == was.count && (now.count ? now.v[0] == was.v[0]
                                                          : strcmp(now.str, was.str) == 0));
        model_free(m);
        model_free(m2);
    }
    assert_int_equal(rows, 21);
}

/* A start along a mode is written back as start-mode = K:AMP and read back the same;
 * the later of x0, v0, random and start-mode wins. */
static void start_mode_round_trip(void **state)
{
    (void)state;
    static struct config c, back;
    char err[512];
    int bad;
    config_init(&c);
    config_set(&c, CFG_MASSES, "3", err, sizeof err);
    assert_int_equal(config_set(&c, CFG_RANDOM, NULL, err, sizeof err), 0);
    assert_int_equal(config_set(&c, CFG_V0, "0.2", err, sizeof err), 0);
    assert_int_equal(config_set(&c, CFG_START_MODE, "3:0.1234567890123", err, sizeof err), 0);
    assert_false(c.random);
    assert_int_equal(c.v0.count, 0);
    struct model *m = config_model(&c, &bad, err, sizeof err);
    assert_non_null(m);
    write_and_read(&c, m, &back);
    assert_int_equal(back.start_mode, 3);
    assert_true(back.start_amp == 0.1234567890123);
    double x[3], v[3], want[3];
    assert_int_equal(config_initial(&back, m, x, v), 0);
    assert_int_equal(modes_start(m, 3, 0.1234567890123, want), 0);
    assert_memory_equal(x, want, sizeof x);
    for (int i = 0; i < 3; i++)
        assert_true(v[i] == 0.0);
    /* x0 after it wins, and so does random. */
    assert_int_equal(config_set(&back, CFG_X0, "0.1", err, sizeof err), 0);
    assert_int_equal(back.start_mode, 0);
    assert_int_equal(config_set(&back, CFG_START_MODE, "1", err, sizeof err), 0);
    assert_true(back.start_mode == 1 && back.start_amp == CONFIG_START_AMP);
    assert_int_equal(back.x0.count, 0);
    assert_int_equal(config_set(&back, CFG_RANDOM, NULL, err, sizeof err), 0);
    assert_int_equal(back.start_mode, 0);
    /* K above N is found with the chain. */
    assert_int_equal(config_set(&back, CFG_START_MODE, "4", err, sizeof err), 0);
    assert_null(config_model(&back, &bad, err, sizeof err));
    assert_int_equal(bad, CFG_START_MODE);
    assert_non_null(strstr(err, "1 <= K <= 3"));
    model_free(m);
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

/* Parses text as the preset "t.ini"; returns the status, the message in err. */
static enum preset_status parse(const char *text, struct config *c, char *err, size_t len)
{
    config_init(c);
    err[0] = '\0';
    return preset_parse("t.ini", text, strlen(text), c, err, len);
}

/* Fails unless err contains want. */
static void assert_says(const char *err, const char *want)
{
    if (!strstr(err, want))
        fail_msg("expected '%s' in: %s", want, err);
}

/* Syntax that inih would let through: text after a section header, CR-only line ends;
 * an over-long line names its key. */
static void syntax_refused(void **state)
{
    (void)state;
    static struct config c;
    char err[600];
    assert_int_equal(parse("[system] junk\nmass = 2\n", &c, err, sizeof err), PRESET_BAD);
    assert_says(err, "t.ini:1: text after the section header [system]");
    assert_int_equal(parse("[system]junk]\nmass = 2\n", &c, err, sizeof err), PRESET_BAD);
    assert_int_equal(parse("[system] ; a comment\nmass = 2\n", &c, err, sizeof err), PRESET_OK);
    assert_int_equal(parse("[system]\t# a comment\nmass = 2\n", &c, err, sizeof err), PRESET_OK);
    /* A lone CR ends a line; CR LF still reads as one line end. */
    assert_int_equal(parse("[system]\rmass = abc\r", &c, err, sizeof err), PRESET_BAD);
    assert_says(err, "t.ini:2: mass: 'abc' is not a number");
    assert_int_equal(parse("[system]\rmasses = 3\rmass = 2.5\r", &c, err, sizeof err), PRESET_OK);
    assert_int_equal(c.masses, 3);
    assert_close(c.mass.v[0], 2.5, 0.0);
    assert_int_equal(parse("[system]\r\nmass = 1,\r\n  2\r\n", &c, err, sizeof err), PRESET_OK);
    assert_int_equal(c.mass.count, 2);
    assert_int_equal(parse("[system]\r\rmass = x\r", &c, err, sizeof err), PRESET_BAD);
    assert_says(err, "t.ini:3: mass:");
    /* 5,000 digits: the key is named, and how a list goes on. */
    char text[6000];
    int n = snprintf(text, sizeof text, "[system]\nmass = ");
    memset(text + n, '9', 5000);
    strcpy(text + n + 5000, "\n");
    assert_int_equal(parse(text, &c, err, sizeof err), PRESET_BAD);
    assert_says(err, "t.ini:2: line is longer than 198 characters, in the value of 'mass'");
    assert_says(err, "indented lines");
    n = snprintf(text, sizeof text, "[initial]\nx0 = 1,\n    ");
    memset(text + n, '1', 300);
    strcpy(text + n + 300, "\n");
    assert_int_equal(parse(text, &c, err, sizeof err), PRESET_BAD);
    assert_says(err, "t.ini:3: line is longer than 198 characters, in a continuation of 'x0'");
}

/* A path over the buffer is refused, never cut to another file's name. */
static void long_path_refused(void **state)
{
    (void)state;
    char name[5000], out[4096];
    memset(name, 'a', sizeof name);
    memcpy(name, "/tmp/", 5);
    strcpy(name + sizeof name - 5, ".ini");
    assert_int_equal(preset_find(name, NULL, out, sizeof out), PRESET_NONE);
    assert_says(out, "too long");
    /* Exactly fitting: taken as it is. */
    name[sizeof out - 5] = '\0';
    strcat(name, ".ini");
    assert_int_equal(strlen(name), sizeof out - 1);
    assert_int_equal(preset_find(name, NULL, out, sizeof out), PRESET_OK);
    assert_string_equal(out, name);
}

/* FIFOs, devices and huge files in a preset directory are neither listed nor read: both
 * would block or never end. */
static void only_regular_files(void **state)
{
    (void)state;
    char dir[] = "/tmp/springsim-scan-XXXXXX", path[600], err[600];
    static struct config c;
    assert_non_null(mkdtemp(dir));
    snprintf(path, sizeof path, "%s/fifo.ini", dir);
    assert_int_equal(mkfifo(path, 0600), 0);
    config_init(&c);
    assert_int_equal(preset_load(path, &c, err, sizeof err), PRESET_IO);
    assert_says(err, "not a regular file");
    snprintf(path, sizeof path, "%s/zero.ini", dir);
    assert_int_equal(symlink("/dev/zero", path), 0);
    assert_int_equal(preset_load(path, &c, err, sizeof err), PRESET_IO);
    assert_says(err, "not a regular file");
    snprintf(path, sizeof path, "%s/huge.ini", dir);
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    fclose(f);
    assert_int_equal(truncate(path, 2000000000), 0);
    assert_int_equal(preset_load(path, &c, err, sizeof err), PRESET_BAD);
    assert_says(err, "too large for a preset");
    snprintf(path, sizeof path, "%s/good.ini", dir);
    f = fopen(path, "w");
    assert_non_null(f);
    fputs("[preset]\ndescription = A good one\n", f);
    fclose(f);

    setenv("SPRINGSIM_PRESETS", dir, 1);
    setenv("XDG_CONFIG_HOME", dir, 1); /* no springsim/presets under it */
    struct search_entry *all;
    int have = preset_scan(NULL, &all), good = 0;
    for (int i = 0; i < have; i++) {
        if (strcmp(all[i].name, "fifo") == 0 || strcmp(all[i].name, "zero") == 0 ||
            strcmp(all[i].name, "huge") == 0)
            fail_msg("preset_scan listed %s", all[i].path);
        if (strcmp(all[i].name, "good") == 0)
            good = strcmp(all[i].about, "A good one") == 0;
    }
    free(all);
    assert_true(good);
    unsetenv("SPRINGSIM_PRESETS");
    unsetenv("XDG_CONFIG_HOME");
    const char *names[] = {"fifo", "zero", "huge", "good"};
    for (int i = 0; i < 4; i++) {
        snprintf(path, sizeof path, "%s/%s.ini", dir, names[i]);
        unlink(path);
    }
    rmdir(dir);
}

/* Saved names: ASCII only, said clearly; "x.ini" is the file x.ini, loaded by -p x.
 * Exports in the same second each get a file of their own. */
static void saved_names(void **state)
{
    (void)state;
    static struct config c;
    static struct app app;
    char dir[] = "/tmp/springsim-save-XXXXXX", path[4200], found[4200];
    assert_non_null(mkdtemp(dir));
    setenv("XDG_CONFIG_HOME", dir, 1);
    config_init(&c);
    assert_int_equal(app_init(&app, &c, NULL), 0);

    assert_int_equal(app_save(&app, "r\xc3\xa9sum\xc3\xa9", false), SAVE_BAD_NAME);
    assert_int_equal(app.said, SAID_ERROR);
    assert_says(app.message, "ASCII");
    snprintf(path, sizeof path, "%s/springsim/presets/rsum.ini", dir);
    assert_int_equal(access(path, F_OK), -1);

    assert_int_equal(app_save(&app, "x.ini", false), SAVE_OK);
    assert_says(app.message, "springsim -p x loads it");
    snprintf(path, sizeof path, "%s/springsim/presets/x.ini", dir);
    assert_int_equal(access(path, F_OK), 0);
    assert_int_equal(preset_find("x", NULL, found, sizeof found), PRESET_OK);
    assert_string_equal(found, path);
    assert_string_equal(app.preset, "x");
    assert_int_equal(app_save(&app, "x.ini", false), SAVE_EXISTS);
    assert_int_equal(app_save(&app, "x", false), SAVE_EXISTS);
    assert_int_equal(app_save(&app, "x.ini.ini", false), SAVE_BAD_NAME);
    snprintf(found, sizeof found, "%s/springsim/presets/x.ini.ini", dir);
    assert_int_equal(access(found, F_OK), -1);
    unlink(path);

    /* Three exports at once: three files. */
    char a[4200], b[4200], d[4200];
    for (int i = 0; i < 5; i++)
        app_step(&app);
    assert_true(app_export(&app, dir, a, sizeof a));
    assert_true(app_export(&app, dir, b, sizeof b));
    assert_true(app_export(&app, dir, d, sizeof d));
    assert_true(strcmp(a, b) != 0 && strcmp(b, d) != 0 && strcmp(a, d) != 0);
    assert_int_equal(access(a, F_OK) | access(b, F_OK) | access(d, F_OK), 0);
    unlink(a), unlink(b), unlink(d);
    app_free(&app);
    snprintf(path, sizeof path, "%s/springsim/presets", dir);
    rmdir(path);
    snprintf(path, sizeof path, "%s/springsim", dir);
    rmdir(path);
    rmdir(dir);
    unsetenv("XDG_CONFIG_HOME");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(value_checks),
        cmocka_unit_test(builtin_presets_show_their_names),
        cmocka_unit_test(write_read_round_trip),
        cmocka_unit_test(start_mode_round_trip),
        cmocka_unit_test(every_saved_row_round_trips),
        cmocka_unit_test(random_positions),
        cmocka_unit_test(syntax_refused),
        cmocka_unit_test(long_path_refused),
        cmocka_unit_test(only_regular_files),
        cmocka_unit_test(saved_names),
    };
    return cmocka_run_group_tests_name("preset", tests, NULL, NULL);
}
