/* figure.c: a page of panels drawn with cairo and written as PNG, SVG or PDF, sized for a
 * report: text of 8 to 10 points, the left margin as wide as the widest tick label needs,
 * the legend and the settings wrapped onto as many lines as they take. The axes' ticks
 * are axes.c's. */
#include "figure.h"

#include <cairo.h>
#include <errno.h>
#include <fontconfig/fontconfig.h>
#include <math.h>
#include <string.h>

#include "chart/axis.h"
#include "axes.h"
#include "surface.h"

#define FONT "DejaVu Sans"
#define TICK_PT 8.0    /* tick labels, the settings: the smallest text */
#define LABEL_PT 9.0   /* axis labels, legend */
#define TITLE_PT 10.0  /* the title, bold */
#define EDGE 12.0      /* the page's margins */
#define GAP_X 30.0     /* under a panel: its x tick labels and x label */
#define GAP_PANEL 12.0 /* between one panel's x label and the next panel */
#define LINE 1.3       /* a line of text is this many times its size */
#define MARKER_R 1.6   /* a measured point's marker radius */

static void set_color(cairo_t *cr, int c)
{
    double rgb[3];
    fig_rgb(c, false, rgb);
    cairo_set_source_rgb(cr, rgb[0], rgb[1], rgb[2]);
}

static double text_width(cairo_t *cr, const char *s)
{
    cairo_text_extents_t e;
    cairo_text_extents(cr, s, &e);
    return e.x_advance;
}

/* Text at (x, y), its anchor: align 0 left, 0.5 centre, 1 right; y is the baseline. */
static void text_at(cairo_t *cr, double x, double y, const char *s, double align)
{
    cairo_move_to(cr, x - align * text_width(cr, s), y);
    cairo_show_text(cr, s);
}

static void font(cairo_t *cr, double size, bool bold)
{
    cairo_select_font_face(cr, FONT, CAIRO_FONT_SLANT_NORMAL,
                           bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr, size);
}

/* The ticks of x: gridlines across the panel (other is the cross axis) and their labels;
 * on a log axis faint minor ticks at every digit of each decade. */
static void ticks(cairo_t *cr, const struct fig_axis *x, const struct fig_axis *other,
                  bool vertical)
{
    char buf[32];
    font(cr, TICK_PT, false);
    cairo_set_line_width(cr, 0.5);
    for (int k = 0; k < x->nt; k++) {
        double at = fig_axis_map(x, x->tv[k]);
        set_color(cr, FIG_GRID);
        if (vertical) {
            cairo_move_to(cr, other->a, at);
            cairo_line_to(cr, other->b, at);
        } else {
            cairo_move_to(cr, at, other->a);
            cairo_line_to(cr, at, other->b);
        }
        cairo_stroke(cr);
        fig_axis_label(x, x->tv[k], buf, sizeof buf);
        set_color(cr, FIG_WALL);
        if (vertical)
            text_at(cr, other->a - 4.0, at + 0.35 * TICK_PT, buf, 1.0);
        else
            text_at(cr, at, other->a + TICK_PT + 3.0, buf, 0.5);
    }
    for (double d = floor(x->lo + 1e-9); x->log && d < x->hi; d += 1.0)
        for (int m = 1; m <= 9; m++) {
            double lv = d + log10(m);
            if (lv < x->lo - 1e-9 || lv > x->hi + 1e-9)
                continue;
            double at = fig_axis_map(x, m * pow(10.0, d));
            set_color(cr, FIG_WALL);
            if (vertical) {
                cairo_move_to(cr, other->a, at);
                cairo_line_to(cr, other->a + (m == 1 ? 4.0 : 2.5), at);
            } else {
                cairo_move_to(cr, at, other->a);
                cairo_line_to(cr, at, other->a - (m == 1 ? 4.0 : 2.5));
            }
            cairo_stroke(cr);
        }
}

/* Point k of s on the page, or false where it cannot be drawn. */
static bool point(const struct fig_series *s, int k, const struct fig_axis *x,
                  const struct fig_axis *y, double *px, double *py, double *vy)
{
    double vx = s->x[(size_t)k * s->stride];
    *vy = s->y[(size_t)k * s->stride];
    if (!fig_axis_ok(x, vx) || !fig_axis_ok(y, *vy))
        return false;
    *px = fig_axis_map(x, vx), *py = fig_axis_map(y, *vy);
    return true;
}

