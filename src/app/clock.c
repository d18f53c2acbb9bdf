/* clock.c: the chain following the wall clock (clock.h). */
#include "clock.h"

#include <time.h>

#include "app.h"

double app_clock_pace(const struct app *app)
{
    return app->speed * (app->sweep && app->sweep->active ? APP_SWEEP_PACE : 1.0);
}

double app_clock_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

void app_clock_follow(struct app_clock *c, struct app *app, double elapsed, double budget,
                      bool (*step)(void *ctx), void *ctx)
{
    if (!app->running) {
        c->debt = 0.0;
        c->behind = false;
        return;
    }
    double pace = app_clock_pace(app);
    c->debt += elapsed * pace;
    double start = app_clock_now();
    while (c->debt >= app->cfg.dt && app->running) {
        if (!(step ? step(ctx) : app_step(app) != 0))
            break;
        c->debt -= app->cfg.dt;
        if (app_clock_now() - start > budget) {
            c->behind = c->debt > 2.0 * app->cfg.dt;
            if (c->debt > 0.25 * pace)
                c->debt = 0.0;
            return;
        }
    }
    c->behind = false;
}
