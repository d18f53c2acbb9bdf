/* damped.c: the damping ratio and damped frequency of each mode (modes_damped).
 *
 * The damped chain z' = A z (model_first_order) has 2N eigenvalues: a complex pair
 * lambda = -zeta w +- i w sqrt(1 - zeta^2) per oscillating mode, two real ones
 * l1 l2 = w^2, -(l1 + l2) / 2 = zeta w per overdamped mode. Which undamped mode each
 * belongs to is read off the displacement half psi of its eigenvector (LAPACK dgeev):
 * the undamped shape phi_j with the largest |phi_j^T M psi| relative to the lengths of
 * both in the M inner product. Candidates are taken best first; a complex pair takes a
 * mode of its own, two real eigenvalues share one, and a real one never takes the last
 * mode a pair still needs. This is done for every N up to 1000 (dgeev on 2N: 1 s at
 * N = 300, about 30 s at 1000 with the reference BLAS) unless C is diagonal in the
 * undamped modes, Rayleigh's C = alpha M + beta K (model_rayleigh: undamped chains, ground
 * dampers proportional to the masses, spring dampers proportional to the springs), whose
 * modal damping (modes_modal, O(N^2)) is then exact. So is that of a mode whose
 * eigenvalues dgeev cannot resolve: an eigenvalue counts only when its
 * backward error in the chain's own equation,
 *   |(lambda^2 M + lambda C + K) psi| / ((|lambda|^2 |M| + |lambda| |C| + |K|) |psi|)
 * (infinity norms, |K| bounded by twice its largest diagonal entry), is below
 * TRUST_ERROR. Masses 1e70 apart make |A| so large that the slow modes' eigenvalues
 * drown in its rounding. A chain without dampers takes the modal route too: C = 0 is
 * diagonal in the modes, so its ratios are exactly 0 (Q infinite), where dgeev's real
 * parts would be rounding (~1e-17, Q ~1e16).
 * Each mode's eigen frequency is |lambda| / 2 pi of its pair (the textbooks' natural
 * frequency of a non-proportionally damped mode), sqrt(l1 l2) / 2 pi of its two real
 * eigenvalues. A rigid-body mode (0 Hz: model_rigid_modes) has no damping ratio: NAN. */
#include "modes.h"

#include <complex.h>
#include <math.h>
#include <stdlib.h>

#include <lapacke.h>

#include "limits.h"

#define TRUST_ERROR 1e-8 /* a backward stable dgeev gives ~1e-15 where it can */

/* One candidate: eigen unit u (a complex pair or one real eigenvalue) for mode j. */
struct candidate {
    double overlap;
    int unit, mode;
};

static int compare_candidate(const void *a, const void *b)
{
    const struct candidate *x = a, *y = b;
    if (x->overlap != y->overlap)
        return (x->overlap < y->overlap) - (x->overlap > y->overlap);
    if (x->unit != y->unit)
        return x->unit - y->unit;
    return x->mode - y->mode;
}

/* The ratio, damped frequency and eigen frequency of a mode oscillating as
 * x'' = -w2 x - 2 s x' (|lambda| = w: l1 l2 = w^2 either way). */
static void from_modal(double w2, double s, double *ratio, double *hz, double *eigen)
{
    double w = sqrt(w2 > 0.0 ? w2 : 0.0);
    *ratio = s / w;
    *hz = s < w ? sqrt((w - s) * (w + s)) / (2.0 * M_PI) : 0.0;
    *eigen = w / (2.0 * M_PI);
}

static int modal_damping(const struct model *m, double *ratio, double *hz, double *eigen)
{
    int n = m->n, rigid = model_rigid_modes(m);
    double *w2 = malloc((size_t)(2 * n) * sizeof *w2);
    int e = w2 ? modes_modal(m, w2, w2 + n) : -1;
    for (int j = rigid; e == 0 && j < n; j++) {
        from_modal(w2[j], w2[n + j], &ratio[j], &hz[j], &eigen[j]);
        if (!isfinite(ratio[j]))
            e = -2;
    }
    free(w2);
    return e;
}

/* |phi^T M psi| / sqrt(phi^T M phi psi^H M psi) for psi = re + i im (im may be NULL). */
static double overlap(const struct model *m, const double *phi, const double *re,
                      const double *im)
{
    double complex dot = 0.0;
    double pp = 0.0, ss = 0.0;
    for (int i = 0; i < m->n; i++) {
        double y = im ? im[i] : 0.0;
        dot += m->m[i] * phi[i] * (re[i] + I * y);
        pp += m->m[i] * phi[i] * phi[i];
        ss += m->m[i] * (re[i] * re[i] + y * y);
    }
    return pp > 0.0 && ss > 0.0 ? cabs(dot) / sqrt(pp * ss) : 0.0;
}

