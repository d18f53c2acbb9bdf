/* view_report.c: what X writes: the charts on the screen as the panels of a report
 * figure, stacked, their curves the values their strokes were drawn from (each dot
 * coordinate mapped back through the axis it was laid on), in the report's words: a title
 * without the key digit, axis titles with units, the legend named, the cursors written. */
#include "view_report.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#define PANELS_MAX 8
#define LEGEND_MAX 16

/* The value at dot column d of chart c. */
static double x_value(const struct fig_chart *c, double d)
{
    const struct fig_report *r = c->report;
    int w = 2 * c->aw;
    if (r->xfreq)
        return r->fmin * pow(r->fmax / r->fmin, d / (w > 1 ? w - 1 : 1));
    return axis_value(&c->xa, d);
}

/* The value at dot row d (from the top) of chart c. */
static double y_value(const struct fig_chart *c, double d)
{
    double v = axis_value(&c->ya, 4 * c->ah - 1 - d);
    return c->report->ylog ? pow(10.0, v) : v;
}

/* Whether stroke s is part of the data: dots only in a mass's colour (points measured),
 * not a cursor's dotted line (the cursors are drawn as marks) nor the dotted stems and
 * lines that mark frequencies on the screen. */
static bool data_stroke(const struct stroke *s)
{
    return s->color != 0 &&
           (s->kind != STROKE_DOTS || (s->color >= FIG_MASS && s->color < FIG_MASS + 10));
}

/* Whether the motor's strokes of c move (a motor standing still is not drawn). */
static bool motor_moves(const struct fig_chart *c)
{
    const struct strokes *k = c->strokes;
    double first = NAN;
    for (int i = 0; i < k->ns; i++) {
        if (k->s[i].color != FIG_MOTOR)
            continue;
        for (int p = k->s[i].start; p < k->s[i].start + k->s[i].count; p++) {
            double y = k->xy[2 * p + 1];
            if (!isfinite(y))
                continue;
            if (isnan(first))
                first = y;
            else if (fabs(y - first) > 1e-6)
                return true;
        }
    }
    return false;
}

/* The series of chart c's strokes, their points into xy (2 doubles a point); returns how
 * many, at most max. */
static int chart_series(const struct fig_chart *c, double *xy, struct fig_series *out,
                        int max)
{
    const struct strokes *k = c->strokes;
    bool motor = motor_moves(c);
    int n = 0;
    for (int i = 0; i < k->ns && n < max; i++) {
        const struct stroke *s = &k->s[i];
        if (!data_stroke(s) || (s->color == FIG_MOTOR && !motor) || s->count < 1)
            continue;
        double *p = xy + 2 * (size_t)s->start;
        for (int q = 0; q < s->count; q++) {
            const double *d = k->xy + 2 * (size_t)(s->start + q);
            p[2 * q] = isfinite(d[0]) ? x_value(c, d[0]) : NAN;
            p[2 * q + 1] = isfinite(d[1]) ? y_value(c, d[1]) : NAN;
        }
        bool marks = s->kind == STROKE_MARKS || s->kind == STROKE_DOTS;
        bool upright = !marks && s->color == FIG_MOTOR; /* the drive's frequency */
        for (int q = 1; q < s->count && upright; q++)
            upright = k->xy[2 * (size_t)(s->start + q)] == k->xy[2 * (size_t)s->start];
        out[n++] = (struct fig_series){.x = p, .y = p + 1, .stride = 2, .count = s->count,
                                       .color = s->color, .dashed = s->kind == STROKE_DASHED,
                                       .no_line = marks, .vline = upright && s->count > 1};
    }
    return n;
}

/* Adds e to lg (nl entries) unless its text is there. */
static void add_once(struct fig_legend *lg, int *nl, struct fig_legend e)
{
    for (int i = 0; i < *nl; i++)
        if (strcmp(lg[i].text, e.text) == 0)
            return;
    if (*nl < LEGEND_MAX)
        lg[(*nl)++] = e;
}

