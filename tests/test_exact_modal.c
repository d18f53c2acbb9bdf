/* test_exact_modal.c: the exact stepper on chains whose dampers are proportional to their
 * masses, which it steps in the modes (exact_modal.c): two masses against their closed
 * form, a chain against long-double RK4 and against the dense exponential (the same chain
 * with one damper moved by 1e-13, which exact.c steps by the dense path), the energy
 * balance of a long undamped run of 50 masses, a copy stepping alike, contacts at N = 50
 * in the driver against RK4 at a small step, and 500 masses with Rayleigh's damping
 * (dampers beside the springs too) stepped in the modes against RK4 at dt 1e-4. */
#include "testutil.h"

#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "core/exact.h"
#include "core/model.h"
#include "core/sim.h"
#include "core/stepper.h"

/* x'' + 2 s x' + w^2 x = f amp sin(om t + phi) from (x0, v0) at t = 0, underdamped
 * (s < w) and off resonance: the transient and the steady state, by hand. */
static void one_mode(double s, double w, double f, double amp, double om, double phi,
                     double x0, double v0, double t, double *x, double *v)
{
    double dw = w * w - om * om, dd = dw * dw + 4.0 * s * s * om * om;
    double px = f * amp * dw / dd, py = -f * amp * 2.0 * s * om / dd;
    /* the steady state px sin + py cos of the drive's angle, and its rate */
    double th0 = phi, th = om * t + phi;
    double sx0 = px * sin(th0) + py * cos(th0), sv0 = om * (px * cos(th0) - py * sin(th0));
    double hx0 = x0 - sx0, hv0 = v0 - sv0;
    double wd = sqrt(w * w - s * s), e = exp(-s * t), b = (hv0 + s * hx0) / wd;
    double cs = cos(wd * t), sn = sin(wd * t);
    *x = e * (hx0 * cs + b * sn) + px * sin(th) + py * cos(th);
    *v = e * (-s * (hx0 * cs + b * sn) + wd * (-hx0 * sn + b * cs)) +
         om * (px * cos(th) - py * sin(th));
}

/* Two masses m between three springs k (the third to the motor), dampers c = g m: the
 * modes (1, 1) / sqrt 2 at k / m and (1, -1) / sqrt 2 at 3 k / m, each driven by
 * +-k / (m sqrt 2) times u. */
static void two_masses(void **state)
{
    (void)state;
    const double m = 1.7, k = 9.0, g = 0.35, amp = 0.4, om = 2.0 * M_PI * 0.6, phi = 0.3;
    struct model *md = model_new(2);
    for (int i = 0; i < 2; i++)
        md->m[i] = m, md->c[i] = g * m;
    for (int j = 0; j < 3; j++)
        md->k[j] = k;
    md->boundary = BOUNDARY_MOTOR;
    assert_true(exact_proportional(md));
    struct exact *e = exact_new(2);
    struct exact_drive d = {.sine = 1, .amp = amp, .omega = om, .phi = phi};
    const double x0[2] = {0.12, -0.05}, v0[2] = {0.3, 0.1};
    double x[2] = {x0[0], x0[1]}, v[2] = {v0[0], v0[1]}, D = 0.0, W = 0.0;
    /* the modes' starts, in y = sqrt(m) x */
    double r = sqrt(0.5), sm = sqrt(m);
    double e1 = r * sm * (x0[0] + x0[1]), e2 = r * sm * (x0[0] - x0[1]);
    double f1 = r * sm * (v0[0] + v0[1]), f2 = r * sm * (v0[0] - v0[1]);
    double err = 0.0;
    const double dts[3] = {0.05, 0.013, 0.2};
    double t = 0.0;
    for (int i = 0; i < 150; i++) {
        double h = dts[i % 3];
        assert_int_equal(exact_advance(e, md, &d, t, t + h, x, v, &D, &W), 0);
        t += h;
        double a1, b1, a2, b2;
        one_mode(0.5 * g, sqrt(k / m), r * k / sm, amp, om, phi, e1, f1, t, &a1, &b1);
        one_mode(0.5 * g, sqrt(3.0 * k / m), -r * k / sm, amp, om, phi, e2, f2, t, &a2, &b2);
        double rx[2] = {r * (a1 + a2) / sm, r * (a1 - a2) / sm};
        double rv[2] = {r * (b1 + b2) / sm, r * (b1 - b2) / sm};
        for (int j = 0; j < 2; j++)
            err = fmax(err, fmax(fabs(x[j] - rx[j]), fabs(v[j] - rv[j])));
    }
    printf("  two masses, damped, sine motor, %.1f s in steps of 0.013 to 0.2: %.2e\n", t,
           err);
    if (!(err <= 1e-12))
        fail_msg("two masses: %.3g from the closed form", err);
    exact_free(e);
    model_free(md);
}

