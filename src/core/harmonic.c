/* harmonic.c: harmonic balance with one harmonic for a chain with cubic springs driven by
 * the motor's sine u = A sin(wt) and the force F sin(wt) on mass K, and its continuation
 * along w (harmonic.h).
 *
 * With x_i = a_i cos wt + b_i sin wt, each spring's stretch is s_j = p_j cos + q_j sin
 * (s_N = u - x_N for the motor's spring, whose q_N carries A), and the first harmonic of
 * its force k s + k3 s^3 + cs s' is (k + 3/4 k3 (p^2 + q^2)) (p cos + q sin) +
 * cs w (q cos - p sin). The balance of each mass's
 * m x'' + c x' + T_i - T_{i+1} = [i = K] F sin wt in cos and sin:
 *
 *   -m w^2 a_i + c w b_i + Tc_i - Tc_{i+1} = 0,
 *   -m w^2 b_i - c w a_i + Ts_i - Ts_{i+1} - [i = K] F = 0,
 *
 * 2N equations in the 2N coefficients, solved by Newton (a banded LU: bordered.h). The curve is
 * followed by pseudo-arclength continuation (Keller 1977; Seydel, Practical Bifurcation
 * and Stability Analysis, 4.5) in scaled unknowns (z / A, w / the span of w): a tangent
 * predictor, a corrector on R = 0 and t . (y - y_predicted) = 0, the tangent's w part
 * changing sign at a fold, found by bisection along the step. Stability: Hill's method
 * on the same harmonic (slow_rate). */
#include "harmonic.h"

#include <complex.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <lapacke.h>

#include "bordered.h"
#include "modes.h"

#define NEWTON_MAX 12     /* corrector iterations */
#define NEWTON_TOL 1e-12  /* of the scaled step */
#define STEP_MAX 0.02     /* scaled arclength a step, at most */
#define STEP_MIN 1e-10    /* below this the continuation gives up */
#define POINTS_MAX 400000 /* points a curve may have */
#define BISECTIONS 60     /* along the step holding a fold */

/* The workspace of one chain: its parameters, the scales and the solves' room. */
struct hb {
    const struct model *m;
    int n, dim;       /* masses, 2N + 1 */
    double amp;       /* A (m): the motor's, 0 without a motor end */
    double force;     /* F (N) on mass force_on, 0 without one */
    double zs, ws;    /* the scales of z and w */
    double *jac;      /* dim x dim, column-major */
    double *rhs;      /* dim */
    double *res;      /* 2N residual */
    double *p, *q;    /* N+1 stretches' cos and sin parts */
    struct bordered band; /* dR/dz is banded: each mass meets only its neighbours */
};

static int hb_init(struct hb *h, const struct model *m, double wspan)
{
    int n = m->n, dim = 2 * n + 1;
    h->m = m;
    h->n = n;
    h->dim = dim;
    h->amp = m->boundary == BOUNDARY_MOTOR ? m->motor.amplitude : 0.0;
    h->force = m->force;
    /* The size of the motion: A, and the force's static deflection on the springs. */
    double springs = 0.0;
    for (int j = 0; j <= n; j++)
        springs += j < n || m->boundary != BOUNDARY_FREE ? m->k[j] : 0.0;
    h->zs = h->amp + (h->force != 0.0 ? fabs(h->force) / (springs > 0.0 ? springs : 1.0) : 0.0);
    h->ws = wspan;
    h->jac = malloc(((size_t)dim * dim + 2 * (size_t)dim + 2 * (size_t)(n + 1)) * sizeof *h->jac);
    /* Row 2i + u of dR/dz holds the columns of masses i - 1, i and i + 1: 3 each side. */
    if (!h->jac || bordered_init(&h->band, 2 * n, 3, 3) != 0) {
        free(h->jac);
        return -1;
    }
    h->rhs = h->jac + (size_t)dim * dim;
    h->res = h->rhs + dim;
    h->p = h->res + dim;
    h->q = h->p + n + 1;
    return 0;
}

static void hb_free(struct hb *h)
{
    free(h->jac);
    bordered_free(&h->band);
}

