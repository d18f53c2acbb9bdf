/* test_modes.c: natural frequencies and shapes against the closed forms of the uniform
 * chain, the eigen-equation itself on a non-uniform chain, the steady state against
 * the 1-DOF formula and against a long simulation, damping ratios and phases against the
 * roots of the characteristic polynomial, modal energies against the chain's. The limits of dt are in
 * test_limits.c. */
#include "testutil.h"

#include <complex.h>
#include <stdlib.h>

#include "core/limits.h"
#include "core/modes.h"
#include "core/sim.h"

static struct model *uniform(int n, double k, double m, enum boundary b)
{
    struct model *md = model_new(n);
    for (int i = 0; i < n; i++)
        md->m[i] = m;
    for (int j = 0; j <= n; j++)
        md->k[j] = k;
    md->boundary = b;
    return md;
}

/* Fixed-fixed (wall and motor ends): w_j = 2 sqrt(k/m) sin(j pi / (2(N+1))). */
static void uniform_fixed_closed_form(void **state)
{
    (void)state;
    const int sizes[] = {1, 2, 3, 5, 10, 100};
    for (size_t s = 0; s < sizeof sizes / sizeof *sizes; s++) {
        for (int b = BOUNDARY_MOTOR; b <= BOUNDARY_WALL; b++) {
            int n = sizes[s];
            struct model *md = uniform(n, 10.0, 1.0, (enum boundary)b);
            double *f = malloc((size_t)n * sizeof *f);
            assert_int_equal(modes_compute(md, f, NULL), 0);
            for (int j = 1; j <= n; j++) {
                double w = 2.0 * sqrt(10.0) * sin(j * M_PI / (2.0 * (n + 1)));
                double want = w / (2.0 * M_PI);
                assert_close(f[j - 1], want, 1e-9 * want);
            }
            free(f);
            model_free(md);
        }
    }
}

/* Fixed-free: w_j = 2 sqrt(k/m) sin((2j-1) pi / (2(2N+1))). */
static void uniform_free_closed_form(void **state)
{
    (void)state;
    for (int n = 1; n <= 12; n++) {
        struct model *md = uniform(n, 7.0, 2.0, BOUNDARY_FREE);
        double f[12];
        assert_int_equal(modes_compute(md, f, NULL), 0);
        for (int j = 1; j <= n; j++) {
            double want = 2.0 * sqrt(3.5) * sin((2 * j - 1) * M_PI / (2.0 * (2 * n + 1))) /
                          (2.0 * M_PI);
            assert_close(f[j - 1], want, 1e-9 * want);
        }
        model_free(md);
    }
}

/* Uniform fixed-fixed shapes: phi_i = sin(i j pi / (N+1)), scaled to max 1. */
static void uniform_shapes(void **state)
{
    (void)state;
    int n = 4;
    struct model *md = uniform(n, 10.0, 1.0, BOUNDARY_WALL);
    double f[4], sh[16];
    assert_int_equal(modes_compute(md, f, sh), 0);
    for (int j = 1; j <= n; j++) {
        double want[4], top = 0.0;
        int big = -1;
        for (int i = 1; i <= n; i++) {
            want[i - 1] = sin(i * j * M_PI / (n + 1));
            if (fabs(want[i - 1]) > top + 1e-12)
                top = fabs(want[i - 1]), big = i - 1;
        }
        double scale = 1.0 / want[big];
        for (int i = 0; i < n; i++)
            assert_close(sh[(j - 1) * n + i], want[i] * scale, 1e-9);
    }
    model_free(md);
}

