/* limits.c: the stability and accuracy limits of dt (SPEC section 1, "Limits").
 *
 * The chain M x'' + C x' + K x = 0 is the first-order system z' = A z with
 * A = [[0, I], [-M^-1 K, -M^-1 C]]; its 2N eigenvalues (LAPACK dgeev) pair into N
 * modes, each the oscillator x'' = -w2 x - 2 s x' with those two eigenvalues. One step h
 * of an integrator maps a mode's (x, v) by a 2x2 matrix (integrator_mode_step); dt is
 * stable when every mode's matrix has spectral radius rho <= 1. For euler and rk4, whose
 * step on z' = A z is the polynomial R(hA), this is |R(h lambda)| <= 1 exactly, whichever
 * way the eigenvalues are paired. For semi-implicit and verlet, which treat x and v
 * apart, it is exact for modal damping (C diagonal in the undamped modes, as with equal
 * dampers on equal masses) and an approximation otherwise.
 *
 * Accuracy: over one period T = 2 pi / |lambda| a mode's amplitude goes by exp(-s T);
 * the method's by rho^(T/h). Their ratio minus one is the mode's error per period.
 *
 * The largest good step of a mode is found along h: a scan of h |lambda| (|lambda| the
 * mode's fastest) in steps of 1/16 up to 8, past the explicit methods' regions, then
 * growing by 1/16 each step up to 1e6 (verlet, whose damping is implicit, is stable on
 * an overdamped mode out to 2 / sqrt(w2), far past its fast eigenvalue), then bisection
 * inside the first bad interval. The good steps here are an interval starting at 0, so
 * the scan only guards against the bisection starting on the wrong side. */
#include "limits.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include <lapacke.h>

#include "modes.h"

#define RHO_TOL 1e-12  /* rho this far above 1 is rounding, not growth */
#define SCAN_STEP 0.0625 /* of h |lambda|, up to SCAN_LINEAR */
#define SCAN_LINEAR 8.0
#define SCAN_END 1e6     /* no limit below this h |lambda|: none at all */
#define BISECTIONS 64

/* ---- the modes ---- */

static int compare_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static int compare_mode(const void *a, const void *b)
{
    const struct limits_mode *x = a, *y = b;
    return (x->w2 > y->w2) - (x->w2 < y->w2);
}

/* Pairs the 2N eigenvalues (re, im) into N modes: each complex pair is one; the real ones,
 * sorted, pair from the outside in (the fastest with the slowest), which for modal
 * damping pairs the two of each overdamped mode: their product is w2 and the fastest
 * belong to the modes of lowest w2. A passive chain has Re lambda <= 0: a positive real
 * part is rounding and counts as 0. Returns the modes made. */
static int pair_modes(const double *re, const double *im, int n2, double *real,
                      struct limits_mode *mode)
{
    int count = 0, nreal = 0;
    for (int k = 0; k < n2; k++) {
        if (im[k] > 0.0)
            mode[count++] = (struct limits_mode){re[k] * re[k] + im[k] * im[k], fmax(-re[k], 0.0)};
        else if (im[k] == 0.0)
            real[nreal++] = fmin(re[k], 0.0);
    }
    qsort(real, (size_t)nreal, sizeof *real, compare_double);
    for (int k = 0; k < nreal / 2; k++) {
        double a = real[k], b = real[nreal - 1 - k];
        mode[count++] = (struct limits_mode){a * b, -0.5 * (a + b)};
    }
    return count;
}

/* Above LIMITS_DGEEV_MAX masses dgeev on 2N is slow (it grows as N^3: 0.03 s at
 * N = 100, 0.7 s at N = 300), so the modes come from the undamped ones (dstevr, O(N^2):
 * 0.05 s at N = 1000) with modal damping s = phi^T C phi / (2 phi^T M phi): exact when C
 * is diagonal in those modes (equal damping per unit mass), an approximation otherwise. */
static int modal_modes(const struct model *m, struct limits_mode *mode)
{
    int n = m->n;
    double *w2 = malloc((size_t)(2 * n) * sizeof *w2);
    int e = w2 ? modes_modal(m, w2, w2 + n) : -1;
    for (int j = 0; e == 0 && j < n; j++)
        mode[j] = (struct limits_mode){w2[j] > 0.0 ? w2[j] : 0.0, w2[n + j]};
    free(w2);
    return e;
}

