/* test_lesson.c: lessons that play (app/lesson_play.c) and their captions (app/caption.c).
 * A run played a step at a time until lesson_run_over, as the interactive program plays
 * it, ends bit for bit where the run done at once ends; a stop leaves a run, and the dry
 * run, at once; a lesson's runs are bounded (their simulated time, when it is read) and
 * refused with FILE:LINE, and the dry run of the longest can be left; the words speed and
 * wait. Captions are cut
 * in screen columns (a CJK character two, a combining mark none), never inside a UTF-8
 * sequence, keep every word, escape U+202E, and every built-in lesson's every step fits
 * the panel at 80x24 and 60x20 by its scroll. */
#include "testutil.h"

#include <dirent.h>
#include <locale.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <unistr.h>
#include <uniwidth.h>

#include "app/app.h"
#include "lab/caption.h"
#include "app/clock.h"
#include "app/command.h"
#include "lab/lesson.h"

static char dir[] = "/tmp/springsim-lesson-XXXXXX";

/* Writes text to dir/name.lesson; its path into path. */
static void write_lesson(const char *name, const char *text, char *path, size_t len)
{
    snprintf(path, len, "%s/%s.lesson", dir, name);
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    fputs(text, f);
    fclose(f);
}

static struct app a, b;

static void two_apps(void)
{
    static struct config c;
    config_init(&c);
    c.masses = 3;
    c.frequency = 0.9;
    assert_int_equal(app_init(&a, &c, SRCDIR), 0);
    assert_int_equal(app_init(&b, &c, SRCDIR), 0);
}

/* A run played a step at a time (the program's clock asks teach_step, which stops at
 * lesson_run_over) ends where lesson_run ends, bit for bit; so does one finished at once
 * half way (space), for several lengths that are not whole steps. */
static void played_run_is_the_run(void **state)
{
    (void)state;
    static const double lengths[] = {15.0, 1.34, 0.005, 2.0 / 3.0};
    char sa[4096], sb[4096];
    two_apps();
    for (size_t k = 0; k < sizeof lengths / sizeof *lengths; k++) {
        assert_true(lesson_run(&a, lengths[k]));
        double end = sim_time(b.sim) + lengths[k];
        b.running = true;
        int steps = 0;
        while (!lesson_run_over(&b, end) && (k % 2 == 0 || steps < 7)) {
            assert_true(app_step(&b) != 0);
            steps++;
        }
        assert_true(lesson_run_to(&b, end, NULL)); /* what is left, at once */
        assert_false(a.running || b.running);
        lesson_state(&a, sa, sizeof sa);
        lesson_state(&b, sb, sizeof sb);
        assert_string_equal(sa, sb);
    }
    app_free(&a);
    app_free(&b);
}

static int polls;
static double said_at; /* when stop_third said to stop */
static bool stop_third(void *ctx)
{
    (void)ctx;
    if (++polls < 3)
        return false;
    said_at = app_clock_now();
    return true;
}

/* A stop is asked every LESSON_POLL seconds and ends the run at once when it says so. */
static void stop_ends_a_run(void **state)
{
    (void)state;
    two_apps();
    struct lesson_stop stop = {.fn = stop_third};
    polls = 0;
    double start = app_clock_now();
    assert_false(lesson_run_to(&a, 1e7, &stop)); /* far more than a second of steps */
    assert_true(stop.said);
    assert_int_equal(polls, 3);
    assert_true(said_at - start >= 2 * LESSON_POLL);
    assert_true(app_clock_now() - said_at < 0.2); /* at once: the 0.2 s a user is promised */
    assert_false(a.running);
    app_free(&a);
    app_free(&b);
}

/* The runs' simulated time is bounded when the lesson is read: the run that passes
 * LESSON_MAX_SECONDS is named by its line; up to it, the lesson is read. */
static void total_time_bounded(void **state)
{
    (void)state;
    char path[4200], err[2048], text[4096];
    struct lesson l;
    snprintf(text, sizeof text, "title t\npreset resonance\nrun 1000\nsay x\nrun 800\n");
    write_lesson("ok", text, path, sizeof path);
    assert_int_equal(lesson_read(path, &l, err, sizeof err), 0);
    assert_close(l.seconds, 1800.0, 0.0);
    lesson_free(&l);
    snprintf(text, sizeof text, "title t\npreset resonance\nrun 1000\nsay x\nrun 800.5\n");
    write_lesson("long", text, path, sizeof path);
    assert_int_equal(lesson_read(path, &l, err, sizeof err), 2);
    char want[4400];
    snprintf(want, sizeof want, "%s:5: run 800.5: ", path);
    assert_memory_equal(err, want, strlen(want));
    assert_non_null(strstr(err, "1800 s (30 minutes)"));
}

