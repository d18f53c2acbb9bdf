/* view_branches.c: the response view of a chain with cubic springs (view_branches.h).
 * The frequency axis is linear over the sweep's range, where the folds are a few
 * per cent apart and a log axis of the whole drive range would put them in one column;
 * the amplitude axis is linear from 0, as the jump is drawn in the books. */
#include "view_branches.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "../app/sweeping.h"
#include "../fig/report.h"
#include "../chart/strokes.h"
#include "draw.h"
#include "term.h"

/* Dot column (unrounded) of frequency f. */
static double dot_x(const struct chart *c, double f)
{
    return axis_dot(&c->xa, f);
}

/* The curve's values of mass i: amplitude (phase false) or phase. */
static double curve_value(const struct jump_theory *t, int k, int i, bool phase)
{
    return (phase ? t->phase : t->amp)[(size_t)k * t->n + i];
}

/* The theory's branches of every mass: stable solid, unstable dashed; a phase curve is not
 * joined across +-180 degrees. */
static void draw_theory(struct chart *c, const struct jump_theory *t, bool phase)
{
    struct canvas *cv = c->canvas;
    cv->mute++; /* the strokes are kept unrounded below */
    for (int i = t->n - 1; i >= 0; i--) {
        uint8_t color = (uint8_t)(PAIR_MASS + i % 10);
        int run = 0;
        for (int k = 0; k + 1 < t->count; k++) {
            double v0 = curve_value(t, k, i, phase), v1 = curve_value(t, k + 1, i, phase);
            if ((t->f[k] < t->lo && t->f[k + 1] < t->lo) || (t->f[k] > t->hi && t->f[k + 1] > t->hi))
                continue;
            if (phase && fabs(v1 - v0) >= 180.0)
                continue;
            double fx0 = dot_x(c, t->f[k]), fx1 = dot_x(c, t->f[k + 1]);
            double fy0 = chart_dot_yf(c, v0), fy1 = chart_dot_yf(c, v1);
            int x0 = (int)lround(fx0), x1 = (int)lround(fx1), y0 = (int)lround(fy0),
                y1 = (int)lround(fy1);
            bool stable = t->rate[k] <= 0.0 && t->rate[k + 1] <= 0.0;
            if (stable)
                canvas_line(cv, x0, y0, x1, y1, color);
            else
                canvas_stroke(cv, x0, y0, x1, y1, color, &run);
            if (cv->strokes)
                strokes_segment(cv->strokes, fx0, fy0, fx1, fy1, color,
                                stable ? STROKE_LINE : STROKE_DASHED);
        }
    }
    cv->mute--;
}

/* The backbone of one mass, dotted: w^2 = (k + 3/4 k3 a^2) / m (k, k3 the two springs'
 * with the motor held), a dot every third dot row. */
static void draw_backbone(struct chart *c, const struct model *m)
{
    if (m->n != 1)
        return;
    double k = m->k[0] + (m->boundary == BOUNDARY_FREE ? 0.0 : m->k[1]);
    double k3 = m->k3[0] + (m->boundary == BOUNDARY_FREE ? 0.0 : m->k3[1]);
    struct canvas *cv = c->canvas;
    int H = 4 * cv->rows;
    cv->mute++; /* in pixels a dashed line in the drive's colour, not dots like points */
    if (cv->strokes)
        strokes_begin(cv->strokes, PAIR_MOTOR, STROKE_DASHED);
    for (int y = H - 1; y >= 0; y--) {
        double a = axis_value(&c->ya, 4 * c->area.h - 1 - y);
        double w2 = (k + 0.75 * k3 * a * a) / m->m[0];
        if (!(a >= 0.0 && w2 > 0.0))
            continue;
        double x = dot_x(c, sqrt(w2) / (2.0 * M_PI));
        if (y % 3 == 0)
            canvas_set(cv, (int)lround(x), y, PAIR_MASS);
        if (cv->strokes)
            strokes_point(cv->strokes, x, y);
    }
    cv->mute--;
}

/* Dotted verticals at the theory's folds, and the drive's frequency solid. */
static void draw_marks(struct chart *c, const struct jump_theory *t, double drive)
{
    int H = 4 * c->canvas->rows;
    c->canvas->mute++;
    for (int j = 0; j < t->folds; j++) {
        double x = dot_x(c, t->fold_f[j]);
        for (int y = 0; y < H; y += 2)
            canvas_set(c->canvas, (int)lround(x), y, PAIR_MOTOR);
        if (c->canvas->strokes)
            strokes_segment(c->canvas->strokes, x, 0, x, H - 1, PAIR_MOTOR, STROKE_DASHED);
    }
    c->canvas->mute--;
    canvas_vspan(c->canvas, (int)lround(dot_x(c, drive)), 0, H - 1, PAIR_MOTOR);
}

