/* test_braille.c: the dot canvas against the Unicode braille layout (dots 1-8 as
 * bits 0-7: 1 4 / 2 5 / 3 6 / 7 8), the drawille cell mapping, and the quadrant blocks
 * that stand in for braille. */
#include "testutil.h"

#include <math.h>
#include <string.h>

#include "chart/braille.h"
#include "chart/strokes.h"

static void dot_bits(void **state)
{
    (void)state;
    /* (x % 2, y % 4) -> braille dot number. */
    static const int dot[4][2] = {{1, 4}, {2, 5}, {3, 6}, {7, 8}};
    struct canvas *c = canvas_new(3, 2);
    for (int y = 0; y < 4; y++) {
        for (int x = 0; x < 2; x++) {
            canvas_clear(c);
            canvas_set(c, 2 + x, 4 + y, 5); /* cell (1, 1) */
            assert_int_equal(canvas_bits(c, 1, 1), 1 << (dot[y][x] - 1));
            assert_int_equal(canvas_bits(c, 0, 0), 0);
            assert_int_equal(c->color[1 * 3 + 1], 5);
        }
    }
    canvas_set(c, -1, 0, 1); /* off the canvas: ignored */
    canvas_set(c, 6, 0, 1);
    canvas_set(c, 0, 8, 1);
    for (int cy = 0; cy < 2; cy++)
        for (int cx = 0; cx < 3; cx++)
            assert_true(cy == 1 && cx == 1 ? 1 : canvas_bits(c, cx, cy) == 0);
    canvas_free(c);
}

static void glyphs(void **state)
{
    (void)state;
    char g[5];
    braille_utf8(0x00, g);
    assert_string_equal(g, "\xE2\xA0\x80"); /* U+2800 */
    braille_utf8(0xFF, g);
    assert_string_equal(g, "⣿");
    braille_utf8(0x47, g); /* dots 1 2 3 7: the left column */
    assert_string_equal(g, "⡇");
    assert_int_equal(braille_ascii(0), ' ');
    assert_int_equal(braille_ascii(0x47), '|');
    assert_int_equal(braille_ascii(0x40), '.');
    assert_int_equal(braille_ascii(0x01), '\'');
}

/* Every pattern of a cell's eight dots, set by position: the block glyph fills exactly the
 * quadrants (2x2 dots each) that hold a dot. The glyphs' quadrants are read off their
 * Unicode names. */
static void quadrants(void **state)
{
    (void)state;
    enum { UL = 1, UR = 2, LL = 4, LR = 8 };
    static const struct {
        unsigned cp;
        int filled;
    } names[] = {
        {0x2598, UL},           /* QUADRANT UPPER LEFT */
        {0x259D, UR},           /* QUADRANT UPPER RIGHT */
        {0x2596, LL},           /* QUADRANT LOWER LEFT */
        {0x2597, LR},           /* QUADRANT LOWER RIGHT */
        {0x2580, UL | UR},      /* UPPER HALF BLOCK */
        {0x2584, LL | LR},      /* LOWER HALF BLOCK */
        {0x258C, UL | LL},      /* LEFT HALF BLOCK */
        {0x2590, UR | LR},      /* RIGHT HALF BLOCK */
        {0x259A, UL | LR},      /* QUADRANT UPPER LEFT AND LOWER RIGHT */
        {0x259E, UR | LL},      /* QUADRANT UPPER RIGHT AND LOWER LEFT */
        {0x259B, UL | UR | LL}, /* QUADRANT UPPER LEFT AND UPPER RIGHT AND LOWER LEFT */
        {0x259C, UL | UR | LR}, /* QUADRANT UPPER LEFT AND UPPER RIGHT AND LOWER RIGHT */
        {0x2599, UL | LL | LR}, /* QUADRANT UPPER LEFT AND LOWER LEFT AND LOWER RIGHT */
        {0x259F, UR | LL | LR}, /* QUADRANT UPPER RIGHT AND LOWER LEFT AND LOWER RIGHT */
        {0x2588, UL | UR | LL | LR}, /* FULL BLOCK */
    };
    struct canvas *c = canvas_new(1, 1);
    for (int pattern = 0; pattern < 256; pattern++) {
        canvas_clear(c);
        int want = 0;
        for (int d = 0; d < 8; d++) {
            if (!(pattern >> d & 1))
                continue;
            int x = d % 2, y = d / 2;
            canvas_set(c, x, y, 1);
            want |= (y < 2 ? (x ? UR : UL) : (x ? LR : LL));
        }
        unsigned got = braille_quadrant(canvas_bits(c, 0, 0));
        if (!want) {
            assert_int_equal(got, 0);
            continue;
        }
        size_t i = 0;
        while (i < sizeof names / sizeof *names && names[i].cp != got)
            i++;
        assert_true(i < sizeof names / sizeof *names);
        assert_int_equal(names[i].filled, want);
    }
    canvas_free(c);
}

