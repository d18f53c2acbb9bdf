/* anchor_plain.c: a plain hand-written RK4 loop, the anchor `make bench` holds springsim's
 * headless step against (whole processes): anchor_chain.h's chain, no contacts and no
 * energy books. Usage: anchor_plain N DT STEPS; prints x_N at the end. */
#include <stdio.h>
#include <stdlib.h>

#include "anchor_chain.h"

int main(int argc, char **argv)
{
    double dt;
    long steps;
    if (chain_args(argc, argv, &dt, &steps) != 0)
        return 2;
    double *y = calloc((size_t)(12 * n), sizeof *y);
    if (!y)
        return 1;
    double *k1 = y + 2 * n, *k2 = k1 + 2 * n, *k3 = k2 + 2 * n, *k4 = k3 + 2 * n,
           *tmp = k4 + 2 * n;
    for (long s = 0; s < steps; s++) {
        double t = s * dt;
        chain_rates(t, y, k1);
        for (int i = 0; i < 2 * n; i++)
            tmp[i] = y[i] + 0.5 * dt * k1[i];
        chain_rates(t + 0.5 * dt, tmp, k2);
        for (int i = 0; i < 2 * n; i++)
            tmp[i] = y[i] + 0.5 * dt * k2[i];
        chain_rates(t + 0.5 * dt, tmp, k3);
        for (int i = 0; i < 2 * n; i++)
            tmp[i] = y[i] + dt * k3[i];
        chain_rates(t + dt, tmp, k4);
        for (int i = 0; i < 2 * n; i++)
            y[i] += dt / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
    }
    printf("%.9f\n", y[n - 1]);
    free(y);
    return 0;
}
