/* tui.h: the interactive terminal program (ncursesw). */
#ifndef SPRINGSIM_TUI_H
#define SPRINGSIM_TUI_H

#include "../core/config.h"

/* Runs the interactive program on cfg until the user quits; returns the exit status. */
int tui_run(const struct config *cfg, const char *exe_dir);

#endif
