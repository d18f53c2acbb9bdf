/* model.c: parameters, equilibrium geometry and the equation of motion
 *
 *   m_i a_i = T_{i+1} - T_i - c_i v_i + [i = K] F w(2 pi f t),
 *   T_j = k_j (d_j - d_{j-1}) + cs_j (v_j - v_{j-1}),
 *
 * T_j the tension of spring j and its damper, with d_{-1} = v_{-1} = 0 (left wall) and
 * d_N = u(t), v_N = u'(t) (right end); for a free end T_N = 0. A cubic spring adds
 * k3_j s^3 to its force k_j s (s its stretch) and k3_j s^4/4 to its energy. */
#include "model.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

static const char *const boundary_names[BOUNDARY_COUNT] = {"motor", "wall", "free"};

const char *model_boundary_name(enum boundary b)
{
    return (unsigned)b < BOUNDARY_COUNT ? boundary_names[b] : NULL;
}

int model_boundary_parse(const char *s)
{
    for (int i = 0; i < BOUNDARY_COUNT; i++)
        if (strcmp(s, boundary_names[i]) == 0)
            return i;
    return -1;
}

struct model *model_new(int n)
{
    if (n < 1 || n > MODEL_MAX_MASSES)
        return NULL;
    struct model *m = calloc(1, sizeof *m);
    double *buf = calloc((size_t)(5 * n + 3), sizeof *buf);
    if (!m || !buf) {
        free(m);
        free(buf);
        return NULL;
    }
    m->n = n;
    m->m = buf;
    m->k = buf + n;
    m->c = buf + 2 * n + 1;
    m->cs = buf + 3 * n + 1; /* zeros: no spring dampers */
    m->k3 = buf + 4 * n + 2; /* zeros: linear springs */
    for (int i = 0; i < n; i++) {
        m->m[i] = MODEL_DEFAULT_MASS;
        m->c[i] = MODEL_DEFAULT_DAMPING;
    }
    for (int j = 0; j <= n; j++)
        m->k[j] = MODEL_DEFAULT_SPRING;
    m->boundary = BOUNDARY_MOTOR;
    m->motor = (struct motor){WAVE_SINE, MODEL_DEFAULT_AMPLITUDE, MODEL_DEFAULT_FREQUENCY, 0.0};
    m->collisions = true;
    return m;
}

void model_free(struct model *m)
{
    if (m)
        free(m->m);
    free(m);
}

void model_copy(struct model *dst, const struct model *src)
{
    int n = src->n;
    memcpy(dst->m, src->m, (size_t)n * sizeof *dst->m);
    memcpy(dst->k, src->k, (size_t)(n + 1) * sizeof *dst->k);
    memcpy(dst->c, src->c, (size_t)n * sizeof *dst->c);
    memcpy(dst->cs, src->cs, (size_t)(n + 1) * sizeof *dst->cs);
    memcpy(dst->k3, src->k3, (size_t)(n + 1) * sizeof *dst->k3);
    dst->force = src->force;
    dst->force_on = src->force_on;
    dst->boundary = src->boundary;
    dst->motor = src->motor;
    dst->collisions = src->collisions;
    model_sync(dst);
}

void model_sync(struct model *m)
{
    m->spring_damped = false;
    for (int j = 0; j <= m->n; j++)
        m->spring_damped |= m->cs[j] != 0.0;
    model_set_cubic(m);
}

int model_rigid_modes(const struct model *m)
{
    int n = m->n, rigid = 0;
    bool right_tied = m->boundary != BOUNDARY_FREE && m->k[n] > 0.0;
    bool grounded = m->k[0] > 0.0; /* the group that holds mass 1 */
    for (int i = 0; i < n; i++) {
        bool joined = i + 1 < n && m->k[i + 1] > 0.0;
        if (!joined) { /* the group ends at mass i */
            if (i + 1 == n)
                grounded |= right_tied;
            rigid += !grounded;
            grounded = false;
        }
    }
    return rigid;
}

/* Whether a / b is r for every pair, to rounding; b = 0 needs a = 0. *r NAN: not set. */
static bool same_ratio(double a, double b, double *r)
{
    if (b == 0.0)
        return a == 0.0;
    double q = a / b;
    if (isnan(*r))
        *r = q;
    return fabs(q - *r) <= 8.0 * DBL_EPSILON * fabs(*r);
}

