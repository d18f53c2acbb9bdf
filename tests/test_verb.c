/* test_verb.c: the table of user verbs (app/command.c), the one place each verb is bound
 * to its command, its action and its function, and what a verb or a command comes to.
 * A verb done as a key does it (verb_do with the argument the screen gives) and as
 * the plain command that names it (command_do) leaves two chains built alike in the
 * same state, bit for bit, with the same kind of result; what a verb done from a key
 * is recorded as (verb_command, for --record) does the same again when replayed as a
 * command. The kinds are set where the answer or the app's message is made, never
 * read back from the words: a change that leaves dt past a limit is done with a
 * warning, a refusal is an error, the commands whose answer says whether the chain
 * runs say so, the cap's count is a kind of its own. */
#include "testutil.h"

#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "app/app.h"
#include "app/command.h"
#include "lab/lesson.h"
#include "app/verb.h"
#include "core/preset.h"

static struct app by_key, by_command; /* the two chains */
static struct command_result res;
static char dir[] = "/tmp/springsim-verb-XXXXXX";
static char home[4200];

static int setup(void **state)
{
    (void)state;
    static struct config c;
    config_init(&c);
    c.masses = 3;
    c.frequency = 0.9;
    return app_init(&by_key, &c, SRCDIR) || app_init(&by_command, &c, SRCDIR);
}

static int teardown(void **state)
{
    (void)state;
    app_free(&by_key);
    app_free(&by_command);
    return 0;
}

/* Everything a verb can change, in one line: t and every x and v exactly, and the rest of
 * what the user sees and sets. */
static void snapshot(const struct app *app, char *buf, size_t len)
{
    char exact[4096], value[96];
    lesson_state(app, exact, sizeof exact);
    size_t used = (size_t)snprintf(buf, len, "%s running=%d window=%a pending=%d said=%d "
                                   "message=%s ghost=%d sweep=%d cursors=%d", exact,
                                   app->running, app->cfg.window, app->masses_pending, app->said,
                                   app->message, app->ghost != NULL, app->sweep->active,
                                   app->scope.cursors);
    for (int c = 0; c < CTL_COUNT && used < len; c++) {
        app_control_value(app, (enum control)c, value, sizeof value);
        used += (size_t)snprintf(buf + used, len - used, " %s", value);
    }
    for (int i = 0; i < app->model->n && used < len; i++)
        used += (size_t)snprintf(buf + used, len - used, " m%a c%a k%a x0%a", app->model->m[i],
                                 app->model->c[i], app->model->k[i], app->cfg.x0.v[i]);
}

/* The reply a result is to the plain mode. */
static enum command_reply reply_of(enum result r)
{
    return r == RESULT_OK ? REPLY_OK : r == RESULT_WARNING ? REPLY_WARNING : REPLY_ERROR;
}

/* Does a with arg on one chain and line on the other, and checks both came to the same
 * state and the same kind of result; returns that result. */
static enum result same(enum action a, const struct verb_arg *arg, const char *line)
{
    static char k[16384], c[16384];
    enum result r = verb_do(&by_key, a, arg, NULL);
    enum command_reply cr = command_do(&by_command, line, &res);
    snapshot(&by_key, k, sizeof k);
    snapshot(&by_command, c, sizeof c);
    if (strcmp(k, c) != 0)
        fail_msg("%s: the key's verb left\n%s\nthe command left\n%s", line, k, c);
    if (reply_of(r) != cr)
        fail_msg("%s: the verb came to %d, the command to %d (%s)", line, r, cr, res.answer);
    return r;
}