/* Non-uniform chain: K phi = w^2 M phi, phi_i' M phi_j = 0, and the scaling rule. */
static void eigen_equation_holds(void **state)
{
    (void)state;
    int n = 5;
    struct model *md = model_new(n);
    const double m[5] = {1.0, 2.5, 0.7, 1.2, 3.0}, k[6] = {10, 3, 25, 7, 12, 4};
    for (int i = 0; i < n; i++)
        md->m[i] = m[i];
    for (int j = 0; j <= n; j++)
        md->k[j] = k[j];
    for (int b = 0; b < BOUNDARY_COUNT; b++) {
        md->boundary = (enum boundary)b;
        double f[5], sh[25];
        assert_int_equal(modes_compute(md, f, sh), 0);
        for (int j = 0; j < n; j++) {
            const double *p = sh + j * n;
            double w2 = pow(2 * M_PI * f[j], 2), top = 0.0;
            for (int i = 0; i < n; i++) {
                double kp = (k[i] + (i < n - 1 || b != BOUNDARY_FREE ? k[i + 1] : 0)) * p[i];
                if (i > 0)
                    kp -= k[i] * p[i - 1];
                if (i < n - 1)
                    kp -= k[i + 1] * p[i + 1];
                assert_close(kp, w2 * m[i] * p[i], 1e-9 * w2 * m[i]);
                top = fmax(top, fabs(p[i]));
            }
            assert_close(top, 1.0, 1e-12);
            if (j > 0)
                assert_true(f[j] > f[j - 1]);
            for (int l = 0; l < j; l++) {
                double dot = 0.0;
                for (int i = 0; i < n; i++)
                    dot += p[i] * m[i] * sh[l * n + i];
                assert_close(dot, 0.0, 1e-9);
            }
        }
    }
    model_free(md);
}

/* One mass between springs k0, k1 with the motor: X = k1 A / |2k - m w^2 + i c w|. */
static void one_dof_response(void **state)
{
    (void)state;
    struct model *md = model_new(1);
    md->m[0] = 1.3, md->k[0] = 9.0, md->k[1] = 11.0, md->c[0] = 0.25;
    md->motor.amplitude = 0.4;
    for (double f = 0.05; f < 3.0; f += 0.0137) {
        double w = 2 * M_PI * f, amp;
        assert_int_equal(modes_response(md, f, &amp), 0);
        double want = 11.0 * 0.4 / hypot(20.0 - 1.3 * w * w, 0.25 * w);
        assert_close(amp, want, 1e-9 * want);
    }
    md->boundary = BOUNDARY_WALL;
    double amp = 1.0;
    assert_int_equal(modes_response(md, 0.5, &amp), 0);
    assert_close(amp, 0.0, 0.0);
    model_free(md);
}

/* The steady state a long simulation settles into has the predicted amplitudes. */
static void response_matches_simulation(void **state)
{
    (void)state;
    struct model *md = model_new(3);
    md->m[1] = 1.5, md->k[2] = 14.0, md->c[0] = 0.6, md->c[1] = 0.4, md->c[2] = 0.5;
    md->motor.amplitude = 0.2, md->motor.frequency = 0.6;
    md->collisions = false;
    double amp[3], peak[3] = {0, 0, 0};
    assert_int_equal(modes_response(md, 0.6, amp), 0);
    struct sim *s = sim_new(md, 0.002);
    for (int n = 0; n < 200000; n++) { /* 400 s: transients decay as exp(-c t / 2m) */
        sim_step(s);
        if (n >= 190000)
            for (int i = 0; i < 3; i++)
                peak[i] = fmax(peak[i], fabs(sim_x(s)[i]));
    }
    /* Peaks of a sampled sine fall short by at most 1 - cos(w dt / 2). */
    for (int i = 0; i < 3; i++)
        assert_close(peak[i], amp[i], 1e-5 * amp[i] + amp[i] * (1 - cos(2 * M_PI * 0.6 * 0.001)));
    sim_free(s);
    model_free(md);
}

/* ---- damping of each mode ---- */

/* modes_damped on m, shapes from modes_compute; ratio, hz and freq of n modes. */
static void damped(const struct model *md, double *freq, double *ratio, double *hz)
{
    int n = md->n;
    double *sh = malloc((size_t)n * (size_t)n * sizeof *sh);
    assert_int_equal(modes_compute(md, freq, sh), 0);
    assert_int_equal(modes_damped(md, sh, ratio, hz), 0);
    free(sh);
}

/* One mass between k1 and k2: lambda^2 m + lambda c + (k1 + k2) = 0, so
 * zeta = c / (2 sqrt(k m)) on both sides of critical damping, and the damped frequency is
 * w sqrt(1 - zeta^2) below it, 0 above. */
