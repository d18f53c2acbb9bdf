/* chart.c: the chart widget. Gridlines sit on whole rows evenly spaced (the axis maths
 * in src/app/axis.c decides where), tick labels are never cut, and a refresh is the only
 * time the data is looked at: frames in between redraw the canvas as it was left. */
#include "chart.h"

#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "draw.h"
#include "term.h"

#define MIN_ROW_GAP 2 /* rows between y gridlines, at least */

static bool pixels;     /* the drawing areas are images: leave them blank */
static bool for_figure; /* a report figure is being made of the charts */

/* The charts' strokes are recorded only when something reads them: the images, or X's
 * figure (braille alone never does). */
static void record_follow(void)
{
    canvas_record(pixels || for_figure);
}

void chart_keep_for_figure(bool on)
{
    for_figure = on;
    record_follow();
}

void chart_use_pixels(bool on)
{
    pixels = on;
    record_follow();
}

bool chart_pixels(void)
{
    return pixels;
}

bool chart_place(struct chart *c, struct rect frame, int header_rows)
{
    struct rect a = layout_drawing(frame);
    a.y += header_rows;
    a.h -= header_rows;
    if (a.h < 0)
        a.h = 0;
    c->frame = frame;
    c->area = a;
    c->xs.set = c->ys.set = false;
    if (c->canvas && c->canvas->cols == a.w && c->canvas->rows == a.h) {
        canvas_clear(c->canvas);
    } else {
        canvas_free(c->canvas);
        c->canvas = a.w > 0 && a.h > 0 ? canvas_new(a.w, a.h) : NULL;
        /* Its strokes too, for pixels; without memory for them the braille still shows. */
        if (c->canvas)
            canvas_keep_strokes(c->canvas);
    }
    c->drawn = false;
    chart_fit_y(c, -1.0, 1.0);
    c->ys.set = false; /* the first real data fits at once */
    chart_fit_x(c, -1.0, 1.0);
    c->xs.set = false;
    return c->canvas != NULL;
}

void chart_free(struct chart *c)
{
    canvas_free(c->canvas);
    c->canvas = NULL;
}

/* True when axes a and b place and label the same ticks. */
static bool same_axis(const struct axis *a, const struct axis *b)
{
    return a->lo == b->lo && a->step == b->step && a->intervals == b->intervals &&
           a->first == b->first && a->spacing == b->spacing && a->cells == b->cells;
}

void chart_ticks_from_axis(struct chart_ticks *t, const struct axis *a)
{
    /* Most refreshes lay an axis as the last one did: its labels are the same. */
    if (t->kept && same_axis(&t->of, a))
        return;
    t->kept = true;
    t->of = *a;
    t->n = 0;
    for (int k = 0; k <= a->intervals && t->n < CHART_MAX_TICKS; k++) {
        int cell = a->first + k * a->spacing;
        if (cell < 0 || cell >= a->cells)
            continue;
        t->cell[t->n] = cell;
        axis_label(a, k, t->label[t->n], sizeof t->label[t->n]);
        t->n++;
    }
}

/* Intervals an axis of `cells` cells may have, at most. */
static int max_ticks(int cells, int per_tick)
{
    int n = cells / per_tick;
    return n < 2 ? 2 : n > 8 ? 8 : n;
}

/* Fits scale s to data in [lo, hi]: it grows at once and shrinks after 30 refreshes of
 * data that would fit in half of it, counted only while the data moves, so that a paused
 * plot keeps its scale however often a key redraws it. */
static void scale_fit(const struct chart *c, struct scale *s, double lo, double hi, int ticks)
{
    int quiet = s->quiet;
    plot_scale_update(s, lo, hi, ticks, c->still ? INT_MAX : 30);
    if (c->still && s->quiet > quiet)
        s->quiet = quiet;
}

/* Fits the y scale and axis to [lo, hi]; inside: the scale rounded out to half the ticks'
 * step or finer and the ticks laid inside it, so a plot a few rows high shows its data,
 * not a step's rounding (a 0.5 m decay on 6 rows: -0.875 .. 0.625, not -1.25 .. 1.75). */
