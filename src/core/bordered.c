/* bordered.c: a banded block bordered by a dense row and column (bordered.h).
 *
 * With the system [A c; r' d] (A banded), the band's LU solves A y = top and A w = c,
 * and then x_n = (bottom - r'y) / (d - r'w), x = y - x_n w (block elimination: Govaerts,
 * Numerical Methods for Bifurcations of Dynamical Equilibria, 3.3). Where A is nearly
 * singular (a fold of the curve a continuation follows) that loses digits, so one step of
 * iterative refinement on the whole system follows; a refinement larger than REFINE_MAX
 * of the solution says the elimination lost too many, and the dense LU of the whole
 * system is taken instead. */
#include "bordered.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* The largest refinement (relative to the solution, largest components) that is
 * trusted: the refined solution is then good to about its square. */
#define REFINE_MAX 1e-7

int bordered_init(struct bordered *b, int n, int kl, int ku)
{
    *b = (struct bordered){.n = n, .kl = kl, .ku = ku, .ldab = 2 * kl + ku + 1};
    /* the band, then the border column, the saved right-hand side and a residual */
    b->ab = malloc(((size_t)b->ldab * n + 3 * ((size_t)n + 1)) * sizeof *b->ab);
    b->piv = malloc(((size_t)n + 1) * sizeof *b->piv);
    if (!b->ab || !b->piv) {
        bordered_free(b);
        return -1;
    }
    b->col = b->ab + (size_t)b->ldab * n;
    return 0;
}

void bordered_free(struct bordered *b)
{
    free(b->ab);
    free(b->piv);
    b->ab = b->col = NULL;
    b->piv = NULL;
}

/* The band of a's leading block into b->ab. */
static void take_band(struct bordered *b, const double *a, int lda)
{
    int n = b->n, kl = b->kl, ku = b->ku;
    for (int j = 0; j < n; j++) {
        double *band = b->ab + (size_t)j * b->ldab;
        memset(band, 0, (size_t)b->ldab * sizeof *band);
        int lo = j - ku > 0 ? j - ku : 0, hi = j + kl < n - 1 ? j + kl : n - 1;
        for (int i = lo; i <= hi; i++)
            band[kl + ku + i - j] = a[i + (size_t)j * lda];
    }
}

/* x = the solution of the factored system for rhs, in place. 0, or -1 when the
 * elimination's pivot d - r'w vanishes. */
static int eliminate(struct bordered *b, const double *a, int lda, bool border, double *x)
{
    int n = b->n;
    if (LAPACKE_dgbtrs_work(LAPACK_COL_MAJOR, 'N', n, b->kl, b->ku, 1, b->ab, b->ldab, b->piv,
                            x, n) != 0)
        return -1;
    if (!border)
        return 0;
    double top = x[n], ry = 0.0, rw = 0.0;
    for (int i = 0; i < n; i++) {
        ry += a[n + (size_t)i * lda] * x[i];
        rw += a[n + (size_t)i * lda] * b->col[i];
    }
    double pivot = a[n + (size_t)n * lda] - rw;
    if (!(fabs(pivot) > 0.0) || !isfinite(pivot))
        return -1;
    x[n] = (top - ry) / pivot;
    for (int i = 0; i < n; i++)
        x[i] -= x[n] * b->col[i];
    return 0;
}

int bordered_solve(struct bordered *b, double *a, int lda, bool border, double *rhs)
{
    int n = b->n, dim = border ? n + 1 : n;
    double *saved = b->col + n + 1, *res = saved + n + 1;
    memcpy(saved, rhs, (size_t)dim * sizeof *rhs);
    take_band(b, a, lda);
    bool banded = LAPACKE_dgbtrf_work(LAPACK_COL_MAJOR, n, n, b->kl, b->ku, b->ab, b->ldab,
                                      b->piv) == 0;
    if (banded && border) {
        for (int i = 0; i < n; i++)
            b->col[i] = a[i + (size_t)n * lda];
        banded = LAPACKE_dgbtrs_work(LAPACK_COL_MAJOR, 'N', n, b->kl, b->ku, 1, b->ab,
                                               b->ldab, b->piv, b->col, n) == 0;
    }
    if (banded && eliminate(b, a, lda, border, rhs) == 0) {
        if (!border)
            return 0;
        /* One step of refinement: the residual of the whole system, solved again. */
        for (int i = 0; i < dim; i++) {
            int lo = i - b->kl > 0 ? i - b->kl : 0, hi = i + b->ku < n - 1 ? i + b->ku : n - 1;
            if (i == n)
                lo = 0, hi = n - 1;
            double s = a[i + (size_t)n * lda] * rhs[n];
            for (int j = lo; j <= hi; j++)
                s += a[i + (size_t)j * lda] * rhs[j];
            res[i] = saved[i] - s;
        }
        if (eliminate(b, a, lda, border, res) == 0) {
            double size = 0.0, fix = 0.0; /* a NaN in the fix makes it NaN: refused */
            for (int i = 0; i < dim; i++) {
                size = fmax(size, fabs(rhs[i]));
                fix = fabs(res[i]) <= fix ? fix : fabs(res[i]);
                rhs[i] += res[i];
            }
            if (fix <= REFINE_MAX * size)
                return 0;
        }
    }
    /* The dense LU of the whole system. */
    memcpy(rhs, saved, (size_t)dim * sizeof *rhs);
    return LAPACKE_dgesv_work(LAPACK_COL_MAJOR, dim, 1, a, lda, b->piv, rhs, dim) == 0 ? 0 : -1;
}
