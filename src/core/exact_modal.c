/* exact_modal.c: the exact step of a chain whose damping is Rayleigh's, C = alpha M +
 * beta K (ground dampers proportional to the masses, spring dampers to the springs), mode
 * by mode; gamma below is mode j's own gamma_j = alpha + beta w_j^2.
 *
 * With y = M^(1/2) x and T = M^(-1/2) K M^(-1/2) = Phi diag(w_j^2) Phi^T (T symmetric
 * tridiagonal: Phi by LAPACK's dstevr, w_j as the singular values of T's bidiagonal
 * factor, accurate however small), eta = Phi^T y: Rayleigh's C keeps every mode a damped
 * oscillator of its own, driven through the last mass by the end's spring and damper
 * (k_N u + cs_N u', the cs_N v_N part being in beta K) and through mass K by the force
 * F w (w the motor's unit waveform, at its phase):
 *
 *     eta_j'' + gamma eta_j' + w_j^2 eta_j = b_j(t),
 *     b_j = cn_j (k_N u + cs_N u') + ck_j F w,   cn_j = Phi_(N,j) / sqrt(m_N),
 *                                                ck_j = Phi_(K,j) / sqrt(m_K).
 *
 * On a piece b_j is a sine of the drive's angle or a straight line, so each mode carries
 * it as two states of its own, scaled by w_j so that a quasi-static mode's q equals s:
 * with q_j = w_j eta_j, p_j = eta_j', z_j = (q_j, p_j, s_j, r_j),
 *
 *     q' = w p,   p' = -w q - gamma p + w s,   s = b_j / w_j,
 *     sine:  s' = om r, r' = -om s  (r = b_j' / (om w_j));
 *     line:  s' = w r,  r' = 0      (r = b_j' / w_j^2).
 *
 * Its 4 x 4 exponential E_j does not depend on the amplitudes, the force or its mass: a
 * cached step serves any of them. The books come by exact.c's method on 4 x 4 matrices
 * (6-point Gauss-Legendre on a base interval with ||A_j|| t <= 1/2, doubled up; every
 * exponential GSL's afresh), each a form in z_j(a):
 *  - the dampers' loss: v^T C v (= sum_j gamma |p_j|^2, Phi orthogonal) and the end's
 *    damper's rest, cs_N (u'^2 - 2 u' v_N), v_N = sum_j cn_j p_j;
 *  - the motor's work (k_N (u - x_N) + cs_N (u' - v_N)) u': k_N (u(b)^2 - u(a)^2) / 2 +
 *    cs_N int u'^2 less int u' (k_N x_N + cs_N v_N), x_N = sum_j cn_j q_j / w_j;
 *  - the force's work int F w v_K, v_K = sum_j ck_j p_j.
 * u' and w over the piece are the drive's states moved by R(tau), the drive's 2 x 2 block
 * of E_j: u'(a + tau) = U . R_r(tau), w(a + tau) = V . R_s(tau) (U, V from the drive at
 * a), so the books need Gd = int gamma E_p^T E_p, and for c = s, r the vectors
 * Nq_c = int R_rc E_q, Np_c = int R_rc E_p and Fp_c = int R_sc E_p (rows of E_j), doubled
 * as Nw is in exact.c: B_c(2t) = B_c(t) + E(t)^T sum_k B_k(t) R_kc(t).
 *
 * Cost: a step is two products with Phi (n x n by n x 2) and 48 numbers a mode; a new step
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

#define SLOTS 8           /* cached step lengths: the grid's and those of contacts */
#define PER_MODE 48       /* numbers a mode keeps for a step: see struct mslot */
#define BASE_NORM 0.5     /* ||A_j|| times the quadrature's base interval */
#define GSL_ROW_TOP 100.0 /* see exact_expm */

/* A mode's part of a cached step, at these offsets of its PER_MODE numbers: E's rows q and
 * p, Gd, then Nq, Np and Fp (each its _s then its _r). */
enum { AT_E = 0, AT_GD = 8, AT_NQ = 24, AT_NP = 32, AT_FP = 40 };

struct mslot {
    struct exact_key key; /* which step it holds, ||A|| the largest ||A_j|| (first:
                             exact_key_find reads it) */
    double *data;         /* PER_MODE a mode */
};

