/* events.c: contacts located inside the step, grazes and resting contacts included.
 *
 * Along a piece the positions are the cubic Hermite interpolant of the two ends (the
 * velocities are their derivatives at the ends), so every gap between masses or to the
 * wall is a cubic in theta in [0, 1],
 *   g(theta) = g0 + s0 theta + c2 theta^2 + c3 theta^3,
 *   c2 = 3 (g1 - g0) - 2 s0 - s1,   c3 = s0 + s1 - 2 (g1 - g0),
 * s = h g' at the ends; the piston's adds the drive, which strays from its own cubic by
 * at most drive_err. The gap is split at the cubic's turning points (roots of g'), so a
 * gap that dips below zero and comes back inside the piece is found, not only one that
 * ends it closed. Most gaps are far from closing: g = L(theta) + theta (1 - theta)
 * ((1 - theta) A - theta B), A = s0 - (g1 - g0), B = s1 - (g1 - g0), so
 * g >= min(g0, g1) - max(|A|, |B|) / 4, and a gap above that bound costs a few flops.
 *
 * A step error of O(h^5) in the state gives a contact instant to O(h^4) on the
 * interpolant, so the method's order survives contacts. */
#include "events.h"

#include <math.h>
#include <stddef.h>

#include "vec2.h"

/* Rates below this (m/s) after a contact count as no motion: the two moved as one. */
#define REST_RATE 1e-9
/* A gap this small (m) may start to rest: the located instant's gap is the interpolant's
 * error, which resting then removes. */
#define REST_GAP 1e-6
/* Sweeps of the contact rule at one instant; then what still closes takes the limit of
 * further sweeps if the last made only contacts slower than the rest speed, or else moves
 * as one with what touches it (an inelastic collapse). */
#define EVENTS_SWEEPS 16

/* x_i at theta of the piece, and its velocity. */
static double hermite(const struct events_piece *p, int i, double th)
{
    int n = p->m->n;
    double h = p->h, t2 = th * th, t3 = t2 * th;
    return (2 * t3 - 3 * t2 + 1) * p->ya[i] + (t3 - 2 * t2 + th) * h * p->ya[n + i] +
           (-2 * t3 + 3 * t2) * p->y[i] + (t3 - t2) * h * p->y[n + i];
}

static double hermite_v(const struct events_piece *p, int i, double th)
{
    int n = p->m->n;
    double h = p->h, t2 = th * th;
    return (6 * t2 - 6 * th) / h * p->ya[i] + (3 * t2 - 4 * th + 1) * p->ya[n + i] +
           (-6 * t2 + 6 * th) / h * p->y[i] + (3 * t2 - 2 * th) * p->y[n + i];
}

/* Constraint k's gap at theta, the drive taken exactly. */
static double gap_at(const struct events_piece *p, int k, double th)
{
    const struct collision_limits *l = p->lim;
    int n = l->n;
    if (k == 0)
        return l->spacing + hermite(p, 0, th) - 0.5 * l->w;
    if (k < n)
        return l->spacing + hermite(p, k, th) - hermite(p, k - 1, th) - l->w;
    double u, du;
    drive_eval(p->d, p->a + th * p->h, &u, &du);
    return MODEL_LENGTH + u - 0.5 * l->w - (n * l->spacing + hermite(p, n - 1, th));
}

static double cubic(const double c[4], double th)
{
    return ((c[3] * th + c[2]) * th + c[1]) * th + c[0];
}

/* The root of the gap in [lo, hi], where it goes from open to closed: regula falsi
 * (Illinois) on the gap itself, or on its cubic where the drive's straying leaves the
 * gap without a change of sign there. */
static double root(const struct events_piece *p, int k, const double c[4], double lo, double hi)
{
    bool exact = true;
    double glo = gap_at(p, k, lo), ghi = gap_at(p, k, hi);
    if (!(glo > 0.0 && ghi < 0.0)) {
        exact = false;
        glo = cubic(c, lo), ghi = cubic(c, hi);
        if (!(glo > 0.0))
            return lo;
    }
    int side = 0;
    for (int it = 0; it < 100 && hi - lo > 1e-15; it++) {
        double th = (lo * ghi - hi * glo) / (ghi - glo);
        if (!(th > lo && th < hi))
            th = 0.5 * (lo + hi);
        double g = exact ? gap_at(p, k, th) : cubic(c, th);
        if (g > 0.0) {
            lo = th, glo = g;
            if (side == -1)
                ghi *= 0.5;
            side = -1;
        } else {
            hi = th, ghi = g;
            if (side == 1)
                glo *= 0.5;
            side = 1;
        }
        if (fabs(g) < 1e-15)
            return th;
    }
    return hi;
}

