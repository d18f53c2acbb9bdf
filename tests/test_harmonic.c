/* test_harmonic.c: harmonic balance and the simulated sweep of chains with cubic springs.
 * One hardening mass: the continuation's folds against the roots of the amplitude
 * equation a^2 [(k - m w^2 + 3/4 k3 a^2)^2 + (c w)^2] = F^2 found here by GSL's Brent
 * solver, the middle branch unstable, the stable branches against long simulations, the
 * simulated sweeps' jumps beside the folds; the same with the force input and a damper
 * beside the spring in place of the motor and part of the ground damper. Three masses: the
 * stable branches against the simulated sweep, and a fold followed. Weakly cubic chains
 * with every damper and both inputs: the linear complex solve. */
#include "testutil.h"

#include <complex.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>
#include <stdlib.h>

#include "core/harmonic.h"
#include "core/model.h"
#include "core/sim.h"
#include "core/sweeprun.h"

/* The duffing preset's mass: wall spring 10 + 4 s^3, motor spring 10, c 0.3, A 0.25:
 * k = 20, k3 = 4, F = 10 A = 2.5 N. */
static struct model *duffing(void)
{
    struct model *m = model_new(1);
    m->k[0] = m->k[1] = 10.0;
    m->k3[0] = 4.0;
    m->c[0] = 0.3;
    model_set_cubic(m);
    m->motor = (struct motor){WAVE_SINE, 0.25, 1.0, 0.0};
    m->collisions = false;
    return m;
}

/* The same oscillator driven by the force input instead: a wall at the right, 2.5 N on the
 * mass, and its damping split between a ground damper (0.1) and a damper beside the wall's
 * spring (0.2): the same amplitude equation, C = 0.1 + 0.2. */
static struct model *duffing_forced(void)
{
    struct model *m = duffing();
    m->boundary = BOUNDARY_WALL;
    m->c[0] = 0.1;
    m->cs[0] = 0.2;
    m->force = 2.5;
    m->force_on = 0;
    model_sync(m);
    return m;
}

/* The oscillator a test takes: the motor's (state NULL) or the forced one. */
static struct model *oscillator(void **state)
{
    return *state ? duffing_forced() : duffing();
}

static int forced_kind = 1; /* the prestate choosing duffing_forced */

#define K 20.0
#define K3 4.0
#define C 0.3
#define F 2.5

/* At a fold of the amplitude equation, G(p) = p [(K - w^2 + q p)^2 + (C w)^2] - F^2 = 0
 * and G'(p) = 3 q^2 p^2 + 4 q (K - w^2) p + (K - w^2)^2 + (C w)^2 = 0 (q = 3/4 K3,
 * p = a^2): for a w, the roots p of G' (upper: the larger, lower: the smaller), and G
 * there. */
static double fold_g(double w, void *which)
{
    double q = 0.75 * K3, d = K - w * w;
    double disc = 16.0 * q * q * d * d - 12.0 * q * q * (d * d + C * C * w * w);
    double p = (-4.0 * q * d + (*(int *)which ? 1.0 : -1.0) * sqrt(fmax(disc, 0.0))) /
               (6.0 * q * q);
    return p * ((d + q * p) * (d + q * p) + C * C * w * w) - F * F;
}

static double brent(int which, double lo, double hi)
{
    gsl_function fn = {fold_g, &which};
    gsl_root_fsolver *s = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
    gsl_root_fsolver_set(s, &fn, lo, hi);
    for (int i = 0; i < 200; i++) {
        gsl_root_fsolver_iterate(s);
        lo = gsl_root_fsolver_x_lower(s);
        hi = gsl_root_fsolver_x_upper(s);
        if (gsl_root_test_interval(lo, hi, 0.0, 1e-15) == GSL_SUCCESS)
            break;
    }
    double w = gsl_root_fsolver_root(s);
    gsl_root_fsolver_free(s);
    return w / (2.0 * M_PI);
}