bool model_rayleigh(const struct model *m)
{
    double alpha = NAN, beta = NAN;
    for (int i = 0; i < m->n; i++)
        if (!same_ratio(m->c[i], m->m[i], &alpha))
            return false;
    for (int j = 0; j <= m->n; j++)
        if ((j < m->n || m->boundary != BOUNDARY_FREE) && !same_ratio(m->cs[j], m->k[j], &beta))
            return false;
    return true;
}

bool model_forced(const struct model *m)
{
    return m->force != 0.0;
}

bool model_motor_moves(const struct model *m)
{
    return m->boundary == BOUNDARY_MOTOR && m->motor.amplitude != 0.0;
}

bool model_driven(const struct model *m)
{
    return model_motor_moves(m) || model_forced(m);
}

double model_force(const struct model *m, double t)
{
    if (m->force == 0.0)
        return 0.0;
    return m->force * motor_wave(m->motor.wave, m->motor.frequency * t + m->motor.phase);
}

void model_rates_damped_springs(const struct model *m, const double *inv_m, const double *x,
                                const double *v, double u, double du, double *a, double *diss,
                                double *work)
{
    int n = m->n;
    const double *c = m->c, *cs = m->cs;
    /* T_j = k_j s_j + k3_j s_j^3 + cs_j s_j' (s_j the stretch); the dampers' loss
     * cs_j s_j'^2 */
    double left = model_spring_force(m, 0, x[0]) + cs[0] * v[0], d = cs[0] * v[0] * v[0];
    for (int i = 0; i < n; i++) {
        double right = 0.0, rate = 0.0;
        if (i < n - 1) {
            rate = v[i + 1] - v[i];
            right = model_spring_force(m, i + 1, x[i + 1] - x[i]) + cs[i + 1] * rate;
        } else if (m->boundary != BOUNDARY_FREE) {
            rate = du - v[i];
            right = model_spring_force(m, n, u - x[i]) + cs[n] * rate;
        }
        double fd = c[i] * v[i];
        a[i] = inv_m ? (right - left - fd) * inv_m[i] : (right - left - fd) / m->m[i];
        d += fd * v[i] + (i < n - 1 || m->boundary != BOUNDARY_FREE ? cs[i + 1] * rate * rate : 0.0);
        if (i == n - 1 && work)
            *work = right * du;
        left = right;
    }
    if (diss)
        *diss = d;
}

double model_equilibrium(const struct model *m, int i)
{
    return (i + 1) * MODEL_LENGTH / (m->n + 1);
}

double model_block_width(const struct model *m)
{
    double half = 0.5 * MODEL_LENGTH / (m->n + 1);
    return half < MODEL_BLOCK ? half : MODEL_BLOCK;
}

double model_end_position(const struct model *m, double t)
{
    return m->boundary == BOUNDARY_MOTOR ? motor_position(&m->motor, t) : 0.0;
}

void model_set_cubic(struct model *m)
{
    m->cubic = false;
    for (int j = 0; j <= m->n; j++)
        m->cubic |= m->k3[j] != 0.0;
}

double model_turnover(const struct model *m, int *spring)
{
    double least = INFINITY;
    for (int j = 0; j <= m->n; j++)
        if (m->k3[j] < 0.0 && sqrt(m->k[j] / (-3.0 * m->k3[j])) < least) {
            least = sqrt(m->k[j] / (-3.0 * m->k3[j]));
            *spring = j;
        }
    return least;
}

bool model_hardening(const struct model *m)
{
    for (int j = 0; j <= m->n; j++)
        if (m->k3[j] > 0.0)
            return true;
    return false;
}

