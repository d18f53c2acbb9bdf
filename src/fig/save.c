/* save.c: X's figure written in each format asked for, each file whole (core/output.c),
 * then named exclusively: a name that replaces nothing, between instances too. */
#include "save.h"

#include <errno.h>
#include <libgen.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>

#include "core/output.h"
#include "report.h"
#include "view_report.h"

static const char *const ext[3] = {[FIG_PNG] = ".png", [FIG_SVG] = ".svg", [FIG_PDF] = ".pdf"};

/* Draws the figure in format f into o, opened on a temporary file in dir; 0 or an errno
 * value. */
static int draw_one(struct app *app, const struct fig_chart *c, int n, struct output *o,
                    const char *dir, enum fig_format f)
{
    char tmp[4200], settings[400];
    snprintf(tmp, sizeof tmp, "%s/springsim-figure%s", dir, ext[f]);
    int e = output_open(o, tmp);
    if (e)
        return e;
    struct config cfg = app->cfg;
    cfg.dt = sim_dt(app->sim);
    cfg.integrator = sim_integrator(app->sim);
    report_settings(&cfg, app->model, settings, sizeof settings);
    struct report_look look = {NULL, settings, 0.0, 0.0, NULL};
    if (n > 0)
        return fig_view_report(o->fp, f, c, n, &look);
    return app->modes_ok ? report_modes(o->fp, f, app->model, app->modes, app->shapes, &look)
                         : EDOM;
}

/* Gives the nf complete files the first names base + their extension (then base-2,
 * base-3, ...) that no file has, each linked exclusively: the first's name claims the
 * set, so of programs saving at the same moment each gets its own. base is rewritten to
 * the name taken. 0 or an errno value. */
static int name_files(struct output *o, const enum fig_format *fmt, int nf, char *base,
                      size_t len)
{
    char first[4000], path[4200];
    snprintf(first, sizeof first, "%.3990s", base);
    for (int k = 2; k < 10000; k++) {
        int e = 0, done = 0;
        for (; done < nf && e == 0; done++) {
            snprintf(path, sizeof path, "%s%s", base, ext[fmt[done]]);
            e = output_link_new(&o[done], path);
        }
        if (e == 0)
            return 0;
        for (int i = 0; i < done - 1; i++) { /* those linked before the one that failed */
            snprintf(path, sizeof path, "%s%s", base, ext[fmt[i]]);
            remove(path);
        }
        if (e != EEXIST)
            return e;
        snprintf(base, len, "%.3990s-%d", first, k);
    }
    return EEXIST;
}

unsigned fig_save_view(struct app *app, const struct fig_chart *c, int n, const char *name)
{
    char base[4096], dir[4096], path[4096];
    enum fig_format fmt[2] = {FIG_SVG, FIG_PNG};
    int nf = 2;
    /* A directory (a name ending in '/', or one that is): the default name inside it, not
     * the hidden DIR/.svg and DIR/.png. */
    struct stat st;
    size_t len = name ? strlen(name) : 0;
    const char *in_dir = len && (name[len - 1] == '/' || (stat(name, &st) == 0 &&
                                                          S_ISDIR(st.st_mode))) ? name : NULL;
    if (name && name[0] && !in_dir) {
        /* A name with an extension of a figure's: that file alone; else the pair. */
        enum fig_format one = fig_format_of(name);
        size_t keep = strlen(name);
        if (one != FIG_FORMAT_NONE)
            fmt[0] = one, nf = 1, keep -= 4;
        snprintf(base, sizeof base, "%s%.*s", strchr(name, '/') ? "" : "./", (int)keep, name);
    } else {
        time_t now = time(NULL);
        struct tm tm;
        char stamp[32];
        localtime_r(&now, &tm);
        strftime(stamp, sizeof stamp, "%Y%m%d-%H%M%S", &tm);
        while (in_dir && len > 1 && in_dir[len - 1] == '/')
            len--;
        snprintf(base, sizeof base, "%.*s/springsim-%s", in_dir ? (int)len : 1,
                 in_dir ? in_dir : ".", stamp);
    }
    snprintf(path, sizeof path, "%s", base);
    snprintf(dir, sizeof dir, "%s", dirname(path)); /* dirname may write into path */
    struct output o[2] = {{0}, {0}};
    int e = 0;
    for (int i = 0; i < nf && e == 0; i++)
        e = draw_one(app, c, n, &o[i], dir, fmt[i]);
    if (e == 0)
        e = name_files(o, fmt, nf, base, sizeof base);
    for (int i = 0; i < nf; i++) {
        int closed = output_close(&o[i], false); /* the temporary names go */
        e = e ? e : closed;
    }
    fig_done();
    if (e == EDOM && n == 0)
        return app_say(app, SAID_ERROR, "figure: the modes cannot be computed for this chain");
    if (e == EDOM)
        return app_say(app, SAID_ERROR, "figure: this view has no figure to write");
    char shown[128];
    if (e)
        return app_say(app, SAID_ERROR, "figure: %s: %s",
                       app_path_shown(base, shown, sizeof shown), strerror(e));
    if (nf == 1)
        return app_say(app, SAID_NOTE, "saved the figure as %s%s", base, ext[fmt[0]]);
    return app_say(app, SAID_NOTE, "saved the figure as %s.svg and .png", base);
}
