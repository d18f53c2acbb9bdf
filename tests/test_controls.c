/* test_controls.c: the Graphics control (issue 18): the arrows go round auto, sixel,
 * kitty, braille; a typed value is checked as --graphics checks it; the chain is never
 * touched; its value says what the front end draws with where that is not what it asks
 * ("auto (sixel)", "sixel: braille"); the plain mode's `set graphics` and `controls`
 * name it as the panel does. The force input's two controls (its amplitude, its mass:
 * the arrows stop at the chain's ends, a mass past N refused) and the dampers beside the
 * springs, one spring's or all, typed in the program or in the plain mode. The app under
 * test comes from tests/app_fixture.c. */
#include "app_fixture.h"

#include <math.h>
#include <string.h>

#include "app/command.h"

static const char *value(void)
{
    static char buf[96];
    app_control_value(&app, CTL_GRAPHICS, buf, sizeof buf);
    return buf;
}

static void arrows_go_round(void **state)
{
    (void)state;
    unsigned version = app.version;
    double t = sim_time(app.sim);
    assert_int_equal(app.cfg.graphics, CONFIG_GRAPHICS_AUTO);
    assert_string_equal(app_control_label(CTL_GRAPHICS), "Graphics");
    const enum config_graphics order[] = {CONFIG_GRAPHICS_SIXEL, CONFIG_GRAPHICS_KITTY,
                                          CONFIG_GRAPHICS_BRAILLE, CONFIG_GRAPHICS_AUTO};
    for (int i = 0; i < 4; i++) {
        assert_int_equal(app_adjust(&app, CTL_GRAPHICS, 1, false), APP_CHANGED_PLAYBACK);
        assert_int_equal(app.cfg.graphics, order[i]);
    }
    assert_int_equal(app_adjust(&app, CTL_GRAPHICS, -1, true), APP_CHANGED_PLAYBACK);
    assert_int_equal(app.cfg.graphics, CONFIG_GRAPHICS_BRAILLE);
    assert_int_equal(app_adjust(&app, CTL_GRAPHICS, 0, false), 0);
    assert_int_equal(app.version, version); /* the chain is as it was */
    assert_true(sim_time(app.sim) == t);
}

static void typed_values(void **state)
{
    (void)state;
    assert_int_equal(app_set_text(&app, CTL_GRAPHICS, "kitty"),
                     APP_CHANGED_PLAYBACK | APP_CHANGED_MESSAGE);
    assert_int_equal(app.cfg.graphics, CONFIG_GRAPHICS_KITTY);
    assert_string_equal(app.message, "Graphics kitty");
    assert_int_equal(app_set_text(&app, CTL_GRAPHICS, "kitty"), APP_CHANGED_MESSAGE);
    /* A bad value: refused with what is allowed, nothing changed. */
    assert_int_equal(app_set_text(&app, CTL_GRAPHICS, "png"), 0);
    assert_int_equal(app.cfg.graphics, CONFIG_GRAPHICS_KITTY);
    assert_int_equal(app.said, SAID_ERROR);
    assert_non_null(strstr(app.message, "graphics"));
    assert_non_null(strstr(app.message, "png"));
    assert_non_null(strstr(app.message, "braille"));
}

/* What the value says, for what is asked and what the front end draws with. */
static void value_says_what_is_drawn(void **state)
{
    (void)state;
    /* The line mode draws no charts (graphics_now AUTO): what is asked alone. */
    assert_int_equal(app.graphics_now, CONFIG_GRAPHICS_AUTO);
    assert_string_equal(value(), "auto");
    app.graphics_now = CONFIG_GRAPHICS_SIXEL;
    assert_string_equal(value(), "auto (sixel)");
    app.graphics_now = CONFIG_GRAPHICS_BRAILLE;
    assert_string_equal(value(), "auto (braille)");
    app.cfg.graphics = CONFIG_GRAPHICS_SIXEL;
    assert_string_equal(value(), "sixel: braille");
    app.graphics_now = CONFIG_GRAPHICS_SIXEL;
    assert_string_equal(value(), "sixel");
    app.cfg.graphics = CONFIG_GRAPHICS_BRAILLE;
    app.graphics_now = CONFIG_GRAPHICS_BRAILLE;
    assert_string_equal(value(), "braille");
}

