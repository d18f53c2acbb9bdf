/* config_model.c: a configuration made into the chain it describes: lists expanded to
 * one value per element (with the reason when a list has the wrong length), and the
 * initial conditions, random positions and a start along a mode included. */
#include "config.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "modes.h"

/* Says that list l has the wrong length for this many elements, quoting its values. */
static void wrong_length(const struct config_list *l, int elements, const char *what,
                         char *err, size_t errlen)
{
    /* The first values as given (well, as read), then "..." if there are more. */
    char text[48];
    size_t used = 0;
    int i = 0;
    for (; i < l->count; i++) {
        char one[32];
        int w = snprintf(one, sizeof one, i ? ",%g" : "%g", l->v[i]);
        if (used + (size_t)w + 4 > sizeof text)
            break;
        memcpy(text + used, one, (size_t)w + 1);
        used += (size_t)w;
    }
    snprintf(err, errlen, "'%s%s' has %d values for %d %s (expected 1 or %d)", text,
             i < l->count ? ",..." : "", l->count, elements, what, elements);
}

/* Checks a list's length against the element count and expands it into dst. */
static int expand(const struct config_list *l, int elements, double fallback, double *dst,
                  const char *what, char *err, size_t errlen)
{
    if (l->count == 0) {
        for (int i = 0; i < elements; i++)
            dst[i] = fallback;
        return 0;
    }
    if (l->count != 1 && l->count != elements) {
        wrong_length(l, elements, what, err, errlen);
        return -1;
    }
    for (int i = 0; i < elements; i++)
        dst[i] = l->v[l->count == 1 ? 0 : i];
    return 0;
}

struct model *config_model(const struct config *c, int *bad_key, char *err, size_t errlen)
{
    int n = c->masses;
    struct model *m = model_new(n);
    *bad_key = -1;
    if (!m) {
        snprintf(err, errlen, "out of memory");
        return NULL;
    }
    const char *per_mass = n == 1 ? "mass" : "masses";
    const char *springs = "springs";
    if (expand(&c->mass, n, config_options[CFG_MASS].def, m->m, per_mass, err, errlen))
        *bad_key = CFG_MASS;
    else if (expand(&c->spring, n + 1, config_options[CFG_SPRING].def, m->k, springs, err,
                    errlen))
        *bad_key = CFG_SPRING;
    else if (expand(&c->spring_cubic, n + 1, 0.0, m->k3, springs, err, errlen))
        *bad_key = CFG_SPRING_CUBIC;
    else if (expand(&c->damping, n, config_options[CFG_DAMPING].def, m->c, per_mass, err,
                    errlen))
        *bad_key = CFG_DAMPING;
    else if (expand(&c->spring_damping, n + 1, 0.0, m->cs, springs, err, errlen))
        *bad_key = CFG_SPRING_DAMPING;
    else if (c->x0.count > 1 && c->x0.count != n)
        *bad_key = CFG_X0;
    else if (c->v0.count > 1 && c->v0.count != n)
        *bad_key = CFG_V0;
    if (*bad_key == CFG_X0 || *bad_key == CFG_V0)
        wrong_length(*bad_key == CFG_X0 ? &c->x0 : &c->v0, n, per_mass, err, errlen);
    if (*bad_key < 0 && c->start_mode > n) {
        *bad_key = CFG_START_MODE;
        snprintf(err, errlen, "'%d' is out of range for %d %s (expected a mode 1 <= K <= %d)",
                 c->start_mode, n, per_mass, n);
    }
    double room = MODEL_LENGTH - n * model_block_width(m);
    if (*bad_key < 0 && !c->no_collisions && c->boundary == BOUNDARY_MOTOR &&
        c->amplitude > room) {
        /* At its furthest in the piston would crush the blocks against the wall. */
        *bad_key = CFG_AMPLITUDE;
        char a[40];
        config_format_exact(c->amplitude, a, sizeof a);
        snprintf(err, errlen, "'%s' leaves the %d %s no room: the piston would crush them "
                 "against the wall (expected amplitude <= L - N w = %.6g m with collisions "
                 "on, the blocks %.6g m wide)", a, n, n == 1 ? "block" : "blocks", room,
                 model_block_width(m));
    }
    if (*bad_key < 0 && c->boundary == BOUNDARY_MOTOR && motor_has_jumps(c->wave) &&
        m->cs[n] != 0.0) {
        /* u jumps, so the damper's rate cs_N (u' - v_N) is a Dirac pulse: no finite force */
        *bad_key = CFG_SPRING_DAMPING;
        snprintf(err, errlen, "'%g' on the motor's spring with a %s wave makes an infinite "
                 "force at each jump (expected 0 for spring %d (%d–motor), a sine or triangle "
                 "wave, or another right end)", m->cs[n], motor_wave_name(c->wave), n + 1, n);
    }
    if (*bad_key < 0 && c->force_on > n) {
        *bad_key = CFG_FORCE_ON;
        snprintf(err, errlen, "'%d' is out of range for %d %s (expected a mass 1 <= K <= %d)",
                 c->force_on, n, per_mass, n);
    }
    model_set_cubic(m);
    if (*bad_key < 0 && m->cubic && c->integrator == INTEGRATOR_EXACT) {
        *bad_key = CFG_INTEGRATOR;
        snprintf(err, errlen, "'exact' steps a linear chain by its matrix exponential, and "
                 "the cubic springs (--spring-cubic) make this one nonlinear (expected rk4, "
                 "verlet, semi-implicit or euler, or --spring-cubic 0)");
    }
    if (*bad_key >= 0) {
        model_free(m);
        return NULL;
    }
    m->boundary = c->boundary;
    m->motor = (struct motor){c->wave, c->amplitude, c->frequency, 0.0};
    m->collisions = !c->no_collisions;
    m->force = c->force;
    m->force_on = c->force_on - 1;
    model_sync(m);
    return m;
}

