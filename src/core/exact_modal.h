/* exact_modal.h: exact.c's propagator for chains with Rayleigh's damping, C = alpha M +
 * beta K (c_i / m_i all alpha, cs_j / k_j all beta: undamped chains included): the
 * undamped modes (LAPACK's dstevr on M^(-1/2) K M^(-1/2) for the shapes, the frequencies
 * as the singular values of its bidiagonal factor) stay uncoupled under such damping, so
 * each step is the modes' own 4 x 4 exponentials (a mode and its two drive states: the
 * motor's end, its damper and the force input together) between two products with the
 * modes' matrix: O(N^2) a step, O(N) a new step length. Internal to exact.c; also home of
 * the small matrix exponential both use. */
#ifndef SPRINGSIM_EXACT_MODAL_H
#define SPRINGSIM_EXACT_MODAL_H

#include <gsl/gsl_matrix.h>

#include "exact.h"
#include "model.h"

/* The drive's form over a piece (exact.c's terms). */
enum exact_kind { EXACT_NONE, EXACT_SINE, EXACT_LINE };

struct modal;

/* Workspace for chains of n masses (about 8 n^2 + 300 n bytes), or NULL on no memory. */
struct modal *modal_new(int n);

/* Frees it. */
void modal_free(struct modal *md);

/* Makes dst (made for the same n) hold what src holds, its cached steps included. */
void modal_copy(struct modal *dst, const struct modal *src);

/* Takes in model m (its values checked by the caller: m, k > 0, c >= 0, finite) whose
 * damping is alpha M + beta K (c_i / m_i all alpha, cs_j / k_j all beta; cs_N read as the
 * end damper's input), and C, the lower bidiagonal factor of M^(-1/2) K M^(-1/2) = C C^T (diagonal ld, n; subdiagonal ls, n - 1; exact.c's, accurate entry by entry): its
 * modes, and a new generation (cached steps are stale). The frequencies are C's singular
 * values (dqds, to a few ulp each however small: a soft-mounted chain's slowest mode
 * keeps its phase), the shapes dstevr's eigenvectors. 0, or -1 when LAPACK fails or a
 * mode's frequency is not positive (the caller then uses the dense exponential). */
int modal_take(struct modal *md, const struct model *m, double alpha, double beta,
               const double *ld, const double *ls);

/* The drive's form over a piece: a sine or a line when it moves the end or drives the
 * force (the caller zeroes the end's part where no motor moves it), else EXACT_NONE. */
enum exact_kind exact_drive_kind(const struct exact_drive *d);

/* Advances x, v (n each) from a to b > a on the drive's form kind (d read for EXACT_SINE
 * and EXACT_LINE: the end's u from amp, omega, phi or u0, du, the force d->force times the
 * unit waveform, sin of the same angle or w0 + dw (t - t0), on mass on, 0-based) and adds
 * the piece's dissipation, motor work and force work to *diss, *work and *fwork, as
 * exact_advance_all does. The end's u is the caller's to zero when no motor moves it.
 * 0, or -1 (an exponential failed, a force on no mass, or a result is not finite:
 * nothing is changed). */
int modal_advance(struct modal *md, enum exact_kind kind, const struct exact_drive *d, int on,
                  double a, double b, double *x, double *v, double *diss, double *work,
                  double *fwork);

/* Which step a cached propagator holds (exact.c's and exact_general.c's caches): the
 * model's generation (0: empty), the drive's form, the sine's angular frequency (sine
 * only), the step h, ||A||, and when it was last used. */
struct exact_key {
    unsigned long model;
    enum exact_kind kind;
    double omega, h, norm;
    unsigned long used;
};

/* A step within this of a cached one, times ||A||, is that one (corrected to first order
 * by the caller): the steps of a long run differ by the rounding of their times. */
#define EXACT_REUSE 1e-8

/* Among count slots, stride bytes apart, each opening with its struct exact_key (first
 * the one at slots): the one that holds the step (model, kind, omega, h), marked used now
 * (*clock advanced); when none does, the least recently used one, emptied and marked used,
 * and *fresh set (the caller fills it and writes its key). Its index. */
int exact_key_find(void *slots, size_t stride, int count, unsigned long *clock,
                   unsigned long model, enum exact_kind kind, double omega, double h,
                   int *fresh);

/* Copies count slots' keys (laid out as for exact_key_find) from src to dst, the slots'
 * other members untouched (each keeps its own memory); all emptied unless filled (the
 * source's cached steps are in memory it copied). */
void exact_key_copy(void *dst, const void *src, size_t stride, int count, int filled);

/* expm(s) into out (square, same size); s is overwritten, t is scratch. 0 or -1. */
int exact_expm(gsl_matrix *s, gsl_matrix *out, gsl_matrix *t);

#endif