static void plain_mode_names_it(void **state)
{
    (void)state;
    static struct command_result res;
    const char *answer = res.answer;
    assert_int_equal(command_do(&app, "set graphics braille", &res),
                     REPLY_OK);
    assert_int_equal(app.cfg.graphics, CONFIG_GRAPHICS_BRAILLE);
    assert_int_equal(command_do(&app, "controls", &res), REPLY_OK);
    assert_non_null(strstr(answer, "; graphics braille"));
    assert_int_equal(command_do(&app, "set graphics sepia", &res),
                     REPLY_ERROR);
    assert_int_equal(app.cfg.graphics, CONFIG_GRAPHICS_BRAILLE);
    assert_int_equal(command_do(&app, "set nosuch 1", &res),
                     REPLY_ERROR);
    assert_non_null(strstr(answer, "bandwidth, graphics"));
}

/* Every control is one row of controls.c's table over a setting of config.c's: its name
 * for set is unique and, where it has a setting, the setting's; a choice typed shows as
 * its name; a number typed shows with the setting's decimals and unit. */
static void every_control_from_its_setting(void **state)
{
    (void)state;
    char buf[96], text[64], want[64];
    int settings = 0;
    for (int c = 0; c < CTL_COUNT; c++) {
        const char *name = app_control_name((enum control)c);
        assert_true(name[0] && app_control_label((enum control)c)[0]);
        for (int d = 0; d < c; d++)
            assert_string_not_equal(name, app_control_name((enum control)d));
        int key = config_find(name);
        if (key < 0)
            continue; /* the speed and the refresh: the app's own words */
        settings++;
        const struct config_option *o = &config_options[key];
        if (o->kind == CONFIG_CHOICE && c != CTL_GRAPHICS) {
            for (int i = o->choices - 1; i >= 0; i--) {
                assert_true(app_set_text(&app, (enum control)c, o->choice_name(i)));
                app_control_value(&app, (enum control)c, buf, sizeof buf);
                assert_string_equal(buf, o->choice_name(i));
            }
        } else if (o->kind == CONFIG_NUMBER || o->kind == CONFIG_LIST) {
            struct config_value now;
            config_get(key, &app.cfg, app.model, &now);
            double unit = pow(10.0, -o->digits);
            double v = round((now.v[0] != 0.0 ? 1.25 * now.v[0] : 1.0) / unit) * unit;
            assert_true(v != now.v[0]);
            snprintf(text, sizeof text, "%g", v);
            assert_true(app_set_text(&app, (enum control)c, text));
            app_control_value(&app, (enum control)c, buf, sizeof buf);
            snprintf(want, sizeof want, "%.*f %s", o->digits, v, o->unit);
            if (strncmp(buf, want, strlen(want)) != 0)
                fail_msg("%s set to %s shows '%s', expected '%s'", name, text, buf, want);
        }
    }
    assert_int_equal(settings, CTL_COUNT - 2);
}

/* The Force and Force on controls set the model's force input, which moves the chain
 * alone when the motor stands still. */
static void force_controls(void **state)
{
    (void)state;
    static struct command_result res;
    char buf[96];
    assert_string_equal(app_control_name(CTL_FORCE), "force");
    assert_string_equal(app_control_name(CTL_FORCE_ON), "force-on");
    assert_true(app_set_text(&app, CTL_AMPLITUDE, "0"));
    assert_true(app_adjust(&app, CTL_FORCE, 1, false));
    assert_close(app.model->force, 0.1, 1e-12);
    assert_true(app_adjust(&app, CTL_FORCE, 1, true)); /* onto the coarse step's grid */
    assert_close(app.model->force, 1.0, 1e-12);
    assert_true(app_adjust(&app, CTL_FORCE_ON, 1, false));
    assert_int_equal(app.model->force_on, 1);
    app_control_value(&app, CTL_FORCE_ON, buf, sizeof buf);
    assert_string_equal(buf, "mass 2");
    assert_true(app_adjust(&app, CTL_FORCE_ON, 1, true)); /* stops at the last mass */
    assert_int_equal(app.model->force_on, 2);
    assert_int_equal(app_adjust(&app, CTL_FORCE_ON, 1, false), 0);
    assert_int_equal(app.model->force_on, 2);
    /* A mass past N: one line naming it and the range, nothing changed. */
    assert_int_equal(app_set_text(&app, CTL_FORCE_ON, "4"), 0);
    assert_int_equal(app.said, SAID_ERROR);
    assert_non_null(strstr(app.message, "'4'"));
    assert_non_null(strstr(app.message, "1 <= K <= 3"));
    assert_int_equal(app.model->force_on, 2);
    /* Alone it moves mass 3 first: after 0.3 s from rest it is ahead of mass 1. */
    run(30);
    const double *x = sim_x(app.sim);
    assert_true(fabs(x[2]) > 10.0 * fabs(x[0]) && fabs(x[2]) > 0.0);
    /* The plain mode's set takes both by their names. */
    assert_int_equal(command_do(&app, "set force 2.5", &res), REPLY_OK);
    assert_true(app.model->force == 2.5);
    assert_int_equal(command_do(&app, "set force-on 1", &res), REPLY_OK);
    assert_int_equal(app.model->force_on, 0);
    assert_int_equal(command_do(&app, "set force -1", &res), REPLY_ERROR);
    assert_true(app.model->force == 2.5);
    /* Fewer masses than the force's carry it down to the last mass, and say so; a force-on
     * past the masses is still refused. */
    assert_int_equal(command_do(&app, "set force-on 3", &res), REPLY_OK);
    assert_int_equal(command_do(&app, "set force 0", &res), REPLY_OK);
    assert_int_equal(command_do(&app, "set masses 2", &res), REPLY_OK);
    assert_int_equal(app.model->n, 2);
    assert_int_equal(app.model->force_on, 1);
    assert_int_equal(app.cfg.force_on, 2);
    assert_non_null(strstr(app.message, "force-on 2 now, the last mass"));
    assert_int_equal(command_do(&app, "set masses 3", &res), REPLY_OK);
    assert_null(strstr(app.message, "force-on"));
    assert_int_equal(app.model->force_on, 1);
    assert_int_equal(command_do(&app, "set force-on 4", &res), REPLY_ERROR);
}

