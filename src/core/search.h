/* search.h: where the program's data files are found and how they are read: presets and
 * lessons alike are looked for in the user's directory, $SPRINGSIM_PRESETS or
 * $SPRINGSIM_LESSONS, the installed directory and beside the program, in that order. */
#ifndef SPRINGSIM_SEARCH_H
#define SPRINGSIM_SEARCH_H

#include <stddef.h>

#define SEARCH_DIRS 4     /* directories on a search path, at most */
#define SEARCH_DIR_MAX 4096 /* bytes of one directory's name */

/* What is searched for. */
enum search_kind { SEARCH_PRESETS, SEARCH_LESSONS };

/* The user's directory: $XDG_CONFIG_HOME/springsim/KIND, or $HOME/.config/springsim/KIND;
 * 0, or -1 when neither variable is set. */
int search_user_dir(enum search_kind kind, char *out, size_t len);

/* The directories searched, in order, into dirs; returns how many. */
int search_dirs(enum search_kind kind, const char *exe_dir, char dirs[SEARCH_DIRS][SEARCH_DIR_MAX]);

/* The installed directory, set at build time. */
const char *search_installed_dir(enum search_kind kind);

/* Reads the regular file at path, of at most max bytes, into a malloc'ed NUL-terminated
 * *text (free it) of *size bytes. Opened without waiting (a FIFO is refused, never waited
 * on). 0; 1 when it cannot be read (err: "PATH: reason"); 2 when it is too large. `what`
 * names the kind of file in messages ("a preset"). */
int search_read(const char *path, size_t max, const char *what, char **text, size_t *size,
                char *err, size_t errlen);

#endif
