/* report.c: what --figure draws for --headless, --modes and --sweep, and the rows it keeps
 * to draw them (min-max decimation, as a plot of many samples on few pixels is drawn). */
#include "report.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#define BUCKETS_MAX 2000 /* buckets a series is cut into, at most */
#define BUCKETS_MIN 50
#define EXT 5

struct report_data {
    int ns;       /* series */
    long k;       /* rows a bucket takes */
    int cap;      /* points each series has room for */
    int *count;   /* points kept, per series */
    double *pts;  /* (x, y) pairs, cap per series */
    long in;      /* rows in the current bucket */
    double *ext;  /* per series (EXT doubles): x and y of the bucket's smallest y, x and y
                   * of its largest, the y of the last row */
    bool *bad;    /* per series: the bucket had a value that is not finite */
    double last_x;
    long rows;    /* rows added */
};

struct report_data *report_data_new(int nseries, double rows)
{
    struct report_data *d = calloc(1, sizeof *d);
    if (!d)
        return NULL;
    long nb = REPORT_POINTS / (2L * nseries);
    nb = nb > BUCKETS_MAX ? BUCKETS_MAX : nb < BUCKETS_MIN ? BUCKETS_MIN : nb;
    if (!(rows >= 1.0))
        rows = 1.0;
    d->k = rows <= (double)nb ? 1 : (long)ceil(rows / (double)nb);
    d->ns = nseries;
    /* A bucket gives at most its smallest, its largest and a break; then the first and
     * last rows. */
    d->cap = 3 * ((int)ceil(rows / (double)d->k) + 2) + 2;
    d->count = calloc((size_t)nseries, sizeof *d->count);
    d->pts = malloc((size_t)nseries * (size_t)d->cap * 2 * sizeof *d->pts);
    d->ext = malloc((size_t)nseries * EXT * sizeof *d->ext);
    d->bad = calloc((size_t)nseries, sizeof *d->bad);
    if (!d->count || !d->pts || !d->ext || !d->bad) {
        report_data_free(d);
        return NULL;
    }
    return d;
}

void report_data_free(struct report_data *d)
{
    if (!d)
        return;
    free(d->count);
    free(d->pts);
    free(d->ext);
    free(d->bad);
    free(d);
}

long report_data_bucket(const struct report_data *d)
{
    return d->k;
}

int report_data_points(const struct report_data *d, int s, const double **xy)
{
    *xy = d->pts + (size_t)s * (size_t)d->cap * 2;
    return d->count[s];
}

/* Adds a point to series s, unless it is the row added last. */
static void push(struct report_data *d, int s, double x, double y)
{
    double *p = d->pts + ((size_t)s * (size_t)d->cap + (size_t)d->count[s]) * 2;
    if (d->count[s] >= d->cap || (d->count[s] > 0 && p[-2] == x && !isnan(p[-1]) && !isnan(y)))
        return;
    d->count[s]++;
    p[0] = x, p[1] = y;
}

/* Closes the current bucket: each series' smallest and largest, in time order. */
static void flush(struct report_data *d)
{
    if (d->in == 0)
        return;
    for (int s = 0; d->k > 1 && s < d->ns; s++) {
        const double *e = d->ext + EXT * s;
        if (isfinite(e[1])) {
            int first = e[0] <= e[2] ? 0 : 2;
            push(d, s, e[first], e[first + 1]);
            if (e[2 - first] != e[first])
                push(d, s, e[2 - first], e[3 - first]);
        }
        if (d->bad[s])
            push(d, s, d->last_x, NAN);
    }
    d->in = 0;
}