int limits_modes(const struct model *m, struct limits_mode *mode)
{
    int n = m->n, n2 = 2 * n, e = 0;
    if (n > LIMITS_DGEEV_MAX)
        e = modal_modes(m, mode);
    else {
        double *a = malloc((size_t)n2 * (size_t)n2 * sizeof *a);
        double *work = malloc((size_t)(5 * n2) * sizeof *work);
        if (!a || !work) {
            free(a);
            free(work);
            return -1;
        }
        double *re = work, *im = work + n2, *real = work + 2 * n2;
        e = model_first_order(m, a, work + 3 * n2);
        if (e == 0)
            e = (int)LAPACKE_dgeev(LAPACK_COL_MAJOR, 'N', 'N', n2, a, n2, re, im, NULL, 1,
                                   NULL, 1);
        if (e == 0 && pair_modes(re, im, n2, real, mode) != n)
            e = -2; /* an odd number of real eigenvalues: not a chain's */
        free(a);
        free(work);
    }
    for (int j = 0; e == 0 && j < n; j++)
        if (!isfinite(mode[j].w2) || !isfinite(mode[j].s))
            e = -2;
    if (e == 0)
        qsort(mode, (size_t)n, sizeof *mode, compare_mode);
    return e;
}

/* ---- one mode ---- */

/* The mode's largest |lambda|: the scale of its step. */
static double mode_scale(const struct limits_mode *md)
{
    double d = md->s * md->s - md->w2;
    return d > 0.0 ? md->s + sqrt(d) : sqrt(md->w2);
}

/* Spectral radius of the step matrix of integrator i on mode md at step h. */
static double radius(const struct limits_mode *md, enum integrator i, double h)
{
    double q[4];
    integrator_mode_step(i, md->w2, md->s, h, q);
    double half = 0.5 * (q[0] + q[3]), det = q[0] * q[3] - q[1] * q[2];
    double disc = half * half - det;
    if (disc < 0.0)
        return sqrt(det); /* a complex pair: both of modulus sqrt(det) */
    return fabs(half) + sqrt(disc);
}

double limits_mode_error(const struct limits_mode *md, enum integrator i, double dt)
{
    if (md->s * md->s >= md->w2)
        return NAN;
    if (i == INTEGRATOR_EXACT)
        return 0.0;
    double period = 2.0 * M_PI / sqrt(md->w2);
    double rho = radius(md, i, dt);
    if (!(rho > 0.0))
        return -1.0; /* the method stops the mode dead within a step */
    return expm1(period / dt * log(rho) + md->s * period);
}

/* What a step is checked for. */
enum check { STABLE, ACCURATE };

static bool good(const struct limits_mode *md, enum integrator i, double h, enum check what)
{
    if (what == STABLE)
        return radius(md, i, h) <= 1.0 + RHO_TOL;
    return fabs(limits_mode_error(md, i, h)) <= LIMITS_LOSS;
}

/* The largest h good for mode md from 0 up: scan, then bisect the first bad interval.
 * INFINITY when nothing up to SCAN_END is bad. */
static double largest_good(const struct limits_mode *md, enum integrator i, enum check what)
{
    double scale = mode_scale(md);
    if (!(scale > 0.0))
        return INFINITY;
    double lo = 0.0, hi = NAN;
    for (double t = SCAN_STEP; t <= SCAN_END;
         t = t < SCAN_LINEAR ? t + SCAN_STEP : t * (1.0 + SCAN_STEP)) {
        if (!good(md, i, t / scale, what)) {
            hi = t;
            break;
        }
        lo = t;
    }
    if (isnan(hi))
        return INFINITY;
    for (int k = 0; k < BISECTIONS; k++) {
        double mid = 0.5 * (lo + hi);
        if (good(md, i, mid / scale, what))
            lo = mid;
        else
            hi = mid;
    }
    return lo / scale;
}

double limits_stable_dt(const struct limits_mode *mode, int n, enum integrator i)
{
    double dt = INFINITY;
    if (i == INTEGRATOR_EXACT)
        return dt;
    for (int j = 0; j < n; j++)
        dt = fmin(dt, largest_good(&mode[j], i, STABLE));
    return dt;
}

double limits_accurate_dt(const struct limits_mode *mode, int n, enum integrator i)
{
    double dt = INFINITY;
    if (i == INTEGRATOR_EXACT)
        return dt;
    for (int j = 0; j < n; j++)
        if (mode[j].s * mode[j].s < mode[j].w2)
            dt = fmin(dt, largest_good(&mode[j], i, ACCURATE));
    return dt;
}

/* ---- the verdict ---- */

