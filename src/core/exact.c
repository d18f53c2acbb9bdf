/* exact.c: the chain over one smooth piece of the drive by the matrix exponential,
 * z(b) = expm(A h) z(a), h = b - a, with the drive's own linear system in A, and the two
 * energy books as quadratic forms in z(a).
 *
 * Coordinates. K (tridiagonal: K_ii = k_i + k_{i+1}, K_{i,i+1} = -k_{i+1}, a free end
 * drops k_N) is positive definite, spring 0 always tying mass 1 to the wall, so
 * M^(-1/2) K M^(-1/2) = L L^T with L lower bidiagonal (from the springs in series, to a few
 * ulp however soft the slowest mode: take_model). With
 *
 *     q = L^T M^(1/2) x,   p = M^(1/2) v,   G = diag(c_i / m_i),
 *     q' = L^T p,          p' = -L q - G p + sqrt(k_N / m_N) e_N s,   s = sqrt(k_N) u,
 *
 * x^T K x / 2 + v^T M v / 2 = (|q|^2 + |p|^2) / 2: the chain's undamped generator is
 * skew and its exponential a rotation (with damping, a contraction), which keeps scaling
 * and squaring near rounding and every entry of A near the chain's frequencies. The
 * drive's two states are scaled by sqrt(k_N) like the chain's: a sine as
 * (s, r) = sqrt(k_N) amp (sin, cos) of its angle, s' = w r, r' = -w s; a line as
 * (s, r) = sqrt(k_N) (u, u' / w_s), s' = w_s r, r' = 0, w_s the largest sqrt(K_ii / m_i).
 *
 * Books. The dampers take p^T G p, the motor gives k_N (u - x_N) u' = (a . z)(b . z), b
 * nonzero only on r (u' = b_r r). On a step, with E(t) = expm(A t),
 *
 *     D = z^T Gd z,   Gd = int_0^h E(t)^T Q E(t) dt,   Q = G on the p block,
 *     W = sum_{c = s, r} z_c (Nw_c . z),   Nw_c = b_r int_0^h E(t)^T a E_rc(t) dt,
 *
 * (row r of E(t) lives on the drive's columns). Both integrals come from a base interval
 * t = h / 2^j short enough that ||A|| t <= 1/2, by 6-point Gauss-Legendre (error about
 * (2 ||A|| t)^12 (6!)^4 / (13 (12!)^3), 2e-16 relative at 1/2), then doubled j times:
 *
 *     Gd(2t) = Gd(t) + E(t)^T Gd(t) E(t),   Nw(2t) = Nw(t) + E(t)^T Nw(t) R(t),
 *
 * R(t) the drive's 2x2 block of E(t). Every E(t) is GSL's exponential taken afresh:
 * squaring up from the base instead costs a digit or more (5e-13 against 2e-14 at
 * ||A h|| = 100, measured against quad precision).
 *
 * Cache. E(h), Gd and Nw depend on the model's values, the drive's form, w (sine) and h,
 * not on z: they are kept for the last few steps, so a run of equal steps costs one
 * matrix-vector product and one quadratic form, O((2N)^2). A step within 1e-8 / ||A|| of
 * a cached one (late in a run, b - a carries the rounding of the times) is taken as a
 * first-order step of the difference, then the cached one.
 *
 * All of the above is the dense path, for ground dampers not proportional to the masses
 * and the motor as the only input. With Rayleigh's damping, C = alpha M + beta K (the
 * default chain, undamped ones, dampers beside the springs in proportion to them), the
 * same method runs mode by mode on 4 x 4 matrices (exact_modal.c), the motor's end, its
 * damper and a force input all carried by each mode's drive states: contacts' step
 * lengths do not make it expensive, and the dense matrices are never made. Other spring
 * dampers, a force or a missing spring take exact_general.c's dense exponential. */
#include "exact.h"

#include <float.h>

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_blas.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_linalg.h>
#include <gsl/gsl_matrix.h>

#include "exact_general.h"
#include "exact_modal.h"

#define MAX_SLOTS 4                      /* cached steps, for small chains */
#define SLOT_BUDGET (32.0 * 1024 * 1024) /* bytes of cache beyond the first slot */
#define BASE_NORM 0.5                    /* ||A|| times the quadrature's base interval */