static void lines_and_spans(void **state)
{
    (void)state;
    struct canvas *c = canvas_new(4, 1); /* 8 x 4 dots */
    canvas_line(c, 0, 0, 7, 3, 2);
    /* A diagonal across: both ends and every column lit. */
    for (int cx = 0; cx < 4; cx++)
        assert_true(canvas_bits(c, cx, 0) != 0);
    assert_true(canvas_bits(c, 0, 0) & 0x01);
    assert_true(canvas_bits(c, 3, 0) & 0x80);
    canvas_clear(c);
    canvas_vspan(c, 3, 3, 0, 1); /* reversed order works too */
    assert_int_equal(canvas_bits(c, 1, 0), 0x08 | 0x10 | 0x20 | 0x80);
    canvas_vspan(c, 0, -5, 99, 1); /* clipped */
    assert_int_equal(canvas_bits(c, 0, 0), 0x47);
    canvas_free(c);
    assert_null(canvas_new(0, 3));
}

/* A canvas muted keeps no strokes of its own; marks carry their size, and the hash tells
 * two sizes apart (an image is sent again when only the discs changed). */
static void strokes_kept(void **state)
{
    (void)state;
    struct canvas *c = canvas_new(4, 2);
    assert_non_null(c);
    assert_true(canvas_keep_strokes(c));
    canvas_line(c, 0, 0, 7, 7, 1);
    assert_int_equal(c->strokes->ns, 1);
    c->mute++;
    canvas_line(c, 0, 7, 7, 0, 1);
    canvas_set(c, 3, 3, 2);
    c->mute--;
    assert_int_equal(c->strokes->ns, 1);
    struct strokes *k = c->strokes;
    strokes_begin(k, 2, STROKE_MARKS);
    strokes_mark_size(k, 3);
    strokes_point(k, 2.25, 3.5);
    assert_int_equal(k->s[1].size, 3);
    assert_int_equal(k->s[1].count, 1);
    uint64_t h = strokes_hash(k);
    strokes_mark_size(k, 4);
    assert_true(strokes_hash(k) != h);
    strokes_mark_size(k, 3);
    assert_true(strokes_hash(k) == h);
    canvas_free(c);
}

/* canvas_record(false) keeps no strokes from the next clear on (the braille is the same);
 * on again, they are kept; a mark's size and shape survive a break in its stroke. */
static void recording_switch(void **state)
{
    (void)state;
    struct canvas *c = canvas_new(4, 2);
    assert_non_null(c);
    assert_true(canvas_keep_strokes(c));
    canvas_record(false);
    canvas_clear(c);
    assert_null(c->strokes);
    canvas_line(c, 0, 0, 7, 7, 3);
    uint8_t off[8];
    memcpy(off, c->bits, sizeof off);
    canvas_record(true);
    canvas_clear(c);
    assert_non_null(c->strokes);
    canvas_line(c, 0, 0, 7, 7, 3);
    assert_memory_equal(off, c->bits, sizeof off);
    assert_int_equal(c->strokes->ns, 1);
    assert_int_equal(c->strokes->n, 2);

    struct strokes *k = c->strokes;
    strokes_clear(k);
    strokes_begin(k, 5, STROKE_MARKS);
    strokes_mark_size(k, 3);
    strokes_mark_shape(k, MARK_DOWN);
    strokes_point(k, 1.0, 1.0);
    strokes_point(k, NAN, NAN);
    strokes_point(k, 2.0, 2.0);
    assert_int_equal(k->ns, 2);
    assert_int_equal(k->s[1].kind, STROKE_MARKS);
    assert_int_equal(k->s[1].size, 3);
    assert_int_equal(k->s[1].shape, MARK_DOWN);
    canvas_free(c);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(dot_bits),
        cmocka_unit_test(glyphs),
        cmocka_unit_test(quadrants),
        cmocka_unit_test(lines_and_spans),
        cmocka_unit_test(strokes_kept),
        cmocka_unit_test(recording_switch),
    };
    return cmocka_run_group_tests_name("braille", tests, NULL, NULL);
}
