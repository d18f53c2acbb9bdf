/* test_answer.c: the terminal's answers told from keys (app/answer.c). Each answer the
 * start-up queries bring (device attributes, sizes, XTSMGRAPHICS, OSC 11 and OSC 4 with
 * ST or BEL, kitty's APC, DCS) is swallowed whole wherever it falls among keys, in one
 * piece or byte by byte, and the keys around it come out in their order; what only looks
 * like the start of an answer (Esc, Alt+[ or Alt+]) comes back as the keys it was; an
 * answer cut off or broken (a hostile terminal's garbage), a CSI sequence that is no
 * answer (a key curses did not know, a focus event) and one too long to keep are dropped
 * whole, never keys; an 8-bit introducer (CSI 0x9b, OSC 0x9d, APC 0x9f, DCS 0x90) begins
 * one and 8-bit ST (0x9c) ends a string, but not inside a UTF-8 character. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>

#include <cmocka.h>

#include "app/answer.h"

static struct answer_scan scan;

/* Feeds text at time t (one byte each), then tells the scanner nothing follows; returns
 * the keys that came out as a string and the answers in answers (joined by '|'). */
static const char *run(const char *text, double t, char *answers, size_t size)
{
    static char keys[4096];
    size_t n = 0;
    answers[0] = '\0';
    for (const char *p = text; *p; p++)
        if (answer_feed(&scan, (unsigned char)*p, t)) {
            strncat(answers, scan.answer, size - strlen(answers) - 2);
            strcat(answers, "|");
        }
    answer_idle(&scan, t + 1.0);
    int k;
    while ((k = answer_key(&scan)) >= 0 && n < sizeof keys - 1)
        keys[n++] = (char)k;
    keys[n] = '\0';
    return keys;
}

static void setup_scan(void)
{
    memset(&scan, 0, sizeof scan);
}

static void answers_between_keys(void **state)
{
    (void)state;
    char ans[2048];
    setup_scan();
    const char *in = "a\033[?63;1;2;4;6;9;15;22cb\033[6;20;10tc\033[4;600;1000t"
                     "d\033[?1;0;256Se\033]11;rgb:ffff/ffff/ffff\033\\f"
                     "\033]4;1;rgb:cd00/0000/0000\007g\033_Gi=31;OK\033\\h"
                     "\033P1$r0m\033\\i";
    assert_string_equal(run(in, 0.0, ans, sizeof ans), "abcdefghi");
    assert_string_equal(ans, "\033[?63;1;2;4;6;9;15;22c|\033[6;20;10t|\033[4;600;1000t|"
                             "\033[?1;0;256S|\033]11;rgb:ffff/ffff/ffff\033\\|"
                             "\033]4;1;rgb:cd00/0000/0000\007|\033_Gi=31;OK\033\\|"
                             "\033P1$r0m\033\\|");
    assert_int_equal(scan.answers, 8);
}

/* The answers of a terminal 150 ms late, read one byte per call as curses hands them
 * over, between keys typed before and after: the keys, nothing of the answers. */
static void byte_by_byte_late(void **state)
{
    (void)state;
    setup_scan();
    const char *in = " \033[?62;1;2;6;9;15;22c\033[6;20;10tq";
    double t = 0.15;
    int keys[64], n = 0, k;
    for (const char *p = in; *p; p++, t += 0.001) {
        answer_feed(&scan, (unsigned char)*p, t);
        if (*p != 0x1b) /* curses hands over what follows an Esc with it */
            answer_idle(&scan, t); /* nothing more yet: a part-answer stays held */
        while ((k = answer_key(&scan)) >= 0 && n < 64)
            keys[n++] = k;
    }
    assert_int_equal(n, 2);
    assert_int_equal(keys[0], ' ');
    assert_int_equal(keys[1], 'q');
    assert_int_equal(scan.answers, 2);
}

