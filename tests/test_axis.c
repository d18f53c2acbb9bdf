/* test_axis.c: axes on whole cells. Every gap between ticks is the same whole number of
 * cells for every size, ticks are exact multiples of a 1-2-5 step on the middle of their
 * cells, labels fit 7 columns, read back as the tick's value and never repeat, and a
 * rolling time axis has the latest time on its last cell. */
#include "testutil.h"

#include <stdbool.h>
#include <stdlib.h>
#include <string.h>

#include "chart/axis.h"

/* True when step is 1, 2 or 5 x 10^k. */
static bool one_two_five(double step)
{
    double m = step / pow(10.0, floor(log10(step) + 1e-9));
    return fabs(m - 1.0) < 1e-9 || fabs(m - 2.0) < 1e-9 || fabs(m - 5.0) < 1e-9;
}

/* Checks everything an axis fitted to [lo, hi] promises. */
static void check_layout(const struct axis *a, double lo, double hi, int cells, int dpc,
                         int min_spacing)
{
    assert_int_equal(a->cells, cells);
    assert_int_equal(a->dpc, dpc);
    assert_true(a->intervals >= 1);
    assert_true(one_two_five(a->step));
    /* Ticks are whole multiples of the step, and cover [lo, hi]. */
    double q = a->lo / a->step;
    assert_close(q, round(q), 1e-9 * fmax(1.0, fabs(q)));
    assert_true(a->lo <= lo + 1e-9 * a->step);
    assert_true(a->lo + a->intervals * a->step >= hi - 1e-9 * a->step);
    /* Every tick on the axis, each on the middle of its cell, spacing cells apart. */
    int last = a->first + a->intervals * a->spacing;
    assert_true(a->first >= 0 && last <= cells - 1);
    for (int k = 0; k <= a->intervals; k++) {
        double want = (a->first + k * a->spacing) * dpc + (dpc - 1) / 2.0;
        assert_close(axis_dot(a, a->lo + k * a->step), want, 1e-9 * want + 1e-9);
    }
    assert_true(a->spacing >= 1);
    if (cells - 1 >= 2 * min_spacing)
        assert_true(a->spacing >= min_spacing);
    /* No room for a wider gap: the leftover cells are fewer than the intervals, and they
     * go half to each side. */
    int leftover = cells - 1 - a->intervals * a->spacing;
    assert_true(leftover < a->intervals);
    assert_int_equal(a->first, leftover / 2);
}

static const double ranges[][2] = {
    {-1.0, 1.0},  {-0.23, 0.61}, {0.0, 10.0},  {-0.4, 0.8},      {3.7, 4.1},      {-30.0, 0.0},
    {1e-6, 7e-6}, {-2e4, 2e4},   {0.05, 0.93}, {-1234.0, -17.0}, {999.9, 1000.1},
};

/* Every size from 3 to 200 cells, every max_ticks 2..8: constant whole-cell gaps. */
static void spacing_exact(void **state)
{
    (void)state;
    for (size_t r = 0; r < sizeof ranges / sizeof ranges[0]; r++)
        for (int cells = 3; cells <= 200; cells++)
            for (int mt = 2; mt <= 8; mt++)
                for (int ms = 1; ms <= 3; ms++) {
                    struct axis a;
                    double lo = ranges[r][0], hi = ranges[r][1];
                    axis_fit(&a, lo, hi, mt, cells, 4, ms);
                    check_layout(&a, lo, hi, cells, 4, ms);
                }
}

/* The step is as fine as max_ticks allows: 1-2-5 with at most max_ticks intervals on the
 * data, and a range already on ticks (a scale's) is laid as it is. */
