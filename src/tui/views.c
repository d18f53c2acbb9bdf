/* views.c: the modes, frequency response and energy views, each a chart over the plot
 * area, each with the state it needs kept in its own struct. */
#include "views.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../core/modes.h"
#include "draw.h"
#include "term.h"

#define ENERGY_HEADER 3 /* rows above the energy view's data: the legend, the balance */

static const char *const mass_keys[10] = {"━1", "━2", "━3", "━4", "━5",
                                          "━6", "━7", "━8", "━9", "━10"};

bool views_place(struct views *v, const struct layout *l)
{
    /* The modes view is a frame of its own small drawings: no axes, no canvas. */
    chart_free(&v->modes);
    v->modes.frame = l->area;
    bool ok = chart_place(&v->response.chart, l->area, 0);
    ok &= chart_place(&v->energy.chart, l->area, ENERGY_HEADER);
    v->energy.chart.zero_line = true;
    ok &= spectrum_view_place(&v->spectrum, l->area);
    v->response.version = 0;
    return ok;
}

void views_free(struct views *v)
{
    chart_free(&v->modes);
    chart_free(&v->response.chart);
    chart_free(&v->energy.chart);
    spectrum_view_free(&v->spectrum);
    free(v->response.curve);
    v->response.curve = NULL;
}

void views_toggle(struct views *v, enum view w)
{
    v->shown = v->shown == w ? VIEW_PLOTS : w;
    v->energy.chart.ys.set = false;
    v->response.version = 0;
}

/* ---- modes ---- */

/* One mode's shape in cell r: its frequency on the first row, under it the chain from
 * the wall to the end with each mass at its displacement, about a zero line. */
static void draw_mode(const struct app *app, int j, struct rect r, bool driven)
{
    const struct model *m = app->model;
    int n = m->n;
    char title[64];
    int len = snprintf(title, sizeof title, "mode %d  %.3f Hz", j + 1, app->modes[j]);
    if (driven)
        snprintf(title + len, sizeof title - len, len + 10 <= r.w - 2 ? "  ◆ driven" : " ◆");
    draw_text_attr(r.y, r.x + 1, r.w - 2, driven ? term_attr(PAIR_MOTOR) | A_BOLD : A_BOLD, title);
    int dh = r.h - 1, dw = r.w - 2;
    if (dh < 1 || dw < 4)
        return;
    struct canvas *c = canvas_new(dw, dh);
    if (!c)
        return;
    const double *phi = app->shapes + (size_t)j * n;
    int H = 4 * dh, W = 2 * dw;
    double mid = 0.5 * (H - 1), amp = 0.5 * (H - 1) - 2.0; /* the markers stay inside */
    /* The zero line: the chain at rest. */
    int zrow = r.y + 1 + (int)lround(mid) / 4;
    attron(term_attr(PAIR_GRID));
    mvhline(zrow, r.x + 1, term_utf8() ? ACS_HLINE : '-', dw);
    attroff(term_attr(PAIR_GRID));
    int x0 = 0, y0 = (int)lround(mid);
    for (int i = 0; i <= n; i++) {
        if (i == n && m->boundary == BOUNDARY_FREE)
            break;
        int x = i < n ? (int)lround((double)(i + 1) * (W - 1) / (n + 1)) : W - 1;
        int y = (int)lround(mid - amp * (i < n ? phi[i] : 0.0));
        canvas_line(c, x0, y0, x, y, 0);
        x0 = x, y0 = y;
    }
    for (int i = 0; i < n; i++) {
        int x = (int)lround((double)(i + 1) * (W - 1) / (n + 1));
        int y = (int)lround(mid - amp * phi[i]);
        for (int dx = -2; dx <= 2; dx++)
            for (int dy = -2; dy <= 2; dy++)
                canvas_set(c, x + dx, y + dy, (uint8_t)(PAIR_MASS + i % 10));
    }
    draw_canvas(c, r.y + 1, r.x + 1);
    canvas_free(c);
}

