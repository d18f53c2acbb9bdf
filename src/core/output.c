/* output.c: atomic output files and the headless CSV. */
#include "output.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

int output_open(struct output *o, const char *path)
{
    struct stat st;
    memset(o, 0, sizeof *o);
    if (!path || strcmp(path, "-") == 0) {
        o->fp = stdout;
        return 0;
    }
    if (stat(path, &st) == 0 && !S_ISREG(st.st_mode)) {
        if (S_ISDIR(st.st_mode))
            return EISDIR;
        o->fp = fopen(path, "w");
        return o->fp ? 0 : errno;
    }
    size_t n = strlen(path);
    o->path = strdup(path);
    o->tmp = malloc(n + 16);
    if (!o->path || !o->tmp) {
        free(o->path);
        free(o->tmp);
        o->path = o->tmp = NULL;
        return ENOMEM;
    }
    snprintf(o->tmp, n + 16, "%s.tmp-XXXXXX", path);
    int fd = mkstemp(o->tmp);
    if (fd < 0) {
        int e = errno;
        free(o->path);
        free(o->tmp);
        o->path = o->tmp = NULL;
        return e;
    }
    /* mkstemp makes 0600; give the file the mode a plain creat() would. */
    mode_t mask = umask(0);
    umask(mask);
    fchmod(fd, 0666 & ~mask);
    if (stat(path, &st) == 0)
        fchmod(fd, st.st_mode & 07777);
    o->fp = fdopen(fd, "w");
    if (!o->fp) {
        int e = errno;
        close(fd);
        unlink(o->tmp);
        free(o->path);
        free(o->tmp);
        o->path = o->tmp = NULL;
        return e;
    }
    return 0;
}

int output_close(struct output *o, bool commit)
{
    int err = 0;
    if (!o->fp)
        return 0;
    if (fflush(o->fp) != 0 || ferror(o->fp))
        err = errno ? errno : EIO;
    if (o->fp == stdout) {
        o->fp = NULL;
        return err;
    }
    if (o->tmp && !err && commit && fsync(fileno(o->fp)) != 0)
        err = errno;
    if (fclose(o->fp) != 0 && !err)
        err = errno;
    o->fp = NULL;
    if (o->tmp) {
        if (!err && commit && rename(o->tmp, o->path) != 0)
            err = errno;
        if (err || !commit)
            unlink(o->tmp);
        free(o->tmp);
        free(o->path);
        o->tmp = o->path = NULL;
    }
    return err;
}

void output_csv_header(FILE *fp, int n, bool energy)
{
    static const char *const groups[] = {"x", "v", "a"};
    fputc('t', fp);
    for (int g = 0; g < 3; g++)
        for (int i = 1; i <= n; i++)
            fprintf(fp, ",%s%d", groups[g], i);
    fputs(",motor", fp);
    if (energy)
        fputs(",kinetic,potential,dissipated,motor_work", fp);
    fputc('\n', fp);
}

void output_csv_values(FILE *fp, int n, double t, const double *x, const double *v,
                       const double *a, double u, const double *energy)
{
    fprintf(fp, "%.12g", t);
    for (int i = 0; i < n; i++)
        fprintf(fp, ",%.12g", x[i]);
    for (int i = 0; i < n; i++)
        fprintf(fp, ",%.12g", v[i]);
    for (int i = 0; i < n; i++)
        fprintf(fp, ",%.12g", a[i]);
    fprintf(fp, ",%.12g", u);
    if (energy)
        fprintf(fp, ",%.12g,%.12g,%.12g,%.12g", energy[0], energy[1], energy[2], energy[3]);
    fputc('\n', fp);
}

void output_csv_row(FILE *fp, const struct sim *s, bool energy, double *scratch)
{
    struct energy e;
    double four[4];
    sim_accel(s, scratch);
    if (energy) {
        sim_energy(s, &e);
        four[0] = e.kinetic, four[1] = e.potential, four[2] = e.dissipated;
        four[3] = e.motor_work;
    }
    output_csv_values(fp, sim_model(s)->n, sim_time(s), sim_x(s), sim_v(s), scratch,
                      sim_end_position(s), energy ? four : NULL);
}
