/* view_response.c: the frequency response view (view_response.h): two charts on one
 * log frequency axis, amplitude above and phase below. */
#include "view_response.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "../app/sweeping.h"
#include "../fig/report.h"
#include "../chart/strokes.h"
#include "../core/modes.h"
#include "draw.h"
#include "view_branches.h"
#include "term.h"

static const char *const mass_keys[10] = {"━1", "━2", "━3", "━4", "━5",
                                          "━6", "━7", "━8", "━9", "━10"};

bool response_view_place(struct response_view *rv, struct rect area)
{
    struct rect amp = area, ph = {0, 0, 0, 0};
    rv->area = area;
    rv->merged = false;
    if (area.h >= RESPONSE_PHASE_MIN_ROWS) {
        ph = area;
        ph.h = area.h * 2 / 5 > RESPONSE_PHASE_ROWS ? area.h * 2 / 5 : RESPONSE_PHASE_ROWS;
        amp.h = area.h - ph.h;
        ph.y = area.y + amp.h;
    }
    bool ok = chart_place(&rv->chart, amp, 0);
    if (ph.h > 0)
        ok &= chart_place(&rv->phase, ph, 0);
    else
        chart_free(&rv->phase), rv->phase.frame = ph;
    rv->version = 0;
    return ok;
}

void response_view_free(struct response_view *rv)
{
    chart_free(&rv->chart);
    chart_free(&rv->phase);
    free(rv->curve);
    free(rv->phase_curve);
    rv->curve = rv->phase_curve = NULL;
    jump_theory_free(&rv->hb);
    rv->hb_version = 0;
}

/* Solves the theory curves for the chain as it is, one solve per dot column, and the
 * phases at the drive's frequency for the legend. */
static void solve_curves(struct response_view *rv, const struct app *app, int width)
{
    const struct model *m = app->model;
    int n = m->n;
    double amp[APP_MAX_MASSES], ph[APP_MAX_MASSES];
    rv->drive_phase_ok = false;
    double *curve = realloc(rv->curve, (size_t)width * n * sizeof *curve);
    if (curve)
        rv->curve = curve;
    double *phase = realloc(rv->phase_curve, (size_t)width * n * sizeof *phase);
    if (phase)
        rv->phase_curve = phase;
    if (!curve || !phase)
        return;
    rv->top = 0.0;
    for (int x = 0; x < width; x++) {
        double f = APP_FMIN * pow(APP_FMAX / APP_FMIN, (double)x / (width > 1 ? width - 1 : 1));
        bool ok = modes_response_phase(m, f, amp, ph) == 0;
        for (int i = 0; i < n; i++) {
            curve[(size_t)x * n + i] = ok ? amp[i] : INFINITY;
            phase[(size_t)x * n + i] = ok ? ph[i] : NAN;
            if (ok && isfinite(amp[i]))
                rv->top = fmax(rv->top, amp[i]);
        }
    }
    rv->drive_phase_ok = modes_response_phase(m, m->motor.frequency, amp, rv->drive_phase) == 0;
    struct sweep_plan plan;
    char why[200];
    if (sweeping_plan(app, &plan, why, sizeof why) != 0)
        plan.scale = INFINITY;
    rv->plan = plan;
    rv->version = app->version;
    rv->width = width;
}

/* The frequency ticks of the control's log range on the columns of c. */
static void frequency_ticks(struct chart *c)
{
    static const double ticks[] = {0.1, 0.2, 0.5, 1.0, 2.0, 5.0};
    static const char *const labels[] = {"0.1", "0.2", "0.5", "1", "2", "5"};
    c->xt.n = 0;
    for (size_t k = 0; k < sizeof ticks / sizeof *ticks; k++) {
        c->xt.cell[c->xt.n] = (int)lround(app_freq_fraction(ticks[k]) * (c->area.w - 1));
        snprintf(c->xt.label[c->xt.n++], sizeof c->xt.label[0], "%s", labels[k]);
    }
}

