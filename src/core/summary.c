/* summary.c: the one-row summary of a headless run (--summary): peaks, rms and contacts
 * gathered step by step, then written as one CSV row after the settings that made it,
 * each named and read through its row of the settings table. */
#include "summary.h"

#include <math.h>
#include <stdlib.h>

#include "config.h"

struct summary {
    int n;          /* masses */
    double *max_x;  /* largest |x_i| so far (m) */
    double *sum_x2; /* sum of x_i^2 over the steps of the last half */
    double *max_v;  /* largest |v_i| so far (m/s) */
    double samples; /* steps in sum_x2 */
    double contacts; /* contacts resolved */
};

struct summary *summary_new(int n)
{
    struct summary *s = calloc(1, sizeof *s);
    double *v = calloc((size_t)(3 * n), sizeof *v);
    if (!s || !v) {
        free(s);
        free(v);
        return NULL;
    }
    *s = (struct summary){n, v, v + n, v + 2 * n, 0.0, 0.0};
    return s;
}

void summary_free(struct summary *s)
{
    if (s)
        free(s->max_x);
    free(s);
}

void summary_add(struct summary *s, const struct sim *sim, double step, double total)
{
    const double *x = sim_x(sim), *v = sim_v(sim);
    /* The steps with t > T/2: for an even count, the last total/2 of them, which span a
     * whole number of periods wherever T/2 does. */
    int rms = 2.0 * step > total || total == 0.0;
    for (int i = 0; i < s->n; i++) {
        s->max_x[i] = fmax(s->max_x[i], fabs(x[i]));
        s->max_v[i] = fmax(s->max_v[i], fabs(v[i]));
        if (rms)
            s->sum_x2[i] += x[i] * x[i];
    }
    s->samples += rms;
    if (step > 0.0)
        s->contacts += sim_last_contacts(sim) - sim_last_capped(sim);
}

/* The settings a study varies, in the order of the columns. */
static const enum config_key columns[] = {
    CFG_MASSES, CFG_MASS,       CFG_SPRING,         CFG_DAMPING,     CFG_FREQUENCY,
    CFG_AMPLITUDE, CFG_WAVE,    CFG_DT,             CFG_INTEGRATOR,  CFG_BOUNDARY,
    CFG_SPRING_DAMPING, CFG_SPRING_CUBIC, CFG_FORCE, CFG_FORCE_ON};
#define NCOLUMNS (int)(sizeof columns / sizeof *columns)

void summary_header(FILE *fp, int n)
{
    static const char *const groups[] = {"max_abs_x", "rms_x", "max_abs_v"};
    for (int k = 0; k < NCOLUMNS; k++)
        fprintf(fp, k ? ",%s" : "%s", config_options[columns[k]].name);
    for (int g = 0; g < 3; g++)
        for (int i = 1; i <= n; i++)
            fprintf(fp, ",%s%d", groups[g], i);
    fputs(",contacts,dissipated,motor_work,force_work\n", fp);
}

/* A list as --mass takes it, after sep: one value when all are equal, else all of them
 * in quotes (CSV's way of keeping the commas inside one field). */
static void write_list(FILE *fp, const char *sep, const double *v, int n)
{
    int same = 1;
    for (int i = 1; i < n; i++)
        same &= v[i] == v[0];
    fprintf(fp, same ? "%s" : "%s\"", sep);
    for (int i = 0; i < (same ? 1 : n); i++)
        fprintf(fp, i ? ",%.12g" : "%.12g", v[i]);
    if (!same)
        fputc('"', fp);
}

void summary_row(FILE *fp, const struct summary *s, const struct sim *sim)
{
    /* The settings as the sim ran them: its model's, and its step and integrator. */
    static struct config ran;
    config_init(&ran);
    ran.dt = sim_dt(sim);
    ran.integrator = sim_integrator(sim);
    struct energy e;
    sim_energy(sim, &e);
    for (int k = 0; k < NCOLUMNS; k++) {
        struct config_value v;
        config_get(columns[k], &ran, sim_model(sim), &v);
        if (v.count)
            write_list(fp, k ? "," : "", v.v, v.count);
        else
            fprintf(fp, "%s%s", k ? "," : "", v.str);
    }
    for (int i = 0; i < s->n; i++)
        fprintf(fp, ",%.12g", s->max_x[i]);
    for (int i = 0; i < s->n; i++)
        fprintf(fp, ",%.12g", s->samples > 0.0 ? sqrt(s->sum_x2[i] / s->samples) : 0.0);
    for (int i = 0; i < s->n; i++)
        fprintf(fp, ",%.12g", s->max_v[i]);
    fprintf(fp, ",%.0f,%.12g,%.12g,%.12g\n", s->contacts, e.dissipated, e.motor_work,
            e.force_work);
}

double summary_contacts(const struct summary *s)
{
    return s->contacts;
}

void summary_mass(const struct summary *s, int i, double *max_x, double *rms_x, double *max_v)
{
    *max_x = s->max_x[i];
    *rms_x = s->samples > 0.0 ? sqrt(s->sum_x2[i] / s->samples) : 0.0;
    *max_v = s->max_v[i];
}
