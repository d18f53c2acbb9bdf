/* tui.h: the interactive terminal program (ncursesw). */
#ifndef SPRINGSIM_TUI_H
#define SPRINGSIM_TUI_H

#include <stdbool.h>

#include "../core/config.h"

struct lesson;

/* Runs the interactive program on cfg until the user quits; returns the exit status. */
int tui_run(const struct config *cfg, const char *exe_dir, const struct lesson *lesson);

/* True for a terminal the interactive program cannot draw on (TERM=dumb, or one that
 * cannot place the cursor), which the plain mode serves instead. */
bool tui_dumb_terminal(void);

#endif
