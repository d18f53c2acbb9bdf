/* sim_state.h: the driver's state, shared by sim.c (the object, its accessors, energy
 * and snapshots) and sim_step.c (the step). Private to those two files. */
#ifndef SPRINGSIM_SIM_STATE_H
#define SPRINGSIM_SIM_STATE_H

#include "clearance.h"
#include "collision.h"
#include "rest.h"
#include "sim.h"
#include "stepper.h"

struct sim {
    struct stepper *st;  /* the steppers, with the model's own copy */
    struct collision_limits lim;
    int n;               /* masses */
    double dt;           /* step */
    double t_base;       /* time at step 0 of the current dt */
    double steps;        /* whole steps since t_base (exact in a double to 2^53) */
    enum integrator integrator;
    double contact;      /* energy removed by contacts and the cap */
    int last_contacts;   /* contacts and caps in the last step */
    int last_capped;     /* caps in the last step */
    double *y;           /* STEPPER_LEN(N): x, v, D (dissipated), W (motor work), P (force) */
    double *y0;          /* the state at the start of the step, for restoring */
    const double *ya;    /* the state at the start of the piece being stepped: y0 or ya_buf */
    double *ya_buf;      /* room for it when the piece starts inside the step */
    struct rest *rest;   /* the contacts resting now */
    double *work;        /* 2N of scratch for the events */
    double *force;       /* N + 1: the resting contacts' forces */
    double sine_err;     /* a sine drive's straying from its cubic over h is this h^4 */
    struct clearance clear; /* how far the gaps are from closing, while the steps are bare */
};

#endif