/* What only starts like an answer is keys. */
static void not_answers(void **state)
{
    (void)state;
    char ans[256];
    setup_scan();
    /* A lone Esc, Esc then a letter (Alt+x), Esc Esc. */
    assert_string_equal(run("\033", 0, ans, sizeof ans), "\033");
    assert_string_equal(run("\033x\033\033y", 0, ans, sizeof ans), "\033x\033\033y");
    /* Keys curses did not translate, focus events, a paste's end alone, a wrong final byte:
     * CSI sequences that are no answer, dropped (their [ and digits would act). */
    assert_string_equal(run("\033[A\033[1;5Cx\033[15~\033[I\033[O\033[201~\033[6;16;8T", 0,
                            ans, sizeof ans),
                        "x");
    /* 8-bit CSI: an answer; the same byte inside a UTF-8 character (ě is C4 9B): keys. */
    assert_string_equal(run("\x9b?63;1;2;4cq", 0, ans, sizeof ans), "q");
    assert_string_equal(ans, "\033[?63;1;2;4c|");
    assert_string_equal(run("\xc4\x9b?", 0, ans, sizeof ans), "\xc4\x9b?");
    /* CSI t and CSI c whatever their parameters: a terminal's garbage, swallowed. */
    assert_string_equal(run("\033[4;-5;-7t\033[>0;1c", 0, ans, sizeof ans), "");
    assert_string_equal(ans, "\033[4;-5;-7t|\033[>0;1c|");
    /* Alt+] then Enter: keys. */
    assert_string_equal(run("\033]\rc", 0, ans, sizeof ans), "\033]\rc");
    /* A string cut by a control character: dropped, what follows is keys. */
    assert_string_equal(run("\033]ab\rc", 0, ans, sizeof ans), "\rc");
    /* An ESC inside a string that is not ST: what came before is dropped, the ESC begins
     * again (here an answer). A hostile terminal's unended OSC before a size answer:
     * nothing of it reaches the keys (its ], g, r acted as keys). */
    assert_string_equal(run("\033_x\033[?1c", 0, ans, sizeof ans), "");
    assert_string_equal(ans, "\033[?1c|");
    assert_string_equal(run("\033]11;rgb:zz\033[4;270000;100tq", 0, ans, sizeof ans), "q");
    assert_string_equal(ans, "\033[4;270000;100t|");
    /* A CSI with numbers cut by an Esc: dropped. */
    assert_string_equal(run("\033[6;9000\033[?6cq", 0, ans, sizeof ans), "q");
    /* A curses key code (above 255) ends a part-answer: it and the code are keys. */
    setup_scan();
    answer_feed(&scan, 0x1b, 0);
    answer_feed(&scan, '[', 0);
    answer_feed(&scan, 0x103, 0);
    assert_int_equal(answer_key(&scan), 0x1b);
    assert_int_equal(answer_key(&scan), '[');
    assert_int_equal(answer_key(&scan), 0x103);
    assert_int_equal(answer_key(&scan), -1);
}

/* A part-answer quiet past ANSWER_GAP goes on only with what an answer holds there, else
 * is dropped (or keys: Alt+]); a lone Esc is a key after ANSWER_ESC_WAIT. */
static void gaps(void **state)
{
    (void)state;
    setup_scan();
    answer_feed(&scan, 0x1b, 1.0);
    answer_feed(&scan, '[', 1.0);
    answer_feed(&scan, '?', 1.0);
    answer_idle(&scan, 1.0 + ANSWER_GAP * 0.5);
    assert_int_equal(answer_key(&scan), -1);
    assert_true(answer_holding(&scan));
    /* The rest within the gap: one answer. */
    assert_false(answer_feed(&scan, '6', 1.0 + ANSWER_GAP * 0.9));
    assert_true(answer_feed(&scan, 'c', 1.0 + ANSWER_GAP * 1.5));
    assert_string_equal(scan.answer, "\033[?6c");
    assert_int_equal(answer_key(&scan), -1);
    /* A part-answer quiet longer than the gap: dropped, the next byte a key. */
    answer_feed(&scan, 0x1b, 4.0);
    answer_feed(&scan, '[', 4.0);
    answer_feed(&scan, '6', 4.0);
    answer_feed(&scan, 'q', 4.0 + ANSWER_GAP * 2);
    assert_int_equal(answer_key(&scan), 'q');
    assert_int_equal(answer_key(&scan), -1);
    /* Alt+] quiet longer than the gap: keys, and the next byte is a key after them. */
    answer_feed(&scan, 0x1b, 5.0);
    answer_feed(&scan, ']', 5.0);
    answer_feed(&scan, 'z', 5.0 + ANSWER_GAP * 2);
    assert_int_equal(answer_key(&scan), 0x1b);
    assert_int_equal(answer_key(&scan), ']');
    assert_int_equal(answer_key(&scan), 'z');
    /* A lone Esc: a key once ANSWER_ESC_WAIT passed with nothing after it (a link may
     * part what a terminal sends by a few tens of milliseconds). */
    answer_feed(&scan, 0x1b, 6.0);
    answer_idle(&scan, 6.0 + ANSWER_ESC_WAIT * 0.5);
    assert_int_equal(answer_key(&scan), -1);
    answer_idle(&scan, 6.0 + ANSWER_ESC_WAIT);
    assert_int_equal(answer_key(&scan), 0x1b);
    assert_false(answer_holding(&scan));
    /* While answers are due, a lone Esc waits ANSWER_ESC_HOLD for the rest of one (a slow
     * link parted it after its Esc), then is a key. */
    answer_feed(&scan, 0x1b, 7.0);
    answer_idle_awaiting(&scan, 7.0 + ANSWER_ESC_HOLD * 0.5);
    assert_int_equal(answer_key(&scan), -1);
    assert_false(answer_feed(&scan, '[', 7.0 + ANSWER_ESC_HOLD * 0.6));
    assert_true(answer_feed(&scan, 'c', 7.0 + ANSWER_ESC_HOLD * 0.7));
    assert_int_equal(answer_key(&scan), -1);
    answer_feed(&scan, 0x1b, 8.0);
    answer_idle_awaiting(&scan, 8.0 + ANSWER_ESC_HOLD * 1.1);
    assert_int_equal(answer_key(&scan), 0x1b);
}

