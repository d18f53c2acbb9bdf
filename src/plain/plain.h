/* plain.h: the plain mode (--plain, and TERM=dumb): the interactive program as lines of
 * text, for screen readers, braille displays, dumb terminals and pipes. */
#ifndef SPRINGSIM_PLAIN_H
#define SPRINGSIM_PLAIN_H

#include "../core/config.h"

struct lesson;

/* Runs the plain mode on cfg until quit, the end of input, a closed standard output or
 * a terminating signal; returns the exit status (or dies of the signal). */
int plain_run(const struct config *cfg, const char *exe_dir, const struct lesson *lesson);

#endif
