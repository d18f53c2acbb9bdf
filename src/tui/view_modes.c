/* view_modes.c: the modes view, alive (view_modes.h): a grid of cells, one per mode, each
 * with its numbers, its energy bar and its shape swinging. */
#include "view_modes.h"

#include <math.h>
#include <stdio.h>
#include <string.h>
#include <time.h>

#include "../chart/strokes.h"
#include "../core/modes.h"
#include "draw.h"
#include "term.h"

#define CELL_TEXT_ROWS 3 /* title, numbers, energy bar */
#define CELL_MIN_COLS 26 /* what the numbers need to read */
#define AT_REST 1e-12    /* J: below this the chain is at rest and has no shares */

static double wall_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

bool modes_view_place(struct modes_view *v, struct rect area)
{
    chart_free(&v->chart);
    v->chart.frame = area;
    for (int j = 0; j < APP_MAX_MASSES; j++)
        v->cell[j].drawn = false;
    if (v->clock0 == 0.0)
        v->clock0 = wall_s();
    return true;
}

void modes_view_free(struct modes_view *v)
{
    chart_free(&v->chart);
    for (int j = 0; j < APP_MAX_MASSES; j++)
        chart_free(&v->cell[j]);
}

int modes_view_cells(struct modes_view *v, struct chart **out, int max)
{
    int k = 0;
    for (int j = 0; j < APP_MAX_MASSES && k < max; j++)
        if (v->cell[j].drawn)
            out[k++] = &v->cell[j];
    return k;
}

/* The factor every mode is slowed by so the fastest swings at most MODES_VIEW_FASTEST
 * times a second on screen (1: real speed). */
static double slowing(const struct app *app)
{
    double top = 0.0;
    for (int j = 0; j < app->model->n; j++)
        top = fmax(top, app->modes[j]);
    return top > MODES_VIEW_FASTEST ? MODES_VIEW_FASTEST / top : 1.0;
}

/* Mode j's damping in words that fit w columns: zeta, Q = 1/(2 zeta), the -3 dB
 * bandwidth 2 zeta f and the damped frequency, or as much of it as fits; above
 * zeta = 1/sqrt(2) "no resonant peak" in place of the band, from 1 "overdamped". */
static void damping_text(const struct app *app, int j, int w, char *buf, size_t len)
{
    bool u = term_utf8();
    const char *zeta = u ? "ζ" : "zeta";
    double z = app->damping_ratio[j], f = app->modes[j];
    if (!app->damping_ok) {
        snprintf(buf, len, "damping not known");
        return;
    }
    if (isnan(z)) { /* a rigid-body mode (damped.c): 0 Hz, no ratio */
        snprintf(buf, len, "rigid-body mode: no spring holds it, no %s", zeta);
        if (draw_width(buf) > w)
            snprintf(buf, len, "rigid-body mode");
        return;
    }
    if (z >= 1.0) {
        snprintf(buf, len, "%s %.3g  overdamped: no resonance", zeta, z);
        if (draw_width(buf) > w)
            snprintf(buf, len, "%s %.3g overdamped", zeta, z);
        return;
    }
    char q[24];
    if (z > 0.0)
        snprintf(q, sizeof q, "%.3g", 0.5 / z);
    else
        snprintf(q, sizeof q, "%s", u ? "∞" : "inf");
    if (z >= M_SQRT1_2) {
        /* The response |X/F| = 1/sqrt((1 - r^2)^2 + (2 zeta r)^2) has its peak at
         * r^2 = 1 - 2 zeta^2: from zeta = 1/sqrt(2) on there is none, and no -3 dB band
         * about it to speak of. */
        snprintf(buf, len, "%s %.3g  Q %s  no resonant peak", zeta, z, q);
        if (draw_width(buf) > w)
            snprintf(buf, len, "%s %.3g  Q %s", zeta, z, q);
        return;
    }
    /* The longest form that fits: with the damped frequency, the bandwidth, or neither. */
    int k = snprintf(buf, len, "%s %.3g  Q %s", zeta, z, q);
    char more[64];
    snprintf(more, sizeof more, "  -3 dB %.3g Hz", 2.0 * z * f);
    if (k > 0 && draw_width(buf) + draw_width(more) <= w && (size_t)k < len) {
        k += snprintf(buf + k, len - (size_t)k, "%s", more);
        snprintf(more, sizeof more, "  fd %.4g Hz", app->damped_hz[j]);
        if (draw_width(buf) + draw_width(more) <= w && (size_t)k < len)
            snprintf(buf + k, len - (size_t)k, "%s", more);
    }
}