/* The verbs the keys do, one after another on the two chains. */
static void keys_and_commands_do_the_same(void **state)
{
    (void)state;
    struct verb_arg none = {0};
    assert_int_equal(same(ACT_RUN, &none, "start"), RESULT_OK); /* space, paused */
    assert_true(by_key.running);
    assert_int_equal(same(ACT_RUN, &none, "pause"), RESULT_OK); /* space, running */
    assert_false(by_key.running);
    assert_int_equal(same(ACT_BACK, NULL, "back"), RESULT_ERROR); /* nothing before t = 0 */
    assert_int_equal(same(ACT_STEP, NULL, "step"), RESULT_OK);
    assert_int_equal(same(ACT_STEP, NULL, "step"), RESULT_OK);
    assert_int_equal(same(ACT_BACK, NULL, "back"), RESULT_OK);
    assert_int_equal(same(ACT_RESET, NULL, "reset"), RESULT_OK);
    assert_int_equal(same(ACT_FASTER, NULL, "faster"), RESULT_OK);
    assert_int_equal(same(ACT_SLOWER, NULL, "slower"), RESULT_OK);
    assert_int_equal(same(ACT_NEAREST, NULL, "nearest"), RESULT_OK);
    assert_int_equal(same(ACT_SWEEP, NULL, "sweep"), RESULT_OK); /* starts it, running */
    assert_true(by_key.sweep->active && by_key.running);
    assert_int_equal(same(ACT_SWEEP, NULL, "sweep"), RESULT_OK); /* stops it */
    assert_int_equal(same(ACT_RUN, &none, "pause"), RESULT_OK);
    /* Enter in the modes view on the second mode. */
    assert_int_equal(same(ACT_MODE, &(struct verb_arg){.index = 1}, "mode 2"), RESULT_OK);
    assert_true(by_key.running);
    assert_int_equal(same(ACT_RUN, &none, "pause"), RESULT_OK);
    /* R: a fresh seed each time, so the chains are compared from a seed the command
     * names; the key's result is a random start all the same. */
    assert_int_equal(same(ACT_RANDOM, &(struct verb_arg){.seeded = true, .seed = 7},
                          "random 7"), RESULT_OK);
    assert_int_equal(same(ACT_RESET, NULL, "reset"), RESULT_OK);
    double x0 = by_key.cfg.x0.v[0];
    assert_int_equal(verb_do(&by_key, ACT_RANDOM, NULL, NULL), RESULT_OK);
    assert_true(by_key.cfg.x0.v[0] != x0);
}

/* What the overlays and the selection hand to a verb, and the commands that name it:
 * the same change, the same warning or error. */
static void typed_values_do_the_same(void **state)
{
    (void)state;
    assert_int_equal(same(ACT_SET, &(struct verb_arg){.index = CTL_FREQUENCY, .text = "1.3"},
                          "set frequency 1.3"), RESULT_OK);
    assert_int_equal(same(ACT_SET, &(struct verb_arg){.index = CTL_DT, .text = "0.05"},
                          "set dt 0.05"), RESULT_OK);
    /* Springs that leave dt past the stability limit: done, with a warning. */
    assert_int_equal(same(ACT_SET, &(struct verb_arg){.index = CTL_SPRING, .text = "5000"},
                          "set spring 5000"), RESULT_WARNING);
    assert_int_equal(same(ACT_SET, &(struct verb_arg){.index = CTL_SPRING, .text = "10"},
                          "set spring 10"), RESULT_OK);
    assert_int_equal(same(ACT_SET, &(struct verb_arg){.index = CTL_DT, .text = "9"},
                          "set dt 9"), RESULT_ERROR);
    assert_int_equal(same(ACT_ELEMENT, &(struct verb_arg){.what = 'k', .index = 0, .text = "50"},
                          "element k 0 50"), RESULT_OK);
    assert_int_equal(same(ACT_ELEMENT, &(struct verb_arg){.what = 'm', .index = 2, .text = "2.5"},
                          "element m 3 2.5"), RESULT_OK);
    assert_int_equal(same(ACT_ELEMENT, &(struct verb_arg){.what = 'c', .index = 1, .text = "-1"},
                          "element c 2 -1"), RESULT_ERROR);
    assert_int_equal(same(ACT_PLACE, &(struct verb_arg){.index = 1, .value = 0.1},
                          "place 2 0.1"), RESULT_OK);
    assert_int_equal(same(ACT_WINDOW, &(struct verb_arg){.text = "33"}, "set window 33"),
                     RESULT_OK);
    assert_int_equal(same(ACT_WINDOW, &(struct verb_arg){.text = "61"}, "set window 61"),
                     RESULT_ERROR);
    /* Masses by the arrows, then Enter on the Masses control; the plain set applies it at
     * once (and says so: the messages differ, the chains may not). */
    static char k[16384], c[16384];
    app_adjust(&by_key, CTL_MASSES, 2, false);
    assert_int_equal(by_key.masses_pending, 5);
    assert_int_equal(verb_do(&by_key, ACT_APPLY, NULL, NULL), RESULT_OK);
    assert_int_equal(command_do(&by_command, "set masses 5", &res), REPLY_OK);
    snapshot(&by_key, k, sizeof k);
    snapshot(&by_command, c, sizeof c);
    *strstr(k, " said=") = *strstr(c, " said=") = '\0';
    assert_string_equal(k, c);
    assert_int_equal(by_key.model->n, 5);
    /* The preset menu's Enter, and the preset command. */
    char path[4400];
    assert_int_equal(preset_find("3-mass-chain", SRCDIR, path, sizeof path), PRESET_OK);
    assert_int_equal(same(ACT_PRESET, &(struct verb_arg){.text = path, .name = "3-mass-chain"},
                          "preset 3-mass-chain"), RESULT_OK);
    assert_int_equal(by_key.model->n, 3);
}

