/* view_picture.c: the charts on the screen as one picture: each frame a rounded box with its
 * title on the top border, the y labels left of the axis, the x labels under it, dotted
 * gridlines on the tick rows and columns, the legend on the bottom border, and the
 * drawing area painted from its strokes. Cells are FIG_CELL_W x FIG_CELL_H points, and a
 * tick's gridline goes through the middle of its cell, where the terminal draws it. */
#include "view_picture.h"

#include <cairo.h>
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <string.h>

#include "paint.h"
#include "surface.h"

#define CW FIG_CELL_W
#define CH FIG_CELL_H
#define FONT "DejaVu Sans Mono"
#define TEXT_PT 11.0

static void rgb(cairo_t *cr, int c)
{
    double v[3];
    fig_rgb(c, false, v);
    cairo_set_source_rgb(cr, v[0], v[1], v[2]);
}

/* Text in cells from column x on row y (x may be fractional), on a white ground so a
 * border line under it is hidden; align 1 ends it at x. */
static void cell_text(cairo_t *cr, double x, int y, const char *s, int color, double align)
{
    cairo_text_extents_t e;
    cairo_text_extents(cr, s, &e);
    double px = x * CW - align * e.x_advance;
    cairo_set_source_rgb(cr, 1.0, 1.0, 1.0);
    cairo_rectangle(cr, px - 1.0, y * CH, e.x_advance + 2.0, CH);
    cairo_fill(cr);
    rgb(cr, color);
    cairo_move_to(cr, px, (y + 0.5) * CH + 0.35 * TEXT_PT);
    cairo_show_text(cr, s);
}

static void chart(cairo_t *cr, const struct fig_chart *c)
{
    /* The frame through the middle of its border cells. */
    rgb(cr, FIG_WALL);
    cairo_set_line_width(cr, 1.0);
    cairo_rectangle(cr, (c->x + 0.5) * CW, (c->y + 0.5) * CH, (c->w - 1) * CW, (c->h - 1) * CH);
    cairo_stroke(cr);
    double left = c->ax * CW, top = c->ay * CH, right = (c->ax + c->aw) * CW,
           bottom = (c->ay + c->ah) * CH;
    if (c->axes) {
        static const double dots[] = {1.0, 3.0};
        rgb(cr, FIG_GRID);
        cairo_set_line_width(cr, 0.8);
        cairo_set_dash(cr, dots, 2, 0.0);
        for (int k = 0; k < c->yt.n; k++) {
            double y = bottom - (c->yt.cell[k] + 0.5) * CH;
            cairo_move_to(cr, left, y);
            cairo_line_to(cr, right, y);
        }
        for (int k = 0; k < c->xt.n; k++) {
            double x = left + (c->xt.cell[k] + 0.5) * CW;
            cairo_move_to(cr, x, top);
            cairo_line_to(cr, x, bottom);
        }
        cairo_stroke(cr);
        cairo_set_dash(cr, NULL, 0, 0.0);
        rgb(cr, FIG_WALL);
        cairo_move_to(cr, left - 0.5 * CW, top);
        cairo_line_to(cr, left - 0.5 * CW, bottom + 0.5 * CH);
        cairo_line_to(cr, right, bottom + 0.5 * CH);
        cairo_stroke(cr);
        for (int k = 0; k < c->yt.n; k++)
            cell_text(cr, c->ax - 1, c->ay + c->ah - 1 - c->yt.cell[k], c->yt.label[k], FIG_WALL,
                      1.0);
        for (int k = 0; k < c->xt.n && c->ay + c->ah + 1 < c->y + c->h - 1; k++)
            cell_text(cr, c->ax + c->xt.cell[k] + 0.5, c->ay + c->ah + 1, c->xt.label[k],
                      FIG_WALL, 0.5);
        if (c->xunit[0] && c->ay + c->ah + 1 < c->y + c->h - 1)
            cell_text(cr, c->x + 2, c->ay + c->ah + 1, c->xunit, FIG_WALL, 0.0);
    }
    if (c->strokes) {
        cairo_save(cr);
        cairo_rectangle(cr, left, top, right - left, bottom - top);
        cairo_clip(cr);
        cairo_translate(cr, left, top);
        fig_paint_strokes(cr, c->strokes, CW, CH, false);
        cairo_restore(cr);
    }
    cell_text(cr, c->x + 2, c->y, c->title, FIG_TITLE, 0.0);
    double x = c->x + 2;
    for (int i = 0; i < c->nlegend; i++) {
        cell_text(cr, x, c->y + c->h - 1, c->legend[i], c->legend_color[i], 0.0);
        cairo_text_extents_t e;
        cairo_text_extents(cr, c->legend[i], &e);
        x += e.x_advance / CW + 1.0;
    }
}

/* The charts at their places, the top left one at the picture's corner. */
struct view_art {
    const struct fig_chart *c;
    int n, x0, y0;
};

static void draw_view(cairo_t *cr, const void *arg)
{
    const struct view_art *a = arg;
    cairo_set_source_rgb(cr, 1.0, 1.0, 1.0);
    cairo_paint(cr);
    cairo_translate(cr, -a->x0 * CW, -a->y0 * CH);
    cairo_select_font_face(cr, FONT, CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr, TEXT_PT);
    for (int i = 0; i < a->n; i++)
        chart(cr, &a->c[i]);
}

int fig_view_write(FILE *fp, enum fig_format f, const struct fig_chart *c, int n)
{
    int x0 = INT_MAX, y0 = INT_MAX, x1 = 0, y1 = 0;
    for (int i = 0; i < n; i++) {
        x0 = c[i].x < x0 ? c[i].x : x0, y0 = c[i].y < y0 ? c[i].y : y0;
        x1 = c[i].x + c[i].w > x1 ? c[i].x + c[i].w : x1;
        y1 = c[i].y + c[i].h > y1 ? c[i].y + c[i].h : y1;
    }
    if (n == 0)
        x0 = y0 = 0, x1 = y1 = 1;
    double w = (x1 - x0) * CW, h = (y1 - y0) * CH;
    struct view_art art = {c, n, x0, y0};
    return fig_surface_write(fp, f, w, h, FIG_PNG_SCALE, NULL, draw_view, &art);
}