/* A step's caption longer than the panel's buffer is refused where it passes it, never
 * cut; the next step starts afresh. */
static void caption_bounded(void **state)
{
    (void)state;
    char path[4200], err[2048], line[120];
    static char text[8192];
    struct lesson l;
    size_t used = (size_t)snprintf(text, sizeof text, "title t\npreset resonance\n");
    memset(line, 'w', 99);
    line[99] = '\0';
    for (int i = 0; i < 20; i++) /* 20 lines of 104 bytes: 2080 */
        used += (size_t)snprintf(text + used, sizeof text - used, "say %s\n%s", line,
                                 i == 9 ? "pause\n" : "");
    write_lesson("cap", text, path, sizeof path);
    assert_int_equal(lesson_read(path, &l, err, sizeof err), 0); /* 10 + 10 lines */
    lesson_free(&l);
    used = (size_t)snprintf(text, sizeof text, "title t\npreset resonance\n");
    for (int i = 0; i < 21; i++)
        used += (size_t)snprintf(text + used, sizeof text - used, "say %s\n", line);
    write_lesson("cap2", text, path, sizeof path);
    assert_int_equal(lesson_read(path, &l, err, sizeof err), 2);
    assert_non_null(strstr(err, ".lesson:23: the step's say lines come to more than 2047"));
}

/* The dry run of the longest lesson there may be (ten masses at the smallest dt for 30
 * simulated minutes: 1.8 million steps) is left within a poll when a stop says so. */
static void check_left(void **state)
{
    (void)state;
    char path[4200], err[2048];
    struct lesson l;
    static struct config base;
    config_init(&base);
    double start;
    write_lesson("left", "title t\npreset resonance\nset masses 10\nset dt 0.001\nrun 1000\n"
                 "run 800\n", path, sizeof path);
    assert_int_equal(lesson_read(path, &l, err, sizeof err), 0);
    struct lesson_stop stop = {.fn = stop_third};
    polls = 0;
    start = app_clock_now();
    assert_int_equal(lesson_check(&l, &base, SRCDIR, &stop, err, sizeof err), LESSON_LEFT);
    /* asked while it ran, and once it said so, left within the 0.2 s a user is promised
     * (Esc leaves the check): no step after it (it was 10 ms here, which a loaded
     * machine under AddressSanitizer missed by a context switch) */
    assert_int_equal(polls, 3);
    assert_true(said_at > start);
    assert_true(app_clock_now() - said_at < 0.2);
    assert_non_null(strstr(err, "the check was left"));
    lesson_free(&l);
}

/* speed N is the Speed control's; wait SECONDS a wall-clock wait the plain mode skips. */
static void speed_and_wait(void **state)
{
    (void)state;
    char path[4200], err[2048];
    struct lesson l;
    write_lesson("sw", "title t\npreset resonance\nspeed 2\nwait 1.5\nrun 1\n", path, sizeof path);
    assert_int_equal(lesson_read(path, &l, err, sizeof err), 0);
    assert_int_equal(l.items[1].kind, LESSON_COMMAND);
    assert_string_equal(l.items[1].text, "set speed 2");
    assert_int_equal(l.items[2].kind, LESSON_WAIT);
    assert_close(l.items[2].value, 1.5, 0.0);
    static struct config base;
    config_init(&base);
    assert_int_equal(lesson_check(&l, &base, SRCDIR, NULL, err, sizeof err), 0);
    lesson_free(&l);
    write_lesson("bad", "title t\npreset resonance\nwait -1\n", path, sizeof path);
    assert_int_equal(lesson_read(path, &l, err, sizeof err), 2);
    assert_non_null(strstr(err, ":3: wait: '-1'"));
    write_lesson("bad2", "title t\npreset resonance\nspeed 50\n", path, sizeof path);
    assert_int_equal(lesson_read(path, &l, err, sizeof err), 0);
    assert_int_equal(lesson_check(&l, &base, SRCDIR, NULL, err, sizeof err), 2);
    assert_non_null(strstr(err, ":3: "));
    lesson_free(&l);
}

/* Screen columns of a line, counted independently of caption.c: libunistring's u8_width. */
static int columns(const char *s)
{
    return u8_width((const uint8_t *)s, strlen(s), "UTF-8");
}