/* The measured points of sweep s (amplitudes, or phases) as dots, in pixels as triangles
 * (the sweep up's ▲, the sweep down's ▼, as the legend says), and its jump as a line from
 * the point before it to the point after. */
static void draw_points(struct chart *c, const struct sweep *s, bool phase, bool up)
{
    struct canvas *cv = c->canvas;
    int n = s->n;
    const double *v = phase ? s->phase : s->peak;
    for (int i = 0; i < n; i++) {
        uint8_t color = (uint8_t)(PAIR_MASS + i % 10);
        if (cv->strokes) {
            strokes_begin(cv->strokes, color, STROKE_MARKS);
            strokes_mark_size(cv->strokes, 3);
            strokes_mark_shape(cv->strokes, up ? MARK_UP : MARK_DOWN);
        }
        cv->mute++;
        for (int p = 0; p < sweep_measured(s); p++) {
            if (!isfinite(v[p * n + i]))
                continue;
            double x = dot_x(c, s->freq[p]), y = chart_dot_yf(c, v[p * n + i]);
            canvas_set(cv, (int)lround(x), (int)lround(y), color);
            if (cv->strokes)
                strokes_point(cv->strokes, x, y);
        }
        cv->mute--;
    }
    for (int k = phase ? -1 : jump_find(s, 0); k >= 0; k = jump_find(s, k + 1)) {
        int x = (int)lround(dot_x(c, 0.5 * (s->freq[k] + s->freq[k + 1])));
        for (int i = 0; i < n; i++)
            canvas_vspan(c->canvas, x, chart_dot_y(c, v[k * n + i]),
                         chart_dot_y(c, v[(k + 1) * n + i]), (uint8_t)(PAIR_MASS + i % 10));
    }
}

/* The glyph of a point of the sweep up (up true) or down at cell (cx, cy) of c, given the
 * other sweep's points: ◆ where both have one. */
static const char *glyph(const struct chart *c, const struct sweep *other, const double *v,
                         int cx, int cy, bool up)
{
    int n = other->n;
    for (int p = 0; p < sweep_measured(other); p++)
        for (int i = 0; i < n; i++)
            if (isfinite(v[p * n + i]) &&
                (int)lround(dot_x(c, other->freq[p])) / 2 == cx &&
                chart_dot_y(c, v[p * n + i]) / 4 == cy)
                return term_utf8() ? "◆" : "*";
    return term_utf8() ? (up ? "▲" : "▼") : (up ? "^" : "v");
}

/* Each measured point as a glyph over the drawing (text, so not in pixel mode): the sweep
 * up's ▲, the sweep down's ▼, ◆ where both fall in one cell. */
static void draw_glyphs(const struct chart *c, const struct sweep *up, const struct sweep *down,
                        bool phase)
{
    if (chart_pixels())
        return;
    for (int leg = 0; leg < 2; leg++) {
        const struct sweep *s = leg ? down : up, *other = leg ? up : down;
        const double *v = phase ? s->phase : s->peak, *ov = phase ? other->phase : other->peak;
        int n = s->n;
        for (int p = 0; p < sweep_measured(s); p++)
            for (int i = 0; i < n; i++) {
                if (!isfinite(v[p * n + i]))
                    continue;
                int cx = (int)lround(dot_x(c, s->freq[p])) / 2, cy = chart_dot_y(c, v[p * n + i]) / 4;
                if (cx < 0 || cx >= c->area.w || cy < 0 || cy >= c->area.h)
                    continue;
                draw_text_attr(c->area.y + cy, c->area.x + cx, 1,
                               term_attr(PAIR_MASS + i % 10) | A_BOLD,
                               glyph(c, other, ov, cx, cy, !leg));
            }
    }
}

/* Where each sweep jumped, over the drawing's top rows (the sweep up's on the first, the
 * sweep down's on the second): "↓0.84" for a drop, "↑0.80" for a rise, from the column
 * of the jump (a drop's to its right, a rise's to its left). */