static void damped_one_dof(void **state)
{
    (void)state;
    struct model *md = model_new(1);
    md->m[0] = 1.7, md->k[0] = 6.0, md->k[1] = 9.0;
    const double cs[] = {0.0, 0.05, 1.3, 8.0, 9.5, 10.5, 40.0};
    for (int b = 0; b < 2; b++) {
        md->boundary = b ? BOUNDARY_WALL : BOUNDARY_MOTOR;
        for (size_t t = 0; t < sizeof cs / sizeof *cs; t++) {
            double c = cs[t], f, ratio, hz;
            md->c[0] = c;
            damped(md, &f, &ratio, &hz);
            double k = 15.0, w = sqrt(k / 1.7), zeta = c / (2.0 * sqrt(k * 1.7));
            assert_close(ratio, zeta, 1e-9 * fmax(zeta, 1.0));
            if (zeta < 1.0)
                assert_close(hz, w * sqrt(1.0 - zeta * zeta) / (2.0 * M_PI), 1e-9 * w);
            else
                assert_true(hz == 0.0 && ratio >= 1.0);
        }
    }
    /* A mass of 1e-70 kg: the slow eigenvalue -k/c is below the rounding of |A| ~ 1e71
     * and fails the backward-error test; the modal route gives the same closed form. */
    md->m[0] = 1e-70, md->c[0] = 0.1;
    double f, ratio, hz, zeta = 0.1 / (2.0 * sqrt(15.0 * 1e-70));
    damped(md, &f, &ratio, &hz);
    assert_close(ratio, zeta, 1e-9 * zeta);
    assert_true(hz == 0.0);
    model_free(md);
}

/* C = a M: the modes do not mix, lambda^2 + a lambda + w_j^2 = 0, zeta_j = a / (2 w_j),
 * the low modes overdamped for large a. On a 2-mass chain w_j^2 are the roots of
 * det(K - w^2 M) = 0; on longer chains (modal route above LIMITS_DGEEV_MAX included) the
 * frequencies are modes_compute's, checked against closed forms above. */
static void damped_proportional(void **state)
{
    (void)state;
    struct model *md = model_new(2);
    double m1 = 1.2, m2 = 0.6, k0 = 8.0, k1 = 5.0, k2 = 11.0;
    md->m[0] = m1, md->m[1] = m2, md->k[0] = k0, md->k[1] = k1, md->k[2] = k2;
    /* (k0 + k1 - w2 m1)(k1 + k2 - w2 m2) = k1^2 */
    double qa = m1 * m2, qb = -(m1 * (k1 + k2) + m2 * (k0 + k1)),
           qc = (k0 + k1) * (k1 + k2) - k1 * k1, disc = sqrt(qb * qb - 4 * qa * qc);
    double w[2] = {sqrt((-qb - disc) / (2 * qa)), sqrt((-qb + disc) / (2 * qa))};
    const double as[] = {0.0, 0.3, 3.0, 5.0, 9.0};
    for (size_t t = 0; t < sizeof as / sizeof *as; t++) {
        double a = as[t], f[2], ratio[2], hz[2];
        md->c[0] = a * m1, md->c[1] = a * m2;
        damped(md, f, ratio, hz);
        for (int j = 0; j < 2; j++) {
            double zeta = a / (2 * w[j]);
            assert_close(ratio[j], zeta, 1e-9 * fmax(zeta, 1.0));
            assert_close(hz[j], zeta < 1 ? w[j] * sqrt(1 - zeta * zeta) / (2 * M_PI) : 0.0,
                         1e-8 * w[j]);
        }
    }
    model_free(md);
    const int sizes[] = {7, LIMITS_DGEEV_MAX + 20};
    for (int s = 0; s < 2; s++) {
        int n = sizes[s];
        md = model_new(n);
        md->boundary = BOUNDARY_WALL;
        for (int i = 0; i < n; i++)
            md->m[i] = 0.5 + 0.37 * (i % 5), md->c[i] = 5.0 * md->m[i];
        for (int j = 0; j <= n; j++)
            md->k[j] = 20.0 + 3.0 * (j % 3);
        double *f = malloc((size_t)(3 * n) * sizeof *f), *ratio = f + n, *hz = f + 2 * n;
        damped(md, f, ratio, hz);
        int over = 0;
        for (int j = 0; j < n; j++) {
            double wj = 2 * M_PI * f[j], zeta = 5.0 / (2 * wj);
            over += zeta > 1.0;
            assert_close(ratio[j], zeta, 1e-8 * fmax(zeta, 1.0));
            assert_close(hz[j], zeta < 1 ? wj * sqrt(1 - zeta * zeta) / (2 * M_PI) : 0.0,
                         1e-7 * wj);
        }
        if (s == 0)
            assert_true(over >= 1 && over < n); /* both kinds were paired */
        free(f);
        model_free(md);
    }
}

