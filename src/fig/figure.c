/* figure.c: a page of panels drawn with cairo and written as PNG, SVG or PDF. Linear axes
 * take 1-2-5 ticks with their ends rounded outward (app/axis.c, as the terminal's charts
 * do); logarithmic axes a tick at every power of ten. */
#include "figure.h"

#include <cairo.h>
#include <errno.h>
#include <fontconfig/fontconfig.h>
#include <math.h>
#include <string.h>
#include <strings.h>

#include "app/axis.h"
#include "surface.h"

#define FONT "DejaVu Sans"
#define TICK_PT 9.0    /* tick labels */
#define LABEL_PT 10.5  /* axis labels, legend */
#define TITLE_PT 13.0
#define MARGIN_L 72.0  /* room for the y tick labels and the y label */
#define MARGIN_R 18.0
#define PANEL_GAP 40.0 /* under a panel: its x tick labels and x label */
#define LEGEND_Y 52.0  /* the legend's first baseline */
#define HEAD_H 76.0    /* title, settings and two lines of legend above the panels */

enum fig_format fig_format_of(const char *path)
{
    const char *dot = path ? strrchr(path, '.') : NULL;
    if (!dot || strchr(dot, '/'))
        return FIG_FORMAT_NONE;
    if (strcasecmp(dot, ".png") == 0)
        return FIG_PNG;
    if (strcasecmp(dot, ".svg") == 0)
        return FIG_SVG;
    if (strcasecmp(dot, ".pdf") == 0)
        return FIG_PDF;
    return FIG_FORMAT_NONE;
}

/* The terminal's 256-colour palette entries (tui/term.c) as red, green, blue: the 6x6x6
 * cube's levels 0, 95, 135, 175, 215, 255. Mid tones that read on black and on white. */
static const unsigned char mass_rgb[10][3] = {
    {0, 95, 255},  {0, 135, 0},   {215, 95, 0},  {215, 0, 0},   {175, 0, 215},
    {0, 135, 135}, {175, 135, 0}, {215, 0, 175}, {135, 95, 0},  {95, 95, 175},
};

void fig_rgb(int c, bool dark, double rgb[3])
{
    static const unsigned char motor[3] = {215, 0, 175}, spring[3] = {0, 135, 0},
                               title[3] = {0, 135, 215}, warn[3] = {215, 0, 0};
    const unsigned char *p = NULL;
    double grey = dark ? 0.85 : 0.1;
    if (c >= FIG_MASS && c < FIG_MASS + 10)
        p = mass_rgb[c - FIG_MASS];
    else if (c == FIG_MOTOR)
        p = motor;
    else if (c == FIG_SPRING)
        p = spring;
    else if (c == FIG_TITLE)
        p = title;
    else if (c == FIG_WARN)
        p = warn;
    else if (c == FIG_GRID)
        grey = dark ? 0.32 : 0.84;
    for (int i = 0; i < 3; i++)
        rgb[i] = p ? p[i] / 255.0 : grey;
}

static void set_color(cairo_t *cr, int c)
{
    double rgb[3];
    fig_rgb(c, false, rgb);
    cairo_set_source_rgb(cr, rgb[0], rgb[1], rgb[2]);
}

/* An axis of a panel: values lo..hi (log10 of them on a log axis) onto a..b. */
struct fig_axis {
    double lo, hi, step; /* range and tick step (log: in decades) */
    bool log;
    double a, b;         /* where lo and hi land on the page */
};

static double ax_map(const struct fig_axis *x, double v)
{
    if (x->log)
        v = log10(v);
    return x->a + (v - x->lo) / (x->hi - x->lo) * (x->b - x->a);
}

/* Whether v can be drawn on x. */
static bool ax_ok(const struct fig_axis *x, double v)
{
    return isfinite(v) && (!x->log || v > 0.0);
}