/* The piston's gap, whose drive strays from its cubic by up to drive_err: on each piece
 * between the cubic's turning points that comes within drive_err of closing, the gap
 * itself is minimised (golden section) and a minimum below -EVENTS_TOUCH closes it. */
static double piston_close(const struct events_piece *p, int k, const double c[4],
                           const double *pts, int np)
{
    const double phi = 0.6180339887498949;
    for (int j = 0; j + 1 < np; j++) {
        double lo = pts[j], hi = pts[j + 1];
        if (fmin(cubic(c, lo), cubic(c, hi)) >= p->drive_err - EVENTS_TOUCH)
            continue;
        double glo = gap_at(p, k, lo);
        if (glo < -EVENTS_TOUCH)
            return lo; /* closed already at the piece's start */
        double a = lo, b = hi, x1 = b - phi * (b - a), x2 = a + phi * (b - a);
        double f1 = gap_at(p, k, x1), f2 = gap_at(p, k, x2);
        for (int it = 0; it < 60 && b - a > 1e-13; it++) {
            if (f1 < f2) {
                b = x2, x2 = x1, f2 = f1;
                x1 = b - phi * (b - a), f1 = gap_at(p, k, x1);
            } else {
                a = x1, x1 = x2, f1 = f2;
                x2 = a + phi * (b - a), f2 = gap_at(p, k, x2);
            }
        }
        double tm = f1 < f2 ? x1 : x2, gm = fmin(f1, f2), ghi = gap_at(p, k, hi);
        if (ghi < gm)
            tm = hi, gm = ghi;
        if (gm >= -EVENTS_TOUCH)
            continue;
        return glo > 0.0 ? root(p, k, c, lo, tm) : lo;
    }
    return -1.0;
}

/* Where constraint k, given its cubic c, first closes: theta, or -1. */
static double first_close(const struct events_piece *p, int k, const double c[4])
{
    /* Touching and closing already; a rate of rounding's size (two masses a release has
     * just put in different clusters differ by 1e-17 m/s) is no motion: the cubic below
     * tells whether the gap closes. */
    if (c[0] <= EVENTS_TOUCH && c[1] < -REST_RATE * p->h)
        return 0.0;
    /* The turning points: roots of c1 + 2 c2 theta + 3 c3 theta^2 inside (0, 1). */
    double pts[4] = {0.0}, qa = 3.0 * c[3], qb = 2.0 * c[2], qc = c[1];
    int np = 1;
    if (qa != 0.0) {
        double disc = qb * qb - 4.0 * qa * qc;
        if (disc > 0.0) {
            double q = -0.5 * (qb + copysign(sqrt(disc), qb));
            double r1 = q / qa, r2 = q != 0.0 ? qc / q : r1;
            if (r1 > r2) {
                double t = r1;
                r1 = r2, r2 = t;
            }
            if (r1 > 0.0 && r1 < 1.0)
                pts[np++] = r1;
            if (r2 > 0.0 && r2 < 1.0 && r2 != r1)
                pts[np++] = r2;
        }
    } else if (qb != 0.0) {
        double r = -qc / qb;
        if (r > 0.0 && r < 1.0)
            pts[np++] = r;
    }
    pts[np++] = 1.0;
    if (k == p->lim->n && p->drive_err > 0.0)
        return piston_close(p, k, c, pts, np);
    for (int j = 0; j + 1 < np; j++) {
        double g1 = cubic(c, pts[j + 1]);
        if (g1 >= -EVENTS_TOUCH)
            continue;
        /* The first piece that ends closed: its root, or its start if it starts closed
         * (a turning point that never opened). */
        return cubic(c, pts[j]) > 0.0 ? root(p, k, c, pts[j], pts[j + 1]) : pts[j];
    }
    return -1.0;
}

/* Constraint k's gap and its rate times h at both ends of the piece, and how far the
 * gap may stray from its cubic. */
