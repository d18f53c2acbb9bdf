/* test_campaign.c: the simulator with contacts against the event-driven reference
 * (contact_reference.h) on a random campaign: chains of 1 to 30 masses (CAMPAIGN_MAXN sets
 * the most), every right end and waveform, head-on throws, piles (masses thrown one way
 * together), masses left to settle on a wall or on the piston, and square pistons.
 * Issue 17's goals, case by case:
 *
 *  - rk4 keeps order >= 3 from dt = 0.01 to 0.0025 (a least-squares slope through the
 *    three errors) in every case but the chaotic ones;
 *  - its contact count equals the reference's at every dt;
 *  - a mass the reference holds on the wall has |v| <= 1e-6 m/s in the simulation;
 *  - the contact column never decreases, and at dt = 0.0025 kinetic + potential +
 *    dissipated + contact - motor_work stays within 1e-6 of the peak energy.
 *
 * Chaotic: the reference itself, started 1e-9 m away and sampled four times as often (its
 * sub-steps then end elsewhere), ends more than 1e-6 m away: its contacts amplify a
 * perturbation 1e3 times, so no fixed-step run can show its order (a grazing contact that
 * comes or goes with the perturbation is one such). Piston jumps into the last mass and
 * into piles are judged like any case. Cases the reference cannot judge (two contacts at
 * one instant, an impact whose 16th sweep still made a contact at the rest speed or
 * faster) are counted and left out. A case whose reference makes a call within the method's own error (a
 * contact within 1e-4 m/s of the rest speed, a graze within 1e-5 m of touching) may count
 * one contact more or less: its count is not compared, its motion is. CAMPAIGN_CASES sets
 * the number of cases (default 240; the memcheck run takes 8 of N 1 to 10), CAMPAIGN_FIRST
 * the first.
 * A case with such a call whose order falls short is run again at dt = 0.00125 and
 * 0.000625, where the call is made as the reference makes it, and judged there. */
#include "testutil.h"

#include <stdlib.h>
#include <string.h>

#include "contact_reference.h"
#include "core/model.h"
#include "core/sim.h"

#define GRID 0.0025
#define DURATION 5.0

static uint64_t rng_state;

static double uniform(double lo, double hi)
{
    return test_uniform(&rng_state, lo, hi);
}

struct kase {
    struct model *m;
    double x0[REF_MAXN], v0[REF_MAXN];
    const char *kind;
    double duration; /* s */
};