/* Feeds text from `at`, byte k at at + k * step, telling the scanner nothing more came
 * (answer_idle, as the loop does when nothing is there) every `idle` seconds between two
 * bytes; a gap of `gap` seconds before byte `cut` (0: none). The keys that came out. */
static const char *parted(const char *text, size_t cut, double gap, double step, double idle)
{
    static char keys[4096];
    size_t n = 0;
    double t = 100.0;
    int k;
    setup_scan();
    for (size_t i = 0; text[i]; i++) {
        double next = t + (i == cut && cut ? gap : step);
        for (double q = t + idle; i && q < next; q += idle)
            answer_idle(&scan, q);
        t = i ? next : t;
        answer_feed(&scan, (unsigned char)text[i], t);
        while ((k = answer_key(&scan)) >= 0 && n < sizeof keys - 1)
            keys[n++] = (char)k;
    }
    answer_idle(&scan, t + 2 * ANSWER_GAP);
    while ((k = answer_key(&scan)) >= 0 && n < sizeof keys - 1)
        keys[n++] = (char)k;
    keys[n] = '\0';
    return keys;
}

/* Each start-up answer parted anywhere by a slow link (1.5 s between its parts, longer
 * than ANSWER_GAP), or coming a byte every 30 ms, between two keys: the keys, and none
 * of its bytes (but an Esc parted from the rest, which no program can tell from the
 * user's). A lone Esc is still a key within ANSWER_ESC_WAIT. */
static void parted_answers(void **state)
{
    (void)state;
    static const char *const answers[] = {
        "\033[?62;1;2;6;9;15;22c", "\033[6;20;10t", "\033[4;600;1000t", "\033[?1;0;256S",
        "\033]11;rgb:ffff/ffff/ffff\033\\", "\033]4;1;rgb:cd00/0000/0000\007",
        "\033_Gi=31;OK\033\\", "\033P1$r0m\033\\"};
    for (size_t a = 0; a < sizeof answers / sizeof *answers; a++) {
        char text[128];
        snprintf(text, sizeof text, "x%sy", answers[a]);
        for (size_t cut = 2; cut + 1 < strlen(text); cut++) {
            /* Parted right after its Esc: the Esc alone is a key by then (a user's Esc
             * is never kept waiting more than ANSWER_ESC_WAIT), the rest is not. */
            const char *want = cut == 2 ? "x\033y" : "xy";
            const char *keys = parted(text, cut, 1.5, 0.0, 0.05);
            if (strcmp(keys, want) != 0)
                fail_msg("answer %zu parted before byte %zu: keys '%s'", a, cut, keys);
        }
        const char *keys = parted(text, 0, 0.0, 0.03, 0.01);
        if (strcmp(keys, "xy") != 0)
            fail_msg("answer %zu a byte every 30 ms: keys '%s'", a, keys);
    }
    setup_scan();
    answer_feed(&scan, 0x1b, 1.0);
    answer_idle(&scan, 1.0 + ANSWER_ESC_WAIT);
    assert_int_equal(answer_key(&scan), 0x1b);
    assert_true(ANSWER_ESC_WAIT <= 0.1);
    /* Parted twice while answers are due, after its Esc (past ANSWER_ESC_HOLD: the Esc
     * went as a key) and after its introducer (past ANSWER_GAP, within ANSWER_TAIL): its
     * rest is still no keys (its [, ?, 6 and c acted: slower, the help, a plot). */
    static const char *const twice[] = {"[?62;4c", "[6;20;10t", "]11;rgb:ffff/ffff/ffff\033\\",
                                        "_Gi=31;OK\033\\"};
    for (size_t a = 0; a < sizeof twice / sizeof *twice; a++) {
        setup_scan();
        double t = 10.0;
        answer_feed(&scan, 0x1b, t);
        answer_idle_awaiting(&scan, t + ANSWER_ESC_HOLD + 0.1);
        assert_int_equal(answer_key(&scan), 0x1b);
        answer_feed(&scan, (unsigned char)twice[a][0], t += 0.5);
        for (double q = t + 0.1; q < t + 1.5; q += 0.1)
            answer_idle_awaiting(&scan, q);
        t += 1.5;
        for (const char *c = twice[a] + 1; *c; c++)
            answer_feed(&scan, (unsigned char)*c, t);
        answer_feed(&scan, 'y', t);
        int k = answer_key(&scan);
        if (k != 'y')
            fail_msg("answer %zu parted twice: key '%c' came first", a, k);
    }
    /* A [ typed long after an Esc is a key at once, not held for an answer's rest. */
    answer_feed(&scan, '[', 1.0 + ANSWER_TAIL + 1.0);
    assert_int_equal(answer_key(&scan), '[');
}