/* A damper beside one spring (the c key on a selected spring, or element cs), or beside
 * every spring (set spring-damping): one spring's changes that spring's alone. */
static void spring_dampers(void **state)
{
    (void)state;
    static struct command_result res;
    assert_true(app_set_spring_damping(&app, 1, "0.3"));
    assert_string_equal(app.message, "spring 2 (1–2): c = 0.3 N·s/m");
    for (int j = 0; j <= 3; j++)
        assert_true(app.model->cs[j] == (j == 1 ? 0.3 : 0.0));
    assert_true(app.model->spring_damped);
    assert_int_equal(app_set_spring_damping(&app, 1, "0.1,0.2"), 0);
    assert_non_null(strstr(app.message, "more than one value"));
    assert_int_equal(app_set_spring_damping(&app, 2, "-1"), 0);
    assert_int_equal(app.said, SAID_ERROR);
    assert_true(app.model->cs[2] == 0.0);
    /* A refused value says why, as --spring-damping does, with every spring spelled out. */
    assert_string_equal(app.message, "spring 3 (2–3): '-1' is out of range (expected spring "
                                     "dampers >= 0 N·s/m: one value, or N+1)");
    assert_int_equal(app_set_spring_damping(&app, 2, "1e999"), 0);
    assert_non_null(strstr(app.message, "'1e999' is not a finite number (expected spring dampers"));
    assert_int_equal(app_set_spring_damping(&app, 2, "abc"), 0);
    assert_non_null(strstr(app.message, "'abc' is not a number (expected spring dampers"));
    assert_true(app_set_cubic(&app, 1, "2"));
    assert_int_equal(app_set_cubic(&app, 1, "abc"), 0);
    assert_non_null(strstr(app.message, "'abc' is not a number"));
    assert_true(app.model->k3[1] == 2.0);
    assert_true(app_set_cubic(&app, 1, "0"));
    assert_int_equal(command_do(&app, "element cs 0 0.4", &res), REPLY_OK);
    /* element numbers springs from 0, their labels from 1: the reply names both */
    assert_string_equal(res.answer, "element cs 0 is spring 1 (wall–1): c = 0.4 N·s/m");
    assert_int_equal(command_do(&app, "element k 3 12", &res), REPLY_OK);
    assert_string_equal(res.answer, "element k 3 is spring 4 (3–motor): k = 12 N/m");
    assert_true(app.model->cs[0] == 0.4 && app.model->cs[1] == 0.3);
    assert_int_equal(command_do(&app, "element cs 4 1", &res), REPLY_ERROR);
    assert_non_null(strstr(res.answer, "cs its damper"));
    assert_int_equal(command_do(&app, "set spring-damping 0.2", &res), REPLY_OK);
    for (int j = 0; j <= 3; j++)
        assert_true(app.model->cs[j] == 0.2);
    assert_int_equal(command_do(&app, "set spring-damping 0", &res), REPLY_OK);
    assert_false(app.model->spring_damped);
}

int main(void)
{
#define T(f) cmocka_unit_test_setup_teardown(f, setup, teardown)
    const struct CMUnitTest tests[] = {
        T(arrows_go_round), T(typed_values), T(value_says_what_is_drawn), T(plain_mode_names_it),
        T(every_control_from_its_setting), T(force_controls), T(spring_dampers),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
