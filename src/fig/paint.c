/* paint.c: strokes in pixels. A dot's centre (x, y) in dot coordinates lands at
 * ((x + 0.5) cw / 2, (y + 0.5) ch / 4): the dots tile the cells as braille's do, so the
 * picture lines up with the axes the terminal drew in text. */
#include "paint.h"

#include <math.h>

#include "figure.h"

void fig_paint_strokes(cairo_t *cr, const struct strokes *k, double cw, double ch,
                       const struct fig_palette *pal)
{
    static const double dash[] = {6.0, 4.0};
    double sx = cw / 2.0, sy = ch / 4.0, lw = fmax(1.0, ch / 12.0);
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
        cairo_move_to(cr, (p[0] + 0.5) * sx, (p[1] + 0.5) * sy);
        for (int j = 1; j < s->count; j++)
            cairo_line_to(cr, (p[2 * j] + 0.5) * sx, (p[2 * j + 1] + 0.5) * sy);
        if (s->count == 1)
            cairo_line_to(cr, (p[0] + 0.5) * sx, (p[1] + 0.5) * sy);
        cairo_set_line_width(cr, lw);
        cairo_set_dash(cr, dash, s->kind == STROKE_DASHED ? 2 : 0, 0.0);
        cairo_stroke(cr);
    }
    cairo_restore(cr);
}
