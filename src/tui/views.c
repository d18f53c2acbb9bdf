/* views.c: the analysis views that can take the plot area: the modes (every natural
 * frequency with its shape), the frequency response (theory on a log axis, with the
 * sine-sweep experiment's measured peaks over it), and the energy balance. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "../core/modes.h"
#include "tui_internal.h"

/* ---- modes ---- */

static void draw_modes(struct tui *t)
{
    const struct app *app = &t->app;
    const struct model *m = app->model;
    int n = m->n;
    struct rect r = t->area;
    tui_frame(t, r, "Modes: natural frequencies and shapes (n drives the nearest)", true);
    if (!app->modes_ok) {
        tui_putn(r.y + 1, r.x + 2, r.w - 4, "the eigenvalue solver failed for these values");
        return;
    }
    int inner_w = r.w - 2, inner_h = r.h - 2;
    int cols = inner_w / 24 > 0 ? inner_w / 24 : 1;
    if (cols > n)
        cols = n;
    int rows = (n + cols - 1) / cols;
    int ph = inner_h / rows, pw = inner_w / cols;
    if (ph < 2)
        ph = 2;
    int driven = modes_nearest(app->modes, n, m->motor.frequency);
    bool on_mode = fabs(m->motor.frequency - app->modes[driven]) <= 0.02 * app->modes[driven];
    for (int j = 0; j < n; j++) {
        int py = r.y + 1 + (j / cols) * ph, px = r.x + 1 + (j % cols) * pw;
        if (py + ph > r.y + r.h - 1 + (ph > 2 ? 0 : 1))
            break;
        bool hot = on_mode && j == driven && m->boundary == BOUNDARY_MOTOR;
        attron(hot ? tui_pair_attr(t, PAIR_MOTOR) | A_BOLD : A_BOLD);
        tui_printf(py, px + 1, pw - 2, "%d  %.3f Hz%s", j + 1, app->modes[j],
                   hot ? "  ◆ driven" : "");
        attroff(tui_pair_attr(t, PAIR_MOTOR) | A_BOLD);
        /* The shape: the chain from wall to end, each mass at its displacement. */
        int dh = ph - 2 > 8 ? 8 : ph - 2, dw = pw - 3;
        if (dh < 1)
            dh = ph - 1;
        if (dh < 1 || dw < 4)
            continue;
        struct canvas *c = canvas_new(dw, dh);
        if (!c)
            continue;
        const double *phi = app->shapes + (size_t)j * n;
        int H = 4 * dh, W = 2 * dw;
        double mid = 0.5 * (H - 1), amp = 0.5 * (H - 1);
        int x0 = 0, y0 = (int)lround(mid);
        for (int i = 0; i <= n; i++) {
            int x = (int)lround((double)(i + 1) * (W - 1) / (n + 1));
            double v = i < n ? phi[i] : 0.0;
            if (i == n && m->boundary == BOUNDARY_FREE)
                break;
            int y = (int)lround(mid - amp * v);
            canvas_line(c, x0, y0, x, y, PAIR_DIM);
            x0 = x, y0 = y;
        }
        for (int i = 0; i < n; i++) {
            /* Each mass as a small block in its colour. */
            int x = (int)lround((double)(i + 1) * (W - 1) / (n + 1));
            int y = (int)lround(mid - amp * phi[i]);
            for (int d = -1; d <= 1; d++) {
                canvas_set(c, x, y + d, (uint8_t)(PAIR_MASS + i % 10));
                canvas_set(c, x + 1, y + d, (uint8_t)(PAIR_MASS + i % 10));
            }
        }
        tui_canvas(t, c, py + 1, px + 2);
        canvas_free(c);
    }
}

/* ---- frequency response ---- */

/* Column of frequency f on a canvas w dots wide over [APP_FMIN, APP_FMAX], log scale
 * (a Bode plot: the modes of a small chain spread out instead of crowding the left). */
static int freq_dot(double f, int w)
{
    return (int)lround(app_freq_fraction(f) * (w - 1));
}