/* One cached step: everything that depends on (model, drive kind, w, h) but not on z. */
struct slot {
    struct exact_key key; /* which step it holds (first: exact_key_find reads it) */
    gsl_matrix prop;      /* E(h) */
    gsl_matrix gram;      /* Gd: the dampers' loss as a quadratic form */
    double *nw;           /* Nw_s then Nw_r (d each): the motor's work */
};

struct exact {
    int n, dmax, slots;
    double *saved; /* m (n), k (n+1), c (n), cs (n+1) as last seen */
    enum boundary boundary;
    int valid; /* the saved model factorised: 1, or 0 */
    unsigned long model, clock;
    double *sqm;        /* sqrt(m_i) */
    double *ld, *ls;    /* L's diagonal (n) and subdiagonal (n-1) */
    double *gam;        /* c_i / m_i */
    double sk, wscale;  /* sqrt(k_N); w_s, the line's slope scale */
    int damped;         /* some c_i > 0 */
    gsl_matrix s, x, t; /* generator, an exponential, product scratch */
    double *z, *z1, *y; /* state vectors (dmax), y also 2 dmax of scratch */
    double *mem;        /* the matrices' storage (not GSL's: its allocation aborts); NULL
                           until a model needs the dense exponential */
    struct slot slot[MAX_SLOTS];
    struct modal *md;   /* the modes' propagator (exact_modal.c) */
    struct general *gen; /* the general one (exact_general.c), made when first needed */
    int use_modal;      /* the saved model's dampers are proportional to its masses */
    int stepped_modal;  /* the last step went through the modes */
};

/* 6-point Gauss-Legendre on [-1, 1]: nodes +-gl_x[i], weights gl_w[i]. */
static const double gl_x[3] = {0.2386191860831969086305017, 0.6612093864662645136613996,
                               0.9324695142031520278123016};
static const double gl_w[3] = {0.4679139345726910473898703, 0.3607615730481386075698335,
                               0.1713244923791703450402961};

struct exact *exact_new(int n)
{
    if (n < 1 || n > MODEL_MAX_MASSES)
        return NULL;
    struct exact *e = calloc(1, sizeof *e);
    if (!e)
        return NULL;
    int d = 2 * n + 2;
    size_t dd = (size_t)d * (size_t)d;
    int slots = 1 + (int)fmin(MAX_SLOTS - 1, floor(SLOT_BUDGET / (2.0 * sizeof(double) * dd)));
    e->n = n;
    e->dmax = d;
    e->slots = slots;
    e->saved = malloc((size_t)(4 * n + 2) * sizeof(double));
    e->sqm = malloc((size_t)(4 * n) * sizeof(double));
    e->md = modal_new(n);
    if (!e->saved || !e->sqm || !e->md) {
        exact_free(e);
        return NULL;
    }
    e->ld = e->sqm + n;
    e->ls = e->ld + n;
    e->gam = e->ls + n;
    return e;
}

int exact_proportional(const struct model *m)
{
    double g0 = m->c[0] / m->m[0];
    for (int i = 1; i < m->n; i++)
        if (!(fabs(m->c[i] / m->m[i] - g0) <= 4.0 * DBL_EPSILON * g0))
            return 0;
    return 1;
}

int exact_in_modes(const struct model *m)
{
    return !exact_needs_general(m) &&
           (m->spring_damped || model_forced(m) ? model_rayleigh(m) : exact_proportional(m));
}

/* The dense exponential's matrices and vectors, made the first time a model needs them
 * (160 MB at n = 1000). 0, or -1 on no memory. */
static int dense_alloc(struct exact *e)
{
    if (e->mem)
        return 0;
    int d = e->dmax, slots = e->slots;
    size_t dd = (size_t)d * (size_t)d;
    e->z = malloc((size_t)(4 * d + 2 * d * slots) * sizeof(double));
    e->mem = malloc((size_t)(3 + 2 * slots) * dd * sizeof(double));
    if (!e->z || !e->mem) {
        free(e->z);
        free(e->mem);
        e->z = e->mem = NULL;
        return -1;
    }
    e->z1 = e->z + d;
    e->y = e->z1 + d;
    e->s = gsl_matrix_view_array(e->mem, (size_t)d, (size_t)d).matrix;
    e->x = gsl_matrix_view_array(e->mem + dd, (size_t)d, (size_t)d).matrix;
    e->t = gsl_matrix_view_array(e->mem + 2 * dd, (size_t)d, (size_t)d).matrix;
    for (int i = 0; i < slots; i++) {
        struct slot *sl = &e->slot[i];
        double *at = e->mem + (3 + 2 * (size_t)i) * dd;
        sl->prop = gsl_matrix_view_array(at, (size_t)d, (size_t)d).matrix;
        sl->gram = gsl_matrix_view_array(at + dd, (size_t)d, (size_t)d).matrix;
        sl->nw = e->y + 2 * d + 2 * (size_t)d * (size_t)i;
        sl->key.model = 0;
    }
    return 0;
}

