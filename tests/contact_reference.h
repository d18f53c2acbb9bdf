/* contact_reference.h: an event-driven reference solution of the chain with contacts,
 * written from the model's definition alone (no code shared with src/core), for test_contact.c
 * and test_campaign.c.
 *
 * Between contacts the chain is the linear ODE
 *   x' = v,  m_i v_i' = -k_i (x_i - x_{i-1}) + k_{i+1} (x_{i+1} - x_i) - c_i v_i,
 * x_{-1} = 0, x_N = u(t) = A sin(2 pi (f t + phase)) (0 for a wall; no k_N term when free),
 * solved by its Taylor series of order REF_ORDER over sub-steps of at most REF_HMAX: the
 * truncation, (w h)^25 / 25!, is far below rounding. The drive's derivatives are exact.
 *
 * Every gap (left wall, each neighbour pair, the right wall or piston face) is a
 * polynomial on the sub-step. A contact is the first instant a gap goes from positive to
 * negative: the sub-step is sampled, split at the gap's extrema, and the root bracketed
 * and bisected down to adjacent doubles. The state is taken there from the series, the
 * restitution rule (e = 0.8, velocity relative to the wall or piston reversed and scaled;
 * neighbours by 1-D restitution, momentum kept) applied, and the run goes on.
 *
 * Resting contacts: a contact closing slower than REF_V_REST is perfectly inelastic; if
 * the forces then press it shut it holds as a constraint. Masses joined by held contacts
 * are one rigid cluster (the wall's cannot move, the piston's moves with the piston), so
 * the series is that of the constrained chain: a free cluster accelerates by its net
 * force over its mass, the piston's by u''. The force across each held contact is a
 * series too (Newton on the part left of it); the contact parts where it turns to a pull,
 * found like a closing gap. An impact is the restitution rule between the two masses it joins
 * (or a mass and the wall or piston), then on every touching gap of the row around it that
 * still closes, pair by pair, in sweeps alternating left to right and back until none
 * does: held contacts take part like merely touching ones (the impulse is infinite beside
 * their force), part if they then move apart, and inelastic ones pressed shut are held
 * (if after 16 sweeps the last made only contacts slower than REF_V_REST, what still
 * closes is carried on as perfectly inelastic sweeps until nothing closes: one contact;
 * one whose last sweep made a faster contact is not this reference's business).
 * The square, triangle and sawtooth drives are pieces of constants and ramps (the definition's
 * formulas), sub-steps ending at their breakpoints; a jump of the end books the change of
 * the end spring's energy as the motor's work, and a jump into the last mass pushes every
 * mass in the way ahead of the face, each against the next, the springs' change paid by
 * the motor, and is an impact on the face (a row pushed into the wall is not this
 * reference's business: the program refuses such an amplitude).
 *
 * The energy books are kept exactly too: dissipated = integral of sum c v^2, motor work =
 * integral of k_N (u - x_N) u' plus the impulse times the piston's velocity at a piston
 * contact; contact = the energy restitution removes, 1/2 mu (1 - e^2) v_rel^2 (mu the
 * reduced mass; the mass itself against a wall or piston). */
#ifndef SPRINGSIM_CONTACT_REFERENCE_H
#define SPRINGSIM_CONTACT_REFERENCE_H

#include <math.h>
#include <stdbool.h>
#include <string.h>

#include "core/model.h"

#define REF_MAXN 30       /* masses the reference takes */
#define REF_ORDER 24      /* Taylor order */
#define REF_HMAX 1e-3     /* longest sub-step (s) by default */
#define REF_SAMPLES 8     /* samples of each gap per sub-step, to find its extrema */
#define REF_MAXEVENTS 256 /* contacts logged (all are counted) */
#define REF_V_REST 1e-3   /* below this approach speed a contact is inelastic (the model: rests) */
#define REF_RATE 1e-9     /* relative speeds below this are none */
#define REF_PULL 1e-9     /* a held contact parts when its force falls below -this (N) */
#define REF_E 0.8         /* restitution */
#define REF_L 10.0        /* right end's base (m) */

enum ref_kind { REF_LEFT, REF_PAIR, REF_RIGHT };