static void draw_modes(struct views *v, const struct app *app)
{
    const struct model *m = app->model;
    int n = m->n;
    chart_draw(&v->modes, "Modes: natural frequencies and shapes (n drives the nearest)",
               "Modes", NULL, NULL, 0);
    struct rect f = v->modes.frame, in = {f.y + 1, f.x + 1, f.h - 2, f.w - 2};
    if (!app->modes_ok) {
        draw_text(in.y, in.x + 1, in.w - 2, "the eigenvalue solver failed for these values");
        return;
    }
    /* The grid of cells that gives each shape the most room (shapes are wide). */
    int best_cols = 1;
    double best = -1.0;
    for (int cols = 1; cols <= n; cols++) {
        int rows = (n + cols - 1) / cols;
        double score = fmin((double)(in.w / cols) / 4.0, (double)(in.h / rows));
        if (score > best)
            best = score, best_cols = cols;
    }
    int cols = best_cols, rows = (n + cols - 1) / cols;
    int cw = in.w / cols, ch = in.h / rows;
    int driven = modes_nearest(app->modes, n, m->motor.frequency);
    bool on_mode = m->boundary == BOUNDARY_MOTOR &&
                   fabs(m->motor.frequency - app->modes[driven]) <= 0.02 * app->modes[driven];
    for (int j = 0; j < n; j++) {
        struct rect r = {in.y + (j / cols) * ch, in.x + (j % cols) * cw, ch, cw};
        if (ch < 2) {
            /* No room for shapes: the frequencies alone. */
            if (r.y < in.y + in.h)
                draw_printf(r.y, r.x + 1, cw - 1, "%d %.3f Hz", j + 1, app->modes[j]);
            continue;
        }
        draw_mode(app, j, r, on_mode && j == driven);
    }
}

/* ---- frequency response ---- */

/* Solves the theory curve for the chain as it is, one solve per dot column. */
static void solve_curve(struct response_view *rv, const struct app *app, int width)
{
    const struct model *m = app->model;
    int n = m->n;
    double amp[APP_MAX_MASSES];
    double *curve = realloc(rv->curve, (size_t)width * n * sizeof *curve);
    if (!curve)
        return;
    rv->curve = curve;
    rv->top = 0.0;
    for (int x = 0; x < width; x++) {
        double f = APP_FMIN * pow(APP_FMAX / APP_FMIN, (double)x / (width > 1 ? width - 1 : 1));
        bool ok = modes_response(m, f, amp) == 0;
        for (int i = 0; i < n; i++) {
            curve[(size_t)x * n + i] = ok ? amp[i] : INFINITY;
            if (ok && isfinite(amp[i]))
                rv->top = fmax(rv->top, amp[i]);
        }
    }
    rv->version = app->version;
    rv->width = width;
}

/* Lays the decades on the rows and the frequency ticks on the columns. */
static void response_axes(struct chart *c, double top)
{
    int h = c->area.h > 1 ? c->area.h : 1;
    double hi = ceil(log10(top) - 1e-9);
    int decades = h >= 9 ? 4 : h >= 5 ? 2 : 1;
    int spacing = (h - 1) / decades > 0 ? (h - 1) / decades : 1;
    c->ya = (struct axis){.lo = hi - decades, .step = 1.0, .intervals = decades,
                          .first = (h - 1 - decades * spacing) / 2, .spacing = spacing,
                          .cells = h, .dpc = 4};
    c->yt.n = 0;
    for (int k = 0; k <= decades && k < CHART_MAX_TICKS; k++) {
        c->yt.cell[c->yt.n] = c->ya.first + k * spacing;
        snprintf(c->yt.label[c->yt.n++], sizeof c->yt.label[0], "1e%d", (int)(hi - decades + k));
    }
    static const double ticks[] = {0.1, 0.2, 0.5, 1.0, 2.0, 5.0};
    static const char *const labels[] = {"0.1", "0.2", "0.5", "1", "2", "5"};
    c->xt.n = 0;
    for (size_t k = 0; k < sizeof ticks / sizeof *ticks; k++) {
        c->xt.cell[c->xt.n] = (int)lround(app_freq_fraction(ticks[k]) * (c->area.w - 1));
        snprintf(c->xt.label[c->xt.n++], sizeof c->xt.label[0], "%s", labels[k]);
    }
}