void report_data_add(struct report_data *d, double x, const double *y)
{
    for (int s = 0; s < d->ns; s++) {
        if (d->k == 1 || d->rows == 0) { /* every row, or the first */
            push(d, s, x, y[s]);
            if (d->k == 1)
                continue;
        }
        double *e = d->ext + EXT * s;
        e[4] = y[s];
        if (d->in == 0)
            e[1] = INFINITY, e[3] = -INFINITY, d->bad[s] = false;
        if (!isfinite(y[s]))
            d->bad[s] = true;
        else if (y[s] < e[1])
            e[0] = x, e[1] = y[s];
        if (isfinite(y[s]) && y[s] > e[3])
            e[2] = x, e[3] = y[s];
    }
    d->last_x = x;
    d->rows++;
    if (++d->in >= d->k)
        flush(d);
}

void report_data_finish(struct report_data *d)
{
    flush(d);
    for (int s = 0; d->k > 1 && d->rows > 0 && s < d->ns; s++)
        push(d, s, d->last_x, d->ext[EXT * s + 4]);
}

/* Series s of d as a figure series. */
static struct fig_series line_of(const struct report_data *d, int s, int color, bool dashed)
{
    const double *p = d->pts + (size_t)s * (size_t)d->cap * 2;
    return (struct fig_series){.x = p, .y = p + 1, .stride = 2, .count = d->count[s],
                               .color = color, .dashed = dashed};
}

/* A list of n values as "v" when they are all equal, else "lo–hi". */
static void list_text(const double *v, int n, char *buf, size_t len)
{
    double lo = v[0], hi = v[0];
    for (int i = 1; i < n; i++)
        lo = fmin(lo, v[i]), hi = fmax(hi, v[i]);
    if (lo == hi)
        snprintf(buf, len, "%g", lo);
    else
        snprintf(buf, len, "%g–%g", lo, hi);
}

void report_settings(const struct config *c, const struct model *m, char *buf, size_t len)
{
    char ms[48], ks[48], cs[48], drive[96];
    list_text(m->m, m->n, ms, sizeof ms);
    list_text(m->k, m->n + 1, ks, sizeof ks);
    list_text(m->c, m->n, cs, sizeof cs);
    if (m->boundary == BOUNDARY_MOTOR)
        snprintf(drive, sizeof drive, "motor: %s, %g m at %g Hz", motor_wave_name(m->motor.wave),
                 m->motor.amplitude, m->motor.frequency);
    else
        snprintf(drive, sizeof drive, "right end: %s", model_boundary_name(m->boundary));
    snprintf(buf, len, "%s%s%d mass%s, m %s kg, k %s N/m, c %s N·s/m; %s; %s, dt %g s",
             c->name[0] ? c->name : "", c->name[0] ? ": " : "", m->n, m->n == 1 ? "" : "es",
             ms, ks, cs, drive, integrator_name(c->integrator), c->dt);
}

struct report_look report_look_of(const struct config *c, const char *subtitle)
{
    return (struct report_look){c->figure_title, subtitle, c->figure_w, c->figure_h};
}

/* The page for look with npanels panels: its title (def unless replaced) and size. */
static struct fig_page page_of(const struct report_look *look, const char *def, int npanels)
{
    double w = look->w_mm > 0.0 ? look->w_mm : 160.0;
    double h = look->h_mm > 0.0 ? look->h_mm : 100.0 + 50.0 * (npanels - 1);
    return (struct fig_page){.title = look->title ? look->title : def,
                             .subtitle = look->subtitle, .width = w * FIG_MM,
                             .height = h * FIG_MM};
}

/* Legend entries "mass 1" .. "mass N", the first 10 of them (the colours repeat after
 * that, and the last entry says so). text has room for 11. */
static int mass_legend(struct fig_legend *lg, char (*text)[48], int n)
{
    int k = 0;
    for (int i = 0; i < n && i < 10; i++, k++) {
        snprintf(text[k], sizeof text[k], "mass %d", i + 1);
        lg[k] = (struct fig_legend){text[k], FIG_MASS + i % 10, false, false};
    }
    if (n > 10) {
        snprintf(text[k], sizeof text[k], "masses 11–%d: the same colours again", n);
        lg[k] = (struct fig_legend){text[k], FIG_GRID, false, false};
        k++;
    }
    return k;
}