/* Case j of the campaign. */
static void make_case(int j, struct kase *c)
{
    rng_state = 0x9E3779B97F4A7C15ull ^ (uint64_t)(j + 1) * 0xBF58476D1CE4E5B9ull;
    for (int i = 0; i < 4; i++)
        uniform(0, 1);
    const char *most = getenv("CAMPAIGN_MAXN");
    int n = 1 + (int)uniform(0, most ? atoi(most) : 30);
    struct model *m = model_new(n);
    assert_non_null(m);
    m->boundary = (enum boundary)(int)uniform(0, 3);
    m->motor.wave = (enum wave)(int)uniform(0, 4);
    m->motor.frequency = uniform(0.2, 2.0);
    m->motor.amplitude = uniform(0.0, 1.5);
    for (int i = 0; i < n; i++) {
        m->m[i] = uniform(0.3, 3.0);
        m->c[i] = uniform(0.0, 1.0) < 0.3 ? 0.0 : uniform(0.0, 1.5);
    }
    for (int i = 0; i <= n; i++)
        m->k[i] = uniform(0.5, 40.0);
    double sp = MODEL_LENGTH / (n + 1), w = model_block_width(m);
    /* Displacements leaving every gap open by at least a tenth of the free room. */
    double room = sp - w;
    int style = j % 6;
    for (int i = 0; i < n; i++) {
        c->x0[i] = uniform(-0.4, 0.4) * room;
        c->v0[i] = uniform(-6.0, 6.0);
    }
    c->kind = "throw";
    if (style == 1) { /* a pile: everything thrown at the left wall */
        double v = uniform(-9.0, -3.0);
        for (int i = 0; i < n; i++)
            c->v0[i] = v * uniform(0.8, 1.2);
        c->kind = "pile";
    } else if (style == 2) { /* pressed on the wall by a long, slow drive, and let go */
        m->boundary = BOUNDARY_MOTOR;
        m->motor.wave = WAVE_SINE;
        m->motor.frequency = uniform(0.1, 0.25);
        m->motor.phase = 0.5; /* pushing first */
        double compliance = 0.0;
        m->k[0] = uniform(0.5, 3.0);
        for (int i = 0; i <= n; i++)
            compliance += 1.0 / m->k[i];
        /* Statically, mass 1 moves by u (1 / k_0) / sum (1 / k_j): past its wall. */
        m->motor.amplitude = -uniform(1.1, 1.6) * (0.5 * w - sp) * m->k[0] * compliance;
        if (m->motor.amplitude > 6.0)
            m->motor.amplitude = 6.0;
        for (int i = 0; i < n; i++)
            c->v0[i] = uniform(-1.0, 1.0), m->c[i] = uniform(0.2, 2.0);
        c->kind = "rest";
    } else if (style == 3) { /* a square piston near the last mass */
        m->boundary = BOUNDARY_MOTOR;
        m->motor.wave = WAVE_SQUARE;
        m->motor.amplitude = uniform(0.1, 0.4) * room;
        m->motor.frequency = uniform(0.3, 1.5);
        c->x0[n - 1] = 0.3 * room;
        c->v0[n - 1] = uniform(0.0, 3.0);
        c->kind = "square";
    }
    c->m = m;
    c->duration = DURATION;
}

/* The reference on the grid, with what it says of the run. */
struct track {
    double grid; /* the reference is kept at t = j grid */
    int steps;
    double *x, *v; /* (steps + 1) * n each */
    unsigned char *wall; /* (steps + 1) * n: the wall holds mass i then */
    int contacts;
    const char *error;
    double near_miss, near_rest; /* the reference's closest graze and rest-threshold call */
};

static void track_run(const struct kase *c, double dx, double grid, struct track *tr)
{
    tr->grid = grid;
    int n = c->m->n;
    tr->steps = (int)lround(c->duration / grid);
    size_t len = (size_t)(tr->steps + 1) * (size_t)n;
    tr->x = calloc(2 * len, sizeof *tr->x);
    tr->wall = calloc(len, 1);
    assert_true(tr->x && tr->wall);
    tr->v = tr->x + len;
    struct ref *r = malloc(sizeof *r);
    assert_non_null(r);
    double x0[REF_MAXN];
    for (int i = 0; i < n; i++)
        x0[i] = c->x0[i] + dx;
    ref_init(r, c->m, x0, c->v0);
    double b0 = ref_balance(r);
    for (int j = 0; j <= tr->steps && !r->error; j++) {
        ref_advance(r, j * grid);
        memcpy(tr->x + (size_t)j * n, r->x, (size_t)n * sizeof *r->x);
        memcpy(tr->v + (size_t)j * n, r->v, (size_t)n * sizeof *r->v);
        for (int i = 0, f, l; i < n; i++)
            tr->wall[(size_t)j * n + i] = ref_cluster(r, i, &f, &l) < 0;
    }
    tr->contacts = r->count;
    tr->near_miss = r->near_miss, tr->near_rest = r->near_rest;
    tr->error = r->error;
    if (!r->error && !(fabs(ref_balance(r) - b0) <= 1e-9 * fmax(1.0, r->motor_work)))
        tr->error = "the reference's own energy balance drifted";
    free(r);
}

static void track_free(struct track *tr)
{
    free(tr->x);
    free(tr->wall);
}

/* What the simulation at step dt did against the track. */
struct outcome {
    double err;       /* max |x - x_ref| on its grid */
    int contacts;     /* contacts counted */
    double rest_v;    /* max |v| of a mass the reference holds on the wall */
    double drop;      /* largest decrease of the contact column */
    double imbalance; /* max |balance - balance(0)| over the peak energy */
};

