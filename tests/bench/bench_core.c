/* bench_core.c: speed of the core, printed as a table (make bench). Ratios come from
 * runs side by side in one process, alternated, medians taken: absolute times on a
 * shared machine are noise.
 *  1. steps per second, N = 5, sine drive, dt = 0.001, collisions on: springsim's sim_step
 *     against GSL's gsl_odeiv2_step_rk4 driven by gsl_odeiv2_driver_apply_fixed_step on
 *     the same equations (the core's own model_accel), with the same contact handling
 *     after each step;
 *  2. time per step and mass for N = 10, 100, 1000;
 *  3. --headless CSV rows per second against bare stepping;
 *  4. the exact integrator on the default chain (proportional dampers: stepped in its
 *     modes) at N = 100, 300, 1000 with and without collisions: the first step (the
 *     set-up: the modes and the step's exponentials), the steps after it, a second of
 *     motion at dt = 0.01 as `--headless --integrator exact -n N --duration 1` runs it, and
 *     the memory the run added (resident, from /proc/self/statm). BENCH_EXACT_MAX caps N;
 *     BENCH_EXACT_ONLY=1 prints these rows alone. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

#include "core/collision.h"
#include "core/model.h"
#include "core/output.h"
#include "core/sim.h"

#include <unistd.h>

#define ROUNDS 5

static double now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static int compare(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static double median(double *v, int n)
{
    qsort(v, (size_t)n, sizeof *v, compare);
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

/* A uniform chain driven at 1 Hz with an amplitude a tenth of the spacing (0.2 m at
 * most): contacts are checked every step but do not pile up, so what is timed is the
 * stepping, for every N alike. */
static struct model *chain(int n)
{
    struct model *m = model_new(n);
    double a = 0.1 * MODEL_LENGTH / (n + 1);
    m->motor = (struct motor){WAVE_SINE, a < 0.2 ? a : 0.2, 1.0, 0.0};
    return m;
}

/* Steps per second of the core. */
static double ours(const struct model *m, double dt, long steps, double *check)
{
    struct sim *s = sim_new(m, dt);
    double t0 = now_s();
    for (long k = 0; k < steps; k++)
        sim_step(s);
    double rate = steps / (now_s() - t0);
    *check = sim_x(s)[m->n - 1];
    sim_free(s);
    return rate;
}

/* The same system for GSL: y = (x, v), the core's equation of motion. */
static int gsl_rhs(double t, const double y[], double dydt[], void *params)
{
    const struct model *m = params;
    int n = m->n;
    memcpy(dydt, y + n, (size_t)n * sizeof *y);
    model_accel(m, y, y + n, model_end_position(m, t), dydt + n);
    return GSL_SUCCESS;
}

static double theirs(const struct model *m, double dt, long steps, double *check)
{
    int n = m->n;
    gsl_odeiv2_system sys = {gsl_rhs, NULL, (size_t)(2 * n), (void *)m};
    gsl_odeiv2_driver *d = gsl_odeiv2_driver_alloc_y_new(&sys, gsl_odeiv2_step_rk4, dt, 1e-6,
                                                         0.0);
    double *y = calloc((size_t)(2 * n), sizeof *y), t = 0.0;
    struct collision_limits l;
    struct collision_books b = {0.0, 0.0};
    collision_limits(&l, m);
    double t0 = now_s();
    for (long k = 0; k < steps; k++) {
        gsl_odeiv2_driver_apply_fixed_step(d, &t, dt, 1, y);
        /* The same contact check and cap as the core makes after each step. */
        double u = motor_position(&m->motor, t);
        if (collision_needed(&l, y, y + n, u))
            collision_settle(&l, m, y, y + n, u, 0.0, &b);
        collision_cap(m, y + n, &b);
    }
    double rate = steps / (now_s() - t0);
    *check = y[n - 1];
    free(y);
    gsl_odeiv2_driver_free(d);
    return rate;
}

/* Resident memory (MB), or -1. */
static double resident_mb(void)
{
    FILE *f = fopen("/proc/self/statm", "r");
    long size, res;
    int got = f && fscanf(f, "%ld %ld", &size, &res) == 2;
    if (f)
        fclose(f);
    return got ? (double)res * (double)sysconf(_SC_PAGESIZE) / 1048576.0 : -1.0;
}

