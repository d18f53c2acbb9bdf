/* test_braille.c: the dot canvas against the Unicode braille layout (dots 1-8 as
 * bits 0-7: 1 4 / 2 5 / 3 6 / 7 8) and the drawille cell mapping. */
#include "testutil.h"

#include <string.h>

#include "app/braille.h"

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

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(dot_bits),
        cmocka_unit_test(glyphs),
        cmocka_unit_test(lines_and_spans),
    };
    return cmocka_run_group_tests_name("braille", tests, NULL, NULL);
}