static void sim_run_with(const struct kase *c, const struct track *tr, double dt,
                         enum integrator integ, struct outcome *o)
{
    int n = c->m->n;
    struct sim *s = sim_new(c->m, dt);
    assert_non_null(s);
    sim_reset(s, c->x0, c->v0);
    sim_set_integrator(s, integ);
    int stride = (int)lround(dt / tr->grid), steps = (int)lround(c->duration / dt);
    struct energy e;
    sim_energy(s, &e);
    double b0 = e.balance, peak = e.kinetic + e.potential, last = e.contact, worst = 0.0;
    *o = (struct outcome){0.0, 0, 0.0, 0.0, 0.0};
    for (int j = 1; j <= steps; j++) {
        assert_int_equal(sim_step(s), SIM_OK);
        o->contacts += sim_last_contacts(s);
        size_t g = (size_t)j * stride * n;
        for (int i = 0; i < n; i++) {
            double d = fabs(sim_x(s)[i] - tr->x[g + i]);
            o->err = isnan(d) || d > o->err ? d : o->err;
            if (tr->wall[g + i] && (j == steps || tr->wall[g + (size_t)stride * n + i]) &&
                (j == 1 || tr->wall[g - (size_t)stride * n + i]))
                o->rest_v = fmax(o->rest_v, fabs(sim_v(s)[i]));
        }
        sim_energy(s, &e);
        o->drop = fmax(o->drop, last - e.contact);
        last = e.contact;
        peak = fmax(peak, e.kinetic + e.potential);
        worst = fmax(worst, fabs(e.balance - b0));
    }
    o->imbalance = worst / peak;
    sim_free(s);
}

static void sim_run(const struct kase *c, const struct track *tr, double dt, struct outcome *o)
{
    sim_run_with(c, tr, dt, INTEGRATOR_RK4, o);
}

/* A case whose reference makes a call closer than the method's error at the campaign's
 * steps (a contact at about the rest speed), whose order from dt = 0.01 to 0.0025 was
 * short: judged on finer steps, where the call is made as the reference makes it. The
 * error must fall at order >= 3 from dt = 0.00125 to 0.000625 (or be rounding's); the
 * counts are not compared (sweeps below the rest speed are counted as the method takes
 * them). *order is then that order; false, with why, if not. */
static bool refined(const struct kase *c, double *order, char *why, size_t size)
{
    static const double fine[2] = {0.00125, 0.000625};
    struct track tr;
    track_run(c, 0.0, fine[1], &tr);
    struct outcome o[2];
    for (int d = 0; d < 2 && !tr.error; d++)
        sim_run(c, &tr, fine[d], &o[d]);
    bool ok = !tr.error;
    if (!ok) {
        snprintf(why, size, "the reference on the finer grid: %s", tr.error);
    } else {
        *order = log2(o[0].err / o[1].err);
        printf("    refined: err %.2e %.2e at dt %g and %g, order %.2f, contacts %d/%d ref %d\n",
               o[0].err, o[1].err, fine[0], fine[1], *order, o[0].contacts, o[1].contacts,
               tr.contacts);
        if (!(*order >= 3.0 || o[0].err <= 1e-10))
            ok = false, snprintf(why, size, "order %.2f at dt %g to %g", *order, fine[0], fine[1]);
    }
    track_free(&tr);
    return ok;
}