/* The words of text, blank-separated, in order, into one string with single blanks. */
static void words_of(const char *text, char *out, size_t len)
{
    size_t o = 0;
    for (const char *s = text; *s;) {
        s += strspn(s, " \n");
        size_t n = strcspn(s, " \n");
        if (n && o + n + 2 < len) {
            o += (size_t)snprintf(out + o, len - o, "%s%.*s", o ? " " : "", (int)n, s);
        }
        s += n;
    }
    out[o] = '\0';
}

/* Wraps text at cols and checks every line: at most cols columns, valid UTF-8, and the
 * words all there in order (a word cut for being too wide joined back). */
static int check_wrap(const char *text, int cols, bool cut_words)
{
    static char lines[96][CAPTION_LINE];
    char got[8192] = "", want[8192];
    int n = caption_wrap(text, cols, lines, 0, 96);
    size_t o = 0;
    for (int i = 0; i < n; i++) {
        assert_true(columns(lines[i]) <= cols || u8_mbsnlen((const uint8_t *)lines[i],
                                                            strlen(lines[i])) == 1);
        assert_null(u8_check((const uint8_t *)lines[i], strlen(lines[i])));
        o += (size_t)snprintf(got + o, sizeof got - o, "%s%s", i && !cut_words ? " " : "",
                              lines[i]);
    }
    words_of(text, want, sizeof want);
    if (cut_words) {
        char *w = want, *g = got;
        for (char *s = want; *s; s++)
            if (*s != ' ')
                *w++ = *s;
        *w = '\0';
        for (char *s = got; *s; s++)
            if (*s != ' ')
                *g++ = *s;
        *g = '\0';
    }
    assert_string_equal(got, want);
    return n;
}

/* Columns, not characters: CJK takes two, combining marks none; no line wider than the
 * panel, no cut inside a sequence, no word lost; U+202E escaped; ASCII spellings. */
static void captions_in_columns(void **state)
{
    (void)state;
    char safe[4096];
    static char lines[8][CAPTION_LINE];
    /* Ten CJK characters are 20 columns: at 11 columns, five a line. */
    const char *cjk = "質量と" "ばねと" "ダンパ" "ー";
    assert_int_equal(check_wrap(cjk, 11, true), 2);
    assert_int_equal(caption_wrap(cjk, 11, lines, 0, 8), 2);
    assert_int_equal(columns(lines[0]), 10);
    /* e + combining acute is one column: "cafe\u0301 " fits five columns a word. */
    assert_int_equal(check_wrap("cafe\xcc\x81 cafe\xcc\x81 cafe\xcc\x81", 9, false), 2);
    caption_wrap("cafe\xcc\x81 cafe\xcc\x81 cafe\xcc\x81", 9, lines, 0, 8);
    assert_string_equal(lines[0], "cafe\xcc\x81 cafe\xcc\x81");
    /* A paragraph of mixed text at several widths. */
    const char *mixed = "The swing 振幅 grows: ζ = c / (2 √(2k m)) = 0.0559, δ = 2π ζ / "
                        "√(1 − ζ²) = 0.352, and ω = 4.47 rad/s; 共振 at f1 = 0.712 Hz.";
    for (int cols = 6; cols <= 80; cols++)
        check_wrap(mixed, cols, cols < 12);
    /* The last line is not one word when narrower lines avoid it at no cost. */
    int n = caption_wrap("aa bb cc dd ee ff gg hh ii", 11, lines, 0, 8);
    assert_int_equal(n, 3);
    assert_non_null(strchr(lines[n - 1], ' '));
    /* U+202E would turn the line around: it is shown as \u202e. */
    caption_text("left \xe2\x80\xae right", true, safe, sizeof safe);
    assert_string_equal(safe, "left \\u202e right");
    caption_text("ζ δ π √ ω 共", false, safe, sizeof safe);
    assert_string_equal(safe, "zeta delta pi sqrt w ?");
    assert_int_equal(caption_width("共振 ζ"), 6);
}

/* Whether every escape the program wrote (\xNN, \uXXXX, \UXXXXXXXX) in the lines is
 * whole: a backslash not followed, on its own line, by the rest of its escape is one cut. */
static bool escapes_whole(char (*lines)[CAPTION_LINE], int n)
{
    for (int i = 0; i < n; i++)
        for (const char *s = strchr(lines[i], '\\'); s; s = strchr(s + 1, '\\')) {
            size_t want = s[1] == 'x' ? 4 : s[1] == 'u' ? 6 : s[1] == 'U' ? 10 : 2;
            if (strlen(s) < want)
                return false;
        }
    return true;
}

