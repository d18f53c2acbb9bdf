/* limits.c: the stability and accuracy limits of dt (docs/accuracy.md).
 *
 * The chain M x'' + C x' + K x = 0 is the first-order system z' = A z with
 * A = [[0, I], [-M^-1 K, -M^-1 C]]; its 2N eigenvalues (LAPACK dgeev) pair into N
 * modes, each the oscillator x'' = -w2 x - 2 s x' with those two eigenvalues.
 *
 * Stability is the spectral radius of each integrator's own one-step matrix S, built by
 * its stepper (onestep.c), up to ONESTEP_MAX masses (the interactive program's 10
 * included). Above that S's 2N x 2N eigenproblem at every h of the search costs too
 * much (dgeev: 0.04 ms at 2N = 20, 35 ms at 200, 15 s at 2000), so:
 * - euler and rk4: S = R(hA), whose eigenvalues are R(h lambda) exactly, so the modes'
 *   2x2 steps (whose eigenvalues are R of the pair's lambdas) give S's radius exactly
 *   while the modes are dgeev's (up to LIMITS_DGEEV_MAX masses); above that, the modes
 *   sampled on the boundary of the region that holds every eigenvalue (stability.c):
 *   a limit never past the real one, reached with proportional damping;
 * - semi-implicit and verlet: the first h at which S has the eigenvalue -1, the only
 *   way out of the unit disc for them (stability.c): exact, O(N) and O(N^2).
 *
 * Accuracy: a mode's motion over one period T = 2 pi / omega_d goes by exp(lambda T);
 * the method's by mu^(T/h), mu the eigenvalue of the mode's 2x2 step (integrator_mode_step)
 * that stands for lambda. Their ratio minus one, E, is the error after one period: its
 * modulus the part of the amplitude the motion is off by, amplitude and phase together
 * (semi-implicit and verlet keep the amplitude but not the phase). With non-modal damping
 * the 2x2 step is the mode's share of S only approximately. The drive: the steady motion
 * at its frequency with the integrator against the exact one (onestep_drive_error), up to
 * ONESTEP_MAX masses; above, the error per period of an undamped mode at the drive's
 * frequency. The good steps are found along h by onestep_search (scan, then bisection).
 *
 * What the searches cost at start-up: for euler and rk4 the modes answer the stability
 * search's question wherever the answer is clear by far more than rounding, and S's
 * radius (a dgeev each) is asked only near the edge (36 solves instead of 95 at N = 10,
 * the same limit); the drive's search asks the steady state only (the exact one solved
 * once, no radius below the stability limit); a least over the modes stops each mode's
 * search once it cannot go lower; above LIMITS_DGEEV_MAX the undamped modes are solved
 * once, not again for the stability region. */
#include "limits.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include <complex.h>

#include <lapacke.h>

#include "modes.h"
#include "onestep.h"
#include "stability.h"

#define RHO_TOL 1e-12      /* rho this far above 1 is rounding, not growth */
#define REGION_MODES 320   /* modes sampled on the eigenvalues' region (long chains) */
#define PERIOD_STEPS 4096  /* steps of a period looked at for its error */

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

/* The eigenvalues of the 2x2 step of integrator i on mode md at step h: the one of
 * largest modulus, and for a complex pair the one with Im >= 0. */
static double complex mode_mu(const struct limits_mode *md, enum integrator i, double h)
{
    double q[4];
    integrator_mode_step(i, md->w2, md->s, h, q);
    double half = 0.5 * (q[0] + q[3]), det = q[0] * q[3] - q[1] * q[2];
    double disc = half * half - det;
    if (disc < 0.0)
        return half + I * sqrt(-disc);
    return half >= 0.0 ? half + sqrt(disc) : half - sqrt(disc);
}

/* The 2x2 step of integrator i on mode md in the coordinates (w x, v), w = sqrt(w2), in
 * which the exact motion turns (and decays) without changing shape. */