static void fit_y(struct chart *c, double lo, double hi, bool inside)
{
    int h = c->area.h > 1 ? c->area.h : 1;
    int ticks = max_ticks(h, 2);
    scale_fit(c, &c->ys, lo, hi, inside ? 2 * ticks : ticks);
    if (inside)
        axis_fit_inside(&c->ya, c->ys.lo, c->ys.hi, ticks, h, 4, MIN_ROW_GAP);
    else
        axis_fit(&c->ya, c->ys.lo, c->ys.hi, ticks, h, 4, MIN_ROW_GAP);
    chart_ticks_from_axis(&c->yt, &c->ya);
}

void chart_fit_y(struct chart *c, double lo, double hi)
{
    fit_y(c, lo, hi, false);
}

void chart_fit_y_inside(struct chart *c, double lo, double hi)
{
    fit_y(c, lo, hi, true);
}

/* Fits axis a on the x cells, its ticks far enough apart for their labels; rolling: a
 * time axis of window hi ending at lo. */
static void fit_x(struct chart *c, double lo, double hi, bool rolling)
{
    int w = c->area.w > 1 ? c->area.w : 1;
    int ticks = max_ticks(w, 8), gap = 4;
    for (int tries = 0; tries < 4; tries++) {
        if (rolling)
            axis_fit_rolling(&c->xa, lo, hi, ticks, w, 2, gap);
        else
            axis_fit(&c->xa, lo, hi, ticks, w, 2, gap);
        int need = axis_label_width(&c->xa) + 1;
        if (c->xa.spacing >= need)
            break;
        gap = need;
    }
    chart_ticks_from_axis(&c->xt, &c->xa);
}

void chart_fit_x(struct chart *c, double lo, double hi)
{
    int w = c->area.w > 1 ? c->area.w : 1;
    scale_fit(c, &c->xs, lo, hi, max_ticks(w, 8));
    fit_x(c, c->xs.lo, c->xs.hi, false);
}

void chart_fit_time(struct chart *c, double end, double window)
{
    fit_x(c, end, window, true);
}

double chart_left_time(const struct chart *c)
{
    return axis_value(&c->xa, -0.5);
}

void chart_fix_x(struct chart *c, double lo, double hi)
{
    fit_x(c, lo, hi, false);
}

void chart_fix_y(struct chart *c, double lo, double hi)
{
    int h = c->area.h > 1 ? c->area.h : 1;
    axis_fit(&c->ya, lo, hi, max_ticks(h, 2), h, 4, MIN_ROW_GAP);
    chart_ticks_from_axis(&c->yt, &c->ya);
}

int chart_dot_y(const struct chart *c, double v)
{
    return 4 * c->area.h - 1 - (int)lround(axis_dot(&c->ya, v));
}

double chart_dot_yf(const struct chart *c, double v)
{
    return 4 * c->area.h - 1 - axis_dot(&c->ya, v);
}

/* True when tick k of axis a is the value 0. */
static bool is_zero(const struct axis *a, int cell)
{
    if (a->spacing <= 0 || (cell - a->first) % a->spacing != 0)
        return false;
    double v = a->lo + (double)((cell - a->first) / a->spacing) * a->step;
    return fabs(v) < 1e-9 * a->step;
}

/* A gridline of w cells from (row, x) in the attributes set: solid for zero, else a dot
 * every other cell. One wide character made once, not a string decoded per dot. */
static void gridline(int row, int x, int w, bool zero)
{
    if (!term_utf8()) {
        for (int col = 0; col < w; col += zero ? 1 : 2)
            mvaddch(row, x + col, (chtype)(zero ? '-' : '.'));
        return;
    }
    cchar_t cc;
    wchar_t wc[2] = {zero ? L'\u2500' : L'\u00b7', 0}; /* ─ and · */
    setcchar(&cc, wc, A_NORMAL, 0, NULL);
    for (int col = 0; col < w; col += zero ? 1 : 2)
        mvadd_wch(row, x + col, &cc);
}