struct ref_event {
    double t;           /* instant of the contact (s) */
    enum ref_kind kind; /* what touched */
    int i;              /* the mass (pair: the left one of the two), 0-based */
    double speed;       /* approach speed, > 0 (m/s) */
};

enum ref_wave { REF_SINE, REF_SQUARE, REF_TRIANGLE, REF_SAWTOOTH };

struct ref {
    int n; /* masses */
    enum ref_wave wave;                     /* the drive's form */
    double freq;                            /* its frequency (Hz); phase in cycles below */
    double cycles0;                         /* the drive's phase (cycles) */
    bool held[REF_MAXN + 1];                /* resting contacts (indexed as gaps) */
    int count;                              /* every contact so far */
    double m[REF_MAXN], k[REF_MAXN + 1], c[REF_MAXN];
    bool motor, free_end;                   /* right end: moving piston / none */
    double amp, omega, phase;               /* u = amp sin(omega t + phase) */
    double w, xeq[REF_MAXN];                /* block width, equilibrium centres */
    double hmax;                            /* longest sub-step (s), REF_HMAX unless set */
    double t, x[REF_MAXN], v[REF_MAXN];     /* the state */
    double dissipated, motor_work, contact; /* energy books (J) */
    struct ref_event ev[REF_MAXEVENTS];     /* the contacts so far */
    int nev;
    double near_miss;  /* smallest local minimum of a gap that stayed open */
    double near_rest;  /* smallest |approach speed - REF_V_REST| of a contact (m/s) */
    const char *error; /* an ambiguous contact (resting, simultaneous) */
};

/* The reference for model md (sine drive only) at t = 0 from x0, v0. */
static void ref_init(struct ref *r, const struct model *md, const double *x0, const double *v0)
{
    int n = md->n;
    *r = (struct ref){.n = n, .near_miss = INFINITY, .near_rest = INFINITY, .hmax = REF_HMAX};
    for (int i = 0; i < n; i++) {
        r->m[i] = md->m[i];
        r->c[i] = md->c[i];
        r->x[i] = x0 ? x0[i] : 0.0;
        r->v[i] = v0 ? v0[i] : 0.0;
        r->xeq[i] = (i + 1) * REF_L / (n + 1);
    }
    for (int j = 0; j <= n; j++)
        r->k[j] = md->k[j];
    r->motor = md->boundary == BOUNDARY_MOTOR;
    r->free_end = md->boundary == BOUNDARY_FREE;
    if (r->motor) {
        r->amp = md->motor.amplitude;
        r->omega = 2.0 * M_PI * md->motor.frequency;
        r->phase = 2.0 * M_PI * md->motor.phase;
        r->freq = md->motor.frequency;
        r->cycles0 = md->motor.phase;
        r->wave = md->motor.wave == WAVE_SQUARE     ? REF_SQUARE
                  : md->motor.wave == WAVE_TRIANGLE ? REF_TRIANGLE
                  : md->motor.wave == WAVE_SAWTOOTH ? REF_SAWTOOTH
                                                    : REF_SINE;
    }
    r->w = fmin(0.4, 0.5 * REF_L / (n + 1));
}

/* The piece of a piecewise drive holding time t: its index j, the pieces being
 * [(j + off) / per, (j + 1 + off) / per) in cycles of the drive. */
static double ref_piece_len(const struct ref *r)
{
    return r->wave == REF_SAWTOOTH ? 1.0 : 0.5; /* cycles */
}

static double ref_piece_off(const struct ref *r)
{
    return r->wave == REF_TRIANGLE ? 0.25 : r->wave == REF_SAWTOOTH ? 0.5 : 0.0;
}

/* u and u' at time t on the piece that starts at or before t (after = 1) or the one that
 * ends at or after it (after = 0), by the definition's formulas. */
