/* panel.c: the status line, the controls panel and the footer. */
#include "panel.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "../app/clock.h"
#include "../app/ghost.h"
#include "draw.h"
#include "term.h"

void panel_status(const struct layout *l, const struct app *app, bool behind)
{
    const struct model *m = app->model;
    const char *bar = "│";
    int d = app_time_decimals(app->cfg.dt);
    char motor[80], speed[64] = "", ghost[120] = "", line[520];
    /* While dt is past a limit the line says so, not only the message at the change
     * that put it there (the next key clears that). */
    const char *limit = limits_unstable(&app->limits)      ? "dt unstable"
                        : limits_rough_modes(&app->limits) ? "dt inaccurate"
                        : limits_rough_drive(&app->limits) ? "dt coarse for the drive"
                                                           : NULL;
    char past[48] = "";
    if (limit)
        snprintf(past, sizeof past, " %s %s", bar, limit);
    if (m->boundary == BOUNDARY_MOTOR)
        snprintf(motor, sizeof motor, "motor %s %.2f Hz %.2f m", motor_wave_name(m->motor.wave),
                 m->motor.frequency, m->motor.amplitude);
    else
        snprintf(motor, sizeof motor, "%s end", model_boundary_name(m->boundary));
    double pace = app_clock_pace(app);
    if (pace != 1.0 || behind || app->cfg.low_bandwidth)
        snprintf(speed, sizeof speed, " %s %gx%s%s", bar, pace, behind ? " behind" : "",
                 app->cfg.low_bandwidth ? " low refresh" : "");
    if (app->ghost) {
        /* The ghost by what differs from the live chain. */
        char what[100];
        ghost_describe(app, what, sizeof what);
        snprintf(ghost, sizeof ghost, " %s %s", bar, what);
    }
    /* The full line where it fits; the essentials (state, t, drive) where it does not. */
    snprintf(line, sizeof line, " springsim ▸ %-7s t = %.*f s %s %s %s N %d %s dt %.*f s%s %s "
             "history %d%s%s", app->running ? "Running" : "Paused", d, sim_time(app->sim), bar,
             motor, bar, m->n, bar, d > 3 ? d : 3, app->cfg.dt, past, bar,
             history_count(app->hist), speed, ghost);
    if (draw_width(line) > l->cols && m->boundary == BOUNDARY_MOTOR)
        snprintf(motor, sizeof motor, "motor %s %.2f Hz", motor_wave_name(m->motor.wave),
                 m->motor.frequency);
    /* The short form: the ghost by its name alone, then not at all (the plots' legends
     * still name it), rather than cut mid-word at the edge. */
    for (int form = 0; form < 3 && draw_width(line) > l->cols; form++) {
        if (form == 1 && app->ghost)
            snprintf(ghost, sizeof ghost, " %s ghost", bar);
        else if (form == 2)
            ghost[0] = '\0';
        snprintf(line, sizeof line, " %s t = %.*f s%s %s %s %s history %d%s%s",
                 app->running ? "Running" : "Paused", d, sim_time(app->sim), past, bar, motor,
                 bar, history_count(app->hist), speed, ghost);
    }
    attron(A_REVERSE);
    mvhline(l->status.y, 0, ' ', l->cols);
    int used = draw_text(l->status.y, 0, l->cols, line);
    const char *at = limit ? strstr(line, limit) : NULL;
    if (at) {
        /* The limit in the warning's colour, out of the reverse bar. */
        char before[520];
        snprintf(before, sizeof before, "%.*s", (int)(at - line), line);
        int x = draw_width(before);
        attroff(A_REVERSE);
        draw_text_attr(l->status.y, x, l->cols - x, term_attr(PAIR_WARN), limit);
        attron(A_REVERSE);
    }
    const char *right = "? help  q quit ";
    int rw = draw_width(right);
    if (used + rw + 2 <= l->cols)
        draw_text(l->status.y, l->cols - rw, rw, right);
    attroff(A_REVERSE);
}

/* The frequency range on a log scale, the natural frequencies marked and the drive on
 * it, on row y. */