static void folds_match_the_amplitude_equation(void **state)
{
    struct model *m = oscillator(state);
    char err[200];
    struct harmonic_curve *c = harmonic_trace(m, 0.5, 1.5, err, sizeof err);
    assert_non_null(c);
    assert_true(c->complete);
    assert_int_equal(c->folds, 2);
    /* Where G' has real roots at all: (K - w^2)^2 >= 3 (C w)^2, w^2 > K. */
    double upper = brent(1, 2.0 * M_PI * 0.81, 2.0 * M_PI * 0.9);
    double lower = brent(0, 2.0 * M_PI * 0.75, 2.0 * M_PI * 0.81);
    printf("  folds %.12g and %.12g Hz; the amplitude equation's %.12g and %.12g Hz\n",
           c->fold_f[0], c->fold_f[1], upper, lower);
    assert_true(fabs(c->fold_f[0] / upper - 1.0) < 1e-6);
    assert_true(fabs(c->fold_f[1] / lower - 1.0) < 1e-6);
    assert_true(upper / lower > 1.05); /* the folds are 5 % apart, as the test asks */
    /* Inside the band three motions, the middle unstable; outside one, stable. */
    struct harmonic_solution s[4];
    double room[8];
    for (int b = 0; b < 4; b++)
        s[b].amp = room + 2 * b, s[b].phase = room + 2 * b + 1;
    double mid = 0.5 * (upper + lower);
    assert_int_equal(harmonic_at(m, c, mid, s, 4), 3);
    assert_true(s[0].stable && !s[1].stable && s[2].stable);
    assert_true(s[0].amp[0] > s[1].amp[0] && s[1].amp[0] > s[2].amp[0]);
    for (int b = 0; b < 3; b++) { /* each on the amplitude equation */
        double w = 2.0 * M_PI * mid, a = s[b].amp[0], d = K - w * w + 0.75 * K3 * a * a;
        assert_close(a * a * (d * d + C * C * w * w), F * F, 1e-9);
    }
    assert_int_equal(harmonic_at(m, c, 0.6, s, 4), 1);
    assert_true(s[0].stable);
    harmonic_curve_free(c);
    model_free(m);
}

/* The largest first-harmonic amplitude of mass i over the last period of a long run from
 * x0, v0 at f: what the chain settles to. */
static double long_run(const struct model *m, double f, const double *x0, const double *v0,
                       int i, double seconds)
{
    struct model *d = model_new(m->n);
    model_copy(d, m);
    d->motor.frequency = f;
    struct sim *s = sim_new(d, 0.002);
    sim_reset(s, x0, v0);
    long steps = lround(1.0 / (f * 0.002)), total = lround(seconds / 0.002 / steps) * steps;
    double in = 0.0, quad = 0.0, w = 2.0 * M_PI * f;
    for (long k = 1; k <= total; k++) {
        sim_step(s);
        if (k > total - steps) {
            in += sim_x(s)[i] * sin(w * sim_time(s));
            quad += sim_x(s)[i] * cos(w * sim_time(s));
        }
    }
    sim_free(s);
    model_free(d);
    return 2.0 * hypot(in, quad) / (double)steps;
}

/* Each stable branch's amplitude, against a long simulation started on it (300 s: the
 * transient decays as exp(-c t / 2m), e^-75): within 1 %, the single harmonic's error. */
static void stable_branches_match_long_runs(void **state)
{
    struct model *m = oscillator(state);
    char err[200];
    struct harmonic_curve *c = harmonic_trace(m, 0.5, 1.5, err, sizeof err);
    struct harmonic_solution s[4];
    double room[8], worst = 0.0;
    for (int b = 0; b < 4; b++)
        s[b].amp = room + 2 * b, s[b].phase = room + 2 * b + 1;
    const double fs[] = {0.6, 0.75, 0.8, 0.82, 1.0};
    for (size_t k = 0; k < sizeof fs / sizeof *fs; k++) {
        int found = harmonic_at(m, c, fs[k], s, 4);
        for (int b = 0; b < found; b++) {
            if (!s[b].stable)
                continue;
            /* x = X sin(wt + phi): at t = 0, x = X sin phi, v = X w cos phi. */
            double ph = s[b].phase[0] * M_PI / 180.0, X = s[b].amp[0];
            double x0 = X * sin(ph), v0 = X * 2.0 * M_PI * fs[k] * cos(ph);
            double a = long_run(m, fs[k], &x0, &v0, 0, 300.0);
            worst = fmax(worst, fabs(a / X - 1.0));
            printf("  %.2f Hz branch %d: balance %.6f m, simulation %.6f m\n", fs[k],
                   s[b].branch, X, a);
            assert_true(fabs(a / X - 1.0) < 0.01);
        }
    }
    printf("  worst %.3g\n", worst);
    harmonic_curve_free(c);
    model_free(m);
}

/* The simulated sweep up stays on the high branch past the lower fold and drops within
 * 0.5 % above the upper fold; the sweep down jumps up within 0.5 % below the lower
 * fold's... at it: 0.1 % steps. */