void exact_free(struct exact *e)
{
    if (!e)
        return;
    modal_free(e->md);
    general_free(e->gen);
    free(e->mem);
    free(e->z);
    free(e->sqm);
    free(e->saved);
    free(e);
}

int exact_copy(struct exact *dst, const struct exact *src)
{
    int n = src->n, d = src->dmax, slots = src->slots;
    size_t dd = (size_t)d * (size_t)d;
    if (src->mem && dense_alloc(dst))
        return -1;
    memcpy(dst->saved, src->saved, (size_t)(4 * n + 2) * sizeof(double));
    memcpy(dst->sqm, src->sqm, (size_t)(4 * n) * sizeof(double));
    if (src->mem) {
        memcpy(dst->z, src->z, (size_t)(4 * d + 2 * d * slots) * sizeof(double));
        memcpy(dst->mem, src->mem, (size_t)(3 + 2 * slots) * dd * sizeof(double));
    }
    modal_copy(dst->md, src->md);
    if (src->gen && !dst->gen && !(dst->gen = general_new(n)))
        return -1;
    if (src->gen && general_copy(dst->gen, src->gen) != 0)
        return -1;
    dst->use_modal = src->use_modal;
    dst->stepped_modal = src->stepped_modal;
    dst->boundary = src->boundary;
    dst->valid = src->valid;
    dst->model = src->model;
    dst->clock = src->clock;
    dst->sk = src->sk;
    dst->wscale = src->wscale;
    dst->damped = src->damped;
    exact_key_copy(dst->slot, src->slot, sizeof src->slot[0], slots, src->mem != NULL);
    return 0;
}

/* Takes in model m if it differs from the one seen last: a new generation (every cached
 * step is stale) and the coordinates' factor L. */
