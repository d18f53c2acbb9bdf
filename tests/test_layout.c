/* test_layout.c: the screen's rectangles at every size from the minimum to 250x70, with
 * the grid, each plot enlarged and an analysis view: inside the screen, not overlapping,
 * the enlarged plot as large as it must be, the grid's plots readable, and the scene's
 * metres-to-columns mapping and the controls' hit-test consistent with what is drawn; a
 * lesson's caption panel below everything but the hints. */
#include "testutil.h"

#include "chart/layout.h"

static bool inside(struct rect r, int cols, int rows)
{
    return r.h > 0 && r.w > 0 && r.y >= 0 && r.x >= 0 && r.y + r.h <= rows && r.x + r.w <= cols;
}

static bool overlap(struct rect a, struct rect b)
{
    return a.x < b.x + b.w && b.x < a.x + a.w && a.y < b.y + b.h && b.y < a.y + a.h;
}

/* Every rectangle of l inside the screen, none overlapping another, the plots inside the
 * plot area. */
static void check_layout(const struct layout *l, int cols, int rows)
{
    struct rect parts[4 + PLOT_COUNT];
    int n = 0;
    parts[n++] = l->status;
    parts[n++] = l->scene;
    parts[n++] = l->controls;
    parts[n++] = l->hints;
    for (int i = 0; i < l->nplots; i++) {
        parts[n++] = l->plot[i];
        struct rect p = l->plot[i], a = l->area;
        if (!(p.x >= a.x && p.y >= a.y && p.x + p.w <= a.x + a.w && p.y + p.h <= a.y + a.h))
            fail_msg("%dx%d: plot %d outside the plot area", cols, rows, i);
    }
    if (l->nplots == 0)
        parts[n++] = l->area;
    for (int i = 0; i < n; i++) {
        if (!inside(parts[i], cols, rows))
            fail_msg("%dx%d: part %d (%d,%d %dx%d) outside the screen", cols, rows, i,
                     parts[i].y, parts[i].x, parts[i].h, parts[i].w);
        for (int j = 0; j < i; j++)
            if (overlap(parts[i], parts[j]))
                fail_msg("%dx%d: parts %d and %d overlap", cols, rows, i, j);
    }
}

/* A lesson's caption panel (layout_caption) at every size, with the grid, a plot
 * enlarged and a view: across the whole width, just above the hints, overlapping nothing,
 * and the plots (or the view's area) and the controls still there above it. */
static void caption_panel(void **state)
{
    (void)state;
    struct layout l;
    for (int cols = LAYOUT_MIN_COLS; cols <= 250; cols += 7)
        for (int rows = LAYOUT_MIN_ROWS; rows <= 70; rows++)
            for (int e = -2; e < PLOT_COUNT; e++) {
                bool view = e == -2;
                int enlarged = view ? -1 : e;
                layout_compute(&l, cols, rows, enlarged, view);
                int want = layout_caption_rows(rows);
                layout_caption(&l, want, enlarged, view);
                struct rect c = l.caption;
                check_layout(&l, cols, rows);
                if (c.x != 0 || c.w != cols || c.y + c.h != l.hints.y || c.h < 5 || c.h > want)
                    fail_msg("%dx%d: caption (%d,%d %dx%d) should span the width above the hints",
                             cols, rows, c.y, c.x, c.h, c.w);
                struct rect parts[] = {l.status, l.scene, l.controls, l.hints, l.area};
                for (size_t i = 0; i < sizeof parts / sizeof *parts; i++)
                    if (overlap(c, parts[i]))
                        fail_msg("%dx%d: the caption overlaps part %zu", cols, rows, i);
                for (int i = 0; i < l.nplots; i++)
                    if (overlap(c, l.plot[i]))
                        fail_msg("%dx%d: the caption overlaps plot %d", cols, rows, i);
                assert_true(l.area.h >= 5 && l.controls.h >= 5);
                assert_true(view ? l.nplots == 0 : l.nplots >= 1);
            }
    /* 80x24 and 120x40, as the terminal tests see them: 7 and 9 rows */
    layout_compute(&l, 80, 24, -1, false);
    layout_caption(&l, layout_caption_rows(24), -1, false);
    assert_int_equal(l.caption.h, 7);
    assert_int_equal(l.caption.y, 16);
    layout_compute(&l, 120, 40, -1, false);
    layout_caption(&l, layout_caption_rows(40), -1, false);
    assert_int_equal(l.caption.h, 9);
    assert_int_equal(l.nplots, 6);
}

static void every_size(void **state)
{
    (void)state;
    struct layout l;
    for (int cols = LAYOUT_MIN_COLS; cols <= 250; cols++)
        for (int rows = LAYOUT_MIN_ROWS; rows <= 70; rows++) {
            for (int e = -1; e < PLOT_COUNT; e++) {
                layout_compute(&l, cols, rows, e, false);
                assert_false(l.too_small);
                check_layout(&l, cols, rows);
                assert_int_equal(l.nplots >= 1, 1);
                /* Every plot shown carries data: a drawing area a plot can use. */
                for (int i = 0; i < l.nplots; i++) {
                    struct rect d = layout_drawing(l.plot[i]);
                    if (d.w < 16 || d.h < 5)
                        fail_msg("%dx%d e=%d: plot %d draws on only %dx%d", cols, rows, e, i,
                                 d.w, d.h);
                }
                if (e >= 0) {
                    assert_int_equal(l.nplots, 1);
                    assert_int_equal(l.plot_id[0], e);
                }
            }
            layout_compute(&l, cols, rows, -1, true);
            assert_int_equal(l.nplots, 0);
            check_layout(&l, cols, rows);
        }
}

