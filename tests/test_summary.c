/* test_summary.c: the one-row summary of a headless run (--summary) against independent
 * answers: a single undamped mass's closed forms (max |x| = |x0|, rms over whole periods
 * = |x0|/sqrt 2, max |v| = w |x0|), the damping's books against the mechanical energy
 * lost, the contacts against the event-driven reference (contact_reference.h) on the
 * collisions preset's chain, and the row's shape: one field per header column, lists
 * quoted. */
#include "testutil.h"

#include <stdlib.h>
#include <string.h>

#include "contact_reference.h"
#include "core/config.h"
#include "core/model.h"
#include "core/sim.h"
#include "core/summary.h"

/* Runs s for steps steps from x0, v0 as --headless does, the summary taking in every
 * state. */
static struct summary *run(struct sim *s, const double *x0, const double *v0, double steps)
{
    struct summary *sum = summary_new(sim_model(s)->n);
    assert_non_null(sum);
    sim_reset(s, x0, v0);
    summary_add(sum, s, 0.0, steps);
    for (double step = 1; step <= steps; step++) {
        assert_int_equal(sim_step(s), SIM_OK);
        summary_add(sum, s, step, steps);
    }
    return sum;
}

/* The header and the row, split into fields (CSV: a quoted field keeps its commas). */
struct table {
    char *text;
    int cols;
    char *head[64], *row[64];
};

static int split(char *line, char **field)
{
    int n = 0;
    char *p = line;
    for (;;) {
        bool quoted = *p == '"';
        field[n++] = p + quoted;
        char *end = quoted ? strchr(p + 1, '"') : p + strcspn(p, ",\n");
        assert_non_null(end);
        if (quoted)
            *end++ = '\0';
        char sep = *end;
        *end = '\0';
        if (sep != ',')
            return n;
        p = end + 1;
    }
}

static void table_of(const struct summary *sum, const struct sim *s, struct table *t)
{
    size_t size;
    FILE *mem = open_memstream(&t->text, &size);
    assert_non_null(mem);
    summary_header(mem, sim_model(s)->n);
    summary_row(mem, sum, s);
    assert_int_equal(fclose(mem), 0);
    char *nl = strchr(t->text, '\n');
    assert_non_null(nl);
    assert_string_equal(nl + 1 + strcspn(nl + 1, "\n"), "\n"); /* two lines, no more */
    *nl = '\0';
    t->cols = split(t->text, t->head);
    assert_int_equal(split(nl + 1, t->row), t->cols);
}

static double field(const struct table *t, const char *name)
{
    for (int i = 0; i < t->cols; i++)
        if (strcmp(t->head[i], name) == 0)
            return strtod(t->row[i], NULL);
    fail_msg("no column %s", name);
    return NAN;
}

static struct model *one_mass(double c)
{
    struct model *m = model_new(1);
    assert_non_null(m);
    m->m[0] = 1.0;
    m->k[0] = m->k[1] = 10.0;
    m->c[0] = c;
    m->boundary = BOUNDARY_WALL;
    return m;
}

static void undamped_mass_closed_forms(void **state)
{
    (void)state;
    struct model *m = one_mass(0.0);
    double w = sqrt(20.0), period = 2.0 * M_PI / w, x0 = -0.5;
    /* 1000 steps a period, 6 periods: the last half is 3 whole periods. */
    struct sim *s = sim_new(m, period / 1000.0);
    assert_non_null(s);
    struct summary *sum = run(s, &x0, NULL, 6000.0);
    double max_x, rms_x, max_v;
    summary_mass(sum, 0, &max_x, &rms_x, &max_v);
    assert_true(max_x == fabs(x0)); /* the start itself */
    assert_close(rms_x, fabs(x0) / sqrt(2.0), 1e-9);
    assert_close(max_v, w * fabs(x0), 1e-9);
    assert_true(summary_contacts(sum) == 0.0);
    struct table t;
    table_of(sum, s, &t);
    assert_close(field(&t, "max_abs_x1"), fabs(x0), 1e-11);
    assert_close(field(&t, "rms_x1"), fabs(x0) / sqrt(2.0), 1e-9);
    assert_close(field(&t, "max_abs_v1"), w * fabs(x0), 1e-9);
    assert_true(field(&t, "dissipated") == 0.0 && field(&t, "motor_work") == 0.0);
    assert_true(field(&t, "contacts") == 0.0);
    free(t.text);
    summary_free(sum);
    sim_free(s);
    model_free(m);
}

