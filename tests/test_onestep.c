/* test_onestep.c: every integrator's stability limit (core/limits.c, onestep.c,
 * stability.c) on random stiff chains with dampers of every size, against two checks of
 * the test's own:
 * - the one-step matrix written here from the integrators' formulas (not from the
 *   steppers), A = [[0, I], [-M^-1 K, -M^-1 C]] assembled here from the springs: its
 *   spectral radius (dgeev) is <= 1 at 0.25, 0.5, 0.75, 0.9 and 0.99 of the limit and
 *   above 1 at 1.01 of it;
 * - the simulation itself, a free decay from a small random start: 3 % past the limit it
 *   grows as the radius says (by 1e3 at least where the radius makes that happen within
 *   50000 steps), 3 % inside it it does not (at most 100 times its start).
 * Also: the issue's two chains (semi-implicit and verlet with dampers that are not
 * proportional to the masses) are judged unstable at its dt and blow up there, with the
 * walls too (the energy watch that stops such a run trips within 20 steps, and not inside
 * the limit, with exact, or on a stable driven chain over 60 s); and the
 * long-chain routes above ONESTEP_MAX masses (eigenvalue -1 for semi-implicit and
 * verlet, the eigenvalues' region for euler and rk4) against the same matrices at
 * N = 150. A force on an undamped mode's frequency: its drive error not known, not 100 %. */
#include "testutil.h"

#include <stdlib.h>
#include <string.h>

#include <lapacke.h>

#include "core/limits.h"
#include "core/modes.h"
#include "core/onestep.h"
#include "core/sim.h"
#include "core/stability.h"

static uint64_t rng_state;

