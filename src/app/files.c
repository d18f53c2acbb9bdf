/* files.c: what the app reads and writes: presets loaded (through app_change, app.c)
 * and saved, and the plots' samples exported as CSV. */
#include "change.h"

#include <errno.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "../core/output.h"
#include "../core/preset.h"

/* Puts the preset read into next (from path, named name) in force. */
static unsigned load_config(struct app *app, struct config *next_in, const char *path,
                            const char *name)
{
    struct config next = *next_in;
    char err[600];
    if (next.random && !next.seed_set)
        next.seed = (uint64_t)time(NULL);
    /* Playback is the user's: a preset changes it only where it says so. */
    if (!next.origin[CFG_FPS].line)
        next.fps = app->cfg.fps;
    if (!next.origin[CFG_WINDOW].line)
        next.window = app->cfg.window;
    if (!next.origin[CFG_LOW_BANDWIDTH].line)
        next.low_bandwidth = app->cfg.low_bandwidth;
    /* The terminal was set up once, at start. */
    next.color = app->cfg.color;
    next.glyphs = app->cfg.glyphs;
    next.graphics = app->cfg.graphics;
    unsigned what = 0;
    bool ghost = app->ghost != NULL; /* a new chain drops it: said, or it vanishes unseen */
    if (app_change(app, &next, CHANGE_REBUILD | CHANGE_SETS_FREQUENCY, "the preset", &what)) {
        snprintf(err, sizeof err, "%s", app->message);
        app_say(app, SAID_ERROR, "%s: %s", path, err);
        return 0;
    }
    snprintf(app->preset, sizeof app->preset, "%s", next.name[0] ? next.name : name);
    const char *dropped = ghost ? ", ghost dropped" : "";
    const char *sep = next.description[0] ? ": " : ""; /* a preset may have none */
    if (next.random && !next.seed_set) /* the seed chosen, so the start can be repeated */
        return what | app_say(app, SAID_NOTE, "preset %s (random positions, seed %llu%s)%s%s",
                              app->preset, (unsigned long long)next.seed, dropped, sep,
                              next.description);
    return what | app_say(app, SAID_NOTE, "preset %s%s%s%s", app->preset,
                          ghost ? " (ghost dropped)" : "", sep, next.description);
}

unsigned app_load_preset(struct app *app, const char *path, const char *name)
{
    static struct config next; /* large: lists of up to 1001 values */
    char err[600];
    config_init(&next);
    if (preset_load(path, &next, err, sizeof err) != PRESET_OK) {
        app_say(app, SAID_ERROR, "%s", err);
        return 0;
    }
    unsigned what = load_config(app, &next, path, name);
    if (what) {
        snprintf(app->preset_file, sizeof app->preset_file, "%s", path);
        app->loads++;
    }
    return what;
}

unsigned app_load_preset_text(struct app *app, const char *path, const char *text, size_t size,
                              const char *name)
{
    static struct config next;
    char err[600];
    config_init(&next);
    if (preset_parse(path, text, size, &next, err, sizeof err) != PRESET_OK) {
        app_say(app, SAID_ERROR, "%s", err);
        return 0;
    }
    return load_config(app, &next, path, name);
}

/* A preset name: ASCII letters, digits, '-', '_' and '.', not starting with '.', at most
 * 64, not ending in ".ini" (preset_find would take it for a file name). */
static const char *bad_name(const char *name)
{
    size_t len = strlen(name);
    if (len == 0)
        return "a name is needed";
    if (len > 64)
        return "names are at most 64 characters";
    if (name[0] == '.')
        return "a name may not start with '.'";
    for (const unsigned char *p = (const unsigned char *)name; *p; p++)
        if (*p >= 0x80)
            return "use ASCII letters (a-z, A-Z), digits, '-', '_' and '.' only, so that the "
                   "name is the same on every system";
    for (const char *p = name; *p; p++)
        if (!((*p >= 'a' && *p <= 'z') || (*p >= 'A' && *p <= 'Z') || (*p >= '0' && *p <= '9') ||
              *p == '-' || *p == '_' || *p == '.'))
            return "use letters, digits, '-', '_' and '.' only";
    if (len > 4 && strcmp(name + len - 4, ".ini") == 0)
        return "a name may not end in '.ini' twice (it would be read as a file name)";
    return NULL;
}

/* mkdir -p. */
static int make_dirs(const char *path)
{
    char buf[4096];
    snprintf(buf, sizeof buf, "%s", path);
    for (char *p = buf + 1; *p; p++) {
        if (*p != '/')
            continue;
        *p = '\0';
        if (mkdir(buf, 0777) != 0 && errno != EEXIST)
            return -1;
        *p = '/';
    }
    return mkdir(buf, 0777) != 0 && errno != EEXIST ? -1 : 0;
}

