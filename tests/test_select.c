/* test_select.c: the keyboard's selection (src/app/select.c): how many elements a chain
 * has at each right end, which mass or spring is selected, an element kept valid when
 * the chain shrinks, moves that wrap around, and the switch between the controls and
 * the chain. */
#include "testutil.h"

#include "app/app.h"
#include "app/select.h"
#include "core/model.h"

/* A chain of n masses with right end b. */
static struct model *chain(int n, enum boundary b)
{
    struct model *m = model_new(n);
    assert_non_null(m);
    m->boundary = b;
    return m;
}

/* N+1 springs and N masses, but no spring past a free end. */
static void elements_per_end(void **state)
{
    (void)state;
    static const struct {
        int n;
        enum boundary b;
        int elements;
    } cases[] = {
        {3, BOUNDARY_MOTOR, 7}, {3, BOUNDARY_WALL, 7}, {3, BOUNDARY_FREE, 6},
        {1, BOUNDARY_MOTOR, 3}, {1, BOUNDARY_WALL, 3}, {1, BOUNDARY_FREE, 2},
        {10, BOUNDARY_MOTOR, 21}, {10, BOUNDARY_FREE, 20},
    };
    for (size_t i = 0; i < sizeof cases / sizeof *cases; i++) {
        struct model *m = chain(cases[i].n, cases[i].b);
        int got = select_elements(m);
        model_free(m);
        if (got != cases[i].elements)
            fail_msg("N = %d, %s end: %d elements, expected %d", cases[i].n,
                     model_boundary_name(cases[i].b), got, cases[i].elements);
    }
}

/* Element 2j is spring j, 2i+1 is mass i; neither while the focus is on the controls. */
static void mass_and_spring_on_the_chain_only(void **state)
{
    (void)state;
    struct selection s = {FOCUS_CHAIN, CTL_FREQUENCY, 0, 0, 0};
    static const struct {
        int elem, mass, spring;
    } cases[] = {
        {0, -1, 0}, {1, 0, -1}, {2, -1, 1}, {5, 2, -1}, {6, -1, 3}, {19, 9, -1}, {20, -1, 10},
    };
    for (size_t i = 0; i < sizeof cases / sizeof *cases; i++) {
        s.focus = FOCUS_CHAIN;
        s.elem = cases[i].elem;
        if (select_mass(&s) != cases[i].mass || select_spring(&s) != cases[i].spring)
            fail_msg("element %d: mass %d, spring %d, expected %d, %d", s.elem,
                     select_mass(&s), select_spring(&s), cases[i].mass, cases[i].spring);
        s.focus = FOCUS_CONTROLS;
        if (select_mass(&s) != -1 || select_spring(&s) != -1)
            fail_msg("element %d, focus on the controls: mass %d, spring %d, expected none",
                     s.elem, select_mass(&s), select_spring(&s));
    }
}

/* An element the chain no longer has goes back to mass 1; one it still has stays. */
static void clamp_after_the_chain_shrinks(void **state)
{
    (void)state;
    struct model *five = chain(5, BOUNDARY_MOTOR), *two = chain(2, BOUNDARY_MOTOR);
    struct selection s = {FOCUS_CHAIN, CTL_MASSES, 9, 0, 0}; /* mass 5 */
    select_clamp(&s, five);
    assert_int_equal(s.elem, 9);
    select_clamp(&s, two); /* N 5 -> 2 */
    assert_int_equal(s.elem, 1);
    assert_int_equal(select_mass(&s), 0);
    assert_int_equal(s.focus, FOCUS_CHAIN);
    assert_int_equal(s.control, CTL_MASSES);
    /* Valid ones are left alone: mass 2, and the spring to the motor. */
    s.elem = 3;
    select_clamp(&s, two);
    assert_int_equal(s.elem, 3);
    s.elem = 4;
    select_clamp(&s, two);
    assert_int_equal(s.elem, 4);
    /* That spring is gone at a free end; nor is there an element before the first. */
    two->boundary = BOUNDARY_FREE;
    select_clamp(&s, two);
    assert_int_equal(s.elem, 1);
    s.elem = -1;
    select_clamp(&s, two);
    assert_int_equal(s.elem, 1);
    model_free(five);
    model_free(two);
}

/* Moves wrap around both ways, among the controls or among the elements, and touch
 * only the one that has the focus. */
