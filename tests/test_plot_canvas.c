/* test_plot_canvas.c: 1-2-5 ticks, axis ends rounded outward, autoscaling that grows at once
 * and shrinks only when told to, and traces and paths rasterised on axes dot by dot
 * (min-max columns that show a fast oscillation as a band). */
#include "testutil.h"

#include <stdbool.h>
#include <string.h>

#include "chart/plot_canvas.h"

static void ticks(void **state)
{
    (void)state;
    assert_close(axis_step(0.0, 10.0, 5), 2.0, 1e-12);
    assert_close(axis_step(0.0, 10.0, 4), 5.0, 1e-12);
    assert_close(axis_step(0.0, 1.0, 10), 0.1, 1e-12);
    assert_close(axis_step(-0.03, 0.07, 4), 0.05, 1e-12);
    assert_close(axis_step(0.0, 7000.0, 4), 2000.0, 1e-9);
    double lo = -0.23, hi = 0.61;
    axis_round_out(&lo, &hi, 0.2);
    assert_close(lo, -0.4, 1e-12);
    assert_close(hi, 0.8, 1e-12);
    lo = 0.4, hi = 0.8; /* already on ticks: unchanged */
    axis_round_out(&lo, &hi, 0.2);
    assert_close(lo, 0.4, 1e-12);
    assert_close(hi, 0.8, 1e-12);
}

static void autoscale(void **state)
{
    (void)state;
    struct scale s = {0};
    plot_scale_update(&s, -0.9, 0.9, 4, 5);
    assert_true(s.set && s.lo <= -0.9 && s.hi >= 0.9);
    double lo = s.lo, hi = s.hi;
    /* Ends are tick multiples. */
    assert_close(s.lo / s.step, round(s.lo / s.step), 1e-9);
    assert_close(s.hi / s.step, round(s.hi / s.step), 1e-9);
    /* Data that fits: nothing moves (no jitter). */
    plot_scale_update(&s, -0.7, 0.8, 4, 5);
    assert_true(s.lo == lo && s.hi == hi);
    /* Data beyond: grows at once. */
    plot_scale_update(&s, -0.5, 3.1, 4, 5);
    assert_true(s.hi >= 3.1 && s.lo <= lo);
    double big = s.hi - s.lo;
    /* Much smaller data: shrinks only after 5 quiet updates in a row. */
    for (int i = 0; i < 4; i++) {
        plot_scale_update(&s, -0.1, 0.1, 4, 5);
        assert_close(s.hi - s.lo, big, 0.0);
    }
    plot_scale_update(&s, -0.1, 0.1, 4, 5);
    assert_true(s.hi - s.lo < 0.5 * big);
    assert_true(s.lo <= -0.1 && s.hi >= 0.1);
    /* A scale set from flat data only (a chain at rest) takes the first real data at
     * once instead of waiting to shrink. */
    struct scale f = {0};
    plot_scale_update(&f, 0.0, 0.0, 4, 5);
    assert_true(f.set && f.hi - f.lo >= 1.0);
    plot_scale_update(&f, 0.0, 0.08, 4, 5);
    assert_true(f.hi - f.lo < 0.2 && f.hi >= 0.08 && f.lo <= 0.0);
    /* A scale forgotten (set cleared, as a chart placed anew does after fitting its axes
     * to a placeholder -1..1) and then given flat data takes the first real data at once
     * too: the placeholder was no data's range. */
    struct scale p = {0};
    plot_scale_update(&p, -1.0, 1.0, 4, 5);
    p.set = false;
    plot_scale_update(&p, 0.0, 0.0, 4, 5);
    plot_scale_update(&p, -0.02, 0.05, 4, 5);
    assert_true(p.hi - p.lo < 0.2 && p.hi >= 0.05 && p.lo <= -0.02);
    /* Flat data keeps the scale. */
    double keep = s.hi - s.lo;
    plot_scale_update(&s, 0.0, 0.0, 4, 5);
    assert_close(s.hi - s.lo, keep, 0.0);
}

/* 20 Hz sampled at 2 kHz over 1 s onto 8 dot columns: each column holds whole periods,
 * so min-max draws every column from top to bottom; a slow ramp draws a thin line. */
/* Dot (x, y) of c (y from the top) is set. */
static bool dot(const struct canvas *c, int x, int y)
{
    static const uint8_t bit[4][2] = {{0x01, 0x08}, {0x02, 0x10}, {0x04, 0x20}, {0x40, 0x80}};
    return (canvas_bits(c, x / 2, y / 4) & bit[y % 4][x % 2]) != 0;
}

/* Dots set on c. */
static int dots(const struct canvas *c)
{
    int n = 0;
    for (int cx = 0; cx < c->cols; cx++)
        for (int cy = 0; cy < c->rows; cy++)
            n += __builtin_popcount(canvas_bits(c, cx, cy));
    return n;
}