/* Lays the decades on the rows and the frequency ticks on the columns. */
static void amplitude_axes(struct chart *c, double top)
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
    frequency_ticks(c);
}

/* -180 to 180 degrees on the rows: every 90 where there is room, else every 180. */
static void phase_axes(struct chart *c)
{
    int h = c->area.h > 1 ? c->area.h : 1;
    int intervals = h >= 9 ? 4 : 2;
    int spacing = (h - 1) / intervals > 0 ? (h - 1) / intervals : 1;
    c->ya = (struct axis){.lo = -180.0, .step = 360.0 / intervals, .intervals = intervals,
                          .first = (h - 1 - intervals * spacing) / 2, .spacing = spacing,
                          .cells = h, .dpc = 4};
    c->yt.n = 0;
    for (int k = 0; k <= intervals; k++) {
        c->yt.cell[c->yt.n] = c->ya.first + k * spacing;
        snprintf(c->yt.label[c->yt.n++], sizeof c->yt.label[0], "%d", -180 + k * 360 / intervals);
    }
    frequency_ticks(c);
}

/* Dot row of amplitude a (log scale), H when below the axis. */
static int amp_dot(const struct chart *c, double a)
{
    if (!(a > 0) || !isfinite(a))
        return 0;
    int y = chart_dot_y(c, log10(a));
    return y >= 4 * c->area.h ? 4 * c->area.h : y;
}

/* Dot row of phase p (degrees), H when it is not known. */
static int phase_dot(const struct chart *c, double p)
{
    int y = isfinite(p) ? chart_dot_y(c, p) : 4 * c->area.h;
    return y < 0 ? 0 : y > 4 * c->area.h ? 4 * c->area.h : y;
}

/* The natural frequencies as dotted verticals, the drive's as a solid one. */
static void mark_frequencies(struct canvas *cv, const struct app *app)
{
    int W = 2 * cv->cols, H = 4 * cv->rows;
    for (int j = 0; j < app->model->n && app->modes_ok; j++)
        for (int y = 0; y < H; y += 3)
            canvas_set(cv, (int)lround(app_freq_fraction(app->modes[j]) * (W - 1)), y, 0);
    canvas_vspan(cv, (int)lround(app_freq_fraction(app->model->motor.frequency) * (W - 1)), 0,
                 H - 1, PAIR_MOTOR);
}

/* The points measured by the sweep, each mass's as one stroke of marks of a fixed small
 * size (a disc two dots across in pixels, one dot in braille: points that do not
 * merge into blocks), at dot row dot_of(value) of each point's frequency; on the theory's
 * line, drawn after it. */
static void mark_points(struct chart *c, const struct app *app, const double *values,
                        double (*dot_of)(const struct chart *, double))
{
    const struct sweep *sw = app->sweep;
    struct canvas *cv = c->canvas;
    int n = app->model->n, W = 2 * cv->cols, H = 4 * cv->rows;
    for (int i = 0; i < n; i++) {
        uint8_t color = (uint8_t)(PAIR_MASS + i % 10);
        if (cv->strokes) {
            strokes_begin(cv->strokes, color, STROKE_MARKS);
            strokes_mark_size(cv->strokes, 2);
        }
        cv->mute++;
        for (int p = 0; p < sweep_measured(sw); p++) {
            double x = app_freq_fraction(sw->freq[p]) * (W - 1), y = dot_of(c, values[p * n + i]);
            if (!isfinite(y) || y < -0.5 || y > H - 0.5)
                continue;
            canvas_set(cv, (int)lround(x), (int)lround(y), color);
            if (cv->strokes)
                strokes_point(cv->strokes, x, y);
        }
        cv->mute--;
    }
}

/* Dot rows (unrounded) of amplitude a on the log axis and of phase p, NAN off it. */
static double amp_dotf(const struct chart *c, double a)
{
    return a > 0.0 && isfinite(a) ? chart_dot_yf(c, log10(a)) : NAN;
}