/* x: the samples, then (in the response view, after a sweep) the sweep's points, into the
 * working directory: the same files, the same results; no sweep measured is an error. */
static void exports_do_the_same(void **state)
{
    (void)state;
    assert_non_null(mkdtemp(dir));
    assert_non_null(getcwd(home, sizeof home));
    assert_int_equal(chdir(dir), 0);
    assert_int_equal(same(ACT_STEP, NULL, "step"), RESULT_OK);
    enum result r = verb_do(&by_key, ACT_EXPORT, NULL, NULL);
    assert_int_equal(command_do(&by_command, "export", &res), reply_of(r));
    assert_int_equal(r, RESULT_OK);
    assert_int_equal(verb_do(&by_key, ACT_EXPORT, &(struct verb_arg){.sweep = true}, NULL),
                     RESULT_ERROR);
    assert_int_equal(by_key.said, SAID_ERROR);
    assert_int_equal(chdir(home), 0);
    char rm[sizeof dir + 16];
    snprintf(rm, sizeof rm, "rm -rf %s", dir);
    assert_int_equal(system(rm), 0);
}

/* What a key's verb is recorded as, replayed as a command on the other chain, leaves it
 * where the key left the first. */
static void recorded_verbs_replay(void **state)
{
    (void)state;
    static const struct {
        enum action a;
        struct verb_arg arg;
    } keys[] = {
        {ACT_RUN, {0}},    {ACT_STEP, {0}},  {ACT_STEP, {0}},   {ACT_BACK, {0}},
        {ACT_FASTER, {0}}, {ACT_SLOWER, {0}}, {ACT_NEAREST, {0}}, {ACT_MODE, {.index = 2}},
        {ACT_RESET, {0}},  {ACT_SWEEP, {0}},  {ACT_SWEEP, {0}},   {ACT_GHOST, {0}},
        {ACT_GHOST, {0}},
    };
    char line[64], k[16384], c[16384];
    for (size_t i = 0; i < sizeof keys / sizeof *keys; i++) {
        unsigned changed;
        verb_do(&by_key, keys[i].a, &keys[i].arg, &changed);
        verb_command(keys[i].a, &keys[i].arg, changed, by_key.running, line, sizeof line);
        assert_true(line[0]); /* each of these did something, and has its command */
        command_do(&by_command, line, &res);
        snapshot(&by_key, k, sizeof k);
        snapshot(&by_command, c, sizeof c);
        /* The message may differ (start answers itself); the chain may not. */
        *strstr(k, " said=") = *strstr(c, " said=") = '\0';
        assert_string_equal(k, c);
        if (by_key.running) { /* a pause is not recorded: done on both by hand */
            verb_do(&by_key, ACT_RUN, &(struct verb_arg){.dir = -1}, NULL);
            verb_do(&by_command, ACT_RUN, &(struct verb_arg){.dir = -1}, NULL);
        }
    }
    /* A pause, a step back at t = 0 and the screen's own actions are recorded as nothing. */
    verb_command(ACT_RUN, NULL, APP_CHANGED_PLAYBACK, false, line, sizeof line);
    assert_string_equal(line, "");
    verb_command(ACT_BACK, NULL, 0, false, line, sizeof line);
    assert_string_equal(line, "");
    verb_command(ACT_HELP, NULL, APP_CHANGED_STATE, false, line, sizeof line);
    assert_string_equal(line, "");
    assert_false(verb_bound(ACT_HELP));
    assert_false(verb_bound(ACT_NONE));
    assert_int_equal(verb_do(&by_key, ACT_HELP, NULL, NULL), RESULT_ERROR);
}