static void ref_drive_side(const struct ref *r, double t, int after, double *u, double *du)
{
    if (!r->motor) {
        *u = *du = 0.0;
        return;
    }
    double cyc = r->freq * t + r->cycles0, A = r->amp, w = r->omega;
    if (r->wave == REF_SINE) {
        *u = A * sin(2.0 * M_PI * cyc);
        *du = A * w * cos(2.0 * M_PI * cyc);
        return;
    }
    double len = ref_piece_len(r), off = ref_piece_off(r);
    /* Within 1e-9 of a piece of a breakpoint, t is on it (the rounding of t): the piece
     * after it, or the one before. */
    double pos = (cyc - off) / len;
    double j = after ? floor(pos + 1e-9) : ceil(pos - 1e-9) - 1.0;
    double mid = (j + 0.5) * len + off; /* a cycle value inside the piece */
    double frac = mid - floor(mid);
    switch (r->wave) {
    case REF_SQUARE:
        *u = frac < 0.5 ? A : -A, *du = 0.0;
        return;
    case REF_TRIANGLE: {
        /* Rising through 0 at cycle 0 with slope 4 A f; falling on the other half. */
        double slope = (frac < 0.25 || frac > 0.75) ? 4.0 * A * r->freq : -4.0 * A * r->freq;
        double c0 = frac < 0.25 || frac > 0.75 ? floor(mid + 0.5) : floor(mid) + 0.5;
        *u = slope * (cyc - c0) / r->freq, *du = slope;
        return;
    }
    case REF_SAWTOOTH: {
        double c0 = floor(mid + 0.5); /* the rising zero inside this piece */
        *u = 2.0 * A * (cyc - c0), *du = 2.0 * A * r->freq;
        return;
    }
    case REF_SINE:
        break;
    }
}

/* u and u' at time t. */
static void ref_drive(const struct ref *r, double t, double *u, double *du)
{
    ref_drive_side(r, t, 1, u, du);
}

/* The next breakpoint of the drive after t (INFINITY for a sine or no motor). */
static double ref_next_break(const struct ref *r, double t)
{
    if (!r->motor || r->wave == REF_SINE || r->amp == 0.0)
        return INFINITY;
    double len = ref_piece_len(r), off = ref_piece_off(r);
    double cyc = r->freq * t + r->cycles0, j = floor((cyc - off) / len + 1e-9) + 1.0;
    double tb = ((j * len + off) - r->cycles0) / r->freq;
    return tb > t ? tb : ((j + 1.0) * len + off - r->cycles0) / r->freq;
}

/* Kinetic plus spring potential energy now. */
static double ref_mechanical(const struct ref *r)
{
    double u, du, e = 0.0;
    ref_drive(r, r->t, &u, &du);
    for (int i = 0; i < r->n; i++) {
        double s = r->x[i] - (i > 0 ? r->x[i - 1] : 0.0);
        e += 0.5 * r->m[i] * r->v[i] * r->v[i] + 0.5 * r->k[i] * s * s;
    }
    if (!r->free_end) {
        double s = u - r->x[r->n - 1];
        e += 0.5 * r->k[r->n] * s * s;
    }
    return e;
}

/* kinetic + potential + dissipated + contact - motor work: constant. */
static double ref_balance(const struct ref *r)
{
    return ref_mechanical(r) + r->dissipated + r->contact - r->motor_work;
}

/* The series at the current time: x(t + s) = sum X[p] s^p, likewise V and, for the drive,
 * U (to order REF_ORDER + 1, so u' has REF_ORDER terms too); F the force across each held
 * contact (its last term left 0). */
struct ref_series {
    double X[REF_ORDER + 1][REF_MAXN], V[REF_ORDER + 1][REF_MAXN], U[REF_ORDER + 2];
    double F[REF_ORDER + 1][REF_MAXN + 1];
};

/* The cluster of held contacts around mass i: [*f, *l], and -1 when the wall holds it, 1
 * the piston, 0 nothing. */
static int ref_cluster(const struct ref *r, int i, int *f, int *l)
{
    int a = i, b = i;
    while (a > 0 && r->held[a])
        a--;
    while (b + 1 < r->n && r->held[b + 1])
        b++;
    *f = a, *l = b;
    if (a == 0 && r->held[0])
        return -1;
    if (b == r->n - 1 && !r->free_end && r->held[r->n])
        return 1;
    return 0;
}

