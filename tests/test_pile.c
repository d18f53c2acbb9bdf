/* test_pile.c: issue 31's contacts. Piston jumps (square and sawtooth) into piles that
 * once froze the chain or made energy: the two reported freezes move on, the reported
 * sawtooth pile keeps its balance, and so does a random campaign of jumps into piles
 * (CAMPAIGN_CASES sets how many; the memcheck run takes fewer). An impact on a row of
 * masses follows the pairwise rule whether or not a force presses the row together.
 *
 * The balance is kinetic + potential + dissipated + contact - motor_work, which the model
 * keeps constant to the method's accuracy, contacts included; it is judged
 * against the peak of kinetic + potential. */
#include "testutil.h"

#include <stdlib.h>
#include <string.h>

#include "core/collision.h"
#include "core/events.h"
#include "core/model.h"
#include "core/rest.h"
#include "core/sim.h"

/* A chain from the command line's lists. */
static struct model *chain(int n, const double *m, const double *k, const double *c,
                           enum wave wave, double amp, double freq)
{
    struct model *md = model_new(n);
    assert_non_null(md);
    for (int i = 0; i < n; i++)
        md->m[i] = m[i], md->c[i] = c[i];
    for (int i = 0; i <= n; i++)
        md->k[i] = k[i];
    md->motor = (struct motor){wave, amp, freq, 0.0};
    return md;
}

/* What a run did. */
struct verdict {
    double imbalance; /* max |balance - balance(0)| over the peak energy */
    double frozen;    /* the first sample time whose positions equal those 1 s before
                         while some |v| > 0.1 m/s; -1 if none */
    double overlap;   /* the deepest overlap after any step (m, >= 0) */
    int teleports;    /* steps in which two or more masses were moved by a piston jump */
    int contacts;
};

static void run(const struct model *md, double dt, double duration, enum integrator integ,
                struct verdict *out)
{
    int n = md->n;
    struct sim *s = sim_new(md, dt);
    assert_non_null(s);
    sim_set_integrator(s, integ);
    const struct collision_limits *l = sim_limits(s);
    int steps = (int)lround(duration / dt), per_second = (int)lround(1.0 / dt);
    double *xs = calloc((size_t)(steps + 1) * (size_t)n, sizeof *xs);
    assert_non_null(xs);
    struct energy e;
    sim_energy(s, &e);
    double b0 = e.balance, peak = e.kinetic + e.potential, worst = 0.0;
    *out = (struct verdict){0.0, -1.0, 0.0, 0, 0};
    for (int j = 1; j <= steps; j++) {
        double before[64], vmax = 0.0;
        memcpy(before, sim_x(s), (size_t)n * sizeof *before);
        for (int i = 0; i < n; i++)
            vmax = fmax(vmax, fabs(sim_v(s)[i]));
        assert_int_equal(sim_step(s), SIM_OK);
        out->contacts += sim_last_contacts(s);
        const double *x = sim_x(s), *v = sim_v(s);
        memcpy(xs + (size_t)j * n, x, (size_t)n * sizeof *x);
        int moved = 0;
        for (int i = 0; i < n; i++)
            moved += fabs(x[i] - before[i]) > 2.0 * (vmax + 10.0) * dt + 1e-3;
        out->teleports += moved >= 2;
        double u = sim_end_position(s);
        for (int k = 0; k < l->count; k++)
            out->overlap = fmax(out->overlap, -collision_gap(l, k, x, u));
        sim_energy(s, &e);
        peak = fmax(peak, e.kinetic + e.potential);
        worst = fmax(worst, fabs(e.balance - b0));
        if (j >= per_second && j % per_second == 0 && out->frozen < 0.0) {
            bool same = memcmp(xs + (size_t)(j - per_second) * n, x, (size_t)n * sizeof *x) == 0;
            bool moving = false;
            for (int i = 0; i < n; i++)
                moving |= fabs(v[i]) > 0.1;
            if (same && moving)
                out->frozen = j * dt;
        }
    }
    out->imbalance = worst / peak;
    free(xs);
    sim_free(s);
}

