/* anchor_gsl.c: the same chain as anchor_plain.c through GSL's rk4 as a user writes it: the
 * state's derivative with no copies, GSL's fixed-step driver taking every step. Usage:
 * anchor_gsl N DT STEPS; prints x_N at the end. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

static int n;
static const double k = 10.0, c = 0.1, m = 1.0, amp = 0.1, w = 2.0 * M_PI;

static int rates(double t, const double y[], double dy[], void *params)
{
    (void)params;
    const double *x = y, *v = y + n;
    double u = amp * sin(w * t);
    for (int i = 0; i < n; i++) {
        double l = i ? x[i - 1] : 0.0, r = i < n - 1 ? x[i + 1] : u;
        dy[i] = v[i];
        dy[n + i] = (k * (r - x[i]) - k * (x[i] - l) - c * v[i]) / m;
    }
    return GSL_SUCCESS;
}

int main(int argc, char **argv)
{
    if (argc != 4)
        return 2;
    n = atoi(argv[1]);
    double dt = atof(argv[2]);
    long steps = atol(argv[3]);
    if (n < 1 || !(dt > 0.0) || steps < 0)
        return 2;
    gsl_odeiv2_system sys = {rates, NULL, (size_t)(2 * n), NULL};
    gsl_odeiv2_driver *d = gsl_odeiv2_driver_alloc_y_new(&sys, gsl_odeiv2_step_rk4, dt, 1e-6,
                                                         0.0);
    double *y = calloc((size_t)(2 * n), sizeof *y), t = 0.0;
    if (!d || !y)
        return 1;
    if (gsl_odeiv2_driver_apply_fixed_step(d, &t, dt, (unsigned long)steps, y) != GSL_SUCCESS)
        return 1;
    printf("%.9f\n", y[n - 1]);
    free(y);
    gsl_odeiv2_driver_free(d);
    return 0;
}
