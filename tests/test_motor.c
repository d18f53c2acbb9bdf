/* test_motor.c: the four waveforms against their defining formulas, their values at
 * the jumps, their breakpoints, and pieces that extend each smooth part exactly. */
#include "testutil.h"

#include "core/motor.h"

/* The definitions, written out independently of motor.c. */
static double spec_wave(enum wave w, double th)
{
    switch (w) {
    case WAVE_SINE:
        return sin(th);
    case WAVE_SQUARE:
        return sin(th) > 0 ? 1.0 : sin(th) < 0 ? -1.0 : 0.0;
    case WAVE_TRIANGLE:
        return 2.0 / M_PI * asin(sin(th));
    case WAVE_SAWTOOTH: {
        double q = th / (2.0 * M_PI) + 0.5;
        return 2.0 * (q - floor(q)) - 1.0;
    }
    default:
        return NAN;
    }
}

static void matches_spec_formulas(void **state)
{
    (void)state;
    for (int w = 0; w < WAVE_COUNT; w++) {
        for (int i = 0; i < 20000; i++) {
            double c = -3.0 + 6.0 * (i + 0.37) / 20000.0; /* never exactly on a jump */
            assert_close(motor_wave((enum wave)w, c), spec_wave((enum wave)w, 2 * M_PI * c),
                         1e-12);
        }
    }
}

static void values_at_special_phases(void **state)
{
    (void)state;
    for (int w = 0; w < WAVE_COUNT; w++)
        assert_close(motor_wave((enum wave)w, 0.0), 0.0, 0.0);
    assert_close(motor_wave(WAVE_SQUARE, 0.5), 0.0, 0.0);    /* sign(0) at the jumps */
    assert_close(motor_wave(WAVE_SQUARE, 0.25), 1.0, 0.0);
    assert_close(motor_wave(WAVE_SQUARE, 0.75), -1.0, 0.0);
    assert_close(motor_wave(WAVE_TRIANGLE, 0.25), 1.0, 1e-15); /* +1 at pi/2 */
    assert_close(motor_wave(WAVE_TRIANGLE, 0.75), -1.0, 1e-15);
    assert_close(motor_wave(WAVE_SAWTOOTH, 0.5), -1.0, 0.0);  /* 2 frac(1) - 1 */
    assert_close(motor_wave(WAVE_SAWTOOTH, 0.25), 0.5, 1e-15); /* rising */
    /* A grid time that lands on a jump up to rounding counts as on it. */
    assert_close(motor_wave(WAVE_SQUARE, 1.8 * (50 * 0.01) / 1.8), 0.0, 0.0);
    assert_close(motor_wave(WAVE_SQUARE, 0.9 * (0.5 / 0.9)), 0.0, 0.0);
    struct motor m = {WAVE_SQUARE, 2.0, 1.0, 0.0};
    assert_close(motor_position(&m, 50 * 0.01), 0.0, 0.0);
    assert_close(motor_position(&m, 0.2), 2.0, 0.0);
}

static void breakpoints_listed(void **state)
{
    (void)state;
    double out[8];
    struct motor sq = {WAVE_SQUARE, 1.0, 2.0, 0.0}; /* jumps every 0.25 s */
    assert_int_equal(motor_breakpoints(&sq, 0.1, 0.6, out, 8), 2);
    assert_close(out[0], 0.25, 1e-15);
    assert_close(out[1], 0.5, 1e-15);
    /* On the ends (up to rounding) does not count as inside. */
    assert_int_equal(motor_breakpoints(&sq, 0.25, 0.5, out, 8), 0);
    assert_int_equal(motor_breakpoints(&sq, 0.24, 0.26, out, 8), 1);
    struct motor tr = {WAVE_TRIANGLE, 1.0, 1.0, 0.0}; /* corners at 0.25 + k/2 */
    assert_int_equal(motor_breakpoints(&tr, 0.0, 1.0, out, 8), 2);
    assert_close(out[0], 0.25, 1e-15);
    assert_close(out[1], 0.75, 1e-15);
    struct motor sw = {WAVE_SAWTOOTH, 1.0, 0.5, 0.0}; /* jumps at (k + 1/2)/f = 1, 3, ... */
    assert_int_equal(motor_breakpoints(&sw, 0.0, 4.0, out, 8), 2);
    assert_close(out[0], 1.0, 1e-15);
    assert_close(out[1], 3.0, 1e-15);
    struct motor si = {WAVE_SINE, 1.0, 1.0, 0.0};
    assert_int_equal(motor_breakpoints(&si, 0.0, 10.0, out, 8), 0);
    /* More than fit: the count is still right, and counting does not walk them. */
    assert_int_equal(motor_breakpoints(&sq, 0.0, 10.1, out, 8), 40);
    assert_close(out[7], 2.0, 1e-15);
    struct motor fast = {WAVE_SQUARE, 1.0, 1e6, 0.0};
    assert_int_equal(motor_breakpoints(&fast, 0.0, 0.05, out, 8), 99999);
    assert_close(out[0], 0.5e-6, 1e-18);
}

