/* test_contact.c: the simulator with collisions against an event-driven reference of its
 * own (contact_reference.h: Taylor series between contacts, exact contact instants, the
 * e = 0.8 restitution rule), on four scenarios: one mass and the left wall, two masses, a mass
 * hit by the moving piston, three masses with six contacts. The goals are issue 10's:
 * max position error at dt = 0.01 <= 1e-5 m and order >= 3 from dt = 0.01 to 0.0025; the
 * energy balance with the contact column within 1e-4 of the peak energy on the piston
 * scenario; momentum kept by pair contacts. The reference is first checked against
 * closed forms (piecewise harmonic bounces, free flight, a driven mass and its piston). */
#include "testutil.h"

#include <stdlib.h>
#include <string.h>

#include "contact_reference.h"
#include "core/model.h"
#include "core/sim.h"

#define GRID 0.0025 /* the finest dt compared; the reference is kept on this grid */
#define MAXSEG 64

/* ---- scenarios ---- */

struct scenario {
    const char *name;
    int n;
    enum boundary boundary;
    double amp, freq; /* sine drive, motor end only */
    double m[REF_MAXN], k[REF_MAXN + 1], c[REF_MAXN], x0[REF_MAXN], v0[REF_MAXN];
    double duration;    /* run length (s) */
    const char *events; /* the reference's contacts in order: L left, P pair, R right */
};

/* Chosen so each has its contacts in the first seconds, at approach speeds of 1.6 m/s or
 * more, none grazing (every open gap's local minimum stays >= 0.1 m) and none close to
 * another in time; scenarios_are_clean checks this on the reference. */
/* One scenario to a few lines, not one field to a line. */
/* clang-format off */
static const struct scenario scenarios[] = {
    /* Released toward the wall: one bounce at 0.33 s, 2.4 m/s; the damping keeps the
     * rebound off the right wall. */
    {.name = "wall", .n = 1, .boundary = BOUNDARY_WALL, .m = {1}, .k = {2, 2}, .c = {0.1},
     .x0 = {-3}, .v0 = {-8}, .duration = 4.0, .events = "L"},
    /* Opposite velocities, a soft spring between: they meet at 0.30 s and 3.54 s. */
    {.name = "pair", .n = 2, .boundary = BOUNDARY_WALL, .m = {1, 1.5}, .k = {2, 0.3, 2},
     .c = {0.02, 0.02}, .x0 = {0.5, -0.5}, .v0 = {4, -3}, .duration = 5.0, .events = "PP"},
    /* A 1.5 m, 1 Hz piston and a mass at rest 0.5 m from its face: the piston hits it at
     * 0.68 s (1.7 m/s) and 3.73 s (5.3 m/s), the left wall in between. */
    {.name = "piston", .n = 1, .boundary = BOUNDARY_MOTOR, .amp = 1.5, .freq = 1.0, .m = {1},
     .k = {0.5, 0.5}, .c = {0.05}, .x0 = {4.3}, .v0 = {0}, .duration = 5.0, .events = "RLR"},
    /* Three masses: both pairs and both walls, six contacts. */
    {.name = "three", .n = 3, .boundary = BOUNDARY_WALL, .m = {1, 1.5, 0.8}, .k = {3, 1, 1, 3},
     .c = {0.05, 0.05, 0.05}, .x0 = {-0.25, 0.25, -0.5}, .v0 = {0, -4, -5}, .duration = 5.0,
     .events = "PLPPRP"},
};
/* clang-format on */
#define NSCEN ((int)(sizeof scenarios / sizeof scenarios[0]))

static struct model *scenario_model(const struct scenario *sc)
{
    struct model *md = model_new(sc->n);
    assert_non_null(md);
    memcpy(md->m, sc->m, (size_t)sc->n * sizeof *md->m);
    memcpy(md->k, sc->k, (size_t)(sc->n + 1) * sizeof *md->k);
    memcpy(md->c, sc->c, (size_t)sc->n * sizeof *md->c);
    md->boundary = sc->boundary;
    md->motor = (struct motor){WAVE_SINE, sc->amp, sc->freq > 0 ? sc->freq : 1.0, 0.0};
    md->collisions = true;
    return md;
}