static void moves_wrap_both_ways(void **state)
{
    (void)state;
    struct model *m = chain(3, BOUNDARY_MOTOR); /* elements 0..6 */
    struct selection s = {FOCUS_CONTROLS, 0, 3, 0, 0};
    select_move(&s, -1, CTL_COUNT, m);
    assert_int_equal(s.control, CTL_COUNT - 1);
    select_move(&s, 1, CTL_COUNT, m);
    assert_int_equal(s.control, 0);
    select_move(&s, 1, CTL_COUNT, m);
    assert_int_equal(s.control, 1);
    assert_int_equal(s.elem, 3);
    for (int i = 0; i < CTL_COUNT; i++)
        select_move(&s, 1, CTL_COUNT, m);
    assert_int_equal(s.control, 1);

    s.focus = FOCUS_CHAIN;
    s.elem = 6;
    select_move(&s, 1, CTL_COUNT, m);
    assert_int_equal(s.elem, 0);
    select_move(&s, -1, CTL_COUNT, m);
    assert_int_equal(s.elem, 6);
    select_move(&s, -1, CTL_COUNT, m);
    assert_int_equal(s.elem, 5);
    assert_int_equal(s.control, 1);
    /* At a free end the last element is mass N. */
    m->boundary = BOUNDARY_FREE;
    s.elem = 0;
    select_move(&s, -1, CTL_COUNT, m);
    assert_int_equal(s.elem, 5);
    assert_int_equal(select_mass(&s), 2);
    select_move(&s, 1, CTL_COUNT, m);
    assert_int_equal(s.elem, 0);
    model_free(m);
}

/* Onto the chain from a spring or an element it no longer has: mass 1; from a mass that
 * is still there: that mass. Back to the controls: the control selected before. */
static void toggle_lands_on_a_mass(void **state)
{
    (void)state;
    struct model *m = chain(3, BOUNDARY_MOTOR);
    static const struct {
        int from, to;
    } cases[] = {
        {0, 1}, {4, 1}, {6, 1}, {7, 1}, {9, 1}, {3, 3}, {5, 5},
    };
    for (size_t i = 0; i < sizeof cases / sizeof *cases; i++) {
        struct selection s = {FOCUS_CONTROLS, CTL_DAMPING, cases[i].from, 0, 0};
        select_toggle_focus(&s, m, false);
        assert_int_equal(s.focus, FOCUS_CHAIN);
        if (s.elem != cases[i].to)
            fail_msg("from element %d: landed on %d, expected %d", cases[i].from, s.elem,
                     cases[i].to);
        select_toggle_focus(&s, m, false);
        assert_int_equal(s.focus, FOCUS_CONTROLS);
        assert_int_equal(s.control, CTL_DAMPING);
        assert_int_equal(s.elem, cases[i].to);
    }
    model_free(m);
}

/* With the modes view shown, Tab goes controls, chain, modes and round; the arrows move
 * the mode, wrapping, and a smaller chain keeps it one that exists. */
static void modes_in_the_round(void **state)
{
    (void)state;
    struct model *m = chain(3, BOUNDARY_WALL);
    struct selection s = {FOCUS_CONTROLS, CTL_DAMPING, 1, 0, 0};
    assert_int_equal(select_mode(&s), -1);
    select_toggle_focus(&s, m, true);
    assert_int_equal(s.focus, FOCUS_CHAIN);
    select_toggle_focus(&s, m, true);
    assert_int_equal(s.focus, FOCUS_MODES);
    assert_int_equal(select_mass(&s), -1);
    select_move(&s, -1, CTL_COUNT, m);
    assert_int_equal(select_mode(&s), 2);
    select_move(&s, 1, CTL_COUNT, m);
    assert_int_equal(select_mode(&s), 0);
    select_move(&s, 1, CTL_COUNT, m);
    select_move(&s, 1, CTL_COUNT, m);
    assert_int_equal(select_mode(&s), 2);
    assert_int_equal(s.control, CTL_DAMPING); /* the controls' selection kept */
    struct model *two = chain(2, BOUNDARY_WALL);
    select_clamp(&s, two);
    assert_int_equal(select_mode(&s), 0);
    select_toggle_focus(&s, two, true);
    assert_int_equal(s.focus, FOCUS_CONTROLS);
    model_free(two);
    model_free(m);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(elements_per_end),
        cmocka_unit_test(mass_and_spring_on_the_chain_only),
        cmocka_unit_test(clamp_after_the_chain_shrinks),
        cmocka_unit_test(moves_wrap_both_ways),
        cmocka_unit_test(toggle_lands_on_a_mass),
        cmocka_unit_test(modes_in_the_round),
    };
    return cmocka_run_group_tests_name("select", tests, NULL, NULL);
}
