/* readout.c: the cursors' readout (t, every mass's x, v, a and the motor at the cursor;
 * with two, Δt, 1/Δt and each Δx) in the masses' colours, and the measurements of the
 * mass measured over the window. Rows go by importance where the column is short; a
 * line that must be cut ends in "…". */
#include "readout.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "../app/scope.h"
#include "../app/scope_text.h"
#include "draw.h"
#include "term.h"

#define LINE 160 /* bytes of one row's text */

/* Draws s in w columns at (y, x) in attribute a, ending in "…" if it had to be cut. */
static void fit(int y, int x, int w, attr_t a, const char *s)
{
    if (draw_width(s) <= w) {
        draw_text_attr(y, x, w, a, s);
        return;
    }
    int ell = draw_width("…");
    draw_text_attr(y, x, w - ell, a, s);
    draw_text_attr(y, x + w - ell, ell, a, "…");
}

/* The first of alternatives (most to least said) that fits w columns. */
static const char *first_fitting(const char *const *alt, int n, int w)
{
    for (int i = 0; i < n - 1; i++)
        if (draw_width(alt[i]) <= w)
            return alt[i];
    return alt[n - 1];
}

/* Row text: a label, then three numbers right-aligned in columns of cw. */
static void row3(char *buf, const char *label, const double v[3], int cw)
{
    char num[3][32];
    for (int k = 0; k < 3; k++)
        scope_number(num[k], sizeof num[k], v[k], cw - 1);
    snprintf(buf, LINE, "%-2s%*s%*s%*s", label, cw, num[0], cw, num[1], cw, num[2]);
}

/* The driven steady state's rows: measured beside the theory's. */
static int steady_lines(const struct scope_motion *sm, char lines[][LINE])
{
    const struct measure_drive *d = &sm->d;
    char a[32], b[32];
    int n = 0;
    snprintf(lines[n++], LINE, "%-8s%10s%10s", "", "measured", sm->linearised ? "linear" : "theory");
    scope_number(a, sizeof a, d->amplitude, 9);
    scope_number(b, sizeof b, sm->theory_ratio * d->drive, 9);
    snprintf(lines[n++], LINE, "%-8s%10s%10s", "amp m", a, b);
    snprintf(a, sizeof a, "%.1f", d->phase);
    snprintf(b, sizeof b, "%.1f", sm->theory_phase);
    snprintf(lines[n++], LINE, "%-8s%10s%10s", term_utf8() ? "phase °" : "phase deg", a, b);
    scope_number(a, sizeof a, d->ratio, 9), scope_number(b, sizeof b, sm->theory_ratio, 9);
    snprintf(lines[n++], LINE, "%-8s%10s%10s", sm->by_force ? "m/N" : "ratio", a, b);
    return n;
}

