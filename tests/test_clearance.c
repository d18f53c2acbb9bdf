/* test_clearance.c: the least gap carried from step to step (core/clearance.h) never
 * skips a look for contacts that would have found one. Step by step on random chains,
 * whenever the clearance says a step is clear, events_may_close on the same step says no
 * gap may close; and whole runs with contacts, stepped as they are and with the clearance
 * forgotten before every step, agree bit for bit. */
#include "testutil.h"

#include <string.h>

#include "core/clearance.h"
#include "core/collision.h"
#include "core/events.h"
#include "core/model.h"
#include "core/rest.h"
#include "core/sim.h"
#include "core/stepper.h"

/* A random chain of 1 to 8 masses (or up to most): masses, springs, ground dampers, now
 * and then cubic springs, spring dampers or a force on a mass; a sine motor, a wall or a
 * free end. */
static struct model *random_chain(uint64_t *rng, int most)
{
    int n = 1 + (int)test_uniform(rng, 0.0, most);
    struct model *m = model_new(n);
    assert_non_null(m);
    for (int i = 0; i < n; i++) {
        m->m[i] = test_uniform(rng, 0.3, 3.0);
        m->c[i] = test_uniform(rng, 0.0, 1.5);
    }
    bool cubic = test_uniform(rng, 0.0, 1.0) < 0.25, damped = test_uniform(rng, 0.0, 1.0) < 0.25;
    for (int j = 0; j <= n; j++) {
        m->k[j] = test_uniform(rng, 1.0, 60.0);
        m->k3[j] = cubic ? test_uniform(rng, 0.0, 200.0) : 0.0;
        m->cs[j] = damped ? test_uniform(rng, 0.0, 1.0) : 0.0;
    }
    model_sync(m);
    double end = test_uniform(rng, 0.0, 1.0);
    m->boundary = end < 0.7 ? BOUNDARY_MOTOR : end < 0.85 ? BOUNDARY_WALL : BOUNDARY_FREE;
    m->motor.amplitude = test_uniform(rng, 0.0, 2.0);
    m->motor.frequency = test_uniform(rng, 0.05, 3.0);
    if (test_uniform(rng, 0.0, 1.0) < 0.2) {
        m->force = test_uniform(rng, -20.0, 20.0);
        m->force_on = (int)test_uniform(rng, 0.0, n);
    }
    m->collisions = true;
    return m;
}

/* How far a sine drive strays from its cubic Hermite over a step h, as sim_step takes it:
 * the largest |u''''| h^4 / 384. */
static double drive_straying(const struct model *m, double h)
{
    double w = 2.0 * M_PI * m->motor.frequency;
    return m->motor.amplitude * w * w * w * w / 384.0 * h * h * h * h;
}

/* Displacements that leave every gap between about -0.02 m and a few tenths, and
 * velocities up to 4 m/s: many steps near a contact, many far from one. */
static void random_state(uint64_t *rng, const struct model *m, double *x, double *v)
{
    struct collision_limits l;
    collision_limits(&l, m);
    double pos = 0.5 * l.w; /* a block's centre, from the wall */
    for (int i = 0; i < m->n; i++) {
        double room = l.spacing - l.w;
        pos += (i ? l.w : 0.0) + test_uniform(rng, -0.02, fmin(0.4, room + 0.1));
        x[i] = pos - model_equilibrium(m, i);
        v[i] = test_uniform(rng, -4.0, 4.0);
    }
}

/* The bound alone, on any two states a step apart (not only those RK4 makes): from a
 * start filled into the clearance, an end whose masses moved at most dx and whose speeds
 * and the piston's are what they are, a clear step is never one events_may_close finds
 * a gap closing in. A mass that turns back inside the step (its gap the same at both
 * ends, its speed reversed) or stops in it is the case the rates' term is for; the
 * drive's straying err is up to 0.1 m (a fast sine at a long step). */
static void any_two_states(void **state)
{
    (void)state;
    uint64_t rng = 0xa11ce5eed2u;
    long clear = 0, close = 0;
    for (int c = 0; c < 200000; c++) {
        struct model *m = random_chain(&rng, 4);
        int n = m->n;
        struct collision_limits l;
        collision_limits(&l, m);
        struct rest *r = rest_new(n);
        assert_non_null(r);
        double ya[STEPPER_LEN(5)] = {0}, y[STEPPER_LEN(5)] = {0};
        random_state(&rng, m, ya, ya + n);
        double h = exp(test_uniform(&rng, log(1e-4), log(0.05))), dx = 0.0, v = 0.0;
        double kind = test_uniform(&rng, 0.0, 1.0);
        bool turn = kind < 0.3, stop = kind > 0.7; /* or stopping in the step */
        for (int i = 0; i < n; i++) {
            y[i] = ya[i] + (turn ? 0.0 : h * test_uniform(&rng, -4.0, 4.0));
            y[n + i] = turn ? -ya[n + i] : test_uniform(&rng, -4.0, 4.0) * (stop ? 0.01 : 1.0);
            dx = fmax(dx, fabs(y[i] - ya[i]));
            v = fmax(v, fabs(y[n + i]));
        }
        double ua = test_uniform(&rng, -0.5, 0.5), ub = ua + h * test_uniform(&rng, -2.0, 2.0);
        double dua = test_uniform(&rng, -2.0, 2.0), dub = test_uniform(&rng, -2.0, 2.0);
        double err = exp(test_uniform(&rng, log(1e-12), log(0.1)));
        struct clearance cl;
        clearance_fill(&cl, &l, ya, ua);
        bool ok = clearance_step(&cl, h, dx, v, ua, ub, dua, dub, err);
        struct drive d = {.kind = DRIVE_NONE};
        struct events_piece p = {&l, m, r, &d, ya, y, 0.0, h, ua, dua, ub, dub, 0.0, err};
        bool may = events_may_close(&p);
        if (ok && may)
            fail_msg("case %d (N = %d, h %.3g%s): clear, but a gap may close", c, n, h,
                     turn ? ", turning back" : "");
        clear += ok, close += may;
        rest_free(r);
        model_free(m);
    }
    printf("  200000 pairs of states: %ld clear, %ld with a gap that may close\n", clear,
           close);
    assert_true(clear > 20000 && close > 20000);
}

