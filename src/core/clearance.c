/* clearance.c: the least gap carried from step to step (clearance.h). */
#include "clearance.h"

#include <math.h>

void clearance_forget(struct clearance *c)
{
    c->valid = false;
}

void clearance_fill(struct clearance *c, const struct collision_limits *l, const double *y,
                    double u)
{
    int n = l->n;
    const double *x = y, *v = y + n;
    double least = l->wall + x[0];
    if (l->count > n) {
        double face = l->face + u - x[n - 1];
        least = face < least ? face : least;
    }
    /* Each pair's gap is pair + x_k - x_k-1: the least of x_k - x_k-1 plus pair. */
    double step = INFINITY, speed = fabs(v[0]);
    for (int k = 1; k < n; k++) {
        double d = x[k] - x[k - 1], a = fabs(v[k]);
        step = d < step ? d : step;
        speed = a > speed ? a : speed;
    }
    if (n > 1)
        least = fmin(least, l->pair + step);
    c->valid = true;
    c->least = least;
    c->speed = speed;
}
