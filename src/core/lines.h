/* lines.h: the one loop that cuts a text read whole (a preset, a lesson) into lines: '\n'
 * ends a line, and a line holding a NUL byte or longer than the reader allows is said,
 * with its number, for the reader's message. */
#ifndef SPRINGSIM_LINES_H
#define SPRINGSIM_LINES_H

#include <stddef.h>

struct lines {
    const char *s, *end; /* the text not read yet */
    int line;            /* the number of the line last read (from 1) */
};

enum lines_status {
    LINES_END,  /* no line left */
    LINES_OK,   /* a line */
    LINES_NUL,  /* a line holding a NUL byte */
    LINES_LONG  /* a line longer than max characters, its '\n' apart */
};

/* Reading text's size bytes from its first line. */
struct lines lines_of(const char *text, size_t size);

/* The next line, [*start, *eol) (eol at its '\n' or the text's end); past it either way. */
enum lines_status lines_next(struct lines *r, size_t max, const char **start, const char **eol);

#endif
