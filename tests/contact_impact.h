/* contact_impact.h: the reference's impacts (contact_reference.h includes it after the
 * state, the drive and the series it needs, and only it does): the restitution rule on
 * one gap, the sweeps along the touching row, their limit when they go on without end,
 * and held contacts made and parted. */
#ifndef SPRINGSIM_CONTACT_IMPACT_H
#define SPRINGSIM_CONTACT_IMPACT_H

/* Gap g now (m), and its rate (m/s) with the end moving at du. */
static double ref_gap_now(const struct ref *r, int g, double *rate, double du)
{
    int n = r->n;
    double u, du0;
    ref_drive(r, r->t, &u, &du0);
    if (g == 0) {
        *rate = r->v[0];
        return r->xeq[0] + r->x[0] - 0.5 * r->w;
    }
    if (g < n) {
        *rate = r->v[g] - r->v[g - 1];
        return r->xeq[g] + r->x[g] - r->xeq[g - 1] - r->x[g - 1] - r->w;
    }
    *rate = du - r->v[n - 1];
    return REF_L + u - 0.5 * r->w - r->xeq[n - 1] - r->x[n - 1];
}

/* The restitution rule on gap g between the two masses it joins (or a mass and the wall, or
 * the piston moving at du), with the books and the log: 1 if they were closing. One
 * closing slower than REF_V_REST is inelastic, and marked in soft (so is one touching and
 * moving as one: it may be held). */
static int ref_pair(struct ref *r, int g, double du, bool *soft)
{
    int n = r->n;
    double ml = g > 0 ? r->m[g - 1] : INFINITY, mr = g < n ? r->m[g] : INFINITY;
    double vl0 = g > 0 ? r->v[g - 1] : 0.0, vr0 = g < n ? r->v[g] : du;
    double closing = vl0 - vr0, e, mu, vl, vr;
    if (!(closing > 0.0)) {
        soft[g] = closing > -REF_RATE;
        return 0;
    }
    e = closing < REF_V_REST ? 0.0 : REF_E;
    soft[g] = e == 0.0;
    r->near_rest = fmin(r->near_rest, fabs(closing - REF_V_REST));
    if (isinf(ml)) {
        mu = mr, vl = vl0, vr = vl0 + e * closing;
    } else if (isinf(mr)) {
        mu = ml, vl = vr0 - e * closing, vr = vr0;
    } else {
        double mt = ml + mr, p = ml * vl0 + mr * vr0;
        mu = ml * mr / mt;
        vl = (p - mr * e * closing) / mt, vr = (p + ml * e * closing) / mt;
    }
    if (g == n) /* the piston's impulse on the mass, times its speed, is its work */
        r->motor_work += ml * (vl - vl0) * du;
    if (g > 0)
        r->v[g - 1] = vl;
    if (g < n)
        r->v[g] = vr;
    r->contact += 0.5 * mu * (1.0 - e * e) * closing * closing;
    struct ref_event ev = {r->t, g == 0 ? REF_LEFT : g == n ? REF_RIGHT : REF_PAIR,
                           g == 0 ? 0 : g - 1, closing};
    r->ev[r->nev % REF_MAXEVENTS] = ev; /* the last REF_MAXEVENTS, in a ring past that */
    r->nev++;
    r->count++;
    return 1;
}

/* After 16 sweeps of an impact, the last of which made only contacts slower than REF_V_REST,
 * what still closes along the row [lo, hi] is resolved as perfectly inelastic sweeps
 * carried on until no gap closes faster than 1e-13 m/s (they converge geometrically), the
 * books kept, the pairs marked in soft; one contact. */
