/* modes.c: eigen-analysis and frequency response through LAPACK.
 *
 * K phi = w^2 M phi with K tridiagonal (K_ii = k_i + k_{i+1}, K_{i,i+1} = -k_{i+1}; a free
 * end drops k_N from the last diagonal entry) becomes, with z = M^(1/2) phi, the
 * symmetric tridiagonal problem M^(-1/2) K M^(-1/2) z = w^2 z: LAPACK dstev (dstevr,
 * O(N^2), where the modal damping needs every vector of a long chain). Springs of k = 0
 * leave K singular: each group of masses nothing ties to a wall or the end has a
 * rigid-body mode, 0 Hz exactly (model_rigid_modes). The steady state under the drive
 * w = sin(w t) solves the complex tridiagonal system (K - w^2 M + i w C) X = G,
 * C tridiagonal with spring dampers, G = (k_N + i w cs_N) A e_N + F e_K (the motor end's
 * spring and damper, the force): LAPACK zgtsv. The damped modes are in damped.c. */
#include "modes.h"

#include <complex.h>
#include <stdbool.h>
#include <math.h>
#include <stdlib.h>

#include <lapacke.h>

/* Diagonal of K. */
static double k_diag(const struct model *m, int i)
{
    double d = m->k[i];
    if (i < m->n - 1 || m->boundary != BOUNDARY_FREE)
        d += m->k[i + 1];
    return d;
}

/* Symmetric tridiagonal M^(-1/2) K M^(-1/2): diagonal d[n], off-diagonal e[n-1]. */
static void scaled_k(const struct model *m, double *d, double *e)
{
    int n = m->n;
    for (int i = 0; i < n; i++)
        d[i] = k_diag(m, i) / m->m[i];
    for (int i = 0; i + 1 < n; i++)
        e[i] = -m->k[i + 1] / sqrt(m->m[i] * m->m[i + 1]);
}

int modes_compute(const struct model *m, double *freq, double *shapes)
{
    int n = m->n;
    double *e = malloc((size_t)(n > 1 ? n - 1 : 1) * sizeof *e);
    double *z = shapes ? malloc((size_t)n * (size_t)n * sizeof *z) : NULL;
    if (!e || (shapes && !z)) {
        free(e);
        free(z);
        return -1;
    }
    scaled_k(m, freq, e);
    lapack_int info = LAPACKE_dstev(LAPACK_COL_MAJOR, shapes ? 'V' : 'N', n, freq, e, z, n);
    free(e);
    if (info != 0) {
        free(z);
        return (int)info;
    }
    int rigid = model_rigid_modes(m);
    for (int j = 0; j < n; j++) {
        if (!isfinite(freq[j])) { /* the values overflowed: no answer, not a wrong one */
            free(z);
            return -2;
        }
        /* a rigid-body mode is 0 Hz exactly, not dstev's rounding about 0 */
        freq[j] = j < rigid ? 0.0 : sqrt(freq[j] > 0.0 ? freq[j] : 0.0) / (2.0 * M_PI);
    }
    if (shapes) {
        /* Column j of z is eigenvector j; phi = M^(-1/2) z. */
        for (int j = 0; j < n; j++) {
            double *phi = shapes + (size_t)j * n;
            double top = 0.0;
            for (int i = 0; i < n; i++) {
                phi[i] = z[(size_t)j * n + i] / sqrt(m->m[i]);
                top = fmax(top, fabs(phi[i]));
            }
            /* Among components equal in size up to rounding, the first decides the sign,
             * so symmetric shapes come out the same on every machine. */
            int big = 0;
            while (fabs(phi[big]) < top * (1.0 - 1e-9))
                big++;
            double scale = 1.0 / phi[big];
            for (int i = 0; i < n; i++) {
                phi[i] *= scale;
                if (fabs(phi[i]) < 1e-12)
                    phi[i] = 0.0; /* a node, not rounding noise */
            }
            phi[big] = 1.0;
        }
        free(z);
    }
    return 0;
}

/* modes_modal when every c_i / m_i is the same. */
static int modal_uniform(const struct model *m, double *w2, double *s)
{
    int n = m->n;
    double *d = malloc((size_t)(2 * n) * sizeof *d);
    lapack_int found = 0, info = -1;
    if (d) {
        scaled_k(m, d, d + n);
        info = LAPACKE_dstevr(LAPACK_COL_MAJOR, 'N', 'A', n, d, d + n, 0.0, 0.0, 0, 0, 0.0,
                              &found, w2, NULL, 1, NULL);
        if (info == 0 && found != n)
            info = -2;
    }
    for (int j = 0; info == 0 && j < n; j++) {
        s[j] = 0.5 * (m->c[0] / m->m[0]);
        if (!isfinite(w2[j]) || !isfinite(s[j]))
            info = -2;
    }
    free(d);
    return (int)info;
}