static void scaled_step(const struct limits_mode *md, enum integrator i, double h, double q[4])
{
    double w = sqrt(md->w2);
    integrator_mode_step(i, md->w2, md->s, h, q);
    q[1] *= w;
    q[2] /= w;
}

/* The largest singular value of the 2x2 matrix a (row-major). */
static double norm2(const double a[4])
{
    double f = a[0] * a[0] + a[1] * a[1] + a[2] * a[2] + a[3] * a[3];
    double det = a[0] * a[3] - a[1] * a[2];
    return sqrt(0.5 * (f + sqrt(fmax(f * f - 4.0 * det * det, 0.0))));
}

/* The largest error of the method's motion within one period against the exact one,
 * over every start of unit size: max over n <= T/h of |Q^n - E^n| (Q the method's step,
 * E the exact one, both scaled). Past PERIOD_STEPS steps a period every method here is
 * within 1 % (euler's growth, the worst, is pi^2 / steps), and the steps after those are
 * not taken. */
static double period_error(const struct limits_mode *md, enum integrator i, double h,
                           double period)
{
    double q[4], e[4], qn[4] = {1, 0, 0, 1}, en[4] = {1, 0, 0, 1}, err = 0.0;
    scaled_step(md, i, h, q);
    scaled_step(md, INTEGRATOR_EXACT, h, e);
    double steps = fmin(ceil(period / h - 1e-9), PERIOD_STEPS);
    for (int n = 1; n <= (int)steps && err < 1e6; n++) {
        double a[4] = {q[0] * qn[0] + q[1] * qn[2], q[0] * qn[1] + q[1] * qn[3],
                       q[2] * qn[0] + q[3] * qn[2], q[2] * qn[1] + q[3] * qn[3]};
        double b[4] = {e[0] * en[0] + e[1] * en[2], e[0] * en[1] + e[1] * en[3],
                       e[2] * en[0] + e[3] * en[2], e[2] * en[1] + e[3] * en[3]};
        double d[4] = {a[0] - b[0], a[1] - b[1], a[2] - b[2], a[3] - b[3]};
        err = fmax(err, norm2(d));
        for (int k = 0; k < 4; k++)
            qn[k] = a[k], en[k] = b[k];
    }
    return err;
}

double limits_mode_error(const struct limits_mode *md, enum integrator i, double dt,
                         double *amp, double *phase)
{
    double a = 0.0, p = 0.0, e = 0.0;
    if (md->s * md->s >= md->w2) {
        a = p = e = NAN;
    } else if (i != INTEGRATOR_EXACT) {
        double wd = sqrt(md->w2 - md->s * md->s), period = 2.0 * M_PI / wd;
        double complex mu = mode_mu(md, i, dt);
        if (cabs(mu) > 0.0) {
            /* log(mu / exp(lambda dt)) per step, lambda = -s + i wd, times the steps */
            a = expm1(period / dt * (log(cabs(mu)) + md->s * dt));
            p = remainder(period / dt * (carg(mu) - wd * dt), 2.0 * M_PI);
        } else {
            a = -1.0; /* the method stops the mode dead within a step */
        }
        e = period_error(md, i, dt, period);
    }
    if (amp)
        *amp = a;
    if (phase)
        *phase = p;
    return e;
}

/* What a step is checked for along h. */
struct mode_ctx {
    const struct limits_mode *md;
    enum integrator i;
};

static bool mode_stable(void *ctx, double h)
{
    const struct mode_ctx *c = ctx;
    return cabs(mode_mu(c->md, c->i, h)) <= 1.0 + RHO_TOL;
}

static bool mode_accurate(void *ctx, double h)
{
    const struct mode_ctx *c = ctx;
    return limits_mode_error(c->md, c->i, h, NULL, NULL) <= LIMITS_LOSS;
}

/* The least over the n modes of the largest good h of each. The fastest modes, which
 * usually set it, go first: a slower mode's search stops as soon as it cannot go below
 * the least so far (most take one or two steps of it). */
