/* lessons_cli.h: the command line's lessons (--list-lessons, --lesson, --replay). */
#ifndef SPRINGSIM_LESSONS_CLI_H
#define SPRINGSIM_LESSONS_CLI_H

#include "lab/lesson.h"
#include "core/config.h"

/* --list-lessons: "NAME  TITLE", one line each, escaped; the exit status. */
int lessons_list(const char *exe_dir);

/* The lesson --lesson or --replay names in c, read into l and every command tried before
 * anything runs: -1 to go on; else the exit status, after one line saying why (FILE:LINE:
 * what). With keys (the interactive program, on a terminal), Esc, q or Ctrl+C typed on
 * standard input leave that check within LESSON_POLL seconds: exit status 1. */
int lessons_load(const struct config *c, const char *exe_dir, bool keys, struct lesson *l);

#endif