static void draw_axes(const struct chart *c, const char *xunit)
{
    struct rect a = c->area, f = c->frame;
    int axis = a.x - 1;
    mvvline(a.y, axis, draw_line(L_V), a.h);
    /* Gridlines under the data, then the y labels. */
    for (int k = 0; k < c->yt.n; k++) {
        int row = a.y + a.h - 1 - c->yt.cell[k];
        bool zero = c->zero_line && is_zero(&c->ya, c->yt.cell[k]);
        attron(term_attr(PAIR_GRID));
        if (!pixels)
            gridline(row, a.x, a.w, zero);
        attroff(term_attr(PAIR_GRID));
        int len = draw_width(c->yt.label[k]);
        draw_text(row, axis - len, len, c->yt.label[k]);
        mvaddch(row, axis, draw_line(L_RTEE));
    }
    int ay = a.y + a.h;
    if (ay >= f.y + f.h - 1)
        return;
    mvaddch(ay, axis, draw_line(L_LL));
    mvhline(ay, a.x, draw_line(L_H), a.w);
    int free_from = f.x + 1;
    if (xunit) {
        draw_text(ay + 1, f.x + 2, a.x - f.x - 3, xunit);
        free_from = f.x + 3 + draw_width(xunit);
    }
    int right = f.x + f.w - 1; /* first column a label may not use */
    for (int k = 0; k < c->xt.n; k++) {
        int col = a.x + c->xt.cell[k];
        mvaddch(ay, col, draw_line(L_TTEE));
        int len = draw_width(c->xt.label[k]);
        int lx = col - len / 2;
        if (lx + len > right)
            lx = right - len;
        if (lx < free_from || ay + 1 >= f.y + f.h - 1)
            continue;
        draw_text(ay + 1, lx, len, c->xt.label[k]);
        free_from = lx + len + 1;
    }
}

/* Whether legend item l is a mass's (the ones left out, with "…", when not all fit). */
static bool is_mass(const struct legend_item *l)
{
    return l->pair >= PAIR_MASS && l->pair < PAIR_MASS + 10;
}

/* The legend on the bottom border, between its corners with a border column kept at
 * each end: every entry a border column apart; if that is too wide, the masses' side by
 * side (each in its own colour); if that is too wide, the masses that fit, "…", and the
 * rest (the motor, the ghost), so nothing is dropped unsaid; an entry that still does
 * not fit is "…". */
static void draw_legend(struct chart *c, const struct legend_item *legend, int nlegend)
{
    struct rect f = c->frame;
    int room = f.w - 4, y = f.y + f.h - 1, right = f.x + f.w - 2;
    int len[12], loose = 0, tight = 0, kept = 0, nmass = 0;
    nlegend = nlegend < 12 ? nlegend : 12;
    for (int i = 0; i < nlegend; i++)
        nmass += is_mass(&legend[i]);
    for (int i = 0; i < nlegend; i++) {
        len[i] = draw_width(legend[i].text);
        bool glued = i > 0 && is_mass(&legend[i]) && is_mass(&legend[i - 1]);
        loose += len[i] + (i > 0);
        tight += len[i] + (i > 0 && !glued);
        kept += is_mass(&legend[i]) ? 0 : len[i] + 1;
    }
    bool glue = loose > room, cut = tight > room && nmass > 1; /* a list of masses */
    const char *ell = term_utf8() ? "…" : "...";
    int ew = draw_width(ell);
    int masses = room - kept - ew; /* the masses' columns when cut */
    bool said = false;
    int x = f.x + 2;
    c->nlegend = 0;
    for (int i = 0; i < nlegend; i++) {
        bool mass = is_mass(&legend[i]);
        if (i > 0 && !(glue && mass && is_mass(&legend[i - 1])))
            x++; /* a border column between */
        if (cut && mass && len[i] > masses) {
            if (!said && x + ew <= right)
                x += draw_text(y, x, ew, ell);
            said = true;
            masses = -1;
            continue;
        }
        if (cut && mass)
            masses -= len[i];
        if (x + len[i] > right) { /* still too wide: say so and stop */
            if (!said && x - 1 + ew <= right)
                draw_text(y, x - 1 + (x - 1 + ew <= right - 1), ew, ell);
            break;
        }
        draw_text_attr(y, x, len[i], term_attr(legend[i].pair) | A_BOLD, legend[i].text);
        snprintf(c->legend[c->nlegend], sizeof c->legend[0], "%s", legend[i].text);
        c->legend_pair[c->nlegend++] = legend[i].pair;
        x += len[i];
    }
}