/* A word of escaped characters (a joiner, an escape byte, a plane-1 format character)
 * and CJK is cut between characters, never inside an escape, a UTF-8 sequence or a wide
 * character, at every width. */
static void captions_keep_escapes(void **state)
{
    (void)state;
    static char lines[96][CAPTION_LINE];
    char safe[4096];
    caption_text("a\xe2\x80\x8d" "b\x1b" "c\xf3\xa0\x80\x81" "d共\xe2\x80\x8d" "振e word "
                 "x\xe2\x80\x8dx\xe2\x80\x8dx\xe2\x80\x8dx\xe2\x80\x8dx", true, safe, sizeof safe);
    assert_non_null(strstr(safe, "\\u200d"));
    assert_non_null(strstr(safe, "\\x1b"));
    assert_non_null(strstr(safe, "\\U000e0001"));
    for (int cols = 1; cols <= 40; cols++) {
        int n = caption_wrap(safe, cols, lines, 0, 96);
        assert_true(escapes_whole(lines, n));
        for (int i = 0; i < n; i++) {
            assert_null(u8_check((const uint8_t *)lines[i], strlen(lines[i])));
            /* wider than the panel only when one unit (an escape, a wide character) is */
            assert_true(columns(lines[i]) <= (cols > 10 ? cols : 10));
        }
    }
}

/* Every step's caption of every built-in lesson, as the panel shows it (one paragraph,
 * the question and its choices), fits its rows at 80x24 and 60x20 or scrolls: the lines
 * are all there and every word of every say line is among them. */
static void builtin_captions_whole(void **state)
{
    (void)state;
    DIR *d = opendir(SRCDIR "/lessons");
    assert_non_null(d);
    struct dirent *e;
    int lessons = 0;
    static char lines[96][CAPTION_LINE];
    while ((e = readdir(d))) {
        if (!strstr(e->d_name, ".lesson"))
            continue;
        char path[4200], err[2048];
        struct lesson l;
        snprintf(path, sizeof path, "%s/lessons/%s", SRCDIR, e->d_name);
        assert_int_equal(lesson_read(path, &l, err, sizeof err), 0);
        lessons++;
        static const int widths[] = {76, 56};
        for (int k = 0; k < 2; k++) {
            struct lesson_play p;
            const struct lesson_item *it;
            lesson_play_start(&p, &l);
            for (;;) {
                while ((it = lesson_next(&p)))
                    ;
                char para[LESSON_CAPTION], safe[4 * LESSON_CAPTION];
                snprintf(para, sizeof para, "%s", p.new_caption ? "" : p.caption);
                for (char *c = para; *c; c++)
                    *c = *c == '\n' ? ' ' : *c;
                caption_text(para, true, safe, sizeof safe);
                int n = caption_wrap(safe, widths[k], lines, 0, 96);
                assert_true(n < 96);
                char all[8192] = "", want[8192], got[8192];
                for (int i = 0; i < n; i++) {
                    assert_true(columns(lines[i]) <= widths[k]);
                    strcat(all, i ? " " : "");
                    strcat(all, lines[i]);
                }
                words_of(safe, want, sizeof want);
                words_of(all, got, sizeof got);
                assert_string_equal(got, want);
                if (p.waiting < 0)
                    break;
                lesson_go_on(&p);
            }
        }
        lesson_free(&l);
    }
    closedir(d);
    assert_true(lessons >= 6);
}

static int cleanup(void **state)
{
    (void)state;
    char cmd[200];
    snprintf(cmd, sizeof cmd, "rm -rf %s", dir);
    return system(cmd) != 0;
}

int main(void)
{
    setlocale(LC_ALL, "C.UTF-8");
    if (!mkdtemp(dir))
        return 1;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(played_run_is_the_run),
        cmocka_unit_test(stop_ends_a_run),
        cmocka_unit_test(total_time_bounded),
        cmocka_unit_test(check_left),
        cmocka_unit_test(speed_and_wait),
        cmocka_unit_test(caption_bounded),
        cmocka_unit_test(captions_in_columns),
        cmocka_unit_test(captions_keep_escapes),
        cmocka_unit_test(builtin_captions_whole),
    };
    int failed = cmocka_run_group_tests(tests, NULL, cleanup);
    return failed;
}
