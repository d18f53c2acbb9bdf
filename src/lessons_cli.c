/* lessons_cli.c: the command line's lessons: --list-lessons, and the lesson --lesson or
 * --replay names read and checked before anything runs. */
#include "lessons_cli.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/search.h"
#include "options.h"

/* --list-lessons: "NAME  TITLE", one line each, escaped as --list-presets is. */
int lessons_list(const char *exe_dir)
{
    struct lesson_entry *all = NULL;
    int have = lesson_scan(exe_dir, &all), width = 0;
    for (int i = 0; i < have; i++)
        if ((int)strlen(all[i].name) > width)
            width = (int)strlen(all[i].name);
    for (int i = 0; i < have; i++) {
        char line[1024], safe[4 * 1024 + 8];
        snprintf(line, sizeof line, "%-*s  %s", width, all[i].name,
                 all[i].title[0] ? all[i].title : "(no title)");
        config_escape(line, strlen(line), 1024, safe, sizeof safe);
        printf("%s\n", safe);
    }
    free(all);
    if (have == 0)
        options_say("no lessons found (searched the user's directory, $SPRINGSIM_LESSONS, %s "
                    "and %s/lessons)", search_installed_dir(SEARCH_LESSONS), exe_dir);
    return options_finish_stdout(true);
}

/* --lesson or --replay: the lesson read and every command tried before anything runs.
 * -1 to go on; else the exit status, after one line saying why (FILE:LINE: what). */
int lessons_load(const struct config *c, const char *exe_dir, struct lesson *l)
{
    static struct config base; /* large: lists of up to 1001 values */
    char path[4400], err[2048];
    if (c->lesson && lesson_find(c->lesson, exe_dir, path, sizeof path) != 0) {
        options_say("--lesson: %s", path);
        return EXIT_USAGE;
    }
    if (!c->lesson)
        snprintf(path, sizeof path, "%s", c->replay);
    int st = lesson_read(path, l, err, sizeof err);
    if (st == 0) {
        config_init(&base);
        base.color = c->color;
        base.glyphs = c->glyphs;
        st = lesson_check(l, &base, exe_dir, err, sizeof err);
    }
    if (st == 0)
        return -1;
    options_say("%s", err);
    lesson_free(l);
    return st == 2 ? EXIT_USAGE : EXIT_FAILURE;
}