static void draw_response(struct tui *t, bool refresh)
{
    const struct app *app = &t->app;
    const struct model *m = app->model;
    int n = m->n;
    struct rect r = t->area;
    struct canvas *c = t->view_canvas;
    tui_frame(t, r, "Frequency response: steady-state amplitude (m) against frequency, log-log", true);
    if (!c)
        return;
    if (m->boundary != BOUNDARY_MOTOR) {
        tui_putn(r.y + 2, r.x + 3, r.w - 6, "The right end does not drive the chain:");
        tui_putn(r.y + 3, r.x + 3, r.w - 6, "choose Right end = motor to see its response.");
        return;
    }
    if (m->motor.amplitude <= 0.0) {
        tui_putn(r.y + 2, r.x + 3, r.w - 6, "The motor's amplitude is 0: nothing drives the chain.");
        tui_putn(r.y + 3, r.x + 3, r.w - 6, "Raise the Amplitude to see its response.");
        return;
    }
    int W = 2 * c->cols, H = 4 * c->rows;
    /* The theory curve: a zgtsv solve per dot column, so only when the chain changed
     * (app->version) or the view's width did, not on every refresh. */
    static double amp[APP_MAX_MASSES], curve[1024][APP_MAX_MASSES], curve_top;
    static unsigned curve_version;
    static int curve_width;
    int cw = W < 1024 ? W : 1024;
    const struct sweep *sw = app->sweep;
    if (curve_version != app->version || curve_width != cw) {
        curve_top = 0.0;
        for (int x = 0; x < cw; x++) {
            double f = APP_FMIN * pow(APP_FMAX / APP_FMIN, (double)x / (cw - 1));
            if (modes_response(m, f, amp) != 0)
                for (int i = 0; i < n; i++)
                    amp[i] = INFINITY;
            for (int i = 0; i < n; i++) {
                curve[x][i] = amp[i];
                if (isfinite(amp[i]))
                    curve_top = fmax(curve_top, amp[i]);
            }
        }
        curve_version = app->version;
        curve_width = cw;
        refresh = true;
    }
    if (refresh || !t->view_ys.set) {
        /* The four decades below the top of the theory and the measurements. */
        double top = curve_top;
        for (int p = 0; p < sweep_measured(sw); p++)
            for (int i = 0; i < n; i++)
                if (isfinite(sw->peak[p * n + i]))
                    top = fmax(top, sw->peak[p * n + i]);
        if (!(top > 0.0))
            top = 1.0;
        t->view_ys.hi = ceil(log10(top) - 1e-9);
        t->view_ys.lo = t->view_ys.hi - 4.0;
        t->view_ys.set = true;
        refresh = true;
    }
    double dhi = t->view_ys.hi, dlo = t->view_ys.lo;
    int cx = r.x + 1 + 6, cy = r.y + 1;
    /* Decade labels and grid. */
    for (double d = dlo; d <= dhi + 1e-9; d += 1.0) {
        int row = (int)lround((dhi - d) / (dhi - dlo) * (H - 1)) / 4;
        char lab[16];
        snprintf(lab, sizeof lab, "1e%d", (int)d);
        tui_printf(cy + row, r.x + 1, 6, "%5s", lab);
        mvaddch(cy + row, r.x + 6, tui_line(L_RTEE));
        attron(tui_pair_attr(t, PAIR_DIM));
        for (int col = 0; col < c->cols; col += 2)
            if (mvinch(cy + row, cx + col) == ' ')
                mvaddstr(cy + row, cx + col, t->utf8 ? "·" : ".");
        attroff(tui_pair_attr(t, PAIR_DIM));
    }
    int ay = cy + c->rows;
    mvaddch(ay, r.x + 6, tui_line(L_LL));
    mvhline(ay, cx, tui_line(L_H), c->cols);
    static const double ticks[] = {0.1, 0.2, 0.5, 1.0, 2.0, 5.0};
    for (size_t k = 0; k < sizeof ticks / sizeof *ticks; k++) {
        double f = ticks[k];
        int col = freq_dot(f, W) / 2;
        char lab[16];
        snprintf(lab, sizeof lab, "%g", f);
        mvaddch(ay, cx + col, tui_line(L_TTEE));
        if (cx + col + (int)strlen(lab) < r.x + r.w - 1)
            tui_put(ay + 1, cx + col - (col > 0), (int)strlen(lab), lab);
    }
    tui_put(ay + 1, r.x + 2, 2, "Hz");
    if (refresh) {
        canvas_clear(c);
        /* Natural frequencies: dotted verticals; the drive: a solid one. */
        for (int j = 0; j < n && app->modes_ok; j++) {
            int x = freq_dot(app->modes[j], W);
            for (int y = 0; y < H; y += 3)
                canvas_set(c, x, y, PAIR_DIM);
        }
        canvas_vspan(c, freq_dot(m->motor.frequency, W), 0, H - 1, PAIR_MOTOR);
        for (int i = n - 1; i >= 0; i--) {
            int py = -1;
            for (int x = 0; x < cw; x++) {
                double a = curve[x][i];
                int y = isfinite(a) && a > 0 ? (int)lround((dhi - log10(a)) / (dhi - dlo) *
                                                           (H - 1))
                                             : 0;
                if (y >= H)
                    y = H; /* below the axis: not drawn */
                if (py >= 0 && y < H && py < H)
                    canvas_line(c, x - 1, py, x, y, (uint8_t)(PAIR_MASS + i % 10));
                else if (y < H)
                    canvas_set(c, x, y, (uint8_t)(PAIR_MASS + i % 10));
                py = y;
            }
        }
        /* The experiment's measured peaks: 3x3 dot squares over the curves. */
        for (int p = 0; p < sweep_measured(sw); p++) {
            int x = freq_dot(sw->freq[p], W);
            for (int i = 0; i < n; i++) {
                double a = sw->peak[p * n + i];
                if (!(a > 0))
                    continue;
                int y = (int)lround((dhi - log10(a)) / (dhi - dlo) * (H - 1));
                for (int dx = -1; dx <= 1; dx++)
                    for (int dy = -1; dy <= 1; dy++)
                        canvas_set(c, x + dx, y + dy, (uint8_t)(PAIR_MASS + i % 10));
            }
        }
    }
    tui_canvas(t, c, cy, cx);
    /* Legend and the experiment's state on the bottom border. */
    int lx = r.x + 2, ly = r.y + r.h - 1;
    for (int i = 0; i < n && lx < r.x + r.w - 10; i++) {
        attron(tui_mass_attr(t, i) | A_BOLD);
        tui_printf(ly, lx, 3, t->utf8 ? "━%d" : "-%d", i + 1);
        attroff(tui_mass_attr(t, i) | A_BOLD);
        lx += i + 1 >= 10 ? 4 : 3;
    }
    char state[120];
    if (sw->active)
        snprintf(state, sizeof state, " sweep %d/%d at %.3f Hz (w stops) ", sw->index + 1,
                 sw->points, sweep_frequency(sw));
    else if (sweep_measured(sw))
        snprintf(state, sizeof state, " ■ measured: %d points (w sweeps again) ",
                 sweep_measured(sw));
    else
        snprintf(state, sizeof state, " ┃ drive %.3f Hz  ┊ modes  w: sweep experiment ",
                 m->motor.frequency);
    attron(tui_pair_attr(t, PAIR_MOTOR));
    tui_putn(ly, lx + 1, r.x + r.w - lx - 2, state);
    attroff(tui_pair_attr(t, PAIR_MOTOR));
}