/* Axes for a 10 x 5 cell canvas (20 x 20 dots) with a tick on every cell: t - t_ref on
 * dot 0.5 + 2 t, y on dot 1.5 + 4 y from the bottom. So t = (X - 0.5) / 2 lands on dot
 * column X and y = (Y - 1.5) / 4 on dot Y from the bottom, row 19 - Y from the top. */
static const struct axis xa10 = {
    .lo = 0.0, .step = 1.0, .intervals = 9, .first = 0, .spacing = 1, .cells = 10, .dpc = 2};
static const struct axis ya5 = {
    .lo = 0.0, .step = 1.0, .intervals = 4, .first = 0, .spacing = 1, .cells = 5, .dpc = 4};

static double t_at(int x)
{
    return (x - 0.5) / 2.0;
}

static double y_at(int y)
{
    return (y - 1.5) / 4.0;
}

/* Known lines through plot_trace, dot by dot. */
static void trace_lines(void **state)
{
    (void)state;
    const double t_ref = 100.0;
    double t[400], y[400];
    struct canvas *c = canvas_new(10, 5);
    /* One sample a column, one dot higher each: a 45-degree line one dot thick. */
    for (int x = 0; x < 20; x++)
        t[x] = t_ref + t_at(x), y[x] = y_at(x);
    plot_trace(c, t, y, 20, 1, t_ref, &xa10, &ya5, false, 1);
    for (int x = 0; x < 20; x++)
        for (int r = 0; r < 20; r++)
            assert_int_equal(dot(c, x, r), r == 19 - x);
    /* Three dots higher a column: each column spans up to the row next to the one
     * before, so the line has no gaps. */
    canvas_clear(c);
    for (int x = 0; x < 7; x++)
        t[x] = t_ref + t_at(x), y[x] = y_at(3 * x);
    plot_trace(c, t, y, 7, 1, t_ref, &xa10, &ya5, false, 1);
    for (int x = 0; x < 20; x++)
        for (int r = 0; r < 20; r++) {
            bool want = x == 0 ? r == 19 : x < 7 && r >= 19 - 3 * x && r <= 21 - 3 * x;
            assert_int_equal(dot(c, x, r), want);
        }
    /* A constant at a tick value (y = 1: cell 1 from the bottom, the dot just above its
     * middle), sampled many times a column: one row, every column. */
    canvas_clear(c);
    for (int k = 0; k < 400; k++)
        t[k] = t_ref - 0.25 + k * (10.0 / 400), y[k] = 1.0;
    plot_trace(c, t, y, 400, 1, t_ref, &xa10, &ya5, false, 1);
    for (int x = 0; x < 20; x++)
        for (int r = 0; r < 20; r++)
            assert_int_equal(dot(c, x, r), r == 19 - 6);
    /* Dashed: four dots on, four off, along the line: columns 4-7, 12-15 left out. */
    canvas_clear(c);
    plot_trace(c, t, y, 400, 1, t_ref, &xa10, &ya5, true, 1);
    for (int x = 0; x < 20; x++)
        assert_int_equal(dot(c, x, 13), (x / 4) % 2 == 0);
    assert_int_equal(dots(c), 12);
    /* Dashed and steep (the ghost's fast swings, issue 22 item 7): dashed along its
     * length, not whole columns on and off, so it still reads as a curve: a line 4 dots
     * down a column has, in every column, dots on and dots off. */
    canvas_clear(c);
    for (int x = 0; x < 5; x++)
        t[x] = t_ref + t_at(x), y[x] = y_at(4 * x);
    plot_trace(c, t, y, 5, 1, t_ref, &xa10, &ya5, true, 1);
    int on = 0;
    for (int x = 1; x < 5; x++) {
        int in_column = 0;
        for (int r = 0; r < 20; r++)
            in_column += dot(c, x, r);
        assert_true(in_column >= 1 && in_column <= 3); /* of 4 */
        on += in_column;
    }
    assert_true(on >= 6 && on <= 10); /* about half of the 16 */
    /* Samples further apart than a column are joined by a straight line. */
    canvas_clear(c);
    t[0] = t_ref + t_at(0), y[0] = y_at(0);
    t[1] = t_ref + t_at(18), y[1] = y_at(18);
    plot_trace(c, t, y, 2, 1, t_ref, &xa10, &ya5, false, 1);
    for (int x = 0; x < 19; x++)
        assert_true(dot(c, x, 19 - x));
    assert_int_equal(dots(c), 19);
    /* A sample off the canvas still joins the first one on it; samples that are not
     * finite are skipped. */
    canvas_clear(c);
    t[0] = t_ref + t_at(-10), y[0] = y_at(-10);
    t[1] = t_ref + t_at(-3), y[1] = NAN;
    t[2] = t_ref + t_at(10), y[2] = y_at(10);
    plot_trace(c, t, y, 3, 1, t_ref, &xa10, &ya5, false, 1);
    for (int x = 0; x <= 10; x++)
        assert_true(dot(c, x, 19 - x));
    assert_int_equal(dots(c), 11);
    /* Interleaved records: stride 2 reads every other value. */
    canvas_clear(c);
    double rec[40];
    for (int x = 0; x < 20; x++)
        rec[2 * x] = t_ref + t_at(x), rec[2 * x + 1] = y_at(19 - x);
    plot_trace(c, rec, rec + 1, 20, 2, t_ref, &xa10, &ya5, false, 1);
    for (int x = 0; x < 20; x++)
        assert_true(dot(c, x, x));
    assert_int_equal(dots(c), 20);
    canvas_free(c);
}

