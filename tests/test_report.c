/* test_report.c: the rows a figure keeps (fig/report.c), the figure formats, and X's
 * figure of a chart (fig/view_report.c): its curves at the values the strokes stand for,
 * a motor that does not move left out, no figure of a chart without a report. Few rows:
 * every one. Many rows: the first, then per bucket the smallest and the largest in time
 * order, then the last, each one of the rows given (so the curve lies on the CSV's rows);
 * an oscillation faster than a bucket keeps its envelope; a value that is not finite
 * breaks the line. */
#include "testutil.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "chart/axis.h"
#include "chart/strokes.h"
#include "fig/figure.h"
#include "fig/report.h"
#include "fig/view_report.h"

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

/* The SVG of the n charts c (report r each) in *svg (freed by the caller); the status. */
static int view_svg(const struct fig_chart *c, int n, char **svg)
{
    size_t len = 0;
    FILE *fp = open_memstream(svg, &len);
    assert_non_null(fp);
    struct report_look look = {NULL, "settings", 0.0, 0.0};
    int e = fig_view_report(fp, FIG_SVG, c, n, &look);
    fclose(fp);
    return e;
}

/* A chart 40 x 10 cells (80 x 40 dots) over t 0..8 s and x -1..1 m: mass 1's line from
 * the bottom left to the top right dot, a motor standing at 0. The figure draws mass 1
 * (one stroked path of its colour) and no motor (nothing black); without a report there
 * is no figure. */
static void view_report_draws_values(void **state)
{
    (void)state;
    struct strokes *k = strokes_new();
    assert_non_null(k);
    struct fig_chart c = {.aw = 40, .ah = 10, .axes = true, .strokes = k};
    axis_fit(&c.xa, 0.0, 8.0, 4, 40, 2, 4);
    axis_fit(&c.ya, -1.0, 1.0, 4, 10, 4, 2);
    strokes_begin(k, FIG_MASS, STROKE_LINE);
    strokes_point(k, 0.0, 39.0);
    strokes_point(k, 79.0, 0.0);
    strokes_begin(k, FIG_MOTOR, STROKE_DASHED);
    double zero = 39.0 - axis_dot(&c.ya, 0.0);
    strokes_point(k, 0.0, zero);
    strokes_point(k, 79.0, zero);
    struct fig_report r = {.title = "Displacement", .xlabel = "time t (s)",
                           .ylabel = "displacement x (m)", .time = true};
    snprintf(r.name[FIG_MASS], sizeof r.name[0], "mass 1");
    snprintf(r.name[FIG_MOTOR], sizeof r.name[0], "motor u(t)");
    c.report = &r;
    char *svg = NULL;
    assert_int_equal(view_svg(&c, 1, &svg), 0);
    assert_non_null(strstr(svg, "</svg>"));
    assert_non_null(strstr(svg, "stroke:rgb(0%,37.254902%,100%)"));
    assert_null(strstr(svg, "stroke:rgb(0%,0%,0%)"));
    free(svg);
    c.report = NULL;
    assert_int_equal(view_svg(&c, 1, &svg), EDOM);
    free(svg);
    fig_done();
    strokes_free(k);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(few_rows_are_all_kept),
        cmocka_unit_test(many_rows_keep_the_envelope),
        cmocka_unit_test(not_finite_breaks),
        cmocka_unit_test(format_from_extension),
        cmocka_unit_test(view_report_draws_values),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