/* The roots of the polynomial p[0] + p[1] z + ... + p[deg] z^deg (Durand-Kerner), each
 * polished by Newton's method. */
static void poly_roots(const double *p, int deg, double complex *z)
{
    for (int i = 0; i < deg; i++)
        z[i] = cpow(0.4 + 0.9 * I, i);
    for (int it = 0; it < 2000; it++)
        for (int i = 0; i < deg; i++) {
            double complex num = p[deg], den = p[deg];
            for (int d = deg - 1; d >= 0; d--)
                num = num * z[i] + p[d];
            for (int l = 0; l < deg; l++)
                if (l != i)
                    den *= z[i] - z[l];
            z[i] -= num / den;
        }
    for (int i = 0; i < deg; i++)
        for (int it = 0; it < 5; it++) {
            double complex v = p[deg], dv = 0.0;
            for (int d = deg - 1; d >= 0; d--) {
                dv = dv * z[i] + v;
                v = v * z[i] + p[d];
            }
            if (cabs(dv) > 0.0)
                z[i] -= v / dv;
        }
}

/* The four roots of det(lambda^2 M + lambda C + K) for a 2-mass chain ending at a wall. */
static void two_dof_roots(const double *m, const double *c, const double *k,
                          double complex *z)
{
    /* (m1 l^2 + c1 l + K11)(m2 l^2 + c2 l + K22) - k1^2 */
    double a[3] = {k[0] + k[1], c[0], m[0]}, b[3] = {k[1] + k[2], c[1], m[1]}, p[5] = {0};
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            p[i + j] += a[i] * b[j];
    p[0] -= k[1] * k[1];
    poly_roots(p, 4, z);
}

/* Unequal dampers (C not a combination of M and K): the ratios and damped frequencies are
 * those of the characteristic polynomial's roots, lowest |Im| with mode 1. Heavy unequal
 * dampers: four real roots, both modes overdamped. */
static void damped_two_dof_general(void **state)
{
    (void)state;
    struct model *md = model_new(2);
    md->boundary = BOUNDARY_WALL;
    const double m[2] = {1.0, 2.2}, k[3] = {7.0, 4.0, 13.0};
    const double cs[][2] = {{0.4, 0.05}, {0.0, 1.1}, {2.0, 0.3}};
    for (int i = 0; i < 2; i++)
        md->m[i] = m[i];
    for (int j = 0; j < 3; j++)
        md->k[j] = k[j];
    for (size_t t = 0; t < sizeof cs / sizeof *cs; t++) {
        md->c[0] = cs[t][0], md->c[1] = cs[t][1];
        double complex z[4], up[2];
        int found = 0;
        two_dof_roots(m, cs[t], k, z);
        for (int i = 0; i < 4; i++)
            if (cimag(z[i]) > 1e-9)
                up[found++] = z[i];
        assert_int_equal(found, 2);
        if (cimag(up[0]) > cimag(up[1])) {
            double complex tmp = up[0];
            up[0] = up[1], up[1] = tmp;
        }
        double f[2], ratio[2], hz[2];
        damped(md, f, ratio, hz);
        for (int j = 0; j < 2; j++) {
            assert_close(ratio[j], -creal(up[j]) / cabs(up[j]), 1e-9);
            assert_close(hz[j], cimag(up[j]) / (2 * M_PI), 1e-9 * cabs(up[j]));
        }
    }
    const double heavy[2] = {30.0, 90.0};
    md->c[0] = heavy[0], md->c[1] = heavy[1];
    double complex z[4];
    two_dof_roots(m, heavy, k, z);
    for (int i = 0; i < 4; i++)
        assert_true(fabs(cimag(z[i])) < 1e-9 && creal(z[i]) < 0.0);
    double f[2], ratio[2], hz[2];
    damped(md, f, ratio, hz);
    for (int j = 0; j < 2; j++)
        assert_true(ratio[j] >= 1.0 && hz[j] == 0.0);
    model_free(md);
}