/* Every row is whole: a command found by its name, with a function that reads its words
 * and its help; an action bound to one row only, with the app's function for it. The
 * commands a lesson may not hold are those that write files or end the program, a pause
 * is not recorded (a lesson's pause waits for the user), and the flags that lessons and
 * recordings decide on are each on the row they name. */
static void every_command_row_is_whole(void **state)
{
    (void)state;
    int named = 0;
    for (int i = 0; i < command_rows; i++) {
        const struct command *row = &commands[i];
        if (row->name) {
            named++;
            assert_ptr_equal(command_find(row->name, strlen(row->name)), row);
            assert_non_null(row->run);
            assert_true(strlen(row->help) > 0);
            bool files = strcmp(row->name, "save") == 0 || strcmp(row->name, "export") == 0 ||
                         strcmp(row->name, "quit") == 0;
            assert_int_equal(!!(row->flags & COMMAND_NOT_IN_LESSON), files);
        } else {
            assert_int_not_equal(row->action, ACT_NONE); /* a verb with no command: a key's */
        }
        if (row->action != ACT_NONE) {
            assert_ptr_equal(command_of_action(row->action), row);
            assert_true(row->fn || row->with || row->act || row->go);
            assert_true(verb_bound(row->action));
        }
        if (row->flags & COMMAND_BY_KEY)
            assert_true(row->name && row->action != ACT_NONE && (row->flags & COMMAND_RECORDED));
    }
    assert_int_equal(named, 28);
    assert_null(command_find("bogus", 5));
    assert_false(command_find("pause", 5)->flags & COMMAND_RECORDED);
    assert_true(command_find("start", 5)->flags & COMMAND_RECORDED);
    assert_true(command_find("run", 3)->flags & COMMAND_SAYS_PLAY);
    assert_true(command_find("run", 3)->flags & COMMAND_RUNS);
    assert_true(command_find("preset", 6)->flags & COMMAND_LOADS);
    assert_true(command_find("quit", 4)->flags & COMMAND_ENDS);
    assert_true(command_find("random", 6)->flags & COMMAND_SEEDED);
}

/* The terminal program refreshes the plots after a verb only when it changed something
 * they draw (APP_CHANGED_DRAWN): a refusal, a note, a number of masses waiting for Enter
 * change nothing drawn; a step, a wider window, a ghost, a new drive do. */
static void what_is_drawn_is_in_the_mask(void **state)
{
    (void)state;
    unsigned changed;
    verb_do(&by_key, ACT_BACK, NULL, &changed); /* nothing before t = 0 */
    assert_int_equal(changed & APP_CHANGED_DRAWN, 0);
    verb_do(&by_key, ACT_SET, &(struct verb_arg){.index = CTL_DT, .text = "9"}, &changed);
    assert_int_equal(changed & APP_CHANGED_DRAWN, 0);
    assert_int_equal(app_adjust(&by_key, CTL_MASSES, 1, false) & APP_CHANGED_DRAWN, 0);
    static const enum action drawn[] = {ACT_STEP, ACT_WIDER, ACT_GHOST, ACT_NEAREST,
                                        ACT_RESET, ACT_SWEEP};
    for (size_t i = 0; i < sizeof drawn / sizeof *drawn; i++) {
        assert_int_equal(verb_do(&by_key, drawn[i], NULL, &changed), RESULT_OK);
        assert_true(changed & APP_CHANGED_DRAWN);
    }
    assert_true(by_key.ghost && by_key.sweep->active);
}

/* Springs that leave dt past the stability limit are set all the same: a warning (an ok
 * to the plain mode), the message a warning too; back under it, a plain ok and a note. */