/* One case for each of the bound's terms, made to need it: a look the clearance must
 * not skip (events_may_close finds a gap that may close), which it would skip without
 * that term. Positions do not move (dx = 0), so only the rates and the drive are left. */
struct need {
    const char *what;
    int n;             /* masses; a free end for two, a motor for one */
    double gap;        /* the gap looked at (the others are wide) */
    double va[2], vb[2]; /* velocities at the start and the end */
    double dua, dub, err;
};

static void each_term_is_needed(void **state)
{
    (void)state;
    const double h = 0.01;
    const struct need cases[] = {
        {"a pair stopping in the step (2 V0)", 2, 0.004, {1.0, -1.0}, {0.0, 0.0}, 0, 0, 0},
        {"a pair starting in the step (2 V1)", 2, 0.004, {0.0, 0.0}, {-1.0, 1.0}, 0, 0, 0},
        {"the piston stopping (|dua|)", 1, 0.002, {0.0}, {0.0}, -1.0, 0.0, 0.0},
        {"the piston starting (|dub|)", 1, 0.002, {0.0}, {0.0}, 0.0, 1.0, 0.0},
        {"the drive straying (err)", 1, 0.002, {0.0}, {0.0}, 0.0, 0.0, 0.003},
    };
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++) {
        const struct need *k = &cases[c];
        struct model *m = model_new(k->n);
        assert_non_null(m);
        m->boundary = k->n == 2 ? BOUNDARY_FREE : BOUNDARY_MOTOR;
        struct collision_limits l;
        collision_limits(&l, m);
        struct rest *r = rest_new(k->n);
        assert_non_null(r);
        double ya[STEPPER_LEN(2)] = {0}, y[STEPPER_LEN(2)] = {0};
        if (k->n == 2) {
            ya[1] = y[1] = k->gap - l.pair; /* the pair's gap */
        } else {
            ya[0] = y[0] = l.face - k->gap; /* the piston's gap, u = 0 */
        }
        for (int i = 0; i < k->n; i++)
            ya[k->n + i] = k->va[i], y[k->n + i] = k->vb[i];
        struct clearance cl;
        clearance_fill(&cl, &l, ya, 0.0);
        struct drive d = {.kind = DRIVE_NONE};
        struct events_piece p = {&l, m, r, &d, ya, y, 0.0, h, 0.0, k->dua, 0.0, k->dub, 0.0,
                                 k->err};
        double v = fmax(fabs(k->vb[0]), k->n == 2 ? fabs(k->vb[1]) : 0.0);
        if (!events_may_close(&p))
            fail_msg("%s: the case should have a gap that may close", k->what);
        if (clearance_step(&cl, h, 0.0, v, 0.0, 0.0, k->dua, k->dub, k->err))
            fail_msg("%s: the clearance skipped a step whose gap may close", k->what);
        rest_free(r);
        model_free(m);
    }
}

/* Step by step: a clear step is never one whose gaps may close. Each case fills the
 * clearance from a random state and steps on while it holds (and a few steps after). */
