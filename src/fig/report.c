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

/* Legend entries "mass 1" .. "mass N" (as many as a line takes), then extra. */
static int mass_legend(struct fig_legend *lg, char (*text)[16], int n, int max)
{
    int k = 0;
    for (int i = 0; i < n && k < max; i++, k++) {
        snprintf(text[k], sizeof text[k], "mass %d", i + 1);
        lg[k] = (struct fig_legend){text[k], FIG_MASS + i % 10, false};
    }
    return k;
}

int report_headless(FILE *fp, enum fig_format f, struct report_data *d, int n, bool motor,
                    double t_end, const char *subtitle)
{
    report_data_finish(d);
    static const char *const ylabel[3] = {"displacement x (m)", "velocity v (m/s)",
                                          "acceleration a (m/s²)"};
    struct fig_series *s = malloc((size_t)(3 * n + 1) * sizeof *s);
    if (!s)
        return ENOMEM;
    struct fig_panel p[3];
    int k = 0;
    for (int q = 0; q < 3; q++) {
        int first = k;
        if (q == 0 && motor)
            s[k++] = line_of(d, 3 * n, FIG_MOTOR, true);
        for (int i = 0; i < n; i++)
            s[k++] = line_of(d, q * n + i, FIG_MASS + i % 10, false);
        p[q] = (struct fig_panel){.xlabel = "t (s)", .ylabel = ylabel[q], .xfixed = true,
                                  .xlo = 0.0, .xhi = t_end, .series = s + first,
                                  .nseries = k - first};
    }
    struct fig_legend lg[12];
    char text[12][16];
    int nl = mass_legend(lg, text, n, 11);
    if (motor)
        lg[nl++] = (struct fig_legend){"motor u(t)", FIG_MOTOR, true};
    struct fig_page pg = {"springsim --headless: displacement, velocity, acceleration",
                          subtitle, lg, nl, p, 3, 720.0, 860.0};
    int e = fig_write(fp, f, &pg);
    free(s);
    return e;
}

int report_modes(FILE *fp, enum fig_format f, const struct model *m, const double *freq,
                 const double *shapes, const char *subtitle)
{
    int n = m->n, shown = n < 10 ? n : 10, fixed = m->boundary != BOUNDARY_FREE;
    size_t w = (size_t)n + 2;
    double *xy = malloc(2 * w * (size_t)shown * sizeof *xy);
    struct fig_series s[10];
    struct fig_legend lg[10];
    char text[10][40];
    if (!xy)
        return ENOMEM;
    for (int j = 0; j < shown; j++) {
        double *x = xy + 2 * w * (size_t)j, *y = x + w;
        x[0] = 0.0, y[0] = 0.0; /* the left wall */
        for (int i = 0; i < n; i++)
            x[i + 1] = i + 1, y[i + 1] = shapes[(size_t)j * (size_t)n + (size_t)i];
        x[n + 1] = n + 1, y[n + 1] = 0.0; /* the right end, held for the modes */
        s[j] = (struct fig_series){.x = x, .y = y, .stride = 1, .count = n + 1 + fixed,
                                   .color = FIG_MASS + j % 10, .markers = n <= 40};
        snprintf(text[j], sizeof text[j], "mode %d: %.4g Hz", j + 1, freq[j]);
        lg[j] = (struct fig_legend){text[j], FIG_MASS + j % 10, false};
    }
    char title[96];
    snprintf(title, sizeof title, "springsim --modes: the shapes of the %s%d modes",
             shown < n ? "lowest " : "", shown);
    struct fig_panel p = {.xlabel = "mass (0: the left wall)",
                          .ylabel = "shape (largest |x| = 1)", .xfixed = true, .xlo = 0.0,
                          .xhi = n + 1, .series = s, .nseries = shown};
    struct fig_page pg = {title, subtitle, lg, shown, &p, 1, 720.0, 480.0};
    int e = fig_write(fp, f, &pg);
    free(xy);
    return e;
}

int report_sweep(FILE *fp, enum fig_format f, struct report_data *d, int n,
                 const char *subtitle)
{
    report_data_finish(d);
    struct fig_series *s = malloc((size_t)(2 * n) * sizeof *s);
    if (!s)
        return ENOMEM;
    for (int i = 0; i < 2 * n; i++)
        s[i] = line_of(d, i, FIG_MASS + i % n % 10, false);
    struct fig_panel p[2] = {
        {.xlabel = "motor frequency f (Hz)", .ylabel = "amplitude (m)", .xlog = true,
         .ylog = true, .series = s, .nseries = n},
        {.xlabel = "motor frequency f (Hz)", .ylabel = "phase (degrees; a lag is negative)",
         .xlog = true, .ylo = -180.0, .yhi = 180.0, .ystep = 90.0, .series = s + n,
         .nseries = n},
    };
    struct fig_legend lg[12];
    char text[12][16];
    int nl = mass_legend(lg, text, n, 12);
    struct fig_page pg = {"springsim --sweep: steady-state amplitude and phase", subtitle, lg,
                          nl, p, 2, 720.0, 700.0};
    int e = fig_write(fp, f, &pg);
    free(s);
    return e;
}