static void take_model(struct exact *e, const struct model *m)
{
    int n = e->n;
    double *sv = e->saved;
    if (e->model && m->boundary == e->boundary && memcmp(sv, m->m, (size_t)n * sizeof *sv) == 0 &&
        memcmp(sv + n, m->k, (size_t)(n + 1) * sizeof *sv) == 0 &&
        memcmp(sv + 2 * n + 1, m->c, (size_t)n * sizeof *sv) == 0 &&
        memcmp(sv + 3 * n + 1, m->cs, (size_t)(n + 1) * sizeof *sv) == 0)
        return;
    memcpy(sv, m->m, (size_t)n * sizeof *sv);
    memcpy(sv + n, m->k, (size_t)(n + 1) * sizeof *sv);
    memcpy(sv + 2 * n + 1, m->c, (size_t)n * sizeof *sv);
    memcpy(sv + 3 * n + 1, m->cs, (size_t)(n + 1) * sizeof *sv);
    e->boundary = m->boundary;
    e->model++;
    e->valid = 0;

    /* M^(-1/2) K M^(-1/2) = C C^T, C lower bidiagonal (diagonal ld, subdiagonal ls), from
     * K = L D L^T taken as the chain's springs in series: eliminating masses 1..i leaves
     * s_i, the springs 0..i in series, tying mass i+1 to the wall, so the pivots are
     * d_i = s_i + k_(i+1) (k_N dropped for a free end) and s_(i+1) = s_i k_(i+1) / d_i,
     * sums and products of positive numbers: every entry of C to a few ulp however soft
     * the chain's slowest mode (dpttrf on the assembled matrix subtracts, and at a spring
     * ratio of 1e17 fails). C's entries: ld_i = sqrt(d_i / m_i) and
     * ls_i = -k_(i+1) / sqrt(d_i m_(i+1)). */
    double series = 0.0, wmax = 0.0;
    e->damped = 0;
    for (int i = 0; i < n; i++) {
        if (!(m->m[i] > 0.0) || !(m->k[i] > 0.0) || !(m->c[i] >= 0.0) || !isfinite(m->m[i]) ||
            !isfinite(m->k[i]) || !isfinite(m->c[i]))
            return;
        double kd = m->k[i];
        if (i < n - 1 || m->boundary != BOUNDARY_FREE)
            kd += m->k[i + 1];
        e->sqm[i] = sqrt(m->m[i]);
        if (!isfinite(kd / m->m[i]))
            return;
        /* sqrt(k) / sqrt(m), not sqrt(k / m): at m = 1e200, k = 1e-200 the quotient
         * underflows, its root does not. */
        wmax = fmax(wmax, sqrt(kd) / e->sqm[i]);
        e->gam[i] = m->c[i] / m->m[i];
        e->damped |= m->c[i] > 0.0;
    }
    if (m->boundary != BOUNDARY_FREE && (!(m->k[n] > 0.0) || !isfinite(m->k[n])))
        return;
    if (!isfinite(wmax))
        return;
    series = m->k[0];
    for (int i = 0; i < n; i++) {
        double next = i < n - 1 || m->boundary != BOUNDARY_FREE ? m->k[i + 1] : 0.0;
        double d = series + next;
        e->ld[i] = sqrt(d) / e->sqm[i];
        if (i < n - 1) {
            e->ls[i] = -m->k[i + 1] / (sqrt(d) * e->sqm[i + 1]);
            series *= m->k[i + 1] / d;
        }
        if (!(e->ld[i] > 0.0) || !isfinite(e->ld[i]) || (i < n - 1 && !isfinite(e->ls[i])))
            return;
    }
    e->sk = m->boundary == BOUNDARY_FREE ? 0.0 : sqrt(m->k[n]);
    e->wscale = wmax;
    /* Dampers proportional to the masses (to rounding) keep the modes apart: the modes'
     * propagator. Otherwise, or if LAPACK fails there, the dense exponential. */
    double beta = 0.0;
    for (int j = 0; j <= n && m->spring_damped; j++)
        if (m->cs[j] != 0.0 && (j < n || m->boundary != BOUNDARY_FREE)) {
            beta = m->cs[j] / m->k[j];
            break;
        }
    e->use_modal = (m->spring_damped ? model_rayleigh(m) : exact_proportional(m)) &&
                   modal_take(e->md, m, e->gam[0], beta, e->ld, e->ls) == 0;
    /* The dense path here knows ground dampers only: spring dampers not in the modes are
     * exact_general's (exact_advance_all goes there) */
    e->valid = e->use_modal || (!m->spring_damped && dense_alloc(e) == 0);
}

/* tau A into s (d x d), A the generator for drive kind and angular frequency omega;
 * returns ||tau A||, the larger of its 1- and infinity-norms (so above its spectral radius
 * and its 2-norm). */
static double generator(const struct exact *e, enum exact_kind kind, double omega, double tau,
                        gsl_matrix *s)
{
    int n = e->n;
    gsl_matrix_set_zero(s);
    for (int i = 0; i < n; i++) {
        gsl_matrix_set(s, i, n + i, tau * e->ld[i]);
        gsl_matrix_set(s, n + i, i, -tau * e->ld[i]);
        gsl_matrix_set(s, n + i, n + i, -tau * e->gam[i]);
        if (i < n - 1) {
            gsl_matrix_set(s, i, n + i + 1, tau * e->ls[i]);
            gsl_matrix_set(s, n + i + 1, i, -tau * e->ls[i]);
        }
    }
    if (kind != EXACT_NONE) {
        gsl_matrix_set(s, 2 * n - 1, 2 * n, tau * e->sk / e->sqm[n - 1]);
        if (kind == EXACT_SINE) {
            gsl_matrix_set(s, 2 * n, 2 * n + 1, tau * omega);
            gsl_matrix_set(s, 2 * n + 1, 2 * n, -tau * omega);
        } else {
            gsl_matrix_set(s, 2 * n, 2 * n + 1, tau * e->wscale);
        }
    }
    double norm = 0.0;
    for (size_t i = 0; i < s->size1; i++) {
        double row = 0.0, col = 0.0;
        for (size_t j = 0; j < s->size2; j++) {
            row += fabs(gsl_matrix_get(s, i, j));
            col += fabs(gsl_matrix_get(s, j, i));
        }
        norm = fmax(norm, fmax(row, col));
    }
    return norm;
}