/* No dampers: every eigenvalue is +-i w_j, so every ratio is exactly 0 (Q infinite, not
 * 1/(2 * rounding)) and the damped frequencies are the natural ones, for every end and
 * chains of unequal masses and springs. */
static void damped_none(void **state)
{
    (void)state;
    const int sizes[] = {1, 2, 3, 10};
    for (int s = 0; s < 4; s++)
        for (int b = 0; b < 3; b++) {
            int n = sizes[s];
            struct model *md = model_new(n);
            md->boundary = b == 0 ? BOUNDARY_MOTOR : b == 1 ? BOUNDARY_WALL : BOUNDARY_FREE;
            for (int i = 0; i < n; i++)
                md->m[i] = 0.3 + 0.7 * (i % 3), md->c[i] = 0.0;
            for (int j = 0; j <= n; j++)
                md->k[j] = 4.0 + 5.0 * (j % 4);
            double f[10], ratio[10], hz[10];
            damped(md, f, ratio, hz);
            for (int j = 0; j < n; j++) {
                assert_true(ratio[j] == 0.0);
                assert_close(hz[j], f[j], 1e-12 * f[j]);
            }
            model_free(md);
        }
}

/* ---- phase ---- */

/* One mass between k1 (wall) and k2 (motor): X / U = k2 / (k1 + k2 - m w^2 + i c w), so
 * the phase is atan2(-c w, k - m w^2): 0 far below resonance, -90 at it, near -180 above. */
static void phase_one_dof(void **state)
{
    (void)state;
    struct model *md = model_new(1);
    md->m[0] = 1.3, md->k[0] = 9.0, md->k[1] = 11.0, md->c[0] = 0.25;
    md->motor.amplitude = 0.4;
    for (double f = 0.05; f < 3.0; f += 0.0137) {
        double w = 2 * M_PI * f, amp, plain, ph;
        assert_int_equal(modes_response_phase(md, f, &amp, &ph), 0);
        assert_int_equal(modes_response(md, f, &plain), 0);
        double want = atan2(-0.25 * w, 20.0 - 1.3 * w * w) * 180.0 / M_PI;
        assert_close(ph, want, 1e-9);
        assert_close(amp, plain, 1e-12 * plain);
        assert_true(ph <= 0.0 && ph > -180.0);
    }
    double at = sqrt(20.0 / 1.3) / (2 * M_PI), amp, ph;
    assert_int_equal(modes_response_phase(md, at, &amp, &ph), 0);
    assert_close(ph, -90.0, 1e-9);
    md->motor.amplitude = 0.0; /* no amplitude, still a phase */
    assert_int_equal(modes_response_phase(md, 2.0, &amp, &ph), 0);
    assert_true(amp == 0.0);
    assert_close(ph, atan2(-0.25 * 4 * M_PI, 20.0 - 1.3 * 16 * M_PI * M_PI) * 180 / M_PI, 1e-9);
    md->c[0] = 0.0; /* undamped above resonance: in phase opposition, +180 by the range */
    assert_int_equal(modes_response_phase(md, 2.0, &amp, &ph), 0);
    assert_true(ph == 180.0);
    md->boundary = BOUNDARY_WALL;
    amp = ph = 1.0;
    assert_int_equal(modes_response_phase(md, 0.5, &amp, &ph), 0);
    assert_true(amp == 0.0 && ph == 0.0);
    assert_int_equal(modes_response_phase(md, 0.5, &amp, NULL), 0);
    model_free(md);
}