static int ref_stick_sweeps(struct ref *r, int lo, int hi, double du, bool *soft)
{
    int n = r->n;
    for (int sweep = 0, found = 1; found && sweep < 1000000; sweep++) {
        found = 0;
        for (int j = 0; j <= hi - lo; j++) {
            int g = sweep % 2 ? hi - j : lo + j;
            double ml = g > 0 ? r->m[g - 1] : INFINITY, mr = g < n ? r->m[g] : INFINITY;
            double vl0 = g > 0 ? r->v[g - 1] : 0.0, vr0 = g < n ? r->v[g] : du;
            double closing = vl0 - vr0, v, mu;
            if (!(closing > 1e-13))
                continue;
            found = 1, soft[g] = true;
            if (isinf(ml))
                v = vl0, mu = mr;
            else if (isinf(mr))
                v = vr0, mu = ml;
            else
                v = (ml * vl0 + mr * vr0) / (ml + mr), mu = ml * mr / (ml + mr);
            if (g == n)
                r->motor_work += ml * (v - vl0) * du;
            if (g > 0)
                r->v[g - 1] = v;
            if (g < n)
                r->v[g] = v;
            r->contact += 0.5 * mu * closing * closing;
        }
    }
    /* The sweeps leave rounding's 1e-13 m/s between masses they joined, which would close
     * a held gap over time: each run they joined takes its momentum's velocity exactly
     * (the wall's 0, the piston's du). */
    bool joined[REF_MAXN + 1];
    for (int g = lo; g <= hi; g++) {
        double rate;
        ref_gap_now(r, g, &rate, du);
        joined[g] = soft[g] && fabs(rate) <= 1e-12;
    }
    for (int a = lo, b; a <= hi; a = b + 1) {
        for (b = a; b + 1 <= hi && joined[a] && joined[b + 1]; b++)
            ;
        if (!joined[a])
            continue;
        int first = a > 0 ? a - 1 : 0, last = b < n ? b : n - 1;
        double p = 0.0, mass = 0.0, e0 = 0.0, e1 = 0.0, vc;
        for (int i = first; i <= last; i++)
            p += r->m[i] * r->v[i], mass += r->m[i], e0 += 0.5 * r->m[i] * r->v[i] * r->v[i];
        vc = a == 0 ? 0.0 : b == n ? du : p / mass;
        for (int i = first; i <= last; i++)
            r->v[i] = vc, e1 += 0.5 * r->m[i] * vc * vc;
        if (b == n)
            r->motor_work += (mass * vc - p) * du;
        r->contact += e0 - e1 + (b == n ? (mass * vc - p) * du : 0.0);
    }
    r->count++;
    return 1;
}

/* An impact on gap g: the restitution rule there, then on every touching gap of the row around
 * it (held or closed to 1e-12 m) still closing, sweeps alternating left to right and
 * back until none closes; held contacts take part like any other (the impulse is infinite
 * beside their force). Then held contacts moving apart part, inelastic ones pressed shut
 * are held. Returns the contacts. */
static int ref_impact(struct ref *r, int g)
{
    int gaps = r->free_end ? r->n : r->n + 1, lo = g, hi = g, hits, found = 1;
    double u, du, rate;
    bool soft[REF_MAXN + 1] = {false};
    ref_drive(r, r->t, &u, &du);
    while (lo > 0 && (r->held[lo - 1] || ref_gap_now(r, lo - 1, &rate, du) <= 1e-12))
        lo--;
    while (hi + 1 < gaps && (r->held[hi + 1] || ref_gap_now(r, hi + 1, &rate, du) <= 1e-12))
        hi++;
    hits = ref_pair(r, g, du, soft);
    double fastest = INFINITY; /* the fastest contact of the last sweep */
    int sweep = 0;
    for (; found && sweep < 16; sweep++) {
        found = 0, fastest = 0.0;
        for (int j = 0; j <= hi - lo; j++) {
            int k = sweep % 2 ? hi - j : lo + j;
            ref_gap_now(r, k, &rate, du);
            if (ref_pair(r, k, du, soft))
                found++, fastest = fmax(fastest, -rate);
        }
        hits += found;
    }
    if (found && fastest >= REF_V_REST) /* the program then moves the row as one */
        r->error = "an impact still closing at the rest speed after 16 sweeps (a collapse)";
    else if (found)
        hits += ref_stick_sweeps(r, lo, hi, du, soft);
    for (int j = lo; j <= hi; j++) {
        ref_gap_now(r, j, &rate, du);
        if (r->held[j] && rate > REF_RATE)
            r->held[j] = false;
        else if (soft[j] && fabs(rate) <= REF_RATE)
            r->held[j] = true;
    }
    double force;
    for (int w; (w = ref_weakest(r, &force)) >= 0 && force < -REF_PULL;)
        r->held[w] = false;
    return hits;
}

/* A contact on gap g found closing: the impact, unless another came at the same instant
 * (not this reference's business). */
static void ref_contact(struct ref *r, int g)
{
    double last = r->nev > 0 ? r->ev[(r->nev - 1) % REF_MAXEVENTS].t : -INFINITY;
    int before = r->nev;
    ref_impact(r, g);
    for (int j = before; j < r->nev && r->nev > 0; j++)
        if (r->t - last < 1e-9 && r->ev[j % REF_MAXEVENTS].speed >= REF_V_REST)
            r->error = "two contacts at one instant";
}

#endif
