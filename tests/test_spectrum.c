/* test_spectrum.c: the Hann-windowed amplitude spectrum against answers found without
 * it: the Hann window's closed-form response (its neighbouring bins at half the level,
 * its scalloping loss between bins), a direct DFT summed term by term, and the levels of
 * sines of known amplitude. The allocations spectrum.c makes are counted (linked with
 * --wrap), so a refresh of the same length is seen to allocate nothing. */
#include "testutil.h"

#include <stdlib.h>

#include <fftw3.h>

#include "alloc_count.h"
#include "core/spectrum.h"

void *__real_fftw_malloc(size_t size);
void *__wrap_fftw_malloc(size_t size);
fftw_plan __real_fftw_plan_dft_r2c_1d(int n, double *in, fftw_complex *out, unsigned flags);
fftw_plan __wrap_fftw_plan_dft_r2c_1d(int n, double *in, fftw_complex *out, unsigned flags);

void *__wrap_fftw_malloc(size_t size)
{
    allocations++;
    return __real_fftw_malloc(size);
}

fftw_plan __wrap_fftw_plan_dft_r2c_1d(int n, double *in, fftw_complex *out, unsigned flags)
{
    allocations++;
    return __real_fftw_plan_dft_r2c_1d(n, in, out, flags);
}

/* count samples dt apart of the sum of sines amp[j] sin(2 pi f[j] t + phase[j]). */
static double *sines(int count, double dt, int nsines, const double *amp, const double *f,
                     const double *phase)
{
    double *x = calloc((size_t)count, sizeof *x);
    assert_non_null(x);
    for (int i = 0; i < count; i++)
        for (int j = 0; j < nsines; j++)
            x[i] += amp[j] * sin(2.0 * M_PI * f[j] * i * dt + phase[j]);
    return x;
}

static double db(double a)
{
    return 20.0 * log10(a);
}

/* The Hann window's response to a tone delta bins from a bin, relative to on the bin,
 * for a long record: W(delta) / W(0) = sinc(delta) / (1 - delta^2). */
static double hann_relative(double delta)
{
    if (delta == 0.0)
        return 1.0;
    return sin(M_PI * delta) / (M_PI * delta) / (1.0 - delta * delta);
}

/* The index of the largest level. */
static int peak_bin(const double *level, int bins)
{
    int k = 0;
    for (int i = 1; i < bins; i++)
        if (level[i] > level[k])
            k = i;
    return k;
}

/* A sine on bin k0 reads its amplitude there to 1e-9 dB; the two neighbours read half
 * of it (20 log10(1/2) = -6.02 dB); every other bin is empty. */
static void on_bin_sine(void **state)
{
    (void)state;
    const int n = 1024, k0 = 50;
    const double dt = 0.01, amp = 0.3, f = k0 / (n * dt), phase = 0.7;
    double *x = sines(n, dt, 1, &amp, &f, &phase);
    struct spectrum *s = spectrum_new();
    assert_int_equal(spectrum_compute(s, x, n, 1, n), 0);
    assert_int_equal(spectrum_bins(s), n / 2 + 1);
    const double *level = spectrum_db(s);
    assert_int_equal(peak_bin(level, n / 2 + 1), k0);
    assert_close(spectrum_bin_hz(s, k0, dt), f, 1e-12);
    assert_close(level[k0], db(amp), 1e-9);
    assert_close(level[k0 - 1] - level[k0], db(0.5), 1e-9);
    assert_close(level[k0 + 1] - level[k0], db(0.5), 1e-9);
    for (int k = 0; k < n / 2 + 1; k++)
        if (abs(k - k0) > 1)
            assert_true(level[k] < db(amp) - 200.0);
    spectrum_free(s);
    free(x);
}

/* Between bins: a tone delta = 0.3 bins above bin k0 peaks at k0, short of its amplitude
 * by the window's response there; half a bin off, the two nearest bins read alike, 1.42 dB
 * short (the Hann window's scalloping loss). Against the long-record closed form, and
 * against a DFT summed directly at the bin. */
