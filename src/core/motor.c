/* motor.c: waveforms of the linear motor and their breakpoints.
 *
 * Phases are handled in cycles c = f*t (theta = 2*pi*c). Between breakpoints every
 * waveform but the sine is linear in c, so a piece is a line w = w0 + slope*(c - cref):
 *   square:   w = +1 on (k, k+1/2), -1 on (k+1/2, k+1)          breakpoints c = k/2
 *   triangle: w = 4(c-k) on (k-1/4, k+1/4), -4(c-k-1/2) next     breakpoints c = 1/4 + k/2
 *   sawtooth: w = 2(c-k) on (k-1/2, k+1/2)                        breakpoints c = 1/2 + k
 * These are the definitions sign(sin), (2/pi)asin(sin) and 2 frac(c + 1/2) - 1. */
#include "motor.h"

#include <limits.h>
#include <math.h>
#include <string.h>

/* A phase this close (in cycles) to a breakpoint is taken to be on it: it absorbs the
 * rounding of f*n*dt on grids that land on a breakpoint. */
#define PHASE_EPS 1e-9

static const char *const wave_names[WAVE_COUNT] = {"sine", "square", "triangle", "sawtooth"};

const char *motor_wave_name(enum wave wave)
{
    return (unsigned)wave < WAVE_COUNT ? wave_names[wave] : NULL;
}

int motor_wave_parse(const char *s)
{
    for (int i = 0; i < WAVE_COUNT; i++)
        if (strcmp(s, wave_names[i]) == 0)
            return i;
    return -1;
}

int motor_has_jumps(enum wave wave)
{
    return wave == WAVE_SQUARE || wave == WAVE_SAWTOOTH;
}

/* Distance of phase p (in [0,1)) from the point q on the unit circle of cycles. */
static double phase_dist(double p, double q)
{
    double d = fabs(p - q);
    return d > 0.5 ? 1.0 - d : d;
}

double motor_wave(enum wave wave, double cycles)
{
    double p = cycles - floor(cycles);
    switch (wave) {
    case WAVE_SINE:
        return sin(2.0 * M_PI * cycles);
    case WAVE_SQUARE:
        if (phase_dist(p, 0.0) < PHASE_EPS || phase_dist(p, 0.5) < PHASE_EPS)
            return 0.0;
        return p < 0.5 ? 1.0 : -1.0;
    case WAVE_TRIANGLE:
        if (p < 0.25)
            return 4.0 * p;
        if (p < 0.75)
            return 2.0 - 4.0 * p;
        return 4.0 * p - 4.0;
    case WAVE_SAWTOOTH:
        if (phase_dist(p, 0.5) < PHASE_EPS)
            return -1.0;
        return p < 0.5 ? 2.0 * p : 2.0 * p - 2.0;
    case WAVE_COUNT:
        break;
    }
    return 0.0;
}

double motor_fundamental(enum wave wave)
{
    switch (wave) {
    case WAVE_SQUARE:
        return 4.0 / M_PI;
    case WAVE_TRIANGLE:
        return 8.0 / (M_PI * M_PI);
    case WAVE_SAWTOOTH:
        return 2.0 / M_PI;
    default:
        return 1.0;
    }
}

double motor_position(const struct motor *m, double t)
{
    return m->amplitude * motor_wave(m->wave, m->frequency * t + m->phase);
}

void motor_piece_at(const struct motor *m, double t, struct motor_piece *p)
{
    double c = m->frequency * t + m->phase;
    double k = floor(c);
    double ph = c - k;

    p->motor = m;
    p->cref = 0.0;
    p->slope = 0.0;
    p->w0 = 0.0;
    switch (m->wave) {
    case WAVE_SINE:
    case WAVE_COUNT:
        break;
    case WAVE_SQUARE:
        p->w0 = ph < 0.5 ? 1.0 : -1.0;
        break;
    case WAVE_TRIANGLE:
        if (ph < 0.25) {
            p->cref = k, p->slope = 4.0;
        } else if (ph < 0.75) {
            p->cref = k + 0.5, p->slope = -4.0;
        } else {
            p->cref = k + 1.0, p->slope = 4.0;
        }
        break;
    case WAVE_SAWTOOTH:
        p->cref = ph < 0.5 ? k : k + 1.0;
        p->slope = 2.0;
        break;
    }
}

void motor_piece_unit(const struct motor_piece *p, double t, double *w, double *dw)
{
    const struct motor *m = p->motor;
    double f = m->frequency;

    if (m->wave == WAVE_SINE) {
        double om = 2.0 * M_PI * f;
        double s, c;
        sincos(om * t + 2.0 * M_PI * m->phase, &s, &c);
        *w = s;
        *dw = om * c;
        return;
    }
    *w = p->w0 + p->slope * (f * t + m->phase - p->cref);
    *dw = p->slope * f;
}

void motor_piece_eval(const struct motor_piece *p, double t, double *u, double *du)
{
    const struct motor *m = p->motor;
    double a = m->amplitude, f = m->frequency;

    if (m->wave == WAVE_SINE) {
        double w = 2.0 * M_PI * f;
        double s, c;
        sincos(w * t + 2.0 * M_PI * m->phase, &s, &c);
        *u = a * s;
        *du = a * w * c;
        return;
    }
    *u = a * (p->w0 + p->slope * (f * t + m->phase - p->cref));
    *du = a * p->slope * f;
}

int motor_breakpoints(const struct motor *m, double t0, double t1, double *out, int max)
{
    double first, period;

    switch (m->wave) {
    case WAVE_SQUARE:
        first = 0.0, period = 0.5;
        break;
    case WAVE_TRIANGLE:
        first = 0.25, period = 0.5;
        break;
    case WAVE_SAWTOOTH:
        first = 0.5, period = 1.0;
        break;
    default:
        return 0;
    }
    double f = m->frequency;
    double c0 = f * t0 + m->phase, c1 = f * t1 + m->phase;
    /* Indices of the first and last breakpoints strictly inside, counted, not walked:
     * the count may be large, and only the first max are written. */
    double j0 = floor((c0 + PHASE_EPS - first) / period) + 1.0;
    double j1 = ceil((c1 - PHASE_EPS - first) / period) - 1.0;
    if (j1 < j0)
        return 0;
    double total = j1 - j0 + 1.0;
    int count = total > INT_MAX ? INT_MAX : (int)total;
    for (int k = 0; k < count && k < max; k++)
        out[k] = (first + (j0 + k) * period - m->phase) / f;
    return count;
}

void motor_retune(struct motor *m, double frequency, double t)
{
    /* f_old t + p_old = f_new t + p_new, kept in [0, 1) cycles. */
    double p = (m->frequency - frequency) * t + m->phase;
    m->phase = p - floor(p);
    m->frequency = frequency;
}