/* The springs' stretches' parts p, q from z = (a_0, b_0, a_1, b_1, ...) (m). */
static int stretches(struct hb *h, const double *z)
{
    int n = h->n;
    for (int j = 0; j < n; j++) {
        h->p[j] = z[2 * j] - (j ? z[2 * j - 2] : 0.0);
        h->q[j] = z[2 * j + 1] - (j ? z[2 * j - 1] : 0.0);
    }
    bool end = h->m->boundary != BOUNDARY_FREE;
    h->p[n] = end ? -z[2 * n - 2] : 0.0;
    h->q[n] = end ? h->amp - z[2 * n - 1] : 0.0;
    return end ? n + 1 : n;
}

/* R(z, w) into h->res; with jac, also dR/dz (2N x 2N, leading dimension h->dim) and
 * dR/dw into column 2N. */
static void residual(struct hb *h, const double *z, double w, double *jac)
{
    const struct model *m = h->m;
    int n = h->n, ld = h->dim, springs = stretches(h, z);
    double *r = h->res;
    for (int i = 0; i < n; i++) {
        double mw2 = m->m[i] * w * w, cw = m->c[i] * w;
        r[2 * i] = -mw2 * z[2 * i] + cw * z[2 * i + 1];
        r[2 * i + 1] = -mw2 * z[2 * i + 1] - cw * z[2 * i];
    }
    if (jac) {
        for (int col = 0; col < ld; col++)
            memset(jac + (size_t)col * ld, 0, (size_t)(2 * n) * sizeof *jac);
        for (int i = 0; i < n; i++) {
            double mw2 = m->m[i] * w * w, cw = m->c[i] * w;
            jac[2 * i + (size_t)(2 * i) * ld] = -mw2;
            jac[2 * i + (size_t)(2 * i + 1) * ld] = cw;
            jac[2 * i + 1 + (size_t)(2 * i + 1) * ld] = -mw2;
            jac[2 * i + 1 + (size_t)(2 * i) * ld] = -cw;
            jac[2 * i + (size_t)(2 * n) * ld] = -2.0 * m->m[i] * w * z[2 * i] + m->c[i] * z[2 * i + 1];
            jac[2 * i + 1 + (size_t)(2 * n) * ld] =
                -2.0 * m->m[i] * w * z[2 * i + 1] - m->c[i] * z[2 * i];
        }
    }
    if (h->force != 0.0)
        r[2 * m->force_on + 1] -= h->force;
    for (int j = 0; j < springs; j++) {
        double p = h->p[j], q = h->q[j], k3 = 0.75 * m->k3[j], cw = m->cs[j] * w;
        double g = m->k[j] + k3 * (p * p + q * q);
        double fc = g * p + cw * q, fs = g * q - cw * p;
        /* Spring j pushes mass j - 1 (+T) and mass j (-T): R_i has +T_i - T_{i+1}. */
        if (j < n)
            r[2 * j] += fc, r[2 * j + 1] += fs;
        if (j > 0)
            r[2 * j - 2] -= fc, r[2 * j - 1] -= fs;
        if (!jac)
            continue;
        /* The damper's part depends on w too: d(Tc, Ts)/dw = cs (q, -p). */
        if (j < n) {
            jac[2 * j + (size_t)(2 * n) * ld] += m->cs[j] * q;
            jac[2 * j + 1 + (size_t)(2 * n) * ld] -= m->cs[j] * p;
        }
        if (j > 0) {
            jac[2 * j - 2 + (size_t)(2 * n) * ld] -= m->cs[j] * q;
            jac[2 * j - 1 + (size_t)(2 * n) * ld] += m->cs[j] * p;
        }
        double d[2][2] = {{g + 2.0 * k3 * p * p, 2.0 * k3 * p * q + cw},
                          {2.0 * k3 * p * q - cw, g + 2.0 * k3 * q * q}};
        /* ds_j/dx_j = +1, ds_j/dx_{j-1} = -1; dR_i/ds_j = +1 for i = j, -1 for i = j - 1. */
        for (int ri = j - 1; ri <= j; ri++) {
            if (ri < 0 || ri >= n)
                continue;
            for (int xi = j - 1; xi <= j; xi++) {
                if (xi < 0 || xi >= n)
                    continue;
                double sign = (ri == j ? 1.0 : -1.0) * (xi == j ? 1.0 : -1.0);
                for (int u = 0; u < 2; u++)
                    for (int v = 0; v < 2; v++)
                        jac[2 * ri + u + (size_t)(2 * xi + v) * ld] += sign * d[u][v];
            }
        }
    }
}