static void ends(const struct events_piece *p, int k, double g[2], double s[2], double *err)
{
    const struct collision_limits *l = p->lim;
    const double *ya = p->ya, *y = p->y;
    int n = l->n;
    double h = p->h, sp = l->spacing, w = l->w;
    *err = 0.0;
    if (k == 0) {
        g[0] = sp + ya[0] - 0.5 * w, g[1] = sp + y[0] - 0.5 * w;
        s[0] = h * ya[n], s[1] = h * y[n];
    } else if (k < n) {
        g[0] = sp + ya[k] - ya[k - 1] - w, g[1] = sp + y[k] - y[k - 1] - w;
        s[0] = h * (ya[n + k] - ya[n + k - 1]), s[1] = h * (y[n + k] - y[n + k - 1]);
    } else {
        double base = MODEL_LENGTH - 0.5 * w - n * sp;
        g[0] = base + p->ua - ya[n - 1], g[1] = base + p->ub - y[n - 1];
        s[0] = h * (p->dua - ya[2 * n - 1]), s[1] = h * (p->dub - y[2 * n - 1]);
        *err = p->drive_err;
    }
}

/* The bound of the header, min(g0, g1) - max(|A|, |B|) / 4, for a gap with these ends. */
__attribute__((always_inline)) static inline double bound(double g0, double g1, double s0,
                                                          double s1)
{
    double dg = g1 - g0, A = fabs(s0 - dg), B = fabs(s1 - dg);
    return (g0 < g1 ? g0 : g1) - 0.25 * (A > B ? A : B);
}

/* Whether a gap with these ends may close inside the piece (the bound of the header). */
__attribute__((always_inline)) static inline bool may_close(double g0, double g1, double s0,
                                                            double s1, double err)
{
    return bound(g0, g1, s0, s1) - err <= -EVENTS_TOUCH;
}

/* Constraint k, which may close: where it first does (theta), or -1. */
static double consider(const struct events_piece *p, int k)
{
    double g[2], s[2], err;
    ends(p, k, g, s, &err);
    if (!may_close(g[0], g[1], s[0], s[1], err))
        return -1.0;
    double dg = g[1] - g[0];
    double c[4] = {g[0], s[0], 3.0 * dg - 2.0 * s[0] - s[1], s[0] + s[1] - 2.0 * dg};
    return first_close(p, k, c);
}

/* Whether constraint k's gap may close inside the piece, by the bound alone (inline: the
 * common case costs a few flops a gap). */
__attribute__((always_inline)) static inline bool
bound_may_close(const struct events_piece *p, int k)
{
    const struct collision_limits *l = p->lim;
    const double *ya = p->ya, *y = p->y;
    int n = l->n;
    double h = p->h;
    if (k > 0 && k < n)
        return may_close(l->pair + ya[k] - ya[k - 1], l->pair + y[k] - y[k - 1],
                         h * (ya[n + k] - ya[n + k - 1]), h * (y[n + k] - y[n + k - 1]), 0.0);
    if (k == 0)
        return may_close(l->wall + ya[0], l->wall + y[0], h * ya[n], h * y[n], 0.0);
    return may_close(l->face + p->ua - ya[n - 1], l->face + p->ub - y[n - 1],
                     h * (p->dua - ya[2 * n - 1]), h * (p->dub - y[2 * n - 1]), p->drive_err);
}

/* bound_may_close for the pairs k and k + 1 at once (vec2.h: bound's operations a lane,
 * the same bits): each lane all ones where its gap may close (never for a NaN, as
 * there). (y loaded whole: in halves, as just stored, measured no faster.) */
__attribute__((always_inline)) static inline vec2_mask pairs_may_close(const struct events_piece *p,
                                                                        int k)
{
    const double *ya = p->ya, *y = p->y;
    int n = p->lim->n;
    double h = p->h, pair = p->lim->pair;
    vec2 g0 = pair + vec2_load(ya + k) - vec2_load(ya + k - 1);
    vec2 g1 = pair + vec2_load(y + k) - vec2_load(y + k - 1);
    vec2 s0 = h * (vec2_load(ya + n + k) - vec2_load(ya + n + k - 1));
    vec2 s1 = h * (vec2_load(y + n + k) - vec2_load(y + n + k - 1));
    vec2 dg = g1 - g0, A = vec2_abs(s0 - dg), B = vec2_abs(s1 - dg);
    vec2 lq = vec2_select(g0 < g1, g0, g1) - 0.25 * vec2_select(A > B, A, B);
    return lq <= -EVENTS_TOUCH;
}