static double phase_dotf(const struct chart *c, double p)
{
    return isfinite(p) ? chart_dot_yf(c, p) : NAN;
}

static void draw_amplitude(struct response_view *rv, const struct app *app)
{
    const struct sweep *sw = app->sweep;
    struct chart *c = &rv->chart;
    int n = app->model->n, H = 4 * c->canvas->rows;
    double top = rv->top;
    for (int p = 0; p < sweep_measured(sw); p++)
        for (int i = 0; i < n; i++)
            if (isfinite(sw->peak[p * n + i]))
                top = fmax(top, sw->peak[p * n + i]);
    amplitude_axes(c, top > 0.0 ? top : 1.0);
    canvas_clear(c->canvas);
    mark_frequencies(c->canvas, app);
    struct strokes *keep = c->canvas->strokes;
    c->canvas->mute++; /* the curves' strokes are kept unrounded below */
    for (int i = n - 1; i >= 0; i--) {
        int py = H;
        if (keep)
            strokes_begin(keep, (uint8_t)(PAIR_MASS + i % 10), STROKE_LINE);
        for (int x = 0; x < rv->width; x++) {
            double a = rv->curve[(size_t)x * n + i];
            int y = amp_dot(c, a);
            if (py < H && y < H)
                canvas_line(c->canvas, x - 1, py, x, y, (uint8_t)(PAIR_MASS + i % 10));
            else if (y < H)
                canvas_set(c->canvas, x, y, (uint8_t)(PAIR_MASS + i % 10));
            if (keep)
                strokes_point(keep, x, a > 0 && isfinite(a) ? chart_dot_yf(c, log10(a)) : NAN);
            py = y;
        }
    }
    c->canvas->mute--;
    mark_points(c, app, sw->peak, amp_dotf);
}

/* The phase curves; a jump across +-180 degrees is not joined. */
static void draw_phase(struct response_view *rv, const struct app *app)
{
    const struct sweep *sw = app->sweep;
    struct chart *c = &rv->phase;
    int n = app->model->n, W = 2 * c->canvas->cols, H = 4 * c->canvas->rows;
    phase_axes(c);
    canvas_clear(c->canvas);
    mark_frequencies(c->canvas, app);
    struct strokes *keep = c->canvas->strokes;
    c->canvas->mute++; /* the curves' strokes are kept unrounded below */
    for (int i = n - 1; i >= 0; i--) {
        int py = H;
        double pp = NAN;
        if (keep)
            strokes_begin(keep, (uint8_t)(PAIR_MASS + i % 10), STROKE_LINE);
        for (int x = 0; x < W && x < rv->width; x++) {
            double p = rv->phase_curve[(size_t)x * n + i];
            int y = phase_dot(c, p);
            bool joined = fabs(p - pp) < 180.0;
            if (py < H && y < H && joined)
                canvas_line(c->canvas, x - 1, py, x, y, (uint8_t)(PAIR_MASS + i % 10));
            else if (y < H)
                canvas_set(c->canvas, x, y, (uint8_t)(PAIR_MASS + i % 10));
            if (keep && !joined)
                strokes_point(keep, NAN, NAN);
            if (keep)
                strokes_point(keep, x, isfinite(p) ? chart_dot_yf(c, p) : NAN);
            py = y, pp = p;
        }
    }
    c->canvas->mute--;
    mark_points(c, app, sw->phase, phase_dotf);
}

/* The phase panel's legend: each mass's phase at the drive's frequency, in its colour,
 * into text[] (n + 1 entries of 24 bytes); returns the entries. */