static void steps(void **state)
{
    (void)state;
    struct axis a;
    axis_fit(&a, -0.23, 0.61, 4, 100, 4, 1);
    assert_close(a.step, 0.5, 1e-15);
    assert_close(a.lo, -0.5, 1e-15);
    assert_int_equal(a.intervals, 3);
    axis_fit(&a, -0.4, 0.8, 5, 100, 4, 1); /* 6 x 0.2: kept, not rounded to 0.5s */
    assert_close(a.step, 0.2, 1e-15);
    assert_close(a.lo, -0.4, 1e-15);
    assert_int_equal(a.intervals, 6);
    /* 13 rows, ticks 2 rows apart at least: 6 intervals fit on rows 0, 2, .. 12. */
    axis_fit(&a, -0.4, 0.8, 5, 13, 4, 2);
    assert_close(a.step, 0.2, 1e-15);
    assert_int_equal(a.spacing, 2);
    assert_int_equal(a.first, 0);
    /* 8 rows: 6 intervals would be 1 row apart; the step widens to 0.5. */
    axis_fit(&a, -0.4, 0.8, 5, 8, 4, 2);
    assert_close(a.step, 0.5, 1e-15);
    assert_close(a.lo, -0.5, 1e-15);
    assert_int_equal(a.intervals, 3);
    assert_int_equal(a.spacing, 2);
    assert_int_equal(a.first, 0);
    /* Flat or reversed data still gives an axis. */
    axis_fit(&a, 0.0, 0.0, 4, 10, 4, 2);
    assert_true(a.intervals >= 1 && a.lo < 0.0 && a.lo + a.intervals * a.step > 0.0);
    axis_fit(&a, 2.0, -2.0, 4, 10, 4, 2);
    assert_true(a.lo <= -2.0 && a.lo + a.intervals * a.step >= 2.0);
}

/* Values map linearly over all the cells, the leftover ones included. */
static void linear(void **state)
{
    (void)state;
    struct axis a;
    axis_fit(&a, -1.0, 1.0, 4, 11, 4, 2); /* 0.5 a tick, 10 / 4: spacing 2, 2 left over */
    assert_int_equal(a.spacing, 2);
    assert_int_equal(a.first, 1);
    assert_close(axis_dot(&a, -1.0), 1 * 4 + 1.5, 1e-12);
    assert_close(axis_dot(&a, 1.0), 9 * 4 + 1.5, 1e-12);
    assert_close(axis_dot(&a, -1.25), 1 * 4 + 1.5 - 4.0, 1e-12); /* the cell below */
    assert_close(axis_dot(&a, 0.125), 5 * 4 + 1.5 + 2.0, 1e-12);
    assert_close(axis_value(&a, -0.5), -1.0 - 0.5 * (5.5 + 0.5) / 8.0, 1e-12);
    for (double d = -0.5; d < 44.0; d += 0.75)
        assert_close(axis_dot(&a, axis_value(&a, d)), d, 1e-12);
}

/* Labels of the axis fitted to [lo, hi]: at most 7 columns, the widest reported, all in
 * one form, each reading back as its tick's value, no two alike. */
static void check_labels(double lo, double hi, int max_ticks, int cells)
{
    struct axis a;
    axis_fit(&a, lo, hi, max_ticks, cells, 4, 2);
    char lab[64][AXIS_LABEL_MAX + 1];
    int n = a.intervals + 1, widest = 0, exps = 0, zeros = 0;
    assert_true(n <= 64);
    for (int k = 0; k < n; k++) {
        char big[32];
        memset(big, 'x', sizeof big);
        axis_label(&a, k, big, sizeof big);
        int len = (int)strlen(big);
        if (len > AXIS_LABEL_MAX)
            fail_msg("[%g, %g]: label %d \"%s\" is %d columns", lo, hi, k, big, len);
        memcpy(lab[k], big, (size_t)len + 1);
        widest = len > widest ? len : widest;
        exps += strchr(big, 'e') != NULL;
        zeros += strcmp(big, "0") == 0;
        double v = a.lo + k * a.step, got = strtod(big, NULL);
        if (!(fabs(got - v) <= 1e-6 * a.step))
            fail_msg("[%g, %g]: label \"%s\" for tick %.17g", lo, hi, big, v);
        if (strchr(big, 'e')) {
            /* Mantissa 1..9.x, no trailing zeros. */
            const char *m = big + (big[0] == '-');
            assert_true(m[0] >= '1' && m[0] <= '9');
            assert_true(m[1] == 'e' || (m[1] == '.' && strchr(m, 'e')[-1] != '0'));
        }
        for (int j = 0; j < k; j++)
            if (strcmp(lab[j], big) == 0)
                fail_msg("[%g, %g]: ticks %d and %d both read \"%s\"", lo, hi, j, k, big);
    }
    assert_int_equal(axis_label_width(&a), widest);
    assert_true(exps == 0 || exps + zeros == n); /* one form for the whole axis */
}

