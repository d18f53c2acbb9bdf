/* exact_general.c: the exact step for any linear chain, z(b) = expm(A h) z(a), h = b - a,
 * in the chain's own coordinates, for what exact.c's factored coordinates cannot hold:
 * spring dampers (C tridiagonal), a force input, springs of k = 0 (K singular).
 *
 * Coordinates. With w_s = sqrt(max K_ii / m_i) (1 when every spring is 0),
 *
 *     q = w_s M^(1/2) x,   p = M^(1/2) v,
 *     q' = w_s p,   p' = -M^(-1/2) K M^(-1/2) q / w_s - M^(-1/2) C M^(-1/2) p + M^(-1/2) f,
 *
 * every entry of A near the chain's frequencies and rates. f is the input: the motor end's
 * spring and damper on the last mass, k_N u + cs_N u', and the force F w on mass K, both
 * from the waveform's two states beside the chain, at amplitude 1: a sine as
 * (s, r) = (sin, cos) of its angle, s' = w r, r' = -w s; a line as (s, r) = (w, w' / w_s),
 * s' = w_s r, r' = 0. So u = A s, u' = A W r (W = w or w_s) and the force is F s.
 *
 * Books. Each is a rate that is a quadratic form z^T Q z: the dampers' loss
 * sum c_i v_i^2 + sum cs_j (stretch_j')^2, the motor's power T_N u' (T_N the end spring's
 * and damper's tension), the force's power F s v_K. Over a step,
 *
 *     B = int_0^h E(t)^T Q E(t) dt,   E(t) = expm(A t),
 *
 * from a base interval t = h / 2^j with ||A|| t <= 1/2 by 6-point Gauss-Legendre, then
 * doubled j times, B(2t) = B(t) + E(t)^T B(t) E(t) (as exact.c does for its books).
 *
 * Cache: E(h) and the three B depend on the model, the drive's form, w and h, not on z; the
 * last few steps are kept, and a step within 1e-8 / ||A|| of one is that one after a
 * first-order step of the difference. */
#include "exact_general.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_blas.h>
#include <gsl/gsl_matrix.h>

#include "exact_modal.h"

#define SLOTS_MAX 4
#define SLOT_BUDGET (32.0 * 1024 * 1024) /* bytes of cache beyond the first slot */
#define BASE_NORM 0.5
enum { BOOK_D, BOOK_W, BOOK_F, BOOKS };

struct gslot {
    struct exact_key key;    /* which step it holds (first: exact_key_find reads it) */
    gsl_matrix prop;         /* E(h) */
    gsl_matrix book[BOOKS];  /* B for each book */
};

struct general {
    int n, dmax, slots;
    double *saved;            /* the parameters last taken (SIG(n) doubles) */
    unsigned long model, clock;
    int valid;                /* the saved parameters are usable */
    double ws, amp, force;    /* w_s; the end's amplitude (0 unless a motor); F */
    int force_on;
    enum boundary boundary;
    double *sqm, *kd, *ko, *cd, *co; /* sqrt(m); K and C: diagonals (n), off-diagonals */
    gsl_matrix s, x, t;       /* generator, exponential, scratch */
    gsl_matrix q[BOOKS];      /* the books' rates */
    double *z, *z1, *y;       /* dmax each */
    double *mem;              /* the matrices, NULL until first stepped */
    struct gslot slot[SLOTS_MAX];
};

/* m, k, c, cs, then boundary, amplitude, force, force_on. */
#define SIG(n) (4 * (n) + 6)

static const double gl_x[3] = {0.2386191860831969086305017, 0.6612093864662645136613996,
                               0.9324695142031520278123016};
static const double gl_w[3] = {0.4679139345726910473898703, 0.3607615730481386075698335,
                               0.1713244923791703450402961};

struct general *general_new(int n)
{
    struct general *g = calloc(1, sizeof *g);
    if (!g)
        return NULL;
    int d = 2 * n + 2;
    double dd = (double)d * d;
    g->n = n;
    g->dmax = d;
    g->slots = 1 + (int)fmin(SLOTS_MAX - 1, floor(SLOT_BUDGET / ((BOOKS + 1) * 8.0 * dd)));
    g->saved = calloc((size_t)SIG(n) + (size_t)(5 * n), sizeof(double));
    if (!g->saved) {
        free(g);
        return NULL;
    }
    g->sqm = g->saved + SIG(n);
    g->kd = g->sqm + n;
    g->ko = g->kd + n;
    g->cd = g->ko + n;
    g->co = g->cd + n;
    return g;
}

void general_free(struct general *g)
{
    if (!g)
        return;
    free(g->mem);
    free(g->z);
    free(g->saved);
    free(g);
}

