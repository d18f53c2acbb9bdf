/* search.c: the search path of presets and lessons, and reading one of their files. */
#include "search.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "config.h"

#ifndef PRESETDIR
#define PRESETDIR "/usr/local/share/springsim/presets"
#endif
#ifndef LESSONDIR
#define LESSONDIR "/usr/local/share/springsim/lessons"
#endif

static const char *const kinds[] = {[SEARCH_PRESETS] = "presets", [SEARCH_LESSONS] = "lessons"};
static const char *const envs[] = {[SEARCH_PRESETS] = "SPRINGSIM_PRESETS",
                                   [SEARCH_LESSONS] = "SPRINGSIM_LESSONS"};

const char *search_installed_dir(enum search_kind kind)
{
    return kind == SEARCH_LESSONS ? LESSONDIR : PRESETDIR;
}

int search_user_dir(enum search_kind kind, char *out, size_t len)
{
    const char *xdg = getenv("XDG_CONFIG_HOME");
    const char *home = getenv("HOME");
    int n;
    if (xdg && *xdg == '/')
        n = snprintf(out, len, "%s/springsim/%s", xdg, kinds[kind]);
    else if (home && *home)
        n = snprintf(out, len, "%s/.config/springsim/%s", home, kinds[kind]);
    else
        return -1;
    return n > 0 && (size_t)n < len ? 0 : -1;
}

int search_dirs(enum search_kind kind, const char *exe_dir, char dirs[SEARCH_DIRS][SEARCH_DIR_MAX])
{
    int count = 0;
    const char *env = getenv(envs[kind]);
    if (search_user_dir(kind, dirs[count], SEARCH_DIR_MAX) == 0)
        count++;
    if (env && *env)
        snprintf(dirs[count++], SEARCH_DIR_MAX, "%s", env);
    snprintf(dirs[count++], SEARCH_DIR_MAX, "%s", search_installed_dir(kind));
    if (exe_dir && *exe_dir)
        snprintf(dirs[count++], SEARCH_DIR_MAX, "%s/%s", exe_dir, kinds[kind]);
    return count;
}

int search_read(const char *path, size_t max, const char *what, char **text, size_t *size,
                char *err, size_t errlen)
{
    struct stat st;
    int fd = open(path, O_RDONLY | O_CLOEXEC | O_NONBLOCK | O_NOCTTY);
    if (fd < 0) {
        snprintf(err, errlen, "%s: %s", path, strerror(errno));
        return 1;
    }
    if (fstat(fd, &st) != 0) {
        snprintf(err, errlen, "%s: %s", path, strerror(errno));
        close(fd);
        return 1;
    }
    if (!S_ISREG(st.st_mode)) {
        snprintf(err, errlen, "%s: %s", path, S_ISDIR(st.st_mode) ? strerror(EISDIR)
                 : "not a regular file (expected a text file)");
        close(fd);
        return 1;
    }
    if ((size_t)st.st_size > max) {
        snprintf(err, errlen, "%s: too large for %s (more than %zu bytes)", path, what, max);
        close(fd);
        return 2;
    }
    char *buf = malloc(max + 2);
    size_t n = 0;
    if (!buf) {
        snprintf(err, errlen, "%s: %s", path, strerror(ENOMEM));
        close(fd);
        return 1;
    }
    /* The size may still grow while it is read: the limit holds on what is read too. */
    for (;;) {
        ssize_t r = read(fd, buf + n, max + 1 - n);
        if (r < 0 && errno == EINTR)
            continue;
        if (r < 0) {
            snprintf(err, errlen, "%s: %s", path, strerror(errno));
            free(buf);
            close(fd);
            return 1;
        }
        if (r == 0)
            break;
        n += (size_t)r;
        if (n > max) {
            snprintf(err, errlen, "%s: too large for %s (more than %zu bytes)", path, what, max);
            free(buf);
            close(fd);
            return 2;
        }
    }
    close(fd);
    buf[n] = '\0';
    *text = buf;
    *size = n;
    return 0;
}

static const char *const exts[] = {[SEARCH_PRESETS] = ".ini", [SEARCH_LESSONS] = ".lesson"};
static const char *const whats[] = {[SEARCH_PRESETS] = "a preset", [SEARCH_LESSONS] = "a lesson"};

static int compare_entries(const void *a, const void *b)
{
    return strcmp(((const struct search_entry *)a)->name, ((const struct search_entry *)b)->name);
}

/* Whether a file of this name is in all[0..have) already (an earlier directory's). */
static int known(const struct search_entry *all, int have, const char *name, size_t n)
{
    for (int i = 0; i < have; i++)
        if (strncmp(all[i].name, name, n) == 0 && !all[i].name[n])
            return 1;
    return 0;
}

/* Adds dir's files of the kind to *all; the new count. */
static int scan_dir(enum search_kind kind, const char *dir_name, size_t max,
                    search_about_fn *about, struct search_entry **all, int have, int *cap)
{
    DIR *dir = opendir(dir_name);
    if (!dir)
        return have;
    size_t e = strlen(exts[kind]);
    struct dirent *ent;
    while ((ent = readdir(dir))) {
        size_t n = strlen(ent->d_name);
        if (n <= e || n - e >= sizeof (*all)->name || strcmp(ent->d_name + n - e, exts[kind]) ||
            known(*all, have, ent->d_name, n - e))
            continue;
        if (have == *cap) {
            int more_cap = *cap ? 2 * *cap : 16;
            struct search_entry *more = realloc(*all, (size_t)more_cap * sizeof *more);
            if (!more)
                break;
            *all = more, *cap = more_cap;
        }
        struct search_entry *en = &(*all)[have];
        int w = snprintf(en->path, sizeof en->path, "%s/%s", dir_name, ent->d_name);
        char *text, why[64];
        size_t size;
        if (w < 0 || (size_t)w >= sizeof en->path ||
            search_read(en->path, max, whats[kind], &text, &size, why, sizeof why) != 0)
            continue;
        memcpy(en->name, ent->d_name, n - e);
        en->name[n - e] = '\0';
        en->about[0] = '\0';
        about(text, en->about, sizeof en->about);
        free(text);
        have++;
    }
    closedir(dir);
    return have;
}

int search_scan(enum search_kind kind, const char *exe_dir, size_t max, search_about_fn *about,
                struct search_entry **out)
{
    char dirs[SEARCH_DIRS][SEARCH_DIR_MAX];
    int count = search_dirs(kind, exe_dir, dirs), have = 0, cap = 0;
    struct search_entry *all = NULL;
    for (int d = 0; d < count; d++)
        have = scan_dir(kind, dirs[d], max, about, &all, have, &cap);
    if (have)
        qsort(all, (size_t)have, sizeof *all, compare_entries);
    *out = all;
    return have;
}

void search_list(FILE *out, const struct search_entry *all, int count, const char *none)
{
    int width = 0;
    for (int i = 0; i < count; i++)
        if ((int)strlen(all[i].name) > width)
            width = (int)strlen(all[i].name);
    for (int i = 0; i < count; i++) {
        char line[1024], safe[4 * 1024 + 8];
        snprintf(line, sizeof line, "%-*s  %s", width, all[i].name,
                 all[i].about[0] ? all[i].about : none);
        config_escape(line, strlen(line), 1024, safe, sizeof safe);
        fprintf(out, "%s\n", safe);
    }
}