/* A chain of n with unequal masses and springs, dampers c_i = g m_i. */
static struct model *chain(int n, enum boundary b, double g)
{
    struct model *m = model_new(n);
    for (int i = 0; i < n; i++) {
        m->m[i] = 0.5 + 0.37 * (i % 7);
        m->c[i] = g * m->m[i];
    }
    for (int j = 0; j <= n; j++)
        m->k[j] = 8.0 + 5.0 * sin(1.3 * j + 0.4);
    m->boundary = b;
    m->motor = (struct motor){WAVE_SINE, 0.6, 1.1, 0.0};
    return m;
}

/* Against classic RK4 in long double at h = 0.05 / 2000, 3 s, every end. */
static void chain_against_rk4(void **state)
{
    (void)state;
    enum { N = 5, SUB = 2000 };
    for (int b = 0; b < BOUNDARY_COUNT; b++) {
        struct model *m = chain(N, (enum boundary)b, 0.15);
        assert_true(exact_proportional(m));
        struct exact *e = exact_new(N);
        double x[N] = {0.3, -0.1, 0.2, 0.05, -0.2}, v[N] = {0.0, 0.4, -0.3, 0.1, 0.2};
        double D = 0.0, W = 0.0;
        long double rx[N], rv[N], kx[4][N], kv[4][N], tx[N], tv[N];
        for (int i = 0; i < N; i++)
            rx[i] = x[i], rv[i] = v[i];
        const long double h = 0.05L / SUB, pi = 3.141592653589793238462643383279503L;
        double err = 0.0;
        for (int step = 0; step < 60; step++) {
            struct exact_drive d = {.sine = 1, .amp = 0.6, .omega = 2.0 * M_PI * 1.1, .phi = 0.0};
            assert_int_equal(exact_advance(e, m, &d, step * 0.05, (step + 1) * 0.05, x, v, &D, &W),
                             0);
            for (int s = 0; s < SUB; s++) {
                long double t = (long double)step * 0.05L + s * h;
                const long double cs[4] = {0.0L, 0.5L, 0.5L, 1.0L};
                for (int st = 0; st < 4; st++) {
                    for (int i = 0; i < N; i++) {
                        tx[i] = rx[i] + (st ? cs[st] * h * kx[st - 1][i] : 0.0L);
                        tv[i] = rv[i] + (st ? cs[st] * h * kv[st - 1][i] : 0.0L);
                    }
                    long double u = m->boundary == BOUNDARY_MOTOR
                                        ? 0.6L * sinl(2.0L * pi * 1.1L * (t + cs[st] * h))
                                        : 0.0L;
                    long double left = m->k[0] * tx[0];
                    for (int i = 0; i < N; i++) {
                        long double right = i < N - 1 ? m->k[i + 1] * (tx[i + 1] - tx[i])
                                            : m->boundary == BOUNDARY_FREE ? 0.0L
                                                                           : m->k[N] * (u - tx[i]);
                        kv[st][i] = (right - left - m->c[i] * tv[i]) / m->m[i];
                        kx[st][i] = tv[i];
                        left = right;
                    }
                }
                for (int i = 0; i < N; i++) {
                    rx[i] += h / 6 * (kx[0][i] + 2 * kx[1][i] + 2 * kx[2][i] + kx[3][i]);
                    rv[i] += h / 6 * (kv[0][i] + 2 * kv[1][i] + 2 * kv[2][i] + kv[3][i]);
                }
            }
            for (int i = 0; i < N; i++)
                err = fmax(err, fabs(x[i] - (double)rx[i]));
        }
        printf("  chain of 5, c = 0.15 m, %-5s dt 0.05, 3 s: %.2e m from long-double RK4\n",
               model_boundary_name(m->boundary), err);
        if (!(err <= 1e-11))
            fail_msg("%s: %.3g m from the reference", model_boundary_name(m->boundary), err);
        exact_free(e);
        model_free(m);
    }
}

