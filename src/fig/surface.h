/* surface.h: one picture drawn with cairo and written to a stream as PNG (at a scale
 * given), SVG or PDF: what --figure and X share. */
#ifndef SPRINGSIM_SURFACE_H
#define SPRINGSIM_SURFACE_H

#include <cairo.h>
#include <stdio.h>

#include "figure.h"

/* Makes a w x h point surface of format f writing to fp (a PNG at scale pixels a point; a
 * PDF or SVG titled title, if not NULL: the PDF's metadata, the SVG's <title>), calls
 * draw(cr, arg) on it, and finishes it. Returns 0, or an errno value (ENOMEM, the write's
 * errno, EIO). */
int fig_surface_write(FILE *fp, enum fig_format f, double w, double h, double scale,
                      const char *title, void (*draw)(cairo_t *cr, const void *arg),
                      const void *arg);

#endif