/* A piece gives the waveform's values and slope across its interval and extends the
 * same line (or constant) past its ends, where the waveform itself has moved on. */
static void pieces_extend_smoothly(void **state)
{
    (void)state;
    for (int w = 0; w < WAVE_COUNT; w++) {
        struct motor m = {(enum wave)w, 0.7, 1.3, 0.0};
        for (int i = 0; i < 50; i++) {
            double tm = 0.013 + i * 0.0917;
            struct motor_piece p;
            motor_piece_at(&m, tm, &p);
            double u, du, h = 1e-6;
            motor_piece_eval(&p, tm, &u, &du);
            assert_close(u, motor_position(&m, tm), 1e-12);
            /* du is the derivative of u along the piece. */
            double up, dup, um, dum;
            motor_piece_eval(&p, tm + h, &up, &dup);
            motor_piece_eval(&p, tm - h, &um, &dum);
            assert_close(du, (up - um) / (2 * h), 1e-6);
        }
    }
    /* The square's positive piece stays +A past its end at t = 0.5/f. */
    struct motor sq = {WAVE_SQUARE, 1.0, 1.0, 0.0};
    struct motor_piece p;
    double u, du;
    motor_piece_at(&sq, 0.4, &p);
    motor_piece_eval(&p, 0.5, &u, &du);
    assert_close(u, 1.0, 0.0);
    motor_piece_at(&sq, 0.6, &p);
    motor_piece_eval(&p, 0.5, &u, &du);
    assert_close(u, -1.0, 0.0);
}

/* Retuning keeps u continuous and then runs at the new frequency. */
static void retune_is_continuous(void **state)
{
    (void)state;
    for (int w = 0; w < WAVE_COUNT; w++) {
        struct motor m = {(enum wave)w, 0.8, 1.3, 0.0};
        double t = 37.123;
        double before = motor_position(&m, t);
        motor_retune(&m, 0.77, t);
        assert_close(motor_position(&m, t), before, 1e-9);
        /* One new period later the drive repeats. */
        assert_close(motor_position(&m, t + 1.0 / 0.77 + 0.05),
                     motor_position(&m, t + 0.05), 1e-9);
        /* Breakpoints follow the shifted phase. */
        double out[4];
        int nb = motor_breakpoints(&m, t, t + 2.0, out, 4);
        for (int i = 0; i < nb && i < 4; i++) {
            struct motor_piece a, b;
            motor_piece_at(&m, out[i] - 1e-6, &a);
            motor_piece_at(&m, out[i] + 1e-6, &b);
            assert_true(a.cref != b.cref || a.w0 != b.w0 || a.slope != b.slope);
        }
    }
}

static void names_round_trip(void **state)
{
    (void)state;
    for (int w = 0; w < WAVE_COUNT; w++)
        assert_int_equal(motor_wave_parse(motor_wave_name((enum wave)w)), w);
    assert_int_equal(motor_wave_parse("Sine"), -1);
    assert_null(motor_wave_name(WAVE_COUNT));
    assert_true(motor_has_jumps(WAVE_SQUARE) && motor_has_jumps(WAVE_SAWTOOTH));
    assert_false(motor_has_jumps(WAVE_SINE) || motor_has_jumps(WAVE_TRIANGLE));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(matches_spec_formulas),
        cmocka_unit_test(values_at_special_phases),
        cmocka_unit_test(breakpoints_listed),
        cmocka_unit_test(pieces_extend_smoothly),
        cmocka_unit_test(retune_is_continuous),
        cmocka_unit_test(names_round_trip),
    };
    return cmocka_run_group_tests_name("motor", tests, NULL, NULL);
}