void model_rates_cubic(const struct model *m, const double *inv_m, const double *x,
                       const double *v, double u, double du, double *a, double *diss,
                       double *work)
{
    int n = m->n;
    const double *c = m->c;
    double left = model_spring_force(m, 0, x[0]), d = 0.0;
    for (int i = 0; i < n - 1; i++) {
        double right = model_spring_force(m, i + 1, x[i + 1] - x[i]);
        double fd = c[i] * v[i];
        a[i] = inv_m ? (right - left - fd) * inv_m[i] : (right - left - fd) / m->m[i];
        d += fd * v[i];
        left = right;
    }
    int i = n - 1;
    double right = m->boundary == BOUNDARY_FREE ? 0.0 : model_spring_force(m, n, u - x[i]);
    double fd = c[i] * v[i];
    a[i] = inv_m ? (right - left - fd) * inv_m[i] : (right - left - fd) / m->m[i];
    if (diss)
        *diss = d + fd * v[i];
    if (work)
        *work = right * du;
}

void model_accel_span(const struct model *m, const double *x, const double *v, double u,
                      double du, int lo, int hi, double *a)
{
    int n = m->n;
    bool damped = m->spring_damped, free_end = m->boundary == BOUNDARY_FREE;
    const double *cs = m->cs;
    /* Each value as model_rates makes it: its two springs' tensions (with the spring
     * dampers' terms whenever the chain has any, as model_rates' general path does) less
     * its own damper's. */
    double left = lo == 0 ? model_spring_force(m, 0, x[0])
                          : model_spring_force(m, lo, x[lo] - x[lo - 1]);
    if (damped)
        left += cs[lo] * (lo == 0 ? v[0] : v[lo] - v[lo - 1]);
    for (int i = lo; i <= hi; i++) {
        double right = 0.0;
        if (i < n - 1) {
            right = model_spring_force(m, i + 1, x[i + 1] - x[i]);
            if (damped)
                right += cs[i + 1] * (v[i + 1] - v[i]);
        } else if (!free_end) {
            right = model_spring_force(m, n, u - x[i]);
            if (damped)
                right += cs[n] * (du - v[i]);
        }
        double fd = m->c[i] * v[i]; /* rounded by itself, as there (no fused multiply-add) */
        a[i] = (right - left - fd) / m->m[i];
        left = right;
    }
}

void model_accel(const struct model *m, const double *x, const double *v, double u, double *a)
{
    model_rates(m, NULL, x, v, u, 0.0, a, NULL, NULL);
}

double model_potential(const struct model *m, const double *x, double u)
{
    int n = m->n;
    double e = model_spring_energy(m, 0, x[0]);
    for (int j = 1; j < n; j++)
        e += model_spring_energy(m, j, x[j] - x[j - 1]);
    if (m->boundary != BOUNDARY_FREE)
        e += model_spring_energy(m, n, u - x[n - 1]);
    return e;
}

double model_kinetic(const struct model *m, const double *v)
{
    double e = 0.0;
    for (int i = 0; i < m->n; i++)
        e += m->m[i] * v[i] * v[i];
    return 0.5 * e;
}

/* Built column by column from the one equation of motion: column j of -M^-1 K is the
 * acceleration of a unit displacement of mass j (right end held at 0), column j of
 * -M^-1 C that of a unit velocity; cubic springs left out (the chain linearised at rest). */
int model_first_order(const struct model *lin, double *a, double *work)
{
    struct model linear = *lin;
    linear.cubic = false;
    const struct model *m = &linear;
    int n = m->n, n2 = 2 * n;
    double *x = work, *v = work + n, *acc = work + 2 * n;
    memset(a, 0, (size_t)n2 * (size_t)n2 * sizeof *a);
    memset(x, 0, (size_t)n * sizeof *x);
    memset(v, 0, (size_t)n * sizeof *v);
    for (int j = 0; j < n; j++) {
        a[j + (size_t)(n + j) * n2] = 1.0; /* x' = v */
        x[j] = 1.0;
        model_rates(m, NULL, x, v, 0.0, 0.0, acc, NULL, NULL);
        x[j] = 0.0;
        for (int i = 0; i < n; i++)
            a[n + i + (size_t)j * n2] = acc[i];
        v[j] = 1.0;
        model_rates(m, NULL, x, v, 0.0, 0.0, acc, NULL, NULL);
        v[j] = 0.0;
        for (int i = 0; i < n; i++)
            a[n + i + (size_t)(n + j) * n2] = acc[i];
    }
    for (size_t k = 0; k < (size_t)n2 * (size_t)n2; k++)
        if (!isfinite(a[k]))
            return -2;
    return 0;
}