static void sweeps_jump_at_the_folds(void **state)
{
    (void)state;
    struct model *m = duffing();
    char err[200];
    struct harmonic_curve *c = harmonic_trace(m, 0.5, 1.5, err, sizeof err);
    double upper = c->fold_f[0], lower = c->fold_f[1], amp, phase, jump = NAN;
    for (int dir = 0; dir < 2; dir++) {
        struct sim *s = sim_new(m, 0.01);
        double f0 = dir == 0 ? 0.95 * lower : 1.05 * upper, step = dir == 0 ? 1.001 : 1 / 1.001;
        double prev = NAN, most = 0.0;
        jump = NAN;
        /* The jump: the largest change of amplitude from one point to the next. */
        for (double f = f0; dir == 0 ? f < 1.05 * upper : f > 0.95 * lower; f *= step) {
            struct sweeprun_point p = sweeprun_point(s, f, &amp, &phase);
            assert_false(p.diverged);
            double change = dir == 0 ? prev / amp : amp / prev;
            if (change > most)
                most = change, jump = f;
            prev = amp;
        }
        assert_true(most > 1.5); /* the jump, against 0.1 % steps elsewhere */
        sim_free(s);
        printf("  sweep %s jumps at %.6f Hz, the fold at %.6f Hz\n", dir ? "down" : "up", jump,
               dir ? lower : upper);
        if (dir == 0)
            assert_true(jump > upper && jump <= 1.005 * upper);
        else
            assert_true(jump < lower && jump >= 0.995 * lower);
    }
    harmonic_curve_free(c);
    model_free(m);
}

/* Three masses, every spring hardening: the continuation turns at least one fold, and on
 * its stable branches matches the simulated sweep up (and down) within 2 %. */
static void three_masses_match_the_simulated_sweeps(void **state)
{
    (void)state;
    struct model *m = model_new(3);
    for (int j = 0; j <= 3; j++)
        m->k3[j] = 5.0;
    for (int i = 0; i < 3; i++)
        m->c[i] = 0.2;
    model_set_cubic(m);
    m->motor = (struct motor){WAVE_SINE, 0.1, 1.0, 0.0};
    m->collisions = false;
    char err[200];
    double lo = 0.3, hi = 1.1;
    struct harmonic_curve *c = harmonic_trace(m, lo, hi, err, sizeof err);
    assert_non_null(c);
    printf("  %d folds:", c->folds);
    for (int k = 0; k < c->folds; k++)
        printf(" %.4f Hz", c->fold_f[k]);
    printf("\n");
    assert_true(c->folds >= 1);
    struct harmonic_solution s[8];
    double room[48], amp[3], phase[3], worst = 0.0;
    int compared = 0;
    for (int b = 0; b < 8; b++)
        s[b].amp = room + 6 * b, s[b].phase = room + 6 * b + 3;
    for (int dir = 0; dir < 2; dir++) {
        struct sim *sim = sim_new(m, 0.005);
        for (int r = 0; r <= 80; r++) {
            double f = dir == 0 ? lo + 0.01 * r : hi - 0.01 * r;
            struct sweeprun_point p = sweeprun_point(sim, f, amp, phase);
            if (!p.settled)
                continue;
            int found = harmonic_at(m, c, f, s, 8), best = -1;
            double dist = INFINITY;
            for (int b = 0; b < found; b++) { /* the branch the chain is on */
                double d = 0.0;
                for (int i = 0; i < 3; i++)
                    d = fmax(d, fabs(s[b].amp[i] - amp[i]) / fmax(amp[i], 1e-3));
                if (s[b].stable && d < dist)
                    dist = d, best = b;
            }
            assert_true(best >= 0);
            worst = fmax(worst, dist);
            compared++;
        }
        sim_free(sim);
    }
    printf("  %d settled points, worst relative difference %.3g\n", compared, worst);
    assert_true(compared > 100);
    assert_true(worst < 0.02);
    harmonic_curve_free(c);
    model_free(m);
}

/* (K - w^2 M + i w C) X = G by Gaussian elimination with partial pivoting, n <= 8: the
 * linear chain's steady motion, X the complex amplitudes of x = Im(X e^{i w t}). */
static void complex_solve(int n, double complex a[8][9], double complex *x)
{
    for (int col = 0; col < n; col++) {
        int p = col;
        for (int r = col + 1; r < n; r++)
            if (cabs(a[r][col]) > cabs(a[p][col]))
                p = r;
        for (int k = 0; k <= n; k++) {
            double complex t = a[col][k];
            a[col][k] = a[p][k], a[p][k] = t;
        }
        for (int r = col + 1; r < n; r++) {
            double complex f = a[r][col] / a[col][col];
            for (int k = col; k <= n; k++)
                a[r][k] -= f * a[col][k];
        }
    }
    for (int r = n - 1; r >= 0; r--) {
        double complex sum = a[r][n];
        for (int k = r + 1; k < n; k++)
            sum -= a[r][k] * x[k];
        x[r] = sum / a[r][r];
    }
}

