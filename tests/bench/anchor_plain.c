/* anchor_plain.c: a plain hand-written RK4 loop, the anchor `make bench` holds springsim's
 * headless step against (whole processes): springsim's default chain (N masses of 1 kg,
 * springs of 10 N/m, dampers of 0.1 N s/m to the ground, the right end driven 0.1 m
 * sin(2 pi t)), no contacts and no energy books. Usage: anchor_plain N DT STEPS; prints
 * x_N at the end. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

static int n;
static const double k = 10.0, c = 0.1, m = 1.0, amp = 0.1, w = 2.0 * M_PI;

static void rates(double t, const double *y, double *dy)
{
    const double *x = y, *v = y + n;
    double u = amp * sin(w * t);
    for (int i = 0; i < n; i++) {
        double l = i ? x[i - 1] : 0.0, r = i < n - 1 ? x[i + 1] : u;
        dy[i] = v[i];
        dy[n + i] = (k * (r - x[i]) - k * (x[i] - l) - c * v[i]) / m;
    }
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
    double *y = calloc((size_t)(12 * n), sizeof *y);
    if (!y)
        return 1;
    double *k1 = y + 2 * n, *k2 = k1 + 2 * n, *k3 = k2 + 2 * n, *k4 = k3 + 2 * n,
           *tmp = k4 + 2 * n;
    for (long s = 0; s < steps; s++) {
        double t = s * dt;
        rates(t, y, k1);
        for (int i = 0; i < 2 * n; i++)
            tmp[i] = y[i] + 0.5 * dt * k1[i];
        rates(t + 0.5 * dt, tmp, k2);
        for (int i = 0; i < 2 * n; i++)
            tmp[i] = y[i] + 0.5 * dt * k2[i];
        rates(t + 0.5 * dt, tmp, k3);
        for (int i = 0; i < 2 * n; i++)
            tmp[i] = y[i] + dt * k3[i];
        rates(t + dt, tmp, k4);
        for (int i = 0; i < 2 * n; i++)
            y[i] += dt / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
    }
    printf("%.9f\n", y[n - 1]);
    free(y);
    return 0;
}