/* Two masses: X solves the 2x2 complex system, here by Cramer's rule. */
static void phase_two_dof(void **state)
{
    (void)state;
    struct model *md = model_new(2);
    md->m[0] = 1.0, md->m[1] = 2.0, md->k[0] = 5.0, md->k[1] = 7.0, md->k[2] = 3.0;
    md->c[0] = 0.3, md->c[1] = 0.8, md->motor.amplitude = 0.7;
    for (double f = 0.02; f < 1.5; f += 0.0311) {
        double w = 2 * M_PI * f, amp[2], ph[2];
        double complex a = 12.0 - w * w * 1.0 + I * w * 0.3, d = 10.0 - w * w * 2.0 + I * w * 0.8;
        double complex det = a * d - 49.0, rhs = 3.0 * 0.7;
        double complex x[2] = {7.0 * rhs / det, a * rhs / det};
        assert_int_equal(modes_response_phase(md, f, amp, ph), 0);
        for (int i = 0; i < 2; i++) {
            assert_close(amp[i], cabs(x[i]), 1e-9 * cabs(x[i]));
            double want = carg(x[i]) * 180 / M_PI;
            assert_close(ph[i], want, 1e-7);
        }
    }
    model_free(md);
}

/* ---- energy per mode, a start along one ---- */

static double uniform01(unsigned *seed)
{
    *seed = *seed * 1103515245u + 12345u;
    return (double)((*seed >> 8) & 0xffffff) / 16777216.0;
}

/* The modes are M- and K-orthogonal and complete: their energies sum to the chain's
 * kinetic and spring energy (right end at rest) for any state; a state along one shape
 * has all of it in that mode. */
static void energy_sums(void **state)
{
    (void)state;
    unsigned seed = 7;
    int n = 6;
    struct model *md = model_new(n);
    for (int i = 0; i < n; i++)
        md->m[i] = 0.3 + 2.0 * uniform01(&seed);
    for (int j = 0; j <= n; j++)
        md->k[j] = 1.0 + 30.0 * uniform01(&seed);
    for (int b = 0; b < BOUNDARY_COUNT; b++) {
        md->boundary = (enum boundary)b;
        double f[6], sh[36], x[6], v[6], e[6];
        assert_int_equal(modes_compute(md, f, sh), 0);
        for (int trial = 0; trial < 20; trial++) {
            for (int i = 0; i < n; i++)
                x[i] = uniform01(&seed) - 0.5, v[i] = 3.0 * (uniform01(&seed) - 0.5);
            modes_energy(md, f, sh, x, v, e);
            double sum = 0.0, want = model_kinetic(md, v) + model_potential(md, x, 0.0);
            for (int j = 0; j < n; j++) {
                assert_true(e[j] >= 0.0);
                sum += e[j];
            }
            assert_close(sum, want, 1e-12 * want);
        }
        for (int k = 1; k <= n; k++) {
            double zero[6] = {0};
            assert_int_equal(modes_start(md, k, 0.3, x), 0);
            modes_energy(md, f, sh, x, zero, e);
            double want = model_potential(md, x, 0.0);
            for (int j = 0; j < n; j++)
                assert_close(e[j], j == k - 1 ? want : 0.0, 1e-12 * want);
        }
    }
    model_free(md);
}