/* Newton at fixed w from z: 0 when converged (z updated), -1 when not. */
static int solve_at(struct hb *h, double *z, double w)
{
    int n2 = 2 * h->n;
    for (int it = 0; it < 2 * NEWTON_MAX; it++) {
        residual(h, z, w, h->jac);
        double step = 0.0, size = 0.0;
        for (int i = 0; i < n2; i++)
            h->rhs[i] = -h->res[i];
        if (bordered_solve(&h->band, h->jac, h->dim, false, h->rhs) != 0)
            return -1;
        for (int i = 0; i < n2; i++) {
            z[i] += h->rhs[i];
            step = fmax(step, fabs(h->rhs[i]));
            size = fmax(size, fabs(z[i]));
        }
        if (!isfinite(step))
            return -1;
        if (step <= NEWTON_TOL * (size + h->zs))
            return 0;
    }
    return -1;
}

/* The residual and the bordered Jacobian at scaled point y = (z / zs, w / ws): dR/dy
 * (dR/dy_i = dR/dz_i zs, dR/dy_w = dR/dw ws) in the first 2N rows of h->jac, the row
 * `last` below them (NULL: the unit vector along w). */
static void scaled_system(struct hb *h, const double *y, const double *last)
{
    int n2 = 2 * h->n, dim = h->dim;
    double zz[2 * HARMONIC_MAX_MASSES] = {0};
    for (int i = 0; i < n2; i++)
        zz[i] = y[i] * h->zs;
    residual(h, zz, y[n2] * h->ws, h->jac);
    for (int col = 0; col < dim; col++) {
        /* dR/dz is banded (3 each side: residual), its zeros left as they are */
        double s = col < n2 ? h->zs : h->ws;
        int lo = col < n2 && col > 3 ? col - 3 : 0, hi = col < n2 && col + 3 < n2 ? col + 3 : n2 - 1;
        for (int r = lo; r <= hi; r++)
            h->jac[r + (size_t)col * dim] *= s;
        h->jac[n2 + (size_t)col * dim] = last ? last[col] : col == n2;
    }
}

/* The unit tangent at y = (z / zs, w / ws) oriented along dir (its dot product with dir
 * positive; dir NULL: w increasing), into t. 0, or -1 when the solve fails. */
static int tangent(struct hb *h, const double *y, const double *dir, double *t)
{
    int n2 = 2 * h->n, dim = h->dim;
    scaled_system(h, y, dir);
    memset(h->rhs, 0, (size_t)dim * sizeof *h->rhs);
    h->rhs[n2] = 1.0;
    if (bordered_solve(&h->band, h->jac, dim, true, h->rhs) != 0)
        return -1;
    double norm = 0.0;
    for (int i = 0; i < dim; i++)
        norm += h->rhs[i] * h->rhs[i];
    norm = sqrt(norm);
    if (!(norm > 0.0) || !isfinite(norm))
        return -1;
    for (int i = 0; i < dim; i++)
        t[i] = h->rhs[i] / norm;
    return 0;
}

/* The corrector: from the prediction y (scaled), Newton on R = 0 and t . (y - pred) = 0.
 * 0 when converged (y the point on the curve), -1 when not; *its the iterations. */
static int correct(struct hb *h, const double *t, double *y, int *its)
{
    int n2 = 2 * h->n, dim = h->dim;
    double pred[2 * HARMONIC_MAX_MASSES + 1];
    memcpy(pred, y, (size_t)dim * sizeof *y);
    for (int it = 1; it <= NEWTON_MAX; it++) {
        scaled_system(h, y, t);
        double along = 0.0;
        for (int i = 0; i < dim; i++)
            along += t[i] * (y[i] - pred[i]);
        for (int i = 0; i < n2; i++)
            h->rhs[i] = -h->res[i];
        h->rhs[n2] = -along;
        if (bordered_solve(&h->band, h->jac, dim, true, h->rhs) != 0)
            return -1;
        double step = 0.0, size = 1.0;
        for (int i = 0; i < dim; i++) {
            y[i] += h->rhs[i];
            step = fmax(step, fabs(h->rhs[i]));
            size = fmax(size, fabs(y[i]));
        }
        *its = it;
        if (!isfinite(step) || y[n2] <= 0.0)
            return -1;
        if (step <= NEWTON_TOL * size)
            return 0;
    }
    return -1;
}

