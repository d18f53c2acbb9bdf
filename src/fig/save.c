/* save.c: the picture of the view written twice, SVG then PNG, each atomically
 * (core/output.c), under one name that replaces nothing. */
#include "save.h"

#include <errno.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>

#include "core/output.h"
#include "report.h"

/* Draws the picture in format f into path; 0 or an errno value. */
static int write_one(struct app *app, const struct fig_chart *c, int n, const char *path,
                     enum fig_format f)
{
    struct output o;
    int e = output_open(&o, path);
    if (e)
        return e;
    if (n > 0) {
        e = fig_view_write(o.fp, f, c, n);
    } else {
        struct config cfg = app->cfg;
        char settings[400];
        cfg.dt = sim_dt(app->sim);
        cfg.integrator = sim_integrator(app->sim);
        report_settings(&cfg, app->model, settings, sizeof settings);
        e = app->modes_ok ? report_modes(o.fp, f, app->model, app->modes, app->shapes, settings)
                          : EDOM;
    }
    int e2 = output_close(&o, e == 0);
    return e ? e : e2;
}

unsigned fig_save_view(struct app *app, const struct fig_chart *c, int n, const char *dir)
{
    time_t now = time(NULL);
    struct tm tm;
    char stamp[32], base[4096], svg[4200], png[4200];
    struct stat st;
    localtime_r(&now, &tm);
    strftime(stamp, sizeof stamp, "%Y%m%d-%H%M%S", &tm);
    if (!dir)
        dir = ".";
    /* Two in one second: the second gets -2, then -3, ... never replacing one. */
    snprintf(base, sizeof base, "%s/springsim-%s", dir, stamp);
    for (int k = 2; k < 1000; k++) {
        snprintf(svg, sizeof svg, "%s.svg", base);
        snprintf(png, sizeof png, "%s.png", base);
        if (lstat(svg, &st) != 0 && lstat(png, &st) != 0)
            break;
        snprintf(base, sizeof base, "%s/springsim-%s-%d", dir, stamp, k);
    }
    int e = write_one(app, c, n, svg, FIG_SVG);
    const char *bad = svg;
    if (e == 0) {
        e = write_one(app, c, n, png, FIG_PNG);
        bad = png;
        if (e)
            remove(svg); /* both or neither */
    }
    fig_done();
    if (e == EDOM)
        return app_say(app, SAID_ERROR, "figure: the modes cannot be computed for this chain");
    if (e)
        return app_say(app, SAID_ERROR, "figure: %s: %s", bad, strerror(e));
    return app_say(app, SAID_NOTE, "saved the view as %s.svg and .png", base);
}