/* The range of the series' x (which 0) or y (1) values that x can show. */
static void data_range(const struct fig_panel *p, int which, const struct fig_axis *x,
                       double *lo, double *hi)
{
    *lo = INFINITY, *hi = -INFINITY;
    for (int s = 0; s < p->nseries; s++) {
        const struct fig_series *sr = &p->series[s];
        const double *v = which ? sr->y : sr->x;
        for (int k = 0; k < sr->count; k++) {
            double d = v[(size_t)k * sr->stride];
            if (ax_ok(x, d))
                *lo = fmin(*lo, d), *hi = fmax(*hi, d);
        }
    }
}

/* Fits x to [lo, hi]: decades rounded out on a log axis, else 1-2-5 ticks rounded out
 * with pad (a fraction of the span) added first. */
static void ax_fit(struct fig_axis *x, double lo, double hi, double pad, int max_ticks)
{
    if (!(lo <= hi)) /* no data */
        lo = x->log ? 0.1 : -1.0, hi = x->log ? 10.0 : 1.0;
    if (x->log) {
        /* Out to 1, 2 or 5 times a power of ten, ticks on the powers of ten. */
        static const double nice[] = {1.0, 2.0, 5.0, 10.0};
        double dl = floor(log10(lo) + 1e-9), dh = floor(log10(hi) - 1e-9);
        double ml = 1.0, mh = 10.0;
        for (int i = 2; i >= 0; i--)
            if (nice[i] * pow(10.0, dl) <= lo * (1.0 + 1e-9)) {
                ml = nice[i];
                break;
            }
        for (int i = 0; i < 4; i++)
            if (nice[i] * pow(10.0, dh) >= hi * (1.0 - 1e-9)) {
                mh = nice[i];
                break;
            }
        x->lo = dl + log10(ml);
        x->hi = dh + log10(mh);
        if (x->hi <= x->lo)
            x->hi = x->lo + 1.0;
        x->step = fmax(1.0, ceil((x->hi - x->lo) / max_ticks));
        return;
    }
    double span = hi - lo;
    if (span <= 1e-12 * fmax(1.0, fabs(hi)))
        span = fmax(fabs(hi), 1.0), lo -= 0.5 * span, hi += 0.5 * span;
    else
        lo -= pad * span, hi += pad * span;
    x->step = axis_step(lo, hi, max_ticks);
    axis_round_out(&lo, &hi, x->step);
    x->lo = lo, x->hi = hi;
}

/* Tick k's label: the value in plain decimals with the digits the step needs, or in
 * exponent form where that would be long. */
