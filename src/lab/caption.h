/* caption.h: a lesson's text made into the lines of its caption panel: escaped as every
 * echo of user text is (control bytes, and Unicode's format characters such as U+202E,
 * which would turn the terminal's line around), spelled in ASCII where the terminal has
 * no UTF-8, and wrapped to the panel's width in screen columns (a CJK character takes
 * two, a combining one none), never cut inside a UTF-8 sequence or an escape. No curses
 * here. */
#ifndef SPRINGSIM_CAPTION_H
#define SPRINGSIM_CAPTION_H

#include <stdbool.h>
#include <stddef.h>

#define CAPTION_LINE 512 /* bytes of one line, at most */

/* text made safe to show into out (room for len): escaped, and spelled in ASCII (the
 * program's own symbols by their names, any other character '?') unless utf8. */
void caption_text(const char *text, bool utf8, char *out, size_t len);

/* The character at s (NUL-terminated): its bytes into *len, its screen columns
 * returned (0 for a combining mark, 2 for a wide one, 1 for a byte that is not UTF-8);
 * an escape written for a control or format character (\x1b, \u200d) is one whole. */
int caption_glyph(const char *s, size_t *len);

/* The screen columns of text (safe text, as caption_text makes it). */
int caption_width(const char *text);

/* Wraps one paragraph of safe text into lines of at most cols columns, cut at blanks (a
 * word wider than cols is cut between two characters), into lines[n], lines[n+1], ...
 * (at most max in all); a last line of one word is avoided by narrower lines when that
 * costs no line. Returns the new count. */
int caption_wrap(const char *text, int cols, char (*lines)[CAPTION_LINE], int n, int max);

#endif
