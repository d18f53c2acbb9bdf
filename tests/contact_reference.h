/* contact_reference.h: an event-driven reference solution of the chain with contacts,
 * written from SPEC section 1 alone (no code shared with src/core), for test_contact.c.
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
 * SPEC's rule (e = 0.8, velocity relative to the wall or piston reversed and scaled;
 * neighbours by 1-D restitution, momentum kept) applied, and the run goes on.
 *
 * The energy books are kept exactly too: dissipated = integral of sum c v^2, motor work =
 * integral of k_N (u - x_N) u' plus the impulse times the piston's velocity at a piston
 * contact; contact = the energy restitution removes, 1/2 mu (1 - e^2) v_rel^2 (mu the
 * reduced mass; the mass itself against a wall or piston). */
#ifndef SPRINGSIM_CONTACT_REFERENCE_H
#define SPRINGSIM_CONTACT_REFERENCE_H

#include <math.h>
#include <stdbool.h>

#include "core/model.h"

#define REF_MAXN 4        /* masses the reference takes */
#define REF_ORDER 24      /* Taylor order */
#define REF_HMAX 1e-3     /* longest sub-step (s) by default */
#define REF_SAMPLES 8     /* samples of each gap per sub-step, to find its extrema */
#define REF_MAXEVENTS 128 /* contacts logged */
#define REF_E 0.8         /* restitution, SPEC section 1 */
#define REF_L 10.0        /* right end's base (m) */

enum ref_kind { REF_LEFT, REF_PAIR, REF_RIGHT };

struct ref_event {
    double t;           /* instant of the contact (s) */
    enum ref_kind kind; /* what touched */
    int i;              /* the mass (pair: the left one of the two), 0-based */
    double speed;       /* approach speed, > 0 (m/s) */
};

struct ref {
    int n; /* masses */
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
    const char *error; /* an ambiguous contact (resting, simultaneous) */
};

/* The reference for model md (sine drive only) at t = 0 from x0, v0. */
static void ref_init(struct ref *r, const struct model *md, const double *x0, const double *v0)
{
    int n = md->n;
    *r = (struct ref){.n = n, .near_miss = INFINITY, .hmax = REF_HMAX};
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
    }
    r->w = fmin(0.4, 0.5 * REF_L / (n + 1));
}

/* u and u' at time t. */
static void ref_drive(const struct ref *r, double t, double *u, double *du)
{
    *u = r->amp * sin(r->omega * t + r->phase);
    *du = r->amp * r->omega * cos(r->omega * t + r->phase);
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
 * U (to order REF_ORDER + 1, so u' has REF_ORDER terms too). */
struct ref_series {
    double X[REF_ORDER + 1][REF_MAXN], V[REF_ORDER + 1][REF_MAXN], U[REF_ORDER + 2];
};

static void ref_expand(const struct ref *r, struct ref_series *s)
{
    int n = r->n;
    double sn = 0.0, cs = 0.0, fact = 1.0, wp = 1.0;
    if (r->motor) {
        sn = sin(r->omega * r->t + r->phase);
        cs = cos(r->omega * r->t + r->phase);
    }
    for (int p = 0; p <= REF_ORDER + 1; p++) {
        /* u^(p) = A w^p sin(theta + p pi/2): sin, cos, -sin, -cos, ... */
        double d = (p % 4 == 0) ? sn : (p % 4 == 1) ? cs : (p % 4 == 2) ? -sn : -cs;
        s->U[p] = r->motor ? r->amp * wp * d / fact : 0.0;
        wp *= r->omega;
        fact *= p + 1;
    }
    for (int i = 0; i < n; i++) {
        s->X[0][i] = r->x[i];
        s->V[0][i] = r->v[i];
    }
    for (int p = 0; p < REF_ORDER; p++) {
        for (int i = 0; i < n; i++) {
            double xl = i > 0 ? s->X[p][i - 1] : 0.0;
            double f = -r->k[i] * (s->X[p][i] - xl) - r->c[i] * s->V[p][i];
            if (i < n - 1)
                f += r->k[i + 1] * (s->X[p][i + 1] - s->X[p][i]);
            else if (!r->free_end)
                f += r->k[n] * (s->U[p] - s->X[p][i]);
            s->X[p + 1][i] = s->V[p][i] / (p + 1);
            s->V[p + 1][i] = f / r->m[i] / (p + 1);
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
        double f[REF_ORDER + 1], du[REF_ORDER + 1];
        for (int p = 0; p <= REF_ORDER; p++) {
            f[p] = se->U[p] - se->X[p][n - 1];
            du[p] = (p + 1) * se->U[p + 1];
        }
        r->motor_work += r->k[n] * ref_integral_of_product(f, du, s);
    }
}

/* The SPEC's rule for the contact of gap g, with the books. */
static void ref_contact(struct ref *r, int g)
{
    int n = r->n;
    struct ref_event ev = {r->t, REF_PAIR, g - 1, 0.0};
    if (g == 0 || g == n) {
        /* A wall or the piston: the velocity relative to it reversed and scaled by e. */
        int i = g == 0 ? 0 : n - 1;
        double u, du;
        ref_drive(r, r->t, &u, &du);
        double wall_v = g == 0 ? 0.0 : du;
        double rel = r->v[i] - wall_v;
        double v1 = wall_v - REF_E * rel;
        r->contact += 0.5 * r->m[i] * (1.0 - REF_E * REF_E) * rel * rel;
        r->motor_work += r->m[i] * (v1 - r->v[i]) * wall_v; /* impulse times wall speed */
        r->v[i] = v1;
        ev.kind = g == 0 ? REF_LEFT : REF_RIGHT;
        ev.i = i;
        ev.speed = fabs(rel);
    } else {
        /* 1-D restitution: momentum kept, v2' - v1' = e (v1 - v2). */
        int i = g - 1;
        double m1 = r->m[i], m2 = r->m[i + 1], v1 = r->v[i], v2 = r->v[i + 1];
        double p = m1 * v1 + m2 * v2, mt = m1 + m2;
        r->v[i] = (p + m2 * REF_E * (v2 - v1)) / mt;
        r->v[i + 1] = (p + m1 * REF_E * (v1 - v2)) / mt;
        r->contact += 0.5 * m1 * m2 / mt * (1.0 - REF_E * REF_E) * (v1 - v2) * (v1 - v2);
        ev.speed = v1 - v2;
    }
    if (r->nev > 0 && r->t - r->ev[r->nev - 1].t < 1e-9)
        r->error = "two contacts at one instant";
    if (r->nev < REF_MAXEVENTS)
        r->ev[r->nev++] = ev;
}

/* Advances the reference to time t1, contacts included. */
static void ref_advance(struct ref *r, double t1)
{
    int gaps = r->free_end ? r->n : r->n + 1;
    while (r->t < t1 && !r->error) {
        double h = fmin(r->hmax, t1 - r->t);
        struct ref_series se;
        ref_expand(r, &se);
        double tau = h;
        int hit = -1;
        for (int g = 0; g < gaps; g++) {
            double G[REF_ORDER + 1], tg;
            ref_gap_poly(r, &se, g, G);
            if (ref_first_close(r, G, h, &tg) && tg < tau) {
                tau = tg;
                hit = g;
            }
        }
        ref_move(r, &se, tau);
        if (hit < 0) {
            r->t = h == t1 - r->t ? t1 : r->t + h;
        } else {
            r->t += tau;
            ref_contact(r, hit);
        }
    }
}

#endif
