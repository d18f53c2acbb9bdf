/* exact_modal.c: the exact step of a chain whose damping is Rayleigh's, C = alpha M +
 * beta K (ground dampers proportional to the masses, spring dampers to the springs), mode
 * by mode; gamma below is mode j's own gamma_j = alpha + beta w_j^2 (exact.c passes no
 * spring dampers where the motor's spring has one and the motor moves).
 *
 * With y = M^(1/2) x and T = M^(-1/2) K M^(-1/2) = Phi diag(w_j^2) Phi^T (T symmetric
 * tridiagonal: Phi by LAPACK's dstevr, w_j as the singular values of T's bidiagonal
 * factor, accurate however small), eta = Phi^T y: C = gamma M makes every mode a damped
 * oscillator of its own, driven through the last mass only,
 *
 *     eta_j'' + gamma eta_j' + w_j^2 eta_j = Phi_(N,j) k_N u / sqrt(m_N).
 *
 * Each mode is taken in exact.c's skewed coordinates, q_j = w_j eta_j, p_j = eta_j', with
 * the drive's two states (s, r) scaled as there (s = sqrt(k_N) u; a sine's r = sqrt(k_N)
 * amp cos, a line's r = sqrt(k_N) u' / w_s): z_j = (q_j, p_j, s, r) and
 *
 *     q' = w p,  p' = -w q - gamma p + f_j s,  f_j = Phi_(N,j) sqrt(k_N) / sqrt(m_N).
 *
 * Its 4 x 4 exponential and books come by exact.c's method on 4 x 4 matrices (6-point
 * Gauss-Legendre on a base interval with ||A_j|| t <= 1/2, doubled up; every exponential
 * GSL's afresh): the dampers' loss gamma |p|^2 sums over the modes (Phi is orthogonal),
 * and the motor's work k_N (u - x_N) u' is k_N (u(b)^2 - u(a)^2) / 2 less the modes' parts
 * k_N x_N u' = sum_j -ax_j q_j u', ax_j = -k_N Phi_(N,j) / (w_j sqrt(m_N)).
 *
 * Cost: a step is two products with Phi (n x n by n x 2) and 32 numbers a mode; a new step
 * length (a contact's) is seven 4 x 4 exponentials a mode, none of them n-sized. The modes
 * are found once per model: contacts change the state, never them. */
#include "exact_modal.h"

#include <math.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_blas.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_linalg.h>
#include <lapacke.h>

#define SLOTS 8          /* cached step lengths: the grid's and those of contacts */
#define PER_MODE 32      /* numbers a mode keeps for a step: E's rows q, p (8), Gd (16), Nw (8) */
#define BASE_NORM 0.5    /* ||A_j|| times the quadrature's base interval */
#define GSL_ROW_TOP 100.0 /* see exact_expm */

struct mslot {
    struct exact_key key; /* which step it holds, ||A|| the largest ||A_j|| (first:
                             exact_key_find reads it) */
    double *data;         /* PER_MODE a mode */
};

struct modal {
    int n, damped;
    unsigned long model, clock;
    double alpha, beta, sk, kn, wscale; /* gamma_j = alpha + beta w_j^2; sqrt(k_N), k_N (0
                                           for a free end); w_s */
    double *w, *f, *ax, *sqm;     /* w_j, f_j, ax_j, sqrt(m_i) */
    double *diag, *off;           /* T for dstevr (overwritten) */
    double *phi;                  /* Phi, column-major: as a row-major n x n matrix, Phi^T */
    double *yin, *hm;             /* n x 2 each: (y, M^(1/2) v) and the modes' (eta, eta') */
    int *isuppz;
    double *mem;
    struct mslot slot[SLOTS];
};

/* 6-point Gauss-Legendre on [-1, 1]: nodes +-gl_x[i], weights gl_w[i]. */
static const double gl_x[3] = {0.2386191860831969086305017, 0.6612093864662645136613996,
                               0.9324695142031520278123016};
static const double gl_w[3] = {0.4679139345726910473898703, 0.3607615730481386075698335,
                               0.1713244923791703450402961};

static size_t doubles(int n)
{
    return (size_t)n * (size_t)n + (size_t)(10 + SLOTS * PER_MODE) * (size_t)n;
}