bool events_may_close(const struct events_piece *p)
{
    const struct collision_limits *l = p->lim;
    const double *ya = p->ya, *y = p->y;
    int n = l->n;
    double h = p->h, pair = l->pair;
    /* bound_may_close's gaps, with no branch: the least of may_close's left sides (an err
     * of 0 subtracts nothing; a NaN never counts, as there), the wall's first; the pairs
     * two at a time, the odd one alone. */
    double least = INFINITY, q = bound(l->wall + ya[0], l->wall + y[0], h * ya[n], h * y[n]);
    least = q < least ? q : least;
    const vec2_mask none = {0, 0};
    vec2_mask hit = none;
    int k = 1;
    for (; k + 1 < n; k += 2)
        hit |= pairs_may_close(p, k);
    for (; k < n; k++) {
        q = bound(pair + ya[k] - ya[k - 1], pair + y[k] - y[k - 1], h * (ya[n + k] - ya[n + k - 1]),
                  h * (y[n + k] - y[n + k - 1]));
        least = q < least ? q : least;
    }
    if (l->count > n) {
        q = bound(l->face + p->ua - ya[n - 1], l->face + p->ub - y[n - 1],
                  h * (p->dua - ya[2 * n - 1]), h * (p->dub - y[2 * n - 1])) -
            p->drive_err;
        least = q < least ? q : least;
    }
    return least <= -EVENTS_TOUCH || (hit[0] | hit[1]) != 0;
}

/* Constraint k of events_contact, whose bound says its gap may close: unless it rests,
 * where along the piece it closes, kept in *first and *which when it is the earliest. */
static void contact_at(const struct events_piece *p, int k, double *first, int *which,
                       int *closing)
{
    if (p->rest->active && p->rest->on[k])
        return;
    double th = consider(p, k);
    if (th < 0.0)
        return;
    ++*closing;
    if (th < *first)
        *first = th, *which = k;
}

double events_contact(const struct events_piece *p, int *which, int *closing)
{
    int n = p->lim->n, k = 1;
    double first = 2.0;
    *which = -1, *closing = 0;
    /* In order of k (the earliest's ties go to the first), the pairs two at a time. */
    if (bound_may_close(p, 0))
        contact_at(p, 0, &first, which, closing);
    for (; k + 1 < n; k += 2) {
        vec2_mask hit = pairs_may_close(p, k);
        if (hit[0])
            contact_at(p, k, &first, which, closing);
        if (hit[1])
            contact_at(p, k + 1, &first, which, closing);
    }
    for (; k < p->lim->count; k++)
        if (bound_may_close(p, k))
            contact_at(p, k, &first, which, closing);
    return *which < 0 ? -1.0 : first;
}

/* The weakest resting contact's force at theta, that contact in *which. */
static double weakest_at(const struct events_piece *p, double th, double *work, double *force,
                         int *which)
{
    int n = p->m->n;
    double u, du, t = p->a + th * p->h;
    drive_eval(p->d, t, &u, &du);
    const double *y = th == 0.0 ? p->ya : th == 1.0 ? p->y : work; /* the ends as they are */
    if (y == work) /* the forces read the clusters' masses and their neighbours */
        for (int c = 0; c < p->rest->clusters; c++) {
            int hi = p->rest->last[c] + 1 < n ? p->rest->last[c] + 1 : n - 1;
            for (int i = p->rest->first[c] > 0 ? p->rest->first[c] - 1 : 0; i <= hi; i++) {
                work[i] = hermite(p, i, th);
                work[n + i] = hermite_v(p, i, th);
            }
        }
    *which = rest_forces(p->rest, p->m, y, y + n, u, du, p->ddu_factor * u, drive_force(p->d, t),
                         force);
    return *which < 0 ? INFINITY : force[*which];
}

double events_release(const struct events_piece *p, double *work, double *force, int *which)
{
    int k;
    double fhi = weakest_at(p, 1.0, work, force, &k);
    if (!(fhi < -REST_PULL))
        return -1.0;
    /* The weakest force is a smooth function of theta, >= 0 at 0 where the contacts held:
     * regula falsi (Illinois) to where it turns to a pull. */
    double lo = 0.0, hi = 1.0, flo = weakest_at(p, 0.0, work, force, &k);
    if (!(flo > 0.0)) {
        *which = k;
        return 0.0;
    }
    int side = 0;
    *which = k;
    for (int it = 0; it < 100 && hi - lo > 1e-14; it++) {
        double th = (lo * fhi - hi * flo) / (fhi - flo);
        if (!(th > lo && th < hi))
            th = 0.5 * (lo + hi);
        double f = weakest_at(p, th, work, force, &k);
        if (f < 0.0) {
            hi = th, fhi = f, *which = k;
            if (side == 1)
                flo *= 0.5;
            side = 1;
        } else {
            lo = th, flo = f;
            if (side == -1)
                fhi *= 0.5;
            side = -1;
        }
        if (fabs(f) <= 1e-12 * (1.0 + fabs(flo - fhi)) && f < 0.0)
            break;
    }
    return hi;
}

