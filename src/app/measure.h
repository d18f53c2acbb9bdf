/* measure.h: a scope's automatic measurements of one sampled series: period and
 * frequency from its successive peaks, peak-to-peak, rms, and for a decay the
 * logarithmic decrement and the damping ratio it implies. No state, no allocation: one
 * pass over the samples. */
#ifndef SPRINGSIM_MEASURE_H
#define SPRINGSIM_MEASURE_H

#include <stddef.h>

/* What one series measures. A figure that the samples cannot give is NAN. */
struct measure {
    int samples;      /* samples measured */
    int peaks;        /* local maxima found (both neighbours inside the span) */
    double first, last; /* times of the first and the last peak (s) */
    double period;    /* s: the least-squares slope of the peaks' times against their
                       * count; NAN with fewer than 2 peaks */
    double frequency; /* Hz: 1 / period */
    double p2p;       /* largest minus smallest sample */
    double rms;       /* root mean square about 0 (the chain's equilibrium) */
    double delta;     /* logarithmic decrement: the least-squares slope of -ln(peak) per
                       * peak; NAN with fewer than 2 peaks or a peak at or below 0 */
    double zeta;      /* the damping ratio delta implies, measure_zeta(delta) */
};

/* Measures count samples y(t), stride doubles apart (t and y interleaved in records),
 * in time order and evenly spaced. Each peak is placed by the parabola through it and
 * its two neighbours (sub-sample time and height). */
void measure_series(struct measure *m, const double *t, const double *y, int count,
                    size_t stride);

/* The damping ratio of logarithmic decrement delta: zeta = delta / sqrt(4 pi^2 + delta^2)
 * (from delta = 2 pi zeta / sqrt(1 - zeta^2) for x = e^(-zeta w t) cos(w_d t)). */
double measure_zeta(double delta);

/* The parabola's vertex through (-1, y0), (0, y1), (1, y2): its abscissa (in samples,
 * within [-1, 1] for a peak) into *at and its height into *height. */
void measure_vertex(double y0, double y1, double y2, double *at, double *height);

#endif
