/* plots.c: the live plots. A refresh scans the samples inside the time window once,
 * fits the axes to them and rasterises the traces; frames in between redraw what the
 * last refresh left. */
#include "plots.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../app/ghost.h"
#include "../app/scope.h"
#include "draw.h"
#include "term.h"

/* What each plot shows: quantity on x (0 time, 1 x, 2 v, 3 a) and on y. */
static const struct {
    int xq, yq;
    const char *title, *short_title;
} kinds[PLOT_COUNT] = {
    [PLOT_X] = {0, 1, "1 Displacement (m)", "1 x (m)"},
    [PLOT_V] = {0, 2, "2 Velocity (m/s)", "2 v (m/s)"},
    [PLOT_A] = {0, 3, "3 Acceleration (m/s²)", "3 a (m/s²)"},
    [PLOT_XV] = {1, 2, "4 x–v (m, m/s)", "4 x–v"},
    [PLOT_XA] = {1, 3, "5 x–a (m, m/s²)", "5 x–a"},
    [PLOT_VA] = {2, 3, "6 v–a (m/s, m/s²)", "6 v–a"},
};

static const char *const mass_keys[10] = {"━1", "━2", "━3", "━4", "━5",
                                          "━6", "━7", "━8", "━9", "━10"};

const char *plots_title(enum plot_id id, bool short_form)
{
    return short_form ? kinds[id].short_title : kinds[id].title;
}

bool plots_place(struct plots *p, const struct layout *l)
{
    bool ok = true;
    for (int k = 0; k < l->nplots; k++) {
        struct chart *c = &p->chart[l->plot_id[k]];
        ok &= chart_place(c, l->plot[k], 0);
        c->zero_line = true;
    }
    return ok;
}

void plots_refit(struct plots *p)
{
    for (int i = 0; i < PLOT_COUNT; i++)
        p->chart[i].xs.set = p->chart[i].ys.set = false;
}

void plots_free(struct plots *p)
{
    for (int i = 0; i < PLOT_COUNT; i++)
        chart_free(&p->chart[i]);
    if (p->kept)
        delwin(p->kept);
    p->kept = NULL;
    p->kept_ok = false;
}

/* Offset of quantity q (1 x, 2 v, 3 a) of mass i in a trail record. */
static int field(const struct trail *tr, int q, int i)
{
    return q == 1 ? TRAIL_X(tr, i) : q == 2 ? TRAIL_V(tr, i) : TRAIL_A(tr, i);
}

/* fmin(lo, v) and fmax(hi, v) for a lo and hi that are never NaN, as glibc answers them
 * (a NaN v leaves them), without a call to libm for each sample. */
static double least(double lo, double v)
{
    return lo < v || v != v ? lo : v;
}

static double most(double hi, double v)
{
    return hi > v || v != v ? hi : v;
}

/* The range of quantity q (0: none) over k records of tr from rec, into [*lo, *hi]. */
static void scan(const struct trail *tr, const double *rec, int k, int q, unsigned hidden,
                 double *lo, double *hi)
{
    if (!q)
        return;
    double l = *lo, h = *hi;
    int off = field(tr, q, 0); /* a quantity's masses are side by side in a record */
    for (int s = 0; s < k; s++) {
        const double *r = rec + (size_t)s * (size_t)tr->width + off;
        for (int i = 0; i < tr->n; i++)
            if (!(hidden >> i & 1u))
                l = least(l, r[i]), h = most(h, r[i]);
    }
    *lo = l, *hi = h;
}

/* Each mass's trace from k records of tr from rec, in its colour: solid, or dashed (the
 * ghost's). */
