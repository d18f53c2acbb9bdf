/* clearance.h: how far every gap is from closing, carried from step to step, so that the
 * common step (RK4, no contact near) skips the per-gap look for contacts. A lower bound
 * on the least gap is taken from the state now and then, and each step lowers it by the
 * most any gap can have shrunk (twice the largest |dx| of a mass, and the piston's |du|);
 * while what is left stays clear of events_may_close's own bound, that look would say
 * "no contact" and is not taken. The step's results are the same bits either way. */
#ifndef SPRINGSIM_CLEARANCE_H
#define SPRINGSIM_CLEARANCE_H

#include <math.h>
#include <stdbool.h>

#include "collision.h"

struct clearance {
    bool valid;   /* least and speed hold for the state now */
    double least; /* every gap is at least this now (m) */
    double speed; /* every |v_i| now is at most this (m/s) */
};

/* Nothing known: the next step looks for contacts and clearance_fill starts again. */
void clearance_forget(struct clearance *c);

/* Takes the least gap and the largest |v_i| from state y (x then v, N each, all finite)
 * with the right end at u. */
void clearance_fill(struct clearance *c, const struct collision_limits *l, const double *y,
                    double u);

/* events_may_close says a gap with ends g0, g1 and rates times h s0, s1 may close when
 * min(g0, g1) - max(|s0 - dg|, |s1 - dg|) / 4 - err <= -EVENTS_TOUCH (dg = g1 - g0, err
 * the drive's straying, for the piston's gap only). A gap is a constant plus at most two
 * displacements (a pair's x_k - x_k-1, the wall's x_1, the piston's u - x_N), so in a
 * step where every mass moved at most dx and the end |ub - ua|, it changed at most
 * d = 2 dx + |ub - ua|, and from a lower bound L on every gap at the start:
 * min(g0, g1) >= L - d, |s0 - dg| <= h (2 V0 + |dua|) + d (V0: the fastest mass at the
 * start), the same at the end. So the look is not needed while
 * L - d - (d + h max(2 V0 + |dua|, 2 V1 + |dub|)) / 4 - err is clear of zero by
 * CLEARANCE_SLACK, far above the rounding of the gaps' sums (positions of metres). */
#define CLEARANCE_SLACK 1e-9 /* m */

/* A step of length h has been taken: the masses moved at most dx and end at most at
 * speed v (each |x_i| and |v_i| change, as stored), the end went from ua to ub at speeds
 * dua and dub, straying at most err from the cubic between. True when no gap could be
 * found closing in it (events_may_close would say false), and c then holds for its end;
 * false when the step must be looked at (c is forgotten). Inline: it is in every step. */
static inline bool clearance_step(struct clearance *c, double h, double dx, double v,
                                  double ua, double ub, double dua, double dub, double err)
{
    if (!c->valid)
        return false;
    double d = 2.0 * dx + fabs(ub - ua);
    double s0 = 2.0 * c->speed + fabs(dua), s1 = 2.0 * v + fabs(dub);
    double left = c->least - d;
    double q = left - 0.25 * (d + h * (s0 > s1 ? s0 : s1)) - err;
    /* !(q > slack): a NaN anywhere (a step that went bad) looks too. */
    if (!(q > CLEARANCE_SLACK)) {
        c->valid = false;
        return false;
    }
    c->least = left;
    c->speed = v;
    return true;
}

#endif