/* The reference on the grid t = j GRID: positions and the energy books. */
struct track {
    int steps;                                  /* grid intervals */
    double *x;                                  /* (steps + 1) * n displacements */
    double *mech, *dissipated, *work, *contact; /* steps + 1 each */
    struct ref r;                               /* the reference at the end of the run */
};

static void track_run(const struct scenario *sc, double hmax, struct track *tr)
{
    struct model *md = scenario_model(sc);
    int n = sc->n;
    tr->steps = (int)lround(sc->duration / GRID);
    size_t len = (size_t)tr->steps + 1;
    tr->x = calloc(len * (size_t)n + 4 * len, sizeof *tr->x);
    assert_non_null(tr->x);
    tr->mech = tr->x + len * (size_t)n;
    tr->dissipated = tr->mech + len;
    tr->work = tr->dissipated + len;
    tr->contact = tr->work + len;
    ref_init(&tr->r, md, sc->x0, sc->v0);
    tr->r.hmax = hmax;
    for (int j = 0; j <= tr->steps; j++) {
        ref_advance(&tr->r, j * GRID);
        assert_null(tr->r.error);
        memcpy(tr->x + (size_t)j * n, tr->r.x, (size_t)n * sizeof *tr->x);
        tr->mech[j] = ref_mechanical(&tr->r);
        tr->dissipated[j] = tr->r.dissipated;
        tr->work[j] = tr->r.motor_work;
        tr->contact[j] = tr->r.contact;
    }
    model_free(md);
}

static void track_free(struct track *tr)
{
    free(tr->x);
}

static double peak_of(const double *a, int len)
{
    double p = 0.0;
    for (int j = 0; j < len; j++)
        p = fmax(p, a[j]);
    return p;
}

/* Max |d|, NaN winning: a blown-up run must not look accurate. */
static double worse(double err, double d)
{
    return (isnan(d) || fabs(d) > err) ? fabs(d) : err;
}

/* ---- the reference against closed forms ---- */

/* A piecewise-analytic trajectory: piece p starts at t[p] from x[p], v[p]. */
struct pieces {
    int count;
    double t[MAXSEG], x[MAXSEG], v[MAXSEG];
};

static int piece_at(const struct pieces *pc, double t)
{
    int p = 0;
    while (p + 1 < pc->count && pc->t[p + 1] <= t)
        p++;
    return p;
}

/* One undamped mass between springs, walls at x = -b and +b: x = R cos(theta), v = -R w
 * sin(theta), theta growing at w. It meets the left wall moving left at theta = acos(-b/R)
 * and the right wall moving right at 2 pi - acos(b/R) (mod 2 pi); each contact makes
 * v -> -e v. */
static void harmonic_pieces(double w, double b, double x0, double v0, double tend,
                            struct pieces *pc)
{
    pc->count = 1;
    pc->t[0] = 0.0, pc->x[0] = x0, pc->v[0] = v0;
    while (pc->count < MAXSEG) {
        int p = pc->count - 1;
        double r = hypot(pc->x[p], pc->v[p] / w);
        if (r <= b)
            return;
        double th0 = atan2(-pc->v[p] / w, pc->x[p]);
        double cand[2] = {acos(-b / r), 2.0 * M_PI - acos(b / r)}, dth = INFINITY;
        int side = 0;
        for (int s = 0; s < 2; s++) {
            double d = fmod(cand[s] - th0, 2.0 * M_PI);
            if (d <= 1e-9)
                d += 2.0 * M_PI;
            if (d < dth)
                dth = d, side = s;
        }
        double tc = pc->t[p] + dth / w;
        if (tc > tend)
            return;
        pc->t[p + 1] = tc;
        pc->x[p + 1] = side == 0 ? -b : b;
        pc->v[p + 1] = -REF_E * (-r * w * sin(th0 + dth));
        pc->count++;
    }
}