static void traces(struct chart *c, enum plot_id id, const struct trail *tr, const double *rec,
                   int k, bool dashed, unsigned hidden, int top)
{
    int xq = kinds[id].xq, yq = kinds[id].yq;
    size_t w = (size_t)tr->width;
    /* Mass 1 over the others, or the one selected in the chain over all; hidden ones not
     * at all. */
    int order[APP_MAX_MASSES], n = 0;
    for (int i = tr->n - 1; i >= 0 && n < APP_MAX_MASSES; i--)
        if (i != top)
            order[n++] = i;
    if (top >= 0 && top < tr->n && n < APP_MAX_MASSES)
        order[n++] = top;
    for (int o = 0; o < n; o++) {
        int i = order[o];
        if (hidden >> i & 1u)
            continue;
        unsigned char col = (unsigned char)(PAIR_MASS + i % 10);
        const double *y = rec + field(tr, yq, i);
        if (xq == 0)
            plot_trace(c->canvas, rec + TRAIL_T, y, k, w, 0.0, &c->xa, &c->ya, dashed, col);
        else if (dashed)
            plot_dashed_path(c->canvas, rec + field(tr, xq, i), y, k, w, &c->xa, &c->ya, col);
        else
            plot_path(c->canvas, rec + field(tr, xq, i), y, k, w, &c->xa, &c->ya, col);
    }
}

/* How many of the k records from rec are at or before t. */
static int up_to(const struct trail *tr, const double *rec, int k, double t)
{
    while (k > 0 && rec[(size_t)(k - 1) * tr->width + TRAIL_T] > t + 1e-9)
        k--;
    return k;
}

/* The cursors on a time plot: a dotted vertical line of dots at each one's sample,
 * drawn under the traces. */
static void cursor_lines(struct chart *c, const struct app *app, const struct scope_view *v)
{
    int h = 4 * c->canvas->rows;
    for (int k = 0; k < app->scope.cursors; k++) {
        const double *r = scope_record(app, v, k);
        if (!r)
            continue;
        int x = (int)floor(axis_dot(&c->xa, r[TRAIL_T]) + 0.5);
        for (int y = k; y < h; y += 2)
            canvas_set(c->canvas, x, y, PAIR_TITLE);
    }
}

/* Takes the samples of the window shown (the present, or paused, scrolled back): fits
 * the axes to the live chain's and the ghost's, and rasterises the ghost's dashed under
 * the live chain's. */
static void take_samples(struct chart *c, enum plot_id id, const struct app *app, int *end_row,
                         int *end_col, unsigned hidden, int top)
{
    for (int i = 0; i < 10; i++)
        end_row[i] = end_col[i] = -1;
    struct scope_view v;
    scope_view(app, &v);
    const struct trail *tr = v.trail, *gt = NULL;
    if (app->ghost)
        gt = tr == app->trail ? app->ghost->trail : app->ghost->coarse;
    const struct model *m = app->model;
    int xq = kinds[id].xq, yq = kinds[id].yq;
    bool motor = id == PLOT_X && m->boundary == BOUNDARY_MOTOR;
    double end = v.end, window = v.window;
    if (xq == 0)
        chart_fit_time(c, end, window);
    int k, gk = 0;
    /* A time plot shows what its axis spans (a little more than the window); a phase
     * portrait, the window. */
    double t0 = xq == 0 ? chart_left_time(c) - 1e-9 : end - window;
    const double *rec = chart_window(tr, t0, &k), *grec = gt ? chart_window(gt, t0, &gk) : NULL;
    k = up_to(tr, rec, k, end);
    if (gt)
        gk = up_to(gt, grec, gk, end);
    size_t w = (size_t)tr->width;
    double ylo = INFINITY, yhi = -INFINITY, xlo = INFINITY, xhi = -INFINITY;
    scan(tr, rec, k, yq, hidden, &ylo, &yhi);
    scan(tr, rec, k, xq, hidden, &xlo, &xhi);
    if (gt) {
        scan(gt, grec, gk, yq, hidden, &ylo, &yhi);
        scan(gt, grec, gk, xq, hidden, &xlo, &xhi);
    }
    for (int s = 0; motor && s < k; s++)
        ylo = least(ylo, rec[s * w + TRAIL_U]), yhi = most(yhi, rec[s * w + TRAIL_U]);
    c->still = !app->running;
    if (k > 0) {
        if (xq)
            chart_fit_y(c, ylo, yhi);
        else
            chart_fit_y_inside(c, ylo, yhi);
        if (xq)
            chart_fit_x(c, xlo, xhi);
    }
    if (!c->canvas)
        return;
    canvas_clear(c->canvas);
    if (xq == 0)
        cursor_lines(c, app, &v);
    /* The drive's dashed line first: where a mass moves with it (the mass next to the
     * motor, often), the mass's colour is the one seen. */
    if (motor)
        plot_trace(c->canvas, rec + TRAIL_T, rec + TRAIL_U, k, w, 0.0, &c->xa, &c->ya, true,
                   PAIR_MOTOR);
    if (gt)
        traces(c, id, gt, grec, gk, true, hidden, top);
    traces(c, id, tr, rec, k, false, hidden, top);
    /* Where each curve ends: the newest sample's cell. */
    int h = 4 * c->canvas->rows;
    const double *last = k > 0 ? rec + (size_t)(k - 1) * w : NULL;
    for (int i = 0; i < 10 && last && i < tr->n; i++) {
        double dx = xq == 0 ? axis_dot(&c->xa, last[TRAIL_T])
                            : axis_dot(&c->xa, last[field(tr, xq, i)]);
        double dy = h - 1 - axis_dot(&c->ya, last[field(tr, yq, i)]);
        if (dx > -0.5 && dx < 2 * c->canvas->cols - 0.5 && dy > -0.5 && dy < h - 0.5) {
            end_col[i] = (int)floor(dx + 0.5) / 2;
            end_row[i] = (int)floor(dy + 0.5) / 4;
        }
    }
}