static double modes_search(const struct limits_mode *mode, int n, enum integrator i,
                           bool (*good)(void *, double), bool oscillating_only)
{
    double dt = INFINITY;
    for (int j = n - 1; j >= 0; j--) {
        if (oscillating_only && mode[j].s * mode[j].s >= mode[j].w2)
            continue;
        struct mode_ctx c = {&mode[j], i};
        dt = fmin(dt, onestep_search_below(good, &c, mode_scale(&mode[j]), dt));
    }
    return dt;
}

/* ---- the chain ---- */

/* euler and rk4 above LIMITS_DGEEV_MAX masses: the modes sampled on the region that holds
 * every eigenvalue of the chain, from the undamped modes' extremes. */
static double region_stable_dt(const struct model *m, enum integrator i, double w2_min,
                               double w2_max)
{
    struct limits_mode *mode = malloc(REGION_MODES * sizeof *mode);
    double *buf = malloc(2 * REGION_MODES * sizeof *buf);
    double dt = 0.0; /* no memory: not known stable at any step */
    if (mode && buf) {
        stability_region_modes(m, w2_min, w2_max, REGION_MODES, buf, buf + REGION_MODES);
        for (int k = 0; k < REGION_MODES; k++)
            mode[k] = (struct limits_mode){fmax(buf[k], 0.0), buf[REGION_MODES + k]};
        dt = modes_search(mode, REGION_MODES, i, mode_stable, false);
    }
    free(mode);
    free(buf);
    return dt;
}

/* Above ONESTEP_MAX masses (see the top of the file). */
static double long_chain_stable_dt(const struct model *m, const struct limits_mode *mode,
                                   int n, enum integrator i)
{
    if (i == INTEGRATOR_SEMI_IMPLICIT)
        return stability_semi_implicit(m);
    if ((i == INTEGRATOR_EULER || i == INTEGRATOR_RK4) && n <= LIMITS_DGEEV_MAX)
        return modes_search(mode, n, i, mode_stable, false);
    /* Above LIMITS_DGEEV_MAX the modes are the undamped ones (modal_modes): their w2
     * are dstevr's own, unless one was clamped at 0. */
    if (n > LIMITS_DGEEV_MAX && mode[0].w2 > 0.0)
        return i == INTEGRATOR_VERLET ? stability_verlet(mode[n - 1].w2)
                                      : region_stable_dt(m, i, mode[0].w2, mode[n - 1].w2);
    double *w2 = malloc((size_t)(2 * n) * sizeof *w2), dt = 0.0;
    if (w2 && modes_modal(m, w2, w2 + n) == 0)
        dt = i == INTEGRATOR_VERLET ? stability_verlet(w2[n - 1])
                                    : region_stable_dt(m, i, w2[0], w2[n - 1]);
    free(w2);
    return dt;
}

/* What the search for S's stable steps is given: euler's and rk4's S = R(hA) has the
 * eigenvalues R(h lambda) of the modes' own 2x2 steps, so where every one is inside the
 * unit circle, or one outside it, by more than MODES_CLEAR (far beyond the rounding of
 * either computation) the modes decide; near the edge S's radius itself does. The search
 * asks the same question at the same h as with S alone, and gets the same answers. */
struct clear_ctx {
    const struct limits_mode *mode;
    int n;
    enum integrator i;
    struct onestep *o;
};

/* The modes here are dgeev's eigenvalues of A (stable_clear runs up to ONESTEP_MAX masses,
 * within LIMITS_DGEEV_MAX), good to the rounding of that solve, about 1e-15 of |lambda|:
 * 1e-12 is a thousand times that, and leaves S's radius (a dgeev of its own, 2N x 2N, at
 * every h) to the last dozen halvings instead of the last thirty. */
#define MODES_CLEAR 1e-12

