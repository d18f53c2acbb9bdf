/* paint.c: strokes in pixels. A dot's centre (x, y) in dot coordinates lands at
 * ((x + 0.5) cw / 2, (y + 0.5) ch / 4): the dots tile the cells as braille's do, so the
 * picture lines up with the axes the terminal drew in text. */
#include "paint.h"

#include <math.h>

#include "figure.h"

/* Where points p[0..n) lie on a line across axis a (0: x, 1: y; scale: pixels a dot)
 * that spans less than a pixel: the middle of the pixel under their mean; else NAN. */
static double level(const double *p, int n, int a, double scale)
{
    double lo = INFINITY, hi = -INFINITY, sum = 0.0;
    for (int j = 0; j < n; j++) {
        double v = (p[2 * j + a] + 0.5) * scale;
        lo = fmin(lo, v), hi = fmax(hi, v), sum += v;
    }
    if (n < 2 || !(hi - lo < 1.0))
        return NAN;
    return floor(sum / n) + 0.5;
}

void fig_paint_strokes(cairo_t *cr, const struct strokes *k, double cw, double ch,
                       const struct fig_palette *pal)
{
    static const double dash[] = {6.0, 4.0};
    /* Lines a twelfth of a cell high, but no wider than a quarter of a cell: a terminal
     * that says its cells are 3 x 65535 pixels (drawn 1 x 124) had cairo stroke 10-pixel
     * lines in columns of one, 58 MB for one plot. */
    double sx = cw / 2.0, sy = ch / 4.0, lw = fmax(1.0, fmin(ch / 12.0, cw / 4.0));
    cairo_save(cr);
    cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
    cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
    for (int i = 0; i < k->ns; i++) {
        const struct stroke *s = &k->s[i];
        const double *p = k->xy + 2 * (size_t)s->start;
        if (s->count == 0)
            continue;
        const double *c = pal->rgb[s->color && s->color < FIG_COLOR_COUNT ? s->color : FIG_WALL];
        cairo_set_source_rgb(cr, c[0], c[1], c[2]);
        cairo_new_path(cr);
        if (s->kind == STROKE_DOTS || s->kind == STROKE_MARKS) {
            double r = s->kind == STROKE_MARKS ? 0.5 * (s->size ? s->size : 5) * fmin(sx, sy)
                                               : 1.2 * lw;
            for (int j = 0; j < s->count; j++) {
                double x = (p[2 * j] + 0.5) * sx, y = (p[2 * j + 1] + 0.5) * sy;
                cairo_new_sub_path(cr);
                if (s->kind == STROKE_MARKS && s->shape != MARK_DISC) {
                    /* a triangle as wide as the disc, its centroid on the point */
                    double d = s->shape == MARK_UP ? -1.0 : 1.0, h = 1.5 * r;
                    cairo_move_to(cr, x, y + d * h * 2.0 / 3.0);
                    cairo_line_to(cr, x - 0.866 * h, y - d * h / 3.0);
                    cairo_line_to(cr, x + 0.866 * h, y - d * h / 3.0);
                    cairo_close_path(cr);
                } else {
                    cairo_arc(cr, x, y, r, 0.0, 2.0 * M_PI);
                }
            }
            cairo_fill(cr);
            continue;
        }
        /* A line upright or level to within a pixel (the drive's frequency, a constant)
         * on the middle of one column or row of pixels: on a boundary between two it
         * would be two paler ones, not the colour of its legend's mark. */
        double snap_x = level(p, s->count, 0, sx), snap_y = level(p, s->count, 1, sy);
        int n = s->count > 1 ? s->count : 2; /* a lone point: a line to itself, a dot */
        for (int j = 0; j < n; j++) {
            const double *q = p + 2 * (j < s->count ? j : 0);
            double x = isnan(snap_x) ? (q[0] + 0.5) * sx : snap_x;
            double y = isnan(snap_y) ? (q[1] + 0.5) * sy : snap_y;
            if (j == 0)
                cairo_move_to(cr, x, y);
            else
                cairo_line_to(cr, x, y);
        }
        cairo_set_line_width(cr, lw);
        cairo_set_dash(cr, dash, s->kind == STROKE_DASHED ? 2 : 0, 0.0);
        cairo_stroke(cr);
    }
    cairo_restore(cr);
}
