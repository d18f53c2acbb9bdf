/* measure.h: a scope's automatic measurements of one sampled series: period and
 * frequency from its successive peaks, peak-to-peak, rms, and for a decay the
 * logarithmic decrement and the damping ratio it implies; under a drive, the amplitude
 * and phase of its fundamental against the drive's and how level its swings are; and
 * from these, what kind of motion it is. No state, no allocation. */
#ifndef SPRINGSIM_MEASURE_H
#define SPRINGSIM_MEASURE_H

#include <stdbool.h>
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
    double high, low; /* the highest and the lowest peak (NAN without peaks) */
    bool falling;     /* 2 peaks or more, each lower than the one before, all above 0 */
    bool rising;      /* 2 peaks or more, each higher than the one before */
};

/* Peaks (or a drive's swings) level within this are steady (relative to the amplitude). */
#define MEASURE_LEVEL 0.01

/* A series against a periodic drive u(t) of frequency f, over the whole drive periods
 * that end at its last sample. A figure that the samples cannot give is NAN. */
struct measure_drive {
    int periods;      /* whole drive periods in the span */
    double level;     /* how far the periods' highs (or lows, the larger) spread, relative
                       * to the amplitude: 0 for a steady state */
    double amplitude; /* the series's fundamental at f: its amplitude (m) */
    double drive;     /* the drive's fundamental amplitude (m, or N for a force) */
    double ratio;     /* amplitude / drive (m/m, or m/N for a force) */
    double phase;     /* the series's fundamental relative to the drive's, degrees in
                       * (-180, 180]: a lag is negative */
};

/* What kind of motion a series is. */
enum motion {
    MOTION_UNKNOWN,   /* too few peaks (free) or drive periods (driven) to tell */
    MOTION_DECAY,     /* free, its peaks falling one after another: period, delta, zeta */
    MOTION_STEADY,    /* its swings level within MEASURE_LEVEL: driven, a steady state */
    MOTION_TRANSIENT, /* neither: growing, beating, settling */
};

/* Measures count samples y(t), stride doubles apart (t and y interleaved in records),
 * in time order and evenly spaced. Each peak is placed by the parabola through it and
 * its two neighbours (sub-sample time and height). */
void measure_series(struct measure *m, const double *t, const double *y, int count,
                    size_t stride);

/* Measures count samples y(t) against the drive u(t) of frequency hz (all three
 * interleaved stride doubles apart, evenly spaced in time) over the whole periods 1/hz
 * that end at the last sample: each period's highest and lowest y (a parabola through
 * the extreme sample and its neighbours), and the fundamentals Y and U at hz (sums of
 * y e^(-i 2 pi hz t) over the samples spanning those periods). */
void measure_drive(struct measure_drive *d, const double *t, const double *y, const double *u,
                   int count, size_t stride, double hz);

/* As measure_drive, the drive's value at each sample's time computed by drive(ctx, t)
 * rather than sampled: a force input, which the records do not hold. */
void measure_drive_at(struct measure_drive *d, const double *t, const double *y,
                      double (*drive)(const void *ctx, double t), const void *ctx, int count,
                      size_t stride, double hz);

/* The kind of motion m (and, driven, d; NULL for free motion) is: free, steady if its
 * peaks are level within MEASURE_LEVEL of the highest, else a decay if they fall one
 * after another; driven, steady if the drive periods' swings are level within
 * MEASURE_LEVEL (at least two periods); otherwise transient; unknown with fewer than 2
 * peaks or drive periods. */
enum motion measure_motion(const struct measure *m, const struct measure_drive *d);

/* The damping ratio of logarithmic decrement delta: zeta = delta / sqrt(4 pi^2 + delta^2)
 * (from delta = 2 pi zeta / sqrt(1 - zeta^2) for x = e^(-zeta w t) cos(w_d t)). */
double measure_zeta(double delta);

/* The parabola's vertex through (-1, y0), (0, y1), (1, y2): its abscissa (in samples,
 * within [-1, 1] for a peak) into *at and its height into *height. */
void measure_vertex(double y0, double y1, double y2, double *at, double *height);

#endif