/* A z into out (dim entries), from the generator's nonzeros. */
static void generator_apply(const struct exact *e, enum exact_kind kind, double omega,
                            const double *z, double *out)
{
    int n = e->n;
    for (int i = 0; i < n; i++) {
        out[i] = e->ld[i] * z[n + i] + (i < n - 1 ? e->ls[i] * z[n + i + 1] : 0.0);
        out[n + i] =
            -e->ld[i] * z[i] - (i > 0 ? e->ls[i - 1] * z[i - 1] : 0.0) - e->gam[i] * z[n + i];
    }
    if (kind != EXACT_NONE) {
        out[2 * n - 1] += e->sk / e->sqm[n - 1] * z[2 * n];
        out[2 * n] = (kind == EXACT_SINE ? omega : e->wscale) * z[2 * n + 1];
        out[2 * n + 1] = kind == EXACT_SINE ? -omega * z[2 * n] : 0.0;
    }
}

/* The motor's power k_N (u - x_N) u' as (ax q_N + as s) br r: x_N = q_N / (L_NN sqrt(m_N)),
 * k_N u = sqrt(k_N) s, and u' = w r / sqrt(k_N) for a sine, w_s r / sqrt(k_N) for a line. */
static void motor_power(const struct exact *e, enum exact_kind kind, double omega, double *ax,
                        double *as, double *br)
{
    int n = e->n;
    *ax = -e->sk * e->sk / (e->ld[n - 1] * e->sqm[n - 1]);
    *as = e->sk;
    *br = (kind == EXACT_SINE ? omega : e->wscale) / e->sk;
}

/* The d x d leading block of a workspace matrix. */
static gsl_matrix_view lead(gsl_matrix *a, int d)
{
    return gsl_matrix_submatrix(a, 0, 0, (size_t)d, (size_t)d);
}

/* Fills slot sl for a step h: E(h), Gd and Nw (see the top of the file). */
static int fill_slot(struct exact *e, struct slot *sl, enum exact_kind kind, double omega, double h,
                     int d)
{
    int n = e->n;
    gsl_matrix_view sv = lead(&e->s, d), xv = lead(&e->x, d), tv = lead(&e->t, d);
    gsl_matrix_view gv = lead(&sl->gram, d), pv = lead(&sl->prop, d);
    gsl_matrix *s = &sv.matrix, *x = &xv.matrix, *t = &tv.matrix, *g = &gv.matrix;
    double *nw = sl->nw, *y = e->y;
    int r = 2 * n + 1, driven = kind != EXACT_NONE;

    double norm = generator(e, kind, omega, 1.0, s);
    int levels = 0;
    while (norm * ldexp(h, -levels) > BASE_NORM && levels < 1000)
        levels++;
    double base = ldexp(h, -levels);

    double a_x = 0.0, a_s = 0.0, b_r = 0.0;
    if (driven)
        motor_power(e, kind, omega, &a_x, &a_s, &b_r);

    gsl_matrix_set_zero(g);
    memset(nw, 0, (size_t)(2 * d) * sizeof *nw);
    for (int i = 0; i < 6; i++) {
        double node = 0.5 * base * (1.0 + (i < 3 ? -gl_x[i] : gl_x[i - 3]));
        double w = 0.5 * base * gl_w[i % 3];
        generator(e, kind, omega, node, s);
        if (exact_expm(s, x, t))
            return -1;
        if (e->damped) {
            /* Gd += w F^T F, F = G^(1/2) (p rows of E) */
            gsl_matrix_view f = gsl_matrix_submatrix(&e->t, 0, 0, (size_t)n, (size_t)d);
            for (int k = 0; k < n; k++) {
                double sg = sqrt(e->gam[k]);
                for (int j = 0; j < d; j++)
                    gsl_matrix_set(&f.matrix, k, j, sg * gsl_matrix_get(x, n + k, j));
            }
            gsl_blas_dsyrk(CblasLower, CblasTrans, w, &f.matrix, 1.0, g);
        }
        if (driven) {
            /* Nw_c += w b_r E^T a E_rc */
            for (int j = 0; j < d; j++)
                y[j] = a_x * gsl_matrix_get(x, n - 1, j) + a_s * gsl_matrix_get(x, 2 * n, j);
            for (int c = 0; c < 2; c++) {
                double f = w * b_r * gsl_matrix_get(x, r, 2 * n + c);
                for (int j = 0; j < d; j++)
                    nw[c * d + j] += f * y[j];
            }
        }
    }
    for (int i = 0; i < d; i++)
        for (int j = i + 1; j < d; j++)
            gsl_matrix_set(g, i, j, gsl_matrix_get(g, j, i));

    for (int level = 0; level < levels; level++) {
        generator(e, kind, omega, ldexp(base, level), s);
        if (exact_expm(s, x, t))
            return -1;
        if (e->damped) {
            gsl_blas_dgemm(CblasNoTrans, CblasNoTrans, 1.0, g, x, 0.0, t);
            gsl_blas_dgemm(CblasTrans, CblasNoTrans, 1.0, x, t, 1.0, g);
        }
        if (driven) {
            /* Nw += E^T (Nw R), R the drive's block of E */
            double r00 = gsl_matrix_get(x, 2 * n, 2 * n), r01 = gsl_matrix_get(x, 2 * n, r);
            double r10 = gsl_matrix_get(x, r, 2 * n), r11 = gsl_matrix_get(x, r, r);
            for (int j = 0; j < d; j++) {
                y[j] = nw[j] * r00 + nw[d + j] * r10;
                y[d + j] = nw[j] * r01 + nw[d + j] * r11;
            }
            for (int c = 0; c < 2; c++) {
                gsl_vector_view yv = gsl_vector_view_array(y + c * d, (size_t)d);
                gsl_vector_view nv = gsl_vector_view_array(nw + c * d, (size_t)d);
                gsl_blas_dgemv(CblasTrans, 1.0, x, &yv.vector, 1.0, &nv.vector);
            }
        }
    }

    generator(e, kind, omega, h, s);
    if (exact_expm(s, &pv.matrix, t))
        return -1;
    sl->key = (struct exact_key){e->model, kind, omega, h, norm, sl->key.used};
    return 0;
}