/* The modes against the dense exponential: the same chain of 8 with one damper moved by
 * 1e-13 of itself (not proportional: the dense path) over 200 steps of sine, ramp and a
 * contact's odd lengths; states within 1e-11 (the CSV's twelve digits), books 1e-11. */
static void against_dense(void **state)
{
    (void)state;
    enum { N = 8 };
    for (int b = 0; b < BOUNDARY_COUNT; b++)
        for (int g = 0; g < 2; g++) {
            struct model *m = chain(N, (enum boundary)b, g ? 0.4 : 0.0);
            struct model *p = chain(N, (enum boundary)b, g ? 0.4 : 0.0);
            p->c[3] = g ? p->c[3] * (1.0 + 1e-13) : 1e-13 * p->m[3];
            assert_true(exact_proportional(m));
            assert_false(exact_proportional(p));
            struct exact *e = exact_new(N), *f = exact_new(N);
            double x[N], v[N], y[N], u[N], D = 0, W = 0, D2 = 0, W2 = 0, err = 0, berr = 0;
            for (int i = 0; i < N; i++)
                x[i] = y[i] = 0.1 * cos(i + 0.5), v[i] = u[i] = 0.2 * sin(2.0 * i);
            double t = 0.0;
            for (int i = 0; i < 200; i++) {
                double h = i % 5 == 4 ? 0.0031 + 0.001 * (i % 7) : 0.02;
                struct exact_drive d = {.sine = 1, .amp = 0.5, .omega = 2.0 * M_PI * 0.9, .phi = 0.1};
                if (i % 50 >= 40)
                    d = (struct exact_drive){.t0 = t, .u0 = 0.2, .du = -0.3};
                assert_int_equal(exact_advance(e, m, &d, t, t + h, x, v, &D, &W), 0);
                assert_int_equal(exact_advance(f, p, &d, t, t + h, y, u, &D2, &W2), 0);
                t += h;
                for (int j = 0; j < N; j++)
                    err = fmax(err, fmax(fabs(x[j] - y[j]), fabs(v[j] - u[j])));
                berr = fmax(berr, fmax(fabs(D - D2), fabs(W - W2)));
            }
            printf("  chain of 8, %-5s c = %.1f m, modes against dense: %.2e, books %.2e J\n",
                   model_boundary_name(m->boundary), g ? 0.4 : 0.0, err, berr);
            if (!(err <= 1e-11 && berr <= 1e-11))
                fail_msg("%s, g %d: state %.3g, books %.3g", model_boundary_name(m->boundary),
                         g, err, berr);
            exact_free(e);
            exact_free(f);
            model_free(m);
            model_free(p);
        }
}

/* 50 undamped masses, sine motor, 100 s at dt = 0.01: kinetic + potential - W stays
 * within 1e-10 of the peak energy; and a damped one with D. */
static void long_balance(void **state)
{
    (void)state;
    enum { N = 50 };
    for (int g = 0; g < 2; g++) {
        struct model *m = chain(N, BOUNDARY_MOTOR, g ? 0.05 : 0.0);
        struct exact *e = exact_new(N);
        double x[N], v[N] = {0}, D = 0.0, W = 0.0;
        for (int i = 0; i < N; i++)
            x[i] = 0.05 * sin(0.3 * i + 1.0);
        double e0 = model_kinetic(m, v) + model_potential(m, x, 0.0), peak = e0, drift = 0.0;
        struct exact_drive d = {.sine = 1, .amp = 0.6, .omega = 2.0 * M_PI * 1.1, .phi = 0.0};
        for (int i = 0; i < 10000; i++) {
            double a = i * 0.01, b = (i + 1) * 0.01;
            assert_int_equal(exact_advance(e, m, &d, a, b, x, v, &D, &W), 0);
            double en = model_kinetic(m, v) + model_potential(m, x, 0.6 * sin(2.0 * M_PI * 1.1 * b));
            peak = fmax(peak, en);
            drift = fmax(drift, fabs(en + D - W - e0));
        }
        printf("  50 masses, c = %.2f m, 100 s at dt 0.01: balance drift %.2e of the peak "
               "(D %.3g J, W %.3g J)\n", g ? 0.05 : 0.0, drift / peak, D, W);
        if (!(drift <= 1e-10 * peak))
            fail_msg("drift %.3g of the peak %.3g", drift / peak, peak);
        if (g == 0)
            assert_true(D == 0.0);
        exact_free(e);
        model_free(m);
    }
}