/* The energy bar: "E ████▌     87 %" in w columns at row y. */
static void draw_bar(const struct modes_view *v, int j, int y, int x, int w)
{
    if (w < 8)
        return;
    if (v->total < AT_REST) {
        draw_text(y, x, w, "E  at rest: no motion to share");
        return;
    }
    double share = v->share[j];
    char pct[16];
    snprintf(pct, sizeof pct, " %3.0f %%", 100.0 * share);
    int cells = w - 2 - (int)strlen(pct);
    draw_text_attr(y, x, 2, A_BOLD, "E ");
    if (cells < 1)
        return;
    double fill = share * cells;
    int whole = (int)floor(fill);
    static const char *const eighths[8] = {"", "▏", "▎", "▍", "▌", "▋", "▊", "▉"};
    bool u = term_utf8();
    attr_t on = term_attr(PAIR_TITLE) | A_BOLD, off = term_attr(PAIR_GRID);
    for (int k = 0; k < cells; k++) {
        if (k < whole)
            draw_text_attr(y, x + 2 + k, 1, on, u ? "█" : "#");
        else if (k == whole && u && (int)((fill - whole) * 8.0) > 0)
            draw_text_attr(y, x + 2 + k, 1, on, eighths[(int)((fill - whole) * 8.0)]);
        else
            draw_text_attr(y, x + 2 + k, 1, off, u ? "·" : ".");
    }
    draw_text_attr(y, x + 2 + cells, (int)strlen(pct), A_BOLD, pct);
}

/* Mode j's shape at this instant of the animation, in the rows of r below the text: in
 * braille, and kept as strokes at full precision for an image (the middle line, the chain
 * through the masses, a disc at each mass), its canvas left off the screen then. */
static void draw_shape(struct modes_view *v, const struct app *app, int j, struct rect r)
{
    const struct model *m = app->model;
    int n = m->n, dw = r.w - 2, dh = r.h - CELL_TEXT_ROWS;
    struct chart *cell = &v->cell[j];
    cell->drawn = false;
    if (dh < 1 || dw < 4)
        return;
    if (!cell->canvas || cell->canvas->cols != dw || cell->canvas->rows != dh) {
        chart_free(cell);
        cell->canvas = canvas_new(dw, dh);
        if (!cell->canvas)
            return;
        canvas_keep_strokes(cell->canvas);
    }
    struct canvas *c = cell->canvas;
    int top = r.y + CELL_TEXT_ROWS;
    cell->frame = cell->area = (struct rect){top, r.x + 1, dh, dw};
    canvas_clear(c);
    const double *phi = app->shapes + (size_t)j * n;
    double swing = cos(2.0 * M_PI * app->modes[j] * v->shown_t);
    int H = 4 * dh, W = 2 * dw, mark = dh >= 2 ? 2 : 1;
    double mid = 0.5 * (H - 1), amp = 0.5 * (H - 1) - mark;
    /* The joints, wall to wall (or to the free end), unrounded. */
    double x[APP_MAX_MASSES + 2], y[APP_MAX_MASSES + 2];
    int joints = m->boundary == BOUNDARY_FREE ? n + 1 : n + 2;
    x[0] = 0.0, y[0] = mid;
    for (int i = 1; i < joints; i++) {
        x[i] = i <= n ? (double)i * (W - 1) / (n + 1) : W - 1;
        y[i] = mid - amp * swing * (i <= n ? phi[i - 1] : 0.0);
    }
    struct strokes *k = c->strokes;
    if (k) {
        /* Discs a quarter of the height across (2 to 5 dots), the swing what they leave. */
        int disc = H / 4 < 2 ? 2 : H / 4 > 5 ? 5 : H / 4;
        double scale = (mid - 0.5 * disc) / amp;
        strokes_begin(k, PAIR_GRID, STROKE_LINE);
        strokes_point(k, 0.0, mid);
        strokes_point(k, W - 1, mid);
        strokes_begin(k, 0, STROKE_LINE);
        for (int i = 0; i < joints; i++)
            strokes_point(k, x[i], mid + (y[i] - mid) * scale);
        for (int i = 0; i < n; i++) {
            strokes_begin(k, (uint8_t)(PAIR_MASS + i % 10), STROKE_MARKS);
            strokes_mark_size(k, disc);
            strokes_point(k, x[i + 1], mid + (y[i + 1] - mid) * scale);
        }
    }
    c->mute++; /* the strokes are kept above, unrounded */
    for (int i = 1; i < joints; i++)
        canvas_line(c, (int)lround(x[i - 1]), (int)lround(y[i - 1]), (int)lround(x[i]),
                    (int)lround(y[i]), 0);
    for (int i = 1; i <= n; i++)
        for (int dx = -mark; dx <= mark; dx++)
            for (int dy = -mark; dy <= mark; dy++)
                canvas_set(c, (int)lround(x[i]) + dx, (int)lround(y[i]) + dy,
                           (uint8_t)(PAIR_MASS + (i - 1) % 10));
    c->mute--;
    cell->drawn = true;
    if (chart_pixels())
        return; /* the image shows it */
    attron(term_attr(PAIR_GRID));
    mvhline(top + (int)lround(mid) / 4, r.x + 1, term_utf8() ? ACS_HLINE : '-', dw);
    attroff(term_attr(PAIR_GRID));
    draw_canvas(c, top, r.x + 1);
}

/* One mode's cell: title, damping, energy bar, then the shape in what is left of its
 * first shape_rows rows. */