/* The measurements' rows, most important first, into lines; how many. */
static int measure_lines(const struct app *app, const struct scope_view *v, int i,
                         char lines[][LINE])
{
    struct scope_motion sm;
    const struct measure *m = &sm.m;
    char a[32], b[32];
    int n = 0;
    scope_motion(app, v, i, &sm);
    snprintf(lines[n++], LINE, "measured: mass %d %s", i + 1,
             app->model->n > 1 ? (term_utf8() ? "(↑↓)" : "(Up/Down)") : "");
    if (sm.kind == MOTION_TRANSIENT) {
        snprintf(lines[n++], LINE, "transient: %s", scope_peaks_word(m));
        snprintf(lines[n++], LINE, "not a free decay, not steady");
    } else if (sm.kind == MOTION_STEADY) {
        snprintf(lines[n++], LINE, "%s (±%g %%)", scope_motion_name(&sm), 100.0 * MEASURE_LEVEL);
    } else if (sm.kind == MOTION_DECAY) {
        snprintf(lines[n++], LINE, "free decay: peaks falling");
    } else {
        snprintf(lines[n++], LINE, m->peaks < 2 ? "not enough peaks (%d)" :
                 "driven: too few periods shown", m->peaks);
    }
    if (sm.kind == MOTION_STEADY && sm.driven)
        n += steady_lines(&sm, lines + n);
    if (m->peaks >= 2) {
        scope_number(a, sizeof a, m->period, 8), scope_number(b, sizeof b, m->frequency, 8);
        snprintf(lines[n++], LINE, "T %s s  f %s Hz", a, b);
    }
    if (sm.kind == MOTION_DECAY) {
        scope_number(a, sizeof a, m->delta, 8), scope_number(b, sizeof b, m->zeta, 8);
        snprintf(lines[n++], LINE, "δ %s  ζ %s", a, b);
    }
    if ((sm.kind == MOTION_DECAY || (sm.kind == MOTION_STEADY && !sm.driven)) &&
        sm.mode >= 0 && !isnan(sm.theory_zeta)) {
        scope_number(a, sizeof a, sm.theory_zeta, 8);
        snprintf(lines[n++], LINE, "theory ζ %s (mode %d)", a, sm.mode + 1);
    }
    scope_number(a, sizeof a, m->p2p, 8), scope_number(b, sizeof b, m->rms, 8);
    snprintf(lines[n++], LINE, "p-p %s m  rms %s m", a, b);
    return n;
}

/* The span shown: its ends, and live or how far back. */
static const char *span_text(const struct scope_view *v, double now, int w, char *buf,
                             char *alt)
{
    if (v->live) {
        snprintf(buf, LINE, "shown %.1f–%.1f s, live", fmax(v->start, 0.0), v->end);
        snprintf(alt, LINE, "%.1f–%.1f s live", fmax(v->start, 0.0), v->end);
    } else {
        snprintf(buf, LINE, "shown %.1f–%.1f s, %.1f s back", v->start, v->end, now - v->end);
        snprintf(alt, LINE, "%.1f–%.1f s, back", v->start, v->end);
    }
    const char *const forms[2] = {buf, alt};
    return first_fitting(forms, 2, w);
}

/* The cursors' times (with two, the difference too), the columns' header and the
 * motor's row. */
static void heads(const double *c0, const double *c1, int d, int cw, char head[2][LINE],
                  char *hdr, char *motor)
{
    /* The cursors' times, and with two the difference. */
    if (c1) {
        double dt = c1[TRAIL_T] - c0[TRAIL_T];
        char a[32], b[32];
        snprintf(head[0], LINE, "t1 %.*f s  t2 %.*f s", d, c0[TRAIL_T], d, c1[TRAIL_T]);
        scope_number(a, sizeof a, dt, 9);
        scope_number(b, sizeof b, dt != 0.0 ? 1.0 / fabs(dt) : NAN, 9);
        snprintf(head[1], LINE, "Δt %s s  1/Δt %s Hz", a, b);
    } else {
        snprintf(head[0], LINE, "t %.*f s", d, c0[TRAIL_T]);
    }
    const char *const labels[2][3] = {{"x m", "v m/s", "a m/s²"}, {"x@1", "x@2", "Δx"}};
    const char *const *lab = labels[c1 != NULL];
    char cols[3][32];
    for (int k = 0; k < 3; k++) {
        /* right-aligned by columns drawn, which UTF-8 and ASCII count differently */
        int pad = cw - draw_width(lab[k]);
        snprintf(cols[k], sizeof cols[k], "%*s%s", pad > 0 ? pad : 0, "", lab[k]);
    }
    snprintf(hdr, LINE, "  %s%s%s", cols[0], cols[1], cols[2]);
    if (c1) {
        double u[3] = {c0[TRAIL_U], c1[TRAIL_U], c1[TRAIL_U] - c0[TRAIL_U]};
        row3(motor, "u", u, cw);
    } else {
        char num[32];
        scope_number(num, sizeof num, c0[TRAIL_U], cw - 1);
        snprintf(motor, LINE, "u %*s", cw, num);
    }
}