static bool stable_clear(void *ctx, double h)
{
    const struct clear_ctx *c = ctx;
    double most = 0.0;
    for (int j = 0; j < c->n; j++)
        most = fmax(most, cabs(mode_mu(&c->mode[j], c->i, h)));
    if (most < 1.0 - MODES_CLEAR)
        return true;
    if (most > 1.0 + MODES_CLEAR)
        return false;
    return onestep_radius(c->o, c->i, h) <= 1.0 + RHO_TOL; /* NAN: not known stable */
}

double limits_stable_dt(const struct model *m, const struct limits_mode *mode, int n,
                        enum integrator i)
{
    if (i == INTEGRATOR_EXACT)
        return INFINITY;
    if (n > ONESTEP_MAX)
        return long_chain_stable_dt(m, mode, n, i);
    double scale = 0.0; /* the fastest |lambda|: the unit of the search */
    for (int j = 0; j < n; j++)
        scale = fmax(scale, mode_scale(&mode[j]));
    struct onestep *o = onestep_new(m);
    double dt;
    if (!o) {
        dt = long_chain_stable_dt(m, mode, n, i);
    } else if (i == INTEGRATOR_EULER || i == INTEGRATOR_RK4) {
        struct clear_ctx c = {mode, n, i, o};
        dt = onestep_search(stable_clear, &c, scale);
    } else {
        dt = onestep_stable_dt(o, i, scale);
    }
    onestep_free(o);
    return dt;
}

/* limits_stable_dt, but NAN where the values overflow its computation (dampers of 1e160
 * N s/m make an infinite limit): no explicit integrator is stable at every step on a
 * chain with springs, so an infinite answer only means it is not known. */
static double known_stable_dt(const struct model *m, const struct limits_mode *mode, int n,
                              enum integrator i)
{
    /* Every lambda 0 (no stiffness and no damper at rest: springs of k = 0, cubic or not):
     * each step is x += h v, v kept, growing with no step length faster than t, so every
     * dt is stable; the search's unit of time, 1/|lambda|, is infinite. */
    double scale = 0.0;
    for (int j = 0; j < n; j++)
        scale = fmax(scale, mode_scale(&mode[j]));
    if (scale == 0.0)
        return INFINITY;
    double dt = limits_stable_dt(m, mode, n, i);
    return i != INTEGRATOR_EXACT && !isfinite(dt) ? NAN : dt;
}

double limits_accurate_dt(const struct limits_mode *mode, int n, enum integrator i)
{
    if (i == INTEGRATOR_EXACT)
        return INFINITY;
    return modes_search(mode, n, i, mode_accurate, true);
}

/* ---- the drive ---- */

struct drive_ctx {
    struct onestep *o; /* NULL: the undamped mode at the drive's frequency */
    enum integrator i;
    double f, stable_dt;
};

/* The drive's error at h; known_stable: h is below the stability limit (the search),
 * so the radius need not be asked again. */
static double drive_error(const struct drive_ctx *c, double h, bool known_stable)
{
    if (c->o)
        return known_stable ? onestep_drive_error_stable(c->o, c->i, h, c->f)
                            : onestep_drive_error(c->o, c->i, h, c->f);
    double w = 2.0 * M_PI * c->f;
    struct limits_mode md = {w * w, 0.0};
    return limits_mode_error(&md, c->i, h, NULL, NULL);
}

static bool drive_accurate(void *ctx, double h)
{
    const struct drive_ctx *c = ctx;
    return h <= c->stable_dt && drive_error(c, h, true) <= LIMITS_LOSS; /* NAN: not accurate */
}

/* The steady motion at the drive's frequency: its error at out->dt and the largest step
 * keeping it within LIMITS_LOSS. */
static void judge_drive(const struct model *m, struct limits *out)
{
    struct drive_ctx c = {NULL, out->integrator, out->drive_hz, out->stable_dt};
    if (out->integrator == INTEGRATOR_EXACT) {
        out->drive_dt = INFINITY; /* it follows the drive exactly */
        return;
    }
    if (m->n <= ONESTEP_MAX)
        c.o = onestep_new(m);
    out->drive_error = limits_unstable(out) ? NAN : drive_error(&c, out->dt, false);
    out->drive_dt = fmin(onestep_search(drive_accurate, &c, 2.0 * M_PI * c.f), out->stable_dt);
    onestep_free(c.o);
}

