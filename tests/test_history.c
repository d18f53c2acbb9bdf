/* test_history.c: stepping back restores state and time exactly, stepping forward again
 * retraces the same states bit for bit, the ring keeps the newest 500 states, and an
 * empty history refuses to pop. */
#include "testutil.h"

#include <stdlib.h>
#include <string.h>

#include "core/history.h"

static struct sim *busy_sim(void)
{
    struct model *md = model_new(3);
    md->motor.wave = WAVE_SQUARE; /* splits, jumps and contacts: all of the state moves */
    md->motor.amplitude = 2.5;
    md->motor.frequency = 1.3;
    struct sim *s = sim_new(md, 0.01);
    double x0[3] = {0.4, -0.9, 1.1};
    sim_reset(s, x0, NULL);
    model_free(md);
    return s;
}

static void back_500_is_exact(void **state)
{
    (void)state;
    struct sim *s = busy_sim();
    struct history *h = history_new(s, HISTORY_DEPTH);
    int size = sim_snapshot_size(s);
    double *start = malloc((size_t)size * sizeof *start);
    double *now = malloc((size_t)size * sizeof *now);
    for (int n = 0; n < 200; n++) /* not at t = 0: history works from anywhere */
        sim_step(s);
    sim_save(s, start);
    double t0 = sim_time(s);
    int contacts = 0;
    for (int n = 0; n < 500; n++) {
        history_push(h, s);
        sim_step(s);
        contacts += sim_last_contacts(s);
    }
    double *end = malloc((size_t)size * sizeof *end);
    sim_save(s, end);
    assert_true(contacts > 0);
    assert_int_equal(history_count(h), 500);
    assert_true(sim_time(s) > t0 + 4.99);
    for (int n = 0; n < 500; n++)
        assert_int_equal(history_pop(h, s), 0);
    sim_save(s, now);
    assert_memory_equal(start, now, (size_t)size * sizeof *now);
    assert_true(sim_time(s) == t0);
    assert_int_equal(history_pop(h, s), -1);
    /* Forward again from the restored state retraces the same path bit for bit: the
     * snapshot holds everything a step depends on. */
    for (int n = 0; n < 500; n++)
        sim_step(s);
    double *again = malloc((size_t)size * sizeof *again);
    sim_save(s, again);
    assert_memory_equal(end, again, (size_t)size * sizeof *again);
    /* The drained ring fills again from where it stands and steps back to it. */
    for (int n = 0; n < 500; n++)
        history_push(h, s), sim_step(s);
    assert_int_equal(history_count(h), 500);
    for (int n = 0; n < 500; n++)
        assert_int_equal(history_pop(h, s), 0);
    sim_save(s, now);
    assert_memory_equal(again, now, (size_t)size * sizeof *now);
    free(again);
    free(end);
    free(start);
    free(now);
    history_free(h);
    sim_free(s);
}

static void ring_keeps_newest(void **state)
{
    (void)state;
    struct sim *s = busy_sim();
    struct history *h = history_new(s, 5);
    double times[12];
    for (int n = 0; n < 12; n++) {
        times[n] = sim_time(s);
        history_push(h, s);
        sim_step(s);
    }
    assert_int_equal(history_count(h), 5);
    for (int n = 11; n >= 7; n--) {
        assert_int_equal(history_pop(h, s), 0);
        assert_true(sim_time(s) == times[n]);
    }
    assert_int_equal(history_pop(h, s), -1);
    history_push(h, s);
    history_clear(h);
    assert_int_equal(history_count(h), 0);
    history_free(h);
    sim_free(s);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(back_500_is_exact),
        cmocka_unit_test(ring_keeps_newest),
    };
    return cmocka_run_group_tests_name("history", tests, NULL, NULL);
}