static void draw_jump_labels(const struct chart *c, const struct sweep *up,
                             const struct sweep *down)
{
    for (int leg = 0; leg < 2; leg++) {
        const struct sweep *s = leg ? down : up;
        for (int k = jump_find(s, 0); k >= 0; k = jump_find(s, k + 1)) {
            double f = 0.5 * (s->freq[k] + s->freq[k + 1]);
            bool rises = jump_rises(s, k);
            char text[24];
            snprintf(text, sizeof text, "%s%.2f", rises ? "↑" : "↓", f);
            int w = draw_width(text), cx = (int)lround(dot_x(c, f)) / 2 - (rises ? w - 1 : 0);
            cx = cx < 0 ? 0 : cx + w > c->area.w ? c->area.w - w : cx;
            draw_text_attr(c->area.y + leg, c->area.x + cx, w, term_attr(PAIR_MOTOR) | A_BOLD,
                           text);
        }
    }
}

/* Jump k of s (-1: none) in words, its frequency with that many decimals. */
static void jump_words(const struct sweep *s, int k, int decimals, char *buf, size_t len)
{
    if (k < 0)
        snprintf(buf, len, "no jump");
    else
        snprintf(buf, len, "%s%.*f", jump_rises(s, k) ? "↑" : "↓", decimals,
                 0.5 * (s->freq[k] + s->freq[k + 1]));
}

/* What the sweep is doing, in the longest of its forms that fits in room columns. */
static void sweep_words(const struct app *app, int room, char *buf, size_t len)
{
    const struct sweep *s = app->sweep;
    const struct sweep *su = app->sweep_up;
    int ku = jump_find(su, 0), kd = jump_find(s, 0), got = sweep_measured(s);
    bool down = sweep_measured(su) > 0;
    char ju[24], jd[24]; /* each sweep's first jump */
    for (int form = 0; form < 3; form++) {
        jump_words(su, ku, form < 2 ? 3 : 2, ju, sizeof ju);
        jump_words(s, kd, form < 2 ? 3 : 2, jd, sizeof jd);
        if (s->active)
            snprintf(buf, len, form == 0 ? "sweeping %s %d/%d at %.3f Hz (w stops)"
                               : form == 1 ? "%s %d/%d at %.3f Hz" : "%s %d/%d",
                     down ? "down" : "up", s->index + 1, s->points, sweep_frequency(s));
        else if (got && down)
            snprintf(buf, len, form == 0 ? "jumped %s, %s Hz (w sweeps again)"
                               : form == 1 ? "jumped %s, %s Hz" : "%s %s", ju, jd);
        else if (got)
            snprintf(buf, len, form == 0 ? "▲ %d points, stopped (w sweeps again)"
                               : form == 1 ? "▲ %d points" : "▲ %d", got);
        else
            snprintf(buf, len, form == 0 ? "w: sweep up, then down" : form == 1 ? "w: sweep"
                                                                                : "w");
        if (draw_width(buf) <= room)
            return;
    }
}

/* The sweep up's points and the sweep down's: while the first sweep runs (or a linear
 * chain's lone sweep stands) it is the up one and there is no down one yet. */
static void legs(const struct app *app, const struct sweep **up, const struct sweep **down)
{
    bool two = sweep_measured(app->sweep_up) > 0;
    *up = two ? app->sweep_up : app->sweep;
    *down = two ? app->sweep : app->sweep_up;
}

static void draw_chart(struct response_view *rv, const struct app *app, struct chart *c,
                       bool phase)
{
    const struct jump_theory *t = &rv->hb;
    const struct sweep *up, *down;
    legs(app, &up, &down);
    chart_fix_x(c, t->lo, t->hi);
    if (phase) {
        chart_fix_y(c, -180.0, 180.0);
    } else {
        double top = t->top;
        for (int leg = 0; leg < 2; leg++) {
            const struct sweep *s = leg ? down : up;
            for (int p = 0; p < sweep_measured(s) * s->n; p++)
                top = isfinite(s->peak[p]) ? fmax(top, s->peak[p]) : top;
        }
        chart_fix_y(c, 0.0, top > 0.0 ? 1.05 * top : 1.0);
    }
    canvas_clear(c->canvas);
    draw_marks(c, t, app->model->motor.frequency);
    if (!phase)
        draw_backbone(c, app->model);
    draw_theory(c, t, phase);
    draw_points(c, up, phase, true);
    draw_points(c, down, phase, false);
}