/* Adds point y (scaled) to the curve; -1 when there is no more room. */
static int add_point(struct harmonic_curve *c, const struct hb *h, const double *y)
{
    int n2 = 2 * c->n;
    if (c->count == c->cap) {
        int cap = c->cap ? 2 * c->cap : 1024;
        if (cap > POINTS_MAX)
            return -1;
        double *f = realloc(c->f, (size_t)cap * sizeof *f);
        if (!f)
            return -1;
        c->f = f;
        double *ab = realloc(c->ab, (size_t)cap * n2 * sizeof *ab);
        if (!ab)
            return -1;
        c->ab = ab;
        c->cap = cap;
    }
    c->f[c->count] = y[n2] * h->ws / (2.0 * M_PI);
    for (int i = 0; i < n2; i++)
        c->ab[(size_t)c->count * n2 + i] = y[i] * h->zs;
    c->count++;
    return 0;
}

/* The largest mass amplitude of scaled point y (m). */
static double top_amp(const struct hb *h, const double *y)
{
    double top = 0.0;
    for (int i = 0; i < h->n; i++)
        top = fmax(top, hypot(y[2 * i], y[2 * i + 1]) * h->zs);
    return top;
}

/* A fold inside the step of length len from y0 along t0 (the tangent's w part changes
 * sign over it): bisected along the step; the fold's point added to the curve, its
 * frequency and amplitude recorded. 0, or -1 on no memory. */
static int find_fold(struct harmonic_curve *c, struct hb *h, const double *y0, const double *t0,
                     double len)
{
    int dim = h->dim, n2 = 2 * h->n, its;
    double lo = 0.0, hi = len, y[2 * HARMONIC_MAX_MASSES + 1], t[2 * HARMONIC_MAX_MASSES + 1];
    double best[2 * HARMONIC_MAX_MASSES + 1];
    bool found = false;
    double sign0 = t0[n2];
    for (int b = 0; b < BISECTIONS; b++) {
        double mid = 0.5 * (lo + hi);
        for (int i = 0; i < dim; i++)
            y[i] = y0[i] + mid * t0[i];
        if (correct(h, t0, y, &its) != 0 || tangent(h, y, t0, t) != 0)
            break;
        memcpy(best, y, (size_t)dim * sizeof *y);
        found = true;
        if ((t[n2] > 0.0) == (sign0 > 0.0))
            lo = mid;
        else
            hi = mid;
    }
    if (!found || c->folds == HARMONIC_MAX_FOLDS)
        return 0;
    if (add_point(c, h, best) != 0)
        return -1;
    c->fold_f[c->folds] = best[n2] * h->ws / (2.0 * M_PI);
    c->fold_amp[c->folds] = top_amp(h, best);
    c->fold_after[c->folds] = c->count - 1;
    c->folds++;
    return 0;
}

/* The linear chain's response at w as a start: x = amp sin(wt + phase). */
static void linear_start(const struct model *m, double w, double *z)
{
    int n = m->n;
    double amp[HARMONIC_MAX_MASSES], ph[HARMONIC_MAX_MASSES];
    if (modes_response_phase(m, w / (2.0 * M_PI), amp, ph) != 0) {
        memset(z, 0, (size_t)(2 * n) * sizeof *z);
        return;
    }
    for (int i = 0; i < n; i++) {
        double phi = ph[i] * M_PI / 180.0;
        z[2 * i] = amp[i] * sin(phi);
        z[2 * i + 1] = amp[i] * cos(phi);
    }
}

/* Follows the curve from scaled point y until w passes wend; 0, or -1 on no memory. */
static int follow(struct harmonic_curve *c, struct hb *h, double *y, double wstart, double wend)
{
    int dim = h->dim, n2 = 2 * h->n, its;
    double t[2 * HARMONIC_MAX_MASSES + 1], tn[2 * HARMONIC_MAX_MASSES + 1];
    double y1[2 * HARMONIC_MAX_MASSES + 1];
    if (tangent(h, y, NULL, t) != 0)
        return 0;
    double len = 0.25 * STEP_MAX;
    while (y[n2] * h->ws < wend) {
        for (int i = 0; i < dim; i++)
            y1[i] = y[i] + len * t[i];
        if (correct(h, t, y1, &its) != 0 || tangent(h, y1, t, tn) != 0) {
            len *= 0.5;
            if (len < STEP_MIN)
                return 0;
            continue;
        }
        if ((tn[n2] > 0.0) != (t[n2] > 0.0) && find_fold(c, h, y, t, len) != 0)
            return c->count == c->cap ? 0 : -1;
        memcpy(y, y1, (size_t)dim * sizeof *y);
        memcpy(t, tn, (size_t)dim * sizeof *t);
        if (add_point(c, h, y) != 0)
            return c->count == c->cap ? 0 : -1;
        if (top_amp(h, y) > MODEL_LENGTH || y[n2] * h->ws < 0.5 * wstart)
            return 0; /* past the walls, or turned back for good (softening) */
        if (its <= 3)
            len = fmin(STEP_MAX, len * 1.5);
    }
    c->complete = true;
    return 0;
}