/* Ranges at every magnitude from 1e-9 to 1e9, either sign, narrow and wide, with steps
 * of 1, 2 and 5 (max_ticks 2..8). */
static void labels_sweep(void **state)
{
    (void)state;
    static const double mant[] = {1.0, 1.5, 2.3, 5.0, 7.7, 9.99};
    static const double rel[] = {1e-4, 1e-3, 0.02, 0.3, 1.0, 4.0};
    for (int p = -9; p <= 9; p++)
        for (size_t i = 0; i < sizeof mant / sizeof mant[0]; i++)
            for (int mt = 2; mt <= 8; mt++) {
                double v = mant[i] * pow(10.0, p);
                check_labels(0.0, v, mt, 40);
                check_labels(-v, 0.0, mt, 40);
                check_labels(-v, v, mt, 40);
                check_labels(-v, 0.3 * v, mt, 40);
                for (size_t r = 0; r < sizeof rel / sizeof rel[0]; r++) {
                    double s = rel[r] * pow(10.0, p);
                    check_labels(v - s / 2, v + s / 2, mt, 40);
                    check_labels(-v - s / 2, -v + s / 2, mt, 40);
                    check_labels(v - s / 2, v + s / 2, mt, 5);
                }
            }
}

/* Plain decimals where they fit, exponent form where they do not. */
static void label_forms(void **state)
{
    (void)state;
    struct axis a;
    char b[AXIS_LABEL_MAX + 1];
    axis_fit(&a, -0.5, 0.5, 4, 20, 4, 2);
    axis_label(&a, 0, b, sizeof b);
    assert_string_equal(b, "-0.5");
    axis_label(&a, 1, b, sizeof b);
    assert_string_equal(b, "0.0");
    axis_fit(&a, 0.0, 0.25, 5, 20, 4, 2);
    axis_label(&a, 5, b, sizeof b);
    assert_string_equal(b, "0.25");
    axis_fit(&a, 0.0, 10.0, 2, 20, 4, 2);
    axis_label(&a, 2, b, sizeof b);
    assert_string_equal(b, "10");
    axis_fit(&a, -20000.0, 20000.0, 4, 20, 4, 2); /* 6 columns: plain */
    axis_label(&a, 0, b, sizeof b);
    assert_string_equal(b, "-20000");
    axis_fit(&a, -2e7, 2e7, 4, 20, 4, 2); /* 9 columns plain: exponent form */
    axis_label(&a, 0, b, sizeof b);
    assert_string_equal(b, "-2e7");
    axis_label(&a, 2, b, sizeof b);
    assert_string_equal(b, "0");
    assert_int_equal(axis_label_width(&a), 4);
    /* -20000 where another label of the axis (10000000) does not fit plain. */
    struct axis wide = {.lo = -20000.0,
                        .step = 10000.0,
                        .intervals = 1002,
                        .first = 0,
                        .spacing = 1,
                        .cells = 1003,
                        .dpc = 2};
    axis_label(&wide, 0, b, sizeof b);
    assert_string_equal(b, "-2e4");
    axis_label(&wide, 1002, b, sizeof b);
    assert_string_equal(b, "1e7");
    axis_label(&wide, 3, b, sizeof b);
    assert_string_equal(b, "1e4");
    axis_fit(&a, 1.5e-5, 3e-5, 4, 20, 4, 2);
    axis_label(&a, 0, b, sizeof b);
    assert_string_equal(b, "1.5e-5");
    /* No "-0.0" from rounding noise. */
    struct axis z = {.lo = -0.3, .step = 0.1, .intervals = 6, .spacing = 1, .cells = 7, .dpc = 4};
    axis_label(&z, 3, b, sizeof b);
    assert_string_equal(b, "0.0");
    /* A hand-made axis no exact label fits (a huge offset beside a tiny step) still gets
     * labels within 7 columns, and a short buffer is never overrun. */
    struct axis odd = {
        .lo = -1.234567e-300, .step = 1e-310, .intervals = 3, .spacing = 1, .cells = 4, .dpc = 2};
    for (int k = 0; k <= 3; k++) {
        axis_label(&odd, k, b, sizeof b);
        assert_true(strlen(b) <= AXIS_LABEL_MAX);
    }
    assert_true(axis_label_width(&odd) <= AXIS_LABEL_MAX);
    char tiny[3] = "xx";
    axis_label(&a, 0, tiny, sizeof tiny);
    assert_string_equal(tiny, "1.");
}

