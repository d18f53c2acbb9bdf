/* cost.c: what a step cost to compute (cost.h). */
#include "cost.h"

#include <stddef.h>

#include "../core/motor.h"

double cost_last_step(const struct sim *s)
{
    const struct model *m = sim_model(s);
    double t1 = sim_time(s), t0 = t1 - sim_dt(s);
    double split = motor_breakpoints(&m->motor, t0, t1, NULL, 0) + sim_last_contacts(s);
    if (sim_integrator(s) == INTEGRATOR_EXACT)
        split *= COST_EXACT_SUBSTEP;
    return m->n * (1.0 + split) + 2.0 * m->motor.frequency * (t1 - t0);
}