void branches_draw(struct response_view *rv, const struct app *app, bool fresh)
{
    const struct model *m = app->model;
    struct chart *c = &rv->chart;
    uint64_t key = rv->hb_version != app->version ? jump_theory_key(m) : rv->hb_key;
    if (rv->hb_version != app->version && (rv->hb_version == 0 || key != rv->hb_key)) {
        struct sweep_plan plan;
        rv->hb_ok = sweeping_plan(app, &plan, rv->hb_why, sizeof rv->hb_why) == 0 &&
                    jump_theory_solve(&rv->hb, m, plan.lo, plan.hi, rv->hb_why,
                                      sizeof rv->hb_why) == 0;
        rv->hb_key = key;
        fresh = true;
    }
    rv->hb_version = app->version;
    /* A low view gives the phase's rows to the amplitude, where the jump is. */
    bool merge = rv->area.h < BRANCHES_PHASE_MIN_ROWS;
    if (merge && !rv->merged && rv->phase.frame.h > 0) {
        chart_free(&rv->phase);
        rv->phase.frame = (struct rect){0, 0, 0, 0};
        rv->merged = true;
        if (!chart_place(c, rv->area, 0))
            return;
        rv->version = 0;
    }
    if (rv->version != app->version) { /* placed afresh, or the linear view's */
        rv->version = app->version;
        fresh = true;
    }
    if (!rv->hb_ok) {
        canvas_clear(c->canvas);
        draw_frame(c->frame, "Harmonic balance", true);
        draw_text(c->frame.y + 2, c->frame.x + 3, c->frame.w - 6, rv->hb_why);
        if (rv->phase.frame.h > 0)
            draw_frame(rv->phase.frame, "Phase", true);
        return;
    }
    if (fresh) {
        draw_chart(rv, app, c, false);
        if (rv->phase.canvas)
            draw_chart(rv, app, &rv->phase, true);
    }
    const struct sweep *up, *down;
    legs(app, &up, &down);
    struct legend_item legend[6];
    char folds[48] = "", state[80];
    int k = 0, used = 0;
    legend[k++] = (struct legend_item){term_utf8() ? "▲ up" : "^ up", PAIR_MASS};
    legend[k++] = (struct legend_item){term_utf8() ? "▼ down" : "v down", PAIR_MASS};
    if (!chart_pixels()) /* text's one glyph a cell; pixels draw both triangles */
        legend[k++] = (struct legend_item){term_utf8() ? "◆ both" : "* both", PAIR_MASS};
    /* Every fold the range holds, as many as the legend's entry takes. */
    for (int j = 0, used_f = 0; j < rv->hb.folds && used_f < (int)sizeof folds - 12; j++)
        used_f += snprintf(folds + used_f, sizeof folds - (size_t)used_f, "%s %.3f",
                           j ? "" : rv->hb.folds > 1 ? "folds" : "fold", rv->hb.fold_f[j]);
    if (folds[0])
        snprintf(folds + strlen(folds), sizeof folds - strlen(folds), " Hz");
    if (folds[0])
        legend[k++] = (struct legend_item){folds, PAIR_MOTOR};
    for (int j = 0; j < k; j++)
        used += draw_width(legend[j].text) + 1;
    sweep_words(app, c->frame.w - 4 - used, state, sizeof state);
    legend[k++] = (struct legend_item){state, PAIR_MOTOR};
    chart_draw(c, m->n == 1 ? "Harmonic balance: amplitude (m), stable ━ unstable ┅ backbone ┄"
                            : "Harmonic balance: amplitude (m), stable ━ unstable ┅",
               "Harmonic balance (m)", "Hz", legend, k);
    chart_report(c, "Harmonic balance and the sweeps up and down", report_frequency_label(m),
                 "amplitude (m)");
    for (int i = 0; i < m->n && i < 10; i++)
        snprintf(c->report.name[FIG_MASS + i], sizeof c->report.name[0],
                 "mass %d", i + 1);
    snprintf(c->report.name[FIG_MOTOR], sizeof c->report.name[0],
             "drive; backbone, folds dashed");
    c->report.branches = true;
    draw_glyphs(c, up, down, false);
    draw_jump_labels(c, up, down);
    if (rv->phase.frame.h > 0) {
        chart_draw(&rv->phase, "Phase to the drive (degrees; a lag is negative), harmonic "
                   "balance", "Phase (deg)", "Hz", NULL, 0);
        chart_report(&rv->phase, "Phase", report_frequency_label(m),
                     "phase to the drive (°; a lag is negative)");
        rv->phase.report.branches = true;
        draw_glyphs(&rv->phase, up, down, true);
    }
}