static void reference_vs_harmonic_bounces(void **state)
{
    (void)state;
    struct model *md = model_new(1);
    md->boundary = BOUNDARY_WALL;
    md->m[0] = 1.0, md->k[0] = 7.0, md->k[1] = 13.0, md->c[0] = 0.0;
    double x0 = -4.0, v0 = -15.0, w = sqrt(20.0), b = 5.0 - 0.2, tend = 4.0;
    struct pieces pc;
    harmonic_pieces(w, b, x0, v0, tend, &pc);
    struct ref r;
    ref_init(&r, md, &x0, &v0);
    double err = 0.0, verr = 0.0, b0 = ref_balance(&r), drift = 0.0;
    for (int j = 1; j <= (int)lround(tend / GRID); j++) {
        double t = j * GRID;
        ref_advance(&r, t);
        int p = piece_at(&pc, t);
        double s = t - pc.t[p];
        err = worse(err, r.x[0] - (pc.x[p] * cos(w * s) + pc.v[p] / w * sin(w * s)));
        verr = worse(verr, r.v[0] - (-pc.x[p] * w * sin(w * s) + pc.v[p] * cos(w * s)));
        drift = worse(drift, ref_balance(&r) - b0);
    }
    assert_null(r.error);
    assert_int_equal(r.nev, pc.count - 1);
    double terr = 0.0;
    for (int e = 0; e < r.nev; e++) {
        terr = worse(terr, r.ev[e].t - pc.t[e + 1]);
        assert_int_equal(r.ev[e].kind, pc.x[e + 1] < 0 ? REF_LEFT : REF_RIGHT);
    }
    printf("  reference vs piecewise cos(wt), %d wall bounces in 4 s: |x| %.1e m, |v| %.1e m/s,"
           " contact times %.1e s, balance drift %.1e J\n",
           r.nev, err, verr, terr, drift);
    assert_true(r.nev >= 5);
    assert_true(err <= 1e-10 && verr <= 1e-9);
    assert_true(terr <= 1e-11);
    assert_true(drift <= 1e-11 * ref_mechanical(&r) + 1e-11);
    model_free(md);
}

/* No springs, no damping, free right end: masses fly straight and meet each other and
 * the left wall at instants found by division. Checks the pair rule (momentum kept,
 * relative velocity reversed and scaled by e) and the contact energy books. */
static void reference_vs_free_flight(void **state)
{
    (void)state;
    enum { N = 2 };
    struct model *md = model_new(N);
    md->boundary = BOUNDARY_FREE;
    md->m[0] = 1.0, md->m[1] = 3.0;
    md->k[0] = md->k[1] = md->k[2] = 0.0;
    md->c[0] = md->c[1] = 0.0;
    double x0[N] = {0.0, 0.0}, v0[N] = {2.0, -1.0}, tend = 10.0, wb = 0.4;
    double xeq[N] = {10.0 / 3.0, 20.0 / 3.0};
    /* The closed form, event by event. */
    double te[8], xs[8][N], vs[8][N], loss = 0.0;
    int ne = 0;
    double t = 0.0, x[N] = {0.0, 0.0}, v[N] = {2.0, -1.0};
    te[0] = 0.0;
    memcpy(xs[0], x, sizeof x);
    memcpy(vs[0], v, sizeof v);
    while (ne < 7) {
        double dl = v[0] < 0 ? (xeq[0] + x[0] - 0.5 * wb) / -v[0] : INFINITY;
        double dp = v[0] > v[1] ? (xeq[1] + x[1] - xeq[0] - x[0] - wb) / (v[0] - v[1]) : INFINITY;
        double d = fmin(dl, dp);
        if (t + d > tend)
            break;
        t += d;
        for (int i = 0; i < N; i++)
            x[i] += v[i] * d;
        if (dl < dp) {
            loss += 0.5 * md->m[0] * v[0] * v[0] * (1 - REF_E * REF_E);
            v[0] = -REF_E * v[0];
        } else {
            double m1 = md->m[0], m2 = md->m[1], p = m1 * v[0] + m2 * v[1], rel = v[0] - v[1];
            double v1 = (p - m2 * REF_E * rel) / (m1 + m2), v2 = v1 + REF_E * rel;
            loss += 0.5 * (m1 * (v[0] * v[0] - v1 * v1) + m2 * (v[1] * v[1] - v2 * v2));
            v[0] = v1, v[1] = v2;
        }
        ne++;
        te[ne] = t;
        memcpy(xs[ne], x, sizeof x);
        memcpy(vs[ne], v, sizeof v);
    }
    struct ref r;
    ref_init(&r, md, x0, v0);
    double err = 0.0;
    for (int j = 1; j <= (int)lround(tend / GRID); j++) {
        double tj = j * GRID;
        ref_advance(&r, tj);
        int p = 0;
        while (p < ne && te[p + 1] <= tj)
            p++;
        for (int i = 0; i < N; i++)
            err = worse(err, r.x[i] - (xs[p][i] + vs[p][i] * (tj - te[p])));
    }
    assert_null(r.error);
    assert_int_equal(r.nev, ne);
    double terr = 0.0;
    for (int e = 0; e < ne; e++)
        terr = worse(terr, r.ev[e].t - te[e + 1]);
    double verr = worse(fabs(r.v[0] - vs[ne][0]), r.v[1] - vs[ne][1]);
    printf("  reference vs free flight, %d contacts (pair and wall) in 10 s: |x| %.1e m, "
           "|v| %.1e m/s, times %.1e s, contact energy %.6f J (closed form %.6f)\n",
           ne, err, verr, terr, r.contact, loss);
    assert_true(ne >= 3);
    assert_true(r.ev[0].kind == REF_PAIR && r.ev[1].kind == REF_LEFT);
    assert_true(err <= 1e-11 && verr <= 1e-12 && terr <= 1e-11);
    assert_close(r.contact, loss, 1e-12);
    model_free(md);
}