struct modal {
    int n, damped;
    unsigned long model, clock;
    double alpha, beta, kn, csn; /* gamma_j = alpha + beta w_j^2; k_N, cs_N (0: free end) */
    double *w, *cn, *sqm;         /* w_j, cn_j, sqrt(m_i) */
    double *diag, *off;           /* T for dstevr (overwritten) */
    double *phi;                  /* Phi, column-major: as a row-major n x n matrix, Phi^T */
    double *yin, *hm;             /* n x 2 each: (y, M^(1/2) v) and the modes' (eta, eta') */
    int *isuppz;
    double *mem;
    struct mslot slot[SLOTS];
};

/* The drive at a time t of a piece: the end's u, u' and the rates that make r (ur, upr: a
 * sine's u' / om and u'' / om, a line's u' and 0), the force's waveform w and its rate wr
 * (likewise), and U, which moves u' (see the top). */
struct piece {
    enum exact_kind kind;
    double force; /* F */
    int on;       /* its mass */
    double u, up, ur, upr, wv, wr, us[2];
};

/* 6-point Gauss-Legendre on [-1, 1]: nodes +-gl_x[i], weights gl_w[i]. */
static const double gl_x[3] = {0.2386191860831969086305017, 0.6612093864662645136613996,
                               0.9324695142031520278123016};
static const double gl_w[3] = {0.4679139345726910473898703, 0.3607615730481386075698335,
                               0.1713244923791703450402961};

static size_t doubles(int n)
{
    return (size_t)n * (size_t)n + (size_t)(9 + SLOTS * PER_MODE) * (size_t)n;
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
    md->cn = md->w + nn;
    md->sqm = md->cn + nn;
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
    dst->w += shift, dst->cn += shift, dst->sqm += shift;
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
    md->kn = free_end ? 0.0 : m->k[n];
    md->csn = free_end ? 0.0 : m->cs[n];
    double top = md->diag[0] * md->diag[0];
    for (int j = 0; j < n; j++) {
        /* The two agree to the eigenvalues' rounding (pairing the shapes with the right
         * frequencies), or the modes are not used. */
        double sv = md->diag[n - 1 - j];
        if (!(sv > 0.0) || !isfinite(sv) || !(fabs(md->w[j] - sv * sv) <= 1e-10 * top))
            return -1;
        md->w[j] = sv;
        md->cn[j] = md->phi[(size_t)(n - 1) + (size_t)n * (size_t)j] / md->sqm[n - 1];
    }
    md->alpha = alpha;
    md->beta = beta;
    md->damped = alpha > 0.0 || beta > 0.0;
    return 0;
}