static void ref_expand(const struct ref *r, struct ref_series *s)
{
    int n = r->n;
    memset(s, 0, sizeof *s);
    if (r->motor && r->wave == REF_SINE) {
        double sn = sin(r->omega * r->t + r->phase), cs = cos(r->omega * r->t + r->phase);
        double fact = 1.0, wp = 1.0;
        for (int p = 0; p <= REF_ORDER + 1; p++) {
            /* u^(p) = A w^p sin(theta + p pi/2): sin, cos, -sin, -cos, ... */
            double d = (p % 4 == 0) ? sn : (p % 4 == 1) ? cs : (p % 4 == 2) ? -sn : -cs;
            s->U[p] = r->amp * wp * d / fact;
            wp *= r->omega;
            fact *= p + 1;
        }
    } else if (r->motor) {
        ref_drive(r, r->t, &s->U[0], &s->U[1]); /* a constant or a ramp */
    }
    for (int i = 0; i < n; i++) {
        s->X[0][i] = r->x[i];
        s->V[0][i] = r->v[i];
    }
    for (int p = 0; p < REF_ORDER; p++) {
        double f[REF_MAXN];
        for (int i = 0; i < n; i++) {
            double xl = i > 0 ? s->X[p][i - 1] : 0.0;
            f[i] = -r->k[i] * (s->X[p][i] - xl) - r->c[i] * s->V[p][i];
            if (i < n - 1)
                f[i] += r->k[i + 1] * (s->X[p][i + 1] - s->X[p][i]);
            else if (!r->free_end)
                f[i] += r->k[n] * (s->U[p] - s->X[p][i]);
        }
        for (int a = 0, b; a < n; a = b + 1) {
            int hold = ref_cluster(r, a, &a, &b);
            double force = 0.0, mass = 0.0;
            for (int i = a; i <= b; i++)
                force += f[i], mass += r->m[i];
            /* The cluster's acceleration term; u'' = sum (p+2)(p+1) U[p+2] s^p. */
            double acc = hold < 0   ? 0.0
                         : hold > 0 ? (p + 2) * (p + 1) * s->U[p + 2]
                                    : force / mass;
            double left = hold < 0 ? -force : 0.0; /* the wall's push */
            if (hold < 0)
                s->F[p][0] = left;
            for (int i = a; i <= b; i++) {
                s->X[p + 1][i] = s->V[p][i] / (p + 1);
                s->V[p + 1][i] = acc / (p + 1);
                left += f[i] - r->m[i] * acc;
                if (i < b || (hold > 0 && i == n - 1))
                    s->F[p][i + 1] = left;
            }
        }
    }
}

/* Gap g's polynomial: g = 0 left wall, 1..n-1 the pair (g-1, g), n the right end. */
static void ref_gap_poly(const struct ref *r, const struct ref_series *s, int g, double *G)
{
    int n = r->n;
    for (int p = 0; p <= REF_ORDER; p++) {
        if (g == 0)
            G[p] = s->X[p][0];
        else if (g < n)
            G[p] = s->X[p][g] - s->X[p][g - 1];
        else
            G[p] = s->U[p] - s->X[p][n - 1];
    }
    if (g == 0)
        G[0] += r->xeq[0] - 0.5 * r->w;
    else if (g < n)
        G[0] += r->xeq[g] - r->xeq[g - 1] - r->w;
    else
        G[0] += REF_L - 0.5 * r->w - r->xeq[n - 1];
}

static double ref_poly(const double *a, double s)
{
    double y = a[REF_ORDER];
    for (int p = REF_ORDER - 1; p >= 0; p--)
        y = y * s + a[p];
    return y;
}

static double ref_dpoly(const double *a, double s)
{
    double y = REF_ORDER * a[REF_ORDER];
    for (int p = REF_ORDER - 1; p >= 1; p--)
        y = y * s + p * a[p];
    return y;
}

/* Bisects [a, b] down to adjacent doubles for the sign change of poly (deriv: of its
 * derivative); returns the end on the side where the function is positive (for a gap:
 * still open) if up, else the other. */
