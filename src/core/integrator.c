/* integrator.c: names and orders of the integrators, and each one's step on a single
 * damped mode (for the stability and accuracy limits). */
#include "integrator.h"

#include <math.h>
#include <string.h>

static const char *const names[INTEGRATOR_COUNT] = {
    [INTEGRATOR_EULER] = "euler",   [INTEGRATOR_SEMI_IMPLICIT] = "semi-implicit",
    [INTEGRATOR_VERLET] = "verlet", [INTEGRATOR_RK4] = "rk4",
    [INTEGRATOR_EXACT] = "exact",
};

const char *integrator_name(enum integrator i)
{
    return (unsigned)i < INTEGRATOR_COUNT ? names[i] : NULL;
}

int integrator_parse(const char *s)
{
    for (int i = 0; i < INTEGRATOR_COUNT; i++)
        if (strcmp(s, names[i]) == 0)
            return i;
    return -1;
}

int integrator_order(enum integrator i)
{
    static const int order[INTEGRATOR_COUNT] = {1, 1, 2, 4, 0};
    return (unsigned)i < INTEGRATOR_COUNT ? order[i] : 0;
}

/* The mode's acceleration. */
static double acc(double w2, double s, double x, double v)
{
    return -w2 * x - 2.0 * s * v;
}

/* One step from (x, v), exactly as the integrator's stepper takes it. */
static void step(enum integrator i, double w2, double s, double h, double *x, double *v)
{
    double x0 = *x, v0 = *v;
    switch (i) {
    case INTEGRATOR_EULER:
        *x = x0 + h * v0;
        *v = v0 + h * acc(w2, s, x0, v0);
        return;
    case INTEGRATOR_SEMI_IMPLICIT:
        *v = v0 + h * acc(w2, s, x0, v0);
        *x = x0 + h * *v;
        return;
    case INTEGRATOR_VERLET: {
        /* Half kick, drift, half kick with the damping at the new velocity, solved for. */
        double vh = v0 + 0.5 * h * acc(w2, s, x0, v0);
        *x = x0 + h * vh;
        *v = (vh - 0.5 * h * w2 * *x) / (1.0 + h * s);
        return;
    }
    case INTEGRATOR_RK4: {
        double k1x = v0, k1v = acc(w2, s, x0, v0);
        double k2x = v0 + 0.5 * h * k1v, k2v = acc(w2, s, x0 + 0.5 * h * k1x, v0 + 0.5 * h * k1v);
        double k3x = v0 + 0.5 * h * k2v, k3v = acc(w2, s, x0 + 0.5 * h * k2x, v0 + 0.5 * h * k2v);
        double k4x = v0 + h * k3v, k4v = acc(w2, s, x0 + h * k3x, v0 + h * k3v);
        *x = x0 + h / 6.0 * (k1x + 2.0 * k2x + 2.0 * k3x + k4x);
        *v = v0 + h / 6.0 * (k1v + 2.0 * k2v + 2.0 * k3v + k4v);
        return;
    }
    case INTEGRATOR_EXACT:
    case INTEGRATOR_COUNT:
        break;
    }
    /* Exact: the damped oscillator's own solution over h. */
    double d = w2 - s * s, e = exp(-s * h), cs, sn_over;
    if (d > 0) {
        double wd = sqrt(d);
        cs = cos(wd * h);
        sn_over = sin(wd * h) / wd;
    } else if (d < 0) {
        double wd = sqrt(-d);
        cs = cosh(wd * h);
        sn_over = sinh(wd * h) / wd;
    } else {
        cs = 1.0;
        sn_over = h;
    }
    *x = e * (x0 * (cs + s * sn_over) + v0 * sn_over);
    *v = e * (v0 * (cs - s * sn_over) - x0 * w2 * sn_over);
}

void integrator_mode_step(enum integrator i, double w2, double s, double h, double m[4])
{
    double x = 1.0, v = 0.0;
    step(i, w2, s, h, &x, &v);
    m[0] = x, m[2] = v;
    x = 0.0, v = 1.0;
    step(i, w2, s, h, &x, &v);
    m[1] = x, m[3] = v;
}