/* Each mass's digit where its curve ends, in its colour: what tells the curves apart
 * where the colours cannot (none, or 8 colours past five masses). */
static void end_marks(const struct chart *c, const int *end_row, const int *end_col, int n,
                      unsigned hidden)
{
    if (!c->drawn || n <= term_hues())
        return;
    /* Two ends in one cell: the later mass's digit goes to the nearest free row. */
    int taken_row[10], taken_col[10], taken = 0;
    for (int i = 0; i < n && i < 10; i++) {
        if (end_row[i] < 0 || (hidden >> i & 1u))
            continue;
        char digit[12];
        snprintf(digit, sizeof digit, "%d", i + 1);
        int len = (int)strlen(digit), col = end_col[i] - (len - 1);
        if (col < 0)
            col = 0;
        int row = -1;
        for (int d = 0; d < c->area.h && row < 0; d++)
            for (int s = d ? -1 : 1; s <= 1 && row < 0; s += 2) {
                int r = end_row[i] + s * d;
                bool free = r >= 0 && r < c->area.h;
                for (int k = 0; k < taken && free; k++)
                    free = !(taken_row[k] == r && abs(taken_col[k] - col) < 2);
                if (free)
                    row = r;
            }
        if (row < 0)
            continue;
        taken_row[taken] = row;
        taken_col[taken++] = col;
        draw_text_attr(c->area.y + row, c->area.x + col, len,
                       term_mass_attr(i) | A_BOLD | A_REVERSE, digit);
    }
}

/* The cursors on a phase portrait: each mass's point at each cursor's sample, a mark in
 * its colour (● the first cursor, ◆ the second). */