static double ref_bisect(const double *G, int deriv, double a, double b)
{
    double fa = deriv ? ref_dpoly(G, a) : ref_poly(G, a);
    for (int it = 0; it < 200; it++) {
        double mid = 0.5 * (a + b);
        if (mid <= a || mid >= b)
            break;
        double fm = deriv ? ref_dpoly(G, mid) : ref_poly(G, mid);
        if ((fm > 0) == (fa > 0))
            a = mid;
        else
            b = mid;
    }
    return a;
}

/* The first instant in (0, h] where gap G closes; returns false if it stays open. Marks
 * an ambiguous case (a gap already closed and closing further) in r->error, and records
 * open local minima in r->near_miss. */
static bool ref_first_close(struct ref *r, const double *G, double h, double *tau)
{
    double pts[2 * REF_SAMPLES + 2];
    int np = 0;
    pts[np++] = 0.0;
    for (int j = 1; j <= REF_SAMPLES; j++) {
        double a = h * (j - 1) / REF_SAMPLES, b = h * j / REF_SAMPLES;
        double da = ref_dpoly(G, a), db = ref_dpoly(G, b);
        if ((da < 0) != (db < 0))
            pts[np++] = ref_bisect(G, 1, a, b); /* an extremum splits the interval */
        pts[np++] = b;
    }
    for (int j = 1; j < np; j++) {
        double a = pts[j - 1], b = pts[j];
        double ga = ref_poly(G, a), gb = ref_poly(G, b);
        if (gb >= 0.0) {
            if (j < np - 1 && ref_dpoly(G, a) < 0 && ref_dpoly(G, pts[j + 1]) > 0)
                r->near_miss = fmin(r->near_miss, gb);
            continue;
        }
        if (!(ga > 0.0)) {
            /* Closed at a and closing: resting contact or penetration, not this
             * reference's business. Just after a contact the gap is ~0 but opening. */
            r->error = "a gap closed and still closing (resting contact?)";
            return false;
        }
        *tau = ref_bisect(G, 0, a, b);
        return true;
    }
    return false;
}

/* The integral over [0, s] of the product of two series (order REF_ORDER each). */
static double ref_integral_of_product(const double *a, const double *b, double s)
{
    double q[2 * REF_ORDER + 1] = {0};
    for (int p = 0; p <= REF_ORDER; p++)
        for (int o = 0; o <= REF_ORDER; o++)
            q[p + o] += a[p] * b[o];
    double y = 0.0;
    for (int p = 2 * REF_ORDER; p >= 0; p--)
        y = y * s + q[p] / (p + 1);
    return y * s;
}

/* Moves the state along the series to t + s, with the energy integrals. */
static void ref_move(struct ref *r, const struct ref_series *se, double s)
{
    int n = r->n;
    for (int i = 0; i < n; i++) {
        double xs[REF_ORDER + 1], vs[REF_ORDER + 1];
        for (int p = 0; p <= REF_ORDER; p++) {
            xs[p] = se->X[p][i];
            vs[p] = se->V[p][i];
        }
        r->dissipated += r->c[i] * ref_integral_of_product(vs, vs, s);
        r->x[i] = ref_poly(xs, s);
        r->v[i] = ref_poly(vs, s);
    }
    if (r->motor) {
        /* Through the end spring k_N (u - x_N) u', and, while the piston carries a
         * cluster, its push on it: power -F_N u' (F_N pushes the cluster left). */
        double f[REF_ORDER + 1], du[REF_ORDER + 1];
        for (int p = 0; p <= REF_ORDER; p++) {
            f[p] = r->k[n] * (se->U[p] - se->X[p][n - 1]);
            if (r->held[n])
                f[p] -= se->F[p][n];
            du[p] = (p + 1) * se->U[p + 1];
        }
        r->motor_work += ref_integral_of_product(f, du, s);
    }
}

/* Held contacts' forces now (F[0] of the series): the weakest one, or -1. */
static int ref_weakest(const struct ref *r, double *force)
{
    struct ref_series se;
    ref_expand(r, &se);
    int gaps = r->free_end ? r->n : r->n + 1, w = -1;
    for (int g = 0; g < gaps; g++)
        if (r->held[g] && (w < 0 || se.F[0][g] < se.F[0][w]))
            w = g;
    *force = w < 0 ? INFINITY : se.F[0][w];
    return w;
}

#include "contact_impact.h"