/* The contact rule on constraint k between the two masses it joins (or a mass and the
 * wall or the piston): 1 if they were closing. Resting contacts take no part: an impact's
 * impulse is infinite beside the finite force that holds them, so a hit on a pressed row
 * goes through it pair by pair as through a row merely touching. */
static int pair_hit(const struct collision_limits *l, const struct model *m, struct rest *r,
                    int k, double *v, double du, struct collision_books *bk)
{
    int n = l->n;
    double mass_l = k > 0 ? m->m[k - 1] : INFINITY, mass_r = k < n ? m->m[k] : INFINITY;
    double vl0 = k > 0 ? v[k - 1] : 0.0, vr0 = k < n ? v[k] : du;
    double closing = vl0 - vr0;
    if (!(closing > 0.0)) {
        /* Touching and moving as one (a pile put on the piston's face): no impact, but
         * the contact may rest if the forces press it shut. */
        if (closing > -REST_RATE)
            r->soft[k] = r->enabled;
        return 0;
    }
    double e = closing < r->v_rest ? 0.0 : MODEL_RESTITUTION, vl, vr, mu;
    r->soft[k] = e == 0.0 && r->enabled;
    if (isinf(mass_l)) {
        vl = vl0, vr = vl0 + e * closing, mu = mass_r;
    } else if (isinf(mass_r)) {
        vl = vr0 - e * closing, vr = vr0, mu = mass_l;
    } else {
        double mt = mass_l + mass_r, p = mass_l * vl0 + mass_r * vr0;
        vl = (p - mass_r * e * closing) / mt, vr = (p + mass_l * e * closing) / mt;
        mu = mass_l * mass_r / mt;
    }
    double lost = 0.5 * mu * (1.0 - e * e) * closing * closing;
    bk->lost += lost;
    if (k > 0)
        v[k - 1] = vl;
    if (k < n)
        v[k] = vr;
    /* The piston, moving, does all the work the contact did: the mass's gain plus the
     * loss. Against the wall it does none. */
    if (k == n)
        bk->piston += 0.5 * mass_l * (vl * vl - vl0 * vl0) + lost;
    return 1;
}

/* Whether constraint k touches: resting, or its gap within EVENTS_TOUCH of closed. */
static bool touching(const struct collision_limits *l, const struct rest *r, int k,
                     const double *x, double u)
{
    return r->on[k] || collision_gap(l, k, x, u) <= EVENTS_TOUCH;
}

/* Element i of the row from the wall (i = -1, at rest) to the piston (i = n, at du):
 * its mass, infinite for the two ends, and its velocity. */
static double element(const struct model *m, int n, int i, const double *v, double du,
                      double *vel)
{
    *vel = i < 0 ? 0.0 : i < n ? v[i] : du;
    return i < 0 || i >= n ? INFINITY : m->m[i];
}

/* What still closes along the row of contacts [lo, hi] after the sweeps, every contact
 * of the last sweep slower than the rest speed, resolved at once: the limit of perfectly
 * inelastic sweeps, which is the velocities made non-decreasing from left to right with
 * each run that would keep closing moving as one, its momentum kept (pool adjacent
 * violators, weighted by the masses; the wall and the piston are ends of infinite mass).
 * The pooled contacts may rest; the energy is booked, the piston doing the work of its
 * impulse. Returns 1. */