enum app_save app_save(struct app *app, const char *name, bool overwrite)
{
    char dir[4096], path[4200], base[64];
    /* "x.ini" is the file x.ini, loaded by "-p x": the extension is the file's, not the
     * name's. */
    size_t len = strlen(name);
    if (len >= 4 && strcmp(name + len - 4, ".ini") == 0 && len - 4 < sizeof base) {
        memcpy(base, name, len - 4);
        base[len - 4] = '\0';
        name = base;
    }
    const char *why = bad_name(name);
    if (why) {
        app_say(app, SAID_ERROR, "save: '%.40s': %s", name, why);
        return SAVE_BAD_NAME;
    }
    if (preset_user_dir(dir, sizeof dir) != 0) {
        app_say(app, SAID_ERROR, "save: neither XDG_CONFIG_HOME nor HOME is set");
        return SAVE_FAILED;
    }
    snprintf(path, sizeof path, "%s/%s.ini", dir, name);
    if (!overwrite && access(path, F_OK) == 0) {
        app_say(app, SAID_NOTE, "preset %s exists: replace it? (y/n)", name);
        return SAVE_EXISTS;
    }
    if (make_dirs(dir) != 0) {
        int e = errno;
        char shown[128];
        app_say(app, SAID_ERROR, "save: %s: %s", app_path_shown(dir, shown, sizeof shown),
                strerror(e));
        return SAVE_FAILED;
    }
    /* The set-up as it stands: every element's values, the initial conditions, and the
     * drive as the user set it, not the sweep's (preset_write reads the model). */
    struct config c = app->cfg;
    struct model m = *app->model; /* shares the arrays, only read */
    if (app->sweep->active)
        c.frequency = m.motor.frequency = app->sweep_from;
    snprintf(c.name, sizeof c.name, "%s", name);
    snprintf(c.description, sizeof c.description, "Saved from springsim");
    /* A new preset is made exclusively: if another program made one of that name since
     * the check above, it is not replaced without asking. The user's yes replaces. */
    struct output o;
    int e = output_open(&o, path);
    if (e == 0) {
        preset_write(o.fp, &c, &m);
        if (overwrite) {
            e = output_close(&o, true);
        } else {
            e = output_link_new(&o, path);
            int closed = output_close(&o, false);
            e = e ? e : closed;
        }
    }
    if (e == EEXIST && !overwrite) {
        app_say(app, SAID_NOTE, "preset %s appeared meanwhile (another springsim?): replace it? "
                "(y/n)", name);
        return SAVE_EXISTS;
    }
    if (e) {
        char shown[128];
        app_say(app, SAID_ERROR, "save: %s: %s", app_path_shown(path, shown, sizeof shown),
                strerror(e));
        return SAVE_FAILED;
    }
    snprintf(app->preset, sizeof app->preset, "%s", name);
    app_say(app, SAID_NOTE, "saved %s (springsim -p %s loads it)", path, name);
    return SAVE_OK;
}

unsigned app_export(struct app *app, const char *dir, char *path, size_t len)
{
    time_t now = time(NULL);
    struct tm tm;
    char stamp[32];
    localtime_r(&now, &tm);
    strftime(stamp, sizeof stamp, "%Y%m%d-%H%M%S", &tm);
    /* Two exports in one second: the second gets -2, then -3, ... never replacing one,
     * even of another program exporting at the same moment: the complete file takes the
     * first name still free, linked exclusively. */
    snprintf(path, len, "%s/springsim-%s.csv", dir ? dir : ".", stamp);
    const struct trail *tr = app->trail;
    int n = tr->n;
    struct output o;
    int e = output_open(&o, path);
    if (e == 0) {
        app_export_meta(o.fp, app);
        output_csv_header(o.fp, n, false);
        const double *rec = trail_first(tr);
        for (int k = 0; k < tr->count; k++, rec += tr->width)
            output_csv_values(o.fp, n, rec[TRAIL_T], rec + TRAIL_X(tr, 0), rec + TRAIL_V(tr, 0),
                              rec + TRAIL_A(tr, 0), rec[TRAIL_U], NULL);
        e = output_link_new(&o, path);
        for (int k = 2; e == EEXIST && k < 1000; k++) {
            snprintf(path, len, "%s/springsim-%s-%d.csv", dir ? dir : ".", stamp, k);
            e = output_link_new(&o, path);
        }
        int closed = output_close(&o, false);
        e = e ? e : closed;
    }
    if (e) {
        char shown[128];
        app_say(app, SAID_ERROR, "export: %s: %s", app_path_shown(path, shown, sizeof shown),
                strerror(e));
        return 0;
    }
    char what[120];
    app_export_summary(app, what, sizeof what);
    return app_say(app, SAID_NOTE, "exported %s to %s", what, path);
}