static int phase_legend(const struct response_view *rv, const struct app *app,
                        char (*text)[24], struct legend_item *items)
{
    const struct model *m = app->model;
    const double *ph = rv->drive_phase;
    if (!rv->drive_phase_ok)
        return 0;
    int k = 0;
    snprintf(text[k], sizeof text[k], "at %.3f Hz", m->motor.frequency);
    items[k] = (struct legend_item){text[k], PAIR_MOTOR}, k++;
    for (int i = 0; i < m->n; i++, k++) {
        double deg = round(ph[i]);
        snprintf(text[k], sizeof text[k], "%d %.0f%s", i + 1, deg == 0.0 ? 0.0 : deg,
                 term_utf8() ? "°" : "");
        items[k] = (struct legend_item){text[k], PAIR_MASS + i % 10};
    }
    return k;
}

/* What a report figure of chart c says: its words on the log frequency axis, the masses'
 * names (measured points and theory), the drive's frequency. */
static void report_words(struct chart *c, const struct app *app, const char *title,
                         const char *ylabel, bool ylog)
{
    chart_report(c, title, report_frequency_label(app->model), ylabel);
    struct fig_report *r = &c->report;
    r->xfreq = true, r->fmin = APP_FMIN, r->fmax = APP_FMAX, r->ylog = ylog;
    for (int i = 0; i < app->model->n && i < 10; i++)
        snprintf(r->name[FIG_MASS + i], sizeof r->name[0], "mass %d", i + 1);
    snprintf(r->name[FIG_MOTOR], sizeof r->name[0], "drive %.3f Hz", app->model->motor.frequency);
}

/* What the sweep is doing, in the longest of its forms that fits in room columns (the
 * shortest if none does): the legend is never cut. */
static void sweep_state(const struct app *app, const struct sweep_plan *plan, int room,
                        char *buf, size_t len)
{
    const struct sweep *sw = app->sweep;
    int at = sw->index + 1, of = sw->points, got = sweep_measured(sw), bad = sw->unsteady;
    long hit = sw->contacts;
    const char *s = hit == 1 ? "" : "s", *ps = got == 1 ? "" : "s";
    double hz = sw->active ? sweep_frequency(sw) : app->model->motor.frequency;
    for (int form = 0; form < 4; form++) {
        if (sw->active && hit > 0)
            snprintf(buf, len, form == 0   ? "sweep %d/%d at %.3f Hz, %ld contact%s (w stops)"
                               : form == 1 ? "sweep %d/%d at %.3f Hz, %ld contact%s"
                               : form == 2 ? "%d/%d, %.3f Hz, %ld contact%s"
                                           : "%d/%d",
                     at, of, hz, hit, s);
        else if (sw->active)
            snprintf(buf, len, form == 0   ? "sweep %d/%d at %.3f Hz (w stops)"
                               : form == 1 ? "sweep %d/%d at %.3f Hz"
                               : form == 2 ? "sweep %d/%d"
                                           : "%d/%d",
                     at, of, hz);
        else if (got && hit > 0) /* contacts: the points are not the linear theory's */
            snprintf(buf, len, form == 0   ? "● %d point%s; %ld contact%s: off the linear theory"
                               : form == 1 ? "● %d point%s; %ld contact%s"
                               : form == 2 ? "● %d%s; %ld contact%s"
                                           : "● %d%s",
                     got, form == 2 || form == 3 ? "" : ps, hit, s);
        else if (got && bad > 0)
            snprintf(buf, len, form == 0   ? "● %d point%s, %d not steady (w sweeps again)"
                               : form == 1 ? "● %d point%s, %d not steady"
                               : form == 2 ? "● %d%s, %d not steady"
                                           : "● %d%s",
                     got, form == 2 || form == 3 ? "" : ps, bad);
        else if (got)
            snprintf(buf, len, form == 0   ? "● measured: %d point%s (w sweeps again)"
                               : form == 1 ? "● measured: %d point%s"
                               : form == 2 ? "● %d point%s"
                                           : "● %d%s",
                     got, form == 3 ? "" : ps);
        else if (plan->scale <= 1.0) {
            char words[80];
            sweeping_contact_words(app, plan, form, words, sizeof words);
            snprintf(buf, len, "%s%s", form == 0 ? "w: sweep; " : "", words);
        }
        else
            snprintf(buf, len, form == 0   ? "┃ drive %.3f Hz  ┊ modes  w: sweep"
                               : form == 1 ? "┃ drive %.3f Hz  ┊ modes"
                               : form == 2 ? "┃ drive %.3f Hz"
                                           : "┃ %.3f Hz",
                     hz);
        if (draw_width(buf) <= room)
            return;
    }
}

