/* test_damped.c: the damped modes (damped.c) with dampers beside springs, a full damping
 * matrix and rigid-body modes: textbook two-mass examples against their characteristic
 * polynomial's roots (GSL's gsl_poly_complex_solve, not LAPACK) or the closed form,
 * the 101-mass half-damped chain against a dense LAPACK solve of the state matrix built
 * here, Rayleigh's damping (the modal route) against that solve too, and a free-free
 * chain's rigid-body mode at 0 Hz. */
#include "testutil.h"

#include <complex.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_poly.h>
#include <lapacke.h>

#include "core/model.h"
#include "core/modes.h"

struct answer {
    double f[MODEL_MAX_MASSES], ratio[MODEL_MAX_MASSES], hz[MODEL_MAX_MASSES],
        eigen[MODEL_MAX_MASSES];
};

static void solve(const struct model *m, struct answer *a)
{
    double *shapes = malloc((size_t)m->n * (size_t)m->n * sizeof *shapes);
    assert_int_equal(modes_compute(m, a->f, shapes), 0);
    assert_int_equal(modes_damped_all(m, shapes, a->ratio, a->hz, a->eigen), 0);
    free(shapes);
}

/* A two-mass chain from M = diag(m1, m2) and tridiagonal K, C: springs k0 = K11 + K12,
 * k1 = -K12, k2 = K22 + K12 (a free end when that is 0), the same for the dampers. */
static struct model *two_mass(const double m[2], const double k[3], const double c[3],
                              const double ground[2])
{
    struct model *md = model_new(2);
    md->m[0] = m[0], md->m[1] = m[1];
    md->c[0] = ground[0], md->c[1] = ground[1];
    for (int j = 0; j < 3; j++)
        md->k[j] = k[j], md->cs[j] = c[j];
    md->boundary = k[2] == 0.0 && c[2] == 0.0 ? BOUNDARY_FREE : BOUNDARY_WALL;
    model_sync(md);
    return md;
}

/* The roots with Im > 0 of det(l^2 M + l C + K) = a11 a22 - a12^2 for a two-mass chain
 * (C = ground dampers + spring dampers), lowest |l| first. */
static void two_mass_roots(const struct model *md, double complex up[2])
{
    double kd[2], cd[2];
    for (int i = 0; i < 2; i++) {
        bool right = i == 0 || md->boundary != BOUNDARY_FREE;
        kd[i] = md->k[i] + (right ? md->k[i + 1] : 0.0);
        cd[i] = md->c[i] + md->cs[i] + (right ? md->cs[i + 1] : 0.0);
    }
    double a[3] = {kd[0], cd[0], md->m[0]}, b[3] = {kd[1], cd[1], md->m[1]};
    double o[3] = {-md->k[1], -md->cs[1], 0.0}, p[5] = {0}, z[8];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            p[i + j] += a[i] * b[j] - o[i] * o[j];
    gsl_poly_complex_workspace *w = gsl_poly_complex_workspace_alloc(5);
    assert_int_equal(gsl_poly_complex_solve(p, 5, w, z), 0);
    gsl_poly_complex_workspace_free(w);
    int found = 0;
    for (int r = 0; r < 4; r++)
        if (z[2 * r + 1] > 1e-9)
            up[found++] = z[2 * r] + I * z[2 * r + 1];
    assert_int_equal(found, 2);
    if (cabs(up[0]) > cabs(up[1])) {
        double complex t = up[0];
        up[0] = up[1], up[1] = t;
    }
}

/* Inman, Engineering Vibration, chapter 4 (modal damping): M = diag(9, 1),
 * K = [27 -3; -3 3], C = 0.1 K = [2.7 -0.3; -0.3 0.3]. As a chain: a wall spring of 24
 * and a damper of 2.4, the two masses joined by 3 and 0.3, a free end. The book's answer,
 * M^(-1/2) K M^(-1/2) = [3 -1; -1 3]: w = sqrt 2 and 2 rad/s, zeta_j = 0.1 w_j / 2 =
 * 0.0707107 and 0.1, |lambda| = w_j. */
static void inman_proportional(void **state)
{
    (void)state;
    const double m[2] = {9, 1}, k[3] = {24, 3, 0}, c[3] = {2.4, 0.3, 0}, g[2] = {0, 0};
    struct model *md = two_mass(m, k, c, g);
    assert_true(model_rayleigh(md));
    struct answer a;
    solve(md, &a);
    const double w[2] = {sqrt(2.0), 2.0};
    for (int j = 0; j < 2; j++) {
        printf("# Inman's example, mode %d: %.9g Hz (book %.9g), zeta %.9g (book %.9g)\n",
               j + 1, a.eigen[j], w[j] / (2 * M_PI), a.ratio[j], 0.05 * w[j]);
        assert_close(a.eigen[j], w[j] / (2 * M_PI), 5e-7 * w[j] / (2 * M_PI));
        assert_close(a.ratio[j], 0.05 * w[j], 5e-7 * 0.05 * w[j]);
        assert_close(a.f[j], w[j] / (2 * M_PI), 1e-12);
    }
    model_free(md);
}