/* A copy goes on bit for bit alike, its cached steps included. */
static void copy(void **state)
{
    (void)state;
    enum { N = 30 };
    struct model *m = chain(N, BOUNDARY_MOTOR, 0.2);
    struct exact *e = exact_new(N), *f = exact_new(N);
    struct exact_drive d = {.sine = 1, .amp = 0.6, .omega = 2.0 * M_PI * 1.1, .phi = 0.0};
    double x[N], v[N] = {0}, y[N], u[N], D = 0, W = 0, D2, W2;
    for (int i = 0; i < N; i++)
        x[i] = 0.05 * sin(0.3 * i + 1.0);
    for (int i = 0; i < 5; i++)
        assert_int_equal(exact_advance(e, m, &d, i * 0.01, (i + 1) * 0.01, x, v, &D, &W), 0);
    assert_int_equal(exact_copy(f, e), 0);
    memcpy(y, x, sizeof x), memcpy(u, v, sizeof v), D2 = D, W2 = W;
    for (int i = 5; i < 50; i++) {
        double a = i * 0.01, b = i % 4 ? (i + 1) * 0.01 : i * 0.01 + 0.0037;
        assert_int_equal(exact_advance(e, m, &d, a, b, x, v, &D, &W), 0);
        assert_int_equal(exact_advance(f, m, &d, a, b, y, u, &D2, &W2), 0);
        if (i % 4 == 0) {
            assert_int_equal(exact_advance(e, m, &d, b, (i + 1) * 0.01, x, v, &D, &W), 0);
            assert_int_equal(exact_advance(f, m, &d, b, (i + 1) * 0.01, y, u, &D2, &W2), 0);
        }
    }
    assert_memory_equal(x, y, sizeof x);
    assert_memory_equal(v, u, sizeof v);
    assert_true(D == D2 && W == W2);
    exact_free(e);
    exact_free(f);
    model_free(m);
}

/* Contacts in the driver at N = 50 (the reference's Taylor series takes 10 masses at
 * most): a wall end, the first mass thrown at the left wall and two neighbours at each
 * other, 3 s; exact at dt = 0.01 and 0.001 against rk4 at 1e-4 (whose own error is near
 * 1e-13 between contacts): the contacts' instants are located on each step's
 * interpolant, so exact's error falls with dt (found: 1.0e-8 and 1.6e-11 m, the latter
 * near rk4's own). */
static double contact_run(enum integrator integ, double dt, int *contacts, double *out)
{
    enum { N = 50 };
    struct model *m = model_new(N);
    m->boundary = BOUNDARY_WALL;
    for (int i = 0; i < N; i++)
        m->c[i] = 0.02 * m->m[i];
    struct sim *s = sim_new(m, dt);
    sim_set_integrator(s, integ);
    double x[N] = {0}, v[N] = {0};
    v[0] = -2.0;
    v[20] = 1.5, v[21] = -1.5;
    sim_reset(s, x, v);
    long steps = lround(3.0 / dt);
    *contacts = 0;
    for (long i = 0; i < steps; i++) {
        assert_int_equal(sim_step(s), SIM_OK);
        *contacts += sim_last_contacts(s);
    }
    memcpy(out, sim_x(s), N * sizeof *out);
    struct energy en;
    sim_energy(s, &en);
    sim_free(s);
    model_free(m);
    return en.contact;
}