enum { E_TERMS = 6 }; /* kinetic, potential, dissipated, motor work, contact, error */

int report_headless_series(int n, bool energy)
{
    return 3 * n + 1 + (energy ? E_TERMS : 0);
}

void report_headless_row(const struct sim *s, const double *a, bool energy,
                         double start_balance, double *row)
{
    int n = sim_model(s)->n;
    memcpy(row, sim_x(s), (size_t)n * sizeof *row);
    memcpy(row + n, sim_v(s), (size_t)n * sizeof *row);
    memcpy(row + 2 * n, a, (size_t)n * sizeof *row);
    row[3 * n] = sim_end_position(s);
    if (energy) {
        struct energy e;
        sim_energy(s, &e);
        double *t = row + 3 * n + 1;
        t[0] = e.kinetic, t[1] = e.potential, t[2] = e.dissipated, t[3] = e.motor_work;
        t[4] = e.contact, t[5] = e.balance - start_balance;
    }
}

/* The largest |value| series s of d holds. */
static double largest(const struct report_data *d, int s)
{
    const double *xy;
    int count = report_data_points(d, s, &xy);
    double most = 0.0;
    for (int k = 0; k < count; k++)
        if (isfinite(xy[2 * k + 1]))
            most = fmax(most, fabs(xy[2 * k + 1]));
    return most;
}

/* The energy panel's series (from series first of d) and its own legend. */
static void energy_panel(const struct report_data *d, int first, struct fig_series *s,
                         struct fig_legend *lg, char *error_text, size_t len)
{
    static const char *const name[E_TERMS - 1] = {"kinetic", "potential", "dissipated",
                                                  "motor work", "contact"};
    for (int i = 0; i < E_TERMS; i++)
        s[i] = line_of(d, first + i, fig_energy_color(i), i == E_TERMS - 1);
    for (int i = 0; i < E_TERMS - 1; i++)
        lg[i] = (struct fig_legend){name[i], fig_energy_color(i), false, false};
    snprintf(error_text, len, "balance error (largest %.2g J)", largest(d, first + E_TERMS - 1));
    lg[E_TERMS - 1] = (struct fig_legend){error_text, fig_energy_color(E_TERMS - 1), true, false};
}

int report_headless(FILE *fp, enum fig_format f, struct report_data *d, int n, bool motor,
                    bool energy, double t0, double t_end, const struct report_look *look)
{
    report_data_finish(d);
    static const char *const ylabel[4] = {"displacement x (m)", "velocity v (m/s)",
                                          "acceleration a (m/s²)", "energy (J)"};
    struct fig_series *s = malloc((size_t)(3 * n + 1 + E_TERMS) * sizeof *s);
    if (!s)
        return ENOMEM;
    struct fig_panel p[4];
    int k = 0, np = energy ? 4 : 3;
    for (int q = 0; q < 3; q++) {
        int first = k;
        if (q == 0 && motor)
            s[k++] = line_of(d, 3 * n, FIG_MOTOR, true);
        for (int i = 0; i < n; i++)
            s[k++] = line_of(d, q * n + i, FIG_MASS + i % 10, false);
        p[q] = (struct fig_panel){.xlabel = "t (s)", .ylabel = ylabel[q], .xfixed = true,
                                  .xlo = t0, .xhi = t_end, .series = s + first,
                                  .nseries = k - first};
    }
    struct fig_legend lg[12], elg[E_TERMS];
    char text[11][48], error_text[64];
    int nl = mass_legend(lg, text, n);
    if (motor)
        lg[nl++] = (struct fig_legend){"motor u(t)", FIG_MOTOR, true, false};
    if (energy) {
        energy_panel(d, 3 * n + 1, s + k, elg, error_text, sizeof error_text);
        p[3] = (struct fig_panel){.xlabel = "t (s)", .ylabel = ylabel[3], .xfixed = true,
                                  .xlo = t0, .xhi = t_end, .series = s + k,
                                  .nseries = E_TERMS, .legend = elg, .nlegend = E_TERMS};
    }
    struct fig_page pg = page_of(look, energy ? "Displacement, velocity, acceleration and "
                                                "energy"
                                              : "Displacement, velocity and acceleration", np);
    pg.legend = lg, pg.nlegend = nl, pg.panels = p, pg.npanels = np;
    int e = fig_write(fp, f, &pg);
    free(s);
    return e;
}