/* ---- the verdict ---- */

void limits_judge(const struct limits_mode *mode, int n, const struct model *m,
                  enum integrator i, double dt, struct limits *out)
{
    *out = (struct limits){.integrator = i, .dt = dt, .worst = -1, .drive_steps = INFINITY,
                           .drive_dt = INFINITY};
    out->stable_dt = known_stable_dt(m, mode, n, i);
    out->accurate_dt = fmin(limits_accurate_dt(mode, n, i), out->stable_dt);
    int top = -1;
    for (int j = 0; j < n; j++) {
        double a, p, e = limits_mode_error(&mode[j], i, dt, &a, &p);
        if (isnan(e))
            continue;
        top = j; /* the modes go up in w2: the last oscillating one is the highest */
        if (out->worst < 0 || e > out->error) {
            out->worst = j;
            out->error = e;
            out->amp_error = a;
            out->phase_error = p;
        }
    }
    if (out->worst >= 0) {
        out->worst_hz = sqrt(mode[out->worst].w2) / (2.0 * M_PI);
        out->worst_is_top = out->worst == top;
    }
    if (model_driven(m)) {
        out->drive_hz = m->motor.frequency;
        out->drive_steps = 1.0 / (m->motor.frequency * dt);
        judge_drive(m, out);
    }
}

bool limits_unstable(const struct limits *l)
{
    return !(l->dt <= l->stable_dt); /* a limit not known (NAN) is not known stable */
}

bool limits_rough_modes(const struct limits *l)
{
    /* Past the stability limit that is all there is to say. */
    return !limits_unstable(l) && l->worst >= 0 && l->error > LIMITS_LOSS;
}

bool limits_rough_drive(const struct limits *l)
{
    /* The search's largest accurate step must agree (NAN: not known rough): an error
     * measured below it has no digits left (dt = 1e-16 s: e^(i w dt) rounds to 1), and
     * no accurate step at all means none were there to measure with (a subnormal spring,
     * so a subnormal drive). */
    return !limits_unstable(l) && l->drive_error > LIMITS_LOSS && l->drive_dt > 0.0 &&
           l->dt > l->drive_dt;
}

void limits_runaway_start(struct limits_runaway *r, const struct model *m,
                          const struct energy *e0)
{
    double amp = m->boundary == BOUNDARY_MOTOR ? m->motor.amplitude : 0.0;
    r->base = e0->kinetic + e0->potential + model_spring_energy(m, m->n, amp);
    r->work0 = e0->motor_work;
    r->most = 0.0;
}

bool limits_runaway_check(struct limits_runaway *r, const struct energy *e)
{
    r->most = fmax(r->most, e->motor_work - r->work0);
    return e->kinetic + e->potential > LIMITS_RUNAWAY * (r->base + r->most);
}

double limits_round_down(double x)
{
    if (!(x > 0.0) || !isfinite(x))
        return x;
    double scale = pow(10.0, 2.0 - floor(log10(x)));
    if (!isfinite(scale) || !isfinite(x * scale))
        return x; /* a subnormal limit: as it is, not 0 */
    return floor(x * scale * (1.0 + 1e-12)) / scale;
}

/* A percentage with the digits it needs: 75, 7.2, 1.3. */
static void percent(double fraction, char *buf, size_t len)
{
    double p = 100.0 * fabs(fraction);
    snprintf(buf, len, p >= 10.0 ? "%.0f" : "%.3g", p);
}

