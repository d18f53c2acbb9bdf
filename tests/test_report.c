/* test_report.c: the rows a figure keeps (fig/report.c) and the figure formats. Few rows:
 * every one. Many rows: the first, then per bucket the smallest and the largest in time
 * order, then the last, each one of the rows given (so the curve lies on the CSV's rows);
 * an oscillation faster than a bucket keeps its envelope; a value that is not finite
 * breaks the line. */
#include "testutil.h"

#include <stdlib.h>
#include <string.h>

#include "fig/figure.h"
#include "fig/report.h"

static void few_rows_are_all_kept(void **state)
{
    (void)state;
    struct report_data *d = report_data_new(2, 100);
    assert_non_null(d);
    assert_int_equal(report_data_bucket(d), 1);
    for (int r = 0; r < 100; r++) {
        double y[2] = {r * 0.5, -r};
        report_data_add(d, r * 0.01, y);
    }
    report_data_finish(d);
    const double *p;
    assert_int_equal(report_data_points(d, 1, &p), 100);
    for (int r = 0; r < 100; r++) {
        assert_close(p[2 * r], r * 0.01, 0.0);
        assert_close(p[2 * r + 1], -r, 0.0);
    }
    report_data_free(d);
}

/* Many rows of sin(2 pi 50 t) sampled 1000 times a second for 60 s: 60001 rows, far more
 * than the buckets; every kept point is a row, in time order, first and last included,
 * and every bucket's extremes reach the envelope (|y| > 0.95 of the amplitude). */
static void many_rows_keep_the_envelope(void **state)
{
    (void)state;
    int rows = 60001;
    struct report_data *d = report_data_new(1, rows);
    assert_non_null(d);
    long k = report_data_bucket(d);
    assert_true(k > 1);
    double *y = malloc((size_t)rows * sizeof *y);
    assert_non_null(y);
    for (int r = 0; r < rows; r++) {
        y[r] = 2.0 * sin(2.0 * M_PI * 50.0 * r / 1000.0 + 0.3);
        report_data_add(d, r / 1000.0, &y[r]);
    }
    report_data_finish(d);
    const double *p;
    int n = report_data_points(d, 0, &p);
    assert_true(n <= 2 * (rows / k + 1) + 2);
    assert_close(p[0], 0.0, 0.0);
    assert_close(p[1], y[0], 0.0);
    assert_close(p[2 * (n - 1)], (rows - 1) / 1000.0, 1e-12);
    assert_close(p[2 * n - 1], y[rows - 1], 0.0);
    double hi = -INFINITY, lo = INFINITY;
    for (int i = 0; i < n; i++) {
        int r = (int)lround(p[2 * i] * 1000.0);
        assert_true(r >= 0 && r < rows);
        assert_close(p[2 * i + 1], y[r], 0.0); /* a row as given */
        if (i)
            assert_true(p[2 * i] > p[2 * i - 2]); /* time order, no row twice */
        hi = fmax(hi, p[2 * i + 1]), lo = fmin(lo, p[2 * i + 1]);
    }
    /* Each bucket (k rows, longer than the 20 ms period) holds a peak and a trough. */
    assert_true(k >= 20);
    for (int i = 1; i + 1 < n; i += 2)
        assert_true(fabs(p[2 * i + 1]) > 1.9);
    assert_true(hi > 1.99 && lo < -1.99);
    free(y);
    report_data_free(d);
}

/* A value that is not finite leaves a break (NaN) in the line, kept or bucketed. */
static void not_finite_breaks(void **state)
{
    (void)state;
    for (int rows = 10; rows <= 100000; rows *= 10000) {
        struct report_data *d = report_data_new(1, rows);
        for (int r = 0; r < rows; r++) {
            double v = r == rows / 2 ? INFINITY : 1.0 + r;
            report_data_add(d, r, &v);
        }
        report_data_finish(d);
        const double *p;
        int n = report_data_points(d, 0, &p), breaks = 0;
        for (int i = 0; i < n; i++)
            breaks += isnan(p[2 * i + 1]) || isinf(p[2 * i + 1]);
        assert_int_equal(breaks, 1);
        report_data_free(d);
    }
}

static void format_from_extension(void **state)
{
    (void)state;
    assert_int_equal(fig_format_of("a.png"), FIG_PNG);
    assert_int_equal(fig_format_of("dir.x/A.SVG"), FIG_SVG);
    assert_int_equal(fig_format_of("report.Pdf"), FIG_PDF);
    assert_int_equal(fig_format_of("a.jpg"), FIG_FORMAT_NONE);
    assert_int_equal(fig_format_of("png"), FIG_FORMAT_NONE);
    assert_int_equal(fig_format_of("dir.png/a"), FIG_FORMAT_NONE);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(few_rows_are_all_kept),
        cmocka_unit_test(many_rows_keep_the_envelope),
        cmocka_unit_test(not_finite_breaks),
        cmocka_unit_test(format_from_extension),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