static void campaign(void **state)
{
    (void)state;
    const char *env = getenv("CAMPAIGN_CASES");
    int cases = env ? atoi(env) : 240;
    const char *from = getenv("CAMPAIGN_FIRST"); /* for looking at one case */
    static const double dts[3] = {0.01, 0.005, 0.0025};
    int judged = 0, chaotic = 0, unjudged = 0, failed = 0, resting = 0, borderline = 0;
    double worst_order = INFINITY, worst_rest = 0.0, worst_drop = 0.0, worst_bal = 0.0;
    int first = from ? atoi(from) : 0;
    for (int j = first; j < cases; j++) {
        struct kase c;
        make_case(j, &c);
        struct track tr, pert;
        track_run(&c, 0.0, GRID, &tr);
        if (tr.error) {
            unjudged++;
            printf("  case %3d (%s, N %d): not judged: %s\n", j, c.kind, c.m->n, tr.error);
            track_free(&tr);
            model_free(c.m);
            continue;
        }
        /* Started 1e-9 m away and sampled four times as often (its sub-steps then end
         * elsewhere): a reference that this moves by more than 1e-6 m judges nothing. */
        track_run(&c, 1e-9, GRID / 4, &pert);
        double spread = 0.0;
        int n = c.m->n;
        size_t len = (size_t)(tr.steps + 1) * (size_t)n;
        for (size_t i = 0; i < len && !pert.error; i++)
            spread = fmax(spread, fabs(pert.x[4 * (i / n) * n + i % n] - tr.x[i]));
        bool chaos = pert.error || spread > 1e-6;
        struct outcome o[3];
        for (int d = 0; d < 3; d++)
            sim_run(&c, &tr, dts[d], &o[d]);
        double order = 0.5 * log2(o[0].err / o[2].err);
        bool ok = true;
        char why[200] = "";
        if (!chaos) {
            judged++;
            /* Below 1e-10 m at dt = 0.01 the error is rounding's, which has no order. */
            if (!(order >= 3.0 || o[0].err <= 1e-10))
                ok = false, snprintf(why, sizeof why, "order %.2f", order);
            /* A contact within 1e-4 m/s of the rest speed (bounce or rest) or a graze within
             * 1e-5 m of touching is a call closer than the method's own error at dt = 0.01:
             * the count may differ by it; the motion is still judged, on finer steps where
             * the coarse ones make the call otherwise than the reference. */
            bool sharp = tr.near_rest < 1e-4 || tr.near_miss < 1e-5;
            borderline += sharp;
            if (sharp && !ok)
                ok = refined(&c, &order, why, sizeof why);
            if (o[0].err <= 1e-10)
                order = INFINITY;
            worst_order = fmin(worst_order, order);
            for (int d = 0; d < 3 && !sharp; d++)
                if (o[d].contacts != tr.contacts)
                    ok = false, snprintf(why, sizeof why, "%d contacts at dt %g, reference %d",
                                         o[d].contacts, dts[d], tr.contacts);
        } else {
            chaotic++;
        }
        bool rests = false;
        for (size_t i = 0; i < len; i++)
            rests |= tr.wall[i];
        resting += rests;
        for (int d = 0; d < 3; d++) {
            if (!chaos)
                worst_rest = fmax(worst_rest, o[d].rest_v);
            worst_drop = fmax(worst_drop, o[d].drop);
            if (!(o[d].rest_v <= 1e-6) && !chaos)
                ok = false, snprintf(why, sizeof why, "resting |v| %.2e", o[d].rest_v);
            if (o[d].drop > 0.0)
                ok = false, snprintf(why, sizeof why, "contact column fell %.2e J", o[d].drop);
        }
        worst_bal = fmax(worst_bal, o[2].imbalance);
        if (!(o[2].imbalance <= 1e-6))
            ok = false, snprintf(why, sizeof why, "balance %.2e of the peak", o[2].imbalance);
        if (!ok || chaos)
            printf("  case %3d (%-6s N %2d, %s %s): err %.2e %.2e %.2e, order %.2f, "
                   "contacts %d/%d/%d ref %d, spread %.1e%s%s\n",
                   j, c.kind, c.m->n, (const char *[]){"motor", "wall", "free"}[c.m->boundary],
                   (const char *[]){"sine", "square", "triangle", "sawtooth"}[c.m->motor.wave],
                   o[0].err, o[1].err, o[2].err, order, o[0].contacts, o[1].contacts,
                   o[2].contacts, tr.contacts, spread, chaos ? " chaotic" : "",
                   ok ? "" : " FAILS: ");
        if (!ok)
            printf("    %s; closest graze %.1e m, closest call at the rest speed %.1e m/s\n", why,
                   tr.near_miss, tr.near_rest);
        failed += !ok;
        track_free(&tr);
        track_free(&pert);
        model_free(c.m);
    }
    printf("  %d cases: %d judged (%d with a contact at a threshold, their counts not compared),"
           " %d chaotic, %d the reference cannot judge; %d with a mass resting on the wall. "
           "Judged: worst order %.2f; worst resting |v| %.1e m/s, contact column's largest fall "
           "%.1e J, balance within %.1e of the peak at dt 0.0025; %d failed\n",
           cases, judged, borderline, chaotic, unjudged, resting, worst_order, worst_rest,
           worst_drop, worst_bal, failed);
    assert_int_equal(failed, 0);
    assert_true(judged >= (cases - first) * 3 / 4);
}