void limits_say_stability(const struct limits *l, bool short_form, char *buf, size_t len)
{
    const char *name = integrator_name(l->integrator);
    buf[0] = '\0';
    if (!limits_unstable(l))
        return;
    if (isnan(l->stable_dt))
        snprintf(buf, len, "%sdt = %g s may be unstable with %s: the stability limit of dt "
                 "cannot be computed for these springs and dampers (the numbers overflow)",
                 short_form ? "warning: " : "", l->dt, name);
    else if (short_form)
        snprintf(buf, len, "warning: dt = %g s is above the stability limit of %s: dt < %.3g s",
                 l->dt, name, limits_round_down(l->stable_dt));
    else
        snprintf(buf, len, "dt = %g s is unstable with %s for these springs and dampers: "
                 "dt < %.3g s is stable", l->dt, name, limits_round_down(l->stable_dt));
}

/* What a period does to the worst mode's amplitude and phase: "loses 76 % and leads 31°". */
static void amp_and_phase(const struct limits *l, char *buf, size_t len)
{
    char pc[16], amp[32], phase[32];
    double deg = l->phase_error * 180.0 / M_PI;
    percent(l->amp_error, pc, sizeof pc);
    if (fabs(l->amp_error) < 0.005)
        snprintf(amp, sizeof amp, "keeps its amplitude");
    else
        snprintf(amp, sizeof amp, "%s %s %%", l->amp_error < 0.0 ? "loses" : "gains", pc);
    if (fabs(deg) < 0.5)
        snprintf(phase, sizeof phase, "its phase");
    else
        snprintf(phase, sizeof phase, "%s %.0f°", deg < 0.0 ? "lags" : "leads", fabs(deg));
    if (fabs(l->amp_error) < 0.005 && fabs(deg) < 0.5)
        snprintf(buf, len, "keeps its amplitude and phase: the error comes and goes within it");
    else
        snprintf(buf, len, "%s and %s%s", amp, fabs(deg) < 0.5 ? "keeps " : "", phase);
}

void limits_say_modes(const struct limits *l, bool short_form, char *buf, size_t len)
{
    char pc[16], mode[48], how[80];
    const char *name = integrator_name(l->integrator);
    buf[0] = '\0';
    if (!limits_rough_modes(l))
        return;
    percent(l->error, pc, sizeof pc);
    if (short_form) {
        snprintf(buf, len, "warning: %.3g Hz mode %s %% off in a period with %s; dt < %.3g s: "
                 "1 %%", l->worst_hz, pc, name, limits_round_down(l->accurate_dt));
        return;
    }
    snprintf(mode, sizeof mode, l->worst_is_top ? "the highest mode (%.3g Hz)"
                                                : "the mode at %.3g Hz", l->worst_hz);
    amp_and_phase(l, how, sizeof how);
    snprintf(buf, len, "dt = %g s is accurate only roughly: within a period %s is off by up "
             "to %s %% of its size with %s (a period %s); dt < %.3g s keeps it under 1 %%",
             l->dt, mode, pc, name, how, limits_round_down(l->accurate_dt));
}

void limits_say_drive(const struct limits *l, bool short_form, char *buf, size_t len)
{
    char pc[16];
    const char *name = integrator_name(l->integrator);
    buf[0] = '\0';
    if (!limits_rough_drive(l))
        return;
    percent(l->drive_error, pc, sizeof pc);
    double need = limits_round_down(l->drive_dt);
    if (short_form)
        snprintf(buf, len, "warning: motion at the %.3g Hz drive %s %% off with %s; dt < %.3g s: "
                 "1 %%", l->drive_hz, pc, name, need);
    else
        snprintf(buf, len, "dt = %g s is accurate only roughly: the steady motion at the "
                 "%.3g Hz drive's frequency is off by %s %% with %s (%.2g steps per period); "
                 "dt < %.3g s keeps it under 1 %%", l->dt, l->drive_hz, pc, name,
                 l->drive_steps, need);
}

const char *limits_linearised_note(const struct model *m)
{
    return m->cubic && model_hardening(m) ? " (linearised at rest: large swings stiffen the "
                                            "hardening springs and lower this limit)"
                                          : "";
}