/* 20 Hz sampled at 2 kHz over 1 s onto 8 dot columns, on axes: [0, 1) s spans the 8
 * columns exactly and [-1, 1] the 8 rows, so min-max fills every dot. */
static void trace_band(void **state)
{
    (void)state;
    enum { N = 2000 };
    static double t[N], y[N];
    for (int k = 0; k < N; k++) {
        t[k] = k / 2000.0;
        y[k] = sin(2 * M_PI * 20.0 * t[k]);
    }
    const struct axis xa = {
        .lo = 0.125, .step = 0.25, .intervals = 3, .first = 0, .spacing = 1, .cells = 4, .dpc = 2};
    const struct axis ya = {
        .lo = -0.5, .step = 1.0, .intervals = 1, .first = 0, .spacing = 1, .cells = 2, .dpc = 4};
    assert_close(axis_dot(&xa, 0.0), -0.5, 1e-12);
    assert_close(axis_dot(&ya, -1.0), -0.5, 1e-12);
    struct canvas *c = canvas_new(4, 2);
    plot_trace(c, t, y, N, 1, 0.0, &xa, &ya, false, 1);
    assert_int_equal(dots(c), 64);
    canvas_free(c);
}

/* A rolling window on a fitted time axis in absolute time: the newest sample (100 s, on a
 * whole cell of 2/7 s) on the last dot column. */
static void trace_rolling(void **state)
{
    (void)state;
    struct axis xa, ya;
    axis_fit_rolling(&xa, 100.0, 10.0, 5, 40, 2, 4);
    axis_fit(&ya, -1.0, 1.0, 4, 10, 4, 2);
    struct canvas *c = canvas_new(40, 10);
    double t[2] = {95.0, 100.0}, y[2] = {0.0, 0.0};
    plot_trace(c, t, y, 2, 1, 0.0, &xa, &ya, false, 1);
    int row = 39 - (int)floor(axis_dot(&ya, 0.0) + 0.5);
    assert_true(dot(c, 79, row));
    assert_true(dot(c, (int)floor(axis_dot(&xa, 95.0) + 0.5), row));
    assert_int_equal(dots(c), 79 - (int)floor(axis_dot(&xa, 95.0) + 0.5) + 1);
    canvas_free(c);
}

/* plot_path: joined segments, clipped to the canvas, broken by a value that is not
 * finite. */
static void path(void **state)
{
    (void)state;
    struct canvas *c = canvas_new(10, 5);
    double x[6] = {t_at(0), t_at(19), t_at(19), 1e300, t_at(0), t_at(2)};
    double y[6] = {y_at(0), y_at(19), y_at(0), 1e300, y_at(10), y_at(10)};
    plot_path(c, x, y, 3, 1, &xa10, &ya5, 2);
    for (int k = 0; k < 20; k++) {
        assert_true(dot(c, k, 19 - k)); /* the diagonal */
        assert_true(dot(c, 19, k));     /* down the right edge */
    }
    assert_int_equal(dots(c), 39);
    canvas_clear(c);
    x[3] = NAN;
    plot_path(c, x + 2, y + 2, 4, 1, &xa10, &ya5, 2);
    /* (19, 19) off to nowhere: its one dot; then after the break a short flat line. */
    assert_true(dot(c, 19, 19));
    for (int k = 0; k <= 2; k++)
        assert_true(dot(c, k, 9));
    assert_int_equal(dots(c), 4);
    canvas_clear(c);
    x[3] = 1e300;
    plot_path(c, x + 2, y + 2, 2, 1, &xa10, &ya5, 2); /* towards a point far away */
    assert_true(dot(c, 19, 19));
    assert_int_equal(dots(c), 1);
    canvas_free(c);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(ticks),
        cmocka_unit_test(autoscale),
        cmocka_unit_test(trace_lines),
        cmocka_unit_test(trace_band),
        cmocka_unit_test(trace_rolling),
        cmocka_unit_test(path),
    };
    return cmocka_run_group_tests_name("plot", tests, NULL, NULL);
}