/* Issue 17's three cases, each against the reference at dt = 0.01 ... 0.00125: two
 * neighbouring pairs meeting in one step, a graze shorter than a step, a mass pressed on
 * the wall by the piston for most of a second. */
static void numbered_cases(void **state)
{
    (void)state;
    static const double dts[4] = {0.01, 0.005, 0.0025, 0.00125};
    for (int j = 0; j < 5; j++) {
        struct kase c = {
            .kind = (const char *[]){"neighbours", "graze", "rest", "corner", "overrun"}[j]};
        c.m = model_new(j == 0 || j == 3 ? 3 - (j == 3) : 1);
        assert_non_null(c.m);
        c.duration = (const double[]){5.0, 5.0, 20.0, 2.1, 0.5}[j];
        if (j == 0) { /* -n 3 --damping 0 --boundary wall --x0=1.95,0,-2.09 --v0=10,0,0 */
            c.m->boundary = BOUNDARY_WALL;
            for (int i = 0; i < 3; i++)
                c.m->c[i] = 0.0;
            c.x0[0] = 1.95, c.x0[1] = 0.0, c.x0[2] = -2.09, c.v0[0] = 10.0;
        } else if (j == 1) { /* --spring 50,10 --damping 0 --boundary free --x0=-4 --v0=... */
            c.m->k[0] = 50.0, c.m->c[0] = 0.0, c.m->boundary = BOUNDARY_FREE;
            c.x0[0] = -4.0, c.v0[0] = -18.762942213309717;
        } else if (j == 2) { /* --spring 2,50 --damping 1 --amplitude 6 --frequency 0.1 */
            c.m->k[0] = 2.0, c.m->k[1] = 50.0, c.m->c[0] = 1.0;
            c.m->motor.amplitude = 6.0, c.m->motor.frequency = 0.1;
        } else if (j == 3) {
            /* A review's find: mass 2 comes to rest on the triangle piston at once; at
             * its corner at 0.5 s the piston turns into the mass (a contact at 2 m/s).
             * -n 2 --mass 1000,1 --spring 0.01,10,0.5 --damping 0 --wave triangle
             * --amplitude 0.5 --frequency 0.5 --x0 4.2,3.1333332333 --v0 0,1.0001 */
            c.m->m[0] = 1000.0, c.m->k[0] = 0.01, c.m->k[2] = 0.5;
            c.m->c[0] = c.m->c[1] = 0.0;
            c.m->motor = (struct motor){WAVE_TRIANGLE, 0.5, 0.5, 0.0};
            c.x0[0] = 4.2, c.x0[1] = 3.1333332333, c.v0[1] = 1.0001;
        } else {
            /* The piston's furthest reach in falls inside a step and overruns the mass
             * by 20 um: a contact the cubic of the drive alone would miss. */
            c.m->k[0] = c.m->k[1] = 1e-6, c.m->c[0] = 0.0;
            c.m->motor = (struct motor){WAVE_SINE, 1.0, 5.0, 0.125};
            c.x0[0] = 10.0 - 1.0 - 0.2 - 5.0 + 2e-5;
        }
        struct track tr;
        track_run(&c, 0.0, dts[3], &tr);
        if (tr.error)
            fail_msg("%s: the reference: %s", c.kind, tr.error);
        struct outcome o[4];
        for (int d = 0; d < 4; d++)
            sim_run(&c, &tr, dts[d], &o[d]);
        bool held = false;
        for (size_t i = 0; i < (size_t)(tr.steps + 1) * (size_t)c.m->n; i++)
            held |= tr.wall[i];
        printf("  %-10s reference: %d contacts%s; max |x - x_ref| %.2e %.2e %.2e %.2e m; "
               "contacts %d %d %d %d; resting |v| <= %.1e m/s; contact column's largest fall "
               "%.1e J; balance within %.1e of the peak at dt 0.0025\n",
               c.kind, tr.contacts, held ? ", a mass held on the wall" : "", o[0].err, o[1].err,
               o[2].err, o[3].err, o[0].contacts, o[1].contacts, o[2].contacts, o[3].contacts,
               fmax(fmax(o[0].rest_v, o[1].rest_v), fmax(o[2].rest_v, o[3].rest_v)),
               fmax(o[0].drop, o[3].drop), o[2].imbalance);
        /* The graze touches 37 um deep at 0.2 m/s: its rebound speed goes as the square
         * root of the depth, so it multiplies rk4's own error at dt = 0.01 (5e-7 m before
         * it) some thousand times; the exact integrator, whose steps have no error, shows
         * that the contacts themselves are found to 1e-8 m there. */
        struct outcome ex;
        sim_run_with(&c, &tr, dts[0], INTEGRATOR_EXACT, &ex);
        printf("    exact at dt 0.01: max |x - x_ref| %.2e m, contacts %d\n", ex.err, ex.contacts);
        assert_true(ex.err <= 1e-8);
        assert_int_equal(ex.contacts, tr.contacts);
        assert_true(o[j == 1 ? 2 : 0].err <= 1e-5);
        assert_true(tr.contacts >= 1);
        assert_true(0.5 * log2(o[0].err / o[2].err) >= 3.0 || o[0].err <= 1e-10);
        for (int d = 0; d < 4; d++) {
            assert_int_equal(o[d].contacts, tr.contacts);
            assert_true(o[d].rest_v <= 1e-6);
            assert_true(o[d].drop <= 0.0);
        }
        assert_true(o[2].imbalance <= 1e-6);
        assert_true(j != 2 || held);
        track_free(&tr);
        model_free(c.m);
    }
}