static void between_bins(void **state)
{
    (void)state;
    const int n = 4096, k0 = 1000;
    const double dt = 0.02, amp = 1.5, phase = 0.2;
    const double deltas[] = {0.3, 0.5};
    for (size_t d = 0; d < sizeof deltas / sizeof *deltas; d++) {
        double f = (k0 + deltas[d]) / (n * dt);
        double *x = sines(n, dt, 1, &amp, &f, &phase);
        struct spectrum *s = spectrum_new();
        assert_int_equal(spectrum_compute(s, x, n, 1, n), 0);
        const double *level = spectrum_db(s);
        int k = peak_bin(level, n / 2 + 1);
        assert_true(k == k0 || (deltas[d] == 0.5 && k == k0 + 1));
        assert_close(level[k0], db(amp * hann_relative(deltas[d])), 1e-5);
        assert_close(level[k0 + 1], db(amp * fabs(hann_relative(deltas[d] - 1.0))), 1e-5);
        /* The DFT at bin k0 summed term by term, the window written out again: with
         * N = count, the periodic Hann window's own DFT is 0 beyond one bin from 0, so
         * taking off the mean changes nothing at k0. */
        double re = 0.0, im = 0.0, wsum = 0.0;
        for (int i = 0; i < n; i++) {
            double w = 0.5 - 0.5 * cos(2.0 * M_PI * i / n);
            re += w * x[i] * cos(2.0 * M_PI * k0 * i / n);
            im -= w * x[i] * sin(2.0 * M_PI * k0 * i / n);
            wsum += w;
        }
        assert_close(level[k0], db(2.0 * hypot(re, im) / wsum), 1e-9);
        if (deltas[d] == 0.5) {
            assert_close(level[k0], level[k0 + 1], 1e-6);
            assert_close(db(amp) - level[k0], 1.4236, 1e-4);
        }
        spectrum_free(s);
        free(x);
    }
}

/* Zero padding moves the bins closer, not the levels: 1000 samples of an on-bin sine
 * padded to 4000 points read its amplitude at bin 4 k0, and an offset of 5 m is taken
 * off (bin 0 empty, the peak unchanged). */
static void padding_and_offset(void **state)
{
    (void)state;
    const int n = 1000, k0 = 37, pad = 4;
    const double dt = 0.015, amp = 0.02, f = k0 / (n * dt), phase = -1.1;
    double *x = sines(n, dt, 1, &amp, &f, &phase);
    for (int i = 0; i < n; i++)
        x[i] += 5.0;
    struct spectrum *s = spectrum_new();
    assert_int_equal(spectrum_compute(s, x, n, 1, pad * n), 0);
    const double *level = spectrum_db(s);
    assert_int_equal(spectrum_bins(s), pad * n / 2 + 1);
    assert_int_equal(peak_bin(level, pad * n / 2 + 1), pad * k0);
    assert_close(spectrum_bin_hz(s, pad * k0, dt), f, 1e-12);
    assert_close(level[pad * k0], db(amp), 1e-9);
    assert_true(level[0] < db(amp) - 200.0);
    spectrum_free(s);
    free(x);
}

/* An offset changes nothing, and leaves no false line at the lowest bins, even when the
 * record is not a whole number of cycles (0.62 Hz over 60 s): the same sine with and
 * without 0.3 m added reads the same at every bin (to 1e-12 m), and the bins below 0.1 Hz, 30
 * resolution bins from the line, are below the Hann window's leakage there (under
 * -90 dB relative; its sidelobes fall 18 dB an octave from -31.5 dB). */
static void offset_leaves_no_line(void **state)
{
    (void)state;
    const int count = 3001;
    const double dt = 0.02, amp = 1.0, f = 0.62, phase = 0.4;
    double *x = sines(count, dt, 1, &amp, &f, &phase);
    double *y = sines(count, dt, 1, &amp, &f, &phase);
    for (int i = 0; i < count; i++)
        y[i] += 0.3;
    int size = spectrum_length(count, 2);
    struct spectrum *a = spectrum_new(), *b = spectrum_new();
    assert_int_equal(spectrum_compute(a, x, count, 1, size), 0);
    assert_int_equal(spectrum_compute(b, y, count, 1, size), 0);
    const double *la = spectrum_db(a), *lb = spectrum_db(b);
    for (int k = 0; k < spectrum_bins(a); k++)
        assert_close(pow(10.0, lb[k] / 20.0), pow(10.0, la[k] / 20.0), 1e-12);
    double bin_hz = spectrum_bin_hz(a, 1, dt);
    for (int k = 0; k * bin_hz < 0.1; k++)
        assert_true(lb[k] < db(amp) - 90.0);
    spectrum_free(a);
    spectrum_free(b);
    free(x);
    free(y);
}

/* Two sines a little apart, as the beating preset's (0.62 and 0.7118 Hz) over 60 s of
 * samples 0.02 s apart, padded to a power of two: two peaks, each within half a bin of
 * its frequency and within the scalloping loss of its level, the trough between them
 * well below both. Read through a stride, as a view reads one column of its records. */
