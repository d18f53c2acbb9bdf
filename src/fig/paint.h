/* paint.h: a canvas's strokes (app/strokes.h) painted with cairo, anti-aliased, in the
 * masses' colours: the drawing area of a chart in pixels, for the terminal's images and
 * for the picture of a view that X saves. */
#ifndef SPRINGSIM_PAINT_H
#define SPRINGSIM_PAINT_H

#include <stdbool.h>

#include <cairo.h>

#include "../chart/strokes.h"
#include "figure.h"

/* Paints k with the drawing area's top left at the origin, a cell cw x ch units (dots
 * are half a cell across and a quarter down), in the colours of pal. */
void fig_paint_strokes(cairo_t *cr, const struct strokes *k, double cw, double ch,
                       const struct fig_palette *pal);

#endif
