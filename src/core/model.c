/* model.c: parameters, equilibrium geometry and the equation of motion
 *
 *   m_i a_i = -k_i (d_i - d_{i-1}) - k_{i+1} (d_i - d_{i+1}) - c_i v_i,
 *
 * with d_{-1} = 0 (left wall) and d_N = u(t) (right end); for a free end the
 * k_N term of the last mass is dropped. A cubic spring adds k3_j s^3 to its force k_j s
 * (s its stretch) and k3_j s^4/4 to its energy. */
#include "model.h"

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
    double *buf = malloc((size_t)(4 * n + 2) * sizeof *buf);
    if (!m || !buf) {
        free(m);
        free(buf);
        return NULL;
    }
    m->n = n;
    m->m = buf;
    m->k = buf + n;
    m->c = buf + 2 * n + 1;
    m->k3 = buf + 3 * n + 1;
    for (int i = 0; i < n; i++) {
        m->m[i] = MODEL_DEFAULT_MASS;
        m->c[i] = MODEL_DEFAULT_DAMPING;
    }
    for (int j = 0; j <= n; j++) {
        m->k[j] = MODEL_DEFAULT_SPRING;
        m->k3[j] = 0.0;
    }
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
    memcpy(dst->k3, src->k3, (size_t)(n + 1) * sizeof *dst->k3);
    dst->cubic = src->cubic;
    dst->boundary = src->boundary;
    dst->motor = src->motor;
    dst->collisions = src->collisions;
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