/* Full C, not proportional (the kind Inman's section 4.7 and the vibration toolbox's
 * VTB4_3 solve through the state matrix): a damper between the masses beside a ground
 * damper, and another with the wall's damper: eigen frequency |lambda| / 2 pi and ratio
 * -Re lambda / |lambda| against the characteristic polynomial's roots, to 1e-9. */
static void full_c_two_mass(void **state)
{
    (void)state;
    const double m[][2] = {{1, 2}, {2, 1}, {1, 1}};
    const double k[][3] = {{10, 5, 0}, {8, 4, 6}, {2, 1, 3}};
    const double c[][3] = {{0, 0.8, 0}, {0.5, 0.3, 0}, {0, 1.2, 0.2}};
    const double g[][2] = {{0.3, 0}, {0, 0}, {0.1, 0}};
    for (int t = 0; t < 3; t++) {
        struct model *md = two_mass(m[t], k[t], c[t], g[t]);
        assert_false(model_rayleigh(md));
        struct answer a;
        solve(md, &a);
        double complex up[2];
        two_mass_roots(md, up);
        for (int j = 0; j < 2; j++) {
            double want_hz = cabs(up[j]) / (2 * M_PI), want_z = -creal(up[j]) / cabs(up[j]);
            printf("# full C %d, mode %d: %.10g Hz, zeta %.10g (roots: %.10g, %.10g)\n", t,
                   j + 1, a.eigen[j], a.ratio[j], want_hz, want_z);
            assert_close(a.eigen[j], want_hz, 1e-9 * want_hz);
            assert_close(a.ratio[j], want_z, 1e-9);
            assert_close(a.hz[j], cimag(up[j]) / (2 * M_PI), 1e-9 * want_hz);
        }
        model_free(md);
    }
}

/* A damper between the two masses of a wall-to-wall chain of equal springs damps only
 * the mode where they move apart: zeta = 0 for (1, 1), c / sqrt 3 for (1, -1) (k = m = 1:
 * w^2 = 3, phi^T C phi / phi^T M phi = 2 c). */
static void between_masses_closed_form(void **state)
{
    (void)state;
    const double m[2] = {1, 1}, k[3] = {1, 1, 1}, c[3] = {0, 0.3, 0}, g[2] = {0, 0};
    struct model *md = two_mass(m, k, c, g);
    struct answer a;
    solve(md, &a);
    assert_close(a.ratio[0], 0.0, 1e-12);
    assert_close(a.eigen[0], 1.0 / (2 * M_PI), 1e-12);
    assert_close(a.ratio[1], 0.3 / sqrt(3.0), 1e-12);
    assert_close(a.eigen[1], sqrt(3.0) / (2 * M_PI), 1e-12);
    model_free(md);
}

/* Every ratio -Re lambda / |lambda| of the complex eigenvalues of the state matrix
 * [[0, I], [-M^-1 K, -M^-1 C]], built here entry by entry, by LAPACK's dgeev without
 * vectors, sorted up into z; returns how many (the other modes are overdamped: two real
 * eigenvalues each). */
static int reference_ratios(const struct model *md, double *z)
{
    int n = md->n, n2 = 2 * n;
    double *a = calloc((size_t)n2 * (size_t)n2, sizeof *a), *re = malloc(2 * n2 * sizeof *re);
    double *im = re + n2;
    for (int i = 0; i < n; i++) {
        a[i + (size_t)(n + i) * n2] = 1.0;
        bool right = i < n - 1 || md->boundary != BOUNDARY_FREE;
        double kd = md->k[i] + (right ? md->k[i + 1] : 0.0);
        double cd = md->c[i] + md->cs[i] + (right ? md->cs[i + 1] : 0.0);
        a[n + i + (size_t)i * n2] = -kd / md->m[i];
        a[n + i + (size_t)(n + i) * n2] = -cd / md->m[i];
        if (i > 0) {
            a[n + i + (size_t)(i - 1) * n2] = md->k[i] / md->m[i];
            a[n + i + (size_t)(n + i - 1) * n2] = md->cs[i] / md->m[i];
        }
        if (i + 1 < n) {
            a[n + i + (size_t)(i + 1) * n2] = md->k[i + 1] / md->m[i];
            a[n + i + (size_t)(n + i + 1) * n2] = md->cs[i + 1] / md->m[i];
        }
    }
    assert_int_equal(LAPACKE_dgeev(LAPACK_COL_MAJOR, 'N', 'N', n2, a, n2, re, im, NULL, 1,
                                   NULL, 1), 0);
    int found = 0;
    for (int k = 0; k < n2; k++)
        if (im[k] > 0.0)
            z[found++] = -re[k] / hypot(re[k], im[k]);
    for (int i = 1; i < found; i++) /* insertion sort: n is small enough */
        for (int j = i; j > 0 && z[j] < z[j - 1]; j--) {
            double t = z[j];
            z[j] = z[j - 1], z[j - 1] = t;
        }
    free(a);
    free(re);
    return found;
}