/* modes_start is amp times the shape: largest |x| = amp, K x = w^2 M x. */
static void start_along_a_mode(void **state)
{
    (void)state;
    int n = 4;
    struct model *md = model_new(n);
    const double m[4] = {1.0, 3.0, 0.5, 2.0}, k[5] = {4, 9, 2, 6, 5};
    for (int i = 0; i < n; i++)
        md->m[i] = m[i];
    for (int j = 0; j <= n; j++)
        md->k[j] = k[j];
    md->boundary = BOUNDARY_WALL;
    double f[4], x[4];
    assert_int_equal(modes_compute(md, f, NULL), 0);
    for (int mode = 1; mode <= n; mode++) {
        assert_int_equal(modes_start(md, mode, 0.25, x), 0);
        double top = 0.0, w2 = pow(2 * M_PI * f[mode - 1], 2);
        for (int i = 0; i < n; i++) {
            double kx = (k[i] + k[i + 1]) * x[i] - (i > 0 ? k[i] * x[i - 1] : 0.0) -
                        (i < n - 1 ? k[i + 1] * x[i + 1] : 0.0);
            assert_close(kx, w2 * m[i] * x[i], 1e-9 * w2);
            if (fabs(x[i]) > fabs(top) + 1e-12)
                top = x[i];
        }
        assert_close(top, 0.25, 1e-12);
        /* Amplitude 0 is the chain at rest: every x is +0 (a -0 would print as "-0"). */
        assert_int_equal(modes_start(md, mode, 0.0, x), 0);
        for (int i = 0; i < n; i++)
            assert_true(x[i] == 0.0 && !signbit(x[i]));
    }
    assert_int_equal(modes_start(md, 0, 0.25, x), -2);
    assert_int_equal(modes_start(md, n + 1, 0.25, x), -2);
    model_free(md);
}

/* An undamped wall chain started along mode 2 stays in it: every step of exact (the
 * exponential exp(h A)) and of rk4 (the polynomial R(h A)) is a function of the
 * first-order matrix A, so it maps the span of A's eigenvectors for +-i w_2 into itself;
 * only rounding feeds the other modes. Their modal coordinates q_j = phi^_j^T M x stay
 * within 1e-8 of mode 2's largest over 20 s. */
static void start_mode_stays(void **state)
{
    (void)state;
    int n = 3;
    const enum integrator ints[] = {INTEGRATOR_EXACT, INTEGRATOR_RK4};
    struct model *md = model_new(n);
    md->boundary = BOUNDARY_WALL;
    md->m[0] = 1.0, md->m[1] = 2.5, md->m[2] = 0.7;
    for (int i = 0; i < n; i++)
        md->c[i] = 0.0;
    double f[3], sh[9], x0[3], v0[3] = {0, 0, 0};
    assert_int_equal(modes_compute(md, f, sh), 0);
    assert_int_equal(modes_start(md, 2, 0.5, x0), 0);
    for (size_t t = 0; t < sizeof ints / sizeof *ints; t++) {
        struct sim *s = sim_new(md, 0.01);
        sim_set_integrator(s, ints[t]);
        sim_reset(s, x0, v0);
        double top[3] = {0, 0, 0};
        for (int step = 0; step <= 2000; step++) {
            for (int j = 0; j < n; j++) {
                double norm = 0.0, q = 0.0;
                for (int i = 0; i < n; i++) {
                    norm += md->m[i] * sh[j * n + i] * sh[j * n + i];
                    q += md->m[i] * sh[j * n + i] * sim_x(s)[i];
                }
                top[j] = fmax(top[j], fabs(q) / sqrt(norm));
            }
            if (step < 2000)
                assert_int_equal(sim_step(s), SIM_OK);
        }
        assert_true(top[1] > 0.1);
        assert_true(top[0] <= 1e-8 * top[1]);
        assert_true(top[2] <= 1e-8 * top[1]);
        assert_close(sim_time(s), 20.0, 1e-9);
        sim_free(s);
    }
    model_free(md);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(uniform_fixed_closed_form),
        cmocka_unit_test(uniform_free_closed_form),
        cmocka_unit_test(uniform_shapes),
        cmocka_unit_test(eigen_equation_holds),
        cmocka_unit_test(one_dof_response),
        cmocka_unit_test(response_matches_simulation),
        cmocka_unit_test(damped_one_dof),
        cmocka_unit_test(damped_proportional),
        cmocka_unit_test(damped_two_dof_general),
        cmocka_unit_test(damped_none),
        cmocka_unit_test(phase_one_dof),
        cmocka_unit_test(phase_two_dof),
        cmocka_unit_test(energy_sums),
        cmocka_unit_test(start_along_a_mode),
        cmocka_unit_test(start_mode_stays),
    };
    return cmocka_run_group_tests_name("modes", tests, NULL, NULL);
}