/* Issue 31's two freezes: the chain stood still with velocities of 8 and 1.3 m/s. */
static void freezes_move_on(void **state)
{
    (void)state;
    struct model *a = chain(2, (const double[]){1.381, 0.837}, (const double[]){1.13, 30.6, 55.18},
                            (const double[]){1.628, 0.896}, WAVE_SQUARE, 4.84, 0.095);
    struct model *b = chain(3, (const double[]){1.918, 1.128, 1.421},
                            (const double[]){3.14, 30.19, 51.37, 53.72},
                            (const double[]){0.512, 0.852, 1.508}, WAVE_SAWTOOTH, 5.26, 0.133);
    const struct {
        struct model *m;
        double dt;
        enum integrator integ;
    } runs[] = {{a, 0.01, INTEGRATOR_RK4},       {b, 0.01, INTEGRATOR_RK4},
                {b, 0.001, INTEGRATOR_EXACT},    {b, 0.001, INTEGRATOR_VERLET},
                {a, 0.001, INTEGRATOR_RK4},      {b, 0.001, INTEGRATOR_RK4}};
    for (size_t j = 0; j < sizeof runs / sizeof runs[0]; j++) {
        struct verdict v;
        run(runs[j].m, runs[j].dt, 20.0, runs[j].integ, &v);
        printf("  freeze %zu (N %d, %s, dt %g): frozen at %g s, balance %.1e of the peak, "
               "overlap %.1e m, %d contacts\n",
               j, runs[j].m->n, integrator_name(runs[j].integ), runs[j].dt, v.frozen,
               v.imbalance, v.overlap, v.contacts);
        assert_true(v.frozen < 0.0);
        assert_true(v.imbalance <= 1e-4);
        assert_true(v.overlap <= 1e-9);
        assert_true(v.teleports >= 1); /* the jump into the pile happened */
    }
    model_free(a);
    model_free(b);
}

/* Issue 31's sawtooth into a 9-mass pile: K+P+D+C-W once rose by 93 % of the peak. */
static void sawtooth_pile_keeps_balance(void **state)
{
    (void)state;
    struct model *m = chain(9, (const double[]){0.81, 1.74, 0.72, 1.27, 0.7, 1.53, 1.76, 1.14, 1.94},
                            (const double[]){2.65, 33.5, 43, 50.1, 53.1, 57.3, 25.8, 49.8, 25.6, 56.3},
                            (const double[]){0.49, 1.31, 0.6, 1.46, 0.87, 0.62, 0.57, 0.99, 0.63},
                            WAVE_SAWTOOTH, 1.339, 0.129);
    const double dts[2] = {0.01, 0.001};
    for (int d = 0; d < 2; d++) {
        struct verdict v;
        run(m, dts[d], 20.0, INTEGRATOR_RK4, &v);
        printf("  sawtooth pile at dt %g: balance %.1e of the peak, overlap %.1e m, %d contacts\n",
               dts[d], v.imbalance, v.overlap, v.contacts);
        assert_true(v.imbalance <= 1e-4);
        assert_true(v.frozen < 0.0);
        assert_true(v.overlap <= 1e-9);
        assert_true(v.teleports >= 1);
    }
    model_free(m);
}

static uint64_t rng_state;

static double uniform(double lo, double hi)
{
    return test_uniform(&rng_state, lo, hi);
}

/* Random square and sawtooth pistons jumping into piles of 2 to 20 masses: an amplitude
 * between half and all of the room the blocks leave (L - N w), stiff and soft springs. */