/* Gives each eigen unit a mode: unit u is a complex pair when pair[u], else one real
 * eigenvalue; owner[u] receives its mode. cand holds units * n candidates. */
static void assign(int n, int units, const bool *pair, struct candidate *cand, int *owner,
                   int *taken)
{
    int empty = n, pairs_left = 0;
    for (int u = 0; u < units; u++) {
        owner[u] = -1;
        pairs_left += pair[u];
    }
    for (int j = 0; j < n; j++)
        taken[j] = 0; /* eigenvalues held: 2 is full */
    qsort(cand, (size_t)units * (size_t)n, sizeof *cand, compare_candidate);
    for (size_t k = 0; k < (size_t)units * (size_t)n; k++) {
        int u = cand[k].unit, j = cand[k].mode;
        if (owner[u] >= 0)
            continue;
        if (pair[u] && taken[j] == 0) {
            pairs_left--;
        } else if (pair[u] || taken[j] == 2 || (taken[j] == 0 && empty - 1 < pairs_left)) {
            continue;
        }
        empty -= taken[j] == 0;
        taken[j] += pair[u] ? 2 : 1;
        owner[u] = j;
    }
    /* Every pair found a mode (a real one never took the last one a pair needed); a real
     * one passed over for that reason takes what is left. */
    for (int u = 0; u < units; u++)
        for (int j = 0; owner[u] < 0 && j < n; j++)
            if (taken[j] < 2) {
                taken[j]++;
                owner[u] = j;
            }
}

/* The backward error above of eigenvalue lambda with displacements psi = re + i im (im
 * NULL for a real one); scratch holds 4N doubles. model_rates, being linear, gives
 * acc = -M^-1 (K x + C v) for the real and the imaginary parts of (psi, lambda psi); the
 * residual is m_i (lambda^2 psi_i - acc_i). */
static double backward_error(const struct model *chain, double complex lambda,
                             const double *re, const double *im, double *scratch)
{
    struct model linear = *chain; /* cubic springs linearised at rest */
    linear.cubic = false;
    const struct model *m = &linear;
    int n = m->n;
    double *x = scratch, *v = scratch + n, *acc_re = scratch + 2 * n, *acc_im = scratch + 3 * n;
    for (int pass = 0; pass < 2; pass++) {
        for (int i = 0; i < n; i++) {
            double complex z = re[i] + I * (im ? im[i] : 0.0), lz = lambda * z;
            x[i] = pass ? cimag(z) : creal(z);
            v[i] = pass ? cimag(lz) : creal(lz);
        }
        model_rates(m, NULL, x, v, 0.0, 0.0, pass ? acc_im : acc_re, NULL, NULL);
    }
    double top_m = 0.0, top_c = 0.0, top_k = 0.0, top_psi = 0.0, top_r = 0.0;
    for (int i = 0; i < n; i++) {
        double complex z = re[i] + I * (im ? im[i] : 0.0);
        top_m = fmax(top_m, m->m[i]);
        top_c = fmax(top_c, m->c[i] + 2.0 * (m->cs[i] + m->cs[i + 1]));
        top_k = fmax(top_k, 2.0 * (m->k[i] + m->k[i + 1]));
        top_psi = fmax(top_psi, cabs(z));
        top_r = fmax(top_r, cabs(m->m[i] * (lambda * lambda * z - (acc_re[i] + I * acc_im[i]))));
    }
    double l = cabs(lambda);
    return top_r / ((l * l * top_m + l * top_c + top_k) * top_psi);
}

/* Ratio and damped frequency of every mode given a pair or two real eigenvalues; NAN for
 * the others. A passive chain has Re lambda <= 0: a positive real part is rounding. */
static void conclude(int n, int units, const bool *pair, const int *owner, const double *re,
                     const double *im, const int *first, double *ratio, double *hz,
                     double *eigen)
{
    for (int j = 0; j < n; j++)
        ratio[j] = hz[j] = eigen[j] = NAN;
    /* A mode's first real eigenvalue waits in hz[j] (as -l1, > 0), tagged by ratio NAN. */
    for (int u = 0; u < units; u++) {
        int j = owner[u], k = first[u];
        if (j < 0)
            continue;
        if (pair[u]) {
            ratio[j] = fmax(-re[k], 0.0) / hypot(re[k], im[k]);
            hz[j] = fabs(im[k]) / (2.0 * M_PI);
            eigen[j] = hypot(re[k], im[k]) / (2.0 * M_PI);
        } else if (isnan(hz[j])) {
            hz[j] = fmax(-re[k], 0.0);
        } else {
            double l1 = hz[j], l2 = fmax(-re[k], 0.0);
            ratio[j] = (l1 + l2) / (2.0 * sqrt(l1 * l2));
            hz[j] = 0.0;
            eigen[j] = sqrt(l1 * l2) / (2.0 * M_PI);
        }
    }
}

