/* test_bordered.c: banded systems bordered by a dense row and column, against the dense
 * LU of the same system and against their own residuals: well conditioned, with a band
 * that is singular or nearly so where the whole system is not (a fold), with the
 * band wider than the system, and a singular whole system, which is refused. */
#include "testutil.h"

#include <stdlib.h>
#include <string.h>

#include <lapacke.h>

#include "core/bordered.h"

#define KL 3
#define KU 3

/* A random system of order n (+1 with border), column-major, leading dimension dim;
 * zeros outside the band; the band's diagonal made dominant by `dominance`. */
static double *random_system(int n, bool border, double dominance, uint64_t *seed)
{
    int dim = border ? n + 1 : n;
    double *a = calloc((size_t)dim * dim, sizeof *a);
    assert_non_null(a);
    for (int j = 0; j < dim; j++)
        for (int i = 0; i < dim; i++) {
            bool band = i < n && j < n && i - j <= KL && j - i <= KU;
            if (band || (border && (i == n || j == n)))
                a[i + (size_t)j * dim] = test_uniform(seed, -1.0, 1.0);
        }
    for (int i = 0; i < n; i++)
        a[i + (size_t)i * dim] += dominance;
    return a;
}

/* The largest |a x - b| over the largest |b|. */
static double residual(const double *a, int dim, const double *x, const double *b)
{
    double worst = 0.0, size = 0.0;
    for (int i = 0; i < dim; i++) {
        double s = 0.0;
        for (int j = 0; j < dim; j++)
            s += a[i + (size_t)j * dim] * x[j];
        worst = fmax(worst, fabs(s - b[i]));
        size = fmax(size, fabs(b[i]));
    }
    return worst / size;
}

/* Solves a x = b both ways; returns the largest difference from the dense solution over
 * its largest component, and checks the residual. */
static double solve_both(double *a, int n, bool border, const double *b, double res_tol)
{
    int dim = border ? n + 1 : n;
    double *keep = malloc((size_t)dim * dim * sizeof *keep), *x = malloc((size_t)dim * sizeof *x);
    double *ref = malloc((size_t)dim * sizeof *ref);
    lapack_int *piv = malloc((size_t)dim * sizeof *piv);
    assert_true(keep && x && ref && piv);
    memcpy(keep, a, (size_t)dim * dim * sizeof *a);
    memcpy(x, b, (size_t)dim * sizeof *b);
    memcpy(ref, b, (size_t)dim * sizeof *b);
    struct bordered bs;
    assert_int_equal(bordered_init(&bs, n, KL, KU), 0);
    assert_int_equal(bordered_solve(&bs, a, dim, border, x), 0);
    bordered_free(&bs);
    double res = residual(keep, dim, x, b);
    if (!(res <= res_tol))
        fail_msg("n %d border %d: residual %.3g, expected at most %.3g", n, border, res, res_tol);
    double *d = malloc((size_t)dim * dim * sizeof *d);
    assert_non_null(d);
    memcpy(d, keep, (size_t)dim * dim * sizeof *d);
    assert_int_equal(LAPACKE_dgesv(LAPACK_COL_MAJOR, dim, 1, d, dim, piv, ref, dim), 0);
    double diff = 0.0, size = 0.0;
    for (int i = 0; i < dim; i++) {
        diff = fmax(diff, fabs(x[i] - ref[i]));
        size = fmax(size, fabs(ref[i]));
    }
    free(keep), free(x), free(ref), free(piv), free(d);
    return diff / size;
}

static void well_conditioned(void **state)
{
    (void)state;
    uint64_t seed = 0x9e3779b97f4a7c15u;
    const int sizes[] = {1, 2, 3, 5, 8, 40, 200};
    double worst = 0.0;
    for (size_t k = 0; k < sizeof sizes / sizeof *sizes; k++)
        for (int border = 0; border < 2; border++)
            for (int rep = 0; rep < 10; rep++) {
                int n = sizes[k], dim = border ? n + 1 : n;
                double *a = random_system(n, border, 8.0, &seed), b[201];
                for (int i = 0; i < dim; i++)
                    b[i] = test_uniform(&seed, -1.0, 1.0);
                worst = fmax(worst, solve_both(a, n, border, b, 1e-14));
                free(a);
            }
    printf("  140 systems of order 1 to 201: largest difference from the dense LU %.2e\n", worst);
    assert_true(worst <= 1e-13);
}

/* A fold: the band singular (or nearly: its last pivot eps), the bordered system not. */
static void singular_band(void **state)
{
    (void)state;
    const double eps[] = {0.0, 1e-15, 1e-12, 1e-9, 1e-6};
    uint64_t seed = 12345;
    for (size_t e = 0; e < sizeof eps / sizeof *eps; e++) {
        int n = 30, dim = n + 1;
        /* An upper-triangular band with unit diagonal but its last entry eps: A's rank
         * falls by one at eps = 0; the border reaches the missing direction. */
        double *a = calloc((size_t)dim * dim, sizeof *a), b[31];
        assert_non_null(a);
        for (int j = 0; j < n; j++) {
            for (int i = j - KU > 0 ? j - KU : 0; i < j; i++)
                a[i + (size_t)j * dim] = test_uniform(&seed, -0.5, 0.5);
            a[j + (size_t)j * dim] = j == n - 1 ? eps[e] : 1.0;
        }
        for (int i = 0; i < n; i++) {
            a[i + (size_t)n * dim] = test_uniform(&seed, -1.0, 1.0);
            a[n + (size_t)i * dim] = test_uniform(&seed, -1.0, 1.0);
        }
        a[n - 1 + (size_t)n * dim] = 1.0, a[n + (size_t)(n - 1) * dim] = 1.0;
        for (int i = 0; i < dim; i++)
            b[i] = test_uniform(&seed, -1.0, 1.0);
        double diff = solve_both(a, n, true, b, 1e-13);
        printf("  band's last pivot %.0e: difference from the dense LU %.2e\n", eps[e], diff);
        assert_true(diff <= 1e-11);
        free(a);
    }
}

/* A whole system that is singular is refused, bordered or not. */
static void singular_system(void **state)
{
    (void)state;
    for (int border = 0; border < 2; border++) {
        int n = 6, dim = border ? n + 1 : n;
        double *a = calloc((size_t)dim * dim, sizeof *a), x[7] = {1, 2, 3, 4, 5, 6, 7};
        assert_non_null(a);
        for (int j = 0; j < n; j++)
            a[j + (size_t)j * dim] = j == 2 ? 0.0 : 1.0; /* column 2 is empty */
        if (border)
            a[n + (size_t)n * dim] = 1.0, a[0 + (size_t)n * dim] = 1.0;
        struct bordered bs;
        assert_int_equal(bordered_init(&bs, n, KL, KU), 0);
        assert_int_equal(bordered_solve(&bs, a, dim, border, x), -1);
        bordered_free(&bs);
        free(a);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(well_conditioned),
        cmocka_unit_test(singular_band),
        cmocka_unit_test(singular_system),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