static void frequency_bar(const struct rect r, int y, const struct app *app)
{
    const struct model *m = app->model;
    int x0 = r.x + 5, w = r.w - 11;
    draw_text(y, r.x + 1, 3, "0.1");
    mvhline(y, x0, draw_line(L_H), w);
    draw_text(y, x0 + w + 1, 3, "5Hz");
    attron(term_attr(PAIR_TITLE));
    for (int j = 0; j < m->n; j++) {
        double f = app->modes[j];
        if (f >= APP_FMIN && f <= APP_FMAX)
            mvaddch(y, x0 + (int)lround(app_freq_fraction(f) * (w - 1)),
                    term_utf8() ? draw_line(L_PLUS) : '|');
    }
    attroff(term_attr(PAIR_TITLE));
    double f = m->motor.frequency;
    if (f >= APP_FMIN && f <= APP_FMAX)
        draw_text_attr(y, x0 + (int)lround(app_freq_fraction(f) * (w - 1)), 1,
                       term_attr(PAIR_MOTOR) | A_BOLD, "●");
}

void panel_controls(const struct layout *l, const struct app *app, struct selection *sel)
{
    struct rect r = l->controls;
    draw_frame(r, "Controls", false);
    int last = r.y + r.h - 2; /* the last row inside the frame */
    /* Where they do not all fit, the list scrolls to the selected one and the frame
     * says how many are above and below. */
    int rows = layout_control_rows(l, CTL_COUNT), top = select_control_top(sel, rows, CTL_COUNT);
    for (int i = top; i < CTL_COUNT && i - top < rows; i++) {
        char value[96], line[160];
        app_control_value(app, (enum control)i, value, sizeof value);
        bool hot = sel->focus == FOCUS_CONTROLS && sel->control == i;
        snprintf(line, sizeof line, "%s%-10s %s", hot ? "▸" : " ",
                 app_control_label((enum control)i), value);
        char *mark = strstr(line, " ◆ f");
        if (mark && draw_width(line) > r.w - 3) /* off the border: "◆f10" */
            memmove(mark + strlen(" ◆"), mark + strlen(" ◆ "), strlen(mark + strlen(" ◆ ")) + 1);
        if (hot)
            attron(term_attr(PAIR_SELECT));
        mvhline(r.y + 1 + i - top, r.x + 1, ' ', r.w - 2);
        draw_text(r.y + 1 + i - top, r.x + 1, r.w - 2, line);
        if (hot)
            attroff(term_attr(PAIR_SELECT));
    }
    if (rows > 0 && rows < CTL_COUNT) {
        bool u = term_utf8();
        char more[40];
        if (top > 0) {
            snprintf(more, sizeof more, " %s %d more ", u ? "↑" : "^", top);
            draw_text(r.y, r.x + r.w - 1 - draw_width(more) - 1, draw_width(more), more);
        }
        if (top + rows < CTL_COUNT) {
            snprintf(more, sizeof more, " %s %d more ", u ? "↓" : "v", CTL_COUNT - top - rows);
            draw_text(r.y + r.h - 1, r.x + r.w - 1 - draw_width(more) - 1, draw_width(more),
                      more);
        }
    }
    int y = r.y + 1 + rows;
    if (y > last || !app->modes_ok)
        return;
    frequency_bar(r, y++, app);
    /* The natural frequencies, so resonance is checked, not guessed; a blank row before
     * them where there is room for it and the numbers. */
    if (last - y >= 2)
        y++;
    if (y > last)
        return;
    /* Their title where there is a row for it and one for the numbers; else the numbers
     * alone on the last row, "Hz" after them (80x24). */
    bool titled = last - y >= 1;
    if (titled)
        draw_text(y++, r.x + 2, r.w - 3, "natural frequencies (Hz)");
    int x = r.x + 2, n = app->model->n, end = r.x + r.w - 2;
    const char *ell = term_utf8() ? "…" : "...";
    for (int j = 0; j < n && y <= last; j++) {
        char num[32];
        app_fixed(app->modes[j], 3, num, sizeof num);
        int len = (int)strlen(num);
        if (x + len > end)
            x = r.x + 2, y++;
        /* On the last row, room for "…" after it unless it is the last number. */
        if (y > last || (y == last && j < n - 1 && x + len + 1 + draw_width(ell) > end)) {
            if (y > last)
                y = last; /* after the previous row's last number */
            draw_text(y, x <= end - draw_width(ell) ? x : end - draw_width(ell),
                      draw_width(ell), ell);
            return;
        }
        draw_text_attr(y, x, len, term_attr(PAIR_TITLE), num);
        x += len + 1;
    }
    if (!titled && y <= last && x + 2 <= r.x + r.w - 2)
        draw_text(y, x, 2, "Hz");
}

/* One hint: the key, then what it does. */
struct hint {
    const char *key, *what;
};