/* The graze case at dt = 0.01 with some steps taken in 8 sub-steps of dt/8 (sim_set_dt
 * and back): those holding a contact of the reference (fine = 1), or all the others
 * (fine = 2), or none (0). The largest |x - x_ref| on the 0.01 grid. */
static double graze_split(const struct kase *c, const struct track *tr, int fine)
{
    const double dt = 0.01;
    struct ref *r = malloc(sizeof *r);
    assert_non_null(r);
    ref_init(r, c->m, c->x0, c->v0);
    ref_advance(r, c->duration);
    assert_true(r->nev <= REF_MAXEVENTS);
    struct sim *s = sim_new(c->m, dt);
    assert_non_null(s);
    sim_reset(s, c->x0, c->v0);
    int stride = (int)lround(dt / tr->grid), steps = (int)lround(c->duration / dt);
    double err = 0.0;
    for (int j = 1; j <= steps; j++) {
        bool contact = false;
        for (int e = 0; e < r->nev; e++)
            contact |= r->ev[e].t > (j - 1) * dt && r->ev[e].t <= j * dt;
        bool split = fine == 1 ? contact : fine == 2 && !contact;
        sim_set_dt(s, split ? dt / 8 : dt);
        for (int q = 0; q < (split ? 8 : 1); q++)
            assert_int_equal(sim_step(s), SIM_OK);
        err = fmax(err, fabs(sim_x(s)[0] - tr->x[(size_t)j * stride]));
    }
    sim_free(s);
    free(r);
    return err;
}

/* The graze's error at dt = 0.01 (issue 31 asked for 1e-4 m) is rk4's own error in the
 * free flight between the grazes, which each graze then multiplies (its rebound speed
 * goes as the square root of the depth): taking the six steps that hold the grazes in 8
 * sub-steps leaves it as it is, taking every other step so brings it under 1e-4 m. */
