/* save.c: the picture of the view written twice, SVG and PNG, each whole (core/output.c),
 * then named as a pair exclusively: a name that replaces nothing, between instances too. */
#include "save.h"

#include <errno.h>
#include <stdio.h>
#include <string.h>
#include <time.h>

#include "core/output.h"
#include "report.h"

/* Draws the picture in format f into o, opened on a temporary file in dir; 0 or an errno
 * value. */
static int draw_one(struct app *app, const struct fig_chart *c, int n, struct output *o,
                    const char *dir, enum fig_format f)
{
    char tmp[4200];
    snprintf(tmp, sizeof tmp, "%s/springsim-figure%s", dir, f == FIG_SVG ? ".svg" : ".png");
    int e = output_open(o, tmp);
    if (e)
        return e;
    if (n > 0) {
        e = fig_view_write(o->fp, f, c, n);
    } else {
        struct config cfg = app->cfg;
        char settings[400];
        cfg.dt = sim_dt(app->sim);
        cfg.integrator = sim_integrator(app->sim);
        report_settings(&cfg, app->model, settings, sizeof settings);
        struct report_look look = {NULL, settings, 0.0, 0.0};
        e = app->modes_ok ? report_modes(o->fp, f, app->model, app->modes, app->shapes, &look)
                          : EDOM;
    }
    return e;
}

/* Gives the two complete files the first pair of names base.svg, base.png (then base-2,
 * base-3, ...) that no file has, each linked exclusively: the SVG's name claims the pair,
 * so of programs saving at the same moment each gets its own. base is rewritten to the
 * name taken. 0 or an errno value. */
static int name_pair(struct output o[2], char *base, size_t len)
{
    char first[4000], svg[4200], png[4200];
    snprintf(first, sizeof first, "%.3990s", base);
    for (int k = 2; k < 10000; k++) {
        snprintf(svg, sizeof svg, "%s.svg", base);
        snprintf(png, sizeof png, "%s.png", base);
        int e = output_link_new(&o[0], svg);
        if (e == 0) {
            e = output_link_new(&o[1], png);
            if (e == 0)
                return 0;
            remove(svg);
        }
        if (e != EEXIST)
            return e;
        snprintf(base, len, "%.3990s-%d", first, k);
    }
    return EEXIST;
}

unsigned fig_save_view(struct app *app, const struct fig_chart *c, int n, const char *dir)
{
    time_t now = time(NULL);
    struct tm tm;
    char stamp[32], base[4096];
    localtime_r(&now, &tm);
    strftime(stamp, sizeof stamp, "%Y%m%d-%H%M%S", &tm);
    if (!dir)
        dir = ".";
    snprintf(base, sizeof base, "%s/springsim-%s", dir, stamp);
    struct output o[2] = {{0}, {0}};
    int e = draw_one(app, c, n, &o[0], dir, FIG_SVG);
    if (e == 0)
        e = draw_one(app, c, n, &o[1], dir, FIG_PNG);
    if (e == 0)
        e = name_pair(o, base, sizeof base);
    for (int i = 0; i < 2; i++) {
        int closed = output_close(&o[i], false); /* the temporary names go */
        e = e ? e : closed;
    }
    fig_done();
    if (e == EDOM)
        return app_say(app, SAID_ERROR, "figure: the modes cannot be computed for this chain");
    if (e)
        return app_say(app, SAID_ERROR, "figure: %s: %s", base, strerror(e));
    return app_say(app, SAID_NOTE, "saved the view as %s.svg and .png", base);
}
