/* report_data.c: what a figure of --headless, --modes or --sweep is made from, kept while
 * the run goes (min-max decimation, as a plot of many samples on few pixels is drawn), and
 * the words around it (the settings line, the look asked for). Drawing it is report.c's, in
 * the figure library the program loads only when a figure is asked for. */
#include "report.h"

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
    char ms[48], ks[48], k3s[64] = "", cs[48], css[80] = "", drive[96], force[96] = "";
    list_text(m->m, m->n, ms, sizeof ms);
    list_text(m->k, m->n + 1, ks, sizeof ks);
    list_text(m->c, m->n, cs, sizeof cs);
    if (m->cubic) {
        char v[48];
        list_text(m->k3, m->n + 1, v, sizeof v);
        snprintf(k3s, sizeof k3s, ", k3 %s N/m³", v);
    }
    if (m->spring_damped) {
        char v[48];
        list_text(m->cs, m->n + 1, v, sizeof v);
        snprintf(css, sizeof css, ", spring dampers %s N·s/m", v);
    }
    if (m->boundary == BOUNDARY_MOTOR)
        snprintf(drive, sizeof drive, "motor: %s, %g m at %g Hz",
                 motor_wave_name(m->motor.wave), m->motor.amplitude, m->motor.frequency);
    else
        snprintf(drive, sizeof drive, "right end: %s", model_boundary_name(m->boundary));
    if (model_forced(m))
        snprintf(force, sizeof force, "; force: %s, %g N at %g Hz on mass %d",
                 motor_wave_name(m->motor.wave), m->force, m->motor.frequency, m->force_on + 1);
    snprintf(buf, len, "%s%s%d mass%s, m %s kg, k %s N/m%s, c %s N·s/m%s; %s%s; %s, dt %g s",
             c->name[0] ? c->name : "", c->name[0] ? ": " : "", m->n, m->n == 1 ? "" : "es",
             ms, ks, k3s, cs, css, drive, force, integrator_name(c->integrator), c->dt);
}

const char *report_frequency_label(const struct model *m)
{
    bool motor = model_motor_moves(m), force = model_forced(m);
    if (force && !motor)
        return "force frequency f (Hz)";
    return motor && !force ? "motor frequency f (Hz)" : "drive frequency f (Hz)";
}

struct report_look report_look_of(const struct config *c, const char *subtitle)
{
    return (struct report_look){c->figure_title, subtitle, c->figure_w, c->figure_h, NULL};
}

int report_headless_series(int n, bool energy)
{
    return 3 * n + 1 + (energy ? REPORT_E_TERMS : 0);
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
        t[4] = e.force_work, t[5] = e.contact, t[6] = e.balance - start_balance;
    }
}
