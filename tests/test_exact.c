/* test_exact.c: the exact stepper against closed forms (one mass: free, damped in all
 * three regimes, driven by a sine, at resonance, by a ramp), against an independent
 * long-double RK4 on a chain, its energy books against the energy balance and against
 * quadrature of the closed forms, its cache, and its failures. */
#include "testutil.h"

#include <stdlib.h>
#include <string.h>

#include "core/exact.h"
#include "core/model.h"
#include "core/motor.h"

/* One mass m between springs k0 (wall) and k1 (the right end), damper c, and its right
 * end: u = amp sin(om t + phi) (sine) or u0 + du (t - t0) (line) for a motor. */
struct one {
    enum boundary b;
    double m, k0, k1, c;
    double x0, v0;
    int sine;
    double amp, om, phi;
    double u0, du, t0;
};

static struct model *one_model(const struct one *s)
{
    struct model *m = model_new(1);
    m->m[0] = s->m;
    m->k[0] = s->k0;
    m->k[1] = s->k1;
    m->c[0] = s->c;
    m->boundary = s->b;
    return m;
}

static struct exact_drive one_drive(const struct one *s)
{
    struct exact_drive d = {s->sine, s->amp, s->om, s->phi, s->t0, s->u0, s->du, 0.0, 0.0, 0.0};
    if (s->b != BOUNDARY_MOTOR)
        d = (struct exact_drive){0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
    return d;
}

/* x'' + 2 s x' + w^2 x = 0 from (x0, v0): under-, critically and overdamped. */
static void free_motion(double s, double w, double x0, double v0, double t, double *x, double *v)
{
    if (s < w) {
        double wd = sqrt(w * w - s * s), e = exp(-s * t);
        double b = (v0 + s * x0) / wd, cs = cos(wd * t), sn = sin(wd * t);
        *x = e * (x0 * cs + b * sn);
        *v = e * (-s * (x0 * cs + b * sn) + wd * (-x0 * sn + b * cs));
    } else if (s == w) {
        double e = exp(-s * t), b = v0 + s * x0;
        *x = e * (x0 + b * t);
        *v = e * (b - s * (x0 + b * t));
    } else {
        double q = sqrt(s * s - w * w), r1 = -w * w / (s + q), r2 = -s - q;
        double a = (v0 - r2 * x0) / (r1 - r2), b = x0 - a;
        *x = a * exp(r1 * t) + b * exp(r2 * t);
        *v = a * r1 * exp(r1 * t) + b * r2 * exp(r2 * t);
    }
}

/* A particular solution of x'' + 2 s x' + w^2 x = (k1/m) u(t) and its velocity. */
static void forced(const struct one *o, double s, double w, double t, double *x, double *v)
{
    *x = *v = 0.0;
    if (o->b != BOUNDARY_MOTOR)
        return;
    double f = o->k1 / o->m;
    if (o->sine) {
        double th = o->om * t + o->phi, f0 = f * o->amp, sn = sin(th), cs = cos(th);
        if (s == 0.0 && o->om == w) { /* resonance: the amplitude grows as t */
            double c = -f0 / (2.0 * w);
            *x = c * t * cs;
            *v = c * cs - c * w * t * sn;
            return;
        }
        double dw = w * w - o->om * o->om, dd = dw * dw + 4.0 * s * s * o->om * o->om;
        double px = f0 * dw / dd, py = -f0 * 2.0 * s * o->om / dd;
        *x = px * sn + py * cs;
        *v = o->om * (px * cs - py * sn);
    } else {
        double f1 = f * o->du, f0 = f * (o->u0 - o->du * o->t0);
        double beta = f1 / (w * w), alpha = (f0 - 2.0 * s * beta) / (w * w);
        *x = alpha + beta * t;
        *v = beta;
    }
}

/* The closed form of scenario o at time t. */
static void one_exact(const struct one *o, double t, double *x, double *v)
{
    double w = sqrt((o->k0 + (o->b == BOUNDARY_FREE ? 0.0 : o->k1)) / o->m);
    double s = o->c / (2.0 * o->m), px, pv, hx, hv;
    forced(o, s, w, 0.0, &px, &pv);
    double x0 = o->x0 - px, v0 = o->v0 - pv;
    forced(o, s, w, t, &px, &pv);
    free_motion(s, w, x0, v0, t, &hx, &hv);
    *x = px + hx;
    *v = pv + hv;
}

/* Steps scenario o from 0 to tend by dt; the largest errors in x and v. */
static void one_run(const struct one *o, double dt, double tend, double *ex, double *ev)
{
    struct model *m = one_model(o);
    struct exact *e = exact_new(1);
    assert_non_null(e);
    struct exact_drive d = one_drive(o);
    double x = o->x0, v = o->v0, diss = 0.0, work = 0.0;
    long steps = lround(tend / dt);
    *ex = *ev = 0.0;
    for (long i = 0; i < steps; i++) {
        assert_int_equal(exact_advance(e, m, &d, i * dt, (i + 1) * dt, &x, &v, &diss, &work), 0);
        double rx, rv;
        one_exact(o, (i + 1) * dt, &rx, &rv);
        *ex = fmax(*ex, fabs(x - rx));
        *ev = fmax(*ev, fabs(v - rv));
    }
    exact_free(e);
    model_free(m);
}

/* o at dt = 0.05 and 0.001 over 20 s: within 1e-9 m (and 1e-9 w m/s). */
static void check_one(const struct one *o, const char *what)
{
    double w = sqrt((o->k0 + o->k1) / o->m);
    const double dts[2] = {0.05, 0.001};
    for (int i = 0; i < 2; i++) {
        double ex, ev;
        one_run(o, dts[i], 20.0, &ex, &ev);
        printf("  %-32s dt %-5g 20 s: |x err| %.2e m, |v err| %.2e m/s\n", what, dts[i], ex, ev);
        if (!(ex <= 1e-9 && ev <= 1e-9 * w))
            fail_msg("%s, dt %g: error %.3g m, %.3g m/s", what, dts[i], ex, ev);
    }
}

static void undamped_wall(void **state)
{
    (void)state;
    /* x0 cos(w t), w = sqrt((k0 + k1) / m) */
    struct one o = {.b = BOUNDARY_WALL, .m = 0.7, .k0 = 10.0, .k1 = 13.0, .x0 = 0.8};
    check_one(&o, "undamped, wall");
    o.k0 = o.k1 = 3e4, o.m = 0.05; /* 175 Hz: 55 radians a step at dt = 0.05 */
    check_one(&o, "undamped, wall, 175 Hz");
}

/* One step of 120 to 200 radians (GSL's table would take 8 Taylor terms there and lose
 * a digit, 1.2e-12): within 5e-13 of the amplitude. */
static void long_step(void **state)
{
    (void)state;
    struct model *m = model_new(1);
    struct exact *e = exact_new(1);
    m->boundary = BOUNDARY_WALL;
    m->c[0] = 0.0;
    for (double wh = 120.0; wh <= 200.0; wh += 10.0) {
        double w = wh / 0.05, x = 1.0, v = 0.0, D = 0.0, W = 0.0;
        m->k[0] = m->k[1] = 0.5 * w * w;
        assert_int_equal(exact_advance(e, m, NULL, 0.0, 0.05, &x, &v, &D, &W), 0);
        double err = hypot(x - cos(w * 0.05), v / w + sin(w * 0.05));
        if (!(err <= 5e-13))
            fail_msg("%g radians in a step: %.3g of the amplitude", wh, err);
    }
    exact_free(e);
    model_free(m);
}

static void damped_wall(void **state)
{
    (void)state;
    /* w = 2: critical damping at c = 2 m w = 4 exactly */
    struct one o = {.b = BOUNDARY_WALL, .m = 1.0, .k0 = 1.5, .k1 = 2.5, .x0 = 0.5, .v0 = -1.0};
    o.c = 0.3;
    check_one(&o, "underdamped");
    o.c = 4.0;
    check_one(&o, "critically damped");
    o.c = 25.0;
    check_one(&o, "overdamped");
    o.c = 400.0; /* a fast mode of -400/s: e^-20 in one step of 0.05 */
    check_one(&o, "heavily overdamped");
}

static void free_end(void **state)
{
    (void)state;
    /* the end's spring is absent: w = sqrt(k0 / m) */
    struct one o = {.b = BOUNDARY_FREE, .m = 2.0, .k0 = 7.0, .k1 = 1e3, .c = 0.2, .x0 = -0.3,
                    .v0 = 2.0};
    check_one(&o, "free end");
}

static void sine_motor(void **state)
{
    (void)state;
    struct one o = {.b = BOUNDARY_MOTOR, .m = 1.3, .k0 = 10.0, .k1 = 10.0, .c = 0.4, .x0 = 0.1,
                    .v0 = -0.2, .sine = 1, .amp = 0.9, .om = 2.0 * M_PI * 0.83, .phi = 0.7};
    check_one(&o, "sine motor");
    o.om = 2.0 * M_PI * 9.7; /* far above resonance: 3 radians a step at dt = 0.05 */
    check_one(&o, "sine motor, 9.7 Hz");
    o.k0 = o.k1 = 5e4, o.m = 0.1, o.c = 2.0, o.om = 2.0 * M_PI * 200.0, o.amp = 0.01;
    check_one(&o, "sine motor, 200 Hz near 159 Hz");
    o = (struct one){.b = BOUNDARY_MOTOR, .m = 1.0, .k0 = 3.0, .k1 = 6.0, .sine = 1, .amp = 0.05,
                     .om = 3.0, .x0 = 0.2};
    check_one(&o, "undamped resonance"); /* x grows as t cos(3 t) */
}

static void ramp_motor(void **state)
{
    (void)state;
    struct one o = {.b = BOUNDARY_MOTOR, .m = 0.8, .k0 = 12.0, .k1 = 6.0, .c = 0.5, .x0 = 0.2,
                    .u0 = 0.3, .du = -0.15, .t0 = 2.5};
    check_one(&o, "ramp");
    o.c = 0.0, o.du = 0.0; /* a constant offset, as on a square wave's level */
    check_one(&o, "constant end");
}

/* A chain of n with every parameter different. */
static struct model *chain(int n, enum boundary b)
{
    struct model *m = model_new(n);
    for (int i = 0; i < n; i++) {
        m->m[i] = 0.5 + 0.37 * i;
        m->c[i] = 0.05 + 0.11 * (i % 3);
    }
    for (int j = 0; j <= n; j++)
        m->k[j] = 8.0 + 5.0 * sin(1.3 * j + 0.4);
    m->boundary = b;
    m->motor = (struct motor){WAVE_SINE, 0.6, 1.1, 0.0};
    return m;
}

/* The model's force law in long double, for the reference. */
static void rates_ld(const struct model *m, const long double *x, const long double *v,
                     long double u, long double *a)
{
    int n = m->n;
    long double left = m->k[0] * x[0];
    for (int i = 0; i < n; i++) {
        long double right = i < n - 1 ? m->k[i + 1] * (x[i + 1] - x[i])
                            : m->boundary == BOUNDARY_FREE ? 0.0L
                                                           : m->k[n] * (u - x[i]);
        a[i] = (right - left - m->c[i] * v[i]) / m->m[i];
        left = right;
    }
}

static long double motor_ld(const struct model *m, long double t)
{
    if (m->boundary != BOUNDARY_MOTOR)
        return 0.0L;
    return m->motor.amplitude * sinl(2.0L * 3.141592653589793238462643383279503L *
                                     m->motor.frequency * t);
}

/* Against classic RK4 in long double at h = 1/40000 (error near 1e-15 m), a chain of 4
 * with unequal masses, springs and dampers, a sine motor, at dt = 0.05 over 3 s. */
static void chain_against_rk4(void **state)
{
    (void)state;
    enum { N = 4 };
    for (int b = 0; b < BOUNDARY_COUNT; b++) {
        struct model *m = chain(N, (enum boundary)b);
        struct exact *e = exact_new(N);
        double x[N] = {0.3, -0.1, 0.2, 0.05}, v[N] = {0.0, 0.4, -0.3, 0.1}, diss = 0, work = 0;
        long double rx[N], rv[N], k[4][2][N], tx[N], tv[N];
        for (int i = 0; i < N; i++)
            rx[i] = x[i], rv[i] = v[i];
        const int sub = 2000;
        const long double h = 0.05L / sub;
        double err = 0.0;
        for (int step = 0; step < 60; step++) {
            struct exact_drive d = {1, m->motor.amplitude, 2.0 * M_PI * m->motor.frequency, 0.0,
                                    0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
            assert_int_equal(
                exact_advance(e, m, &d, step * 0.05, (step + 1) * 0.05, x, v, &diss, &work), 0);
            for (int s = 0; s < sub; s++) {
                long double t = (long double)step * 0.05L + s * h;
                const long double cs[4] = {0.0L, 0.5L, 0.5L, 1.0L};
                for (int st = 0; st < 4; st++) {
                    for (int i = 0; i < N; i++) {
                        tx[i] = rx[i] + (st ? cs[st] * h * k[st - 1][0][i] : 0.0L);
                        tv[i] = rv[i] + (st ? cs[st] * h * k[st - 1][1][i] : 0.0L);
                    }
                    rates_ld(m, tx, tv, motor_ld(m, t + cs[st] * h), k[st][1]);
                    memcpy(k[st][0], tv, sizeof tv);
                }
                for (int i = 0; i < N; i++) {
                    rx[i] += h / 6 * (k[0][0][i] + 2 * k[1][0][i] + 2 * k[2][0][i] + k[3][0][i]);
                    rv[i] += h / 6 * (k[0][1][i] + 2 * k[1][1][i] + 2 * k[2][1][i] + k[3][1][i]);
                }
            }
            for (int i = 0; i < N; i++)
                err = fmax(err, fabs(x[i] - (double)rx[i]));
        }
        printf("  chain of 4, %-5s dt 0.05, 3 s: %.2e m from long-double RK4\n",
               model_boundary_name(m->boundary), err);
        if (!(err <= 1e-11))
            fail_msg("%s: %.3g m from the reference", model_boundary_name(m->boundary), err);
        exact_free(e);
        model_free(m);
    }
}

/* Steps a chain over tend by dt with its motor's waveform split at the breakpoints, as
 * the driver does, a jump of the end booking its change of the spring energy as the
 * motor's work; the largest drift of kinetic + potential + D - W, relative to the largest
 * kinetic + potential seen. */
static double balance_drift(struct model *m, double dt, double tend)
{
    int n = m->n, motor = m->boundary == BOUNDARY_MOTOR;
    struct exact *e = exact_new(n);
    double *x = calloc((size_t)n, sizeof *x), *v = calloc((size_t)n, sizeof *v);
    for (int i = 0; i < n; i++)
        x[i] = 0.1 * sin(i + 1.0);
    double diss = 0.0, work = 0.0, u = model_end_position(m, 0.0);
    double e0 = model_kinetic(m, v) + model_potential(m, x, u);
    double peak = e0, drift = 0.0;
    long steps = lround(tend / dt);
    for (long i = 0; i < steps; i++) {
        double t0 = i * dt, t1 = (i + 1) * dt, cut[8];
        int nb = motor_breakpoints(&m->motor, t0, t1, cut, 7);
        assert_true(nb <= 7);
        cut[nb] = t1;
        double a = t0;
        for (int j = 0; j <= nb; j++) {
            struct motor_piece p;
            motor_piece_at(&m->motor, 0.5 * (a + cut[j]), &p);
            struct exact_drive d = {0, 0.0, 0.0, 0.0, a, 0.0, 0.0, 0.0, 0.0, 0.0};
            if (m->motor.wave == WAVE_SINE)
                d = (struct exact_drive){1, m->motor.amplitude,
                                         2.0 * M_PI * m->motor.frequency, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
            else
                motor_piece_eval(&p, a, &d.u0, &d.du);
            double ua, du;
            motor_piece_eval(&p, a, &ua, &du);
            ua = motor ? ua : 0.0;
            work += model_potential(m, x, ua) - model_potential(m, x, u); /* a jump */
            assert_int_equal(exact_advance(e, m, &d, a, cut[j], x, v, &diss, &work), 0);
            motor_piece_eval(&p, cut[j], &u, &du);
            u = motor ? u : 0.0;
            a = cut[j];
        }
        double en = model_kinetic(m, v) + model_potential(m, x, u);
        peak = fmax(peak, en);
        drift = fmax(drift, fabs(en + diss - work - e0));
    }
    exact_free(e);
    free(x);
    free(v);
    return drift / peak;
}

static void energy_balance(void **state)
{
    (void)state;
    const enum wave waves[] = {WAVE_SINE, WAVE_TRIANGLE, WAVE_SAWTOOTH, WAVE_SQUARE};
    const double dts[2] = {0.05, 0.001};
    for (int b = 0; b < BOUNDARY_COUNT; b++)
        for (int w = 0; w < 4; w++) {
            if (b != BOUNDARY_MOTOR && w > 0)
                continue;
            for (int i = 0; i < 2; i++) {
                struct model *m = chain(5, (enum boundary)b);
                m->motor.wave = waves[w];
                m->motor.frequency = 0.7;
                double drift = balance_drift(m, dts[i], 20.0);
                printf("  chain of 5, %-5s %-8s dt %-5g 20 s: balance drift %.2e of the peak\n",
                       model_boundary_name(m->boundary), motor_wave_name(m->motor.wave), dts[i],
                       drift);
                if (!(drift <= 1e-10))
                    fail_msg("%s %s, dt %g: balance drifts %.3g of the peak energy",
                             model_boundary_name(m->boundary), motor_wave_name(m->motor.wave),
                             dts[i], drift);
                model_free(m);
            }
        }
}

/* D and W on single steps of 0.05 s (up to 200 Hz) against composite Gauss-Legendre
 * (400 panels of 8 points) on the closed forms: 1e-12 relative. */
static void books_against_closed_form(void **state)
{
    (void)state;
    static const double x8[4] = {0.1834346424956498, 0.5255324099163290, 0.7966664774136267,
                                 0.9602898564975363};
    static const double w8[4] = {0.3626837833783620, 0.3137066458778873, 0.2223810344533745,
                                 0.1012285362903763};
    struct one cases[3] = {
        {.b = BOUNDARY_MOTOR, .m = 1.3, .k0 = 10.0, .k1 = 10.0, .c = 0.4, .x0 = 0.1, .v0 = -0.2,
         .sine = 1, .amp = 0.9, .om = 2.0 * M_PI * 0.83, .phi = 0.7},
        {.b = BOUNDARY_MOTOR, .m = 0.1, .k0 = 5e4, .k1 = 5e4, .c = 2.0, .x0 = 0.01, .sine = 1,
         .amp = 0.01, .om = 2.0 * M_PI * 200.0, .phi = 0.3},
        {.b = BOUNDARY_MOTOR, .m = 0.8, .k0 = 12.0, .k1 = 6.0, .c = 0.5, .x0 = 0.2, .u0 = 0.3,
         .du = -0.15, .t0 = 2.5},
    };
    for (int k = 0; k < 3; k++) {
        const struct one *o = &cases[k];
        struct model *m = one_model(o);
        struct exact *e = exact_new(1);
        struct exact_drive d = one_drive(o);
        for (double a = 0.0; a < 1.0; a += 0.35) {
            double b = a + 0.05, x, v, diss = 0.0, work = 0.0;
            one_exact(o, a, &x, &v);
            assert_int_equal(exact_advance(e, m, &d, a, b, &x, &v, &diss, &work), 0);
            double rd = 0.0, rw = 0.0, pw = 0.0;
            const int panels = 400;
            double ph = (b - a) / panels;
            for (int p = 0; p < panels; p++)
                for (int j = 0; j < 8; j++) {
                    double t = a + ph * (p + 0.5 + 0.5 * (j < 4 ? -x8[j] : x8[j - 4]));
                    double w = 0.5 * ph * w8[j % 4], xt, vt, u, du;
                    one_exact(o, t, &xt, &vt);
                    double th = o->om * t + o->phi;
                    u = o->sine ? o->amp * sin(th) : o->u0 + o->du * (t - o->t0);
                    du = o->sine ? o->amp * o->om * cos(th) : o->du;
                    rd += w * o->c * vt * vt;
                    rw += w * o->k1 * (u - xt) * du;
                    pw += w * fabs(o->k1 * (u - xt) * du);
                }
            printf("  one mass, case %d, step at %.2f: D %.2e, W %.2e relative\n", k, a,
                   fabs(diss - rd) / rd, fabs(work - rw) / pw);
            if (!(fabs(diss - rd) <= 1e-12 * rd && fabs(work - rw) <= 1e-12 * pw))
                fail_msg("case %d at %g: D %.17g (%.17g), W %.17g (%.17g)", k, a, diss, rd, work,
                         rw);
        }
        exact_free(e);
        model_free(m);
    }
}

/* Steps of several lengths in turn (more than the cache holds), a model changed under
 * it, and a step cut in two: the same as a fresh stepper taking each step whole. */
static void cache(void **state)
{
    (void)state;
    enum { N = 3 };
    struct model *m = chain(N, BOUNDARY_MOTOR);
    struct exact *e = exact_new(N), *f = NULL;
    struct exact_drive d = {1, 0.6, 2.0 * M_PI * 1.1, 0.2, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
    double x[N] = {0.1, 0.2, -0.1}, v[N] = {0}, D = 0, W = 0;
    double y[N], u[N], D2, W2;
    double t = 0.0;
    const double hs[7] = {0.01, 0.013, 0.01, 0.0021, 0.037, 0.0005, 0.01};
    for (int round = 0; round < 3; round++)
        for (int i = 0; i < 7; i++) {
            if (round == 1 && i == 3)
                m->k[2] *= 1.5; /* the cached exponentials are stale now */
            memcpy(y, x, sizeof x), memcpy(u, v, sizeof v), D2 = D, W2 = W;
            assert_int_equal(exact_advance(e, m, &d, t, t + hs[i], x, v, &D, &W), 0);
            f = exact_new(N);
            assert_int_equal(exact_advance(f, m, &d, t, t + hs[i], y, u, &D2, &W2), 0);
            exact_free(f);
            for (int j = 0; j < N; j++) {
                assert_close(x[j], y[j], 1e-15);
                assert_close(v[j], u[j], 1e-15);
            }
            assert_close(D, D2, 1e-15 * D);
            assert_close(W, W2, 1e-15 * fabs(W));
            t += hs[i];
        }
    /* one step of 0.05 against the same in two pieces */
    memcpy(y, x, sizeof x), memcpy(u, v, sizeof v), D2 = D, W2 = W;
    assert_int_equal(exact_advance(e, m, &d, t, t + 0.05, x, v, &D, &W), 0);
    assert_int_equal(exact_advance(e, m, &d, t, t + 0.0173, y, u, &D2, &W2), 0);
    assert_int_equal(exact_advance(e, m, &d, t + 0.0173, t + 0.05, y, u, &D2, &W2), 0);
    for (int j = 0; j < N; j++)
        assert_close(x[j], y[j], 1e-14);
    assert_close(D, D2, 1e-14 * D);
    assert_close(W, W2, 1e-14 * fabs(W) + 1e-15);
    exact_free(e);
    model_free(m);
}

/* Late in a long run the steps' lengths b - a differ by the rounding of the times; the
 * cached step is corrected for that, so 20000 steps from t = 1e5 end where a stepper
 * that takes each b - a afresh does (uncorrected, they would drift about 1e-7 m). */
static void late_steps(void **state)
{
    (void)state;
    struct one o = {.b = BOUNDARY_MOTOR, .m = 1.3, .k0 = 10.0, .k1 = 10.0, .c = 0.4, .x0 = 0.1,
                    .v0 = 0.5, .sine = 1, .amp = 0.9, .om = 2.0 * M_PI * 0.83, .phi = 0.7};
    struct model *m = one_model(&o);
    struct exact *e = exact_new(1);
    struct exact_drive d = one_drive(&o);
    double x = o.x0, v = o.v0, rx = x, rv = v, D = 0.0, W = 0.0, rd = 0.0, rw = 0.0;
    for (int i = 0; i < 20000; i++) {
        double a = 1e5 + i * 0.001, b = 1e5 + (i + 1) * 0.001;
        assert_int_equal(exact_advance(e, m, &d, a, b, &x, &v, &D, &W), 0);
        struct exact *f = exact_new(1);
        assert_int_equal(exact_advance(f, m, &d, a, b, &rx, &rv, &rd, &rw), 0);
        exact_free(f);
    }
    printf("  20000 steps from t = 1e5, cached against afresh: %.2e m, D %.2e, W %.2e J\n",
           fabs(x - rx), fabs(D - rd), fabs(W - rw));
    assert_close(x, rx, 1e-12);
    assert_close(v, rv, 1e-11);
    assert_close(D, rd, 1e-12 * rd);
    assert_close(W, rw, 1e-12 * fabs(rw) + 1e-13);
    exact_free(e);
    model_free(m);
}

/* Failures leave the state and the books as they were. */
static void failures(void **state)
{
    (void)state;
    struct model *m = chain(2, BOUNDARY_MOTOR);
    struct exact *e = exact_new(2);
    assert_null(exact_new(0));
    assert_null(exact_new(MODEL_MAX_MASSES + 1));
    struct exact_drive d = {1, 0.5, 3.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
    double x[2] = {0.1, 0.2}, v[2] = {0.3, 0.4}, D = 1.0, W = 2.0;
    assert_int_equal(exact_advance(e, m, &d, 1.0, 1.0, x, v, &D, &W), 0); /* nothing to do */
    assert_int_equal(exact_advance(e, m, &d, 1.0, 0.9, x, v, &D, &W), -1);
    assert_int_equal(exact_advance(e, m, &d, 0.0, NAN, x, v, &D, &W), -1);
    m->k[1] = -1.0; /* 0 is a missing spring (exact_general.c), below 0 is not a spring */
    assert_int_equal(exact_advance(e, m, &d, 0.0, 0.01, x, v, &D, &W), -1);
    m->k[1] = NAN;
    assert_int_equal(exact_advance(e, m, &d, 0.0, 0.01, x, v, &D, &W), -1);
    m->k[1] = 10.0;
    d.omega = INFINITY;
    assert_int_equal(exact_advance(e, m, &d, 0.0, 0.01, x, v, &D, &W), -1);
    d.omega = 3.0;
    /* a state that is not finite, on a chain with neither books (nothing else to catch it) */
    m->boundary = BOUNDARY_WALL;
    m->c[0] = m->c[1] = 0.0;
    x[1] = NAN;
    assert_int_equal(exact_advance(e, m, &d, 0.0, 0.01, x, v, &D, &W), -1);
    assert_true(isnan(x[1]));
    x[1] = 0.2;
    assert_close(x[0], 0.1, 0.0);
    assert_close(v[0], 0.3, 0.0);
    assert_close(v[1], 0.4, 0.0);
    assert_close(D, 1.0, 0.0);
    assert_close(W, 2.0, 0.0);
    struct model *m3 = chain(3, BOUNDARY_MOTOR);
    assert_int_equal(exact_advance(e, m3, &d, 0.0, 0.01, x, v, &D, &W), -1); /* n differs */
    assert_int_equal(exact_advance(e, m, &d, 0.0, 0.01, x, v, &D, &W), 0);  /* and recovers */
    exact_free(e);
    exact_free(NULL);
    model_free(m);
    model_free(m3);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(undamped_wall),
        cmocka_unit_test(long_step),
        cmocka_unit_test(damped_wall),
        cmocka_unit_test(free_end),
        cmocka_unit_test(sine_motor),
        cmocka_unit_test(ramp_motor),
        cmocka_unit_test(chain_against_rk4),
        cmocka_unit_test(energy_balance),
        cmocka_unit_test(books_against_closed_form),
        cmocka_unit_test(cache),
        cmocka_unit_test(late_steps),
        cmocka_unit_test(failures),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
