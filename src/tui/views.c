/* views.c: the analysis views over the plot area, one at a time: which is shown, and
 * the energy view; the modes and the response views have files of their own. */
#include "views.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "draw.h"
#include "term.h"

#define ENERGY_HEADER 3 /* rows above the energy view's data: the legend, the balance */

bool views_place(struct views *v, const struct layout *l)
{
    bool ok = modes_view_place(&v->modes, l->area);
    ok &= response_view_place(&v->response, l->area);
    ok &= chart_place(&v->energy.chart, l->area, ENERGY_HEADER);
    v->energy.chart.zero_line = true;
    ok &= spectrum_view_place(&v->spectrum, l->area);
    return ok;
}

void views_free(struct views *v)
{
    modes_view_free(&v->modes);
    response_view_free(&v->response);
    chart_free(&v->energy.chart);
    spectrum_view_free(&v->spectrum);
}

void views_toggle(struct views *v, enum view w)
{
    v->shown = v->shown == w ? VIEW_PLOTS : w;
    v->energy.chart.ys.set = false;
    v->response.version = 0;
}

/* ---- energy ---- */

static const char *const names[TRAIL_ENERGIES] = {"kinetic", "potential", "damped", "motor",
                                                  "contact", "force"};
static const int colors[TRAIL_ENERGIES] = {PAIR_MASS + 0, PAIR_MASS + 1, PAIR_MASS + 2,
                                           PAIR_MOTOR, PAIR_MASS + 4, PAIR_MASS + 3};

/* The energies the view shows for app's chain: the force's work (the last) only where a
 * force acts or has worked. */
static int energies_shown(const struct app *app, const struct energy *e)
{
    return model_forced(app->model) || e->force_work != 0.0 ? TRAIL_ENERGIES
                                                            : TRAIL_ENERGIES - 1;
}

/* The first nq energies now, in their colours, in the rows above the data of frame f:
 * named in full (form 0) or briefly (1). Whether they all fit; drawn (those that fit,
 * then "…") if draw. */
static bool energy_items(struct rect f, const double *vals, int nq, int form, bool draw)
{
    static const char *const brief[TRAIL_ENERGIES] = {"kin", "pot", "damp", "motor", "cont",
                                                      "force"};
    int x = f.x + 2, y = f.y + 1, right = f.x + f.w - 2;
    for (int q = 0; q < nq; q++) {
        char item[48];
        if (form)
            snprintf(item, sizeof item, "━%s %.2g", brief[q], vals[q]);
        else
            snprintf(item, sizeof item, "━ %s %.3g", names[q], vals[q]);
        int len = draw_width(item);
        if (x + len > right)
            x = f.x + 2, y++;
        if (y >= f.y + ENERGY_HEADER) { /* "…" after the last row's items */
            if (draw)
                draw_text(f.y + ENERGY_HEADER - 1, right - 1, 1, term_utf8() ? "…" : "~");
            return false;
        }
        if (draw)
            draw_text_attr(y, x, len, term_attr(colors[q]) | A_BOLD, item);
        x += len + (form ? 1 : 2);
    }
    return true;
}

static void draw_energy(struct energy_view *ev, const struct app *app, bool fresh)
{
    struct chart *c = &ev->chart;
    const struct trail *tr = app_trail(app);
    struct energy e;
    sim_energy(app->sim, &e);
    int nq = energies_shown(app, &e);
    double now = sim_time(app->sim), window = app_window(app);
    if (fresh) {
        chart_fit_time(c, now, window);
        int k;
        const double *rec = chart_window(tr, chart_left_time(c) - 1e-9, &k);
        double lo = 0.0, hi = 0.0;
        ev->peak = 0.0;
        for (int s = 0; s < k; s++)
            for (int q = 0; q < nq; q++) {
                double val = rec[(size_t)s * tr->width + TRAIL_E(tr, q)];
                lo = fmin(lo, val), hi = fmax(hi, val);
                if (q < 2)
                    ev->peak = fmax(ev->peak, val);
            }
        chart_fit_y(c, lo, hi);
        if (c->canvas) {
            canvas_clear(c->canvas);
            for (int q = nq - 1; q >= 0; q--)
                plot_trace(c->canvas, rec + TRAIL_T, rec + TRAIL_E(tr, q), k, (size_t)tr->width,
                           0.0, &c->xa, &c->ya, q == TRAIL_WORK, (unsigned char)colors[q]);
        }
    }
    chart_draw(c, nq == TRAIL_ENERGIES
                      ? "Energy (J): balance = kinetic + potential + damped + contact − motor − "
                        "force"
                      : "Energy (J): balance = kinetic + potential + damped + contact − motor",
               "Energy (J)", "s", NULL, 0);
    chart_report(c, "Energy balance", "time t (s)", "energy (J)");
    c->report.time = true;
    /* The report's words are --energy --figure's (the screen's "damped" is short). */
    static const char *const report_names[TRAIL_ENERGIES] = {"kinetic", "potential",
                                                             "dissipated", "motor work",
                                                             "contact", "force work"};
    for (int q = 0; q < nq; q++)
        snprintf(c->report.name[colors[q]], sizeof c->report.name[0], "%s", report_names[q]);
    /* Above the data: each energy now, in its colour, then how good the balance is. */
    struct rect f = c->frame;
    const double vals[TRAIL_ENERGIES] = {e.kinetic, e.potential, e.dissipated, e.motor_work,
                                         e.contact, e.force_work};
    /* Each with its name, or where they do not all fit in the rows, shorter ("━kin
     * 0.047"); if even that does not fit, the ones that do and "…". */
    energy_items(f, vals, nq, energy_items(f, vals, nq, 0, false) ? 0 : 1, true);
    if (c->area.y <= f.y + ENERGY_HEADER)
        return; /* no room above the data */
    double drift = app_energy_drift(app), rel = ev->peak > 0 ? fabs(drift) / ev->peak : 0.0;
    char line[200];
    /* The longest form that fits: the drift, relative to the peak, is what matters. */
    for (int form = 0; form < 3; form++) {
        if (e.contact > 0.0)
            snprintf(line, sizeof line, form ? "balance %.3g J (contact)" :
                     "balance %.6g J (contact counted)", e.balance);
        else if (form == 0)
            snprintf(line, sizeof line, "balance %.6g J  drift %.1e of the peak", e.balance, rel);
        else if (form == 1)
            snprintf(line, sizeof line, "balance %.3g J, drift %.0e", e.balance, rel);
        else
            snprintf(line, sizeof line, "drift %.1e of the peak", rel);
        if (draw_width(line) <= f.w - 4)
            break;
    }
    draw_text(f.y + ENERGY_HEADER, f.x + 2, f.w - 4, line);
}

void views_draw(struct views *v, const struct app *app, const struct selection *sel,
                bool refresh)
{
    switch (v->shown) {
    case VIEW_MODES:
        modes_view_draw(&v->modes, app, select_mode(sel), refresh);
        break;
    case VIEW_RESPONSE:
        response_view_draw(&v->response, app, refresh);
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

int views_charts(struct views *v, struct chart **out, int max)
{
    int n = 0;
    switch (v->shown) {
    case VIEW_RESPONSE:
        out[n++] = &v->response.chart;
        if (v->response.phase.frame.h > 0 && n < max)
            out[n++] = &v->response.phase;
        break;
    case VIEW_ENERGY:
        out[n++] = &v->energy.chart;
        break;
    case VIEW_SPECTRUM:
        out[n++] = &v->spectrum.chart;
        break;
    case VIEW_MODES:
    case VIEW_PLOTS:
        break;
    }
    return n;
}
