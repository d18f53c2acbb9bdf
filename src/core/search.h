/* search.h: where the program's data files are found and how they are read: presets and
 * lessons alike are looked for in the user's directory, $SPRINGSIM_PRESETS or
 * $SPRINGSIM_LESSONS, the installed directory and beside the program, in that order. */
#ifndef SPRINGSIM_SEARCH_H
#define SPRINGSIM_SEARCH_H

#include <stddef.h>
#include <stdio.h>

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

/* One data file found on the search path: a preset or a lesson. */
struct search_entry {
    char name[256];  /* the word that names it: the file name without .ini or .lesson */
    char path[4400]; /* its file */
    char about[256]; /* what its about function found in it (a preset's description, a
                      * lesson's title), control bytes made harmless, or "" */
};

/* Finds in a file's text (NUL-terminated) what a list says about it, into about. */
typedef void search_about_fn(const char *text, char *about, size_t len);

/* Every file of the kind on the search path (regular files of at most max bytes: a FIFO,
 * a device or a huge file is not one, and reading it could hang the listing), the first
 * of each name only, sorted by name, into a malloc'ed *out (free it); how many. */
int search_scan(enum search_kind kind, const char *exe_dir, size_t max, search_about_fn *about,
                struct search_entry **out);

/* "NAME  ABOUT" a line each (none where about is ""), names in one column, each line
 * escaped whole: a control byte in a file's name or its about cannot reach the terminal
 * nor split the line. */
void search_list(FILE *out, const struct search_entry *all, int count, const char *none);

#endif
