/* anchor_gsl.c: the same chain as anchor_plain.c through GSL's rk4 as a user writes it: the
 * state's derivative with no copies, GSL's fixed-step driver taking every step. Usage:
 * anchor_gsl N DT STEPS; prints x_N at the end. */
#include <stdio.h>
#include <stdlib.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

#include "anchor_chain.h"

static int rates(double t, const double y[], double dy[], void *params)
{
    (void)params;
    chain_rates(t, y, dy);
    return GSL_SUCCESS;
}

int main(int argc, char **argv)
{
    double dt;
    long steps;
    if (chain_args(argc, argv, &dt, &steps) != 0)
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