static void draw_cell(struct modes_view *v, const struct app *app, int j, struct rect r,
                      int shape_rows, bool driven, bool selected)
{
    char title[80];
    const char *mark = !selected ? "" : term_utf8() ? "▸ " : "> ";
    char hz[32];
    int len = snprintf(title, sizeof title, "%smode %d  %s Hz", mark, j + 1,
                       app_fixed(app->modes[j], 3, hz, sizeof hz));
    if (driven)
        snprintf(title + len, sizeof title - (size_t)len, "%s",
                 len + 11 + (r.h < 2 ? 7 : 0) <= r.w - 2 ? (term_utf8() ? "  ◆ driven" : "  * driven")
                                     : (term_utf8() ? " ◆" : " *"));
    attr_t a = A_BOLD | (selected ? A_REVERSE : 0) | (driven ? term_attr(PAIR_MOTOR) : 0);
    draw_text_attr(r.y, r.x + 1, r.w - 2, a, title);
    char line[96];
    if (r.h >= 3) {
        damping_text(app, j, r.w - 2, line, sizeof line);
        draw_text(r.y + 1, r.x + 1, r.w - 2, line);
    }
    if (r.h >= 2) {
        draw_bar(v, j, r.y + (r.h >= 3 ? 2 : 1), r.x + 1, r.w - 2);
    } else if (v->total >= AT_REST) {
        /* One row: the share at the row's end, where the title leaves room. */
        char pct[16];
        int plen = snprintf(pct, sizeof pct, "%3.0f %%", 100.0 * v->share[j]);
        if (draw_width(title) + plen + 2 <= r.w - 2)
            draw_text_attr(r.y, r.x + r.w - 1 - plen, plen, A_BOLD, pct);
    }
    r.h = shape_rows;
    draw_shape(v, app, j, r);
}

/* Takes the energies of the motion now and moves the animation on. */
static void take_now(struct modes_view *v, const struct app *app)
{
    int n = app->model->n;
    double e[APP_MAX_MASSES];
    modes_energy(app->model, app->modes, app->shapes, sim_x(app->sim), sim_v(app->sim), e);
    v->total = 0.0;
    for (int j = 0; j < n; j++)
        v->total += e[j];
    for (int j = 0; j < n; j++)
        v->share[j] = v->total >= AT_REST ? e[j] / v->total : 0.0;
    v->shown_t = (wall_s() - v->clock0) * slowing(app);
}

void modes_view_draw(struct modes_view *v, const struct app *app, int selected, bool refresh)
{
    const struct model *m = app->model;
    int n = m->n;
    char title[120];
    double slow = app->modes_ok ? slowing(app) : 1.0;
    if (m->cubic)
        snprintf(title, sizeof title, "Modes of the chain linearised at rest: shapes swinging, "
                 "damping, energy share (Enter starts one)");
    else if (slow < 1.0)
        snprintf(title, sizeof title, "Modes: shapes swinging at 1/%.3g speed, damping, energy "
                 "share (Enter starts one)", 1.0 / slow);
    else
        snprintf(title, sizeof title, "Modes: shapes swinging, damping, energy share (Enter "
                 "starts one)");
    chart_draw(&v->chart, title, "Modes", NULL, NULL, 0);
    struct rect f = v->chart.frame, in = {f.y + 1, f.x + 1, f.h - 2, f.w - 2};
    if (!app->modes_ok) {
        draw_text(in.y, in.x + 1, in.w - 2, "the eigenvalue solver failed for these values");
        return;
    }
    if (refresh || v->shown_t == 0.0)
        take_now(v, app);
    for (int j = 0; j < APP_MAX_MASSES; j++)
        v->cell[j].drawn = false; /* until drawn below */
    /* The grid that gives each shape the most room, cells wide enough for the numbers. */
    int best_cols = 1;
    double best = -1.0;
    for (int cols = 1; cols <= n; cols++) {
        int rows = (n + cols - 1) / cols, cw = in.w / cols, ch = in.h / rows;
        if (cols > 1 && cw < CELL_MIN_COLS)
            break;
        double score = fmin((double)cw / 4.0, (double)(ch - CELL_TEXT_ROWS + 1));
        if (score > best)
            best = score, best_cols = cols;
    }
    int cols = best_cols, rows = (n + cols - 1) / cols;
    /* Rows left over go to the cells one each, top first (their text gets the room); the
     * shapes all take the same height, so one canvas serves them all. */
    int cw = in.w / cols, ch = in.h / rows;
    int driven = modes_nearest(app->modes, n, m->motor.frequency);
    bool on_mode = model_motor_moves(m) &&
                   fabs(m->motor.frequency - app->modes[driven]) <= 0.02 * app->modes[driven];
    for (int j = 0; j < n; j++) {
        int row = j / cols, extra = in.h - rows * ch;
        int y = in.y + row * ch + (row < extra ? row : extra);
        struct rect r = {y, in.x + (j % cols) * cw, ch + (row < extra), cw};
        if (r.h < 1 || r.y >= in.y + in.h)
            continue;
        draw_cell(v, app, j, r, ch, on_mode && j == driven, j == selected);
    }
}