static int compare(const void *x, const void *y)
{
    double a = *(const double *)x, b = *(const double *)y;
    return (a > b) - (a < b);
}

/* The chain: 101 masses, springs 10, a wall at the end, the left half damped by 2
 * and the right half not. The modal estimate said 0.0775 for the smallest ratio; the
 * dense solve says about 9e-6. Every underdamped mode's ratio within 1e-9 of the
 * reference, and as many overdamped modes (ratio >= 1) as it has pairs of real roots. */
static void half_damped_chain(void **state)
{
    (void)state;
    struct model *md = model_new(101);
    md->boundary = BOUNDARY_WALL;
    for (int i = 0; i < 101; i++)
        md->c[i] = i < 50 ? 2.0 : 0.0;
    model_sync(md);
    static struct answer a;
    static double want[101];
    solve(md, &a);
    int pairs = reference_ratios(md, want);
    qsort(a.ratio, 101, sizeof *a.ratio, compare);
    double worst = 0.0;
    for (int j = 0; j < pairs; j++)
        worst = fmax(worst, fabs(a.ratio[j] - want[j]));
    for (int j = pairs; j < 101; j++)
        assert_true(a.ratio[j] >= 1.0);
    assert_true(a.ratio[pairs - 1] < 1.0);
    printf("# half-damped 101: smallest zeta %.3g (reference %.3g), largest difference %.2e, "
           "%d overdamped\n", a.ratio[0], want[0], worst, 101 - pairs);
    assert_true(worst <= 1e-9);
    assert_true(a.ratio[0] < 1e-4);
    model_free(md);
}

/* Rayleigh's damping, C = 0.3 M + 0.02 K, on an uneven chain: the modal route against the
 * dense reference, and |lambda| = w_j. */
static void rayleigh_modal(void **state)
{
    (void)state;
    int n = 7;
    struct model *md = model_new(n);
    md->boundary = BOUNDARY_WALL;
    for (int i = 0; i < n; i++) {
        md->m[i] = 0.5 + 0.3 * (i % 4);
        md->c[i] = 0.3 * md->m[i];
    }
    for (int j = 0; j <= n; j++) {
        md->k[j] = 5.0 + 4.0 * (j % 3);
        md->cs[j] = 0.02 * md->k[j];
    }
    model_sync(md);
    assert_true(model_rayleigh(md));
    struct answer a;
    double want[7];
    solve(md, &a);
    for (int j = 0; j < n; j++) {
        double w = 2 * M_PI * a.f[j];
        assert_close(a.ratio[j], (0.3 + 0.02 * w * w) / (2 * w), 1e-12);
        assert_close(a.eigen[j], a.f[j], 1e-12 * a.f[j]);
    }
    assert_int_equal(reference_ratios(md, want), n);
    qsort(a.ratio, (size_t)n, sizeof *a.ratio, compare);
    for (int j = 0; j < n; j++)
        assert_close(a.ratio[j], want[j], 1e-9);
    model_free(md);
}

/* Three masses with no wall springs and a free end: one rigid-body mode, 0 Hz exactly,
 * no ratio (NAN); the others as the pair's closed form with a damper beside the middle
 * spring. Two groups joined to nothing: two rigid-body modes. */
static void rigid_body(void **state)
{
    (void)state;
    struct model *md = model_new(3);
    md->boundary = BOUNDARY_FREE;
    md->k[0] = 0.0, md->k[1] = 4.0, md->k[2] = 4.0;
    md->c[0] = md->c[1] = md->c[2] = 0.0;
    md->cs[1] = 0.2;
    model_sync(md);
    assert_int_equal(model_rigid_modes(md), 1);
    struct answer a;
    solve(md, &a);
    assert_true(a.f[0] == 0.0 && a.eigen[0] == 0.0 && isnan(a.ratio[0]));
    /* equal masses and springs, free-free: w^2 = k (1, 3) / m */
    assert_close(a.f[1], 2.0 / (2 * M_PI), 1e-12);
    assert_close(a.f[2], sqrt(12.0) / (2 * M_PI), 1e-12);
    for (int j = 1; j < 3; j++)
        assert_true(a.ratio[j] > 0.0 && a.ratio[j] < 0.2);
    md->k[2] = 0.0;
    md->k[1] = 0.0, md->k[2] = 4.0; /* mass 1 alone, masses 2 and 3 joined: two groups */
    model_sync(md);
    assert_int_equal(model_rigid_modes(md), 2);
    md->boundary = BOUNDARY_WALL;
    assert_int_equal(model_rigid_modes(md), 1);
    model_free(md);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(inman_proportional),
        cmocka_unit_test(full_c_two_mass),
        cmocka_unit_test(between_masses_closed_form),
        cmocka_unit_test(half_damped_chain),
        cmocka_unit_test(rayleigh_modal),
        cmocka_unit_test(rigid_body),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