struct modal *modal_new(int n)
{
    if (n < 1)
        return NULL;
    struct modal *md = calloc(1, sizeof *md);
    if (!md)
        return NULL;
    md->n = n;
    md->mem = malloc(doubles(n) * sizeof(double));
    md->isuppz = malloc((size_t)(2 * n) * sizeof(int));
    if (!md->mem || !md->isuppz) {
        modal_free(md);
        return NULL;
    }
    size_t nn = (size_t)n;
    md->w = md->mem;
    md->f = md->w + nn;
    md->ax = md->f + nn;
    md->sqm = md->ax + nn;
    md->diag = md->sqm + nn;
    md->off = md->diag + nn;
    md->yin = md->off + nn;
    md->hm = md->yin + 2 * nn;
    md->phi = md->hm + 2 * nn;
    for (int i = 0; i < SLOTS; i++)
        md->slot[i].data = md->phi + nn * nn + (size_t)i * PER_MODE * nn;
    return md;
}

void modal_free(struct modal *md)
{
    if (!md)
        return;
    free(md->isuppz);
    free(md->mem);
    free(md);
}

void modal_copy(struct modal *dst, const struct modal *src)
{
    double *mem = dst->mem;
    int *isuppz = dst->isuppz;
    struct mslot slot[SLOTS];
    memcpy(slot, dst->slot, sizeof slot);
    memcpy(mem, src->mem, doubles(src->n) * sizeof(double));
    *dst = *src;
    /* The values only: each keeps its own memory. */
    ptrdiff_t shift = mem - src->mem;
    dst->mem = mem;
    dst->isuppz = isuppz;
    dst->w += shift, dst->f += shift, dst->ax += shift, dst->sqm += shift;
    dst->diag += shift, dst->off += shift, dst->yin += shift, dst->hm += shift;
    dst->phi += shift;
    for (int i = 0; i < SLOTS; i++)
        dst->slot[i].data = slot[i].data;
}

/* Mode j's damping rate gamma_j = alpha + beta w_j^2. */
static double mode_gamma(const struct modal *md, int j)
{
    return md->alpha + md->beta * md->w[j] * md->w[j];
}

int modal_take(struct modal *md, const struct model *m, double alpha, double beta,
               const double *ld, const double *ls)
{
    int n = md->n, free_end = m->boundary == BOUNDARY_FREE;
    md->model++; /* every cached step is stale */
    for (int i = 0; i < n; i++) {
        md->sqm[i] = sqrt(m->m[i]);
        md->diag[i] = (m->k[i] + (i < n - 1 || !free_end ? m->k[i + 1] : 0.0)) / m->m[i];
    }
    for (int i = 0; i < n - 1; i++)
        md->off[i] = -m->k[i + 1] / (md->sqm[i] * md->sqm[i + 1]);
    lapack_int found = 0;
    if (LAPACKE_dstevr(LAPACK_COL_MAJOR, 'V', 'A', n, md->diag, md->off, 0.0, 0.0, 0, 0, 0.0,
                       &found, md->w, md->phi, n, md->isuppz) != 0 ||
        found != n)
        return -1;
    /* dstevr's eigenvalues are good to eps times the largest, which can be all a soft
     * mode has (w^2 5e-9 against 2e6: 8 % off, 3e-5 m after 1000 s): the frequencies are
     * C's singular values instead, by dqds (dbdsqr without vectors), each to a few ulp of
     * itself. Both sort them, dstevr up and dbdsqr down. */
    memcpy(md->diag, ld, (size_t)n * sizeof *md->diag);
    if (n > 1)
        memcpy(md->off, ls, (size_t)(n - 1) * sizeof *md->off);
    if (LAPACKE_dbdsqr(LAPACK_COL_MAJOR, 'L', n, 0, 0, 0, md->diag, md->off, NULL, 1, NULL, 1,
                       NULL, 1) != 0)
        return -1;
    md->sk = free_end ? 0.0 : sqrt(m->k[n]);
    md->kn = free_end ? 0.0 : m->k[n];
    double top = md->diag[0] * md->diag[0];
    for (int j = 0; j < n; j++) {
        /* The two agree to the eigenvalues' rounding (pairing the shapes with the right
         * frequencies), or the modes are not used. */
        double sv = md->diag[n - 1 - j];
        if (!(sv > 0.0) || !isfinite(sv) || !(fabs(md->w[j] - sv * sv) <= 1e-10 * top))
            return -1;
        md->w[j] = sv;
        double last = md->phi[(size_t)(n - 1) + (size_t)n * (size_t)j];
        md->f[j] = last * md->sk / md->sqm[n - 1];
        md->ax[j] = -md->kn * last / (md->w[j] * md->sqm[n - 1]);
    }
    md->wscale = md->w[n - 1]; /* the largest: sorted up above */
    md->alpha = alpha;
    md->beta = beta;
    md->damped = alpha > 0.0 || beta > 0.0;
    return 0;
}