static void cursor_points(const struct chart *c, enum plot_id id, const struct app *app)
{
    if (!c->canvas || app->scope.cursors == 0)
        return;
    struct scope_view v;
    scope_view(app, &v);
    const struct trail *tr = v.trail;
    int h = 4 * c->canvas->rows;
    for (int k = 0; k < app->scope.cursors; k++) {
        const double *r = scope_record(app, &v, k);
        for (int i = 0; r && i < tr->n; i++) {
            double dx = axis_dot(&c->xa, r[field(tr, kinds[id].xq, i)]);
            double dy = h - 1 - axis_dot(&c->ya, r[field(tr, kinds[id].yq, i)]);
            if (!(dx > -0.5 && dx < 2 * c->canvas->cols - 0.5 && dy > -0.5 && dy < h - 0.5))
                continue;
            int col = (int)floor(dx + 0.5) / 2, row = (int)floor(dy + 0.5) / 4;
            draw_text_attr(c->area.y + row, c->area.x + col, 1,
                           term_attr(PAIR_MASS + i % 10) | A_BOLD, k == 0 ? "●" : "◆");
        }
    }
}

/* What a report figure of plot id says (chart_report): its words, each mass's and the
 * motor's name, and on a time plot the cursors with what each shown mass reads there. */
static void report_words(struct chart *c, enum plot_id id, const struct app *app,
                         unsigned hidden)
{
    static const char *const what[4] = {"Time", "Displacement", "Velocity", "Acceleration"};
    static const char *const label[4] = {"time t (s)", "displacement x (m)", "velocity v (m/s)",
                                         "acceleration a (m/s²)"};
    static const char *const sym[4] = {"t", "x", "v", "a"};
    static const char *const unit[4] = {"s", "m", "m/s", "m/s²"};
    int xq = kinds[id].xq, yq = kinds[id].yq;
    char title[80];
    if (xq)
        snprintf(title, sizeof title, "%s against %c%s", what[yq], what[xq][0] + 'a' - 'A',
                 what[xq] + 1);
    else
        snprintf(title, sizeof title, "%s", what[yq]);
    chart_report(c, title, label[xq], label[yq]);
    struct fig_report *r = &c->report;
    r->time = xq == 0;
    for (int i = 0; i < app->model->n && i < 10; i++)
        snprintf(r->name[FIG_MASS + i], sizeof r->name[0], "mass %d", i + 1);
    snprintf(r->name[FIG_MOTOR], sizeof r->name[0], "motor u(t)");
    if (xq || !app->scope.cursors)
        return;
    struct scope_view v;
    scope_view(app, &v);
    for (int k = 0; k < app->scope.cursors && k < FIG_CURSORS; k++) {
        const double *rec = scope_record(app, &v, k);
        if (!rec)
            continue;
        struct fig_cursor *cu = &r->cursor[r->ncursors++];
        cu->x = rec[TRAIL_T];
        snprintf(cu->line[0], sizeof cu->line[0], "t = %.3f s", rec[TRAIL_T]);
        cu->color[0] = FIG_WALL;
        cu->nlines = 1;
        for (int i = 0; i < v.trail->n && cu->nlines < FIG_MARK_LINES; i++) {
            if (hidden >> i & 1u)
                continue;
            snprintf(cu->line[cu->nlines], sizeof cu->line[0], "%s%d = %.4g %s", sym[yq], i + 1,
                     rec[field(v.trail, yq, i)], unit[yq]);
            cu->color[cu->nlines++] = FIG_MASS + i % 10;
        }
    }
}

/* Whether the frames kept are the plots l lays out, where it lays them. */
static bool kept_fits(const struct plots *p, const struct layout *l)
{
    if (!p->kept_ok || p->kept_n != l->nplots)
        return false;
    for (int k = 0; k < l->nplots; k++) {
        struct rect a = p->kept_plot[k], b = l->plot[k];
        if (p->kept_id[k] != l->plot_id[k] || a.x != b.x || a.y != b.y || a.w != b.w ||
            a.h != b.h)
            return false;
    }
    return true;
}

/* Copies each plot's frame between the screen and the kept copy (in the same place);
 * false when a copy fails. */
