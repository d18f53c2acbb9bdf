/* test_command.c: what a plain command comes to is a kind beside its answer, set where
 * the answer or the app's message is made, never read back from the words: a change that
 * leaves dt past a limit is done with a warning, a refusal is an error, the commands
 * whose answer says whether the chain runs say so, and the app's messages carry their
 * kind (a note, a warning, an error, the cap's count). */
#include "testutil.h"

#include <string.h>

#include "app/app.h"
#include "app/command.h"

static struct app app;
static struct command_result res;

/* Three masses at dt 0.01 (rk4), paused. */
static int setup(void **state)
{
    (void)state;
    static struct config c;
    config_init(&c);
    c.masses = 3;
    c.dt = 0.01;
    return app_init(&app, &c, SRCDIR);
}

static int teardown(void **state)
{
    (void)state;
    app_free(&app);
    return 0;
}

/* Springs that leave dt past the stability limit are set all the same: a warning (an ok
 * to the plain mode), the message a warning too; back under it, a plain ok and a note. */
static void a_change_past_a_limit_is_a_warning(void **state)
{
    (void)state;
    assert_int_equal(command_do(&app, "set dt 0.05", &res), REPLY_OK);
    assert_int_equal(command_do(&app, "set spring 5000", &res), REPLY_WARNING);
    assert_true(app.model->k[0] == 5000.0);
    assert_int_equal(app.said, SAID_WARNING);
    assert_true(command_done(res.reply));
    assert_int_equal(command_do(&app, "set spring 10", &res), REPLY_OK);
    assert_true(app.model->k[0] == 10.0);
    assert_int_equal(app.said, SAID_NOTE);
    /* One spring alone, by another route: the same warning. */
    assert_int_equal(command_do(&app, "element k 1 1e6", &res), REPLY_WARNING);
    assert_true(app.model->k[1] == 1e6);
}

/* A refusal: an error, nothing changed, and the app's message (where it made one) an
 * error too. */
static void a_refusal_is_an_error(void **state)
{
    (void)state;
    double dt = app.cfg.dt;
    assert_int_equal(command_do(&app, "set dt -1", &res), REPLY_ERROR);
    assert_int_equal(app.said, SAID_ERROR);
    assert_true(app.cfg.dt == dt);
    assert_false(command_done(res.reply));
    assert_int_equal(command_do(&app, "back", &res), REPLY_ERROR);
    assert_int_equal(command_do(&app, "nosuch", &res), REPLY_ERROR);
}

/* start, pause, step, run and mode K say in their answer whether the chain runs; a
 * sweep starts it without saying so (the plain mode tells an event then). */
static void play_is_said_by_the_commands_that_play(void **state)
{
    (void)state;
    static const char *const says[] = {"start", "pause", "step", "run 0.1", "mode 1"};
    for (size_t i = 0; i < sizeof says / sizeof *says; i++) {
        command_do(&app, says[i], &res);
        assert_true(res.says_play);
    }
    command_do(&app, "pause", &res);
    assert_int_equal(command_do(&app, "sweep", &res), REPLY_OK);
    assert_true(app.running);
    assert_false(res.says_play);
    assert_int_equal(command_do(&app, "run 0.5", &res), REPLY_RUN);
    assert_true(res.seconds == 0.5);
    assert_int_equal(command_do(&app, "view modes", &res), REPLY_VIEW);
    assert_int_equal(res.view, CV_MODES);
    assert_true(command_done(res.reply));
}

/* The velocity cap's count is a kind of its own, said anew at every step it acts. */
static void the_cap_is_its_own_kind(void **state)
{
    (void)state;
    assert_int_equal(command_do(&app, "set dt 0.001", &res), REPLY_OK);
    assert_int_equal(command_do(&app, "place 1 2", &res), REPLY_OK);
    assert_int_equal(command_do(&app, "set spring 2000", &res), REPLY_OK);
    unsigned says = app.says;
    int steps = 0;
    while (app.said != SAID_CAP && steps++ < 2000)
        app_step(&app);
    assert_int_equal(app.said, SAID_CAP);
    assert_true(app.says > says);
    says = app.says;
    app_say(&app, SAID_NOTE, "%s", app.message); /* the same words, said again */
    assert_int_equal(app.said, SAID_NOTE);
    assert_int_equal(app.says, says + 1);
    app_quiet(&app);
    assert_string_equal(app.message, "");
    assert_int_equal(app.said, SAID_NOTE);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup_teardown(a_change_past_a_limit_is_a_warning, setup, teardown),
        cmocka_unit_test_setup_teardown(a_refusal_is_an_error, setup, teardown),
        cmocka_unit_test_setup_teardown(play_is_said_by_the_commands_that_play, setup, teardown),
        cmocka_unit_test_setup_teardown(the_cap_is_its_own_kind, setup, teardown),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