static size_t mem_doubles(const struct general *g)
{
    size_t dd = (size_t)g->dmax * (size_t)g->dmax;
    return (3 + BOOKS + (size_t)g->slots * (1 + BOOKS)) * dd;
}

static int alloc_mem(struct general *g)
{
    if (g->mem)
        return 0;
    size_t d = (size_t)g->dmax, dd = d * d;
    g->z = malloc(3 * d * sizeof(double));
    g->mem = calloc(mem_doubles(g), sizeof(double));
    if (!g->z || !g->mem) {
        free(g->z);
        free(g->mem);
        g->z = g->mem = NULL;
        return -1;
    }
    g->z1 = g->z + d;
    g->y = g->z1 + d;
    double *at = g->mem;
    gsl_matrix *fixed[3 + BOOKS] = {&g->s, &g->x, &g->t, &g->q[0], &g->q[1], &g->q[2]};
    for (int i = 0; i < 3 + BOOKS; i++, at += dd)
        *fixed[i] = gsl_matrix_view_array(at, d, d).matrix;
    for (int i = 0; i < g->slots; i++) {
        struct gslot *sl = &g->slot[i];
        sl->prop = gsl_matrix_view_array(at, d, d).matrix;
        at += dd;
        for (int b = 0; b < BOOKS; b++, at += dd)
            sl->book[b] = gsl_matrix_view_array(at, d, d).matrix;
        sl->key.model = 0;
    }
    return 0;
}

int general_copy(struct general *dst, const struct general *src)
{
    int n = src->n;
    if (src->mem && alloc_mem(dst))
        return -1;
    memcpy(dst->saved, src->saved, ((size_t)SIG(n) + (size_t)(5 * n)) * sizeof(double));
    if (src->mem) {
        memcpy(dst->mem, src->mem, mem_doubles(src) * sizeof(double));
        memcpy(dst->z, src->z, 3 * (size_t)src->dmax * sizeof(double));
    }
    dst->model = src->model, dst->clock = src->clock, dst->valid = src->valid;
    dst->ws = src->ws, dst->amp = src->amp, dst->force = src->force;
    dst->force_on = src->force_on, dst->boundary = src->boundary;
    exact_key_copy(dst->slot, src->slot, sizeof src->slot[0], src->slots, src->mem != NULL);
    return 0;
}

/* Takes model m if its parameters differ from the last: K, C, w_s, a new generation. */
static void take_model(struct general *g, const struct model *m)
{
    int n = g->n;
    double sig[6] = {(double)m->boundary, m->boundary == BOUNDARY_MOTOR ? m->motor.amplitude : 0.0,
                     m->force, (double)m->force_on, 0.0, 0.0};
    double *sv = g->saved;
    if (g->model && memcmp(sv, m->m, (size_t)n * sizeof *sv) == 0 &&
        memcmp(sv + n, m->k, (size_t)(n + 1) * sizeof *sv) == 0 &&
        memcmp(sv + 2 * n + 1, m->c, (size_t)n * sizeof *sv) == 0 &&
        memcmp(sv + 3 * n + 1, m->cs, (size_t)(n + 1) * sizeof *sv) == 0 &&
        memcmp(sv + 4 * n + 2, sig, 4 * sizeof *sv) == 0)
        return;
    memcpy(sv, m->m, (size_t)n * sizeof *sv);
    memcpy(sv + n, m->k, (size_t)(n + 1) * sizeof *sv);
    memcpy(sv + 2 * n + 1, m->c, (size_t)n * sizeof *sv);
    memcpy(sv + 3 * n + 1, m->cs, (size_t)(n + 1) * sizeof *sv);
    memcpy(sv + 4 * n + 2, sig, 4 * sizeof *sv);
    g->model++;
    g->valid = 0;
    g->boundary = m->boundary;
    g->amp = sig[1];
    g->force = m->force;
    g->force_on = m->force_on;
    if (!isfinite(g->amp) || !isfinite(g->force) || m->force_on < 0 || m->force_on >= n)
        return;
    double wmax = 0.0;
    for (int i = 0; i < n; i++) {
        bool right = i < n - 1 || m->boundary != BOUNDARY_FREE;
        double kr = right ? m->k[i + 1] : 0.0, cr = right ? m->cs[i + 1] : 0.0;
        if (!(m->m[i] > 0.0) || !(m->k[i] >= 0.0) || !(kr >= 0.0) || !(m->c[i] >= 0.0) ||
            !(m->cs[i] >= 0.0) || !(cr >= 0.0) || !isfinite(m->m[i] + m->k[i] + kr + m->c[i] +
                                                               m->cs[i] + cr))
            return;
        g->sqm[i] = sqrt(m->m[i]);
        g->kd[i] = m->k[i] + kr;
        g->cd[i] = m->c[i] + m->cs[i] + cr;
        if (i < n - 1) {
            g->ko[i] = -m->k[i + 1];
            g->co[i] = -m->cs[i + 1];
        }
        wmax = fmax(wmax, g->kd[i] / m->m[i]);
    }
    g->ws = wmax > 0.0 ? sqrt(wmax) : 1.0;
    g->valid = isfinite(g->ws) && alloc_mem(g) == 0;
}

