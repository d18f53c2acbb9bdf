/* preset_save.c: writing a configuration back as a preset file, in the format
 * preset.c reads: every key in its section, numbers with the digits that read back
 * exactly, long lists on indented lines. */
#include "preset.h"

#include <stdlib.h>
#include <string.h>

/* key = list, one value if all are equal, long lists wrapped onto indented lines. */
static void write_list(FILE *out, const char *key, const double *v, int n)
{
    int same = 1;
    for (int i = 1; i < n; i++)
        same &= v[i] == v[0];
    int col = fprintf(out, "%s =", key);
    for (int i = 0; i < (same ? 1 : n); i++) {
        char num[32];
        config_format_exact(v[i], num, sizeof num);
        if (col + (int)strlen(num) + 2 > 78) {
            fputs(i ? ",\n   " : "\n   ", out);
            col = 3;
        } else if (i) {
            fputc(',', out);
            col++;
        }
        col += fprintf(out, " %s", num);
    }
    fputc('\n', out);
}

static void write_number(FILE *out, const char *key, double v)
{
    char num[32];
    config_format_exact(v, num, sizeof num);
    fprintf(out, "%s = %s\n", key, num);
}

int preset_write(FILE *out, const struct config *c, const struct model *m)
{
    int n = m->n;
    fprintf(out, "; springsim preset\n[preset]\n");
    if (c->name[0])
        fprintf(out, "name = %s\n", c->name);
    if (c->description[0])
        fprintf(out, "description = %s\n", c->description);
    fprintf(out, "\n[system]\nmasses = %d\n", n);
    write_list(out, "mass", m->m, n);
    write_list(out, "spring", m->k, n + 1);
    write_list(out, "damping", m->c, n);
    write_number(out, "dt", c->dt);
    fprintf(out, "integrator = %s\n", integrator_name(c->integrator));
    fprintf(out, "no-collisions = %s\n", m->collisions ? "false" : "true");
    fprintf(out, "\n[motor]\nboundary = %s\nwave = %s\n", model_boundary_name(m->boundary),
            motor_wave_name(m->motor.wave));
    write_number(out, "amplitude", m->motor.amplitude);
    write_number(out, "frequency", m->motor.frequency);
    fprintf(out, "\n[initial]\n");
    if (c->start_mode > 0) {
        char amp[32];
        config_format_exact(c->start_amp, amp, sizeof amp);
        fprintf(out, "start-mode = %d:%s\n", c->start_mode, amp);
    } else if (c->random) {
        fprintf(out, "random = true\nseed = %llu\n", (unsigned long long)c->seed);
    } else {
        double *x = calloc((size_t)n, sizeof *x);
        if (!x)
            return -1;
        for (int i = 0; i < n; i++)
            x[i] = c->x0.count ? c->x0.v[c->x0.count == 1 ? 0 : i] : 0.0;
        write_list(out, "x0", x, n);
        for (int i = 0; i < n; i++)
            x[i] = c->v0.count ? c->v0.v[c->v0.count == 1 ? 0 : i] : 0.0;
        write_list(out, "v0", x, n);
        free(x);
    }
    fprintf(out, "\n[run]\n");
    write_number(out, "window", c->window);
    return ferror(out) ? -1 : 0;
}
