/* stability.c: stability limits of long chains (stability.h).
 *
 * Why mu = -1 is where semi-implicit and verlet fail. With mu an eigenvalue of the step
 * and x the positions of its eigenvector, eliminating the velocities gives
 *   semi-implicit: (mu - 1)^2 M x + h (mu - 1) C x + h^2 mu K x = 0,
 *   verlet:        (mu - 1)^2 M x + (h/2) (mu^2 - 1) C x + h^2 mu K x = 0
 * (verlet's uses that M and C are diagonal, so commute). For |mu| = 1, mu = e^{i theta},
 * divide by mu and multiply by x*: (2 cos theta - 2) m + i h sin(theta) c' + h^2 k = 0
 * with m = x*Mx > 0, k = x*Kx >= 0 and c' = x*Cx (semi-implicit: also a real part
 * h (1 - cos theta) c). Its imaginary part needs sin(theta) = 0 or Cx = 0, and with
 * Cx = 0 x is an undamped mode met at h omega = 2 sin(theta/2) <= 2, which leaves the
 * circle only at theta = pi. mu = +1 needs Kx = 0: a free chain's rigid motion, neutral.
 * An eigenvalue leaves the unit disc only by crossing it, so every h below the first
 * h with mu = -1 is stable: at mu = -1, semi-implicit's equation is
 * (h^2 K + 2 h C - 4 M) x = 0, verlet's (h^2 K - 4 M) x = 0. */
#include "stability.h"

#include <math.h>

#define BISECTIONS 60

/* Whether h^2 K + 2 h C - 4 M is negative definite: every pivot of its LDL^T negative
 * (Sylvester's law of inertia; the matrix is tridiagonal). */
static bool negative_definite(const struct model *m, double h)
{
    int n = m->n;
    double prev = 0.0, off = 0.0; /* the last pivot and the entry left of the diagonal */
    for (int i = 0; i < n; i++) {
        bool end = i + 1 == n && m->boundary == BOUNDARY_FREE;
        double right = end ? 0.0 : m->k[i + 1], cright = end ? 0.0 : m->cs[i + 1];
        double diag = h * h * (m->k[i] + right) + 2.0 * h * (m->c[i] + m->cs[i] + cright) -
                      4.0 * m->m[i];
        double d = i == 0 ? diag : diag - off * off / prev;
        if (!(d < 0.0))
            return false;
        prev = d;
        /* T[i][i+1] = -h^2 k_{i+1} - 2 h cs_{i+1}: C is tridiagonal with spring dampers */
        off = -h * h * right - 2.0 * h * cright;
    }
    return true;
}

double stability_semi_implicit(const struct model *m)
{
    double lo = 0.0, hi = 1e-9;
    int k = 0;
    while (negative_definite(m, hi)) {
        lo = hi;
        hi *= 2.0;
        if (++k > 200)
            return INFINITY;
    }
    for (k = 0; k < BISECTIONS; k++) {
        double mid = 0.5 * (lo + hi);
        if (negative_definite(m, mid))
            lo = mid;
        else
            hi = mid;
    }
    return lo;
}

double stability_verlet(double w2_max)
{
    return w2_max > 0.0 ? 2.0 / sqrt(w2_max) : INFINITY;
}

/* Samples count points from a to b (both ends included) into v. */
static void spread(double a, double b, int count, double *v)
{
    for (int k = 0; k < count; k++)
        v[k] = count > 1 ? a + (b - a) * k / (count - 1) : a;
}

int stability_region_modes(const struct model *m, double w2_min, double w2_max, int count,
                           double *w2, double *s)
{
    double g0 = INFINITY, g1 = 0.0;
    for (int i = 0; i < m->n; i++) {
        g0 = fmin(g0, m->c[i] / m->m[i]);
        g1 = fmax(g1, m->c[i] / m->m[i]);
    }
    double s0 = 0.5 * g0, s1 = 0.5 * g1, r0 = sqrt(fmax(w2_min, 0.0)), r1 = sqrt(w2_max);
    int side = count / 5, k = 0;
    /* The rectangle's four sides in (s, sqrt(w2)), then the critical parabola w2 = s^2
     * inside it, where the two roots meet and turn real. */
    for (int e = 0; e < 4; e++) {
        double *v = e < 2 ? w2 + k : s + k, *fixed = e < 2 ? s + k : w2 + k;
        spread(e < 2 ? r0 : s0, e < 2 ? r1 : s1, side, v);
        for (int j = 0; j < side; j++) {
            if (e < 2)
                v[j] *= v[j];
            fixed[j] = e == 0 ? s0 : e == 1 ? s1 : e == 2 ? w2_min : w2_max;
        }
        k += side;
    }
    double p0 = fmax(s0, r0), p1 = fmin(s1, r1);
    bool crosses = p0 <= p1;
    spread(crosses ? p0 : s1, crosses ? p1 : s1, count - k, s + k);
    for (; k < count; k++)
        w2[k] = crosses ? s[k] * s[k] : w2_max; /* without a crossing: one more corner */
    return count;
}