void response_view_draw(struct response_view *rv, const struct app *app, bool fresh)
{
    const struct model *m = app->model;
    struct chart *c = &rv->chart;
    int n = m->n;
    const char *title = m->cubic ? "Frequency response of the chain linearised at rest: "
                                   "amplitude (m) against frequency, log-log"
                                 : "Frequency response: steady-state amplitude (m) against "
                                   "frequency, log-log";
    bool motor = model_motor_moves(m);
    if ((!motor && !model_forced(m)) || !c->canvas) {
        /* The frame and the reason alone: no axis, curve or tick of a chain driven before
         * is left standing, and the canvas is clean for the next drive. */
        if (c->canvas)
            canvas_clear(c->canvas);
        rv->version = 0;
        struct rect f = c->frame;
        draw_frame(f, draw_width(title) + 4 <= f.w ? title : "Response", true);
        bool end = m->boundary != BOUNDARY_MOTOR;
        draw_text(f.y + 2, f.x + 3, f.w - 6, end ? "Nothing drives the chain:"
                                                  : "The motor's amplitude is 0 and no force acts:");
        draw_text(f.y + 3, f.x + 3, f.w - 6, end ? "choose Right end = motor, or a Force, to see its response."
                                                  : "raise the Amplitude or the Force to see its response.");
        if (rv->phase.frame.h > 0)
            draw_frame(rv->phase.frame, "Phase", true);
        return;
    }
    if (jump_two_way(m)) {
        branches_draw(rv, app, fresh);
        return;
    }
    if (rv->merged && !response_view_place(rv, rv->area))
        return;
    int W = 2 * c->canvas->cols;
    if (rv->version != app->version || rv->width != W) {
        solve_curves(rv, app, W);
        fresh = true;
    }
    if (fresh && rv->curve && rv->phase_curve) {
        draw_amplitude(rv, app);
        if (rv->phase.canvas)
            draw_phase(rv, app);
    }
    struct legend_item legend[11];
    int k = 0, keys = 0;
    for (int i = 0; i < n && i < 10; i++) {
        legend[k++] = (struct legend_item){mass_keys[i], PAIR_MASS + i};
        keys += draw_width(mass_keys[i]) + 1;
    }
    char state[120];
    int room = c->frame.w - 4; /* the masses' keys give way to the state where it needs */
    sweep_state(app, &rv->plan, room - (keys < room / 2 ? keys : room / 2), state, sizeof state);
    legend[k++] = (struct legend_item){state, PAIR_MOTOR};
    chart_draw(c, title, "Response (m) against Hz", "Hz", legend, k);
    report_words(c, app, "Frequency response", "steady-state amplitude (m)", true);
    if (rv->phase.frame.h > 0) {
        char text[APP_MAX_MASSES + 1][24];
        struct legend_item pl[APP_MAX_MASSES + 1];
        int np = phase_legend(rv, app, text, pl);
        chart_draw(&rv->phase, "Phase of each mass to the drive (degrees; a lag is negative)",
                   "Phase (deg)", "Hz", pl, np);
        report_words(&rv->phase, app, "Phase", "phase to the drive (°; a lag is negative)",
                     false);
        rv->phase.report.ylo = -180.0, rv->phase.report.yhi = 180.0;
        rv->phase.report.ystep = 90.0;
    }
}