/* The piston scenario without damping: m x'' = -(k0 + k1) x + k1 u(t), u = A sin(W t), is
 * x = C cos w(t - ts) + D sin w(t - ts) + B sin(W t), B = k1 A / (m (w^2 - W^2)). The
 * contacts are the roots of the gaps 4.8 + x (left) and 4.8 + u - x (piston face),
 * bracketed on a 1e-4 s scan of these formulas and bisected. */
struct driven {
    double w, W, A, B;
};

static void driven_at(const struct driven *d, const struct pieces *pc, int p, double t, double *x,
                      double *v)
{
    double ts = pc->t[p];
    double c0 = pc->x[p] - d->B * sin(d->W * ts);
    double d0 = (pc->v[p] - d->B * d->W * cos(d->W * ts)) / d->w;
    double s = t - ts;
    *x = c0 * cos(d->w * s) + d0 * sin(d->w * s) + d->B * sin(d->W * t);
    *v = d->w * (-c0 * sin(d->w * s) + d0 * cos(d->w * s)) + d->B * d->W * cos(d->W * t);
}

static double driven_gap(const struct driven *d, const struct pieces *pc, int p, double t,
                         int right)
{
    double x, v;
    driven_at(d, pc, p, t, &x, &v);
    return right ? 4.8 + d->A * sin(d->W * t) - x : 4.8 + x;
}