/* Text pasted (bracketed paste) is no keys, whatever it holds: the keys around it are,
 * its text is kept to its first new line; a paste whose end never comes ends after
 * ANSWER_GAP. Without brackets, ANSWER_BURST printable keys read at once are a paste,
 * dropped; fewer are typing. */
static void pastes(void **state)
{
    (void)state;
    char ans[64];
    setup_scan();
    assert_string_equal(run("a\033[200~q?[]1 gG\r\033[201~b\033[200~x\033[201~", 0, ans,
                            sizeof ans), "ab");
    assert_int_equal(scan.pastes, 2);
    assert_string_equal(scan.paste, "x");
    setup_scan();
    answer_feed(&scan, 0x1b, 1.0);
    for (const char *p = "[200~12.5\rq"; *p; p++)
        answer_feed(&scan, (unsigned char)*p, 1.0);
    assert_int_equal(answer_key(&scan), -1);
    assert_string_equal(scan.paste, "12.5");
    answer_idle(&scan, 1.0 + ANSWER_GAP * 0.5);
    assert_true(scan.pasting);
    answer_feed(&scan, 'q', 1.0 + ANSWER_GAP * 2);
    assert_false(scan.pasting);
    assert_int_equal(answer_key(&scan), 'q');
    answer_paste_keys(&scan);
    assert_int_equal(answer_key(&scan), '1');
    setup_scan();
    for (int i = 0; i < ANSWER_BURST - 1; i++)
        answer_feed(&scan, ' ', 1.0);
    assert_int_equal(answer_burst(&scan), 0);
    assert_int_equal(answer_key(&scan), ' ');
    setup_scan();
    for (const char *p = "set frequency 0.7\rq"; *p; p++)
        answer_feed(&scan, (unsigned char)*p, 1.0);
    assert_int_equal(answer_burst(&scan), 19);
    assert_int_equal(answer_key(&scan), -1);
    assert_string_equal(scan.paste, "set frequency 0.7");
}

/* A string longer than ANSWER_MAX is swallowed to its end, not read; the keys after it
 * come through. A CSI that long is swallowed to its final byte too. */
static void too_long(void **state)
{
    (void)state;
    setup_scan();
    char in[3 * ANSWER_MAX], ans[64];
    strcpy(in, "\033]");
    memset(in + 2, 'x', 2 * ANSWER_MAX);
    strcpy(in + 2 + 2 * ANSWER_MAX, "\033\\q");
    assert_string_equal(run(in, 0, ans, sizeof ans), "q");
    assert_string_equal(ans, "");
    assert_int_equal(scan.dropped, 1);
    strcpy(in, "\033[");
    memset(in + 2, '1', ANSWER_MAX + 10);
    strcpy(in + 2 + ANSWER_MAX + 10, "tq");
    assert_string_equal(run(in, 0, ans, sizeof ans), "q");
    assert_string_equal(ans, "");
    assert_int_equal(scan.dropped, 2);
}

/* Answers in 8-bit form (a terminal set to send C1 controls as single bytes): OSC 0x9d,
 * APC 0x9f and DCS 0x90 begin one as CSI 0x9b does, and ST 0x9c ends a string (in 7-bit
 * strings too), so none of their bytes act as keys (DCS's 1, r, 0 and m enlarged a plot,
 * reset and opened the modes view; a 7-bit OSC ended by 0x9c swallowed every key after
 * it, q too). Inside a UTF-8 character typed, or in a string's UTF-8 text, these bytes
 * are continuation bytes. */
