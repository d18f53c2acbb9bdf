/* draw.h: drawing primitives on stdscr: text that never runs past its width, spelled in
 * ASCII outside UTF-8, line characters, frames and braille canvases. */
#ifndef SPRINGSIM_DRAW_H
#define SPRINGSIM_DRAW_H

#include <stdbool.h>

#include <curses.h>

#include "../chart/braille.h"
#include "../chart/layout.h"

/* Line-drawing characters: the terminal's own in UTF-8, plain ASCII otherwise. */
enum line { L_H, L_V, L_UL, L_UR, L_LL, L_LR, L_RTEE, L_TTEE, L_PLUS };

/* A line-drawing character. */
chtype draw_line(enum line l);

/* Columns that UTF-8 text s takes as draw_text draws it (each character one column, or
 * its ASCII spelling's length where the terminal has no UTF-8: "²" takes 2). */
int draw_width(const char *s);

/* Writes at most w columns of UTF-8 text s at (y, x); our few symbols are spelled in
 * ASCII outside UTF-8. Text that does not fit ends in "…" ("..." in ASCII) in its last
 * column(s). Returns the columns written. */
int draw_text(int y, int x, int w, const char *s);

/* draw_text with printf formatting. */
int draw_printf(int y, int x, int w, const char *fmt, ...) __attribute__((format(printf, 4, 5)));

/* draw_text in attribute a. */
int draw_text_attr(int y, int x, int w, attr_t a, const char *s);

/* A box with an optional title near the left or centred; the title is cut to fit. */
void draw_frame(struct rect r, const char *title, bool centre);

/* Blanks rectangle r. */
void draw_clear(struct rect r);

/* Draws canvas c with its top-left cell at (y, x), each cell in its colour pair. */
void draw_canvas(const struct canvas *c, int y, int x);

#endif
