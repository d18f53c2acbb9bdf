/* anchor_chain.h: the chain both anchors of `make bench` step (anchor_plain.c by hand,
 * anchor_gsl.c through GSL): springsim's default chain, N masses of 1 kg, springs of
 * 10 N/m, dampers of 0.1 N s/m to the ground, the right end driven 0.1 m sin(2 pi t); the
 * derivative as a user writes it, no copies. Their arguments: N DT STEPS. */
#ifndef ANCHOR_CHAIN_H
#define ANCHOR_CHAIN_H

#include <math.h>
#include <stdlib.h>

static int n;
static const double k = 10.0, c = 0.1, m = 1.0, amp = 0.1, w = 2.0 * M_PI;

/* dy/dt of y = (x, v) at t. */
static inline void chain_rates(double t, const double *y, double *dy)
{
    const double *x = y, *v = y + n;
    double u = amp * sin(w * t);
    for (int i = 0; i < n; i++) {
        double l = i ? x[i - 1] : 0.0, r = i < n - 1 ? x[i + 1] : u;
        dy[i] = v[i];
        dy[n + i] = (k * (r - x[i]) - k * (x[i] - l) - c * v[i]) / m;
    }
}

/* N, DT and STEPS from the command line into n, *dt and *steps; 0, or -1 when they are
 * not three good values. */
static int chain_args(int argc, char **argv, double *dt, long *steps)
{
    if (argc != 4)
        return -1;
    n = atoi(argv[1]);
    *dt = atof(argv[2]);
    *steps = atol(argv[3]);
    return n >= 1 && *dt > 0.0 && *steps >= 0 ? 0 : -1;
}

#endif
