/* bordered.h: linear systems whose leading block is banded, bordered by one dense row and
 * column (a continuation's Jacobian with its arclength row), solved in O(n) by block
 * elimination on LAPACK's banded LU, and by the dense LU where that block is near
 * singular (at a fold) or the elimination's pivot vanishes. */
#ifndef SPRINGSIM_BORDERED_H
#define SPRINGSIM_BORDERED_H

#include <stdbool.h>

#include <lapacke.h>

/* The room for systems of a banded block of order n, kl sub- and ku super-diagonals. */
struct bordered {
    int n, kl, ku, ldab;
    double *ab;      /* the band, LAPACK's layout (ldab x n) */
    double *col;     /* the border column solved through the band (n) */
    lapack_int *piv; /* n + 1 */
};

/* 0, or -1 without memory. */
int bordered_init(struct bordered *b, int n, int kl, int ku);
void bordered_free(struct bordered *b);

/* Solves a x = rhs in place (rhs becomes x). a: column-major with leading dimension lda,
 * its leading n x n block banded as b says (zeros outside the band); with border,
 * the system is (n + 1) x (n + 1) and row and column n are dense. a may be overwritten
 * (by the dense fallback). 0, or -1 when the system is singular. */
int bordered_solve(struct bordered *b, double *a, int lda, bool border, double *rhs);

#endif