static void reference_vs_driven_piston(void **state)
{
    (void)state;
    const struct scenario *sc = &scenarios[2];
    struct model *md = scenario_model(sc);
    md->c[0] = 0.0;
    double tend = sc->duration;
    struct driven d = {1.0, 2.0 * M_PI, sc->amp, 0.0};
    d.B = sc->k[1] * sc->amp / (sc->m[0] * (d.w * d.w - d.W * d.W));
    struct pieces pc = {1, {0.0}, {sc->x0[0]}, {sc->v0[0]}};
    int kinds[MAXSEG];
    double step = 1e-4, t = 0.0;
    while (t < tend && pc.count < MAXSEG) {
        int p = pc.count - 1, hit = -1;
        double a = t, bnd = t + step;
        for (int side = 0; side < 2; side++)
            if (driven_gap(&d, &pc, p, bnd, side) < 0 && driven_gap(&d, &pc, p, a, side) > 0)
                hit = side;
        if (hit < 0) {
            t = bnd;
            continue;
        }
        for (int it = 0; it < 200; it++) {
            double mid = 0.5 * (a + bnd);
            if (mid <= a || mid >= bnd)
                break;
            if (driven_gap(&d, &pc, p, mid, hit) > 0)
                a = mid;
            else
                bnd = mid;
        }
        double x, v, du = hit ? d.A * d.W * cos(d.W * a) : 0.0;
        driven_at(&d, &pc, p, a, &x, &v);
        pc.t[pc.count] = a, pc.x[pc.count] = x, pc.v[pc.count] = du - REF_E * (v - du);
        kinds[pc.count - 1] = hit ? REF_RIGHT : REF_LEFT;
        pc.count++;
        t = a;
    }
    struct ref r;
    ref_init(&r, md, sc->x0, sc->v0);
    double err = 0.0, b0 = ref_balance(&r), drift = 0.0, peak = ref_mechanical(&r);
    for (int j = 1; j <= (int)lround(tend / GRID); j++) {
        double tj = j * GRID, x, v;
        ref_advance(&r, tj);
        driven_at(&d, &pc, piece_at(&pc, tj), tj, &x, &v);
        err = worse(err, r.x[0] - x);
        drift = worse(drift, ref_balance(&r) - b0);
        peak = fmax(peak, ref_mechanical(&r));
    }
    assert_null(r.error);
    assert_int_equal(r.nev, pc.count - 1);
    double terr = 0.0;
    for (int e = 0; e < r.nev; e++) {
        terr = worse(terr, r.ev[e].t - pc.t[e + 1]);
        assert_int_equal(r.ev[e].kind, kinds[e]);
    }
    printf("  reference vs driven mass and piston (closed form), %d contacts in 5 s: |x| %.1e m,"
           " times %.1e s, balance drift %.1e J (motor work %.3f J)\n",
           r.nev, err, terr, drift, r.motor_work);
    assert_true(r.nev >= 3);
    assert_true(err <= 1e-10 && terr <= 1e-11);
    assert_true(drift <= 1e-12 * peak);
    model_free(md);
}

/* Each scenario's reference: its contacts as named, none grazing or nearly simultaneous,
 * the energy books closing, and the same answer with sub-steps four times shorter. */
static void scenarios_are_clean(void **state)
{
    (void)state;
    for (int s = 0; s < NSCEN; s++) {
        const struct scenario *sc = &scenarios[s];
        struct track a, b;
        track_run(sc, REF_HMAX, &a);
        track_run(sc, REF_HMAX / 4, &b);
        /* The reference holds the rule's numbers itself; they must be the model's. */
        struct model *md = scenario_model(sc);
        assert_true(a.r.w == model_block_width(md) && REF_E == MODEL_RESTITUTION);
        assert_true(REF_L == MODEL_LENGTH &&
                    a.r.xeq[sc->n - 1] == model_equilibrium(md, sc->n - 1));
        model_free(md);
        int len = a.steps + 1, n = sc->n;
        double self = 0.0, drift = 0.0, minspeed = INFINITY, minsep = INFINITY;
        for (int j = 0; j < len * n; j++)
            self = worse(self, a.x[j] - b.x[j]);
        double b0 = a.mech[0];
        for (int j = 0; j < len; j++)
            drift = worse(drift, a.mech[j] + a.dissipated[j] + a.contact[j] - a.work[j] - b0);
        char kinds[REF_MAXEVENTS + 1];
        for (int e = 0; e < a.r.nev; e++) {
            kinds[e] = "LPR"[a.r.ev[e].kind];
            minspeed = fmin(minspeed, a.r.ev[e].speed);
            if (e > 0)
                minsep = fmin(minsep, a.r.ev[e].t - a.r.ev[e - 1].t);
        }
        kinds[a.r.nev] = '\0';
        printf("  %-6s contacts %-6s (first at %.4f s), slowest %.2f m/s, closest open gap %.3f"
               " m, apart >= %.2f s; balance drift %.1e of %.1f J; h/4 changes x by %.1e m\n",
               sc->name, kinds, a.r.ev[0].t, minspeed, a.r.near_miss, minsep,
               drift / peak_of(a.mech, len), peak_of(a.mech, len), self);
        assert_string_equal(kinds, sc->events);
        assert_true(minspeed >= 1.0);
        assert_true(a.r.near_miss >= 0.1);
        assert_true(minsep >= 0.1);
        assert_true(drift <= 1e-12 * peak_of(a.mech, len));
        assert_true(self <= 1e-9);
        track_free(&a);
        track_free(&b);
    }
}