/* One series: its line, broken where a point cannot be drawn or y jumps by more than
 * max_jump, then its markers (a point with no neighbour on its line gets one too, so a
 * run of one sample still shows). */
static void series(cairo_t *cr, const struct fig_series *s, const struct fig_axis *x,
                   const struct fig_axis *y)
{
    static const double dash[] = {5.0, 3.0};
    double px, py, vy, last = NAN;
    int run = 0; /* points in the line's current piece */
    set_color(cr, s->color);
    cairo_set_line_width(cr, 1.0);
    if (s->vline) {
        if (s->count > 0 && fig_axis_ok(x, s->x[0])) {
            cairo_move_to(cr, fig_axis_map(x, s->x[0]), y->a);
            cairo_line_to(cr, fig_axis_map(x, s->x[0]), y->b);
            cairo_stroke(cr);
        }
        return;
    }
    cairo_set_dash(cr, dash, s->dashed ? 2 : 0, 0.0);
    cairo_new_path(cr);
    for (int k = 0; !s->no_line && k < s->count; k++) {
        if (!point(s, k, x, y, &px, &py, &vy)) {
            run = 0;
            continue;
        }
        if (run > 0 && s->max_jump > 0.0 && fabs(vy - last) > s->max_jump)
            run = 0;
        if (run++ > 0)
            cairo_line_to(cr, px, py);
        else
            cairo_move_to(cr, px, py);
        last = vy;
    }
    cairo_stroke(cr);
    cairo_set_dash(cr, NULL, 0, 0.0);
    for (int k = 0; k < s->count; k++) {
        if (!point(s, k, x, y, &px, &py, &vy))
            continue;
        double qx, qy, qv;
        bool alone = !s->no_line && !s->markers &&
                     !(k > 0 && point(s, k - 1, x, y, &qx, &qy, &qv)) &&
                     !(k + 1 < s->count && point(s, k + 1, x, y, &qx, &qy, &qv));
        if (s->markers || s->no_line || alone) {
            cairo_new_sub_path(cr);
            cairo_arc(cr, px, py, MARKER_R, 0.0, 2.0 * M_PI);
        }
    }
    cairo_fill(cr);
}

/* The range of the series' x (which 0) or y (1) values that x can show. */
static void data_range(const struct fig_panel *p, int which, const struct fig_axis *x,
                       double *lo, double *hi)
{
    *lo = INFINITY, *hi = -INFINITY;
    for (int s = 0; s < p->nseries; s++) {
        const struct fig_series *sr = &p->series[s];
        const double *v = which ? sr->y : sr->x;
        if (sr->vline)
            continue;
        for (int k = 0; k < sr->count; k++) {
            double d = v[(size_t)k * sr->stride];
            if (fig_axis_ok(x, d))
                *lo = fmin(*lo, d), *hi = fmax(*hi, d);
        }
    }
}

/* The axes of panel p for a plot area w x h points. */
static void fit_axes(const struct fig_panel *p, double w, double h, struct fig_axis *x,
                     struct fig_axis *y)
{
    double lo, hi;
    x->log = p->xlog, y->log = p->ylog;
    if (p->xfixed) /* a run of no length: its one instant and a second after it */
        lo = p->xlo, hi = p->xhi > p->xlo ? p->xhi : p->xlo + 1.0;
    else
        data_range(p, 0, x, &lo, &hi);
    int nx = (int)fmax(2.0, w / 55.0), ny = (int)fmax(2.0, h / 18.0);
    if (p->xlog)
        fig_axis_log(x, lo, hi, 0.0, nx);
    else if (p->xexact && hi > lo)
        fig_axis_fixed(x, lo, hi, axis_step(lo, hi, nx));
    else
        fig_axis_linear(x, lo, hi, 0.0, nx, p->xwhole);
    if (p->ystep > 0.0) {
        fig_axis_fixed(y, p->ylo, p->yhi, p->ystep);
        return;
    }
    data_range(p, 1, y, &lo, &hi);
    if (p->ylog)
        fig_axis_log(y, lo, hi, lo > 0.0 ? 0.04 * fmax(log10(hi / lo), 0.5) : 0.0, ny);
    else
        fig_axis_linear(y, lo, hi, 0.02, ny, false);
}

