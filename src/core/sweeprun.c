/* sweeprun.c: one point of a simulated sweep (sweeprun.h).
 *
 * Each drive period (the number of whole steps nearest to 1/f) the first harmonic of
 * every mass is fitted by least squares, x ~ in sin(theta) + quad cos(theta) over the
 * period's samples (theta the drive's angle: the motor is A sin theta), so x ~ X
 * sin(theta + phi) gives X = hypot(in, quad) and phi = atan2(quad, in). A lock-in's sums
 * (2/T sum x sin theta dt) would do only over a whole period: the steps seldom make one
 * (68 steps of 0.01 s against 0.685 s at 1.46 Hz), and that bias, 0.7 % there, is ten
 * times the steadiness asked for. The point is steady when, for
 * every mass, the amplitude changed by at most SWEEPRUN_STEADY of itself over the last
 * period and the change still to come (the geometric tail d r / (1 - r), r the ratio of
 * the last two changes) is as small, for as many periods running as the slowest mode's
 * decay time holds (calm_periods). */
#include "sweeprun.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "modes.h"
#include "sweep.h"

/* Periods at frequency f in the slowest decay time of m's modes (1 / the least modal decay
 * rate, rigid modes left out), at least 2: a transient still moves by 63 % of what is
 * left of it in that time, so an amplitude steady for so long is not a slow drift (as
 * past a fold, where the motion lingers before it falls). */
static long calm_periods(const struct model *m, double f)
{
    int n = m->n;
    double *w2 = malloc((size_t)(2 * n) * sizeof *w2), least = INFINITY;
    if (w2 && modes_modal(m, w2, w2 + n) == 0)
        for (int j = 0; j < n; j++)
            if (w2[j] > 0.0 && w2[n + j] > 0.0)
                least = fmin(least, w2[n + j]);
    free(w2);
    double p = ceil(f / least);
    return isfinite(p) && p > 2.0 ? (long)fmin(p, SWEEPRUN_MAX_PERIODS / 4) : 2;
}

struct sweeprun_point sweeprun_point(struct sim *s, double f, double *amp, double *phase)
{
    struct sweeprun_point r = {false, 0, false, 0};
    const struct model *m0 = sim_model(s);
    int n = m0->n;
    struct model *m = model_new(n);
    double *in = calloc((size_t)(4 * n), sizeof *in), *quad = in ? in + n : NULL;
    double *last = in ? quad + n : NULL, *change = in ? last + n : NULL;
    if (!m || !in) {
        model_free(m);
        free(in);
        r.diverged = true;
        return r;
    }
    model_copy(m, m0);
    motor_retune(&m->motor, f, sim_time(s));
    sim_set_model(s, m);
    double dt = sim_dt(s), w = 2.0 * M_PI * f;
    long steps = lround(1.0 / (f * dt));
    steps = steps < 1 ? 1 : steps;
    long calm = 0, need = calm_periods(m, f);
    for (int i = 0; i < n; i++)
        last[i] = change[i] = NAN;
    while (r.periods < SWEEPRUN_MAX_PERIODS && r.periods * steps * dt < SWEEPRUN_MAX_SECONDS) {
        memset(in, 0, (size_t)(2 * n) * sizeof *in);
        double ss = 0.0, sc = 0.0, cc = 0.0; /* the normal equations' matrix */
        for (long k = 0; k < steps && !r.diverged; k++) {
            /* A step that cannot be taken (non-finite numbers) leaves the state as it
             * was: a runaway, not a steady motion. */
            r.diverged = sim_step(s) != SIM_OK;
            r.capped += sim_last_capped(s) > 0;
            double th = w * sim_time(s) + 2.0 * M_PI * m->motor.phase, sn = sin(th),
                   cs = cos(th);
            const double *x = sim_x(s);
            ss += sn * sn, sc += sn * cs, cc += cs * cs;
            for (int i = 0; i < n; i++)
                in[i] += x[i] * sn, quad[i] += x[i] * cs;
        }
        /* Solved: [ss sc; sc cc] (in, quad) = (sum x sin, sum x cos). Two or more samples
         * of a period's angles make it regular; one (a drive of one step a period) falls
         * back on the lock-in's scale. */
        if (r.diverged)
            break;
        double det = ss * cc - sc * sc;
        for (int i = 0; i < n; i++) {
            double p = in[i], q = quad[i];
            if (det > 1e-12 * (ss + cc) * (ss + cc))
                in[i] = (cc * p - sc * q) / det, quad[i] = (ss * q - sc * p) / det;
            else
                in[i] = 2.0 * p / (double)steps, quad[i] = 2.0 * q / (double)steps;
        }
        r.periods++;
        bool steady = true;
        for (int i = 0; i < n; i++) {
            double a = hypot(in[i], quad[i]);
            if (!isfinite(a)) {
                r.diverged = true;
                break;
            }
            double d = fabs(a - last[i]), ratio = d / change[i];
            double tail = d == 0.0 ? 0.0 : ratio < 1.0 ? d * ratio / (1.0 - ratio) : INFINITY;
            double scale = fmax(a, 1e-9);
            steady &= d <= SWEEPRUN_STEADY * scale && tail <= SWEEPRUN_STEADY * scale;
            change[i] = d;
            last[i] = a;
            amp[i] = a;
            phase[i] = sweep_phase_deg(in[i], quad[i]);
        }
        if (r.diverged)
            break;
        calm = steady ? calm + 1 : 0;
        if (calm >= need) {
            r.settled = true;
            break;
        }
    }
    model_free(m);
    free(in);
    return r;
}