/* ---- the simulator against the reference ---- */

/* Max |x_sim - x_ref| over every step of the run at step dt. */
static double sim_error(const struct scenario *sc, const struct track *tr, double dt)
{
    struct model *md = scenario_model(sc);
    struct sim *s = sim_new(md, dt);
    assert_non_null(s);
    sim_reset(s, sc->x0, sc->v0);
    int stride = (int)lround(dt / GRID), steps = (int)lround(sc->duration / dt);
    double err = 0.0;
    for (int j = 1; j <= steps; j++) {
        assert_int_equal(sim_step(s), SIM_OK);
        const double *ref = tr->x + (size_t)j * stride * sc->n;
        for (int i = 0; i < sc->n; i++)
            err = worse(err, sim_x(s)[i] - ref[i]);
    }
    assert_close(sim_time(s), sc->duration, 1e-9);
    sim_free(s);
    model_free(md);
    return err;
}

static void accuracy_and_order(void **state)
{
    (void)state;
    static const double dts[3] = {0.01, 0.005, 0.0025};
    double err[NSCEN][3], fit[NSCEN];
    printf("  max |x - x_ref| over the run; order: log2 of successive ratios, and the fit\n");
    printf("  %-7s %11s %11s %11s %7s %7s %7s\n", "", "dt=0.01", "dt=0.005", "dt=0.0025", "p1",
           "p2", "fit");
    for (int s = 0; s < NSCEN; s++) {
        struct track tr;
        track_run(&scenarios[s], REF_HMAX, &tr);
        for (int d = 0; d < 3; d++)
            err[s][d] = sim_error(&scenarios[s], &tr, dts[d]);
        track_free(&tr);
        /* Least squares through three points equally spaced in log2 dt. */
        fit[s] = 0.5 * log2(err[s][0] / err[s][2]);
        printf("  %-7s %11.3e %11.3e %11.3e %7.2f %7.2f %7.2f\n", scenarios[s].name, err[s][0],
               err[s][1], err[s][2], log2(err[s][0] / err[s][1]), log2(err[s][1] / err[s][2]),
               fit[s]);
    }
    for (int s = 0; s < NSCEN; s++) {
        if (!(err[s][0] <= 1e-5))
            fail_msg("%s: max error at dt = 0.01 is %.3e m, goal <= 1e-5 m", scenarios[s].name,
                     err[s][0]);
        if (!(fit[s] >= 3.0))
            fail_msg("%s: observed order %.2f, goal >= 3", scenarios[s].name, fit[s]);
    }
}

/* The piston scenario at dt = 0.01: kinetic + potential + dissipated + contact - motor_work
 * stays within 1e-4 of the peak energy, the contact column is never negative, and each
 * book agrees with the reference's (the piston's contact work is motor work, the loss in
 * the piston's frame is contact). */
static void piston_energy_balance(void **state)
{
    (void)state;
    const struct scenario *sc = &scenarios[2];
    struct track tr;
    track_run(sc, REF_HMAX, &tr);
    double peak = peak_of(tr.mech, tr.steps + 1), dt = 0.01;
    struct model *md = scenario_model(sc);
    struct sim *s = sim_new(md, dt);
    sim_reset(s, sc->x0, sc->v0);
    struct energy e;
    sim_energy(s, &e);
    double b0 = e.balance, drift = 0.0, dc = 0.0, dw = 0.0, dd = 0.0, cmin = 0.0;
    int stride = (int)lround(dt / GRID), steps = (int)lround(sc->duration / dt);
    for (int j = 1; j <= steps; j++) {
        assert_int_equal(sim_step(s), SIM_OK);
        sim_energy(s, &e);
        int g = j * stride;
        drift = worse(drift, e.balance - b0);
        dc = worse(dc, e.contact - tr.contact[g]);
        dw = worse(dw, e.motor_work - tr.work[g]);
        dd = worse(dd, e.dissipated - tr.dissipated[g]);
        cmin = fmin(cmin, e.contact);
    }
    printf("  piston, dt = 0.01, peak energy %.3f J: balance drift %.2e J (%.1e of peak); vs "
           "reference: contact %.2e, motor_work %.2e, dissipated %.2e J; contact at end %.4f J"
           " (reference %.4f), lowest %.2e J\n",
           peak, drift, drift / peak, dc, dw, dd, e.contact, tr.contact[tr.steps], cmin);
    assert_true(drift <= 1e-4 * peak);
    assert_true(cmin >= 0.0);
    assert_true(dc <= 1e-4 * peak);
    assert_true(dw <= 1e-4 * peak);
    assert_true(dd <= 1e-4 * peak);
    sim_free(s);
    model_free(md);
    track_free(&tr);
}