void chart_draw(struct chart *c, const char *title, const char *short_title,
                const char *xunit, const struct legend_item *legend, int nlegend)
{
    struct rect f = c->frame;
    bool fits = draw_width(title) + 4 <= f.w || !short_title;
    draw_frame(f, fits ? title : short_title, true);
    snprintf(c->title, sizeof c->title, "%s", fits ? title : short_title);
    snprintf(c->xunit, sizeof c->xunit, "%s", xunit ? xunit : "");
    c->drawn = c->canvas && c->area.w >= 2 && c->area.h >= 1;
    if (c->drawn) {
        draw_axes(c, xunit);
        if (!pixels)
            draw_canvas(c->canvas, c->area.y, c->area.x);
    }
    draw_legend(c, legend, nlegend);
}

/* Ticks t as a picture's. */
static void picture_ticks(const struct chart_ticks *t, struct fig_ticks *out)
{
    out->n = t->n < FIG_VIEW_TICKS ? t->n : FIG_VIEW_TICKS;
    for (int k = 0; k < out->n; k++) {
        out->cell[k] = t->cell[k];
        snprintf(out->label[k], sizeof out->label[k], "%s", t->label[k]);
    }
}

void chart_report(struct chart *c, const char *title, const char *xlabel, const char *ylabel)
{
    struct fig_report *r = &c->report;
    memset(r, 0, sizeof *r);
    snprintf(r->title, sizeof r->title, "%s", title);
    snprintf(r->xlabel, sizeof r->xlabel, "%s", xlabel);
    snprintf(r->ylabel, sizeof r->ylabel, "%s", ylabel);
}

void chart_picture(const struct chart *c, struct fig_chart *out)
{
    memset(out, 0, sizeof *out);
    out->x = c->frame.x, out->y = c->frame.y, out->w = c->frame.w, out->h = c->frame.h;
    out->ax = c->area.x, out->ay = c->area.y, out->aw = c->area.w, out->ah = c->area.h;
    snprintf(out->title, sizeof out->title, "%s", c->title);
    snprintf(out->xunit, sizeof out->xunit, "%s", c->xunit);
    out->axes = c->drawn;
    if (c->drawn) {
        picture_ticks(&c->xt, &out->xt);
        picture_ticks(&c->yt, &out->yt);
        out->strokes = c->canvas->strokes;
        out->xa = c->xa, out->ya = c->ya;
        out->report = c->report.title[0] ? &c->report : NULL;
    }
    out->nlegend = c->nlegend < FIG_VIEW_LEGEND ? c->nlegend : FIG_VIEW_LEGEND;
    for (int i = 0; i < out->nlegend; i++) {
        snprintf(out->legend[i], sizeof out->legend[i], "%s", c->legend[i]);
        out->legend_color[i] = c->legend_pair[i];
    }
}

const double *chart_window(const struct trail *tr, double t0, int *count)
{
    const double *first = trail_first(tr);
    int lo = 0, hi = tr->count; /* the first record at or after t0 is in [lo, hi] */
    while (lo < hi) {
        int mid = lo + (hi - lo) / 2;
        if (first[(size_t)mid * tr->width + TRAIL_T] < t0)
            lo = mid + 1;
        else
            hi = mid;
    }
    *count = tr->count - lo;
    return first + (size_t)lo * tr->width;
}