static double uniform01(void)
{
    /* splitmix64 */
    uint64_t z = (rng_state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z ^= z >> 31;
    return (double)(z >> 11) / 9007199254740992.0;
}

/* lo * (hi / lo)^u: spread over decades. */
static double log_uniform(double lo, double hi)
{
    return lo * pow(hi / lo, uniform01());
}

/* A random stiff chain: masses 0.02..2 kg, springs 1..500 N/m, dampers 0..30 N s/m
 * (a fifth of them none, at least one not), any right end (the motor's held still). */
static struct model *random_chain(int n)
{
    struct model *m = model_new(n);
    bool damped = false;
    for (int i = 0; i < n; i++) {
        m->m[i] = log_uniform(0.02, 2.0);
        m->c[i] = uniform01() < 0.2 ? 0.0 : log_uniform(0.01, 30.0);
        damped = damped || m->c[i] > 0.0;
    }
    if (!damped)
        m->c[0] = 1.0;
    for (int j = 0; j <= n; j++)
        m->k[j] = log_uniform(1.0, 500.0);
    m->boundary = (enum boundary)(uniform01() * 3.0);
    m->motor.amplitude = 0.0; /* free decay: the motor end held still */
    m->collisions = false;
    return m;
}

/* The test's own A (2N x 2N, column-major) from the springs, masses and dampers. */
static void first_order(const struct model *m, double *a)
{
    int n = m->n, n2 = 2 * n;
    memset(a, 0, (size_t)n2 * n2 * sizeof *a);
    for (int i = 0; i < n; i++) {
        a[i + (size_t)(n + i) * n2] = 1.0;
        double right = i + 1 < n ? m->k[i + 1] : m->boundary == BOUNDARY_FREE ? 0.0 : m->k[n];
        a[n + i + (size_t)i * n2] = -(m->k[i] + right) / m->m[i];
        if (i > 0)
            a[n + i + (size_t)(i - 1) * n2] = m->k[i] / m->m[i];
        if (i + 1 < n)
            a[n + i + (size_t)(i + 1) * n2] = m->k[i + 1] / m->m[i];
        a[n + i + (size_t)(n + i) * n2] = -m->c[i] / m->m[i];
    }
}

/* c = a b, all n x n column-major. */
static void matmul(int n, const double *a, const double *b, double *c)
{
    for (int j = 0; j < n; j++)
        for (int i = 0; i < n; i++) {
            double sum = 0.0;
            for (int k = 0; k < n; k++)
                sum += a[i + (size_t)k * n] * b[k + (size_t)j * n];
            c[i + (size_t)j * n] = sum;
        }
}

/* The one-step matrix of integrator i at h from the formulas:
 * euler         S = I + hA;
 * rk4           S = I + hA + (hA)^2/2 + (hA)^3/6 + (hA)^4/24;
 * semi-implicit v1 = v + h(-Kx - Cv), x1 = x + h v1      (K, C: M^-1 K, M^-1 C);
 * verlet        vh = v + h/2 (-Kx - Cv), x1 = x + h vh,
 *               (I + h/2 C) v1 = vh - h/2 K x1. */
static void step_matrix(const struct model *m, enum integrator in, double h, double *s)
{
    int n = m->n, n2 = 2 * n;
    size_t sq = (size_t)n2 * n2;
    double *a = malloc(3 * sq * sizeof *a), *p = a + sq, *q = p + sq;
    first_order(m, a);
    if (in == INTEGRATOR_EULER || in == INTEGRATOR_RK4) {
        /* Horner: S = I + hA (I + hA/2 (I + hA/3 (I + hA/4))) */
        int top = in == INTEGRATOR_EULER ? 1 : 4;
        memset(p, 0, sq * sizeof *p);
        for (int k = 0; k < n2; k++)
            p[k + (size_t)k * n2] = 1.0;
        for (int d = top; d >= 1; d--) {
            matmul(n2, a, p, q);
            for (size_t k = 0; k < sq; k++)
                p[k] = q[k] * h / d;
            for (int k = 0; k < n2; k++)
                p[k + (size_t)k * n2] += 1.0;
        }
        memcpy(s, p, sq * sizeof *s);
    } else {
        /* column by column: the state e_j stepped by the formulas */
        double *x = p, *v = x + n, *vh = v + n, *acc = vh + n;
        for (int j = 0; j < n2; j++) {
            memset(p, 0, (size_t)(4 * n) * sizeof *p);
            (j < n ? x : v - n)[j] = 1.0;
            for (int i = 0; i < n; i++) { /* acc = -K x - C v, from A's lower rows */
                acc[i] = 0.0;
                for (int k = 0; k < n2; k++)
                    acc[i] += a[n + i + (size_t)k * n2] * (k < n ? x[k] : v[k - n]);
            }
            double kick = in == INTEGRATOR_SEMI_IMPLICIT ? h : 0.5 * h;
            for (int i = 0; i < n; i++)
                vh[i] = v[i] + kick * acc[i];
            for (int i = 0; i < n; i++)
                x[i] += h * vh[i];
            if (in == INTEGRATOR_VERLET) {
                for (int i = 0; i < n; i++) { /* -K x1 alone: A's lower left block */
                    double kx = 0.0;
                    for (int k = 0; k < n; k++)
                        kx += a[n + i + (size_t)k * n2] * x[k];
                    v[i] = (vh[i] + 0.5 * h * kx) / (1.0 + 0.5 * h * m->c[i] / m->m[i]);
                }
            } else {
                memcpy(v, vh, (size_t)n * sizeof *v);
            }
            memcpy(s + (size_t)j * n2, x, (size_t)n * sizeof *s);
            memcpy(s + (size_t)j * n2 + n, v, (size_t)n * sizeof *s);
        }
    }
    free(a);
}

/* The spectral radius of the test's one-step matrix. */
static double radius(const struct model *m, enum integrator in, double h)
{
    int n2 = 2 * m->n;
    double *s = malloc(((size_t)n2 * n2 + 2 * n2) * sizeof *s), *re = s + (size_t)n2 * n2,
           *im = re + n2;
    step_matrix(m, in, h, s);
    assert_int_equal(LAPACKE_dgeev(LAPACK_COL_MAJOR, 'N', 'N', n2, s, n2, re, im, NULL, 1, NULL,
                                   1), 0);
    double rho = 0.0;
    for (int k = 0; k < n2; k++)
        rho = fmax(rho, hypot(re[k], im[k]));
    free(s);
    return rho;
}

/* max |x_i| after steps of the simulation from x0 (v = 0), or INFINITY once a step fails
 * or the cap acts. */
static double run(const struct model *m, enum integrator in, double h, const double *x0,
                  long steps)
{
    struct sim *s = sim_new(m, h);
    sim_set_integrator(s, in);
    sim_reset(s, x0, NULL);
    double peak = 0.0;
    for (long k = 0; k < steps; k++)
        if (sim_step(s) != SIM_OK || sim_last_capped(s)) {
            sim_free(s);
            return INFINITY;
        }
    for (int i = 0; i < m->n; i++)
        peak = fmax(peak, fabs(sim_x(s)[i]));
    sim_free(s);
    return peak;
}

/* Steps of the simulation until the runaway watch (limits_runaway_*) trips: the step,
 * or 0 when it does not within steps. */
static long runaway_step(const struct model *m, enum integrator in, double h, const double *x0,
                         long steps)
{
    struct sim *s = sim_new(m, h);
    struct limits_runaway watch;
    struct energy e;
    sim_set_integrator(s, in);
    sim_reset(s, x0, NULL);
    sim_energy(s, &e);
    limits_runaway_start(&watch, m, &e);
    long k = 1;
    for (; k <= steps; k++) {
        assert_int_equal(sim_step(s), SIM_OK);
        sim_energy(s, &e);
        if (limits_runaway_check(&watch, &e))
            break;
    }
    sim_free(s);
    return k <= steps ? k : 0;
}

static const enum integrator integrators[] = {INTEGRATOR_EULER, INTEGRATOR_SEMI_IMPLICIT,
                                              INTEGRATOR_VERLET, INTEGRATOR_RK4};

/* The limit of chain m for integrator in, checked against the matrix and the run;
 * *grew_seen counts the runs past the limit whose growth could be seen. */
static void check_limit(const struct model *m, enum integrator in, double h, int *grew_seen)
{
    const char *name = integrator_name(in);
    int n = m->n;
    if (!(h > 0.0 && isfinite(h)))
        fail_msg("N = %d, %s: limit %g", n, name, h);
    static const double inside[] = {0.25, 0.5, 0.75, 0.9, 0.99};
    for (size_t k = 0; k < sizeof inside / sizeof *inside; k++) {
        double rho = radius(m, in, inside[k] * h);
        if (!(rho <= 1.0 + 1e-9))
            fail_msg("N = %d, %s: radius %.12g at %.2f of the limit %g s", n, name, rho,
                     inside[k], h);
    }
    double rho_out = radius(m, in, 1.01 * h);
    if (!(rho_out > 1.0))
        fail_msg("N = %d, %s: radius %.15g at 1.01 of the limit %g s", n, name, rho_out, h);
    /* The run: 3 % past the limit it grows as the radius there says; 3 % inside not. */
    double rho = radius(m, in, 1.03 * h);
    double x0[ONESTEP_MAX], start = 0.0;
    for (int i = 0; i < n; i++) {
        x0[i] = 1e-9 * (2.0 * uniform01() - 1.0);
        start = fmax(start, fabs(x0[i]));
    }
    long steps = (long)ceil(log(1e9) / log(rho));
    if (rho > 1.0 && steps <= 50000) {
        double out = run(m, in, 1.03 * h, x0, steps);
        if (!(out > 1e3 * start))
            fail_msg("N = %d, %s: %ld steps 3 %% past the limit %g s took %g to %g "
                     "(radius %.6g)", n, name, steps, h, start, out, rho);
        ++*grew_seen;
    } else {
        steps = 5000;
    }
    double in_run = run(m, in, 0.97 * h, x0, steps);
    if (!(in_run <= 100.0 * start))
        fail_msg("N = %d, %s: %ld steps 3 %% inside the limit %g s took %g to %g", n, name,
                 steps, h, start, in_run);
}

/* 48 random stiff chains of 1 to 10 masses and 4 of 11 to 20: every integrator's limit
 * holds against the matrix and the run; semi-implicit's and verlet's equal the first
 * h with the eigenvalue -1 (stability.c, the route of longer chains). */
static void random_stiff_chains(void **state)
{
    (void)state;
    rng_state = 17;
    int chains = 0, grew = 0, checked = 0, crossing_equal = 0, crossing_checked = 0;
    for (int c = 0; c < 52; c++) {
        int n = c < 48 ? 1 + c % 10 : 11 + (int)(uniform01() * 10.0);
        struct model *m = random_chain(n);
        struct limits_mode mode[ONESTEP_MAX];
        assert_int_equal(limits_modes(m, mode), 0);
        double w2[2 * ONESTEP_MAX];
        assert_int_equal(modes_modal(m, w2, w2 + n), 0);
        for (size_t k = 0; k < sizeof integrators / sizeof *integrators; k++) {
            enum integrator in = integrators[k];
            double h = limits_stable_dt(m, mode, n, in);
            check_limit(m, in, h, &grew);
            checked++;
            if (in == INTEGRATOR_SEMI_IMPLICIT || in == INTEGRATOR_VERLET) {
                double cross = in == INTEGRATOR_VERLET ? stability_verlet(w2[n - 1])
                                                       : stability_semi_implicit(m);
                /* never past the limit; equal to it unless -1 is only touched */
                if (!(cross <= h * (1.0 + 1e-9)))
                    fail_msg("N = %d, %s: the -1 crossing %.12g s is past the limit %.12g s",
                             n, integrator_name(in), cross, h);
                crossing_equal += fabs(cross - h) <= 1e-7 * h;
                crossing_checked++;
            }
        }
        chains++;
        model_free(m);
    }
    printf("%d chains, %d limits checked; %d runs past the limit grew as the radius said; "
           "semi-implicit and verlet: the -1 crossing is the limit in %d of %d\n", chains,
           checked, grew, crossing_equal, crossing_checked);
    assert_true(grew > checked / 2);
    assert_int_equal(crossing_equal, crossing_checked);
}

/* The issue's chains, dampers not proportional to the masses: judged unstable at their
 * dt, and the run blows up there (the cap acts), while 0.97 of the limit does not. */
static void issue_chains(void **state)
{
    (void)state;
    struct model *a = model_new(2), *b = model_new(2);
    double ma[] = {2, 0.1}, ka[] = {10, 50, 10}, ca[] = {10, 5};
    double kb[] = {100, 50, 100}, cb[] = {20, 0};
    for (int i = 0; i < 2; i++) {
        a->m[i] = ma[i], a->c[i] = ca[i], b->m[i] = 0.1, b->c[i] = cb[i];
    }
    for (int j = 0; j < 3; j++)
        a->k[j] = ka[j], b->k[j] = kb[j];
    a->boundary = b->boundary = BOUNDARY_WALL;
    a->collisions = b->collisions = false;
    struct {
        struct model *m;
        enum integrator in;
        double dt;
        double x0[2];
    } cases[] = {{a, INTEGRATOR_SEMI_IMPLICIT, 0.04, {0.01, 0}}, {b, INTEGRATOR_VERLET, 0.05, {0, 0.01}}};
    for (int c = 0; c < 2; c++) {
        struct limits_mode mode[2];
        struct limits l;
        assert_int_equal(limits_modes(cases[c].m, mode), 0);
        limits_judge(mode, 2, cases[c].m, cases[c].in, cases[c].dt, &l);
        assert_true(limits_unstable(&l));
        printf("issue chain %d, %s: stable dt %.6g s, radius at dt %.6g\n", c + 1,
               integrator_name(cases[c].in), l.stable_dt,
               radius(cases[c].m, cases[c].in, cases[c].dt));
        assert_true(radius(cases[c].m, cases[c].in, cases[c].dt) > 1.1);
        assert_true(isinf(run(cases[c].m, cases[c].in, cases[c].dt, cases[c].x0, 200)));
        assert_true(run(cases[c].m, cases[c].in, 0.97 * l.stable_dt, cases[c].x0, 2000) < 0.02);
        /* With the walls the velocities may never reach the cap; the energy watch trips
         * all the same, within 20 steps, and never inside the limit or with exact. */
        cases[c].m->collisions = true;
        long k = runaway_step(cases[c].m, cases[c].in, cases[c].dt, cases[c].x0, 2000);
        printf("  with contacts: the watch trips at step %ld\n", k);
        assert_true(k > 0 && k <= 20);
        assert_int_equal(runaway_step(cases[c].m, cases[c].in, 0.97 * l.stable_dt, cases[c].x0,
                                      4000), 0);
        assert_int_equal(runaway_step(cases[c].m, INTEGRATOR_EXACT, cases[c].dt, cases[c].x0,
                                      4000), 0);
        cases[c].m->collisions = false;
    }
    /* A driven chain at rest, stable: the motor's work makes room for what it puts in. */
    struct model *d = model_new(3);
    d->motor.frequency = 0.6; /* near a mode: the energy builds up */
    for (int in = 0; in < INTEGRATOR_COUNT; in++)
        assert_int_equal(runaway_step(d, (enum integrator)in, 0.002, (double[3]){0}, 30000), 0);
    model_free(d);
    model_free(a);
    model_free(b);
}

/* Above ONESTEP_MAX masses: N = 150 with random dampers. Semi-implicit and verlet (the
 * -1 crossing) are exact against the test's matrix; euler and rk4 (the region) are never
 * past the limit, and with dampers proportional to the masses equal to it. */
static void long_chains(void **state)
{
    (void)state;
    rng_state = 4242;
    const int n = 150;
    for (int proportional = 0; proportional < 2; proportional++) {
        struct model *m = random_chain(n);
        m->boundary = BOUNDARY_WALL;
        if (proportional)
            for (int i = 0; i < n; i++)
                m->c[i] = 0.5 * m->m[i];
        struct limits_mode *mode = malloc((size_t)n * sizeof *mode);
        assert_int_equal(limits_modes(m, mode), 0);
        for (size_t k = 0; k < sizeof integrators / sizeof *integrators; k++) {
            enum integrator in = integrators[k];
            double h = limits_stable_dt(m, mode, n, in);
            double below = radius(m, in, 0.999 * h), above = radius(m, in, 1.01 * h);
            printf("N = %d, %s dampers, %s: limit %.6g s, radius %.12g below, %.12g above\n", n,
                   proportional ? "proportional" : "random", integrator_name(in), h, below,
                   above);
            assert_true(below <= 1.0 + 1e-9);
            bool exact = in == INTEGRATOR_SEMI_IMPLICIT || in == INTEGRATOR_VERLET || proportional;
            if (exact && !(above > 1.0))
                fail_msg("%s: radius %.15g at 1.01 of the limit", integrator_name(in), above);
        }
        free(mode);
        model_free(m);
    }
}

/* A force driving an undamped mass on its own natural frequency has no steady motion: the
 * drive's error is not known (NAN), not a rough 100 %; with a damper it is small at rk4's
 * 200 steps a period. The same drive one percent off resonance, undamped, is judged. */
static void drive_on_an_undamped_mode(void **state)
{
    (void)state;
    struct model *m = model_new(1);
    m->k[0] = 10.0;
    m->k[1] = 0.0;
    m->c[0] = 0.0;
    m->boundary = BOUNDARY_FREE;
    m->force = 1.0;
    model_sync(m);
    double f = sqrt(10.0) / (2.0 * M_PI);
    struct onestep *o = onestep_new(m);
    assert_true(isnan(onestep_drive_error(o, INTEGRATOR_RK4, 0.005, f)));
    double off = onestep_drive_error(o, INTEGRATOR_RK4, 0.005, 1.01 * f);
    assert_true(off >= 0.0 && off < 0.01);
    onestep_free(o);
    m->c[0] = 0.2;
    o = onestep_new(m);
    double damped = onestep_drive_error(o, INTEGRATOR_RK4, 0.005, f);
    assert_true(damped >= 0.0 && damped < 0.01);
    onestep_free(o);
    model_free(m);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(random_stiff_chains),
        cmocka_unit_test(issue_chains),
        cmocka_unit_test(long_chains),
        cmocka_unit_test(drive_on_an_undamped_mode),
    };
    return cmocka_run_group_tests_name("onestep", tests, NULL, NULL);
}