/* The first instant in [0, h] at which a held contact's force F turns to a pull. */
static bool ref_first_pull(struct ref *r, const double *F, double h, double *tau)
{
    if (ref_poly(F, 0.0) <= 0.0 && ref_dpoly(F, 0.0) < 0.0) {
        *tau = 0.0;
        return true;
    }
    const char *err = r->error;
    double miss = r->near_miss;
    bool found = ref_first_close(r, F, h, tau);
    r->error = err, r->near_miss = miss; /* a force's minima are not near misses */
    return found;
}

/* Advances the reference to time t1, contacts included. */
static void ref_advance(struct ref *r, double t1)
{
    int gaps = r->free_end ? r->n : r->n + 1;
    while (r->t < t1 && !r->error) {
        double tb = ref_next_break(r, r->t);
        double end = fmin(t1, tb), h = fmin(r->hmax, end - r->t);
        struct ref_series se;
        ref_expand(r, &se);
        double tau = h;
        int hit = -1, part = -1;
        for (int g = 0; g < gaps; g++) {
            double G[REF_ORDER + 1], tg;
            if (r->held[g]) {
                for (int p = 0; p <= REF_ORDER; p++)
                    G[p] = se.F[p][g];
                if (ref_first_pull(r, G, h, &tg) && tg < tau)
                    tau = tg, part = g, hit = -1;
                continue;
            }
            ref_gap_poly(r, &se, g, G);
            if (ref_first_close(r, G, h, &tg) && tg < tau)
                tau = tg, hit = g, part = -1;
        }
        ref_move(r, &se, tau);
        if (hit < 0 && part < 0) {
            r->t = h == end - r->t ? end : r->t + h;
        } else {
            r->t += tau;
        }
        if (hit >= 0)
            ref_contact(r, hit);
        if (part >= 0) {
            double force;
            r->held[part] = false;
            for (int w; (w = ref_weakest(r, &force)) >= 0 && force < -REF_PULL;)
                r->held[w] = false;
        }
        if (r->t == tb && hit < 0 && part < 0 && r->motor) {
            /* A breakpoint: a jump of the end changes the end spring's energy, which the
             * motor pays; the piston leaves what it carried if it jumps away from it. */
            double u0, du0, u1, du1, x = r->x[r->n - 1];
            ref_drive_side(r, tb, 0, &u0, &du0);
            ref_drive_side(r, tb, 1, &u1, &du1);
            r->motor_work += 0.5 * r->k[r->n] * ((u1 - x) * (u1 - x) - (u0 - x) * (u0 - x));
            double gap = REF_L + u1 - 0.5 * r->w - r->xeq[r->n - 1] - x;
            if (r->held[r->n] && gap > 1e-12)
                r->held[r->n] = false;
            if (gap < -1e-12) {
                /* Into the last mass: every mass in the way is pushed ahead of the face,
                 * each against the next, the springs' change paid by the motor; then the
                 * face's impact (a contact even if nothing closes), unless the piston
                 * carried them. */
                double lim = REF_L + u1 - 0.5 * r->w, e0 = ref_mechanical(r);
                for (int i = r->n - 1; i >= 0 && r->xeq[i] + r->x[i] > lim; i--) {
                    r->x[i] = lim - r->xeq[i];
                    lim -= r->w;
                }
                if (r->xeq[0] + r->x[0] < 0.5 * r->w - 1e-12) {
                    r->error = "the piston jumped the row into the wall";
                    return;
                }
                r->motor_work += ref_mechanical(r) - e0;
                if (!r->held[r->n] && ref_impact(r, r->n) == 0) {
                    struct ref_event ev = {r->t, REF_RIGHT, r->n - 1, 0.0};
                    r->ev[r->nev % REF_MAXEVENTS] = ev;
                    r->nev++;
                    r->count++;
                }
            }
            if (r->held[r->n] && du1 != r->v[r->n - 1]) {
                /* A corner under what the piston carries: turning away it leaves it,
                 * turning into it that is a contact. */
                bool into = du1 < r->v[r->n - 1];
                r->held[r->n] = false;
                if (into)
                    ref_contact(r, r->n);
            }
        }
    }
}

#endif