/* 4. The exact integrator at large N. */
static void exact_rows(void)
{
    const char *cap = getenv("BENCH_EXACT_MAX");
    int most = cap ? atoi(cap) : 1000;
    printf("\n| exact, default chain at 1 m, dt 0.01 | set-up (first step) | per step after | 1 s of "
           "motion | contacts | memory added |\n| --- | --- | --- | --- | --- | --- |\n");
    const int sizes[] = {100, 300, 1000};
    for (int i = 0; i < 3; i++)
        for (int c = 0; c < 2; c++) {
            if (sizes[i] > most)
                continue;
            struct model *m = model_new(sizes[i]);
            m->motor.amplitude = 1.0; /* a 1 m stroke: the contacts pile up */
            m->collisions = c == 0;
            double r0 = resident_mb();
            struct sim *s = sim_new(m, 0.01);
            sim_set_integrator(s, INTEGRATOR_EXACT);
            double t0 = now_s();
            int contacts = 0;
            sim_step(s);
            contacts += sim_last_contacts(s);
            double t1 = now_s();
            for (int k = 1; k < 100; k++) {
                sim_step(s);
                contacts += sim_last_contacts(s);
            }
            double t2 = now_s();
            printf("| N = %d, collisions %s | %.1f ms | %.2f ms | %.2f s | %d | %.1f MB |\n",
                   sizes[i], c == 0 ? "on" : "off", 1e3 * (t1 - t0), 1e3 * (t2 - t1) / 99,
                   t2 - t0, contacts, resident_mb() - r0);
            sim_free(s);
            model_free(m);
        }
}

int main(void)
{
    gsl_set_error_handler_off();
    if (getenv("BENCH_EXACT_ONLY")) {
        exact_rows();
        return 0;
    }
    printf("springsim core benchmark (medians of %d alternated rounds)\n\n", ROUNDS);

    /* 1. Against GSL. */
    struct model *m5 = chain(5);
    double a[ROUNDS], b[ROUNDS], xa = 0, xb = 0;
    long steps = 400000;
    for (int r = 0; r < ROUNDS; r++) {
        a[r] = ours(m5, 0.001, steps, &xa);
        b[r] = theirs(m5, 0.001, steps, &xb);
    }
    double ma = median(a, ROUNDS), mb = median(b, ROUNDS);
    printf("| physics, N = 5, sine, dt = 0.001, collisions on | steps/s |\n| --- | --- |\n");
    printf("| springsim sim_step | %.3g |\n", ma);
    printf("| GSL rk4 + driver_apply_fixed_step | %.3g |\n", mb);
    printf("| ratio (goal >= 4) | **%.1fx** |\n", ma / mb);
    printf("| same answer: x5 after %.0f s | %.9f vs %.9f |\n\n", steps * 0.001, xa, xb);
    model_free(m5);

    /* 2. Linear in N. */
    printf("| N | ns per step | ns per step and mass |\n| --- | --- | --- |\n");
    const int sizes[] = {10, 100, 1000};
    for (int i = 0; i < 3; i++) {
        struct model *m = chain(sizes[i]);
        double r[ROUNDS], x;
        long k = 20000000L / sizes[i];
        for (int j = 0; j < ROUNDS; j++)
            r[j] = ours(m, 0.001, k, &x);
        double ns = 1e9 / median(r, ROUNDS);
        printf("| %d | %.0f | %.1f |\n", sizes[i], ns, ns / sizes[i]);
        model_free(m);
    }

    /* 3. A pile-up: N = 1000 under a 0.3 m drive, its masses pressed together near the
     * motor, against the same chain with collisions off. */
    {
        struct model *pm = model_new(1000);
        pm->motor = (struct motor){WAVE_SINE, 0.3, 1.0, 0.0};
        double on[ROUNDS], off[ROUNDS], xp;
        for (int j = 0; j < ROUNDS; j++) {
            pm->collisions = true;
            on[j] = ours(pm, 0.001, 5000, &xp);
            pm->collisions = false;
            off[j] = ours(pm, 0.001, 5000, &xp);
        }
        double ratio = median(off, ROUNDS) / median(on, ROUNDS);
        printf("\n| N = 1000, 0.3 m drive, 5 s | ns per step |\n| --- | --- |\n");
        printf("| collisions on (pile-up) | %.0f |\n", 1e9 / median(on, ROUNDS));
        printf("| collisions off | %.0f |\n", 1e9 / median(off, ROUNDS));
        printf("| ratio (goal <= 2.5) | **%.2fx** |\n", ratio);
        model_free(pm);
    }

    /* 4. CSV rows per second against bare stepping (N = 5, every step written). */
    struct model *m = chain(5);
    double bare[ROUNDS], csv[ROUNDS], x;
    FILE *null = fopen("/dev/null", "w");
    double scratch[5];
    for (int j = 0; j < ROUNDS; j++) {
        bare[j] = ours(m, 0.001, 200000, &x);
        struct sim *s = sim_new(m, 0.001);
        double t0 = now_s();
        for (long k = 0; k < 200000; k++) {
            sim_step(s);
            output_csv_row(null, s, false, scratch);
        }
        csv[j] = 200000 / (now_s() - t0);
        sim_free(s);
    }
    fclose(null);
    printf("\n| --headless, N = 5 | per second |\n| --- | --- |\n");
    printf("| bare steps | %.3g |\n| steps with a CSV row each | %.3g |\n",
           median(bare, ROUNDS), median(csv, ROUNDS));
    model_free(m);
    exact_rows();
    return 0;
}
