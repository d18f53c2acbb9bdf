/* braille.c: the dot canvas. A dot at (x, y) is bit map[y % 4][x % 2] of cell
 * (x / 2, y / 4) and the glyph is U+2800 + bits (the drawille scheme). */
#include "braille.h"

#include <stdlib.h>
#include <string.h>

#include "strokes.h"

/* Unicode braille dot numbering: 1 4 / 2 5 / 3 6 / 7 8, as bits 0..7. */
static const uint8_t dot_bit[4][2] = {{0x01, 0x08}, {0x02, 0x10}, {0x04, 0x20}, {0x40, 0x80}};

struct canvas *canvas_new(int cols, int rows)
{
    if (cols < 1 || rows < 1)
        return NULL;
    struct canvas *c = malloc(sizeof *c);
    if (!c)
        return NULL;
    size_t cells = (size_t)cols * (size_t)rows;
    c->cols = cols;
    c->rows = rows;
    c->strokes = c->kept = NULL;
    c->mute = 0;
    c->bits = calloc(2 * cells, 1);
    if (!c->bits) {
        free(c);
        return NULL;
    }
    c->color = c->bits + cells;
    return c;
}

void canvas_free(struct canvas *c)
{
    if (c) {
        free(c->bits);
        strokes_free(c->kept);
    }
    free(c);
}

static bool recording = true; /* canvas_record */

void canvas_record(bool on)
{
    recording = on;
}

bool canvas_keep_strokes(struct canvas *c)
{
    if (!c->kept)
        c->kept = strokes_new();
    c->strokes = recording ? c->kept : NULL;
    return c->kept != NULL;
}

void canvas_clear(struct canvas *c)
{
    memset(c->bits, 0, 2 * (size_t)c->cols * (size_t)c->rows);
    c->strokes = recording ? c->kept : NULL;
    if (c->strokes)
        strokes_clear(c->strokes);
}

/* Whether what is drawn now is kept as strokes too. */
static bool keeping(const struct canvas *c)
{
    return c->strokes && c->mute == 0;
}

static void set_dot(struct canvas *c, int x, int y, uint8_t color)
{
    if (x < 0 || y < 0 || x >= 2 * c->cols || y >= 4 * c->rows)
        return;
    size_t cell = (size_t)(y / 4) * (size_t)c->cols + (size_t)(x / 2);
    c->bits[cell] |= dot_bit[y % 4][x % 2];
    c->color[cell] = color;
}

void canvas_set(struct canvas *c, int x, int y, uint8_t color)
{
    if (keeping(c))
        strokes_segment(c->strokes, x, y, x, y, color, STROKE_DOTS);
    set_dot(c, x, y, color);
}

void canvas_line(struct canvas *c, int x0, int y0, int x1, int y1, uint8_t color)
{
    canvas_dashed_line(c, x0, y0, x1, y1, color, false);
}

/* Quarter cells of a canvas_stroke dash, and of the gap after it. */
#define STROKE_DASH 8

/* The dots of the line from (x0, y0) to (x1, y1) (Bresenham): all of them; with dash, those
 * of every other pair of columns; with run, those of every other STROKE_DASH quarter cells
 * along it (a dot across is half a cell, a dot down a quarter). */
static void walk(struct canvas *c, int x0, int y0, int x1, int y1, uint8_t color, bool dash,
                 int *run)
{
    int dx = abs(x1 - x0), sx = x0 < x1 ? 1 : -1;
    int dy = -abs(y1 - y0), sy = y0 < y1 ? 1 : -1;
    int err = dx + dy;
    for (;;) {
        bool on = run ? (*run / STROKE_DASH) % 2 == 0 : !dash || (x0 / 2) % 2 == 0;
        if (on)
            set_dot(c, x0, y0, color);
        if (x0 == x1 && y0 == y1)
            break;
        int e2 = 2 * err;
        if (e2 >= dy) {
            err += dy;
            x0 += sx;
            if (run)
                *run += 2;
        }
        if (e2 <= dx) {
            err += dx;
            y0 += sy;
            if (run)
                *run += 1;
        }
    }
}

void canvas_dashed_line(struct canvas *c, int x0, int y0, int x1, int y1, uint8_t color,
                        bool dash)
{
    if (keeping(c))
        strokes_segment(c->strokes, x0, y0, x1, y1, color, dash ? STROKE_DASHED : STROKE_LINE);
    walk(c, x0, y0, x1, y1, color, dash, NULL);
}

void canvas_stroke(struct canvas *c, int x0, int y0, int x1, int y1, uint8_t color, int *run)
{
    if (keeping(c))
        strokes_segment(c->strokes, x0, y0, x1, y1, color, STROKE_DASHED);
    walk(c, x0, y0, x1, y1, color, false, run);
}

void canvas_vspan(struct canvas *c, int x, int y0, int y1, uint8_t color)
{
    if (y0 > y1) {
        int t = y0;
        y0 = y1;
        y1 = t;
    }
    if (y0 < 0)
        y0 = 0;
    if (y1 >= 4 * c->rows)
        y1 = 4 * c->rows - 1;
    if (keeping(c) && y0 <= y1)
        strokes_segment(c->strokes, x, y0, x, y1, color, STROKE_LINE);
    for (int y = y0; y <= y1; y++)
        set_dot(c, x, y, color);
}

uint8_t canvas_bits(const struct canvas *c, int cx, int cy)
{
    if (cx < 0 || cy < 0 || cx >= c->cols || cy >= c->rows)
        return 0;
    return c->bits[(size_t)cy * (size_t)c->cols + (size_t)cx];
}

void braille_utf8(uint8_t bits, char out[5])
{
    unsigned cp = 0x2800u + bits; /* three bytes: 1110xxxx 10xxxxxx 10xxxxxx */
    out[0] = (char)(0xE0 | (cp >> 12));
    out[1] = (char)(0x80 | ((cp >> 6) & 0x3F));
    out[2] = (char)(0x80 | (cp & 0x3F));
    out[3] = '\0';
    out[4] = '\0';
}

char braille_ascii(uint8_t bits)
{
    int top = (bits & 0x09) != 0;    /* row 0 */
    int upper = (bits & 0x12) != 0;  /* row 1 */
    int lower = (bits & 0x24) != 0;  /* row 2 */
    int bottom = (bits & 0xC0) != 0; /* row 3 */
    int high = top || upper, low = lower || bottom;
    if (!bits)
        return ' ';
    if (high && low)
        return (top && bottom) ? '|' : ':';
    if (high)
        return top ? '\'' : '-';
    return bottom ? '.' : '-';
}

unsigned braille_quadrant(uint8_t bits)
{
    /* Indexed by the quadrants filled: 1 upper left, 2 upper right, 4 lower left, 8
     * lower right. */
    static const unsigned block[16] = {0,      0x2598, 0x259D, 0x2580, 0x2596, 0x258C,
                                       0x259E, 0x259B, 0x2597, 0x259A, 0x2590, 0x259C,
                                       0x2584, 0x2599, 0x259F, 0x2588};
    int q = ((bits & (dot_bit[0][0] | dot_bit[1][0])) != 0) |
            ((bits & (dot_bit[0][1] | dot_bit[1][1])) != 0) << 1 |
            ((bits & (dot_bit[2][0] | dot_bit[3][0])) != 0) << 2 |
            ((bits & (dot_bit[2][1] | dot_bit[3][1])) != 0) << 3;
    return block[q];
}