void panel_hints(const struct layout *l, const struct app *app, const struct hint_state *h)
{
    int y = l->hints.y;
    if (app->message[0]) {
        attr_t a = app->said != SAID_NOTE ? term_attr(PAIR_WARN) : A_BOLD;
        draw_text_attr(y, 1, l->cols - 1, a, app->message);
        return;
    }
    /* In order of importance; each one that does not fit is left out, not the rest. */
    struct hint hints[16];
    int n = 0;
    hints[n++] = (struct hint){h->space_key ? h->space_key : "space",
                               h->space ? h->space : app->running ? "pause" : "start"};
    if (h->cursor) {
        bool u = term_utf8();
        hints[n++] = (struct hint){u ? "←→" : "Left/Right", "cursor"};
        hints[n++] = (struct hint){"H L", "a tenth"};
        if (!app->running)
            hints[n++] = (struct hint){"PgUp PgDn", "scroll"};
        hints[n++] = (struct hint){"|", app->scope.cursors == 1 ? "second" : "none"};
        hints[n++] = (struct hint){"Esc", "none"};
        if (app->model->n > 1)
            hints[n++] = (struct hint){u ? "↑↓" : "Up/Down", "mass"};
        hints[n++] = (struct hint){"?", "help"};
        goto draw;
    }
    if (h->modes) {
        hints[n++] = (struct hint){term_utf8() ? "↑↓" : "arrows", "mode"};
        hints[n++] = (struct hint){"Enter", "start in it"};
    }
    hints[n++] = (struct hint){".", h->dot ? h->dot : "step"};
    if (h->comma)
        hints[n++] = (struct hint){",", h->comma};
    if (h->view)
        hints[n++] = (struct hint){"m f e F", "views (again: plots)"};
    else
        hints[n++] = (struct hint){"m f e F", "views"};
    if (h->modes)
        hints[n++] = (struct hint){"Tab", "controls"};
    if (h->enlarged >= 0)
        hints[n++] = (struct hint){"0", "all plots"};
    else if (!h->view)
        hints[n++] = (struct hint){"1-6", "enlarge"};
    hints[n++] = (struct hint){"<>", "window"};
    if (!app->running && !h->comma)
        hints[n++] = (struct hint){",", "back"};
    hints[n++] = (struct hint){"r", "reset"};
    hints[n++] = (struct hint){"p", "presets"};
    if (!h->modes) {
        hints[n++] = (struct hint){term_utf8() ? "↑↓←→" : "arrows", "controls"};
        hints[n++] = (struct hint){"Enter", "type"};
        hints[n++] = (struct hint){"Tab", "masses"};
    }
    hints[n++] = (struct hint){"?", "help"};
draw:;
    int x = 1;
    for (int i = 0; i < n; i++) {
        int need = draw_width(hints[i].key) + 1 + draw_width(hints[i].what);
        if (x + need > l->cols - 1)
            continue;
        x += draw_text_attr(y, x, need, A_BOLD, hints[i].key) + 1;
        x += draw_text(y, x, l->cols - x, hints[i].what) + 2;
    }
}

/* The message below the minimum size, cut to fit any size. */
void panel_too_small(const struct layout *l)
{
    char msg[2][64];
    /* The longest wording that fits: the size wanted is never cut. */
    static const char *const what[] = {"Terminal too small", "too small", "small"};
    int k = 0;
    while (k < 2 && (int)strlen(what[k]) > l->cols)
        k++;
    snprintf(msg[0], sizeof msg[0], "%s", what[k]);
    snprintf(msg[1], sizeof msg[1], "need %dx%d, have %dx%d", LAYOUT_MIN_COLS, LAYOUT_MIN_ROWS,
             l->cols, l->rows);
    if ((int)strlen(msg[1]) > l->cols)
        snprintf(msg[1], sizeof msg[1], "need %dx%d", LAYOUT_MIN_COLS, LAYOUT_MIN_ROWS);
    if ((int)strlen(msg[1]) > l->cols)
        snprintf(msg[1], sizeof msg[1], "%dx%d", LAYOUT_MIN_COLS, LAYOUT_MIN_ROWS);
    for (int i = 0; i < 2; i++) {
        int len = (int)strlen(msg[i]) < l->cols ? (int)strlen(msg[i]) : l->cols;
        int y = l->rows / 2 - (l->rows > 1) + i;
        if (y >= 0 && y < l->rows)
            mvaddnstr(y, (l->cols - len) / 2, msg[i], len);
    }
}