/* The drive's rate scale in mode j: om for a sine, w_j for a line. */
static double rate_scale(const struct modal *md, int j, enum exact_kind kind, double omega)
{
    return kind == EXACT_SINE ? omega : md->w[j];
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
        s[6] = tau * md->w[j];
        s[11] = tau * rate_scale(md, j, kind, omega);
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

/* A drive book at one quadrature node: B_c += wt R_(row, c) E_(from) for c = s, r (x =
 * E at the node). */
static void book_node(double *bk, const double *x, int row, int from, double wt)
{
    for (int c = 0; c < 2; c++) {
        double f = wt * x[4 * row + 2 + c];
        for (int b = 0; b < 4; b++)
            bk[4 * c + b] += f * x[4 * from + b];
    }
}

/* A drive book doubled: B_c += E^T sum_k B_k R_kc, R the drive's block of E (x). */
static void book_double(double *bk, const double *x)
{
    double r00 = x[10], r01 = x[11], r10 = x[14], r11 = x[15], y[8];
    for (int b = 0; b < 4; b++) {
        y[b] = bk[b] * r00 + bk[4 + b] * r10;
        y[4 + b] = bk[b] * r01 + bk[4 + b] * r11;
    }
    for (int c = 0; c < 2; c++)
        for (int a = 0; a < 4; a++) {
            double sum = 0.0;
            for (int k = 0; k < 4; k++)
                sum += x[4 * k + a] * y[4 * c + k];
            bk[4 * c + a] += sum;
        }
}

/* Gd doubled: Gd += E^T Gd E. */
static void gram_double(double *g, const double *x)
{
    double gx[16];
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
}

/* Mode j's part of a step h into out (PER_MODE numbers); *norm gets ||A_j||. */
static int fill_mode(const struct modal *md, int j, enum exact_kind kind, double omega, double h,
                     double *out, double *norm)
{
    double s[16], x[16];
    double *g = out + AT_GD, *nq = out + AT_NQ, *np = out + AT_NP, *fp = out + AT_FP;
    int driven = kind != EXACT_NONE;
    *norm = mode_generator(md, j, kind, omega, 1.0, s);
    memset(out, 0, PER_MODE * sizeof *out);
    if (md->damped || driven) {
        int levels = 0;
        while (*norm * ldexp(h, -levels) > BASE_NORM && levels < 1000)
            levels++;
        double base = ldexp(h, -levels), gamma = mode_gamma(md, j);
        for (int i = 0; i < 6; i++) {
            double node = 0.5 * base * (1.0 + (i < 3 ? -gl_x[i] : gl_x[i - 3]));
            double w = 0.5 * base * gl_w[i % 3];
            if (mode_expm(md, j, kind, omega, node, x))
                return -1;
            for (int a = 0; a < 4; a++)
                for (int b = 0; b < 4; b++)
                    g[4 * a + b] += w * gamma * x[4 + a] * x[4 + b];
            if (driven) {
                book_node(nq, x, 3, 0, w);
                book_node(np, x, 3, 1, w);
                book_node(fp, x, 2, 1, w);
            }
        }
        for (int level = 0; level < levels; level++) {
            if (mode_expm(md, j, kind, omega, ldexp(base, level), x))
                return -1;
            gram_double(g, x);
            if (driven) {
                book_double(nq, x);
                book_double(np, x);
                book_double(fp, x);
            }
        }
    }
    if (mode_expm(md, j, kind, omega, h, x))
        return -1;
    memcpy(out + AT_E, x, 8 * sizeof *out);
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

/* The drive of kind at time t into p (d read for a sine or a line). */
static void piece_at(struct piece *p, enum exact_kind kind, const struct exact_drive *d, double t)
{
    memset(p, 0, sizeof *p);
    p->kind = kind;
    p->force = kind != EXACT_NONE ? d->force : 0.0;
    if (kind == EXACT_SINE) {
        double th = d->omega * t + d->phi, sn = sin(th), cs = cos(th), aw = d->amp * d->omega;
        p->u = d->amp * sn, p->up = aw * cs, p->ur = d->amp * cs, p->upr = -aw * sn;
        p->wv = sn, p->wr = cs;
        p->us[0] = aw * sn, p->us[1] = aw * cs;
    } else if (kind == EXACT_LINE) {
        double tau = t - d->t0;
        p->u = d->u0 + d->du * tau, p->up = p->ur = d->du;
        p->wv = d->w0 + d->dw * tau, p->wr = d->dw;
        p->us[1] = d->du;
    }
}

/* Mode j's drive states (s, r) at p into z[2], z[3], and the force's book states F ck_j V
 * into fv (see the top). */
static void mode_drive(const struct modal *md, const struct piece *p, int j, double *z,
                       double *fv)
{
    double wj = md->w[j], rho = p->kind == EXACT_LINE ? wj : 1.0;
    double ck = p->force != 0.0
                    ? p->force * md->phi[(size_t)p->on + (size_t)md->n * (size_t)j] / md->sqm[p->on]
                    : 0.0;
    z[2] = (md->cn[j] * (md->kn * p->u + md->csn * p->up) + ck * p->wv) / wj;
    z[3] = (md->cn[j] * (md->kn * p->ur + md->csn * p->upr) + ck * p->wr) / (wj * rho);
    fv[0] = ck * p->wv;
    fv[1] = ck * p->wr / rho;
}

/* A step delta (the difference from a cached step) of every mode in md->hm, to first
 * order (error (delta ||A||)^2 / 2 <= 5e-17, as exact.c does), its books at p's powers. */
static void nudge(struct modal *md, const struct piece *p, double delta, double *add)
{
    for (int j = 0; j < md->n; j++) {
        double z[4], fv[2], w = md->w[j], g = mode_gamma(md, j), cn = md->cn[j];
        mode_drive(md, p, j, z, fv);
        double q = w * md->hm[2 * j], v = md->hm[2 * j + 1];
        add[0] += delta * (g * v * v - 2.0 * md->csn * cn * p->up * v);
        add[1] -= delta * p->up * cn * (md->kn * q / w + md->csn * v);
        add[2] += delta * fv[0] * v;
        md->hm[2 * j] = (q + delta * w * v) / w;
        md->hm[2 * j + 1] = v + delta * (-w * q - g * v + w * z[2]);
    }
}

/* Mode j's cached step sl from p, in md->hm, its books added to add. */
static void mode_step(struct modal *md, const struct mslot *sl, const struct piece *p, int j,
                      double *add)
{
    const double *k = sl->data + (size_t)PER_MODE * (size_t)j;
    double z[4] = {md->w[j] * md->hm[2 * j], md->hm[2 * j + 1]}, fv[2];
    mode_drive(md, p, j, z, fv);
    double q1 = 0.0, p1 = 0.0, nq[2] = {0.0, 0.0}, np[2] = {0.0, 0.0}, fp[2] = {0.0, 0.0};
    for (int c = 0; c < 4; c++) {
        q1 += k[AT_E + c] * z[c];
        p1 += k[AT_E + 4 + c] * z[c];
    }
    if (md->damped)
        for (int c = 0; c < 4; c++) {
            double gz = 0.0;
            for (int e = 0; e < 4; e++)
                gz += k[AT_GD + 4 * c + e] * z[e];
            add[0] += z[c] * gz;
        }
    if (p->kind != EXACT_NONE) {
        for (int c = 0; c < 2; c++)
            for (int e = 0; e < 4; e++) {
                nq[c] += k[AT_NQ + 4 * c + e] * z[e];
                np[c] += k[AT_NP + 4 * c + e] * z[e];
                fp[c] += k[AT_FP + 4 * c + e] * z[e];
            }
        double uq = p->us[0] * nq[0] + p->us[1] * nq[1], uv = p->us[0] * np[0] + p->us[1] * np[1];
        add[0] -= 2.0 * md->csn * md->cn[j] * uv;
        add[1] -= md->cn[j] * (md->kn * uq / md->w[j] + md->csn * uv);
        add[2] += fv[0] * fp[0] + fv[1] * fp[1];
    }
    md->hm[2 * j] = q1 / md->w[j];
    md->hm[2 * j + 1] = p1;
}

/* The books' parts that the drive alone makes over [a, b]: k_N (u(b)^2 - u(a)^2) / 2 of
 * the motor's work, and cs_N int u'^2 of it and of the loss. */
static void drive_books(const struct modal *md, enum exact_kind kind, const struct exact_drive *d,
                        double a, double b, double *add)
{
    if (kind == EXACT_NONE)
        return;
    struct piece pa, pb;
    piece_at(&pa, kind, d, a);
    piece_at(&pb, kind, d, b);
    double h = b - a, sq = 0.0;
    if (kind == EXACT_SINE) /* int cos^2 = h / 2 + cos(th_a + th_b) sin(om h) / (2 om) */
        sq = 0.5 * d->amp * d->amp * d->omega *
             (d->omega * h + cos(d->omega * (a + b) + 2.0 * d->phi) * sin(d->omega * h));
    else
        sq = d->du * d->du * h;
    add[0] += md->csn * sq;
    add[1] += 0.5 * md->kn * (pb.u - pa.u) * (pb.u + pa.u) + md->csn * sq;
}

enum exact_kind exact_drive_kind(const struct exact_drive *d)
{
    if (d->sine)
        return d->amp != 0.0 || d->force != 0.0 ? EXACT_SINE : EXACT_NONE;
    if (d->u0 != 0.0 || d->du != 0.0 || (d->force != 0.0 && (d->w0 != 0.0 || d->dw != 0.0)))
        return EXACT_LINE;
    return EXACT_NONE;
}

int modal_advance(struct modal *md, enum exact_kind kind, const struct exact_drive *d, int on,
                  double a, double b, double *x, double *v, double *diss, double *work,
                  double *fwork)
{
    int n = md->n;
    double h = b - a, omega = kind == EXACT_SINE ? d->omega : 0.0;
    if (kind != EXACT_NONE && d->force != 0.0 && (on < 0 || on >= n))
        return -1;
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

    /* A step a little longer or shorter than the cached one: the difference first. */
    double add[3] = {0.0, 0.0, 0.0}, delta = h - sl->key.h;
    struct piece p;
    piece_at(&p, kind, d, a);
    p.on = on;
    if (delta != 0.0) {
        nudge(md, &p, delta, add);
        piece_at(&p, kind, d, a + delta);
        p.on = on;
    }
    for (int j = 0; j < n; j++)
        mode_step(md, sl, &p, j, add);
    drive_books(md, kind, d, a, b, add);
    gsl_blas_dgemm(CblasTrans, CblasNoTrans, 1.0, &pt.matrix, &hv.matrix, 0.0, &yv.matrix);
    for (int i = 0; i < 2 * n; i++)
        if (!isfinite(md->yin[i]))
            return -1;
    for (int i = 0; i < 3; i++)
        if (!isfinite(add[i]))
            return -1;
    for (int i = 0; i < n; i++) {
        x[i] = md->yin[2 * i] / md->sqm[i];
        v[i] = md->yin[2 * i + 1] / md->sqm[i];
    }
    *diss += add[0];
    *work += add[1];
    *fwork += add[2];
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
