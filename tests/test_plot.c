/* test_plot.c: 1-2-5 ticks, axis ends rounded outward, autoscaling that grows at once
 * and shrinks only when told to, tick labels, and min-max columns that show a fast
 * oscillation as a band. */
#include "testutil.h"

#include <string.h>

#include "app/plot.h"

static void ticks(void **state)
{
    (void)state;
    assert_close(plot_tick_step(0.0, 10.0, 5), 2.0, 1e-12);
    assert_close(plot_tick_step(0.0, 10.0, 4), 5.0, 1e-12);
    assert_close(plot_tick_step(0.0, 1.0, 10), 0.1, 1e-12);
    assert_close(plot_tick_step(-0.03, 0.07, 4), 0.05, 1e-12);
    assert_close(plot_tick_step(0.0, 7000.0, 4), 2000.0, 1e-9);
    double lo = -0.23, hi = 0.61;
    plot_round_out(&lo, &hi, 0.2);
    assert_close(lo, -0.4, 1e-12);
    assert_close(hi, 0.8, 1e-12);
    lo = 0.4, hi = 0.8; /* already on ticks: unchanged */
    plot_round_out(&lo, &hi, 0.2);
    assert_close(lo, 0.4, 1e-12);
    assert_close(hi, 0.8, 1e-12);
}

static void labels(void **state)
{
    (void)state;
    char b[16];
    plot_tick_label(-0.5, 0.5, b, sizeof b);
    assert_string_equal(b, "-0.5");
    plot_tick_label(10.0, 5.0, b, sizeof b);
    assert_string_equal(b, "10");
    plot_tick_label(-1e-17, 0.1, b, sizeof b); /* no "-0.0" */
    assert_string_equal(b, "0.0");
    plot_tick_label(0.25, 0.05, b, sizeof b);
    assert_string_equal(b, "0.25");
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
    /* Flat data keeps the scale. */
    double keep = s.hi - s.lo;
    plot_scale_update(&s, 0.0, 0.0, 4, 5);
    assert_close(s.hi - s.lo, keep, 0.0);
}

/* 20 Hz sampled at 2 kHz over 1 s onto 8 dot columns: each column holds whole periods,
 * so min-max draws every column from top to bottom; a slow ramp draws a thin line. */
static void minmax_band(void **state)
{
    (void)state;
    enum { N = 2000 };
    static double t[N], y[N];
    for (int k = 0; k < N; k++) {
        t[k] = k / 2000.0;
        y[k] = sin(2 * M_PI * 20.0 * t[k]);
    }
    struct canvas *c = canvas_new(4, 2); /* 8 x 8 dots */
    struct scale s = {.lo = -1.0, .hi = 1.0, .step = 0.5, .set = true};
    plot_series(c, t, y, N, 1, 0.0, 1.0, &s, false, 1);
    for (int cx = 0; cx < 4; cx++)
        for (int cy = 0; cy < 2; cy++)
            assert_int_equal(canvas_bits(c, cx, cy), 0xFF);
    canvas_clear(c);
    for (int k = 0; k < N; k++)
        y[k] = -1.0 + 2.0 * t[k];
    plot_series(c, t, y, N, 1, 0.0, 1.0, &s, false, 1);
    int dots = 0;
    for (int cx = 0; cx < 4; cx++)
        for (int cy = 0; cy < 2; cy++)
            dots += __builtin_popcount(canvas_bits(c, cx, cy));
    assert_true(dots >= 8 && dots <= 16); /* about one dot a column, joined */
    /* Dashed: every other pair of columns left out. */
    canvas_clear(c);
    for (int k = 0; k < N; k++)
        y[k] = 0.0;
    plot_series(c, t, y, N, 1, 0.0, 1.0, &s, true, 1);
    assert_true(canvas_bits(c, 0, 0) != 0 || canvas_bits(c, 0, 1) != 0);
    assert_true(canvas_bits(c, 1, 0) == 0 && canvas_bits(c, 1, 1) == 0);
    canvas_free(c);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(ticks),
        cmocka_unit_test(labels),
        cmocka_unit_test(autoscale),
        cmocka_unit_test(minmax_band),
    };
    return cmocka_run_group_tests_name("plot", tests, NULL, NULL);
}
