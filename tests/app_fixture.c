/* app_fixture.c: the app under test for test_app.c and test_app_rules.c, and the
 * wrappers (linked in by --wrap) that make the chain's allocations fail on demand and
 * count the modes' computations. */
#include "app_fixture.h"

#include <stdlib.h>
#include <unistd.h>

struct app app;
struct config cfg;
int modes_calls;
int limit_calls;

static int alloc_calls; /* wrapped allocations since fail_at was set */
static int fail_at;     /* the one of them that fails (1 = the next), 0 for none */

static bool fail_now(void)
{
    return fail_at > 0 && ++alloc_calls == fail_at;
}

void fail_allocation(int k)
{
    fail_at = k;
    alloc_calls = 0;
}

struct model *__real_config_model(const struct config *c, int *bad_key, char *err, size_t len);
struct model *__wrap_config_model(const struct config *c, int *bad_key, char *err, size_t len);
struct sim *__real_sim_new(const struct model *model, double dt);
struct sim *__wrap_sim_new(const struct model *model, double dt);
struct history *__real_history_new(const struct sim *s, int capacity);
struct history *__wrap_history_new(const struct sim *s, int capacity);
struct trail *__real_trail_new(int n, int capacity);
struct trail *__wrap_trail_new(int n, int capacity);
struct trail *__real_trail_new_motion(int n, int capacity);
struct trail *__wrap_trail_new_motion(int n, int capacity);
struct sweep *__real_sweep_new(int n, int points);
struct sweep *__wrap_sweep_new(int n, int points);
int __real_modes_compute(const struct model *m, double *freq, double *shapes);
int __wrap_modes_compute(const struct model *m, double *freq, double *shapes);
int __real_limits_modes(const struct model *m, struct limits_mode *mode);
int __wrap_limits_modes(const struct model *m, struct limits_mode *mode);

struct model *__wrap_config_model(const struct config *c, int *bad_key, char *err, size_t len)
{
    if (fail_now()) {
        *bad_key = -1;
        snprintf(err, len, "out of memory");
        return NULL;
    }
    return __real_config_model(c, bad_key, err, len);
}

struct sim *__wrap_sim_new(const struct model *model, double dt)
{
    return fail_now() ? NULL : __real_sim_new(model, dt);
}

struct history *__wrap_history_new(const struct sim *s, int capacity)
{
    return fail_now() ? NULL : __real_history_new(s, capacity);
}

struct trail *__wrap_trail_new(int n, int capacity)
{
    return fail_now() ? NULL : __real_trail_new(n, capacity);
}

struct trail *__wrap_trail_new_motion(int n, int capacity)
{
    return fail_now() ? NULL : __real_trail_new_motion(n, capacity);
}

struct sweep *__wrap_sweep_new(int n, int points)
{
    return fail_now() ? NULL : __real_sweep_new(n, points);
}

int __wrap_modes_compute(const struct model *m, double *freq, double *shapes)
{
    modes_calls++;
    return __real_modes_compute(m, freq, shapes);
}

int __wrap_limits_modes(const struct model *m, struct limits_mode *mode)
{
    limit_calls++;
    return __real_limits_modes(m, mode);
}

int setup(void **state)
{
    (void)state;
    fail_allocation(0);
    config_init(&cfg);
    cfg.masses = 3;
    cfg.frequency = 0.9;
    int e = app_init(&app, &cfg, SRCDIR);
    modes_calls = limit_calls = 0;
    return e;
}

int teardown(void **state)
{
    (void)state;
    fail_allocation(0);
    app_free(&app);
    return 0;
}

void run(int n)
{
    for (int i = 0; i < n; i++)
        assert_true(app_step(&app));
}

void start_sweep(void)
{
    double user = app.model->motor.frequency;
    app_toggle_sweep(&app);
    app.running = false;
    assert_true(app.sweep->active);
    assert_true(app.model->motor.frequency != user);
    assert_close(app.sweep_from, user, 0.0);
}

double drive_frequency(void)
{
    assert_close(app.cfg.frequency, app.model->motor.frequency, 0.0);
    assert_close(sim_model(app.sim)->motor.frequency, app.model->motor.frequency, 0.0);
    return app.model->motor.frequency;
}

unsigned new_n(void)
{
    app_adjust(&app, CTL_MASSES, 5 - app.masses_pending, false); /* 5 masses, pending */
    return app_apply_masses(&app);
}

unsigned preset(void)
{
    return app_load_preset(&app, SRCDIR "/presets/3-mass-chain.ini", "3-mass-chain");
}

unsigned preset_text(const char *name, const char *text)
{
    char dir[] = "/tmp/springsim-fix-XXXXXX", path[512];
    assert_non_null(mkdtemp(dir));
    snprintf(path, sizeof path, "%s/%s.ini", dir, name);
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    fputs(text, f);
    fclose(f);
    unsigned what = app_load_preset(&app, path, name);
    unlink(path);
    rmdir(dir);
    return what;
}
