/* preset.h: presets as INI files (read with libinih): loading into a config, the
 * search path, listing, and writing a config back in the same format (springsim(1), PRESETS). */
#ifndef SPRINGSIM_PRESET_H
#define SPRINGSIM_PRESET_H

#include <stddef.h>
#include <stdio.h>

#include "config.h"
#include "search.h"

#define PRESET_MAX_BYTES (256 * 1024) /* larger files are refused */
#define PRESET_MAX_LINE 198           /* longest line libinih reads whole */

enum preset_status {
    PRESET_OK = 0,
    PRESET_IO = 1,   /* the file could not be read: err is "PATH: reason" */
    PRESET_BAD = 2,  /* the file is not a valid preset: err is "PATH:LINE: what" */
    PRESET_NONE = 3  /* no preset of that name: err says so */
};

/* Applies the preset file at path to c; its keys record path (which must outlive c)
 * and line as their origin. Only a regular file is read, opened without waiting (a FIFO
 * is refused, not waited on). On failure c may be partly set and err says why. */
enum preset_status preset_load(const char *path, struct config *c, char *err, size_t errlen);

/* Applies preset text (size bytes, not necessarily NUL-terminated) to c, as if read
 * from the file path (named in messages and origins; it must outlive c). */
enum preset_status preset_parse(const char *path, const char *text, size_t size,
                                struct config *c, char *err, size_t errlen);

/* The file a preset name or path stands for. A value with a '/' or ending in ".ini" is
 * a path; otherwise the search order is the user's directory, $SPRINGSIM_PRESETS, the
 * installed directory and exe_dir/presets. Writes the path into out and returns
 * PRESET_OK, or PRESET_NONE with a message in out (also for a path too long for out:
 * it is never cut, which could name another file). */
enum preset_status preset_find(const char *name, const char *exe_dir, char *out, size_t len);

/* The user's preset directory: $XDG_CONFIG_HOME/springsim/presets, or
 * $HOME/.config/springsim/presets; 0, or -1 when neither variable is set. */
int preset_user_dir(char *out, size_t len);

/* Every preset on the search path (search_scan: regular files of at most
 * PRESET_MAX_BYTES, sorted by name, each name once, the first found shadowing later
 * ones), each one's about its [preset] description, escaped; *out is malloc'ed (free
 * it); returns the count. */
int preset_scan(const char *exe_dir, struct search_entry **out);

/* One line per preset found on the search path, as preset_scan orders them:
 * "NAME  DESCRIPTION", control bytes (a newline in a file's name too) escaped as every
 * message escapes them. Returns the count. */
int preset_list(FILE *out, const char *exe_dir);

/* Writes c (with its per-element values from model m) as a preset file. */
int preset_write(FILE *out, const struct config *c, const struct model *m);

/* The installed preset directory, set at build time. */
extern const char preset_installed_dir[];

#endif