int report_modes(FILE *fp, enum fig_format f, const struct model *m, const double *freq,
                 const double *shapes, const struct report_look *look)
{
    int n = m->n, shown = n < 10 ? n : 10, fixed = m->boundary != BOUNDARY_FREE;
    size_t w = (size_t)n + 2;
    double *xy = malloc(2 * w * (size_t)shown * sizeof *xy);
    struct fig_series s[10];
    struct fig_legend lg[10];
    char text[10][40];
    if (!xy)
        return ENOMEM;
    /* One number of decimals for every frequency: four digits of the lowest. */
    double low = freq[0] > 0.0 ? freq[0] : 1.0;
    int dec = 3 - (int)floor(log10(low));
    dec = dec < 0 ? 0 : dec > 6 ? 6 : dec;
    for (int j = 0; j < shown; j++) {
        double *x = xy + 2 * w * (size_t)j, *y = x + w;
        x[0] = 0.0, y[0] = 0.0; /* the left wall */
        for (int i = 0; i < n; i++)
            x[i + 1] = i + 1, y[i + 1] = shapes[(size_t)j * (size_t)n + (size_t)i];
        x[n + 1] = n + 1, y[n + 1] = 0.0; /* the right end, held for the modes */
        s[j] = (struct fig_series){.x = x, .y = y, .stride = 1, .count = n + 1 + fixed,
                                   .color = FIG_MASS + j % 10, .markers = n <= 40};
        snprintf(text[j], sizeof text[j], "mode %d: %.*f Hz", j + 1, dec, freq[j]);
        lg[j] = (struct fig_legend){text[j], FIG_MASS + j % 10, false, false};
    }
    struct fig_panel p = {.xlabel = "mass (0: the left wall)",
                          .ylabel = "shape (largest |x| = 1)", .xfixed = true, .xwhole = true,
                          .xlo = 0.0, .xhi = n + 1, .series = s, .nseries = shown};
    char title[64];
    snprintf(title, sizeof title, "Mode shapes%s", shown < n ? ": the lowest ten" : "");
    struct fig_page pg = page_of(look, title, 1);
    pg.legend = lg, pg.nlegend = shown, pg.panels = &p, pg.npanels = 1;
    int e = fig_write(fp, f, &pg);
    free(xy);
    return e;
}

int report_sweep(FILE *fp, enum fig_format f, struct report_data *d, int n,
                 const struct report_look *look)
{
    report_data_finish(d);
    struct fig_series *s = malloc((size_t)(2 * n) * sizeof *s);
    if (!s)
        return ENOMEM;
    for (int i = 0; i < 2 * n; i++) {
        s[i] = line_of(d, i, FIG_MASS + i % n % 10, false);
        s[i].max_jump = i >= n ? 90.0 : 0.0;
    }
    struct fig_panel p[2] = {
        {.xlabel = "motor frequency f (Hz)", .ylabel = "amplitude (m)", .xlog = true,
         .ylog = true, .series = s, .nseries = n},
        {.xlabel = "motor frequency f (Hz)", .ylabel = "phase (°; a lag is negative)",
         .xlog = true, .ylo = -180.0, .yhi = 180.0, .ystep = 90.0, .series = s + n,
         .nseries = n},
    };
    struct fig_legend lg[11];
    char text[11][48];
    int nl = mass_legend(lg, text, n);
    struct fig_page pg = page_of(look, "Frequency response", 2);
    pg.legend = lg, pg.nlegend = nl, pg.panels = p, pg.npanels = 2;
    int e = fig_write(fp, f, &pg);
    free(s);
    return e;
}