/* Pair contacts keep momentum. No wall spring, no damping, a free right end: only the
 * springs between masses act, and they cancel, so sum m v is constant through every step,
 * contacts included, to rounding. Two masses meeting head on, then a cradle of three where
 * the middle mass, hit, runs into the third 5 cm away. No pair may be left touching and
 * approaching. */
static void pair_contacts_keep_momentum(void **state)
{
    (void)state;
    static const struct {
        int n;
        double m[3], x0[3], v0[3];
    } runs[2] = {
        {2, {1.0, 2.0}, {0.0, 0.0}, {3.0, -1.0}},
        {3, {1.0, 1.0, 1.0}, {0.5, 1.0, -1.05}, {3.0, 0.0, 0.0}},
    };
    for (int k = 0; k < 2; k++) {
        int n = runs[k].n;
        struct model *md = model_new(n);
        md->boundary = BOUNDARY_FREE;
        for (int i = 0; i < n; i++) {
            md->m[i] = runs[k].m[i];
            md->c[i] = 0.0;
            md->k[i + 1] = 0.1;
        }
        md->k[0] = 0.0;
        struct sim *s = sim_new(md, 0.01);
        sim_reset(s, runs[k].x0, runs[k].v0);
        double p0 = 0.0, dp = 0.0, w = model_block_width(md);
        for (int i = 0; i < n; i++)
            p0 += runs[k].m[i] * runs[k].v0[i];
        int reversed = 0, bad = 0;
        for (int j = 0; j < 200; j++) {
            double before = sim_v(s)[0] - sim_v(s)[1];
            assert_int_equal(sim_step(s), SIM_OK);
            const double *x = sim_x(s), *v = sim_v(s);
            double p = 0.0;
            for (int i = 0; i < n; i++)
                p += runs[k].m[i] * v[i];
            dp = worse(dp, p - p0);
            if (before > 0 && v[0] - v[1] < 0)
                reversed++;
            for (int i = 0; i + 1 < n; i++) {
                double gap =
                    model_equilibrium(md, i + 1) + x[i + 1] - model_equilibrium(md, i) - x[i] - w;
                if (gap <= 1e-9 && v[i] > v[i + 1])
                    bad++;
            }
            assert_true(model_equilibrium(md, 0) + x[0] > 0.5 * w);
        }
        printf("  %d masses, pair contacts over 2 s: |sum m v - p0| <= %.1e (p0 = %.1f), "
               "touching and approaching at %d steps\n",
               n, dp, p0, bad);
        assert_true(reversed >= 1);
        assert_true(dp <= 1e-12);
        assert_int_equal(bad, 0);
        if (n == 3)
            assert_true(sim_v(s)[2] > 0.5); /* the third mass was hit */
        sim_free(s);
        model_free(md);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(reference_vs_harmonic_bounces),
        cmocka_unit_test(reference_vs_free_flight),
        cmocka_unit_test(reference_vs_driven_piston),
        cmocka_unit_test(scenarios_are_clean),
        cmocka_unit_test(accuracy_and_order),
        cmocka_unit_test(piston_energy_balance),
        cmocka_unit_test(pair_contacts_keep_momentum),
    };
    return cmocka_run_group_tests_name("contact", tests, NULL, NULL);
}
