/* strokes.c: lines and dots in dot coordinates, grown as needed (a refresh's worth, kept
 * between refreshes so their memory is allocated once). */
#include "strokes.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "../core/hash.h"

#define FAR 1e6 /* dots: a point this far off the canvas is as good as at infinity */

struct strokes *strokes_new(void)
{
    return calloc(1, sizeof(struct strokes));
}

void strokes_free(struct strokes *k)
{
    if (!k)
        return;
    free(k->xy);
    free(k->s);
    free(k);
}

void strokes_clear(struct strokes *k)
{
    k->n = k->ns = 0;
    k->full = false;
}

/* Room for one more point and one more stroke. */
static bool room(struct strokes *k)
{
    if (k->n == k->cap) {
        int cap = k->cap ? 2 * k->cap : 1024;
        double *xy = realloc(k->xy, (size_t)cap * 2 * sizeof *xy);
        if (!xy)
            return k->full = true, false;
        k->xy = xy, k->cap = cap;
    }
    if (k->ns == k->scap) {
        int cap = k->scap ? 2 * k->scap : 64;
        struct stroke *s = realloc(k->s, (size_t)cap * sizeof *s);
        if (!s)
            return k->full = true, false;
        k->s = s, k->scap = cap;
    }
    return true;
}

void strokes_begin(struct strokes *k, uint8_t color, enum stroke_kind kind)
{
    if (!room(k))
        return;
    k->s[k->ns++] = (struct stroke){k->n, 0, color, (uint8_t)kind, 0, 0};
}

void strokes_mark_size(struct strokes *k, int dots)
{
    if (k->ns > 0)
        k->s[k->ns - 1].size = (uint8_t)(dots < 0 ? 0 : dots > 255 ? 255 : dots);
}

void strokes_mark_shape(struct strokes *k, enum stroke_mark shape)
{
    if (k->ns > 0)
        k->s[k->ns - 1].shape = (uint8_t)shape;
}

void strokes_point(struct strokes *k, double x, double y)
{
    if (k->ns == 0 || !room(k))
        return;
    struct stroke *s = &k->s[k->ns - 1];
    if (!isfinite(x) || !isfinite(y)) {
        if (s->count > 0) {
            struct stroke was = *s;
            strokes_begin(k, was.color, (enum stroke_kind)was.kind);
            strokes_mark_size(k, was.size);
            strokes_mark_shape(k, (enum stroke_mark)was.shape);
        }
        return;
    }
    k->xy[2 * k->n] = fmin(fmax(x, -FAR), FAR);
    k->xy[2 * k->n + 1] = fmin(fmax(y, -FAR), FAR);
    k->n++;
    s->count++;
}

void strokes_segment(struct strokes *k, double x0, double y0, double x1, double y1,
                     uint8_t color, enum stroke_kind kind)
{
    const struct stroke *s = k->ns ? &k->s[k->ns - 1] : NULL;
    bool same = s && s->color == color && s->kind == kind && s->count > 0 &&
                s->start + s->count == k->n;
    if (kind == STROKE_DOTS) { /* dots: any number in one stroke */
        if (!same)
            strokes_begin(k, color, kind);
        strokes_point(k, x0, y0);
        if (x1 != x0 || y1 != y0)
            strokes_point(k, x1, y1);
        return;
    }
    if (!same || k->xy[2 * k->n - 2] != x0 || k->xy[2 * k->n - 1] != y0) {
        strokes_begin(k, color, kind);
        strokes_point(k, x0, y0);
    }
    strokes_point(k, x1, y1);
}

uint64_t strokes_hash(const struct strokes *k)
{
    uint64_t h = HASH_START;
    h = hash_bytes(h, &k->n, sizeof k->n);
    if (k->n)
        h = hash_bytes(h, k->xy, (size_t)k->n * 2 * sizeof *k->xy);
    for (int i = 0; i < k->ns; i++) {
        const struct stroke *s = &k->s[i];
        h = hash_bytes(h, &s->start, sizeof s->start);
        h = hash_bytes(h, &s->count, sizeof s->count);
        h = hash_bytes(h, &s->color, 4); /* colour, kind, size, shape */
    }
    return h;
}
