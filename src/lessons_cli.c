/* lessons_cli.c: the command line's lessons: --list-lessons, and the lesson --lesson or
 * --replay names read and checked before anything runs. */
#include "lessons_cli.h"

#include <poll.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <termios.h>
#include <unistd.h>

#include "core/search.h"
#include "options.h"

/* --list-lessons: "NAME  TITLE", one line each, escaped as --list-presets is. */
int lessons_list(const char *exe_dir)
{
    struct search_entry *all = NULL;
    int have = lesson_scan(exe_dir, &all);
    search_list(stdout, all, have, "(no title)");
    free(all);
    if (have == 0)
        options_say("no lessons found (searched the user's directory, $SPRINGSIM_LESSONS, %s "
                    "and %s/lessons)", search_installed_dir(SEARCH_LESSONS), exe_dir);
    return options_finish_stdout(true);
}

/* Whether Esc, q or Ctrl+C came on standard input (read a byte at a time, unbuffered). */
static bool key_left(void *ctx)
{
    (void)ctx;
    struct pollfd in = {.fd = STDIN_FILENO, .events = POLLIN};
    unsigned char ch;
    while (poll(&in, 1, 0) > 0 && (in.revents & POLLIN) && read(STDIN_FILENO, &ch, 1) == 1)
        if (ch == 27 || ch == 'q' || ch == 3)
            return true;
    return false;
}

/* The dry run, which Esc, q or Ctrl+C leaves when keys: the terminal reads a byte at a
 * time meanwhile (no echo; Ctrl+C a byte, not a signal), as it was afterwards. */
static int check(const struct lesson *l, const struct config *base, const char *exe_dir,
                 bool keys, char *err, size_t errlen)
{
    struct termios was, now;
    keys = keys && isatty(STDIN_FILENO) && tcgetattr(STDIN_FILENO, &was) == 0;
    if (keys) {
        now = was;
        now.c_lflag &= ~(tcflag_t)(ICANON | ECHO | ISIG);
        now.c_cc[VMIN] = 0;
        now.c_cc[VTIME] = 0;
        keys = tcsetattr(STDIN_FILENO, TCSANOW, &now) == 0;
    }
    struct lesson_stop stop = {.fn = key_left};
    int st = lesson_check(l, base, exe_dir, keys ? &stop : NULL, err, errlen);
    if (keys)
        tcsetattr(STDIN_FILENO, TCSANOW, &was);
    return st;
}

/* --lesson or --replay: the lesson read and every command tried before anything runs.
 * -1 to go on; else the exit status, after one line saying why (FILE:LINE: what). */
int lessons_load(const struct config *c, const char *exe_dir, bool keys, struct lesson *l)
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
        st = check(l, &base, exe_dir, keys, err, sizeof err);
    }
    if (st == 0)
        return -1;
    options_say("%s", err);
    lesson_free(l);
    return st == 2 ? EXIT_USAGE : EXIT_FAILURE;
}