static void jump_campaign(void **state)
{
    (void)state;
    const char *env = getenv("CAMPAIGN_CASES");
    int cases = env ? atoi(env) : 240, failed = 0, jumped = 0;
    double worst = 0.0, worst_overlap = 0.0;
    for (int j = 0; j < cases; j++) {
        rng_state = 0x2545F4914F6CDD1Dull ^ (uint64_t)(j + 1) * 0x9E3779B97F4A7C15ull;
        for (int i = 0; i < 4; i++)
            uniform(0, 1);
        int n = 2 + (int)uniform(0, 19);
        struct model *m = model_new(n);
        assert_non_null(m);
        for (int i = 0; i < n; i++)
            m->m[i] = uniform(0.5, 2.0), m->c[i] = uniform(0.0, 1.5);
        for (int i = 0; i <= n; i++)
            m->k[i] = uniform(0.0, 1.0) < 0.3 ? uniform(0.5, 5.0) : uniform(10.0, 60.0);
        double room = MODEL_LENGTH - n * model_block_width(m);
        m->motor = (struct motor){j % 2 ? WAVE_SAWTOOTH : WAVE_SQUARE,
                                  uniform(0.5, 0.999) * room, uniform(0.1, 0.5), 0.0};
        double dt = j % 3 == 2 ? 0.001 : 0.01;
        struct verdict v;
        run(m, dt, 1.0 / m->motor.frequency + 1.0, INTEGRATOR_RK4, &v);
        jumped += v.teleports > 0;
        worst = fmax(worst, v.imbalance);
        worst_overlap = fmax(worst_overlap, v.overlap);
        bool ok = v.imbalance <= 1e-4 && v.frozen < 0.0 && v.overlap <= 1e-9;
        if (!ok)
            printf("  case %d (N %d, %s A %.3f f %.3f, dt %g) FAILS: balance %.1e of the "
                   "peak, frozen at %g s, overlap %.1e m\n",
                   j, n, j % 2 ? "sawtooth" : "square", m->motor.amplitude,
                   m->motor.frequency, dt, v.imbalance, v.frozen, v.overlap);
        failed += !ok;
        model_free(m);
    }
    printf("  %d piston jumps into piles (%d with masses pushed along by a jump): balance within "
           "%.1e of the peak, deepest overlap %.1e m; %d failed\n",
           cases, jumped, worst, worst_overlap, failed);
    assert_int_equal(failed, 0);
    assert_true(jumped >= cases * 3 / 4);
}

/* The restitution rule between two masses: velocities after a contact closing at vl - vr. */
static void two_body(double ml, double *vl, double mr, double *vr)
{
    double c = *vl - *vr, mt = ml + mr, p = ml * *vl + mr * *vr;
    *vl = (p - mr * MODEL_RESTITUTION * c) / mt;
    *vr = (p + ml * MODEL_RESTITUTION * c) / mt;
}

/* Masses 2 and 3 of four touch; mass 4 hits mass 3 at 6 m/s. The pairwise rule: 4 on 3,
 * then 3 on 2, after which nothing closes (checked). The same impact on the row pressed
 * (a resting contact) and merely touching gives the same velocities, bit for bit. */