/* W: u' = A W r. */
static double rate_scale(const struct general *g, enum exact_kind kind, double omega)
{
    return kind == EXACT_SINE ? omega : g->ws;
}

/* tau A into s (dim x dim); returns ||A|| (the larger of its 1- and infinity-norms). */
static double generator(const struct general *g, enum exact_kind kind, double omega, double tau,
                        gsl_matrix *s)
{
    int n = g->n, sd = 2 * n, rd = 2 * n + 1;
    const double *sq = g->sqm;
    gsl_matrix_set_zero(s);
    for (int i = 0; i < n; i++) {
        gsl_matrix_set(s, i, n + i, tau * g->ws);
        gsl_matrix_set(s, n + i, i, -tau * g->kd[i] / (sq[i] * sq[i] * g->ws));
        gsl_matrix_set(s, n + i, n + i, -tau * g->cd[i] / (sq[i] * sq[i]));
        if (i < n - 1) {
            double kk = -tau * g->ko[i] / (sq[i] * sq[i + 1] * g->ws);
            double cc = -tau * g->co[i] / (sq[i] * sq[i + 1]);
            gsl_matrix_set(s, n + i, i + 1, kk);
            gsl_matrix_set(s, n + i + 1, i, kk);
            gsl_matrix_set(s, n + i, n + i + 1, cc);
            gsl_matrix_set(s, n + i + 1, n + i, cc);
        }
    }
    if (kind != EXACT_NONE) {
        double kn = g->boundary == BOUNDARY_FREE ? 0.0 : g->saved[2 * n];
        double csn = g->boundary == BOUNDARY_FREE ? 0.0 : g->saved[4 * n + 1];
        double w = rate_scale(g, kind, omega);
        *gsl_matrix_ptr(s, 2 * n - 1, sd) += tau * g->amp * kn / sq[n - 1];
        *gsl_matrix_ptr(s, 2 * n - 1, rd) += tau * g->amp * csn * w / sq[n - 1];
        *gsl_matrix_ptr(s, n + g->force_on, sd) += tau * g->force / sq[g->force_on];
        gsl_matrix_set(s, sd, rd, tau * w);
        if (kind == EXACT_SINE)
            gsl_matrix_set(s, rd, sd, -tau * omega);
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
    return norm / fabs(tau);
}

/* q += coef (a b^T + b a^T) / 2 for sparse a, b (na, nb entries at ia, ib). */
static void add_outer(gsl_matrix *q, double coef, const int *ia, const double *a, int na,
                      const int *ib, const double *b, int nb)
{
    for (int i = 0; i < na; i++)
        for (int j = 0; j < nb; j++) {
            double v = 0.5 * coef * a[i] * b[j];
            *gsl_matrix_ptr(q, (size_t)ia[i], (size_t)ib[j]) += v;
            *gsl_matrix_ptr(q, (size_t)ib[j], (size_t)ia[i]) += v;
        }
}

/* The books' rates as quadratic forms for drive kind (q[b], dim x dim). */
static void book_forms(struct general *g, enum exact_kind kind, double omega, int dim,
                       gsl_matrix *q)
{
    int n = g->n, driven = kind != EXACT_NONE;
    const double *sq = g->sqm, *c = g->saved + 2 * n + 1, *cs = g->saved + 3 * n + 1;
    double w = rate_scale(g, kind, omega), au = driven ? g->amp * w : 0.0;
    for (int b = 0; b < BOOKS; b++)
        gsl_matrix_set_zero(&q[b]);
    for (int i = 0; i < n; i++)
        *gsl_matrix_ptr(&q[BOOK_D], (size_t)(n + i), (size_t)(n + i)) += c[i] / (sq[i] * sq[i]);
    /* spring j's stretch rate: v_j - v_(j-1), the walls' and the end's included */
    for (int j = 0; j <= n; j++) {
        if (j == n && g->boundary == BOUNDARY_FREE)
            break;
        int ix[3], k = 0;
        double a[3];
        if (j < n)
            ix[k] = n + j, a[k++] = 1.0 / sq[j];
        if (j > 0)
            ix[k] = n + j - 1, a[k++] = -1.0 / sq[j - 1];
        if (j == n && au != 0.0)
            ix[k] = 2 * n + 1, a[k++] = au;
        if (cs[j] != 0.0)
            add_outer(&q[BOOK_D], cs[j], ix, a, k, ix, a, k);
    }
    if (driven && g->boundary == BOUNDARY_MOTOR && g->amp != 0.0) {
        double kn = g->saved[2 * n], csn = cs[n];
        int it[4] = {2 * n, n - 1, 2 * n + 1, 2 * n - 1}, ir[1] = {2 * n + 1};
        double tn[4] = {kn * g->amp, -kn / (g->ws * sq[n - 1]), csn * au, -csn / sq[n - 1]};
        double rr[1] = {au};
        add_outer(&q[BOOK_W], 1.0, it, tn, 4, ir, rr, 1);
    }
    if (driven && g->force != 0.0) {
        int is[1] = {2 * n}, iv[1] = {n + g->force_on};
        double fs[1] = {g->force}, vv[1] = {1.0 / sq[g->force_on]};
        add_outer(&q[BOOK_F], 1.0, is, fs, 1, iv, vv, 1);
    }
    (void)dim;
}

static gsl_matrix_view lead(gsl_matrix *a, int d)
{
    return gsl_matrix_submatrix(a, 0, 0, (size_t)d, (size_t)d);
}

/* Fills slot sl for a step h: E(h) and each book's B. */
static int fill_slot(struct general *g, struct gslot *sl, enum exact_kind kind, double omega,
                     double h, int d)
{
    gsl_matrix_view sv = lead(&g->s, d), xv = lead(&g->x, d), tv = lead(&g->t, d);
    gsl_matrix *s = &sv.matrix, *x = &xv.matrix, *t = &tv.matrix;
    gsl_matrix_view qv[BOOKS], bv[BOOKS];
    gsl_matrix q[BOOKS];
    for (int b = 0; b < BOOKS; b++) {
        qv[b] = lead(&g->q[b], d);
        bv[b] = lead(&sl->book[b], d);
        q[b] = qv[b].matrix;
        gsl_matrix_set_zero(&bv[b].matrix);
    }
    book_forms(g, kind, omega, d, q);
    double norm = generator(g, kind, omega, 1.0, s);
    int levels = 0;
    while (norm * ldexp(h, -levels) > BASE_NORM && levels < 1000)
        levels++;
    double base = ldexp(h, -levels);
    for (int i = 0; i < 6; i++) {
        double node = 0.5 * base * (1.0 + (i < 3 ? -gl_x[i] : gl_x[i - 3]));
        double w = 0.5 * base * gl_w[i % 3];
        generator(g, kind, omega, node, s);
        if (exact_expm(s, x, t))
            return -1;
        for (int b = 0; b < BOOKS; b++) {
            gsl_blas_dgemm(CblasNoTrans, CblasNoTrans, 1.0, &q[b], x, 0.0, t);
            gsl_blas_dgemm(CblasTrans, CblasNoTrans, w, x, t, 1.0, &bv[b].matrix);
        }
    }
    for (int level = 0; level < levels; level++) {
        generator(g, kind, omega, ldexp(base, level), s);
        if (exact_expm(s, x, t))
            return -1;
        for (int b = 0; b < BOOKS; b++) {
            gsl_blas_dgemm(CblasNoTrans, CblasNoTrans, 1.0, &bv[b].matrix, x, 0.0, t);
            gsl_blas_dgemm(CblasTrans, CblasNoTrans, 1.0, x, t, 1.0, &bv[b].matrix);
        }
    }
    gsl_matrix_view pv = lead(&sl->prop, d);
    generator(g, kind, omega, h, s);
    if (exact_expm(s, &pv.matrix, t))
        return -1;
    sl->key = (struct exact_key){g->model, kind, omega, h, norm, sl->key.used};
    return 0;
}

/* The cached step for (kind, omega, h), filled if need be; NULL when that fails. */
static struct gslot *find_slot(struct general *g, enum exact_kind kind, double omega, double h,
                               int d)
{
    int fresh, i = exact_key_find(g->slot, sizeof g->slot[0], g->slots, &g->clock, g->model,
                                  kind, omega, h, &fresh);
    return fresh && fill_slot(g, &g->slot[i], kind, omega, h, d) ? NULL : &g->slot[i];
}

/* z^T B z for the d x d leading block of b (y: d of scratch). */
static double quad(gsl_matrix *b, const double *z, double *y, int d)
{
    gsl_matrix_view bv = lead(b, d);
    gsl_vector_const_view zv = gsl_vector_const_view_array(z, (size_t)d);
    gsl_vector_view yv = gsl_vector_view_array(y, (size_t)d);
    double r;
    gsl_blas_dgemv(CblasNoTrans, 1.0, &bv.matrix, &zv.vector, 0.0, &yv.vector);
    gsl_blas_ddot(&zv.vector, &yv.vector, &r);
    return r;
}

int general_advance(struct general *g, const struct model *m, const struct exact_drive *d,
                    double a, double b, double *x, double *v, double *diss, double *work,
                    double *fwork)
{
    double h = b - a;
    if (!(h > 0.0) || m->n != g->n)
        return -1;
    take_model(g, m);
    if (!g->valid)
        return -1;
    int n = g->n;
    enum exact_kind kind = EXACT_NONE;
    if (d && (g->amp != 0.0 || g->force != 0.0)) {
        if (d->sine)
            kind = EXACT_SINE;
        else if (d->w0 != 0.0 || d->dw != 0.0)
            kind = EXACT_LINE;
    }
    int dim = kind == EXACT_NONE ? 2 * n : 2 * n + 2;
    double omega = kind == EXACT_SINE ? d->omega : 0.0;
    if (!isfinite(omega))
        return -1;
    struct gslot *sl = find_slot(g, kind, omega, h, dim);
    if (!sl)
        return -1;
    double *z = g->z, *z1 = g->z1, *y = g->y;
    for (int i = 0; i < n; i++) {
        z[i] = g->ws * g->sqm[i] * x[i];
        z[n + i] = g->sqm[i] * v[i];
    }
    if (kind == EXACT_SINE) {
        z[2 * n] = sin(d->omega * a + d->phi);
        z[2 * n + 1] = cos(d->omega * a + d->phi);
    } else if (kind == EXACT_LINE) {
        z[2 * n] = d->w0 + d->dw * (a - d->t0);
        z[2 * n + 1] = d->dw / g->ws;
    }
    double add[BOOKS] = {0.0, 0.0, 0.0}, delta = h - sl->key.h;
    if (delta != 0.0) {
        /* the difference first, to first order: z += delta A z, books += delta z^T Q z */
        gsl_matrix q[BOOKS];
        for (int bk = 0; bk < BOOKS; bk++)
            q[bk] = g->q[bk];
        book_forms(g, kind, omega, dim, q);
        for (int bk = 0; bk < BOOKS; bk++)
            add[bk] += delta * quad(&g->q[bk], z, y, dim);
        gsl_matrix_view sv = lead(&g->s, dim);
        generator(g, kind, omega, delta, &sv.matrix);
        gsl_vector_view zv = gsl_vector_view_array(z, (size_t)dim);
        gsl_vector_view yv = gsl_vector_view_array(y, (size_t)dim);
        gsl_blas_dgemv(CblasNoTrans, 1.0, &sv.matrix, &zv.vector, 0.0, &yv.vector);
        for (int j = 0; j < dim; j++)
            z[j] += y[j];
    }
    for (int bk = 0; bk < BOOKS; bk++)
        add[bk] += quad(&sl->book[bk], z, y, dim);
    gsl_matrix_view pv = lead(&sl->prop, dim);
    gsl_vector_view zv = gsl_vector_view_array(z, (size_t)dim);
    gsl_vector_view z1v = gsl_vector_view_array(z1, (size_t)dim);
    gsl_blas_dgemv(CblasNoTrans, 1.0, &pv.matrix, &zv.vector, 0.0, &z1v.vector);
    for (int j = 0; j < dim; j++)
        if (!isfinite(z1[j]))
            return -1;
    for (int bk = 0; bk < BOOKS; bk++)
        if (!isfinite(add[bk]))
            return -1;
    for (int i = 0; i < n; i++) {
        x[i] = z1[i] / (g->ws * g->sqm[i]);
        v[i] = z1[n + i] / g->sqm[i];
    }
    *diss += add[BOOK_D];
    *work += add[BOOK_W];
    *fwork += add[BOOK_F];
    return 0;
}

/* Declared in exact.h: the question exact.c asks before each step. */
int exact_needs_general(const struct model *m)
{
    /* Rayleigh's damping stays in the modes, with a force and a damper at the motor's end
     * too (both inputs of the modes' drive states). */
    if ((m->spring_damped || model_forced(m)) && !model_rayleigh(m))
        return 1;
    for (int j = 0; j <= m->n; j++)
        if (m->k[j] == 0.0 && (j < m->n || m->boundary != BOUNDARY_FREE))
            return 1;
    return 0;
}