/* The goals: an enlarged plot draws on at least 40x12 at 80x24, 70x24 at 120x40. */
static void enlarged_sizes(void **state)
{
    (void)state;
    static const struct {
        int cols, rows, w, h;
    } want[] = {{80, 24, 40, 12}, {120, 40, 70, 24}};
    for (size_t k = 0; k < sizeof want / sizeof *want; k++)
        for (int e = 0; e < PLOT_COUNT; e++) {
            struct layout l;
            layout_compute(&l, want[k].cols, want[k].rows, e, false);
            struct rect d = layout_drawing(l.plot[0]);
            if (d.w < want[k].w || d.h < want[k].h)
                fail_msg("%dx%d: plot %d enlarged draws on %dx%d, below %dx%d", want[k].cols,
                         want[k].rows, e + 1, d.w, d.h, want[k].w, want[k].h);
        }
}

/* The grid shows all six where each is readable, fewer and larger where not. */
static void grid_choice(void **state)
{
    (void)state;
    struct layout l;
    layout_compute(&l, 120, 40, -1, false);
    assert_int_equal(l.nplots, 6);
    for (int i = 0; i < 6; i++)
        assert_int_equal(l.plot_id[i], i);
    layout_compute(&l, 80, 24, -1, false);
    assert_in_range(l.nplots, 1, 2);
    assert_int_equal(l.plot_id[0], PLOT_X);
    if (l.nplots == 2)
        assert_int_equal(l.plot_id[1], PLOT_XV);
    layout_compute(&l, 60, 20, -1, false);
    assert_in_range(l.nplots, 1, 2);
    assert_int_equal(l.plot_id[0], PLOT_X);
}

static void too_small(void **state)
{
    (void)state;
    struct layout l;
    layout_compute(&l, LAYOUT_MIN_COLS - 1, 40, -1, false);
    assert_true(l.too_small);
    layout_compute(&l, 100, LAYOUT_MIN_ROWS - 1, -1, false);
    assert_true(l.too_small);
    layout_compute(&l, 1, 1, 3, true);
    assert_true(l.too_small);
    assert_int_equal(l.nplots, 0);
}

/* The scene: 0 m at the wall's face, L + the stroke before the housing; columns and metres
 * map back onto each other; the controls' hit-test matches their rows. */
static void scene_and_controls(void **state)
{
    (void)state;
    for (int cols = LAYOUT_MIN_COLS; cols <= 250; cols += 7) {
        struct layout l;
        layout_compute(&l, cols, 30, -1, false);
        assert_close(layout_scene_col(&l, 0.0), 1 + LAYOUT_WALL_COLS, 1e-12);
        assert_close(layout_scene_col(&l, LAYOUT_SCENE_SPAN), cols - 1 - LAYOUT_HOUSE_COLS, 1e-9);
        for (int c = l.scene_x0; c < cols - 1 - LAYOUT_HOUSE_COLS; c++) {
            double X = layout_scene_metres(&l, c);
            assert_int_equal((int)layout_scene_col(&l, X), c);
        }
        struct rect r = l.controls;
        for (int i = 0; i < 12; i++)
            assert_int_equal(layout_control_at(&l, r.y + 1 + i, r.x + 1, 12, 0), i);
        assert_int_equal(layout_control_at(&l, r.y, r.x + 1, 12, 0), -1);      /* the frame */
        assert_int_equal(layout_control_at(&l, r.y + 13, r.x + 1, 12, 0), -1); /* below them */
        assert_int_equal(layout_control_at(&l, r.y + 1, r.x, 12, 0), -1);      /* the border */
        assert_int_equal(layout_control_at(&l, r.y + 1, 0, 12, 0), -1);
    }
}

/* The controls' list at the sizes people use: 80x24 keeps the frequency bar and the
 * natural frequencies below 13 of 16 controls (the list scrolls by three); 60x20 gives every
 * row to the list; a large terminal shows them all with room to spare. The mouse finds a
 * control only on the rows the list takes. */
static void control_rows(void **state)
{
    (void)state;
    static const struct { int cols, rows, shown; } sizes[] = {
        {80, 24, 13}, {60, 20, 11}, {120, 40, 16}, {100, 30, 16},
    };
    for (size_t k = 0; k < sizeof sizes / sizeof *sizes; k++) {
        struct layout l;
        layout_compute(&l, sizes[k].cols, sizes[k].rows, -1, false);
        int inside = l.controls.h - 2, shown = layout_control_rows(&l, 16);
        assert_int_equal(shown, sizes[k].shown);
        assert_true(shown == 16 ? inside >= 18 : shown == 13 ? inside == 15 : inside == shown);
        struct rect r = l.controls;
        int top = 16 - shown; /* scrolled to the last */
        assert_int_equal(layout_control_at(&l, r.y + shown, r.x + 1, 16, top), 15);
        assert_int_equal(layout_control_at(&l, r.y + shown + 1, r.x + 1, 16, top), -1);
    }
    /* Fewer controls than rows: all of them. */
    struct layout l;
    layout_compute(&l, 80, 24, -1, false);
    assert_int_equal(layout_control_rows(&l, 12), 12);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(every_size),     cmocka_unit_test(enlarged_sizes),
        cmocka_unit_test(grid_choice),    cmocka_unit_test(too_small),
        cmocka_unit_test(scene_and_controls), cmocka_unit_test(caption_panel),
        cmocka_unit_test(control_rows),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