static bool copy_frames(const struct plots *p, const struct layout *l, bool keep)
{
    for (int k = 0; k < l->nplots; k++) {
        struct rect r = l->plot[k];
        if (r.w <= 0 || r.h <= 0)
            continue;
        int y1 = r.y + r.h - 1, x1 = r.x + r.w - 1;
        int ok = keep ? copywin(stdscr, p->kept, r.y, r.x, r.y, r.x, y1, x1, FALSE)
                      : copywin(p->kept, stdscr, r.y, r.x, r.y, r.x, y1, x1, FALSE);
        if (ok == ERR)
            return false;
    }
    return true;
}

/* Keeps the frames just drawn, for the frames before the next refresh. */
static void keep_frames(struct plots *p, const struct layout *l)
{
    int rows, cols, kr = 0, kc = 0;
    getmaxyx(stdscr, rows, cols);
    if (p->kept)
        getmaxyx(p->kept, kr, kc);
    if (p->kept && (kr != rows || kc != cols)) {
        delwin(p->kept);
        p->kept = NULL;
    }
    if (!p->kept)
        p->kept = newpad(rows, cols);
    p->kept_ok = p->kept && l->nplots <= PLOT_COUNT && copy_frames(p, l, true);
    p->kept_n = l->nplots;
    for (int k = 0; k < l->nplots && k < PLOT_COUNT; k++)
        p->kept_plot[k] = l->plot[k], p->kept_id[k] = l->plot_id[k];
}

void plots_draw(struct plots *p, const struct layout *l, const struct app *app, bool fresh)
{
    if (!fresh && kept_fits(p, l) && copy_frames(p, l, false))
        return;
    const struct model *m = app->model;
    struct legend_item legend[12];
    int n = 0;
    unsigned all = (1u << m->n) - 1u; /* a new chain: only its masses, and one shown */
    p->hidden &= all;
    if (p->hidden == all)
        p->hidden = 0;
    /* A hidden mass keeps its place, its line left out: " 3" for "━3". */
    static const char *const hidden_keys[10] = {"·1", "·2", "·3", "·4", "·5",
                                                "·6", "·7", "·8", "·9", "·10"};
    for (int i = 0; i < m->n && i < 10; i++)
        legend[n++] = (struct legend_item){p->hidden >> i & 1u ? hidden_keys[i] : mass_keys[i],
                                           PAIR_MASS + i};
    if (app->ghost)
        legend[n++] = (struct legend_item){"┄ghost", PAIR_WALL};
    for (int k = 0; k < l->nplots; k++) {
        enum plot_id id = l->plot_id[k];
        struct chart *c = &p->chart[id];
        if (fresh)
            take_samples(c, id, app, p->end_row[id], p->end_col[id], p->hidden, p->top);
        int items = n;
        if (id == PLOT_X && m->boundary == BOUNDARY_MOTOR)
            legend[items++] = (struct legend_item){"┅motor", PAIR_MOTOR};
        chart_draw(c, kinds[id].title, kinds[id].short_title, kinds[id].xq ? NULL : "s", legend,
                   items);
        end_marks(c, p->end_row[id], p->end_col[id], m->n, p->hidden);
        if (fresh)
            report_words(c, id, app, p->hidden);
        if (kinds[id].xq)
            cursor_points(c, id, app);
    }
    keep_frames(p, l);
}

void plots_toggle_mass(struct plots *p, struct app *app, int i)
{
    if (i < 0 || i >= app->model->n) {
        app_say(app, SAID_NOTE, "v shows or hides a mass's curves: select it in the chain first "
                "(Tab, then ↑↓)");
        return;
    }
    unsigned all = (1u << app->model->n) - 1u;
    if (!(p->hidden >> i & 1u) && (p->hidden | 1u << i) == all) {
        app_say(app, SAID_ERROR, "mass %d is the only one shown: the plots keep one", i + 1);
        return;
    }
    p->hidden ^= 1u << i;
    app_say(app, SAID_NOTE, "mass %d %s the plots (v again: %s)", i + 1,
            p->hidden >> i & 1u ? "hidden in" : "shown in", p->hidden >> i & 1u ? "shown" :
            "hidden");
}
