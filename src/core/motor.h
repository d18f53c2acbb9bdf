/* motor.h: the right end's drive u(t) = A * w(2*pi*f*t), its four waveforms and
 * their breakpoints (jumps and corners), so a stepper can split its steps there. */
#ifndef SPRINGSIM_MOTOR_H
#define SPRINGSIM_MOTOR_H

enum wave { WAVE_SINE, WAVE_SQUARE, WAVE_TRIANGLE, WAVE_SAWTOOTH, WAVE_COUNT };

struct motor {
    enum wave wave;   /* waveform w */
    double amplitude; /* A, metres */
    double frequency; /* f, hertz */
    double phase;     /* cycles added to f t, so f can change without a jump in u */
};

/* Changes the frequency at time t keeping the phase, and so u, continuous. */
void motor_retune(struct motor *m, double frequency, double t);

/* One smooth piece of the waveform, extended past its ends: between two
 * breakpoints the drive is sin, a constant or a straight line. */
struct motor_piece {
    const struct motor *motor;
    double cref;  /* reference phase (cycles) of the linear piece */
    double slope; /* dw/dcycle on the piece; unused for sine */
    double w0;    /* w at cref */
};

/* The waveform w at a phase given in cycles (theta / 2pi), with the defined values at
 * the jumps themselves (square 0, sawtooth -1). */
double motor_wave(enum wave wave, double cycles);

/* The waveform's fundamental, b sin(2 pi cycles): every waveform here is odd and in phase
 * with the sine, its first Fourier coefficient b 1 (sine), 4/pi (square), 8/pi^2
 * (triangle) or 2/pi (sawtooth). */
double motor_fundamental(enum wave wave);

/* The motor position u(t) = A w(2 pi (f t + phase)) in metres. */
double motor_position(const struct motor *m, double t);

/* The piece of the waveform that contains time t (t should lie inside the piece,
 * not on a breakpoint: pass the middle of the interval of interest). */
void motor_piece_at(const struct motor *m, double t, struct motor_piece *p);

/* u(t) and u'(t) from a piece, valid on the whole interval the piece covers. */
void motor_piece_eval(const struct motor_piece *p, double t, double *u, double *du);

/* The waveform w(t) and w'(t) from a piece, amplitude 1: what the force input and a
 * stepper's unit drive read. */
void motor_piece_unit(const struct motor_piece *p, double t, double *w, double *dw);

/* Breakpoints strictly inside (t0, t1), ascending, at most max of them written to
 * out; returns how many there are in all. Points within a tiny tolerance of t0 or
 * t1 count as on the ends and are not returned. */
int motor_breakpoints(const struct motor *m, double t0, double t1, double *out, int max);

/* Whether the waveform jumps (square, sawtooth). */
int motor_has_jumps(enum wave wave);

/* The waveform's name ("sine", ...), or NULL for an invalid value. */
const char *motor_wave_name(enum wave wave);

/* The waveform named by s, or -1. */
int motor_wave_parse(const char *s);

#endif