/* The cached step for (kind, omega, h), filled if need be; NULL when that fails. */
static struct slot *find_slot(struct exact *e, enum exact_kind kind, double omega, double h, int d)
{
    int fresh, i = exact_key_find(e->slot, sizeof e->slot[0], e->slots, &e->clock, e->model,
                                  kind, omega, h, &fresh);
    return fresh && fill_slot(e, &e->slot[i], kind, omega, h, d) ? NULL : &e->slot[i];
}

int exact_stepped_in_modes(const struct exact *e)
{
    return e->stepped_modal;
}

int exact_advance(struct exact *e, const struct model *m, const struct exact_drive *d, double a,
                  double b, double *x, double *v, double *diss, double *work)
{
    double fwork = 0.0;
    return exact_advance_all(e, m, d, a, b, x, v, diss, work, &fwork);
}

/* The dense step of h from a (exact_advance_all's, the chain's own coordinates z = (L^T
 * M^(1/2) x, M^(1/2) v, the drive's two)): through the cached E(h) and its books. */
static int dense_advance(struct exact *e, enum exact_kind kind, const struct exact_drive *d,
                         double a, double h, double *x, double *v, double *diss, double *work)
{
    int n = e->n, dim = kind == EXACT_NONE ? 2 * n : 2 * n + 2;
    double omega = kind == EXACT_SINE ? d->omega : 0.0;
    struct slot *sl = find_slot(e, kind, omega, h, dim);
    if (!sl)
        return -1;

    /* z(a) */
    double *z = e->z, *z1 = e->z1, *y = e->y;
    for (int i = 0; i < n; i++) {
        double q = e->sqm[i] * x[i];
        z[i] = e->ld[i] * q + (i < n - 1 ? e->ls[i] * e->sqm[i + 1] * x[i + 1] : 0.0);
        z[n + i] = e->sqm[i] * v[i];
    }
    if (kind == EXACT_SINE) {
        double th = d->omega * a + d->phi;
        z[2 * n] = e->sk * d->amp * sin(th);
        z[2 * n + 1] = e->sk * d->amp * cos(th);
    } else if (kind == EXACT_LINE) {
        z[2 * n] = e->sk * (d->u0 + d->du * (a - d->t0));
        z[2 * n + 1] = e->sk * d->du / e->wscale;
    }

    /* A step a little longer or shorter than the cached one: the difference first, as
     * z + delta A z (error (delta ||A||)^2 / 2 <= 5e-17) and its books as delta times the
     * powers at z. */
    double dd = 0.0, ww = 0.0, delta = h - sl->key.h;
    if (delta != 0.0) {
        for (int i = 0; i < n; i++)
            dd += delta * e->gam[i] * z[n + i] * z[n + i];
        if (kind != EXACT_NONE) {
            double ax, as, br;
            motor_power(e, kind, omega, &ax, &as, &br);
            ww += delta * (ax * z[n - 1] + as * z[2 * n]) * br * z[2 * n + 1];
        }
        generator_apply(e, kind, omega, z, y);
        for (int j = 0; j < dim; j++)
            z[j] += delta * y[j];
    }

    gsl_vector_view zv = gsl_vector_view_array(z, (size_t)dim);
    gsl_vector_view z1v = gsl_vector_view_array(z1, (size_t)dim);
    gsl_vector_view yv = gsl_vector_view_array(y, (size_t)dim);
    gsl_matrix_view pv = lead(&sl->prop, dim), gv = lead(&sl->gram, dim);
    gsl_blas_dgemv(CblasNoTrans, 1.0, &pv.matrix, &zv.vector, 0.0, &z1v.vector);
    if (e->damped) {
        double q;
        gsl_blas_dsymv(CblasLower, 1.0, &gv.matrix, &zv.vector, 0.0, &yv.vector);
        gsl_blas_ddot(&zv.vector, &yv.vector, &q);
        dd += q;
    }
    if (kind != EXACT_NONE) {
        for (int c = 0; c < 2; c++) {
            double s = 0.0;
            for (int j = 0; j < dim; j++)
                s += sl->nw[c * dim + j] * z[j];
            ww += z[2 * n + c] * s;
        }
    }
    for (int j = 0; j < dim; j++)
        if (!isfinite(z1[j]))
            return -1;
    if (!isfinite(dd) || !isfinite(ww))
        return -1;

    /* x from q = L^T M^(1/2) x: back-substitution on the upper bidiagonal L^T */
    double next = 0.0;
    for (int i = n - 1; i >= 0; i--) {
        double q = (z1[i] - (i < n - 1 ? e->ls[i] * next : 0.0)) / e->ld[i];
        next = q;
        x[i] = q / e->sqm[i];
        v[i] = z1[n + i] / e->sqm[i];
    }
    *diss += dd;
    *work += ww;
    return 0;
}