/* The widest y tick label of panel p, in points. */
static double ylabel_width(cairo_t *cr, const struct fig_panel *p, double w, double h)
{
    struct fig_axis x, y;
    char buf[32];
    double most = 0.0;
    fit_axes(p, w, h, &x, &y);
    font(cr, TICK_PT, false);
    for (int k = 0; k < y.nt; k++) {
        fig_axis_label(&y, y.tv[k], buf, sizeof buf);
        most = fmax(most, text_width(cr, buf));
    }
    return most;
}

/* A cursor's text on the page: its ground's edges; x1 < x0 for a mark not shown. */
struct mark_box {
    double x0, y0, x1, y1;
};

/* A mark's dashed line across the panel (top to bottom) at page x at. */
static void mark_line(cairo_t *cr, double at, double top, double bottom)
{
    static const double dash[] = {2.0, 2.0};
    set_color(cr, FIG_WALL);
    cairo_set_line_width(cr, 0.8);
    cairo_set_dash(cr, dash, 2, 0.0);
    cairo_move_to(cr, at, top);
    cairo_line_to(cr, at, bottom);
    cairo_stroke(cr);
    cairo_set_dash(cr, NULL, 0, 0.0);
}

/* Mark m's lines of text in box b, on a white ground. */
static void mark_text(cairo_t *cr, const struct fig_mark *m, const struct mark_box *b)
{
    font(cr, TICK_PT, false);
    cairo_set_source_rgba(cr, 1.0, 1.0, 1.0, 0.85);
    cairo_rectangle(cr, b->x0, b->y0, b->x1 - b->x0, b->y1 - b->y0);
    cairo_fill(cr);
    for (int i = 0; i < m->nlines; i++) {
        set_color(cr, m->color[i]);
        text_at(cr, b->x0 + 1.0, b->y0 + (i + 1) * LINE * TICK_PT - 1.0, m->line[i], 0.0);
    }
}

/* Whether box b for mark k of n is free: inside the plot (x its axis, bottom its lower
 * edge), meeting none of the k boxes placed before it and, with lines, crossing none of
 * the other marks' lines at[]. */
static bool box_free(const struct mark_box *b, int k, int n, const struct mark_box *placed,
                     const double *at, const struct fig_axis *x, double bottom, bool lines)
{
    if (b->x0 < x->a || b->x1 > x->b || b->y1 > bottom)
        return false;
    for (int j = 0; j < n; j++) {
        const struct mark_box *o = &placed[j];
        if (j < k && o->x0 < b->x1 && b->x0 < o->x1 && o->y0 < b->y1 && b->y0 < o->y1)
            return false;
        if (lines && j != k && at[j] > b->x0 && at[j] < b->x1)
            return false;
    }
    return true;
}

/* A free place (box_free) for mark k of n's text, w x h points, into b: at the top, on
 * the side left says then the other, then a row lower, and so on; first crossing no other
 * mark's line, then crossing them if need be. False where none is free. */
static bool free_place(int k, int n, double w, double h, bool left, const double *at,
                       const struct mark_box *placed, const struct fig_axis *x, double top,
                       double bottom, struct mark_box *b)
{
    for (int pass = 0; pass < 2; pass++)
        for (int row = 0; top + 2.0 + row * (h + 2.0) + h <= bottom; row++)
            for (int side = 0; side < 2; side++) {
                bool l = side ? !left : left;
                b->x0 = l ? at[k] - 4.0 - w : at[k] + 2.0, b->x1 = b->x0 + w + 2.0;
                b->y0 = top + 2.0 + row * (h + 2.0), b->y1 = b->y0 + h;
                if (box_free(b, k, n, placed, at, x, bottom, pass == 0))
                    return true;
            }
    return false;
}

/* Where each of the n marks' text goes (box[k]): beside its line, at the top, right of it
 * or, past the middle, left of it; where that meets another mark's text or line or leaves
 * the plot, elsewhere (free_place); where nothing is free, the first place, kept inside
 * the plot. at[k]: each line's page x, NAN for a mark off the axis. */
static void place_marks(cairo_t *cr, const struct fig_mark *m, int n, const double *at,
                        const struct fig_axis *x, double top, double bottom, struct mark_box *box)
{
    font(cr, TICK_PT, false);
    for (int k = 0; k < n; k++) {
        double w = 0.0, h = m[k].nlines * LINE * TICK_PT + 2.0;
        box[k] = (struct mark_box){0.0, 0.0, -1.0, 0.0};
        if (isnan(at[k]))
            continue;
        for (int i = 0; i < m[k].nlines; i++)
            w = fmax(w, text_width(cr, m[k].line[i]));
        bool left = at[k] > 0.5 * (x->a + x->b);
        struct mark_box b;
        if (!free_place(k, n, w, h, left, at, box, x, top, bottom, &b)) {
            b.x0 = left ? at[k] - 4.0 - w : at[k] + 2.0;
            b.x0 = fmax(x->a, fmin(b.x0, x->b - w - 2.0));
            b.x1 = b.x0 + w + 2.0, b.y0 = top + 2.0, b.y1 = b.y0 + h;
        }
        box[k] = b;
    }
}

