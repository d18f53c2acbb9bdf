/* trail.h: the recent samples the plots draw (t, u and each mass's x, v, a), kept in
 * a ring whose every window of records is contiguous, so plots read it in one piece. */
#ifndef SPRINGSIM_TRAIL_H
#define SPRINGSIM_TRAIL_H

#include "../core/sim.h"

struct trail {
    int n;          /* masses */
    int width;      /* doubles per record: t, u, x[n], v[n], a[n], 5 energies */
    int capacity;   /* records kept */
    int head;       /* index of the oldest record */
    int count;      /* records kept now */
    double *buf;    /* 2 * capacity records: each written at i and i + capacity */
    double *accel;  /* scratch for accelerations, n doubles */
};

/* Offsets inside a record. */
#define TRAIL_T 0
#define TRAIL_U 1
#define TRAIL_X(tr, i) (2 + (i))
#define TRAIL_V(tr, i) (2 + (tr)->n + (i))
#define TRAIL_A(tr, i) (2 + 2 * (tr)->n + (i))
/* Energies: kinetic, potential, dissipated, motor work, taken by contacts. */
enum { TRAIL_KE, TRAIL_PE, TRAIL_DISS, TRAIL_WORK, TRAIL_CONTACT, TRAIL_ENERGIES };
#define TRAIL_E(tr, k) (2 + 3 * (tr)->n + (k))

/* A trail of capacity records for n masses, or NULL on no memory. */
struct trail *trail_new(int n, int capacity);

/* Frees a trail. */
void trail_free(struct trail *tr);

/* Appends the current state of s, dropping the oldest record when full. */
void trail_push(struct trail *tr, const struct sim *s);

/* Drops the records later than t (after stepping back). */
void trail_drop_after(struct trail *tr, double t);

/* Drops everything. */
void trail_clear(struct trail *tr);

/* The oldest record; the rest follow contiguously, width doubles apart. */
const double *trail_first(const struct trail *tr);

#endif