struct harmonic_curve *harmonic_trace(const struct model *m, double fmin, double fmax,
                                      char *err, size_t errlen)
{
    int n = m->n;
    if (!model_driven(m)) {
        snprintf(err, errlen, "harmonic balance needs a drive (--boundary motor with "
                 "--amplitude above 0, or --force above 0)");
        return NULL;
    }
    if (n > HARMONIC_MAX_MASSES) {
        snprintf(err, errlen, "harmonic balance takes at most %d masses, not %d (its dense "
                 "solves grow as N^3)", HARMONIC_MAX_MASSES, n);
        return NULL;
    }
    double wstart = 2.0 * M_PI * fmin * 0.9, wend = 2.0 * M_PI * fmax * 1.02;
    struct harmonic_curve *c = calloc(1, sizeof *c);
    struct hb h;
    if (!c || hb_init(&h, m, wend - wstart) != 0) {
        free(c);
        snprintf(err, errlen, "out of memory");
        return NULL;
    }
    c->n = n;
    double z[2 * HARMONIC_MAX_MASSES], y[2 * HARMONIC_MAX_MASSES + 1];
    linear_start(m, wstart, z);
    if (solve_at(&h, z, wstart) != 0) {
        memset(z, 0, sizeof z);
        if (solve_at(&h, z, wstart) != 0) {
            snprintf(err, errlen, "harmonic balance found no steady motion at %.6g Hz to start "
                     "from", wstart / (2.0 * M_PI));
            harmonic_curve_free(c);
            hb_free(&h);
            return NULL;
        }
    }
    for (int i = 0; i < 2 * n; i++)
        y[i] = z[i] / h.zs;
    y[2 * n] = wstart / h.ws;
    int e = add_point(c, &h, y) != 0 ? -1 : follow(c, &h, y, wstart, wend);
    hb_free(&h);
    if (e != 0) {
        snprintf(err, errlen, "out of memory");
        harmonic_curve_free(c);
        return NULL;
    }
    return c;
}

void harmonic_curve_free(struct harmonic_curve *c)
{
    if (!c)
        return;
    free(c->f);
    free(c->ab);
    free(c);
}

/* Hill's method with the one harmonic: with a_i, b_i slowly varying, x'' and x' gain
 * 2 w m (-a_i' sin + b_i' cos) and C (a' cos + b' sin) (C the damping matrix: the ground
 * dampers c_i on its diagonal, each spring damper cs_j on its two masses' rows as K has
 * k_j), so the balance becomes B z' = -R(z) with B's cos row of mass i (C a')_i +
 * 2 m_i w b_i' and its sin row (C b')_i - 2 m_i w a_i'. The motion is stable when every
 * eigenvalue of -B^-1 dR/dz (dgesv, then dgeev) has a negative real part: the largest
 * real part (1/s) is returned (NAN when LAPACK fails). It crosses 0 exactly at the folds
 * of the same balance. Undamped, the slow flow conserves energy: its eigenvalues come in
 * pairs +-l, on the imaginary axis (a centre, neutrally stable) or on the real one (a
 * saddle); a real part within rounding of the largest |l| is a centre's, returned as 0. */
