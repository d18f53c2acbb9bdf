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

#endif