static void pressed_row_takes_the_pairwise_rule(void **state)
{
    (void)state;
    struct model *m = model_new(4);
    assert_non_null(m);
    m->boundary = BOUNDARY_WALL;
    const double mass[4] = {1.0, 2.0, 1.5, 1.0};
    memcpy(m->m, mass, sizeof mass);
    struct collision_limits l;
    collision_limits(&l, m);
    double sp = l.spacing, w = l.w;
    /* Centres 1.5, 3.0, 3.0 + w, 3.0 + 2 w: masses 3 and 4 touch too, as at the instant. */
    const double x[4] = {1.5 - sp, 3.0 - 2 * sp, 3.0 + w - 3 * sp, 3.0 + 2 * w - 4 * sp};
    double want[4] = {0.0, 0.0, 0.0, -6.0};
    two_body(mass[2], &want[2], mass[3], &want[3]);
    two_body(mass[1], &want[1], mass[2], &want[2]);
    assert_true(want[2] <= want[3] && want[1] <= want[2]); /* nothing closes after */
    double got[2][4];
    for (int pressed = 0; pressed < 2; pressed++) {
        struct rest *r = rest_new(4);
        assert_non_null(r);
        rest_clear(r, &l);
        r->enabled = true;
        if (pressed)
            rest_set(r, 2, true);
        memcpy(got[pressed], (const double[]){0.0, 0.0, 0.0, -6.0}, sizeof got[0]);
        struct collision_books b = {0.0, 0.0};
        int hits = events_hit(&l, m, r, 3, x, got[pressed], 0.0, 0.0, &b);
        printf("  %s row: v = %.6f %.6f %.6f %.6f after %d contacts (pairwise rule %.6f "
               "%.6f %.6f %.6f)\n",
               pressed ? "pressed" : "touching", got[pressed][0], got[pressed][1],
               got[pressed][2], got[pressed][3], hits, want[0], want[1], want[2], want[3]);
        assert_int_equal(hits, 2);
        for (int i = 0; i < 4; i++)
            assert_close(got[pressed][i], want[i], 1e-12);
        rest_free(r);
    }
    assert_memory_equal(got[0], got[1], sizeof got[0]);
    model_free(m);
}

/* The same in the running program: masses 2 and 3 pressed together by their outer
 * springs (they rest as one), or with springs too weak to press them; mass 4 hits at
 * 6 m/s. Across the step of the impact (dt 1e-5) the velocities go from those before to
 * the pairwise rule's within 1 % of each (the springs' own change over the step is 3e-4 m/s). */
static void resting_pair_hit_in_a_run(void **state)
{
    (void)state;
    for (int pressed = 0; pressed < 2; pressed++) {
        struct model *m = model_new(4);
        assert_non_null(m);
        m->boundary = BOUNDARY_WALL;
        const double mass[4] = {1.0, 2.0, 1.5, 1.0}, k[5] = {1.0, 20.0, 0.1, 20.0, 1.0};
        memcpy(m->m, mass, sizeof mass);
        for (int i = 0; i < 5; i++)
            m->k[i] = pressed ? k[i] : 0.0;
        for (int i = 0; i < 4; i++)
            m->c[i] = 0.0;
        double sp = MODEL_LENGTH / 5, w = model_block_width(m);
        const double x0[4] = {1.5 - sp, 3.0 - 2 * sp, 3.0 + w - 3 * sp, 3.05 + 2 * w - 4 * sp};
        const double v0[4] = {0.0, 0.0, 0.0, -6.0};
        struct sim *s = sim_new(m, 1e-5);
        assert_non_null(s);
        sim_reset(s, x0, v0);
        double before[4] = {0};
        int j = 0;
        for (; j < 10000; j++) {
            memcpy(before, sim_v(s), sizeof before);
            assert_int_equal(sim_step(s), SIM_OK);
            if (sim_last_contacts(s) > 0)
                break;
        }
        assert_true(j > 10 && j < 10000); /* the impact, after the pair came to rest */
        assert_true(before[1] == before[2]); /* resting (pressed) or at rest (touching) */
        double want[4];
        memcpy(want, before, sizeof want);
        two_body(mass[2], &want[2], mass[3], &want[3]);
        two_body(mass[1], &want[1], mass[2], &want[2]);
        const double *v = sim_v(s);
        printf("  %s pair hit at t = %.4f s: v = %.4f %.4f %.4f, pairwise rule %.4f %.4f "
               "%.4f; %d contacts\n",
               pressed ? "pressed" : "touching", sim_time(s), v[1], v[2], v[3], want[1],
               want[2], want[3], sim_last_contacts(s));
        for (int i = 1; i < 4; i++)
            assert_close(v[i], want[i], 0.01 * fabs(want[i]));
        sim_free(s);
        model_free(m);
    }
}