static void clear_means_no_contact(void **state)
{
    (void)state;
    uint64_t rng = 0x5eed0c1ea4a9ce11u;
    long clear = 0, looked = 0, would_close = 0, steps = 0;
    for (int c = 0; c < 3000; c++) {
        struct model *m = random_chain(&rng, 8);
        int n = m->n, len = STEPPER_LEN(n);
        double dt = exp(test_uniform(&rng, log(1e-4), log(0.05)));
        struct stepper *st = stepper_new(m);
        assert_non_null(st);
        stepper_set_model(st, m, dt);
        struct collision_limits l;
        collision_limits(&l, m);
        struct rest *r = rest_new(n);
        assert_non_null(r);
        double y[STEPPER_LEN(9)] = {0}, ya[STEPPER_LEN(9)];
        random_state(&rng, m, y, y + n);
        double t = test_uniform(&rng, 0.0, 10.0);
        struct clearance cl;
        clearance_fill(&cl, &l, y, model_end_position(m, t));
        for (int k = 0; k < 400; k++, t += dt) {
            memcpy(ya, y, (size_t)len * sizeof *y);
            struct drive d;
            drive_at(&d, m, t + 0.5 * dt);
            if (stepper_rk4(st, &d, t, t + dt, y) & STEPPER_NONFINITE)
                break;
            struct stepper_reach re;
            stepper_rk4_reach(st, &re);
            double err = d.kind == DRIVE_SINE ? drive_straying(m, dt) : 0.0;
            bool ok = clearance_step(&cl, dt, re.dx, re.v, re.ua, re.ub, re.dua, re.dub, err);
            struct events_piece p = {&l, m, r, &d, ya, y, t, dt, re.ua, re.dua, re.ub, re.dub,
                                     0.0, err};
            bool may = events_may_close(&p);
            if (ok && may)
                fail_msg("case %d step %d (N = %d, dt %.3g): clear, but a gap may close", c, k,
                         n, dt);
            clear += ok, looked += !ok, would_close += may, steps++;
            if (!ok && may)
                break; /* a contact: sim_step would locate it; the case ends */
            if (!ok)
                clearance_fill(&cl, &l, y, re.ub);
        }
        rest_free(r);
        stepper_free(st);
        model_free(m);
    }
    printf("  %ld steps: %ld clear, %ld looked at, %ld of them with a gap that may close\n",
           steps, clear, looked, would_close);
    /* Both sides met often: the campaign tests the bound where it matters. */
    assert_true(clear > steps / 4);
    assert_true(would_close > 1000);
}

/* Whole runs: the same chain stepped as it is, and with the clearance forgotten before
 * every step (sim_set_integrator does it, and nothing else here), give the same bits
 * and the same contacts every step. */
static void runs_keep_their_bits(void **state)
{
    (void)state;
    uint64_t rng = 0xc1ea2a9ce5eed5u;
    long contacts = 0;
    for (int c = 0; c < 120; c++) {
        struct model *m = random_chain(&rng, 12);
        if (test_uniform(&rng, 0.0, 1.0) < 0.2)
            m->motor.wave = (enum wave)(1 + (int)test_uniform(&rng, 0.0, 3.0));
        int n = m->n;
        double dt = exp(test_uniform(&rng, log(5e-4), log(0.02)));
        struct sim *a = sim_new(m, dt), *b = sim_new(m, dt);
        assert_non_null(a);
        assert_non_null(b);
        double x[12], v[12];
        random_state(&rng, m, x, v);
        sim_reset(a, x, v);
        sim_reset(b, x, v);
        for (int k = 0; k < 3000; k++) {
            enum sim_status sa = sim_step(a);
            sim_set_integrator(b, INTEGRATOR_RK4);
            enum sim_status sb = sim_step(b);
            assert_int_equal(sa, sb);
            if (memcmp(sim_x(a), sim_x(b), (size_t)n * sizeof(double)) != 0 ||
                memcmp(sim_v(a), sim_v(b), (size_t)n * sizeof(double)) != 0)
                fail_msg("case %d (N = %d, dt %.3g): the states part at step %d", c, n, dt, k);
            assert_int_equal(sim_last_contacts(a), sim_last_contacts(b));
            contacts += sim_last_contacts(a);
            if (sa != SIM_OK)
                break;
        }
        sim_free(a);
        sim_free(b);
        model_free(m);
    }
    printf("  120 runs of 3000 steps, %ld contacts\n", contacts);
    assert_true(contacts > 10000);
}

/* The common case: the default chain at dt 0.001 looks for contacts once in many steps. */
static void default_chain_looks_seldom(void **state)
{
    (void)state;
    struct model *m = model_new(5);
    assert_non_null(m);
    double dt = 0.001, y[STEPPER_LEN(5)] = {0};
    struct stepper *st = stepper_new(m);
    assert_non_null(st);
    stepper_set_model(st, m, dt);
    struct collision_limits l;
    collision_limits(&l, m);
    struct clearance cl = {0};
    int looks = 0, steps = 20000;
    for (int k = 0; k < steps; k++) {
        struct drive d;
        double t = k * dt;
        drive_at(&d, m, t + 0.5 * dt);
        assert_int_equal(stepper_rk4(st, &d, t, t + dt, y) & STEPPER_NONFINITE, 0);
        struct stepper_reach re;
        stepper_rk4_reach(st, &re);
        double err = drive_straying(m, dt);
        if (!clearance_step(&cl, dt, re.dx, re.v, re.ua, re.ub, re.dua, re.dub, err)) {
            looks++;
            clearance_fill(&cl, &l, y, re.ub);
        }
    }
    printf("  the default chain, %d steps of 1 ms: %d looks\n", steps, looks);
    assert_true(looks * 50 < steps);
    stepper_free(st);
    model_free(m);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(each_term_is_needed),
        cmocka_unit_test(any_two_states),
        cmocka_unit_test(clear_means_no_contact),
        cmocka_unit_test(runs_keep_their_bits),
        cmocka_unit_test(default_chain_looks_seldom),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
