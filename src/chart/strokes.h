/* strokes.h: what a canvas drew, kept as lines and dots in dot coordinates (fractional,
 * x from the left, y from the top, dot d's centre at d), so that the same drawing can be
 * painted sharp in pixels (a figure file, a sixel or kitty image) at any scale. No curses
 * here, and no cairo: fig/ paints them. */
#ifndef SPRINGSIM_STROKES_H
#define SPRINGSIM_STROKES_H

#include <stdbool.h>
#include <stdint.h>

enum stroke_kind {
    STROKE_LINE,
    STROKE_DASHED,
    STROKE_DOTS,
    STROKE_MARKS, /* a mass's mark at each point: a disc (5 dots across unless sized) */
};

/* The shape of STROKE_MARKS' marks. */
enum stroke_mark { MARK_DISC, MARK_UP, MARK_DOWN }; /* a disc, a triangle ▲ or ▼ */

/* One stroke: points [start, start + count) of the list, in one colour. */
struct stroke {
    int start, count;
    uint8_t color;  /* a colour pair's number (fig_color) */
    uint8_t kind;   /* an enum stroke_kind */
    uint8_t size;   /* STROKE_MARKS: the marks' size across in dots (0: 5) */
    uint8_t shape;  /* STROKE_MARKS: an enum stroke_mark */
};

struct strokes {
    double *xy;        /* points, (x, y) pairs */
    int n, cap;        /* points kept, room */
    struct stroke *s;  /* strokes */
    int ns, scap;
    bool full;         /* memory ran out: some were left out */
};

/* An empty list, or NULL on no memory. */
struct strokes *strokes_new(void);

/* Frees it. */
void strokes_free(struct strokes *k);

/* Empties it (keeping its memory). */
void strokes_clear(struct strokes *k);

/* Starts a stroke. */
void strokes_begin(struct strokes *k, uint8_t color, enum stroke_kind kind);

/* The current stroke's discs (STROKE_MARKS) are `dots` dots across. */
void strokes_mark_size(struct strokes *k, int dots);

/* The current stroke's marks (STROKE_MARKS) are shaped so: discs unless said. */
void strokes_mark_shape(struct strokes *k, enum stroke_mark shape);

/* Adds a point to the current stroke; a point that is not finite ends it (the next point
 * starts another of the same colour and kind). */
void strokes_point(struct strokes *k, double x, double y);

/* A segment: joined to the current stroke when that has the same colour and kind and
 * ends at (x0, y0), else a stroke of its own. */
void strokes_segment(struct strokes *k, double x0, double y0, double x1, double y1,
                     uint8_t color, enum stroke_kind kind);

/* A hash of everything kept: a drawing that did not change hashes the same. */
uint64_t strokes_hash(const struct strokes *k);

#endif