/* Checks everything a rolling time axis promises for the window ending at end. */
static void check_rolling(const struct axis *a, double end, double win, int cells, int gap)
{
    assert_int_equal(a->cells, cells);
    assert_true(one_two_five(a->step));
    assert_true(a->spacing >= 1);
    if (cells - 1 >= 2 * gap)
        assert_true(a->spacing >= gap);
    /* The latest time on the last cell (its two dot columns; on its left edge it may
     * round to the dot before), or, until time fills the axis, 0 on the first cell's
     * middle. */
    if (axis_value(a, 0.5) > 1e-9 * win) {
        int dot_end = (int)floor(axis_dot(a, end) + 0.5);
        assert_true(dot_end >= 2 * cells - 3 && dot_end <= 2 * cells - 1);
        assert_true(axis_dot(a, end) >= 2 * cells - 2.5 - 1e-6);
    } else {
        assert_close(axis_dot(a, 0.0), 0.5, 1e-9);
        assert_true(axis_dot(a, end) <= 2 * cells - 0.5);
    }
    /* The whole window shown. */
    assert_true(axis_value(a, -0.5) <= fmax(end - win, 0.0) + 1e-9 * win);
    assert_true(axis_value(a, 2 * cells - 0.5) >= fmax(end, win) - 1e-9 * win);
    /* Ticks: whole multiples of the step, each on the middle of its cell, spacing apart,
     * all of those that fall on the axis and none before t = 0. */
    double q = a->lo / a->step;
    assert_close(q, round(q), 1e-9 * fmax(1.0, fabs(q)));
    assert_true(a->lo >= -1e-9 * a->step);
    int last = a->first + a->intervals * a->spacing;
    /* (A window on few cells may hold one tick: the axis's second is then past its end.) */
    assert_true(a->first >= 0 && (last <= cells - 1 || (a->intervals == 1 &&
                                                         a->first <= cells - 1)));
    assert_true(a->first < a->spacing);
    assert_true(last + a->spacing > cells - 1);
    for (int k = 0; k <= a->intervals; k++) {
        double want = (a->first + k * a->spacing) * 2 + 0.5;
        assert_close(axis_dot(a, a->lo + k * a->step), want, 1e-9 * want + 1e-9);
        /* Each label reads back as its tick's absolute time. */
        char b[AXIS_LABEL_MAX + 1];
        axis_label(a, k, b, sizeof b);
        assert_close(strtod(b, NULL), a->lo + k * a->step, 1e-9 * fabs(a->lo) + 1e-12);
    }
}

/* A rolling time axis in absolute time: the latest time on the last cell, the whole
 * window shown, ticks on whole cells labelled with their absolute time; as time goes on
 * the axis moves by whole cells, so a time already drawn stays on its dot columns'
 * pattern (its dot moves by 2 at a time). */
