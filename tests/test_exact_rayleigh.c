/* test_exact_rayleigh.c: the exact stepper on chains with Rayleigh's damping, C = alpha M +
 * beta K, driven by what the modes once left to the dense exponential: a force on a mass
 * (wall and free ends), the motor moving the end of a damped spring (its damper's cs_N u'
 * an input), and both at once, in every waveform. Each is stepped in the modes (checked),
 * and against RK4 at dt 1e-4 and the dense exponential (the same chain with one damper
 * moved by 1e-13, off Rayleigh's, which exact.c steps by exact_general.c) its motion, its
 * three books and its energy balance agree. (A damper on the motor's spring with a square
 * or sawtooth wave is refused by the command line, its jumps being infinite forces; the
 * model steps it with the jump booked as the change of the end spring's energy, alike in
 * every path, and it is kept here for the waveform's pieces.) */
#include "testutil.h"

#include <stdlib.h>
#include <string.h>

#include "core/exact.h"
#include "core/model.h"
#include "core/sim.h"
#include "core/stepper.h"

enum { N = 10, BIG = 300 };

#define ALPHA 0.08 /* c_i / m_i */
#define BETA 0.004 /* cs_j / k_j */

struct rcase {
    const char *name;
    enum boundary boundary;
    double force;
    int on;
};

static const struct rcase cases[] = {
    {"force, wall end", BOUNDARY_WALL, 1.5, 3},
    {"force, free end", BOUNDARY_FREE, 1.5, N - 1},
    {"motor, end damper", BOUNDARY_MOTOR, 0.0, 0},
    {"motor, end damper, force", BOUNDARY_MOTOR, 1.5, 4},
};

/* A chain of N with unequal masses and springs, C = ALPHA M + BETA K (the motor's spring's
 * damper included), the case's drive in waveform w. */
static struct model *rayleigh_chain(const struct rcase *rc, enum wave w, int n)
{
    struct model *m = model_new(n);
    for (int i = 0; i < n; i++) {
        m->m[i] = 0.5 + 0.37 * (i % 7);
        m->c[i] = ALPHA * m->m[i];
    }
    for (int j = 0; j <= n; j++) {
        m->k[j] = 8.0 + 5.0 * sin(1.3 * j + 0.4);
        m->cs[j] = BETA * m->k[j];
    }
    m->boundary = rc->boundary;
    m->motor = (struct motor){w, 0.3, 0.9, 0.1};
    m->force = rc->force;
    m->force_on = rc->on;
    m->collisions = false;
    model_sync(m);
    return m;
}

/* One step through exact_advance_all: it must go through the modes. */
static void takes_modes(const struct model *m)
{
    assert_true(model_rayleigh(m));
    assert_int_equal(exact_needs_general(m), 0);
    struct exact *e = exact_new(m->n);
    assert_non_null(e);
    struct drive d;
    struct exact_drive ed;
    drive_at(&d, m, 0.005);
    drive_exact(&d, 0.0, &ed);
    static double x[BIG] = {0.1, -0.05}, v[BIG] = {0.2};
    double D = 0.0, W = 0.0, P = 0.0;
    assert_int_equal(exact_advance_all(e, m, &ed, 0.0, 0.01, x, v, &D, &W, &P), 0);
    assert_true(exact_stepped_in_modes(e));
    exact_free(e);
}

static struct sim *start(const struct model *m, enum integrator integ, double dt)
{
    static double x0[BIG], v0[BIG];
    for (int i = 0; i < m->n; i++) {
        x0[i] = 0.05 * sin(0.9 * i + 0.3);
        v0[i] = 0.1 * cos(1.7 * i);
    }
    struct sim *s = sim_new(m, dt);
    assert_non_null(s);
    sim_set_integrator(s, integ);
    sim_reset(s, x0, v0);
    return s;
}

/* The largest difference of two sims' displacements and velocities. */
static double apart(const struct sim *a, const struct sim *b, int n)
{
    double most = 0.0;
    for (int i = 0; i < n; i++)
        most = fmax(most, fmax(fabs(sim_x(a)[i] - sim_x(b)[i]), fabs(sim_v(a)[i] - sim_v(b)[i])));
    return most;
}

