/* test_output.c: the one way every output file is written (core/output.c: -o, --figure,
 * --record, presets, exports, X pictures). A new file is made with the umask's mode; an
 * old one is replaced whole and keeps its mode; nothing but the file appears in its
 * directory, before or after, also for names of 249 to 255 bytes; a symbolic link is
 * followed (the link stays, its target is written, a dangling one's target made); a FIFO
 * and a character device are written in place and stay what they were; a directory is
 * refused; an output abandoned leaves the old file as it was; a name taken is never
 * replaced by output_link_new. */
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>
#include <dirent.h>

#include <cmocka.h>

#include "core/output.h"

static char dir[1024];

static int make_dir(void **state)
{
    (void)state;
    snprintf(dir, sizeof dir, "%s/test_output.XXXXXX", getenv("TMPDIR") ? getenv("TMPDIR") : "/tmp");
    return mkdtemp(dir) ? 0 : -1;
}

static int remove_dir(void **state)
{
    (void)state;
    char cmd[1100];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    return system(cmd) == 0 ? 0 : -1;
}

static const char *at(const char *name)
{
    static char path[2][1400];
    static int which;
    which ^= 1;
    snprintf(path[which], sizeof path[which], "%s/%s", dir, name);
    return path[which];
}

/* The entries of dir, not . and .. */
static int entries(void)
{
    DIR *d = opendir(dir);
    assert_non_null(d);
    int n = 0;
    struct dirent *e;
    while ((e = readdir(d)))
        n += strcmp(e->d_name, ".") != 0 && strcmp(e->d_name, "..") != 0;
    closedir(d);
    return n;
}

static void write_text(const char *path, const char *text, int *err)
{
    struct output o;
    *err = output_open(&o, path);
    if (*err)
        return;
    fputs(text, o.fp);
    *err = output_close(&o, true);
}

static const char *read_text(const char *path)
{
    static char buf[256];
    FILE *f = fopen(path, "r");
    assert_non_null(f);
    size_t n = fread(buf, 1, sizeof buf - 1, f);
    buf[n] = '\0';
    fclose(f);
    return buf;
}

static mode_t mode_of(const char *path)
{
    struct stat st;
    assert_int_equal(lstat(path, &st), 0);
    return st.st_mode;
}

static void modes_and_umask(void **state)
{
    (void)state;
    int e;
    mode_t old = umask(077);
    write_text(at("private"), "a\n", &e);
    umask(022);
    write_text(at("shared"), "b\n", &e);
    assert_int_equal(e, 0);
    assert_int_equal(mode_of(at("private")) & 07777, 0600);
    assert_int_equal(mode_of(at("shared")) & 07777, 0644);
    /* An old file keeps its mode when replaced, whatever the umask. */
    chmod(at("shared"), 0640);
    write_text(at("shared"), "c\n", &e);
    assert_int_equal(e, 0);
    assert_int_equal(mode_of(at("shared")) & 07777, 0640);
    assert_string_equal(read_text(at("shared")), "c\n");
    umask(old);
    assert_int_equal(entries(), 2);
}

/* Abandoned (commit false): the old file as it was, nothing else in the directory, also
 * while it is being written. */
static void abandoned_and_nothing_beside(void **state)
{
    (void)state;
    int e;
    write_text(at("keep"), "old\n", &e);
    struct output o;
    assert_int_equal(output_open(&o, at("keep")), 0);
    fputs("new\n", o.fp);
    assert_int_equal(entries(), 1); /* no temporary name while it is written */
    assert_int_equal(output_close(&o, false), 0);
    assert_string_equal(read_text(at("keep")), "old\n");
    assert_int_equal(entries(), 1);
}

/* Names of 249 to 255 bytes (the longest a directory holds) are written like any. */
static void long_names(void **state)
{
    (void)state;
    for (int len = 249; len <= 255; len++) {
        char name[256];
        memset(name, 'n', (size_t)len);
        name[len] = '\0';
        int e;
        write_text(at(name), "long\n", &e);
        assert_int_equal(e, 0);
        assert_string_equal(read_text(at(name)), "long\n");
        unlink(at(name));
    }
    assert_int_equal(entries(), 0);
}

static void links_followed(void **state)
{
    (void)state;
    int e;
    assert_int_equal(symlink("target", at("link")), 0);
    write_text(at("link"), "through\n", &e); /* dangling: its target is made */
    assert_int_equal(e, 0);
    assert_true(S_ISLNK(mode_of(at("link"))));
    assert_string_equal(read_text(at("target")), "through\n");
    write_text(at("link"), "again\n", &e);
    assert_true(S_ISLNK(mode_of(at("link"))));
    assert_string_equal(read_text(at("target")), "again\n");
}

/* A FIFO is written in place (a reader gets the text) and stays a FIFO. */
static void fifo_in_place(void **state)
{
    (void)state;
    assert_int_equal(mkfifo(at("fifo"), 0600), 0);
    pid_t pid = fork();
    assert_true(pid >= 0);
    if (pid == 0) {
        FILE *f = fopen(at("fifo"), "r");
        char buf[64] = "";
        size_t n = f ? fread(buf, 1, sizeof buf - 1, f) : 0;
        buf[n] = '\0';
        _exit(strcmp(buf, "piped\n") == 0 ? 0 : 1);
    }
    int e;
    write_text(at("fifo"), "piped\n", &e);
    assert_int_equal(e, 0);
    int status;
    waitpid(pid, &status, 0);
    assert_true(WIFEXITED(status) && WEXITSTATUS(status) == 0);
    assert_true(S_ISFIFO(mode_of(at("fifo"))));
}

/* A character device (/dev/null; a link to it here, since the test may not make one) is
 * written in place: it is still the device after. */
static void device_in_place(void **state)
{
    (void)state;
    assert_int_equal(symlink("/dev/null", at("null")), 0);
    int e;
    write_text(at("null"), "gone\n", &e);
    assert_int_equal(e, 0);
    assert_true(S_ISCHR(mode_of("/dev/null")));
    assert_true(S_ISLNK(mode_of(at("null"))));
    /* A directory is refused. */
    struct output o;
    assert_int_equal(output_open(&o, dir), EISDIR);
}

/* output_link_new never replaces a name that exists. */
static void exclusive(void **state)
{
    (void)state;
    int e;
    write_text(at("taken"), "first\n", &e);
    struct output o;
    assert_int_equal(output_open(&o, at("taken")), 0);
    fputs("second\n", o.fp);
    assert_int_equal(output_link_new(&o, at("taken")), EEXIST);
    assert_int_equal(output_link_new(&o, at("free")), 0);
    assert_int_equal(output_close(&o, false), 0);
    assert_string_equal(read_text(at("taken")), "first\n");
    assert_string_equal(read_text(at("free")), "second\n");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup_teardown(modes_and_umask, make_dir, remove_dir),
        cmocka_unit_test_setup_teardown(abandoned_and_nothing_beside, make_dir, remove_dir),
        cmocka_unit_test_setup_teardown(long_names, make_dir, remove_dir),
        cmocka_unit_test_setup_teardown(links_followed, make_dir, remove_dir),
        cmocka_unit_test_setup_teardown(fifo_in_place, make_dir, remove_dir),
        cmocka_unit_test_setup_teardown(device_in_place, make_dir, remove_dir),
        cmocka_unit_test_setup_teardown(exclusive, make_dir, remove_dir),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
