/* braille.h: a dot canvas drawn with Unicode braille (2x4 dots a cell), with quadrant
 * block and ASCII fallbacks; pure, no curses, so it is unit-tested on its own. */
#ifndef SPRINGSIM_BRAILLE_H
#define SPRINGSIM_BRAILLE_H

#include <stdbool.h>
#include <stdint.h>

struct strokes;

struct canvas {
    int cols, rows;  /* size in cells; dots are 2*cols by 4*rows */
    uint8_t *bits;   /* braille dot bits per cell (U+2800 + bits) */
    uint8_t *color;  /* colour index per cell: the last dot set wins */
    struct strokes *strokes; /* what is drawn as lines, for pixels (NULL: not kept now) */
    struct strokes *kept;    /* the strokes' memory, kept while not recording */
    int mute;        /* > 0: a caller keeps the strokes itself (plot_canvas.c, at full precision) */
};

/* A blank canvas of cols x rows cells, or NULL on no memory. */
struct canvas *canvas_new(int cols, int rows);

/* Frees a canvas. */
void canvas_free(struct canvas *c);

/* From now on also keeps what is drawn as strokes (strokes.h), for pixel output; false on
 * no memory. */
bool canvas_keep_strokes(struct canvas *c);

/* Whether canvases that keep strokes record them from their next canvas_clear on (on by
 * default; the terminal program turns it off while nothing needs them: braille charts
 * and no figure being saved). */
void canvas_record(bool on);

/* Clears every dot (and the strokes). */
void canvas_clear(struct canvas *c);

/* Sets the dot at (x, y), y = 0 at the top; dots off the canvas are ignored. */
void canvas_set(struct canvas *c, int x, int y, uint8_t color);

/* Sets the dots of a straight line from (x0, y0) to (x1, y1) (Bresenham). */
void canvas_line(struct canvas *c, int x0, int y0, int x1, int y1, uint8_t color);

/* canvas_line; with dash, only the dots of every other pair of columns (x / 2 even). */
void canvas_dashed_line(struct canvas *c, int x0, int y0, int x1, int y1, uint8_t color,
                        bool dash);

/* canvas_line in dashes along its length, the same on a line at any slope: *run counts
 * the line walked so far in quarter cells (carried from one segment to the next, so a
 * path's dashes run on across its joins); two cells drawn, two left out. */
void canvas_stroke(struct canvas *c, int x0, int y0, int x1, int y1, uint8_t color, int *run);

/* Sets every dot of column x from y0 to y1 inclusive, in either order. */
void canvas_vspan(struct canvas *c, int x, int y0, int y1, uint8_t color);

/* Dot bits of cell (cx, cy). */
uint8_t canvas_bits(const struct canvas *c, int cx, int cy);

/* UTF-8 of the braille glyph for bits into out (4 bytes and a NUL). */
void braille_utf8(uint8_t bits, char out[5]);

/* An ASCII character that reads like the dots: '.', ':', '\'', '|' and so on. */
char braille_ascii(uint8_t bits);

/* The Unicode block element (U+2580..U+259F, quadrants: 2x2 a cell) that covers the
 * dots: a quadrant is filled where any of its four dots is set; 0 for no dot. For
 * terminals whose fonts lack braille (--glyphs blocks). */
unsigned braille_quadrant(uint8_t bits);

#endif