static void a_change_past_a_limit_is_a_warning(void **state)
{
    (void)state;
    assert_int_equal(command_do(&by_command, "set dt 0.05", &res), REPLY_OK);
    assert_int_equal(command_do(&by_command, "set spring 5000", &res), REPLY_WARNING);
    assert_true(by_command.model->k[0] == 5000.0);
    assert_int_equal(by_command.said, SAID_WARNING);
    assert_true(command_done(res.reply));
    assert_int_equal(command_do(&by_command, "set spring 10", &res), REPLY_OK);
    assert_true(by_command.model->k[0] == 10.0);
    assert_int_equal(by_command.said, SAID_NOTE);
    /* One spring alone, by another route: the same warning. */
    assert_int_equal(command_do(&by_command, "element k 1 1e6", &res), REPLY_WARNING);
    assert_true(by_command.model->k[1] == 1e6);
}

/* A refusal: an error, nothing changed, and the app's message (where it made one) an
 * error too. */
static void a_refusal_is_an_error(void **state)
{
    (void)state;
    double dt = by_command.cfg.dt;
    assert_int_equal(command_do(&by_command, "set dt -1", &res), REPLY_ERROR);
    assert_int_equal(by_command.said, SAID_ERROR);
    assert_true(by_command.cfg.dt == dt);
    assert_false(command_done(res.reply));
    assert_int_equal(command_do(&by_command, "back", &res), REPLY_ERROR);
    assert_int_equal(command_do(&by_command, "nosuch", &res), REPLY_ERROR);
}

/* start, pause, step, run and mode K say in their answer whether the chain runs; a
 * sweep starts it without saying so (the plain mode tells an event then). */
static void play_is_said_by_the_commands_that_play(void **state)
{
    (void)state;
    static const char *const says[] = {"start", "pause", "step", "run 0.1", "mode 1"};
    for (size_t i = 0; i < sizeof says / sizeof *says; i++) {
        command_do(&by_command, says[i], &res);
        assert_true(res.says_play);
    }
    command_do(&by_command, "pause", &res);
    assert_int_equal(command_do(&by_command, "sweep", &res), REPLY_OK);
    assert_true(by_command.running);
    assert_false(res.says_play);
    assert_int_equal(command_do(&by_command, "run 0.5", &res), REPLY_RUN);
    assert_true(res.seconds == 0.5);
    assert_int_equal(command_do(&by_command, "view modes", &res), REPLY_VIEW);
    assert_int_equal(res.view, CV_MODES);
    assert_true(command_done(res.reply));
}

/* The velocity cap's count is a kind of its own, said anew at every step it acts. */
static void the_cap_is_its_own_kind(void **state)
{
    (void)state;
    assert_int_equal(command_do(&by_command, "set dt 0.001", &res), REPLY_OK);
    assert_int_equal(command_do(&by_command, "place 1 2", &res), REPLY_OK);
    assert_int_equal(command_do(&by_command, "set spring 2000", &res), REPLY_OK);
    unsigned says = by_command.says;
    int steps = 0;
    while (by_command.said != SAID_CAP && steps++ < 2000)
        app_step(&by_command);
    assert_int_equal(by_command.said, SAID_CAP);
    assert_true(by_command.says > says);
    says = by_command.says;
    app_say(&by_command, SAID_NOTE, "%s", by_command.message); /* the same words, said again */
    assert_int_equal(by_command.said, SAID_NOTE);
    assert_int_equal(by_command.says, says + 1);
    app_quiet(&by_command);
    assert_string_equal(by_command.message, "");
    assert_int_equal(by_command.said, SAID_NOTE);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup_teardown(keys_and_commands_do_the_same, setup, teardown),
        cmocka_unit_test_setup_teardown(typed_values_do_the_same, setup, teardown),
        cmocka_unit_test_setup_teardown(exports_do_the_same, setup, teardown),
        cmocka_unit_test_setup_teardown(recorded_verbs_replay, setup, teardown),
        cmocka_unit_test_setup_teardown(every_command_row_is_whole, setup, teardown),
        cmocka_unit_test_setup_teardown(what_is_drawn_is_in_the_mask, setup, teardown),
        cmocka_unit_test_setup_teardown(a_change_past_a_limit_is_a_warning, setup, teardown),
        cmocka_unit_test_setup_teardown(a_refusal_is_an_error, setup, teardown),
        cmocka_unit_test_setup_teardown(play_is_said_by_the_commands_that_play, setup, teardown),
        cmocka_unit_test_setup_teardown(the_cap_is_its_own_kind, setup, teardown),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