/* Random chains of 2 to 5 masses with ground and spring dampers, the motor and a force on
 * a mass together, their cubic constants 1e-9 N/m^3 (a nonlinear chain whose cubic part
 * moves nothing measurable): every harmonic-balance point matches the complex solve of
 * (K - w^2 M + i w C) X = (k_N + i w cs_N) A e_N + F e_K to 1e-8, amplitude and phase. */
static void weak_cubic_matches_the_complex_solve(void **state)
{
    (void)state;
    uint64_t seed = 0x9e3779b97f4a7c15ULL;
    double worst = 0.0;
    for (int chain = 0; chain < 6; chain++) {
        int n = 2 + chain % 4;
        struct model *m = model_new(n);
        for (int i = 0; i < n; i++) {
            m->m[i] = test_uniform(&seed, 0.5, 2.0);
            m->c[i] = test_uniform(&seed, 0.0, 0.3);
        }
        for (int j = 0; j <= n; j++) {
            m->k[j] = test_uniform(&seed, 5.0, 20.0);
            m->cs[j] = test_uniform(&seed, 0.0, 0.5);
            m->k3[j] = 1e-9;
        }
        m->boundary = chain % 3 == 2 ? BOUNDARY_WALL : BOUNDARY_MOTOR;
        m->motor = (struct motor){WAVE_SINE, 0.05, 1.0, 0.0};
        m->force = test_uniform(&seed, 0.1, 1.0);
        m->force_on = chain % n;
        m->collisions = false;
        model_sync(m);
        char err[200];
        struct harmonic_curve *c = harmonic_trace(m, 0.1, 1.5, err, sizeof err);
        assert_non_null(c);
        assert_int_equal(c->folds, 0);
        double room[16];
        struct harmonic_solution s = {.amp = room, .phase = room + 8};
        for (double f = 0.1; f <= 1.5; f += 0.07) {
            assert_int_equal(harmonic_at(m, c, f, &s, 1), 1);
            assert_true(s.stable);
            double w = 2.0 * M_PI * f;
            double complex a[8][9] = {{0}}, x[8];
            for (int i = 0; i < n; i++) {
                a[i][i] = -w * w * m->m[i] + I * w * m->c[i];
                if (i == m->force_on)
                    a[i][n] += m->force;
            }
            for (int j = 0; j <= n; j++) {
                double complex z = m->k[j] + I * w * m->cs[j];
                if (j < n)
                    a[j][j] += z;
                if (j > 0 && j < n)
                    a[j - 1][j - 1] += z, a[j][j - 1] -= z, a[j - 1][j] -= z;
                if (j == n && m->boundary == BOUNDARY_MOTOR)
                    a[n - 1][n - 1] += z, a[n - 1][n] += z * m->motor.amplitude;
                if (j == n && m->boundary == BOUNDARY_WALL)
                    a[n - 1][n - 1] += z;
            }
            complex_solve(n, a, x);
            for (int i = 0; i < n; i++) {
                double complex hb = s.amp[i] * cexp(I * s.phase[i] * M_PI / 180.0);
                double d = cabs(hb - x[i]) / cabs(x[i]);
                worst = fmax(worst, d);
                if (!(d < 1e-8))
                    fail_msg("chain %d, %.2f Hz, mass %d: balance %.10g at %.6g deg, complex "
                             "solve %.10g at %.6g deg", chain, f, i + 1, s.amp[i], s.phase[i],
                             cabs(x[i]), carg(x[i]) * 180.0 / M_PI);
            }
        }
        harmonic_curve_free(c);
        model_free(m);
    }
    printf("  worst relative difference %.3g\n", worst);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(folds_match_the_amplitude_equation),
        cmocka_unit_test_prestate(folds_match_the_amplitude_equation, &forced_kind),
        cmocka_unit_test(stable_branches_match_long_runs),
        cmocka_unit_test_prestate(stable_branches_match_long_runs, &forced_kind),
        cmocka_unit_test(weak_cubic_matches_the_complex_solve),
        cmocka_unit_test(sweeps_jump_at_the_folds),
        cmocka_unit_test(three_masses_match_the_simulated_sweeps),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
