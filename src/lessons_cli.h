/* lessons_cli.h: the command line's lessons (--list-lessons, --lesson, --replay). */
#ifndef SPRINGSIM_LESSONS_CLI_H
#define SPRINGSIM_LESSONS_CLI_H

#include "app/lesson.h"
#include "core/config.h"

/* --list-lessons: "NAME  TITLE", one line each, escaped; the exit status. */
int lessons_list(const char *exe_dir);

/* The lesson --lesson or --replay names in c, read into l and every command tried before
 * anything runs: -1 to go on; else the exit status, after one line saying why (FILE:LINE:
 * what). */
int lessons_load(const struct config *c, const char *exe_dir, struct lesson *l);

#endif
