/* spectrum.c: the Hann-windowed amplitude spectrum with FFTW3. One plan per transform
 * length, made with FFTW_ESTIMATE (no measuring, so it is quick and the input buffer is
 * not touched while planning) and kept with its buffers until the length changes: a view
 * that refreshes the spectrum of a window of the same length allocates nothing. */
#include "spectrum.h"

#include <limits.h>
#include <math.h>
#include <stdbool.h>
#include <stdlib.h>

#include <fftw3.h>

struct spectrum {
    int size;          /* transform length planned for (0: none) */
    int count;         /* samples the window below is for (0: none) */
    int bins;          /* bins of the last spectrum computed (0: none) */
    fftw_plan plan;    /* r2c of size points, in -> out */
    double *in;        /* size samples: the windowed series, then zeros */
    fftw_complex *out; /* size / 2 + 1 coefficients */
    double *window;    /* the Hann window for count samples */
    double window_sum; /* its sum */
    double *db;        /* size / 2 + 1 levels */
};

struct spectrum *spectrum_new(void)
{
    return calloc(1, sizeof(struct spectrum));
}

/* Lets go of the plan and the buffers. */
static void drop(struct spectrum *s)
{
    if (s->plan)
        fftw_destroy_plan(s->plan);
    fftw_free(s->in);
    fftw_free(s->out);
    free(s->window);
    free(s->db);
    *s = (struct spectrum){0};
}

void spectrum_free(struct spectrum *s)
{
    if (!s)
        return;
    drop(s);
    free(s);
}

int spectrum_length(int count, int pad)
{
    if (count < 1 || pad < 1)
        return 0;
    int n = 1;
    while (n < count) {
        if (n > INT_MAX / 4)
            return 0;
        n *= 2;
    }
    return n <= INT_MAX / 2 / pad ? n * pad : 0;
}

/* The plan and buffers for a transform of size points; false on no memory. */
static bool plan(struct spectrum *s, int size)
{
    drop(s);
    size_t half = (size_t)size / 2 + 1;
    s->in = fftw_malloc((size_t)size * sizeof *s->in);
    s->out = fftw_malloc(half * sizeof *s->out);
    s->window = malloc((size_t)size * sizeof *s->window);
    s->db = malloc(half * sizeof *s->db);
    if (s->in && s->out && s->window && s->db)
        s->plan = fftw_plan_dft_r2c_1d(size, s->in, s->out, FFTW_ESTIMATE);
    if (!s->plan) {
        drop(s);
        return false;
    }
    s->size = size;
    return true;
}

/* The periodic Hann window for count samples, w_n = (1 - cos(2 pi n / count)) / 2: on a
 * transform of count points an on-bin sine leaks into its two neighbours only, at half
 * its level (-6.02 dB), and its sum is exactly count / 2. */
static void hann(struct spectrum *s, int count)
{
    s->window_sum = 0.0;
    for (int i = 0; i < count; i++) {
        s->window[i] = 0.5 * (1.0 - cos(2.0 * M_PI * i / count));
        s->window_sum += s->window[i];
    }
    s->count = count;
}

int spectrum_compute(struct spectrum *s, const double *x, int count, size_t stride, int size)
{
    if (!x || count < 2 || size < count || stride < 1)
        return -2;
    if (size != s->size && !plan(s, size))
        return -1;
    if (count != s->count)
        hann(s, count);
    /* The offset taken off is the window-weighted mean, sum(w x) / sum(w): then bin 0 is
     * exactly empty and the result does not depend on the offset at all. (The plain
     * mean of a record that is not a whole number of cycles differs from it, and the
     * difference leaks into the lowest bins as a false line.) */
    double mean = 0.0;
    for (int i = 0; i < count; i++)
        mean += s->window[i] * x[(size_t)i * stride];
    mean /= s->window_sum;
    for (int i = 0; i < count; i++)
        s->in[i] = s->window[i] * (x[(size_t)i * stride] - mean);
    for (int i = count; i < size; i++)
        s->in[i] = 0.0;
    fftw_execute(s->plan);
    /* A_k = 2 |X_k| / sum(w), once for the bins that have no mirror image (0, size / 2). */
    s->bins = size / 2 + 1;
    for (int k = 0; k < s->bins; k++) {
        double a = hypot(s->out[k][0], s->out[k][1]) / s->window_sum;
        if (k > 0 && 2 * k != size)
            a *= 2.0;
        s->db[k] = a > 1e-15 ? 20.0 * log10(a) : SPECTRUM_FLOOR_DB;
    }
    return 0;
}

int spectrum_bins(const struct spectrum *s)
{
    return s->bins;
}

const double *spectrum_db(const struct spectrum *s)
{
    return s->db;
}

double spectrum_bin_hz(const struct spectrum *s, double k, double dt)
{
    return s->size > 0 ? k / (s->size * dt) : 0.0;
}