int modes_modal(const struct model *m, double *w2, double *s)
{
    int n = m->n;
    /* Equal damping per unit mass, c_i / m_i = r, and no spring dampers: C = r M is diagonal in every basis of
     * modes, phi^T C phi = r phi^T M phi, so s_j = r / 2 and the shapes are not needed
     * (dstevr without vectors: 0.16e9 instructions fewer at N = 1000). */
    bool uniform = true;
    for (int j = 0; j <= n; j++)
        uniform &= m->cs[j] == 0.0; /* a damper beside a spring is not r M */
    for (int i = 1; i < n; i++)
        uniform &= m->c[i] / m->m[i] == m->c[0] / m->m[0];
    if (uniform)
        return modal_uniform(m, w2, s);
    double *d = malloc((size_t)(2 * n) * sizeof *d);
    double *z = malloc((size_t)n * (size_t)n * sizeof *z);
    lapack_int *support = malloc((size_t)(2 * n) * sizeof *support);
    lapack_int found = 0, info = -1;
    if (d && z && support) {
        double *e = d + n;
        scaled_k(m, d, e);
        info = LAPACKE_dstevr(LAPACK_COL_MAJOR, 'V', 'A', n, d, e, 0.0, 0.0, 0, 0, 0.0, &found,
                              w2, z, n, support);
        if (info == 0 && found != n)
            info = -2;
    }
    /* z_j = M^(1/2) phi_j with |z_j| = 1: phi^T M phi = 1, and phi^T C phi the ground
     * dampers' sum c_i phi_i^2 and each spring damper's cs_j (phi_j - phi_(j-1))^2. */
    int rigid = info == 0 ? model_rigid_modes(m) : 0;
    for (int j = 0; info == 0 && j < n; j++) {
        const double *zj = z + (size_t)j * n;
        double cc = 0.0, prev = 0.0;
        for (int i = 0; i < n; i++) {
            double phi = zj[i] / sqrt(m->m[i]), rate = phi - prev;
            cc += m->c[i] * phi * phi + m->cs[i] * rate * rate;
            prev = phi;
        }
        if (m->boundary != BOUNDARY_FREE)
            cc += m->cs[n] * prev * prev;
        s[j] = 0.5 * cc;
        if (j < rigid)
            w2[j] = 0.0;
        if (!isfinite(w2[j]) || !isfinite(s[j]))
            info = -2;
    }
    free(d);
    free(z);
    free(support);
    return (int)info;
}

int modes_response_phase(const struct model *m, double freq_hz, double *amp, double *phase_deg)
{
    int n = m->n;
    bool forced = model_forced(m);
    if (m->boundary != BOUNDARY_MOTOR && !forced) {
        for (int i = 0; i < n; i++) {
            amp[i] = 0.0;
            if (phase_deg)
                phase_deg[i] = 0.0;
        }
        return 0;
    }
    lapack_complex_double *buf = malloc((size_t)(4 * n) * sizeof *buf);
    if (!buf)
        return -1;
    lapack_complex_double *dl = buf, *d = buf + n, *du = buf + 2 * n, *b = buf + 3 * n;
    double w = 2.0 * M_PI * freq_hz;
    for (int i = 0; i < n; i++) {
        bool right = i < n - 1 || m->boundary != BOUNDARY_FREE;
        double cd = m->c[i] + m->cs[i] + (right ? m->cs[i + 1] : 0.0);
        d[i] = k_diag(m, i) - w * w * m->m[i] + I * w * cd;
        b[i] = 0.0;
        if (i + 1 < n)
            dl[i] = du[i] = -m->k[i + 1] - I * w * m->cs[i + 1];
    }
    /* The end's spring and damper, k_N u + cs_N u' = (k_N + i w cs_N) u, and the force. A
     * motor alone is a unit drive, scaled after: the phase is there even at amplitude 0. */
    double scale = m->motor.amplitude;
    if (m->boundary == BOUNDARY_MOTOR)
        b[n - 1] = (m->k[n] + I * w * m->cs[n]) * (forced ? m->motor.amplitude : 1.0);
    if (forced) {
        b[m->force_on] += m->force;
        scale = 1.0;
    }
    lapack_int info = LAPACKE_zgtsv(LAPACK_COL_MAJOR, n, 1, dl, d, du, b, n);
    scale *= motor_fundamental(m->motor.wave); /* the drive's first harmonic */
    for (int i = 0; info == 0 && i < n; i++) {
        amp[i] = cabs(b[i]) * scale;
        if (phase_deg) {
            /* carg is in [-pi, pi]: -180 (a real negative X with Im -0) is 180. */
            double p = carg(b[i]) * (180.0 / M_PI);
            phase_deg[i] = p <= -180.0 ? p + 360.0 : p + 0.0; /* + 0.0: no -0 */
        }
    }
    free(buf);
    return (int)info;
}

int modes_response(const struct model *m, double freq_hz, double *amp)
{
    return modes_response_phase(m, freq_hz, amp, NULL);
}

void modes_energy(const struct model *m, const double *freq, const double *shapes,
                  const double *x, const double *v, double *energy)
{
    int n = m->n;
    for (int j = 0; j < n; j++) {
        const double *phi = shapes + (size_t)j * n;
        double norm = 0.0, q = 0.0, p = 0.0;
        for (int i = 0; i < n; i++) {
            double mp = m->m[i] * phi[i];
            norm += mp * phi[i];
            q += mp * x[i];
            p += mp * v[i];
        }
        /* With phi^ = phi / sqrt(norm): q^ = q / sqrt(norm), p^ = p / sqrt(norm). */
        double w = 2.0 * M_PI * freq[j];
        energy[j] = 0.5 * (p * p + w * w * q * q) / norm;
    }
}

int modes_start(const struct model *m, int k, double amp, double *x0)
{
    int n = m->n;
    if (k < 1 || k > n)
        return -2;
    double *buf = malloc((size_t)n * (size_t)(n + 1) * sizeof *buf);
    if (!buf)
        return -1;
    int e = modes_compute(m, buf, buf + n);
    for (int i = 0; e == 0 && i < n; i++)
        x0[i] = amp * buf[n + (size_t)(k - 1) * n + i] + 0.0; /* + 0.0: amp 0 gives no -0 */
    free(buf);
    return e;
}

int modes_nearest(const double *f, int n, double freq)
{
    int best = 0;
    for (int j = 1; j < n; j++)
        if (fabs(f[j] - freq) < fabs(f[best] - freq))
            best = j;
    return best;
}
