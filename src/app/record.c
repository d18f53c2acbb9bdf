/* record.c: --record, the session written as a lesson file (record.h). */
#include "record.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "../core/preset.h"
#include "app.h"
#include "command.h"
#include "lesson.h"

#ifndef VERSION
#define VERSION "0.1.0"
#endif

bool record_wants(int cmd)
{
    switch ((enum command_id)cmd) {
    case CMD_START:
    case CMD_PAUSE:
    case CMD_STEP:
    case CMD_BACK:
    case CMD_RESET:
    case CMD_RANDOM:
    case CMD_SET:
    case CMD_PRESET:
    case CMD_MODE:
    case CMD_NEAREST:
    case CMD_SWEEP:
    case CMD_FASTER:
    case CMD_SLOWER:
    case CMD_VIEW:
        return true;
    default:
        return false;
    }
}

int record_start(struct record *r, const char *path, const struct app *app, char *err,
                 size_t errlen)
{
    memset(r, 0, sizeof *r);
    if (snprintf(r->path, sizeof r->path, "%s", path) >= (int)sizeof r->path ||
        snprintf(r->tmp, sizeof r->tmp, "%s.XXXXXX", path) >= (int)sizeof r->tmp) {
        snprintf(err, errlen, "%.60s...: too long for a file name", path);
        return -1;
    }
    int fd = mkstemp(r->tmp);
    if (fd < 0) {
        snprintf(err, errlen, "%s: %s", path, strerror(errno));
        r->tmp[0] = '\0';
        return -1;
    }
    fchmod(fd, 0644); /* as a file written with the usual umask */
    close(fd);
    r->mem = open_memstream(&r->text, &r->size);
    if (!r->mem) {
        snprintf(err, errlen, "%s: %s", path, strerror(errno));
        record_abandon(r);
        return -1;
    }
    char when[64];
    time_t now = time(NULL);
    strftime(when, sizeof when, "%Y-%m-%d %H:%M", localtime(&now));
    fprintf(r->mem, "# A session recorded by springsim %s (--record), a lesson file:\n"
            "# springsim --replay FILE plays it back to the state on its last line.\n"
            "title Recorded %s\nsetup\n", VERSION, when);
    preset_write(r->mem, &app->cfg, app->model);
    fputs("end\n", r->mem);
    r->t = sim_time(app->sim);
    return 0;
}

void record_time(struct record *r, const struct app *app)
{
    double t = sim_time(app->sim);
    if (!r->mem || !(t > r->t))
        return;
    char num[32];
    config_format_exact(t - r->t, num, sizeof num);
    fprintf(r->mem, "run %s\n", num);
    r->t = t;
}

void record_line(struct record *r, const struct app *app, const char *line)
{
    if (!r->mem)
        return;
    fprintf(r->mem, "%s\n", line);
    r->t = sim_time(app->sim);
    r->lines++;
}

void record_command(struct record *r, const struct app *app, const char *line)
{
    const char *w = line + strspn(line, " \t");
    size_t n = strcspn(w, " \t");
    int cmd = command_find(w, n);
    if (!r->mem || cmd < 0 || !record_wants(cmd))
        return;
    char text[2100];
    if (cmd == CMD_RANDOM) {
        /* the seed it drew, so that the replay draws the same positions */
        snprintf(text, sizeof text, "random %llu", (unsigned long long)app->cfg.seed);
    } else {
        /* the words as typed, their blanks made one */
        size_t o = 0;
        for (const char *s = w; *s && o + 1 < sizeof text;) {
            size_t k = strcspn(s, " \t");
            if (k == 0) {
                s += strspn(s, " \t");
                continue;
            }
            o += (size_t)snprintf(text + o, sizeof text - o, "%s%.*s", o ? " " : "", (int)k, s);
            s += k;
        }
        text[o < sizeof text ? o : sizeof text - 1] = '\0';
    }
    record_line(r, app, text);
}

void record_abandon(struct record *r)
{
    if (r->mem)
        fclose(r->mem);
    r->mem = NULL;
    free(r->text);
    r->text = NULL;
    if (r->tmp[0])
        unlink(r->tmp);
    r->tmp[0] = '\0';
}

int record_finish(struct record *r, const struct app *app, char *err, size_t errlen)
{
    char state[4096];
    if (!r->mem) {
        snprintf(err, errlen, "%s: not recording", r->path);
        return -1;
    }
    record_time(r, app);
    lesson_state(app, state, sizeof state);
    fprintf(r->mem, "expect %s\n", state);
    if (fclose(r->mem) != 0) {
        r->mem = NULL;
        snprintf(err, errlen, "%s: %s", r->path, strerror(errno));
        record_abandon(r);
        return -1;
    }
    r->mem = NULL;
    FILE *f = fopen(r->tmp, "w");
    int e = 0;
    if (!f || fwrite(r->text, 1, r->size, f) != r->size)
        e = errno ? errno : EIO;
    if (f && fclose(f) != 0 && !e)
        e = errno;
    if (!e && rename(r->tmp, r->path) != 0)
        e = errno;
    if (e) {
        snprintf(err, errlen, "%s: %s", r->path, strerror(e));
        record_abandon(r);
        return -1;
    }
    r->tmp[0] = '\0';
    free(r->text);
    r->text = NULL;
    return 0;
}
