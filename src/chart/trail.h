/* trail.h: the recent samples the plots draw (t, u and each mass's x, v, a), kept in
 * a ring whose every window of records is contiguous, so plots read it in one piece. */
#ifndef SPRINGSIM_TRAIL_H
#define SPRINGSIM_TRAIL_H

#include "../core/sim.h"

struct trail {
    int n;          /* masses */
    int width;      /* doubles per record: t, u, x[n], v[n], a[n], then 5 energies
                     * unless it keeps the motion alone */
    int capacity;   /* records kept */
    int head;       /* index of the oldest record */
    int count;      /* records kept now */
    double *buf;    /* 2 * capacity records: each written at i and i + capacity */
    double *accel;  /* scratch for accelerations, n doubles */
};

/* The plots' samples of a chain: fine ones at least this far apart (s), this many: 11 s
 * or more, for the windows up to 10 s and for export; coarse ones 66 s or more, for the
 * longer windows. At N = 10 a record is 37 doubles, stored twice: 2.6 MB per trail; at
 * N = 2, 0.9 MB. */
#define TRAIL_FINE_SPACING 0.0025
#define TRAIL_FINE_RECORDS 4400
#define TRAIL_COARSE_SPACING 0.015
#define TRAIL_COARSE_RECORDS 4400

/* Offsets inside a record. */
#define TRAIL_T 0
#define TRAIL_U 1
#define TRAIL_X(tr, i) (2 + (i))
#define TRAIL_V(tr, i) (2 + (tr)->n + (i))
#define TRAIL_A(tr, i) (2 + 2 * (tr)->n + (i))
/* Energies: kinetic, potential, dissipated, motor work, taken by contacts. */
enum { TRAIL_KE, TRAIL_PE, TRAIL_DISS, TRAIL_WORK, TRAIL_CONTACT, TRAIL_FORCE, TRAIL_ENERGIES };
#define TRAIL_E(tr, k) (2 + 3 * (tr)->n + (k))

/* A trail of capacity records for n masses, or NULL on no memory. */
struct trail *trail_new(int n, int capacity);

/* As trail_new, the motion alone: records without the energies (TRAIL_E is not to be
 * read from it), for a chain no energy plot shows (the ghost). */
struct trail *trail_new_motion(int n, int capacity);

/* Frees a trail. */
void trail_free(struct trail *tr);

/* Appends the current state of s, dropping the oldest record when full. */
void trail_push(struct trail *tr, const struct sim *s);

/* Steps of dt between samples at least spacing (s) apart: 1 at least. */
int trail_every(double spacing, double dt);

/* Counts a step of s in *since and, when it makes every steps, pushes the state of s and
 * starts counting again. */
void trail_tick(struct trail *tr, int *since, int every, const struct sim *s);

/* Drops the records later than t (after stepping back). */
void trail_drop_after(struct trail *tr, double t);

/* Drops the records later than the time of s (after stepping back), keeping at least
 * its state now. */
void trail_follow(struct trail *tr, const struct sim *s);

/* Drops everything. */
void trail_clear(struct trail *tr);

/* The oldest record; the rest follow contiguously, width doubles apart. */
const double *trail_first(const struct trail *tr);

/* Index (0 the oldest) of the first record at or after time t, count if none. */
int trail_index(const struct trail *tr, double t);

/* Index of the record nearest to time t (the earlier of two as near), -1 if empty. */
int trail_nearest(const struct trail *tr, double t);

/* Time of record i (0 the oldest). */
double trail_time(const struct trail *tr, int i);

#endif
