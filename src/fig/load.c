/* load.c: finds the figure library (lib.h) and keeps it loaded to the end (never closed:
 * its fonts and caches live as long as the program). Part of the program, not of the
 * library. */
#include "lib.h"

#include <dlfcn.h>
#include <limits.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#ifndef FIGLIBDIR
#define FIGLIBDIR "/usr/local/lib/springsim"
#endif

static char first_dir[PATH_MAX];
static const struct fig_lib *table;
static bool tried;
static char failed[PATH_MAX + 200];

void fig_lib_where(const char *exe_dir)
{
    snprintf(first_dir, sizeof first_dir, "%s", exe_dir ? exe_dir : "");
}

/* The table in the library at path, or NULL with the reason in failed. */
static const struct fig_lib *open_at(const char *path)
{
    void *h = dlopen(path, RTLD_NOW | RTLD_LOCAL);
    if (!h) {
        const char *e = dlerror();
        snprintf(failed, sizeof failed, "%s", e ? e : path);
        return NULL;
    }
    const struct fig_lib *t = dlsym(h, FIG_LIB_SYMBOL);
    if (!t || !t->abi || strcmp(t->abi, FIG_LIB_ABI) != 0) {
        snprintf(failed, sizeof failed, "%s: not the figure library of this springsim (%s)",
                 path, t && t->abi ? t->abi : "no table");
        dlclose(h);
        return NULL;
    }
    return t;
}

const struct fig_lib *fig_lib(char *why, size_t len)
{
    if (!tried) {
        tried = true;
        char path[PATH_MAX + 32];
        /* beside the program when it is there (a build tree's; its error, if any, is the
         * one said), else the installed one */
        snprintf(path, sizeof path, "%s/%s", first_dir, FIG_LIB_FILE);
        if (first_dir[0] && access(path, F_OK) == 0) {
            table = open_at(path);
        } else {
            snprintf(path, sizeof path, "%s/%s", FIGLIBDIR, FIG_LIB_FILE);
            table = open_at(path);
        }
    }
    if (!table && why)
        snprintf(why, len, "the figure library could not be loaded: %s", failed);
    return table;
}

const struct fig_lib *fig_lib_loaded(void)
{
    return table;
}