/* The marks of panel p across it (x its axis, top and bottom its edges): the dashed
 * lines, then each one's values beside it (place_marks). */
static void marks(cairo_t *cr, const struct fig_panel *p, const struct fig_axis *x, double top,
                  double bottom)
{
    enum { MAX = 8 };
    double at[MAX];
    struct mark_box box[MAX];
    int n = p->nmarks < MAX ? p->nmarks : MAX;
    for (int k = 0; k < n; k++) {
        at[k] = fig_axis_ok(x, p->marks[k].x) ? fig_axis_map(x, p->marks[k].x) : NAN;
        if (!isnan(at[k]))
            mark_line(cr, at[k], top, bottom);
    }
    place_marks(cr, p->marks, n, at, x, top, bottom, box);
    for (int k = 0; k < n; k++)
        if (box[k].x1 > box[k].x0)
            mark_text(cr, &p->marks[k], &box[k]);
}

/* Panel p in the box (left, top, width, height) of its plot area; margin: the room left of
 * it for the y label and tick labels. */
static void panel(cairo_t *cr, const struct fig_panel *p, double left, double top, double w,
                  double h, double margin)
{
    struct fig_axis x, y;
    fit_axes(p, w, h, &x, &y);
    x.a = left, x.b = left + w, y.a = top + h, y.b = top;
    ticks(cr, &y, &x, true);
    ticks(cr, &x, &y, false);
    cairo_save(cr);
    /* Lines end at the frame; a marker on it shows whole. */
    cairo_rectangle(cr, left - 2.0 * MARKER_R, top - 2.0 * MARKER_R, w + 4.0 * MARKER_R,
                    h + 4.0 * MARKER_R);
    cairo_clip(cr);
    for (int s = 0; s < p->nseries; s++)
        series(cr, &p->series[s], &x, &y);
    cairo_restore(cr);
    marks(cr, p, &x, top, top + h);
    set_color(cr, FIG_WALL);
    cairo_set_line_width(cr, 0.7);
    cairo_rectangle(cr, left, top, w, h);
    cairo_stroke(cr);
    font(cr, LABEL_PT, false);
    if (p->xlabel)
        text_at(cr, left + 0.5 * w, top + h + TICK_PT + LABEL_PT + 7.0, p->xlabel, 0.5);
    if (p->ylabel) {
        cairo_save(cr);
        cairo_translate(cr, left - margin + LABEL_PT, top + 0.5 * h);
        cairo_rotate(cr, -M_PI / 2.0);
        text_at(cr, 0.0, 0.0, p->ylabel, 0.5);
        cairo_restore(cr);
    }
}

/* The legend from x0 at baseline y, wrapped before right: a short stroke (a dot for
 * markers, upright for a line at one x) in each entry's colour, then its text. Draws only
 * when draw is true; returns the baseline after its last line. */
static double legend(cairo_t *cr, const struct fig_legend *lg, int nl, double x0, double right,
                     double y, bool draw)
{
    static const double dash[] = {3.0, 2.0};
    double x = x0;
    font(cr, LABEL_PT, false);
    for (int i = 0; i < nl; i++) {
        const struct fig_legend *e = &lg[i];
        double w = 20.0 + text_width(cr, e->text) + 12.0;
        if (x > x0 && x + w - 12.0 > right)
            x = x0, y += LINE * LABEL_PT; /* the next line */
        if (draw) {
            set_color(cr, e->color);
            cairo_set_line_width(cr, 1.6);
            cairo_set_dash(cr, dash, e->dashed ? 2 : 0, 0.0);
            if (e->dot) {
                cairo_arc(cr, x + 7.5, y - 0.33 * LABEL_PT, MARKER_R + 0.4, 0.0, 2.0 * M_PI);
                cairo_fill(cr);
            } else if (e->upright) {
                cairo_move_to(cr, x + 7.5, y - LABEL_PT);
                cairo_line_to(cr, x + 7.5, y + 0.2 * LABEL_PT);
                cairo_stroke(cr);
            } else {
                cairo_move_to(cr, x, y - 0.33 * LABEL_PT);
                cairo_line_to(cr, x + 15.0, y - 0.33 * LABEL_PT);
                cairo_stroke(cr);
            }
            cairo_set_dash(cr, NULL, 0, 0.0);
            set_color(cr, FIG_WALL);
            text_at(cr, x + 20.0, y, e->text, 0.0);
        }
        x += w;
    }
    return y + LINE * LABEL_PT;
}