/* Damping and no drive: what the dampers took is the mechanical energy lost. */
static void dissipated_is_energy_lost(void **state)
{
    (void)state;
    struct model *m = one_mass(0.7);
    struct sim *s = sim_new(m, 0.001);
    assert_non_null(s);
    double x0 = 0.5, v0 = 1.5;
    double e0 = 0.5 * v0 * v0 + 2.0 * 0.5 * 10.0 * x0 * x0;
    struct summary *sum = run(s, &x0, &v0, 5000.0);
    double x = sim_x(s)[0], v = sim_v(s)[0];
    double e1 = 0.5 * v * v + 2.0 * 0.5 * 10.0 * x * x;
    struct table t;
    table_of(sum, s, &t);
    assert_true(e1 < 0.2 * e0); /* it did lose most of it */
    assert_close(field(&t, "dissipated"), e0 - e1, 1e-9 * e0);
    assert_true(field(&t, "motor_work") == 0.0);
    free(t.text);
    summary_free(sum);
    sim_free(s);
    model_free(m);
}

/* The settings columns: option names, as the command line spells the values. */
static void settings_as_the_command_line_spells_them(void **state)
{
    (void)state;
    struct model *m = model_new(2);
    assert_non_null(m);
    m->m[1] = 2.5;
    m->k[0] = m->k[1] = m->k[2] = 7.0;
    m->motor = (struct motor){WAVE_SQUARE, 0.25, 0.75, 0.0};
    struct sim *s = sim_new(m, 0.005);
    assert_non_null(s);
    sim_set_integrator(s, INTEGRATOR_VERLET);
    struct summary *sum = run(s, NULL, NULL, 10.0);
    struct table t;
    table_of(sum, s, &t);
    static const char *const want[][2] = {
        {"masses", "2"},     {"mass", "1,2.5"},     {"spring", "7"}, {"damping", "0.1"},
        {"frequency", "0.75"}, {"amplitude", "0.25"}, {"wave", "square"}, {"dt", "0.005"},
        {"integrator", "verlet"}, {"boundary", "motor"}, {"spring-damping", "0"},
        {"spring-cubic", "0"}, {"force", "0"}, {"force-on", "1"},
    };
    assert_int_equal(t.cols, 14 + 3 * 2 + 4);
    for (size_t i = 0; i < sizeof want / sizeof *want; i++) {
        assert_string_equal(t.head[i], want[i][0]);
        assert_string_equal(t.row[i], want[i][1]);
    }
    /* Each is a setting of the table, its value one the option takes back. */
    static struct config c;
    config_init(&c);
    for (size_t i = 0; i < sizeof want / sizeof *want; i++) {
        char err[256];
        int key = config_find(t.head[i]);
        assert_true(key >= 0 && config_options[key].section);
        if (config_set(&c, key, t.row[i], err, sizeof err) != 0)
            fail_msg("--%s %s: %s", t.head[i], t.row[i], err);
    }
    assert_true(c.masses == 2 && c.mass.count == 2 && c.mass.v[1] == 2.5 && c.dt == 0.005);
    free(t.text);
    summary_free(sum);
    sim_free(s);
    model_free(m);
}

/* The collisions preset's chain for 120 s: every bounce the reference finds, counted
 * once, and no other contact. */
static void contacts_match_reference(void **state)
{
    (void)state;
    struct model *m = model_new(2);
    assert_non_null(m);
    m->m[0] = m->m[1] = 1.0;
    m->k[0] = 5.0, m->k[1] = 10.0, m->k[2] = 20.0;
    m->c[0] = m->c[1] = 0.3;
    m->motor = (struct motor){WAVE_SINE, 1.0, 0.503292, 0.0};
    m->collisions = true;
    struct ref r;
    ref_init(&r, m, NULL, NULL);
    ref_advance(&r, 120.0);
    assert_null(r.error);
    assert_true(r.nev > 20 && r.nev < REF_MAXEVENTS);
    assert_true(fabs(ref_balance(&r)) <= 1e-9 * r.motor_work); /* the reference holds */
    struct sim *s = sim_new(m, 0.01);
    assert_non_null(s);
    struct summary *sum = run(s, NULL, NULL, 12000.0);
    assert_true(summary_contacts(sum) == r.nev);
    summary_free(sum);
    sim_free(s);
    model_free(m);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(undamped_mass_closed_forms),
        cmocka_unit_test(dissipated_is_energy_lost),
        cmocka_unit_test(settings_as_the_command_line_spells_them),
        cmocka_unit_test(contacts_match_reference),
    };
    return cmocka_run_group_tests_name("summary", tests, NULL, NULL);
}