static double slow_rate(struct hb *h, const double *z, double w)
{
    const struct model *m = h->m;
    int n = h->n, n2 = 2 * n, ld = h->dim;
    residual(h, z, w, h->jac);
    double *a = malloc((2 * (size_t)n2 * n2 + 2 * (size_t)n2) * sizeof *a);
    lapack_int *piv = malloc((size_t)n2 * sizeof *piv);
    if (!a || !piv) {
        free(a);
        free(piv);
        return NAN;
    }
    double *b = a + (size_t)n2 * n2, *wr = b + (size_t)n2 * n2, *wi = wr + n2;
    memset(b, 0, (size_t)n2 * n2 * sizeof *b);
    for (int col = 0; col < n2; col++)
        for (int r = 0; r < n2; r++)
            a[r + (size_t)col * n2] = -h->jac[r + (size_t)col * ld];
    for (int i = 0; i < n; i++) {
        double g = 2.0 * m->m[i] * w;
        b[2 * i + (size_t)(2 * i + 1) * n2] = g;
        b[2 * i + 1 + (size_t)(2 * i) * n2] = -g;
        for (int u = 0; u < 2; u++)
            b[2 * i + u + (size_t)(2 * i + u) * n2] = m->c[i];
    }
    for (int j = 0; j <= n; j++) {
        double cs = m->cs[j];
        if (cs == 0.0 || (j == n && m->boundary == BOUNDARY_FREE))
            continue;
        for (int ri = j - 1; ri <= j; ri++)
            for (int xi = j - 1; xi <= j; xi++)
                if (ri >= 0 && ri < n && xi >= 0 && xi < n)
                    for (int u = 0; u < 2; u++)
                        b[2 * ri + u + (size_t)(2 * xi + u) * n2] += ri == xi ? cs : -cs;
    }
    double top = NAN;
    if (LAPACKE_dgesv(LAPACK_COL_MAJOR, n2, n2, b, n2, piv, a, n2) == 0 &&
        LAPACKE_dgeev(LAPACK_COL_MAJOR, 'N', 'N', n2, a, n2, wr, wi, NULL, 1, NULL, 1) == 0) {
        top = -INFINITY;
        double size = 0.0;
        for (int i = 0; i < n2; i++)
            top = fmax(top, wr[i]), size = fmax(size, hypot(wr[i], wi[i]));
        if (fabs(top) <= 1e-9 * size)
            top = 0.0;
    }
    free(a);
    free(piv);
    return top;
}

int harmonic_at(const struct model *m, const struct harmonic_curve *c, double f,
                struct harmonic_solution *out, int max)
{
    int n = c->n, n2 = 2 * n, found = 0, branch = 1, fold = 0;
    struct hb h;
    double w = 2.0 * M_PI * f, z[2 * HARMONIC_MAX_MASSES];
    if (hb_init(&h, m, 1.0) != 0)
        return 0;
    for (int k = 0; k + 1 < c->count && found < max; k++) {
        while (fold < c->folds && c->fold_after[fold] <= k)
            fold++, branch++;
        double f0 = c->f[k], f1 = c->f[k + 1];
        if (!((f0 <= f && f < f1) || (f1 < f && f <= f0)))
            continue;
        double s = (f - f0) / (f1 - f0);
        const double *a0 = c->ab + (size_t)k * n2, *a1 = a0 + n2;
        for (int i = 0; i < n2; i++)
            z[i] = a0[i] + s * (a1[i] - a0[i]);
        double guess[2 * HARMONIC_MAX_MASSES];
        memcpy(guess, z, (size_t)n2 * sizeof *z);
        if (solve_at(&h, z, w) != 0)
            memcpy(z, guess, (size_t)n2 * sizeof *z); /* at a fold: the curve's own */
        struct harmonic_solution *o = &out[found++];
        o->branch = branch;
        for (int i = 0; i < n; i++) {
            o->amp[i] = hypot(z[2 * i], z[2 * i + 1]);
            o->phase[i] = atan2(z[2 * i], z[2 * i + 1]) * 180.0 / M_PI;
            if (o->phase[i] <= -180.0)
                o->phase[i] += 360.0;
        }
        o->rate = slow_rate(&h, z, w);
        o->stable = o->rate <= 0.0; /* 0: a centre, neutrally stable */
    }
    hb_free(&h);
    return found;
}

int harmonic_curve_rates(const struct model *m, const struct harmonic_curve *c, double *rate)
{
    struct hb h;
    if (hb_init(&h, m, 1.0) != 0)
        return -1;
    for (int k = 0; k < c->count; k++)
        rate[k] = slow_rate(&h, c->ab + (size_t)k * 2 * c->n, 2.0 * M_PI * c->f[k]);
    hb_free(&h);
    return 0;
}

double harmonic_backbone(const struct model *m, double f)
{
    if (m->n != 1)
        return NAN;
    double k = m->k[0] + (m->boundary == BOUNDARY_FREE ? 0.0 : m->k[1]);
    double k3 = m->k3[0] + (m->boundary == BOUNDARY_FREE ? 0.0 : m->k3[1]);
    double w = 2.0 * M_PI * f, a2 = (m->m[0] * w * w - k) / (0.75 * k3);
    return k3 != 0.0 && a2 >= 0.0 ? sqrt(a2) : NAN;
}