/* splitmix64 (Steele, Lea and Flood 2014): small, fast, and fixed across platforms. */
static uint64_t splitmix64(uint64_t *state)
{
    uint64_t z = (*state += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
}

static int compare_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

void config_random_positions(const struct model *m, uint64_t seed, double *x)
{
    int n = m->n;
    double w = model_block_width(m);
    double sep = 1.5 * w;
    double lo = 0.5 * w;
    double hi = MODEL_LENGTH - 0.5 * w;
    if (m->boundary == BOUNDARY_MOTOR && hi - m->motor.amplitude - lo > (n - 1) * sep)
        hi -= m->motor.amplitude; /* clear of the piston at its furthest in */
    /* n sorted uniforms on [0, room], spread by sep: uniform over the allowed set. */
    double room = (hi - lo) - (n - 1) * sep;
    uint64_t state = seed;
    for (int i = 0; i < n; i++)
        x[i] = room * (double)(splitmix64(&state) >> 11) * 0x1.0p-53;
    qsort(x, (size_t)n, sizeof *x, compare_double);
    for (int i = 0; i < n; i++)
        x[i] = lo + x[i] + i * sep - model_equilibrium(m, i);
}

int config_initial(const struct config *c, const struct model *m, double *x, double *v)
{
    int n = m->n;
    if (c->start_mode > 0) {
        int e = modes_start(m, c->start_mode, c->start_amp, x);
        for (int i = 0; i < n; i++) {
            v[i] = 0.0;
            if (e != 0)
                x[i] = 0.0;
        }
        return e;
    }
    if (c->random)
        config_random_positions(m, c->seed, x);
    else
        for (int i = 0; i < n; i++)
            x[i] = c->x0.count ? c->x0.v[c->x0.count == 1 ? 0 : i] : 0.0;
    for (int i = 0; i < n; i++)
        v[i] = c->v0.count ? c->v0.v[c->v0.count == 1 ? 0 : i] : 0.0;
    return 0;
}