/* text at baseline y from x0, wrapped at blanks before right; the baseline after it. */
static double wrapped(cairo_t *cr, const char *text, double x0, double right, double y,
                      double size)
{
    char line[512];
    size_t n = 0;
    const char *p = text;
    while (*p) {
        const char *word = p + strspn(p, " ");
        size_t wl = strcspn(word, " ");
        char trial[512];
        snprintf(trial, sizeof trial, "%.*s%s%.*s", (int)n, line, n ? " " : "", (int)wl, word);
        if (n && x0 + text_width(cr, trial) > right) {
            text_at(cr, x0, y, line, 0.0);
            y += LINE * size;
            n = (size_t)snprintf(line, sizeof line, "%.*s", (int)wl, word);
        } else {
            n = (size_t)snprintf(line, sizeof line, "%s", trial);
        }
        n = n < sizeof line ? n : sizeof line - 1;
        p = word + wl;
    }
    if (n)
        text_at(cr, x0, y, line, 0.0);
    return y + LINE * size;
}

static void draw_page(cairo_t *cr, const struct fig_page *pg)
{
    cairo_set_source_rgb(cr, 1.0, 1.0, 1.0);
    cairo_paint(cr);
    set_color(cr, FIG_WALL);
    double y = EDGE + TITLE_PT, right = pg->width - EDGE;
    font(cr, TITLE_PT, true);
    if (pg->title)
        y = wrapped(cr, pg->title, EDGE, right, y, TITLE_PT);
    font(cr, TICK_PT, false);
    if (pg->subtitle)
        y = wrapped(cr, pg->subtitle, EDGE, right, y - LINE * TITLE_PT + LINE * TICK_PT + 2.0,
                    TICK_PT);
    y = legend(cr, pg->legend, pg->nlegend, EDGE, right, y + 4.0, true) - LINE * LABEL_PT;
    double top = y + 10.0, under[8] = {0}, room = pg->height - top - EDGE;
    int np = pg->npanels < 8 ? pg->npanels : 8;
    /* Under each panel its x labels, its own legend's lines, and a gap to the next. */
    for (int i = 0; i < np; i++) {
        const struct fig_panel *p = &pg->panels[i];
        under[i] = GAP_X + (i + 1 < np ? GAP_PANEL : 0.0);
        under[i] += p->title ? LINE * LABEL_PT : 0.0;
        if (p->nlegend)
            under[i] += legend(cr, p->legend, p->nlegend, EDGE, right, 0.0, false);
        room -= under[i];
    }
    double ph = room / np, margin = 0.0;
    for (int i = 0; i < np; i++)
        margin = fmax(margin, ylabel_width(cr, &pg->panels[i], right - EDGE - 60.0, ph));
    margin += LABEL_PT * LINE + 8.0;
    for (int i = 0; i < np; i++) {
        const struct fig_panel *p = &pg->panels[i];
        if (p->title) {
            font(cr, LABEL_PT, true);
            set_color(cr, FIG_WALL);
            text_at(cr, EDGE + margin, top + LABEL_PT, p->title, 0.0);
            top += LINE * LABEL_PT;
        }
        panel(cr, p, EDGE + margin, top, right - EDGE - margin, ph, margin);
        if (p->nlegend)
            legend(cr, p->legend, p->nlegend, EDGE + margin, right, top + ph + GAP_X + LABEL_PT,
                   true);
        top += ph + under[i] - (p->title ? LINE * LABEL_PT : 0.0); /* its title is above */
    }
}

static void draw_page_of(cairo_t *cr, const void *page)
{
    draw_page(cr, page);
}

int fig_write(FILE *fp, enum fig_format f, const struct fig_page *page)
{
    return fig_surface_write(fp, f, page->width, page->height, FIG_PAGE_SCALE, page->title,
                             draw_page_of, page);
}

void fig_done(void)
{
    cairo_debug_reset_static_data();
    FcFini();
}