static void contacts_at_50(void **state)
{
    (void)state;
    double ref[50], got[50];
    int cref, cgot;
    double eref = contact_run(INTEGRATOR_RK4, 1e-4, &cref, ref);
    assert_true(cref >= 3);
    const double dts[2] = {0.01, 0.001}, tol[2] = {5e-8, 2e-10};
    for (int k = 0; k < 2; k++) {
        double egot = contact_run(INTEGRATOR_EXACT, dts[k], &cgot, got), err = 0.0;
        for (int i = 0; i < 50; i++)
            err = fmax(err, fabs(got[i] - ref[i]));
        printf("  50 masses, contacts: exact at dt %g against rk4 at 1e-4: %.2e m, contact "
               "energy %.6f J (%.6f), %d contacts (%d)\n", dts[k], err, egot, eref, cgot, cref);
        if (!(err <= tol[k]) || cgot != cref)
            fail_msg("dt %g: %.3g m, %d contacts against %d", dts[k], err, cgot, cref);
    }
}

/* A soft mount: two masses held by springs of 1e-8 N/m (and 1e-14) at the wall(s), 1e6 N/m
 * between them, so the slow mode's w^2 (5e-9, 5e-15, against 2e6) is below the rounding of
 * the fast one (at 1e-14 LAPACK's dpttrf on the assembled matrix failed: no step at all).
 * Against the closed form in long double (the slow w^2 as the determinant over the fast
 * one: no cancellation), 200 s at dt 0.05, every end without a motor and both paths (one
 * damper 1e-300, the dense one): 1e-9 m, the specification's bound for exact (measured
 * 2e-11 to 1.5e-10; the fast mode's 74 radians a step add rounding as t^2). An
 * eigen-solver with absolute accuracy (dstevr: 4e-10 on 5e-9) missed it by 1.2e-6 m, and
 * at 1e-14 the dense path made no step. */
static void soft_mount(void **state)
{
    (void)state;
    const double mass[2] = {1.3, 0.7}, k1 = 1e6;
    for (int run = 0; run < 8; run++) {
        int soft = run / 4, b = run / 2 % 2, dense = run % 2;
        const double k0 = soft ? 1e-14 : 1e-8;
        struct model *m = model_new(2);
        m->m[0] = mass[0], m->m[1] = mass[1];
        m->k[0] = k0, m->k[1] = k1, m->k[2] = b ? k0 : 7.0; /* free: k_2 unread */
        m->c[0] = dense ? 1e-300 : 0.0, m->c[1] = 0.0;
        m->boundary = b ? BOUNDARY_WALL : BOUNDARY_FREE;
        assert_int_equal(exact_proportional(m), !dense);
        long double k2 = b ? k0 : 0.0L, m1 = mass[0], m2 = mass[1];
        long double a = (k0 + k1) / m1, c = (k1 + k2) / m2, off = -k1 / sqrtl(m1 * m2);
        long double hi = 0.5L * (a + c) + sqrtl(0.25L * (a - c) * (a - c) + off * off);
        long double lo = ((long double)k0 * k1 + k0 * k2 + k1 * k2) / (m1 * m2) / hi;
        /* the slow mode's shape (lo - c, off), the fast one's perpendicular to it */
        long double p0 = lo - c, p1 = off, nrm = sqrtl(p0 * p0 + p1 * p1);
        p0 /= nrm, p1 /= nrm;
        const double x0[2] = {1.0, 0.9}, v0[2] = {0.0, 1e-4};
        long double y0[2] = {sqrtl(m1) * x0[0], sqrtl(m2) * x0[1]};
        long double z0[2] = {sqrtl(m1) * v0[0], sqrtl(m2) * v0[1]};
        long double es = p0 * y0[0] + p1 * y0[1], ef = -p1 * y0[0] + p0 * y0[1];
        long double ds = p0 * z0[0] + p1 * z0[1], df = -p1 * z0[0] + p0 * z0[1];
        long double ws = sqrtl(lo), wf = sqrtl(hi);
        struct exact *e = exact_new(2);
        double x[2] = {x0[0], x0[1]}, v[2] = {v0[0], v0[1]}, D = 0.0, W = 0.0, err = 0.0;
        for (int step = 1; step <= 4000; step++) {
            assert_int_equal(exact_advance(e, m, NULL, (step - 1) * 0.05, step * 0.05, x, v,
                                           &D, &W),
                             0);
            if (step % 200)
                continue;
            long double t = step * 0.05L;
            long double s = es * cosl(ws * t) + ds / ws * sinl(ws * t);
            long double f = ef * cosl(wf * t) + df / wf * sinl(wf * t);
            long double r0 = (p0 * s - p1 * f) / sqrtl(m1), r1 = (p1 * s + p0 * f) / sqrtl(m2);
            err = fmax(err, fmax(fabs(x[0] - (double)r0), fabs(x[1] - (double)r1)));
        }
        printf("  soft mount (w^2 %.2Lg and %.2Lg), %-4s end, %s path, 200 s: %.2e m\n", lo,
               hi, model_boundary_name(m->boundary), dense ? "dense" : "modes", err);
        if (!(err <= 1e-9))
            fail_msg("soft mount, %s end, %s path: %.3g m from the closed form",
                     model_boundary_name(m->boundary), dense ? "dense" : "modes", err);
        exact_free(e);
        model_free(m);
    }
}