static void eight_bit(void **state)
{
    (void)state;
    char ans[256];
    setup_scan();
    assert_string_equal(run("a\x9d" "11;rgb:ffff/ffff/ffff\x9c" "b\x9f" "Gi=31;OK\x9c"
                            "c\x90" "1$r0m\x9c" "d\033]10;rgb:0/0/0\x9cq", 0, ans, sizeof ans),
                        "abcdq");
    assert_string_equal(ans, "\033]11;rgb:ffff/ffff/ffff\033\\|\033_Gi=31;OK\033\\|"
                             "\033P1$r0m\033\\|\033]10;rgb:0/0/0\033\\|");
    /* ŝ (C5 9D), ✜ (E2 9C 9C), Đ (C4 90), ş (C5 9F) typed: keys. */
    assert_string_equal(run("\xc5\x9d\xe2\x9c\x9c\xc4\x90\xc5\x9fq", 0, ans, sizeof ans),
                        "\xc5\x9d\xe2\x9c\x9c\xc4\x90\xc5\x9fq");
    /* ✜ inside a string's text: no ST, the string goes on to its own. */
    assert_string_equal(run("\033]2;\xe2\x9c\x9c\033\\q", 0, ans, sizeof ans), "q");
    assert_string_equal(ans, "\033]2;\xe2\x9c\x9c\033\\|");
}

/* A string answer cut off by a hostile terminal (no ST ever comes): a key typed after
 * ANSWER_GAP that no such answer holds there (q) is a key, and so is any key once
 * ANSWER_TAIL has passed since the answer began; keys typed sooner come back once the
 * string has been quiet for ANSWER_GAP (they went on with it, for ever: q never quit). */
static void cut_strings(void **state)
{
    (void)state;
    static const char *const cut[] = {"\033]11;rgb:ffff/ff", "\033_Gi=31;OK", "\033P1+r",
                                      "\033]4;1;rgb:cd"};
    for (size_t i = 0; i < sizeof cut / sizeof *cut; i++) {
        setup_scan();
        for (const char *p = cut[i]; *p; p++)
            answer_feed(&scan, (unsigned char)*p, 1.0);
        answer_feed(&scan, 'q', 1.0 + ANSWER_GAP * 2);
        int k = answer_key(&scan);
        if (k != 'q')
            fail_msg("'%s' then q after the gap: key %d", cut[i] + 1, k);
        setup_scan();
        for (const char *p = cut[i]; *p; p++)
            answer_feed(&scan, (unsigned char)*p, 1.0);
        answer_feed(&scan, 'A', 1.0 + ANSWER_TAIL * 0.5);
        answer_feed(&scan, '1', 1.0 + ANSWER_TAIL + ANSWER_GAP * 1.5);
        k = answer_key(&scan);
        if (k != '1')
            fail_msg("'%s' then 1 past ANSWER_TAIL: key %d", cut[i] + 1, k);
    }
    /* Keys typed soon after it (within the gap): once nothing came for ANSWER_GAP, those
     * from the first that no such answer holds are given back, in order. */
    setup_scan();
    for (const char *p = "\033]11;rgb:ffff/ff gq"; *p; p++)
        answer_feed(&scan, (unsigned char)*p, *p == 'q' ? 1.9 : 1.0);
    answer_idle(&scan, 1.9 + ANSWER_GAP * 0.5);
    assert_int_equal(answer_key(&scan), -1);
    answer_idle(&scan, 1.9 + ANSWER_GAP * 1.5);
    assert_int_equal(answer_key(&scan), ' ');
    assert_int_equal(answer_key(&scan), 'g');
    assert_int_equal(answer_key(&scan), 'q');
    assert_false(answer_holding(&scan));
    /* A CSI answer's digits long after it began: keys too. */
    setup_scan();
    for (const char *p = "\033[?63;1"; *p; p++)
        answer_feed(&scan, (unsigned char)*p, 1.0);
    answer_feed(&scan, '1', 1.0 + ANSWER_TAIL + ANSWER_GAP * 1.5);
    assert_int_equal(answer_key(&scan), '1');
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(answers_between_keys), cmocka_unit_test(byte_by_byte_late),
        cmocka_unit_test(not_answers),          cmocka_unit_test(gaps),
        cmocka_unit_test(too_long),             cmocka_unit_test(parted_answers),
        cmocka_unit_test(pastes),               cmocka_unit_test(eight_bit),
        cmocka_unit_test(cut_strings),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
