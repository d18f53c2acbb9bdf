/* report.c: what --figure draws for --headless, --modes and --sweep, from the rows
 * report_data.c kept. Part of the figure library (loaded only when a figure is drawn). */
#include "report.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Series s of d as a figure series. */
static struct fig_series line_of(const struct report_data *d, int s, int color, bool dashed)
{
    const double *p;
    int count = report_data_points(d, s, &p);
    return (struct fig_series){.x = p, .y = p + 1, .stride = 2, .count = count,
                               .color = color, .dashed = dashed};
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
        lg[k] = (struct fig_legend){.text = text[k], .color = FIG_MASS + i % 10};
    }
    if (n > 10) {
        snprintf(text[k], sizeof text[k], "masses 11–%d: the same colours again", n);
        lg[k] = (struct fig_legend){.text = text[k], .color = FIG_GRID};
        k++;
    }
    return k;
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

/* The energy panel's series (from series first of d) and its own legend; the force's
 * work only where a force did some. How many series and legend items. */
static int energy_panel(const struct report_data *d, int first, struct fig_series *s,
                        struct fig_legend *lg, char *error_text, size_t len)
{
    static const char *const name[REPORT_E_TERMS - 1] = {"kinetic", "potential", "dissipated",
                                                  "motor work", "force work", "contact"};
    enum { FORCE = 4 };
    int last = REPORT_E_TERMS - 1, k = 0; /* last: the balance's error */
    for (int i = 0; i < REPORT_E_TERMS; i++) {
        if (i == FORCE && largest(d, first + i) == 0.0)
            continue;
        s[k] = line_of(d, first + i, fig_energy_color(i), i == last);
        if (i < last)
            lg[k] = (struct fig_legend){.text = name[i], .color = fig_energy_color(i)};
        k++;
    }
    snprintf(error_text, len, "balance error (largest %.2g J)", largest(d, first + last));
    lg[k - 1] = (struct fig_legend){.text = error_text, .color = fig_energy_color(last),
                                    .dashed = true};
    return k;
}

int report_headless(FILE *fp, enum fig_format f, struct report_data *d, int n, bool motor,
                    bool energy, double t0, double t_end, const struct report_look *look)
{
    report_data_finish(d);
    static const char *const ylabel[4] = {"displacement x (m)", "velocity v (m/s)",
                                          "acceleration a (m/s²)", "energy (J)"};
    struct fig_series *s = malloc((size_t)(3 * n + 1 + REPORT_E_TERMS) * sizeof *s);
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
        p[q] = (struct fig_panel){.xlabel = "time t (s)", .ylabel = ylabel[q], .xfixed = true,
                                  .xlo = t0, .xhi = t_end, .series = s + first,
                                  .nseries = k - first};
    }
    struct fig_legend lg[12], elg[REPORT_E_TERMS];
    char text[11][48], error_text[64];
    int nl = mass_legend(lg, text, n);
    if (motor)
        lg[nl++] = (struct fig_legend){.text = "motor u(t)", .color = FIG_MOTOR, .dashed = true};
    if (energy) {
        int ne = energy_panel(d, 3 * n + 1, s + k, elg, error_text, sizeof error_text);
        p[3] = (struct fig_panel){.xlabel = "time t (s)", .ylabel = ylabel[3], .xfixed = true,
                                  .xlo = t0, .xhi = t_end, .series = s + k, .nseries = ne,
                                  .legend = elg, .nlegend = ne};
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
        lg[j] = (struct fig_legend){.text = text[j], .color = FIG_MASS + j % 10};
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
    const char *xfreq = look->xfreq ? look->xfreq : "motor frequency f (Hz)";
    struct fig_panel p[2] = {
        {.xlabel = xfreq, .ylabel = "amplitude (m)", .xlog = true,
         .ylog = true, .series = s, .nseries = n},
        {.xlabel = xfreq, .ylabel = "phase (°; a lag is negative)",
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