/* tau A_j into s (4 x 4, row-major) for mode j; returns ||A_j|| (tau = 1: the larger of
 * the 1- and infinity-norms). */
static double mode_generator(const struct modal *md, int j, enum exact_kind kind, double omega,
                             double tau, double *s)
{
    memset(s, 0, 16 * sizeof *s);
    s[1] = tau * md->w[j];
    s[4] = -tau * md->w[j];
    s[5] = -tau * mode_gamma(md, j);
    if (kind != EXACT_NONE) {
        s[6] = tau * md->f[j];
        s[11] = tau * (kind == EXACT_SINE ? omega : md->wscale);
        s[14] = kind == EXACT_SINE ? -tau * omega : 0.0;
    }
    double norm = 0.0;
    for (int i = 0; i < 4; i++) {
        double row = 0.0, col = 0.0;
        for (int k = 0; k < 4; k++) {
            row += fabs(s[4 * i + k]);
            col += fabs(s[4 * k + i]);
        }
        norm = fmax(norm, fmax(row, col));
    }
    return norm;
}

/* expm(tau A_j) into x (4 x 4). */
static int mode_expm(const struct modal *md, int j, enum exact_kind kind, double omega, double tau,
                     double *x)
{
    double s[16], t[16];
    mode_generator(md, j, kind, omega, tau, s);
    gsl_matrix_view sv = gsl_matrix_view_array(s, 4, 4), xv = gsl_matrix_view_array(x, 4, 4);
    gsl_matrix_view tv = gsl_matrix_view_array(t, 4, 4);
    return exact_expm(&sv.matrix, &xv.matrix, &tv.matrix);
}

/* Mode j's part of a step h into out (PER_MODE numbers); *norm gets ||A_j||. */
static int fill_mode(const struct modal *md, int j, enum exact_kind kind, double omega, double h,
                     double *out, double *norm)
{
    double s[16], x[16];
    double *prop = out, *g = out + 8, *nw = out + 24;
    int driven = kind != EXACT_NONE;
    *norm = mode_generator(md, j, kind, omega, 1.0, s);
    memset(g, 0, 24 * sizeof *g);
    if (md->damped || driven) {
        int levels = 0;
        while (*norm * ldexp(h, -levels) > BASE_NORM && levels < 1000)
            levels++;
        double base = ldexp(h, -levels);
        double br = driven ? (kind == EXACT_SINE ? omega : md->wscale) / md->sk : 0.0;
        for (int i = 0; i < 6; i++) {
            double node = 0.5 * base * (1.0 + (i < 3 ? -gl_x[i] : gl_x[i - 3]));
            double w = 0.5 * base * gl_w[i % 3];
            if (mode_expm(md, j, kind, omega, node, x))
                return -1;
            for (int a = 0; a < 4; a++)
                for (int b = 0; b < 4; b++)
                    g[4 * a + b] += w * mode_gamma(md, j) * x[4 + a] * x[4 + b];
            for (int c = 0; driven && c < 2; c++) {
                double fc = w * br * x[12 + 2 + c] * md->ax[j];
                for (int b = 0; b < 4; b++)
                    nw[4 * c + b] += fc * x[b];
            }
        }
        for (int level = 0; level < levels; level++) {
            if (mode_expm(md, j, kind, omega, ldexp(base, level), x))
                return -1;
            double gx[16], y[8];
            /* Gd += E^T Gd E */
            for (int a = 0; a < 4; a++)
                for (int b = 0; b < 4; b++) {
                    double sum = 0.0;
                    for (int k = 0; k < 4; k++)
                        sum += g[4 * a + k] * x[4 * k + b];
                    gx[4 * a + b] = sum;
                }
            for (int a = 0; a < 4; a++)
                for (int b = 0; b < 4; b++) {
                    double sum = 0.0;
                    for (int k = 0; k < 4; k++)
                        sum += x[4 * k + a] * gx[4 * k + b];
                    g[4 * a + b] += sum;
                }
            /* Nw += E^T (Nw R), R the drive's block of E */
            double r00 = x[10], r01 = x[11], r10 = x[14], r11 = x[15];
            for (int b = 0; b < 4; b++) {
                y[b] = nw[b] * r00 + nw[4 + b] * r10;
                y[4 + b] = nw[b] * r01 + nw[4 + b] * r11;
            }
            for (int c = 0; c < 2; c++)
                for (int a = 0; a < 4; a++) {
                    double sum = 0.0;
                    for (int k = 0; k < 4; k++)
                        sum += x[4 * k + a] * y[4 * c + k];
                    nw[4 * c + a] += sum;
                }
        }
    }
    if (mode_expm(md, j, kind, omega, h, x))
        return -1;
    memcpy(prop, x, 8 * sizeof *prop);
    return 0;
}