static int pool(const struct collision_limits *l, const struct model *m, struct rest *r,
                int lo, int hi, double *v, double du, struct collision_books *bk)
{
    int n = l->n, first = lo - 1, last = hi < n ? hi : n, nb = 0;
    double *bm = r->pool, *bv = bm + n + 2, *bs = bv + n + 2; /* each block's mass, v, start */
    for (int i = first; i <= last; i++) {
        bm[nb] = element(m, n, i, v, du, &bv[nb]), bs[nb] = i, nb++;
        while (nb > 1 && bv[nb - 2] > bv[nb - 1]) {
            double ma = bm[nb - 2], mb = bm[nb - 1], va = bv[nb - 2], vb = bv[nb - 1];
            bv[nb - 2] = isinf(ma) ? va : isinf(mb) ? vb : (ma * va + mb * vb) / (ma + mb);
            bm[nb - 2] = ma + mb;
            nb--;
        }
    }
    double e0 = 0.0, e1 = 0.0, impulse = 0.0;
    for (int b = 0; b < nb; b++) {
        int end = b + 1 < nb ? (int)bs[b + 1] : last + 1;
        bool piston = end > n;
        for (int i = (int)bs[b]; i < end; i++) {
            if (i < 0 || i >= n)
                continue;
            e0 += 0.5 * m->m[i] * v[i] * v[i];
            if (piston)
                impulse += m->m[i] * (bv[b] - v[i]);
            v[i] = bv[b];
            e1 += 0.5 * m->m[i] * v[i] * v[i];
        }
        for (int k = (int)bs[b] + 1; k < end; k++)
            r->soft[k] = r->enabled; /* constraint k joins elements k - 1 and k */
    }
    bk->piston += impulse * du;
    bk->lost += fmax(0.0, e0 - e1 + impulse * du);
    return 1;
}

int events_hit(const struct collision_limits *l, const struct model *m, struct rest *r, int k,
               const double *x, double *v, double u, double du, struct collision_books *b)
{
    /* The impulse travels along the row of touching contacts around k, so the sweeps
     * need look no further. They go left to right and back in turn, so a wave running
     * either way crosses the row in one sweep. */
    int lo = k, hi = k;
    while (lo > 0 && touching(l, r, lo - 1, x, u))
        lo--;
    while (hi + 1 < l->count && touching(l, r, hi + 1, x, u))
        hi++;
    int hits = pair_hit(l, m, r, k, v, du, b), found = 1;
    double fastest = INFINITY; /* the fastest contact of the last sweep (m/s) */
    /* A contact whose two masses have not changed since it was last visited does nothing
     * (it was left open or parting), so each sweep visits only [from, to]: the contacts
     * beside a change of the sweep before, stretched as a change reaches an end. */
    int from = lo, to = hi;
    for (int sweep = 0; found && sweep < EVENTS_SWEEPS; sweep++) {
        found = 0, fastest = 0.0;
        int step = sweep % 2 ? -1 : 1, hit_lo = hi + 1, hit_hi = lo - 1;
        for (int kk = step > 0 ? from : to; kk >= from && kk <= to; kk += step) {
            double closing = -collision_rate(l, kk, v, du);
            if (!pair_hit(l, m, r, kk, v, du, b))
                continue;
            found++, fastest = closing > fastest ? closing : fastest;
            hit_lo = kk < hit_lo ? kk : hit_lo, hit_hi = kk > hit_hi ? kk : hit_hi;
            if (step > 0 && kk == to && to < hi)
                to++;
            else if (step < 0 && kk == from && from > lo)
                from--;
        }
        hits += found;
        from = hit_lo - 1 > lo ? hit_lo - 1 : lo, to = hit_hi + 1 < hi ? hit_hi + 1 : hi;
    }
    if (found && fastest < r->v_rest)
        hits += pool(l, m, r, lo, hi, v, du, b);
    else if (found)
        hits += collision_merge(l, m, x, v, u, du, b);
    return hits;
}

void events_settle_rest(const struct collision_limits *l, const struct model *m, struct rest *r,
                        double *x, double *v, double u, double du, double ddu, double f,
                        double *force)
{
    for (int k = 0; k < l->count; k++) {
        if (!r->on[k] && !r->soft[k])
            continue; /* the common case, in a long chain nearly every k */
        double rate = collision_rate(l, k, v, du);
        if (r->on[k] && rate > REST_RATE)
            rest_set(r, k, false);
        else if (!r->on[k] && r->soft[k] && fabs(rate) <= REST_RATE &&
                 fabs(collision_gap(l, k, x, u)) <= REST_GAP)
            rest_set(r, k, true);
        r->soft[k] = false;
    }
    while (r->active) {
        int k = rest_forces(r, m, x, v, u, du, ddu, f, force);
        if (k < 0 || force[k] >= -REST_PULL)
            break;
        rest_set(r, k, false);
    }
    rest_snap(r, l, m, x, v, u, du);
}