/* The largest difference of two energy books. */
static double books_apart(const struct energy *a, const struct energy *b)
{
    return fmax(fabs(a->dissipated - b->dissipated),
                fmax(fabs(a->motor_work - b->motor_work), fabs(a->force_work - b->force_work)));
}

/* steps of 0.01 of the case in waveform w on n masses: exact in the modes against RK4 at
 * dt 1e-4 and the dense exponential, every step; the balance of the exact run. */
static void one_case(const struct rcase *rc, enum wave w, int n, int steps)
{
    enum { SUB = 100 };
    struct model *m = rayleigh_chain(rc, w, n), *off = rayleigh_chain(rc, w, n);
    takes_modes(m);
    off->c[2] *= 1.0 + 1e-13; /* off Rayleigh's: the dense exponential */
    assert_false(model_rayleigh(off));
    struct sim *ex = start(m, INTEGRATOR_EXACT, 0.01), *rk = start(m, INTEGRATOR_RK4, 0.01 / SUB);
    /* (the dense reference's set-up is seconds a step length at 300 masses: small only) */
    struct sim *dense = n <= N ? start(off, INTEGRATOR_EXACT, 0.01) : NULL;
    struct energy e0, e, ed;
    sim_energy(ex, &e0);
    double to_rk4 = 0.0, to_dense = 0.0, books = 0.0, drift = 0.0, peak = 0.0;
    for (int k = 0; k < steps; k++) {
        assert_int_equal(sim_step(ex), SIM_OK);
        assert_true(!dense || sim_step(dense) == SIM_OK);
        for (int s = 0; s < SUB; s++)
            assert_int_equal(sim_step(rk), SIM_OK);
        to_rk4 = fmax(to_rk4, apart(ex, rk, n));
        sim_energy(ex, &e);
        if (dense) {
            to_dense = fmax(to_dense, apart(ex, dense, n));
            sim_energy(dense, &ed);
            books = fmax(books, books_apart(&e, &ed));
        }
        peak = fmax(peak, e.kinetic + e.potential);
        drift = fmax(drift, fabs(e.balance - e0.balance));
    }
    if (!dense) /* not compared */
        to_dense = books = NAN;
    printf("  %-25s %-8s %3d masses, %.1f s: %.1e from rk4 at 1e-4, %.1e from dense, books "
           "%.1e, balance drift %.1e of the peak (D %.3g, W %.3g, P %.3g J)\n",
           rc->name, motor_wave_name(w), n, 0.01 * steps, to_rk4, to_dense, books / peak,
           drift / peak, e.dissipated, e.motor_work, e.force_work);
    assert_true(e.dissipated > 0.0);
    assert_true(rc->force == 0.0 || e.force_work != 0.0);
    assert_true(rc->boundary != BOUNDARY_MOTOR || e.motor_work != 0.0);
    if (!(to_rk4 <= 1e-10 && drift <= 1e-9 * peak &&
          (!dense || (to_dense <= 1e-11 && books <= 1e-10 * peak))))
        fail_msg("%s, %s, %d masses: %.3g from rk4, %.3g from dense, books %.3g, drift %.3g "
                 "of the peak", rc->name, motor_wave_name(w), n, to_rk4, to_dense,
                 books / peak, drift / peak);
    sim_free(ex);
    sim_free(rk);
    if (dense)
        sim_free(dense);
    model_free(m);
    model_free(off);
}

static void force_and_end_damper(void **state)
{
    (void)state;
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++)
        for (int w = 0; w < WAVE_COUNT; w++)
            one_case(&cases[c], (enum wave)w, N, 300);
}

/* The same at 300 masses (both inputs, a sine and a triangle) for 0.3 s against RK4: the
 * modes' shapes and the books hold at size. */
static void at_size(void **state)
{
    (void)state;
    one_case(&cases[3], WAVE_SINE, BIG, 30);
    one_case(&cases[3], WAVE_TRIANGLE, BIG, 30);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(force_and_end_damper),
        cmocka_unit_test(at_size),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
