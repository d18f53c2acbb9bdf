/* command_say.h: the plain mode's telling commands (status, modes, controls, presets,
 * cursor, measure): the functions of their rows in command.c, each answering in one
 * line. */
#ifndef SPRINGSIM_COMMAND_SAY_H
#define SPRINGSIM_COMMAND_SAY_H

#include "command.h"

/* The chain's modes: each frequency with its damping ratio and Q = 1/(2 zeta). */
enum command_reply say_modes(struct command_call *c);

/* Every control with its name for set and its value. */
enum command_reply say_controls(struct command_call *c);

/* The presets' names. */
enum command_reply say_presets(struct command_call *c);

/* The status line now (command_status). */
enum command_reply say_status(struct command_call *c);

/* cursor T: every mass's x, v, a and the motor at the sample nearest to T. */
enum command_reply say_cursor(struct command_call *c);

/* measure [MASS]: a mass's period, amplitude and damping over the window. */
enum command_reply say_measure(struct command_call *c);

#endif
