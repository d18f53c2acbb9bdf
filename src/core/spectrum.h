/* spectrum.h: the amplitude spectrum of a uniformly sampled real series (a mass's
 * displacement), Hann-windowed, in dB re 1 m, with FFTW3's real-to-complex transform.
 *
 * Normalisation: a sine of amplitude A (m) whose frequency falls on a bin reads
 * 20 log10(A / 1 m) dB there, whatever the number of samples or the padding: the
 * transform is divided by the window's sum (count/2 for the Hann window, its coherent
 * gain 0.5 times count) and doubled for every bin but 0 and the Nyquist bin. The
 * window-weighted mean of the samples is taken off first, so an offset (a mass's resting
 * place, a drift) changes nothing and leaves no false line in the lowest bins. The
 * samples may be zero-padded to a longer transform: the bins are then closer together
 * (a smoother curve), the levels are the same, the resolution is still 1 / (count dt). */
#ifndef SPRINGSIM_SPECTRUM_H
#define SPRINGSIM_SPECTRUM_H

#include <stddef.h>

#define SPECTRUM_FLOOR_DB (-300.0) /* the level of a bin with nothing in it */

struct spectrum;

/* An empty spectrum (nothing computed, nothing planned), or NULL on no memory. */
struct spectrum *spectrum_new(void);

/* Frees s and its plan and buffers; NULL is allowed. */
void spectrum_free(struct spectrum *s);

/* The transform length for count samples zero-padded pad times: pad times the smallest
 * power of two at least count (0 when that passes INT_MAX / 2). */
int spectrum_length(int count, int pad);

/* The spectrum of count samples x[0], x[stride], x[2 stride], ... (2 <= count <= size),
 * weighted mean removed, periodic Hann window w_n = (1 - cos(2 pi n / count)) / 2, zero-padded to
 * a transform of size points. The plan and buffers are made only when size differs from
 * the last call's (FFTW_ESTIMATE; the one allocation); with the same size nothing is
 * allocated. Returns 0, -1 on no memory (s is then empty), -2 on bad arguments (s is left
 * as it was). */
int spectrum_compute(struct spectrum *s, const double *x, int count, size_t stride, int size);

/* Bins of the last spectrum computed: size / 2 + 1, or 0 if there is none. */
int spectrum_bins(const struct spectrum *s);

/* Levels of the last spectrum (dB re 1 m, SPECTRUM_FLOOR_DB at the least), one per bin;
 * bin k is the frequency k / (size dt) for samples dt apart. */
const double *spectrum_db(const struct spectrum *s);

/* The frequency (Hz) of bin k for samples dt seconds apart. */
double spectrum_bin_hz(const struct spectrum *s, double k, double dt);

#endif