static void graze_error_source(void **state)
{
    (void)state;
    struct kase c = {.kind = "graze", .duration = 5.0};
    c.m = model_new(1);
    assert_non_null(c.m);
    c.m->k[0] = 50.0, c.m->c[0] = 0.0, c.m->boundary = BOUNDARY_FREE;
    c.x0[0] = -4.0, c.v0[0] = -18.762942213309717;
    struct track tr;
    track_run(&c, 0.0, 0.00125, &tr);
    assert_null(tr.error);
    double plain = graze_split(&c, &tr, 0), at = graze_split(&c, &tr, 1);
    double between = graze_split(&c, &tr, 2);
    printf("  graze at dt 0.01: %.3e m; its 6 contact steps in 8 sub-steps %.3e m; every "
           "other step in 8 sub-steps %.3e m\n", plain, at, between);
    assert_true(plain > 1e-4);
    assert_true(fabs(at - plain) <= 0.05 * plain);
    assert_true(between <= 1e-4);
    track_free(&tr);
    model_free(c.m);
}

#ifndef CAMPAIGN_DEBUG
int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(numbered_cases),
        cmocka_unit_test(graze_error_source),
        cmocka_unit_test(campaign),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
#endif
#ifdef CAMPAIGN_DEBUG
void campaign_debug(int j, double dt);
void campaign_debug(int j, double dt)
{
    struct kase c;
    make_case(j, &c);
    struct track tr;
    track_run(&c, 0.0, GRID, &tr);
    struct ref *r = malloc(sizeof *r);
    ref_init(r, c.m, c.x0, c.v0);
    ref_advance(r, DURATION);
    if (getenv("EVENTS"))
        for (int e = 0; e < r->nev && e < REF_MAXEVENTS; e++)
            if (r->ev[e].t > atof(getenv("EVENTS")) && r->ev[e].t < atof(getenv("EVENTS")) + 0.5)
                printf("ref event t %.6f kind %d i %d speed %.4g\n", r->ev[e].t, r->ev[e].kind, r->ev[e].i, r->ev[e].speed);
    printf("near miss %g, count %d\n", r->near_miss, r->count);
    struct sim *s = sim_new(c.m, dt);
    sim_reset(s, c.x0, c.v0);
    int n = c.m->n, stride = (int)lround(dt / GRID), ev = 0;
    double thr = 1e-9;
    for (int st = 1; st <= (int)lround(DURATION / dt); st++) {
        sim_step(s);
        double err = 0;
        int wi = 0;
        for (int i = 0; i < n; i++) {
            double d = fabs(sim_x(s)[i] - tr.x[(size_t)st * stride * n + i]);
            if (d > err) err = d, wi = i;
        }
        double t = st * dt;
        if (getenv("WIN") && fabs(t - atof(getenv("WIN"))) < 0.05)
        {
            printf("  t %.4f dv:", t);
            for (int i = 0; i < n; i++)
                printf(" %.1e", sim_v(s)[i] - tr.v[(size_t)st * stride * n + i]);
            printf("  gaps:");
            for (int i = 1; i < n; i++)
                printf(" %.4f", 10.0 / (n + 1) + sim_x(s)[i] - sim_x(s)[i - 1] - model_block_width(c.m));
            printf("\n");
        }
        if (err > thr) {
            printf("t %.4f err %.2e (mass %d), contacts this step %d\n", t, err, wi, sim_last_contacts(s));
            for (; ev < r->nev && r->ev[ev].t <= t; ev++)
                if (r->ev[ev].t > t - 3 * dt)
                    printf("   ref event t %.6f kind %d i %d speed %.4g\n", r->ev[ev].t, r->ev[ev].kind, r->ev[ev].i, r->ev[ev].speed);
            thr *= 4;
        }
        for (; ev < r->nev && r->ev[ev].t <= t - 3 * dt; ev++);
    }
}
#endif