int modes_damped(const struct model *m, const double *shapes, double *ratio, double *damped_hz)
{
    double *eigen = malloc((size_t)m->n * sizeof *eigen);
    int e = eigen ? modes_damped_all(m, shapes, ratio, damped_hz, eigen) : -1;
    free(eigen);
    return e;
}

/* A rigid-body mode: 0 Hz, no ratio. */
static void rigid_modes(const struct model *m, double *ratio, double *hz, double *eigen)
{
    for (int j = 0; j < model_rigid_modes(m); j++) {
        ratio[j] = NAN;
        hz[j] = eigen[j] = 0.0;
    }
}

static int dense_damping(const struct model *m, const double *shapes, double *ratio,
                         double *damped_hz, double *eigen);

int modes_damped_all(const struct model *m, const double *shapes, double *ratio,
                     double *damped_hz, double *eigen)
{
    int e = model_rayleigh(m) ? modal_damping(m, ratio, damped_hz, eigen)
                              : dense_damping(m, shapes, ratio, damped_hz, eigen);
    rigid_modes(m, ratio, damped_hz, eigen);
    return e;
}

static int dense_damping(const struct model *m, const double *shapes, double *ratio,
                         double *damped_hz, double *eigen)
{
    int n = m->n, n2 = 2 * n, rigid = model_rigid_modes(m);
    size_t nn = (size_t)n2 * (size_t)n2;
    double *a = malloc(2 * nn * sizeof *a);
    double *work = malloc((size_t)(4 * n2) * sizeof *work);
    struct candidate *cand = malloc((size_t)n2 * (size_t)n * sizeof *cand);
    int *ints = malloc((size_t)(4 * n2) * sizeof *ints);
    bool *pair = malloc((size_t)n2 * sizeof *pair);
    int e = a && work && cand && ints && pair ? 0 : -1;
    double *vr = a ? a + nn : NULL, *re = work, *im = work ? work + n2 : NULL;
    double *scratch = work ? work + 2 * n2 : NULL;
    if (e == 0)
        e = model_first_order(m, a, scratch);
    if (e == 0)
        e = (int)LAPACKE_dgeev(LAPACK_COL_MAJOR, 'N', 'V', n2, a, n2, re, im, NULL, 1, vr, n2);
    int units = 0, *first = ints, *owner = ints + n2, *taken = ints + 2 * n2;
    /* Column k of vr is the eigenvector of a real lambda_k; for a pair (im[k] > 0, its
     * conjugate next), columns k and k+1 are its real and imaginary parts. */
    for (int k = 0; e == 0 && k < n2; k++) {
        const double *psi = vr + (size_t)k * n2, *psi_im = im[k] != 0.0 ? psi + n2 : NULL;
        bool is_pair = psi_im != NULL;
        if (backward_error(m, re[k] + I * im[k], psi, psi_im, scratch) <= TRUST_ERROR) {
            for (int j = 0; j < n; j++)
                cand[(size_t)units * n + j] = (struct candidate){
                    overlap(m, shapes + (size_t)j * n, psi, psi_im), units, j};
            pair[units] = is_pair;
            first[units++] = k;
        }
        k += is_pair;
    }
    bool missing = false;
    if (e == 0) {
        assign(n, units, pair, cand, owner, taken);
        conclude(n, units, pair, owner, re, im, first, ratio, damped_hz, eigen);
        for (int j = rigid; j < n; j++)
            missing |= !isfinite(ratio[j]) || !isfinite(damped_hz[j]);
    }
    if (missing) {
        /* Reuses re, im and scratch as the modal route's answer for the modes dgeev could
         * not give. */
        e = modal_damping(m, re, im, scratch);
        for (int j = rigid; e == 0 && j < n; j++)
            if (!isfinite(ratio[j]) || !isfinite(damped_hz[j]))
                ratio[j] = re[j], damped_hz[j] = im[j], eigen[j] = scratch[j];
    }
    for (int j = rigid; e == 0 && j < n; j++)
        if (!isfinite(ratio[j]) || !isfinite(damped_hz[j]))
            e = -2; /* w^2 underflowed to 0: no answer, not an infinite one */
    free(a);
    free(work);
    free(cand);
    free(ints);
    free(pair);
    return e;
}