/* Seconds on the monotonic clock. */
static double now_seconds(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

/* 500 masses between two walls with Rayleigh's damping, C = 0.05 M + 0.002 K (ground
 * dampers and dampers beside every spring): exact steps them in the modes, O(n^2) a step,
 * not by the dense exponential of the 1000-state system, and over 2 s in steps of 0.01
 * stays within 1e-8 m of the RK4 stepper at dt 1e-4 at every step's end. */
static void rayleigh_500(void **state)
{
    (void)state;
    enum { N = 500, SUB = 100, STEPS = 200 };
    struct model *m = chain(N, BOUNDARY_WALL, 0.05);
    for (int j = 0; j <= N; j++)
        m->cs[j] = 0.002 * m->k[j];
    model_sync(m);
    assert_true(m->spring_damped && model_rayleigh(m));
    assert_int_equal(exact_needs_general(m), 0);
    struct exact *e = exact_new(N);
    struct stepper *st = stepper_new(m);
    assert_non_null(e);
    assert_non_null(st);
    const double h = 0.01;
    stepper_set_model(st, m, h / SUB);
    static double x[N], v[N], y[STEPPER_LEN(N)];
    for (int i = 0; i < N; i++) {
        x[i] = y[i] = 0.05 * sin(0.3 * i + 1.0) + 0.02 * cos(2.9 * i);
        v[i] = y[N + i] = 0.1 * cos(0.7 * i);
    }
    double D = 0.0, W = 0.0, err = 0.0, secs = 0.0;
    struct drive d;
    drive_at(&d, m, 0.5 * h);
    for (int k = 0; k < STEPS; k++) {
        double a = k * h, b = (k + 1) * h;
        double t0 = now_seconds();
        assert_int_equal(exact_advance(e, m, NULL, a, b, x, v, &D, &W), 0);
        secs += now_seconds() - t0;
        assert_true(exact_stepped_in_modes(e));
        for (int s = 0; s < SUB; s++)
            assert_int_equal(stepper_apply(st, INTEGRATOR_RK4, &d, a + s * h / SUB,
                                           a + (s + 1) * h / SUB, y), 0);
        for (int i = 0; i < N; i++)
            err = fmax(err, fabs(x[i] - y[i]));
    }
    printf("  500 masses, Rayleigh C = 0.05 M + 0.002 K, 2 s: in the modes, %.2e m from RK4 at "
           "dt 1e-4; %.2g ms an exact step (the first finds the modes)\n", err,
           1e3 * secs / STEPS);
    if (!(err <= 1e-8))
        fail_msg("%.3g m from RK4", err);
    stepper_free(st);
    exact_free(e);
    model_free(m);
    /* and the check can fail: one damper off Rayleigh's takes the dense exponential */
    m = chain(8, BOUNDARY_WALL, 0.05);
    for (int j = 0; j <= 8; j++)
        m->cs[j] = 0.002 * m->k[j] * (j == 3 ? 2.0 : 1.0);
    model_sync(m);
    e = exact_new(8);
    double x8[8] = {0.1}, v8[8] = {0.0};
    assert_int_equal(exact_advance(e, m, NULL, 0.0, h, x8, v8, &D, &W), 0);
    assert_false(exact_stepped_in_modes(e));
    exact_free(e);
    model_free(m);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(two_masses),   cmocka_unit_test(chain_against_rk4),
        cmocka_unit_test(against_dense), cmocka_unit_test(long_balance),
        cmocka_unit_test(copy),          cmocka_unit_test(contacts_at_50),
        cmocka_unit_test(soft_mount),    cmocka_unit_test(rayleigh_500),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