/* The cached step for (kind, omega, h), filled if need be; NULL when that fails. */
static struct mslot *find_slot(struct modal *md, enum exact_kind kind, double omega, double h)
{
    int fresh, i = exact_key_find(md->slot, sizeof md->slot[0], SLOTS, &md->clock, md->model,
                                  kind, omega, h, &fresh);
    struct mslot *sl = &md->slot[i];
    if (!fresh)
        return sl;
    double most = 0.0;
    for (int j = 0; j < md->n; j++) {
        double norm;
        if (fill_mode(md, j, kind, omega, h, sl->data + (size_t)PER_MODE * (size_t)j, &norm))
            return NULL;
        most = fmax(most, norm);
    }
    sl->key = (struct exact_key){md->model, kind, omega, h, most, sl->key.used};
    return sl;
}

/* The drive's end u at t. */
static double drive_u(enum exact_kind kind, const struct exact_drive *d, double t)
{
    if (kind == EXACT_SINE)
        return d->amp * sin(d->omega * t + d->phi);
    return kind == EXACT_LINE ? d->u0 + d->du * (t - d->t0) : 0.0;
}

int modal_advance(struct modal *md, enum exact_kind kind, const struct exact_drive *d, double a,
                  double b, double *x, double *v, double *diss, double *work)
{
    int n = md->n;
    double h = b - a, omega = kind == EXACT_SINE ? d->omega : 0.0;
    struct mslot *sl = find_slot(md, kind, omega, h);
    if (!sl)
        return -1;
    for (int i = 0; i < n; i++) {
        md->yin[2 * i] = md->sqm[i] * x[i];
        md->yin[2 * i + 1] = md->sqm[i] * v[i];
    }
    gsl_matrix_view pt = gsl_matrix_view_array(md->phi, (size_t)n, (size_t)n);
    gsl_matrix_view yv = gsl_matrix_view_array(md->yin, (size_t)n, 2);
    gsl_matrix_view hv = gsl_matrix_view_array(md->hm, (size_t)n, 2);
    gsl_blas_dgemm(CblasNoTrans, CblasNoTrans, 1.0, &pt.matrix, &yv.matrix, 0.0, &hv.matrix);

    double s = 0.0, r = 0.0, br = 0.0;
    if (kind == EXACT_SINE) {
        double th = d->omega * a + d->phi;
        s = md->sk * d->amp * sin(th);
        r = md->sk * d->amp * cos(th);
        br = omega / md->sk;
    } else if (kind == EXACT_LINE) {
        s = md->sk * (d->u0 + d->du * (a - d->t0));
        r = md->sk * d->du / md->wscale;
        br = md->wscale / md->sk;
    }
    /* A step a little longer or shorter than the cached one: the difference first, to
     * first order (error (delta ||A||)^2 / 2 <= 5e-17), as exact.c does. */
    double dd = 0.0, ww = 0.0, delta = h - sl->key.h;
    if (delta != 0.0) {
        for (int j = 0; j < n; j++) {
            double q = md->w[j] * md->hm[2 * j], p = md->hm[2 * j + 1];
            dd += delta * mode_gamma(md, j) * p * p;
            ww += delta * md->ax[j] * q * br * r;
            md->hm[2 * j] = (q + delta * md->w[j] * p) / md->w[j];
            md->hm[2 * j + 1] = p + delta * (-md->w[j] * q - mode_gamma(md, j) * p + md->f[j] * s);
        }
        if (kind != EXACT_NONE) {
            double s1 = s + delta * (kind == EXACT_SINE ? omega : md->wscale) * r;
            r += kind == EXACT_SINE ? -delta * omega * s : 0.0;
            s = s1;
        }
    }
    for (int j = 0; j < n; j++) {
        const double *k = sl->data + (size_t)PER_MODE * (size_t)j, *g = k + 8, *nw = k + 24;
        double z[4] = {md->w[j] * md->hm[2 * j], md->hm[2 * j + 1], s, r};
        double q1 = 0.0, p1 = 0.0;
        for (int c = 0; c < 4; c++) {
            q1 += k[c] * z[c];
            p1 += k[4 + c] * z[c];
        }
        if (md->damped)
            for (int c = 0; c < 4; c++) {
                double gz = 0.0;
                for (int e = 0; e < 4; e++)
                    gz += g[4 * c + e] * z[e];
                dd += z[c] * gz;
            }
        if (kind != EXACT_NONE) {
            double ns = 0.0, nr = 0.0;
            for (int c = 0; c < 4; c++) {
                ns += nw[c] * z[c];
                nr += nw[4 + c] * z[c];
            }
            ww += s * ns + r * nr;
        }
        md->hm[2 * j] = q1 / md->w[j];
        md->hm[2 * j + 1] = p1;
    }
    if (kind != EXACT_NONE) {
        double ua = drive_u(kind, d, a), ub = drive_u(kind, d, b);
        ww += 0.5 * md->kn * (ub - ua) * (ub + ua);
    }
    gsl_blas_dgemm(CblasTrans, CblasNoTrans, 1.0, &pt.matrix, &hv.matrix, 0.0, &yv.matrix);
    for (int i = 0; i < 2 * n; i++)
        if (!isfinite(md->yin[i]))
            return -1;
    if (!isfinite(dd) || !isfinite(ww))
        return -1;
    for (int i = 0; i < n; i++) {
        x[i] = md->yin[2 * i] / md->sqm[i];
        v[i] = md->yin[2 * i + 1] / md->sqm[i];
    }
    *diss += dd;
    *work += ww;
    return 0;
}

