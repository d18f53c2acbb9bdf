/* search.c: the search path of presets and lessons, and reading one of their files. */
#include "search.h"

#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

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