/* Mass i's row: x, v, a at the cursor (with two: x at each and the difference), in its
 * colour; its number in reverse when it is the mass measured. */
static void mass_row(int y, int x, int w, int cw, const struct trail *tr, const double *c0,
                     const double *c1, int i, bool measured)
{
    char line[LINE], label[16];
    snprintf(label, sizeof label, "%d", i + 1);
    double vals[3] = {c0[TRAIL_X(tr, i)], c0[TRAIL_V(tr, i)], c0[TRAIL_A(tr, i)]};
    if (c1) {
        vals[1] = c1[TRAIL_X(tr, i)];
        vals[2] = c1[TRAIL_X(tr, i)] - c0[TRAIL_X(tr, i)];
    }
    row3(line, label, vals, cw);
    attr_t a = term_attr(PAIR_MASS + i % 10);
    fit(y, x, w, a, line);
    if (measured)
        draw_text_attr(y, x, 2, a | A_REVERSE, label);
}

void readout_draw(const struct layout *l, const struct app *app)
{
    struct rect r = l->controls;
    const struct scope *s = &app->scope;
    struct scope_view v;
    scope_view(app, &v);
    int nc = s->cursors;
    draw_frame(r, nc == 2 ? "Cursors" : "Cursor", false);
    int w = r.w - 2, x = r.x + 1, top = r.y + 1, rows = r.h - 2;
    const double *c0 = scope_record(app, &v, 0), *c1 = nc == 2 ? scope_record(app, &v, 1) : NULL;
    if (!c0 || rows < 1) {
        fit(top, x, w, 0, "no samples in the window");
        return;
    }
    const struct trail *tr = v.trail;
    int n = tr->n, mass = scope_mass(app), cw = (w - 2) / 3;
    int d = app_time_decimals(app->cfg.dt);
    char head[2][LINE], span[2][LINE], hdr[LINE], motor[LINE];
    char meas[12][LINE];
    int nm = measure_lines(app, &v, mass, meas);
    heads(c0, c1, d, cw, head, hdr, motor);
    const char *spant = span_text(&v, sim_time(app->sim), w, span[0], span[1]);
    /* Rows by importance: the times, the header and the mass measured, the measurements,
     * the span, the motor, the other masses, a blank before the measurements. */
    int left = rows;
    int nhead = c1 ? 2 : 1;
    left -= nhead + 2;
    int nmeas = left > 0 ? (left < nm ? left : nm) : 0;
    left -= nmeas;
    bool show_span = left > 0;
    left -= show_span;
    bool show_motor = left > 0;
    left -= show_motor;
    int mrows = 1 + (left > 0 ? (left < n - 1 ? left : n - 1) : 0);
    left -= mrows - 1;
    bool blank = left > 0 && nmeas > 0;
    bool cut = mrows < n;
    /* With masses left out, the last row says so (when there are two or more). */
    int shown = cut && mrows >= 2 ? mrows - 1 : mrows;
    int first = mass - (shown - 1) / 2;
    first = first < 0 ? 0 : first > n - shown ? n - shown : first;
    int y = top;
    for (int k = 0; k < nhead; k++)
        fit(y++, x, w, A_BOLD, head[k]);
    if (show_span)
        fit(y++, x, w, 0, spant);
    fit(y++, x, w, 0, hdr);
    for (int i = first; i < first + shown; i++)
        mass_row(y++, x, w, cw, tr, c0, c1, i, i == mass && n > 1);
    if (cut && shown < mrows) {
        char more[LINE];
        snprintf(more, LINE, "… %d more masses (%s)", n - shown, term_utf8() ? "↑↓" : "Up/Down");
        fit(y++, x, w, 0, more);
    }
    if (show_motor)
        fit(y++, x, w, term_attr(PAIR_MOTOR), motor);
    if (blank)
        y++;
    for (int k = 0; k < nmeas; k++)
        fit(y++, x, w, k == 0 ? A_BOLD : 0, meas[k]);
}