static void tick_label(const struct fig_axis *x, double v, char *buf, size_t len)
{
    if (x->log) {
        int e = (int)lround(v);
        if (e >= -4 && e <= 5)
            snprintf(buf, len, "%.*f", e < 0 ? -e : 0, pow(10.0, e));
        else
            snprintf(buf, len, "1e%d", e);
        return;
    }
    double big = fmax(fabs(x->lo), fabs(x->hi));
    int dec = (int)ceil(-log10(x->step) - 1e-9);
    if (fabs(v) < 0.5 * x->step)
        v = 0.0; /* no "-0" */
    if (big >= 1e5 || (big > 0.0 && dec > 4))
        snprintf(buf, len, "%.3g", v);
    else
        snprintf(buf, len, "%.*f", dec > 0 ? dec : 0, v);
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

/* The ticks of x: gridlines across the panel (other is the cross axis) and their labels. */
static void ticks(cairo_t *cr, const struct fig_axis *x, const struct fig_axis *other,
                  bool vertical)
{
    char buf[32];
    double first = x->log ? ceil(x->lo - 1e-9) : x->lo;
    double n = floor((x->hi - first) / x->step + 1e-9);
    font(cr, TICK_PT, false);
    for (int k = 0; k <= (int)n; k++) {
        double v = first + k * x->step;
        double at = x->a + (v - x->lo) / (x->hi - x->lo) * (x->b - x->a);
        set_color(cr, FIG_GRID);
        cairo_set_line_width(cr, 0.6);
        if (vertical) {
            cairo_move_to(cr, other->a, at);
            cairo_line_to(cr, other->b, at);
        } else {
            cairo_move_to(cr, at, other->a);
            cairo_line_to(cr, at, other->b);
        }
        cairo_stroke(cr);
        tick_label(x, v, buf, sizeof buf);
        set_color(cr, FIG_WALL);
        if (vertical)
            text_at(cr, other->a - 5.0, at + 0.35 * TICK_PT, buf, 1.0);
        else
            text_at(cr, at, other->a + TICK_PT + 4.0, buf, 0.5);
    }
    /* A log axis: faint minor ticks at 2..9 of every decade. */
    for (double d = floor(x->lo + 1e-9); x->log && d < x->hi; d += 1.0)
        for (int m = 2; m <= 9; m++) {
            double lv = d + log10(m);
            if (lv < x->lo - 1e-9 || lv > x->hi + 1e-9)
                continue;
            double at = ax_map(x, m * pow(10.0, d));
            set_color(cr, FIG_GRID);
            cairo_set_line_width(cr, 0.6);
            if (vertical) {
                cairo_move_to(cr, other->a, at);
                cairo_line_to(cr, other->a + 4.0, at);
            } else {
                cairo_move_to(cr, at, other->a);
                cairo_line_to(cr, at, other->a - 4.0);
            }
            cairo_stroke(cr);
        }
}

/* One series as one stroke: its line, broken where a point cannot be drawn, and its
 * markers. */
static void series(cairo_t *cr, const struct fig_series *s, const struct fig_axis *x,
                   const struct fig_axis *y)
{
    static const double dash[] = {6.0, 4.0};
    bool pen = false;
    cairo_new_path(cr);
    for (int k = 0; k < s->count; k++) {
        double vx = s->x[(size_t)k * s->stride], vy = s->y[(size_t)k * s->stride];
        if (!ax_ok(x, vx) || !ax_ok(y, vy)) {
            pen = false;
            continue;
        }
        double px = ax_map(x, vx), py = ax_map(y, vy);
        if (pen)
            cairo_line_to(cr, px, py);
        else
            cairo_move_to(cr, px, py);
        pen = true;
    }
    for (int k = 0; s->markers && k < s->count; k++) {
        double vx = s->x[(size_t)k * s->stride], vy = s->y[(size_t)k * s->stride];
        if (!ax_ok(x, vx) || !ax_ok(y, vy))
            continue;
        cairo_new_sub_path(cr);
        cairo_arc(cr, ax_map(x, vx), ax_map(y, vy), 2.5, 0.0, 2.0 * M_PI);
    }
    set_color(cr, s->color);
    cairo_set_line_width(cr, 1.3);
    cairo_set_dash(cr, dash, s->dashed ? 2 : 0, 0.0);
    cairo_stroke(cr);
    cairo_set_dash(cr, NULL, 0, 0.0);
}

/* Panel p in the box (left, top, width, height) of its plot area. */
static void panel(cairo_t *cr, const struct fig_panel *p, double left, double top, double w,
                  double h)
{
    struct fig_axis x = {.log = p->xlog, .a = left, .b = left + w};
    struct fig_axis y = {.log = p->ylog, .a = top + h, .b = top};
    double lo, hi;
    if (p->xfixed)
        lo = p->xlo, hi = p->xhi;
    else
        data_range(p, 0, &x, &lo, &hi);
    ax_fit(&x, lo, hi, 0.0, (int)fmax(2.0, w / 70.0));
    if (p->ystep > 0.0) {
        y.lo = p->ylo, y.hi = p->yhi, y.step = p->ystep;
    } else {
        data_range(p, 1, &y, &lo, &hi);
        ax_fit(&y, lo, hi, 0.05, (int)fmax(2.0, h / 35.0));
    }
    ticks(cr, &y, &x, true);
    ticks(cr, &x, &y, false);
    cairo_save(cr);
    cairo_rectangle(cr, left, top, w, h);
    cairo_clip(cr);
    for (int s = 0; s < p->nseries; s++)
        series(cr, &p->series[s], &x, &y);
    cairo_restore(cr);
    set_color(cr, FIG_WALL);
    cairo_set_line_width(cr, 0.8);
    cairo_rectangle(cr, left, top, w, h);
    cairo_stroke(cr);
    font(cr, LABEL_PT, false);
    if (p->xlabel)
        text_at(cr, left + 0.5 * w, top + h + TICK_PT + LABEL_PT + 10.0, p->xlabel, 0.5);
    if (p->ylabel) {
        cairo_save(cr);
        cairo_translate(cr, left - MARGIN_L + LABEL_PT + 4.0, top + 0.5 * h);
        cairo_rotate(cr, -M_PI / 2.0);
        text_at(cr, 0.0, 0.0, p->ylabel, 0.5);
        cairo_restore(cr);
    }
}

/* The legend along one line at baseline y: a short stroke in each entry's colour, then
 * its text; entries that do not fit are left out after an ellipsis. */
static void legend(cairo_t *cr, const struct fig_page *pg, double y)
{
    static const double dash[] = {4.0, 3.0};
    double x = MARGIN_L;
    font(cr, LABEL_PT, false);
    for (int i = 0; i < pg->nlegend; i++) {
        const struct fig_legend *e = &pg->legend[i];
        double w = 24.0 + text_width(cr, e->text) + 14.0;
        if (x + w > pg->width - MARGIN_R && y < LEGEND_Y + 1.0) {
            x = MARGIN_L, y += LABEL_PT + 5.0; /* a second line */
        } else if (x + w > pg->width - MARGIN_R) {
            set_color(cr, FIG_WALL);
            text_at(cr, x, y, "…", 0.0);
            break;
        }
        set_color(cr, e->color);
        cairo_set_line_width(cr, 2.0);
        cairo_set_dash(cr, dash, e->dashed ? 2 : 0, 0.0);
        cairo_move_to(cr, x, y - 0.35 * LABEL_PT);
        cairo_line_to(cr, x + 18.0, y - 0.35 * LABEL_PT);
        cairo_stroke(cr);
        cairo_set_dash(cr, NULL, 0, 0.0);
        set_color(cr, FIG_WALL);
        text_at(cr, x + 24.0, y, e->text, 0.0);
        x += w;
    }
}

static void draw_page(cairo_t *cr, const struct fig_page *pg)
{
    cairo_set_source_rgb(cr, 1.0, 1.0, 1.0);
    cairo_paint(cr);
    set_color(cr, FIG_WALL);
    font(cr, TITLE_PT, true);
    if (pg->title)
        text_at(cr, MARGIN_L, 20.0, pg->title, 0.0);
    font(cr, TICK_PT, false);
    if (pg->subtitle)
        text_at(cr, MARGIN_L, 34.0, pg->subtitle, 0.0);
    legend(cr, pg, LEGEND_Y);
    double ph = (pg->height - HEAD_H - 8.0) / pg->npanels - PANEL_GAP;
    for (int i = 0; i < pg->npanels; i++)
        panel(cr, &pg->panels[i], MARGIN_L, HEAD_H + 8.0 + i * (ph + PANEL_GAP),
              pg->width - MARGIN_L - MARGIN_R, ph);
}

static void draw_page_of(cairo_t *cr, const void *page)
{
    draw_page(cr, page);
}

int fig_write(FILE *fp, enum fig_format f, const struct fig_page *page)
{
    return fig_surface_write(fp, f, page->width, page->height, draw_page_of, page);
}

void fig_done(void)
{
    cairo_debug_reset_static_data();
    FcFini();
}
