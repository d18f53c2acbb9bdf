/* testutil.h: what every cmocka test program here needs, and small helpers. */
#ifndef SPRINGSIM_TESTUTIL_H
#define SPRINGSIM_TESTUTIL_H

#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <math.h>
#include <stdio.h>

/* Fails unless |got - want| <= tol, printing both. */
#define assert_close(got, want, tol)                                                       \
    do {                                                                                   \
        double g_ = (got), w_ = (want), t_ = (tol);                                        \
        if (!(fabs(g_ - w_) <= t_))                                                        \
            fail_msg("%s = %.15g, expected %.15g within %.3g", #got, g_, w_, t_);          \
    } while (0)

/* A number in [lo, hi) from the xorshift64 generator in *state: the same sequence on
 * every machine, so a random campaign's case j is the same case everywhere. */
static inline double test_uniform(uint64_t *state, double lo, double hi)
{
    *state ^= *state << 13;
    *state ^= *state >> 7;
    *state ^= *state << 17;
    return lo + (hi - lo) * (double)(*state >> 11) / 9007199254740992.0;
}

#endif