void limits_judge(const struct limits_mode *mode, int n, const struct model *m,
                  enum integrator i, double dt, struct limits *out)
{
    *out = (struct limits){.integrator = i, .dt = dt, .worst = -1, .drive_steps = INFINITY};
    out->stable_dt = limits_stable_dt(mode, n, i);
    out->accurate_dt = fmin(limits_accurate_dt(mode, n, i), out->stable_dt);
    int top = -1;
    for (int j = 0; j < n; j++) {
        double e = limits_mode_error(&mode[j], i, dt);
        if (isnan(e))
            continue;
        top = j; /* the modes go up in w2: the last oscillating one is the highest */
        if (out->worst < 0 || fabs(e) > fabs(out->error)) {
            out->worst = j;
            out->error = e;
        }
    }
    if (out->worst >= 0) {
        out->worst_hz = sqrt(mode[out->worst].w2) / (2.0 * M_PI);
        out->worst_is_top = out->worst == top;
    }
    if (m->boundary == BOUNDARY_MOTOR && m->motor.amplitude > 0.0) {
        out->drive_hz = m->motor.frequency;
        out->drive_steps = 1.0 / (m->motor.frequency * dt);
    }
}

bool limits_unstable(const struct limits *l)
{
    return l->dt > l->stable_dt;
}

bool limits_rough_modes(const struct limits *l)
{
    /* Past the stability limit that is all there is to say. */
    return !limits_unstable(l) && l->worst >= 0 && fabs(l->error) > LIMITS_LOSS;
}

bool limits_rough_drive(const struct limits *l)
{
    return l->drive_steps < LIMITS_DRIVE_STEPS;
}

double limits_round_down(double x)
{
    if (!(x > 0.0) || !isfinite(x))
        return x;
    double scale = pow(10.0, 2.0 - floor(log10(x)));
    return floor(x * scale * (1.0 + 1e-12)) / scale;
}

/* A percentage with the digits it needs: 75, 7.2, 1.3. */
static void percent(double fraction, char *buf, size_t len)
{
    double p = 100.0 * fabs(fraction);
    snprintf(buf, len, p >= 10.0 ? "%.0f" : "%.2g", p);
}

void limits_say_stability(const struct limits *l, bool short_form, char *buf, size_t len)
{
    const char *name = integrator_name(l->integrator);
    buf[0] = '\0';
    if (!limits_unstable(l))
        return;
    if (short_form)
        snprintf(buf, len, "warning: dt = %g s is above the stability limit of %s: dt < %.3g s",
                 l->dt, name, limits_round_down(l->stable_dt));
    else
        snprintf(buf, len, "dt = %g s is unstable with %s for these springs and dampers: "
                 "dt < %.3g s is stable", l->dt, name, limits_round_down(l->stable_dt));
}

void limits_say_modes(const struct limits *l, bool short_form, char *buf, size_t len)
{
    char pc[16], mode[48];
    const char *name = integrator_name(l->integrator);
    const char *verb = l->error < 0.0 ? "loses" : "gains";
    buf[0] = '\0';
    if (!limits_rough_modes(l))
        return;
    percent(l->error, pc, sizeof pc);
    if (short_form) {
        snprintf(buf, len, "warning: the %.3g Hz mode %s %s %% a period to %s; dt < %.3g s: "
                 "under 1 %%", l->worst_hz, verb, pc, name, limits_round_down(l->accurate_dt));
        return;
    }
    snprintf(mode, sizeof mode, l->worst_is_top ? "the highest mode (%.3g Hz)"
                                                : "the mode at %.3g Hz", l->worst_hz);
    snprintf(buf, len, "dt = %g s is accurate only roughly: %s %s %s %% of its amplitude per "
             "period to %s; dt < %.3g s keeps it under 1 %%", l->dt, mode, verb, pc, name,
             limits_round_down(l->accurate_dt));
}

void limits_say_drive(const struct limits *l, bool short_form, char *buf, size_t len)
{
    buf[0] = '\0';
    if (!limits_rough_drive(l))
        return;
    double need = limits_round_down(1.0 / (LIMITS_DRIVE_STEPS * l->drive_hz));
    if (short_form)
        snprintf(buf, len, "warning: %.2g steps per period of the %.3g Hz drive; dt <= %.3g s "
                 "gives %.0f", l->drive_steps, l->drive_hz, need, LIMITS_DRIVE_STEPS);
    else
        snprintf(buf, len, "dt = %g s is accurate only roughly: the %.3g Hz drive gets %.2g "
                 "steps per period; dt <= %.3g s gives it %.0f", l->dt, l->drive_hz,
                 l->drive_steps, need, LIMITS_DRIVE_STEPS);
}
