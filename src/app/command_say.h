/* command_say.h: the answers of the plain mode's telling commands (status, modes,
 * controls, presets), each one line into answer; command.c's rows call them. */
#ifndef SPRINGSIM_COMMAND_SAY_H
#define SPRINGSIM_COMMAND_SAY_H

#include <stddef.h>

#include "command.h"

struct app;

/* The chain's modes: each frequency with its damping ratio and Q = 1/(2 zeta). */
enum command_reply say_modes(const struct app *app, char *answer, size_t len);

/* Every control with its name for set and its value. */
enum command_reply say_controls(const struct app *app, char *answer, size_t len);

/* The presets' names. */
enum command_reply say_presets(const struct app *app, char *answer, size_t len);

#endif