/* GSL takes its Taylor degree and squarings from Moler and Van Loan's table (SIAM Rev.
 * 20, 1978) by the largest |entry|: from 100 up its rows use 8 terms, whose truncation
 * leaves about 1.2e-12 relative (measured on a rotation of 100 to 800 radians). Halving s
 * into the [10, 100) row (10 terms, 10 squarings) and squaring the result back leaves
 * 1.5e-13 at 120 radians, 7e-13 at 500: rounding in the squarings, about 2^squarings eps. */
int exact_expm(gsl_matrix *s, gsl_matrix *out, gsl_matrix *t)
{
    double lo, hi;
    gsl_matrix_minmax(s, &lo, &hi);
    double big = fmax(fabs(lo), fabs(hi));
    if (!isfinite(big))
        return -1;
    int halvings = 0;
    while (big >= GSL_ROW_TOP) {
        big *= 0.5;
        halvings++;
    }
    if (halvings)
        gsl_matrix_scale(s, ldexp(1.0, -halvings));
    if (gsl_linalg_exponential_ss(s, out, GSL_PREC_DOUBLE) != GSL_SUCCESS)
        return -1;
    for (int i = 0; i < halvings; i++) {
        gsl_blas_dgemm(CblasNoTrans, CblasNoTrans, 1.0, out, out, 0.0, t);
        gsl_matrix_memcpy(out, t);
    }
    return 0;
}

int exact_key_find(void *slots, size_t stride, int count, unsigned long *clock,
                   unsigned long model, enum exact_kind kind, double omega, double h,
                   int *fresh)
{
    int old = 0;
    struct exact_key *ko = slots;
    ++*clock;
    for (int i = 0; i < count; i++) {
        struct exact_key *k = (struct exact_key *)((char *)slots + (size_t)i * stride);
        if (k->model == model && k->kind == kind && (kind != EXACT_SINE || k->omega == omega) &&
            fabs(k->h - h) * k->norm <= EXACT_REUSE) {
            k->used = *clock;
            *fresh = 0;
            return i;
        }
        if (k->used < ko->used)
            ko = k, old = i;
    }
    ko->model = 0;
    ko->used = *clock;
    *fresh = 1;
    return old;
}

void exact_key_copy(void *dst, const void *src, size_t stride, int count, int filled)
{
    for (int i = 0; i < count; i++) {
        struct exact_key *a = (struct exact_key *)((char *)dst + (size_t)i * stride);
        *a = *(const struct exact_key *)((const char *)src + (size_t)i * stride);
        if (!filled)
            a->model = 0;
    }
}