/* Adds to lg (nl entries) what the series s of chart c are, each name once: the named
 * colours, then the ghost (the masses' colours dashed) and a sweep's points and lines. */
static void add_legend(const struct fig_chart *c, const struct fig_series *s, int ns,
                       struct fig_legend *lg, int *nl)
{
    bool ghost = false;
    for (int col = 1; col < FIG_COLOR_COUNT; col++) {
        const char *name = c->report->name[col];
        int solid = -1;
        for (int i = 0; i < ns; i++) {
            bool mass = s[i].color >= FIG_MASS && s[i].color < FIG_MASS + 10;
            if (s[i].color != col)
                continue;
            if (mass && s[i].dashed)
                ghost = true;
            else if (solid < 0 || (s[solid].no_line && !s[i].no_line))
                solid = i; /* a line rather than points */
        }
        if (name[0] && solid >= 0 && *nl < LEGEND_MAX - 3) /* the drive's line: upright */
            add_once(lg, nl, (struct fig_legend){name, col, s[solid].dashed, s[solid].no_line,
                                                 s[solid].vline});
    }
    bool points = false;
    for (int i = 0; i < ns; i++)
        points |= s[i].no_line;
    if (c->report->branches) { /* the jump view's: no ghost, two sweeps */
        add_once(lg, nl,
                 (struct fig_legend){.text = "harmonic balance, stable", .color = FIG_WALL});
        add_once(lg, nl,
                 (struct fig_legend){.text = "unstable", .color = FIG_WALL, .dashed = true});
        add_once(lg, nl, (struct fig_legend){.text = "measured: up large, down small",
                                             .color = FIG_WALL, .dot = true});
        return;
    }
    if (ghost)
        add_once(lg, nl, (struct fig_legend){.text = "ghost: dashed, each mass's colour",
                                             .color = FIG_MASS, .dashed = true});
    if (points) { /* a sweep's: the points measured on the lines of the theory */
        add_once(lg, nl, (struct fig_legend){.text = "measured", .color = FIG_WALL, .dot = true});
        add_once(lg, nl, (struct fig_legend){.text = "linear theory", .color = FIG_WALL});
    }
}

/* The page's title from the panels' (one: its own; more: "A, b and c"), the phase
 * portraits ("X against Y") said together where there are more than one. */
static void page_title(const struct fig_chart *const *c, int n, char *buf, size_t len)
{
    const char *part[PANELS_MAX];
    int np = 0, portraits = 0;
    for (int i = 0; i < n; i++)
        portraits += strstr(c[i]->report->title, " against ") != NULL;
    for (int i = 0; i < n; i++) {
        bool portrait = strstr(c[i]->report->title, " against ") != NULL;
        if (portraits < 2 || !portrait)
            part[np++] = c[i]->report->title;
        else if (np == 0 || strcmp(part[np - 1], "Phase portraits") != 0)
            part[np++] = "Phase portraits";
    }
    size_t at = 0;
    buf[0] = '\0';
    for (int i = 0; i < np && at < len; i++) {
        const char *sep = i == 0 ? "" : i + 1 == np ? " and " : ", ";
        int w = snprintf(buf + at, len - at, "%s%s", sep, part[i]);
        if (w < 0)
            break;
        if (i > 0 && at + strlen(sep) < len)
            buf[at + strlen(sep)] = (char)tolower((unsigned char)buf[at + strlen(sep)]);
        at += (size_t)w;
    }
}

/* Axis title t shortened to its symbol and unit ("displacement x (m)": "x (m)") into buf,
 * for panels too short for the whole; t itself where it has no symbol. */
static const char *short_label(const char *t, char *buf, size_t len)
{
    const char *paren = strstr(t, " (");
    const char *word = paren;
    while (word && word > t && word[-1] != ' ')
        word--;
    if (!paren || !word || word == t)
        return t;
    snprintf(buf, len, "%s", word);
    return buf;
}