/* ---- energy ---- */

static void draw_energy(struct tui *t, bool refresh)
{
    const struct app *app = &t->app;
    const struct trail *tr = app->trail;
    struct rect r = t->area;
    struct canvas *c = t->view_canvas;
    struct energy e;
    sim_energy(app->sim, &e);
    char title[160];
    double drift = app_energy_drift(app);
    snprintf(title, sizeof title, "Energy (J): balance %.6g J, drift %.2e J", e.balance, drift);
    tui_frame(t, r, title, true);
    if (!c)
        return;
    static const char *const names[TRAIL_ENERGIES] = {"kinetic", "potential", "dissipated",
                                                      "motor work", "collisions"};
    static const int colors[TRAIL_ENERGIES] = {PAIR_MASS + 0, PAIR_MASS + 1, PAIR_MASS + 2,
                                               PAIR_MOTOR, PAIR_WARN};
    double t_now = sim_time(app->sim), t0 = t_now - APP_WINDOW;
    int yticks = c->rows >= 8 ? 5 : 3;
    /* Only a refresh looks at the samples (the window, the scale, the peak energy). */
    const double *rec = NULL;
    int k = 0;
    if (refresh) {
        const double *first = trail_first(tr);
        int start = 0;
        while (start < tr->count && first[(size_t)start * tr->width + TRAIL_T] < t0)
            start++;
        rec = first + (size_t)start * tr->width;
        k = tr->count - start;
        double lo = 0.0, hi = 0.0;
        t->view_peak = 0.0;
        for (int s = 0; s < k; s++)
            for (int q = 0; q < TRAIL_ENERGIES; q++) {
                double v = rec[(size_t)s * tr->width + TRAIL_E(tr, q)];
                lo = fmin(lo, v), hi = fmax(hi, v);
                if (q < 2)
                    t->view_peak = fmax(t->view_peak, v);
            }
        plot_scale_update(&t->view_ys, lo, hi, yticks, 30);
    }
    double peak = t->view_peak;
    if (!t->view_ys.set)
        plot_scale_update(&t->view_ys, 0.0, 1.0, yticks, 30);
    const struct scale *ys = &t->view_ys;
    int cx = r.x + 1 + 7, cy = r.y + 1;
    for (double v = ys->lo; v <= ys->hi + 1e-9 * ys->step; v += ys->step) {
        int row = (int)lround((1.0 - (v - ys->lo) / (ys->hi - ys->lo)) * (4 * c->rows - 1)) / 4;
        char lab[16];
        plot_tick_label(v, ys->step, lab, sizeof lab);
        tui_printf(cy + row, r.x + 1, 7, "%6.6s", lab);
        mvaddch(cy + row, r.x + 7, tui_line(L_RTEE));
    }
    int ay = cy + c->rows;
    mvaddch(ay, r.x + 7, tui_line(L_LL));
    mvhline(ay, cx, tui_line(L_H), c->cols);
    for (double v = -APP_WINDOW; v <= 1e-9; v += 2.0) {
        int col = (int)lround((v + APP_WINDOW) / APP_WINDOW * (c->cols - 1));
        char lab[16];
        snprintf(lab, sizeof lab, "%g", v);
        mvaddch(ay, cx + col, tui_line(L_TTEE));
        int lx = cx + col - (int)strlen(lab) / 2;
        if (lx + (int)strlen(lab) > r.x + r.w - 1)
            lx = r.x + r.w - 1 - (int)strlen(lab);
        tui_put(ay + 1, lx, (int)strlen(lab), lab);
    }
    tui_put(ay + 1, r.x + 2, 1, "s");
    if (refresh) {
        canvas_clear(c);
        for (int q = TRAIL_ENERGIES - 1; q >= 0; q--)
            plot_series(c, rec + TRAIL_T, rec + TRAIL_E(tr, q), k, (size_t)tr->width, t0,
                        t_now, ys, q == TRAIL_WORK, (uint8_t)colors[q]);
    }
    tui_canvas(t, c, cy, cx);
    /* Legend with the values now; collisions show as steps in their own line. */
    int lx = r.x + 2, ly = r.y + r.h - 1;
    const double now[TRAIL_ENERGIES] = {e.kinetic, e.potential, e.dissipated, e.motor_work,
                                        e.contact};
    for (int q = 0; q < TRAIL_ENERGIES; q++) {
        char item[64];
        snprintf(item, sizeof item, " %s %.3g", names[q], now[q]);
        if (lx + (int)strlen(item) >= r.x + r.w - 1)
            break;
        attron(tui_pair_attr(t, colors[q]) | A_BOLD);
        tui_putn(ly, lx, (int)strlen(item), item);
        attroff(tui_pair_attr(t, colors[q]) | A_BOLD);
        lx += (int)strlen(item);
    }
    /* How good the balance is: the drift against the largest energy seen. */
    if (r.h > 4) {
        char line[200];
        if (e.contact > 0.0)
            snprintf(line, sizeof line, "kinetic + potential + dissipated + collisions - motor "
                     "work = %.6g J; collisions took %.4g J (steps in their line)", e.balance,
                     e.contact);
        else
            snprintf(line, sizeof line, "kinetic + potential + dissipated - motor work = %.6g J;"
                     " drift %.2e J = %.1e of the peak", e.balance, drift,
                     peak > 0 ? fabs(drift) / peak : 0.0);
        attron(tui_pair_attr(t, PAIR_DIM));
        tui_putn(r.y + 1, cx + 1, r.x + r.w - cx - 3, line);
        attroff(tui_pair_attr(t, PAIR_DIM));
    }
}

void views_draw(struct tui *t, bool refresh)
{
    switch (t->view) {
    case VIEW_MODES:
        draw_modes(t);
        break;
    case VIEW_RESPONSE:
        draw_response(t, refresh);
        break;
    case VIEW_ENERGY:
        draw_energy(t, refresh);
        break;
    case VIEW_PLOTS:
        break;
    }
}