/* Dot row of amplitude a (log scale), H when below the axis. */
static int amp_dot(const struct chart *c, double a)
{
    if (!(a > 0) || !isfinite(a))
        return 0;
    int y = chart_dot_y(c, log10(a));
    return y >= 4 * c->area.h ? 4 * c->area.h : y;
}

static void draw_response(struct response_view *rv, const struct app *app, bool fresh)
{
    const struct model *m = app->model;
    const struct sweep *sw = app->sweep;
    struct chart *c = &rv->chart;
    int n = m->n;
    const char *title = "Frequency response: steady-state amplitude (m) against frequency, log-log";
    if (m->boundary != BOUNDARY_MOTOR || m->motor.amplitude <= 0.0 || !c->canvas) {
        chart_draw(c, title, "Response", NULL, NULL, 0);
        struct rect f = c->frame;
        bool end = m->boundary != BOUNDARY_MOTOR;
        draw_text(f.y + 2, f.x + 3, f.w - 6, end ? "The right end does not drive the chain:"
                                                  : "The motor's amplitude is 0:");
        draw_text(f.y + 3, f.x + 3, f.w - 6, end ? "choose Right end = motor to see its response."
                                                  : "raise the Amplitude to see its response.");
        return;
    }
    int W = 2 * c->canvas->cols, H = 4 * c->canvas->rows;
    if (rv->version != app->version || rv->width != W) {
        solve_curve(rv, app, W);
        fresh = true;
    }
    if (fresh && rv->curve) {
        double top = rv->top;
        for (int p = 0; p < sweep_measured(sw); p++)
            for (int i = 0; i < n; i++)
                if (isfinite(sw->peak[p * n + i]))
                    top = fmax(top, sw->peak[p * n + i]);
        response_axes(c, top > 0.0 ? top : 1.0);
        canvas_clear(c->canvas);
        /* Natural frequencies: dotted verticals; the drive: a solid one. */
        for (int j = 0; j < n && app->modes_ok; j++)
            for (int y = 0; y < H; y += 3)
                canvas_set(c->canvas, (int)lround(app_freq_fraction(app->modes[j]) * (W - 1)), y,
                           0);
        canvas_vspan(c->canvas, (int)lround(app_freq_fraction(m->motor.frequency) * (W - 1)), 0,
                     H - 1, PAIR_MOTOR);
        for (int i = n - 1; i >= 0; i--) {
            int py = H;
            for (int x = 0; x < rv->width; x++) {
                int y = amp_dot(c, rv->curve[(size_t)x * n + i]);
                if (py < H && y < H)
                    canvas_line(c->canvas, x - 1, py, x, y, (uint8_t)(PAIR_MASS + i % 10));
                else if (y < H)
                    canvas_set(c->canvas, x, y, (uint8_t)(PAIR_MASS + i % 10));
                py = y;
            }
        }
        /* The experiment's measured peaks: 3x3 dot squares over the curves. */
        for (int p = 0; p < sweep_measured(sw); p++) {
            int x = (int)lround(app_freq_fraction(sw->freq[p]) * (W - 1));
            for (int i = 0; i < n; i++) {
                int y = amp_dot(c, sw->peak[p * n + i]);
                for (int dx = -1; dx <= 1 && y < H; dx++)
                    for (int dy = -1; dy <= 1; dy++)
                        canvas_set(c->canvas, x + dx, y + dy, (uint8_t)(PAIR_MASS + i % 10));
            }
        }
    }
    char state[120];
    if (sw->active)
        snprintf(state, sizeof state, "sweep %d/%d at %.3f Hz (w stops)", sw->index + 1,
                 sw->points, sweep_frequency(sw));
    else if (sweep_measured(sw))
        snprintf(state, sizeof state, "■ measured: %d points (w sweeps again)",
                 sweep_measured(sw));
    else
        snprintf(state, sizeof state, "┃ drive %.3f Hz  ┊ modes  w: sweep", m->motor.frequency);
    struct legend_item legend[11];
    int k = 0;
    for (int i = 0; i < n && i < 10; i++)
        legend[k++] = (struct legend_item){mass_keys[i], PAIR_MASS + i};
    legend[k++] = (struct legend_item){state, PAIR_MOTOR};
    chart_draw(c, title, "Response (m) against Hz", "Hz", legend, k);
}