static void two_sines(void **state)
{
    (void)state;
    const int count = 3000, stride = 3;
    const double dt = 0.02, amp[2] = {1.04, 0.1}, f[2] = {0.62, 0.7118}, phase[2] = {0, 1};
    double *y = sines(count, dt, 2, amp, f, phase);
    double *x = calloc((size_t)count * stride, sizeof *x);
    assert_non_null(x);
    for (int i = 0; i < count; i++)
        x[(size_t)i * stride] = y[i], x[(size_t)i * stride + 1] = 99.0;
    int size = spectrum_length(count, 2);
    assert_int_equal(size, 8192);
    struct spectrum *s = spectrum_new();
    assert_int_equal(spectrum_compute(s, x, count, stride, size), 0);
    const double *level = spectrum_db(s);
    int bins = spectrum_bins(s);
    /* The two highest local maxima. */
    int top[2] = {-1, -1};
    for (int k = 1; k < bins - 1; k++) {
        if (!(level[k] > level[k - 1] && level[k] >= level[k + 1]))
            continue;
        if (top[0] < 0 || level[k] > level[top[0]])
            top[1] = top[0], top[0] = k;
        else if (top[1] < 0 || level[k] > level[top[1]])
            top[1] = k;
    }
    double bin_hz = spectrum_bin_hz(s, 1, dt);
    for (int j = 0; j < 2; j++) {
        assert_close(spectrum_bin_hz(s, top[j], dt), f[j], 0.5 * bin_hz);
        assert_true(level[top[j]] <= db(amp[j]) + 0.05);
        assert_true(level[top[j]] >= db(amp[j]) - 1.43);
    }
    int lo = top[0] < top[1] ? top[0] : top[1], hi = top[0] + top[1] - lo;
    double trough = level[lo];
    for (int k = lo; k <= hi; k++)
        trough = fmin(trough, level[k]);
    assert_true(trough < db(amp[1]) - 10.0);
    spectrum_free(s);
    free(x);
    free(y);
}

/* A refresh of the same length allocates nothing, whatever the count; a new length
 * plans again. */
static void no_allocation_per_refresh(void **state)
{
    (void)state;
    const double amp = 1.0, f = 1.0, phase = 0.0;
    double *x = sines(4000, 0.015, 1, &amp, &f, &phase);
    struct spectrum *s = spectrum_new();
    long before = allocations;
    assert_int_equal(spectrum_compute(s, x, 4000, 1, 8192), 0);
    assert_true(allocations > before);
    for (int count = 3990; count <= 4000; count++) {
        before = allocations;
        assert_int_equal(spectrum_compute(s, x, count, 1, 8192), 0);
        assert_int_equal(allocations, before);
    }
    before = allocations;
    assert_int_equal(spectrum_compute(s, x, 1000, 1, 2048), 0);
    assert_true(allocations > before);
    assert_int_equal(spectrum_bins(s), 1025);
    spectrum_free(s);
    free(x);
}

/* Bad arguments are refused and leave the last spectrum; lengths are powers of two. */
static void arguments(void **state)
{
    (void)state;
    double x[8] = {0, 1, 0, -1, 0, 1, 0, -1};
    struct spectrum *s = spectrum_new();
    assert_int_equal(spectrum_bins(s), 0);
    assert_int_equal(spectrum_compute(s, x, 8, 1, 8), 0);
    assert_int_equal(spectrum_compute(s, x, 1, 1, 8), -2);
    assert_int_equal(spectrum_compute(s, x, 8, 1, 4), -2);
    assert_int_equal(spectrum_compute(s, NULL, 8, 1, 8), -2);
    assert_int_equal(spectrum_bins(s), 5);
    /* 1, 0, -1, 0 repeated: a sine at a quarter of the rate, amplitude 1, on bin 2. */
    assert_close(spectrum_db(s)[2], 0.0, 1e-9);
    spectrum_free(s);
    spectrum_free(NULL);
    assert_int_equal(spectrum_length(3000, 2), 8192);
    assert_int_equal(spectrum_length(4096, 1), 4096);
    assert_int_equal(spectrum_length(4097, 1), 8192);
    assert_int_equal(spectrum_length(1, 1), 1);
    assert_int_equal(spectrum_length(0, 1), 0);
    assert_int_equal(spectrum_length(1 << 30, 2), 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(on_bin_sine),
        cmocka_unit_test(between_bins),
        cmocka_unit_test(padding_and_offset),
        cmocka_unit_test(offset_leaves_no_line),
        cmocka_unit_test(two_sines),
        cmocka_unit_test(no_allocation_per_refresh),
        cmocka_unit_test(arguments),
    };
    return cmocka_run_group_tests_name("spectrum", tests, NULL, NULL);
}