static void time_axis(void **state)
{
    (void)state;
    static const double windows[] = {1, 2, 5, 10, 20, 30, 60};
    static const double ends[] = {0.0, 0.37, 3.7, 10.0, 25.0, 25.3, 1234.56, 99999.9};
    for (size_t w = 0; w < sizeof windows / sizeof windows[0]; w++)
        for (size_t e = 0; e < sizeof ends / sizeof ends[0]; e++)
            for (int cells = 10; cells <= 200; cells += 7)
                for (int mt = 2; mt <= 8; mt++) {
                    struct axis a;
                    axis_fit_rolling(&a, ends[e], windows[w], mt, cells, 2, 5);
                    check_rolling(&a, ends[e], windows[w], cells, 5);
                }
    /* 10 s on 40 columns at t = 25 s: 14 .. 24 by 2, 7 columns apart, the latest time
     * (25 s) on the last cell. */
    struct axis a;
    axis_fit_rolling(&a, 25.0, 10.0, 5, 40, 2, 4);
    assert_close(a.lo, 14.0, 1e-12);
    assert_close(a.step, 2.0, 1e-12);
    assert_int_equal(a.intervals, 5);
    assert_int_equal(a.spacing, 7);
    char b[AXIS_LABEL_MAX + 1];
    axis_label(&a, a.intervals, b, sizeof b);
    assert_string_equal(b, "24");
    /* Before a window has passed: 0 .. 10 s and the leftover cells (4 of 2/7 s) on the
     * right, 0 on the first cell. */
    axis_fit_rolling(&a, 3.2, 10.0, 5, 40, 2, 4);
    assert_close(a.lo, 0.0, 1e-12);
    assert_int_equal(a.first, 0);
    assert_close(axis_value(&a, 2 * 40 - 1.5), 39 * 2.0 / 7, 1e-12);
    /* Time going on in steps of 0.01 s: t = 30 s moves by whole cells, never back. */
    double last = -1.0;
    for (int n = 3000; n <= 4000; n++) {
        axis_fit_rolling(&a, n * 0.01, 10.0, 5, 40, 2, 4);
        double d = axis_dot(&a, 30.0);
        assert_close(d - 2 * floor(d / 2), 0.5, 1e-6);
        assert_true(last < 0.0 || d <= last + 1e-9);
        last = d;
    }
    /* Times past 10^5 s: the step widens until the plain labels fit 7 columns. */
    axis_fit_rolling(&a, 123456.7, 1.0, 5, 40, 2, 4);
    assert_true(axis_label_width(&a) <= AXIS_LABEL_MAX);
    assert_true(a.step >= 1.0);
}

/* axis_fit_inside: the range's values all on the cells (to the outer cells' edges), at
 * least two ticks min_spacing apart inside it, never more shown than axis_fit shows; on
 * few rows, much less (the damping lesson's plot: 6 rows, [-0.6, 0.6]); and ranges
 * whose steps would be subnormal or overflow are laid without a fault. */
static void inside(void **state)
{
    (void)state;
    static const double ranges[][2] = {{-0.6, 0.6}, {-1.5, 1.5}, {-0.1, 0.6}, {0, 1000},
                                       {-0.002, 0.006}, {-3.2, 7.9}, {12.5, 13.25}};
    for (size_t i = 0; i < sizeof ranges / sizeof *ranges; i++)
        for (int cells = 3; cells <= 40; cells++) {
            double lo = ranges[i][0], hi = ranges[i][1];
            int ticks = cells / 2 < 2 ? 2 : cells / 2 > 8 ? 8 : cells / 2;
            struct axis a, b;
            axis_fit_inside(&a, lo, hi, ticks, cells, 4, 2);
            axis_fit(&b, lo, hi, ticks, cells, 4, 2);
            double shown = a.cells * a.step / a.spacing, wide = b.cells * b.step / b.spacing;
            assert_true(shown <= wide * (1 + 1e-12));
            assert_true(a.intervals >= 1 && a.first >= 0);
            assert_true(a.first + a.intervals * a.spacing <= cells - 1);
            /* every value of the range on the canvas's dots (dot d spans d +- 0.5) */
            assert_true(axis_dot(&a, lo) >= -0.5 - 1e-9);
            assert_true(axis_dot(&a, hi) <= cells * a.dpc - 0.5 + 1e-9);
            if (a.spacing < b.spacing || a.step != b.step) /* laid inside: ticks in range */
                assert_true(a.lo >= lo - 1e-12 && a.lo + a.intervals * a.step <= hi + 1e-12);
        }
    struct axis a;
    axis_fit_inside(&a, -0.6, 0.6, 3, 6, 4, 2);
    assert_true(a.cells * a.step / a.spacing <= 1.5 + 1e-12); /* axis_fit's: 3 */
    static const double odd[][2] = {{5e-324, 1e-323}, {0, 1e-320}, {-1.7e308, 1.7e308}};
    for (size_t i = 0; i < sizeof odd / sizeof *odd; i++) {
        axis_fit_inside(&a, odd[i][0], odd[i][1], 3, 7, 4, 2);
        assert_true(a.step > 0.0 && isfinite(a.lo) && a.intervals >= 1 && a.spacing >= 1);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(spacing_exact), cmocka_unit_test(steps),       cmocka_unit_test(linear),
        cmocka_unit_test(labels_sweep),  cmocka_unit_test(label_forms), cmocka_unit_test(time_axis),
        cmocka_unit_test(inside),
    };
    return cmocka_run_group_tests_name("axis", tests, NULL, NULL);
}