/* Where a pile thrown at the wall is after duration, and its contacts. */
static long pile_run(int n, double dt, double duration, enum integrator integ, double v0,
                     double spread, double *x)
{
    struct model *m = model_new(n);
    assert_non_null(m);
    m->motor.amplitude = 1.0; /* the piston's 1 m stroke these piles were measured with */
    struct sim *s = sim_new(m, dt);
    assert_non_null(s);
    sim_set_integrator(s, integ);
    double v[64];
    for (int i = 0; i < n; i++)
        v[i] = v0 * (1.0 + spread * i);
    sim_reset(s, NULL, v);
    long contacts = 0;
    for (int j = 0, steps = (int)lround(duration / dt); j < steps; j++) {
        assert_int_equal(sim_step(s), SIM_OK);
        contacts += sim_last_contacts(s);
    }
    memcpy(x, sim_x(s), (size_t)n * sizeof *x);
    sim_free(s);
    model_free(m);
    return contacts;
}

/* Every chain length locates its contacts and lets them rest (there was an economy mode
 * over 12 masses: a 13-mass pile's x3 at 5 s was -1.035, -1.027, -0.836 m at dt 0.01,
 * 0.001, 0.00025). A 13-mass pile (thrown at the wall at 5 to 8 m/s) and a 50-mass one (at
 * 0.5 m/s, the blocks 0.1 m wide) against rk4 at dt 1e-4: order >= 3 from dt 0.002 to
 * 0.0005, the same contacts at the two finest; exact at dt 0.01 on the 13 within 1e-8 m. */
static void long_piles_converge(void **state)
{
    (void)state;
    static const double dts[3] = {0.002, 0.001, 0.0005};
    const struct {
        int n;
        double v0, spread, duration;
    } piles[2] = {{13, -5.0, 0.05, 5.0}, {50, -0.5, 0.0, 3.0}};
    for (int p = 0; p < 2; p++) {
        int n = piles[p].n;
        double ref[64], x[64], err[3];
        long c[3], cref = pile_run(n, 1e-4, piles[p].duration, INTEGRATOR_RK4, piles[p].v0,
                                   piles[p].spread, ref);
        for (int d = 0; d < 3; d++) {
            c[d] = pile_run(n, dts[d], piles[p].duration, INTEGRATOR_RK4, piles[p].v0,
                            piles[p].spread, x);
            err[d] = 0.0;
            for (int i = 0; i < n; i++)
                err[d] = fmax(err[d], fabs(x[i] - ref[i]));
        }
        double order = 0.5 * log2(err[0] / err[2]);
        printf("  %d-mass pile: max |x - rk4(1e-4)| %.2e %.2e %.2e m at dt 0.002, 0.001, "
               "0.0005 (order %.2f); contacts %ld %ld %ld (%ld at dt 1e-4)\n",
               n, err[0], err[1], err[2], order, c[0], c[1], c[2], cref);
        assert_true(order >= 3.0);
        assert_true(c[1] == c[2]);
        assert_true(cref > 100);
        if (n <= 20) {
            long ce = pile_run(n, 0.01, piles[p].duration, INTEGRATOR_EXACT, piles[p].v0,
                               piles[p].spread, x);
            double e = 0.0;
            for (int i = 0; i < n; i++)
                e = fmax(e, fabs(x[i] - ref[i]));
            printf("  exact at dt 0.01: max |x - rk4(1e-4)| %.2e m, %ld contacts\n", e, ce);
            assert_true(e <= 1e-8);
            assert_true(ce == cref);
        }
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(freezes_move_on),
        cmocka_unit_test(sawtooth_pile_keeps_balance),
        cmocka_unit_test(jump_campaign),
        cmocka_unit_test(pressed_row_takes_the_pairwise_rule),
        cmocka_unit_test(resting_pair_hit_in_a_run),
        cmocka_unit_test(long_piles_converge),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