int exact_advance_all(struct exact *e, const struct model *m, const struct exact_drive *d,
                      double a, double b, double *x, double *v, double *diss, double *work,
                      double *fwork)
{
    double h = b - a;
    if (h == 0.0)
        return 0;
    if (!(h > 0.0) || m->n != e->n)
        return -1;
    int forced = model_forced(m) || (d && d->force != 0.0);
    int general = exact_needs_general(m) || (forced && !model_rayleigh(m));
    if (!general) {
        take_model(e, m);
        /* the modes failed: the general path for what the dense one here cannot hold */
        general = !e->use_modal && (m->spring_damped || forced);
    }
    if (general) {
        e->stepped_modal = 0;
        if (!e->gen && !(e->gen = general_new(e->n)))
            return -1;
        return general_advance(e->gen, m, d, a, b, x, v, diss, work, fwork);
    }
    if (!e->valid)
        return -1;

    /* The end moves with a motor only; the force is the modes' alone (forced chains that
     * reach here are stepped in them). */
    struct exact_drive ed = d ? *d : (struct exact_drive){0};
    if (m->boundary != BOUNDARY_MOTOR)
        ed.amp = ed.u0 = ed.du = 0.0;
    enum exact_kind kind = exact_drive_kind(&ed);
    if (kind == EXACT_SINE && !isfinite(ed.omega))
        return -1;
    e->stepped_modal = e->use_modal;
    if (e->use_modal)
        return modal_advance(e->md, kind, &ed, m->force_on, a, b, x, v, diss, work, fwork);
    return dense_advance(e, kind, &ed, a, h, x, v, diss, work);
}