int fig_view_report(FILE *fp, enum fig_format f, const struct fig_chart *charts, int n,
                    const struct report_look *look)
{
    const struct fig_chart *c[PANELS_MAX];
    int np = 0;
    size_t points = 0, strokes = 0;
    for (int i = 0; i < n && np < PANELS_MAX; i++)
        if (charts[i].report && charts[i].report->title[0] && charts[i].strokes) {
            c[np++] = &charts[i];
            points += (size_t)charts[i].strokes->n;
            strokes += (size_t)charts[i].strokes->ns;
        }
    if (np == 0)
        return EDOM;
    double *xy = malloc((points ? points : 1) * 2 * sizeof *xy);
    struct fig_series *s = malloc((strokes ? strokes : 1) * sizeof *s);
    if (!xy || !s) {
        free(xy);
        free(s);
        return ENOMEM;
    }
    struct fig_panel p[PANELS_MAX];
    struct fig_mark marks[PANELS_MAX][FIG_CURSORS];
    struct fig_legend lg[LEGEND_MAX];
    char shorter[PANELS_MAX][2][48];
    int nl = 0, used = 0;
    size_t at = 0;
    for (int i = 0; i < np; i++) {
        const struct fig_report *r = c[i]->report;
        int ns = chart_series(c[i], xy + 2 * at, s + used, (int)strokes - used);
        add_legend(c[i], s + used, ns, lg, &nl);
        bool brief = np > 3; /* panels too short for a whole axis title */
        p[i] = (struct fig_panel){.title = np > 1 ? r->title : NULL,
                                  .xlabel = brief ? short_label(r->xlabel, shorter[i][0], 48)
                                                  : r->xlabel,
                                  .ylabel = brief ? short_label(r->ylabel, shorter[i][1], 48)
                                                  : r->ylabel,
                                  .xlog = r->xfreq, .ylog = r->ylog,
                                  .xfixed = true, .series = s + used, .nseries = ns,
                                  .ystep = r->ystep, .ylo = r->ylo, .yhi = r->yhi};
        if (r->xfreq)
            p[i].xlo = r->fmin, p[i].xhi = r->fmax;
        else
            p[i].xlo = x_value(c[i], -0.5), p[i].xhi = x_value(c[i], 2 * c[i]->aw - 0.5),
            p[i].xexact = true;
        if (r->time && p[i].xlo < 0.0)
            p[i].xlo = 0.0;
        for (int k = 0; k < r->ncursors && k < FIG_CURSORS; k++) {
            struct fig_mark *m = &marks[i][k];
            m->x = r->cursor[k].x;
            m->nlines = r->cursor[k].nlines;
            for (int q = 0; q < m->nlines && q < FIG_MARK_LINES; q++)
                m->line[q] = r->cursor[k].line[q], m->color[q] = r->cursor[k].color[q];
        }
        p[i].marks = marks[i], p[i].nmarks = r->ncursors;
        used += ns;
        at += (size_t)c[i]->strokes->n;
    }
    /* The time plots on one span: each chart's axis reaches as far as its width on the
     * screen lets it, a little more or less than its neighbours'; on the page they show
     * the span all of them hold, one above the other. */
    double tlo = -INFINITY, thi = INFINITY;
    for (int i = 0; i < np; i++)
        if (c[i]->report->time)
            tlo = fmax(tlo, p[i].xlo), thi = fmin(thi, p[i].xhi);
    for (int i = 0; i < np && tlo < thi; i++)
        if (c[i]->report->time)
            p[i].xlo = tlo, p[i].xhi = thi;
    char title[200];
    page_title(c, np, title, sizeof title);
    double w = look->w_mm > 0.0 ? look->w_mm : 160.0;
    double h = look->h_mm > 0.0 ? look->h_mm : fmin(100.0 + 60.0 * (np - 1), 240.0);
    struct fig_page pg = {.title = look->title ? look->title : title, .subtitle = look->subtitle,
                          .legend = lg, .nlegend = nl, .panels = p, .npanels = np,
                          .width = w * FIG_MM, .height = h * FIG_MM};
    int e = fig_write(fp, f, &pg);
    free(xy);
    free(s);
    return e;
}