/* ---- energy ---- */

static void draw_energy(struct energy_view *ev, const struct app *app, bool fresh)
{
    static const char *const names[TRAIL_ENERGIES] = {"kinetic", "potential", "damped",
                                                      "motor", "contact"};
    static const int colors[TRAIL_ENERGIES] = {PAIR_MASS + 0, PAIR_MASS + 1, PAIR_MASS + 2,
                                               PAIR_MOTOR, PAIR_WARN};
    struct chart *c = &ev->chart;
    const struct trail *tr = app_trail(app);
    struct energy e;
    sim_energy(app->sim, &e);
    double now = sim_time(app->sim), window = app_window(app);
    if (fresh) {
        chart_fit_time(c, window);
        int k;
        const double *rec = chart_window(tr, now - window, &k);
        double lo = 0.0, hi = 0.0;
        ev->peak = 0.0;
        for (int s = 0; s < k; s++)
            for (int q = 0; q < TRAIL_ENERGIES; q++) {
                double val = rec[(size_t)s * tr->width + TRAIL_E(tr, q)];
                lo = fmin(lo, val), hi = fmax(hi, val);
                if (q < 2)
                    ev->peak = fmax(ev->peak, val);
            }
        chart_fit_y(c, lo, hi);
        if (c->canvas) {
            canvas_clear(c->canvas);
            for (int q = TRAIL_ENERGIES - 1; q >= 0; q--)
                plot_trace(c->canvas, rec + TRAIL_T, rec + TRAIL_E(tr, q), k, (size_t)tr->width,
                           now, &c->xa, &c->ya, q == TRAIL_WORK, (unsigned char)colors[q]);
        }
    }
    chart_draw(c, "Energy (J): balance = kinetic + potential + damped + contact − motor",
               "Energy (J)", "s", NULL, 0);
    /* Above the data: each energy now, in its colour, then how good the balance is. */
    struct rect f = c->frame;
    const double vals[TRAIL_ENERGIES] = {e.kinetic, e.potential, e.dissipated, e.motor_work,
                                         e.contact};
    int x = f.x + 2, y = f.y + 1;
    for (int q = 0; q < TRAIL_ENERGIES; q++) {
        char item[48];
        snprintf(item, sizeof item, "━ %s %.3g", names[q], vals[q]);
        int len = draw_width(item);
        if (x + len > f.x + f.w - 2)
            x = f.x + 2, y++;
        if (y >= f.y + ENERGY_HEADER)
            break;
        draw_text_attr(y, x, len, term_attr(colors[q]) | A_BOLD, item);
        x += len + 2;
    }
    if (c->area.y <= f.y + ENERGY_HEADER)
        return; /* no room above the data */
    double drift = app_energy_drift(app);
    char line[200];
    if (e.contact > 0.0)
        snprintf(line, sizeof line, "balance %.6g J (contact counted)", e.balance);
    else
        snprintf(line, sizeof line, "balance %.6g J  drift %.1e of the peak", e.balance,
                 ev->peak > 0 ? fabs(drift) / ev->peak : 0.0);
    draw_text(f.y + ENERGY_HEADER, f.x + 2, f.w - 4, line);
}

void views_draw(struct views *v, const struct app *app, bool refresh)
{
    switch (v->shown) {
    case VIEW_MODES:
        draw_modes(v, app);
        break;
    case VIEW_RESPONSE:
        draw_response(&v->response, app, refresh);
        break;
    case VIEW_ENERGY:
        draw_energy(&v->energy, app, refresh);
        break;
    case VIEW_SPECTRUM:
        spectrum_view_draw(&v->spectrum, app, refresh);
        break;
    case VIEW_PLOTS:
        break;
    }
}
