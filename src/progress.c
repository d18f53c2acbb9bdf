/* progress.c: the headless run's progress line (progress.h). */
#include "progress.h"

#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

static double wall(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

void progress_start(struct progress *p, double end)
{
    const char *force = getenv("SPRINGSIM_PROGRESS");
    memset(p, 0, sizeof *p);
    p->out = isatty(STDERR_FILENO) || (force && strcmp(force, "1") == 0) ? stderr : NULL;
    p->start = wall();
    p->end = end;
}

void progress_tick(struct progress *p, double t)
{
    if (!p->out)
        return;
    double now = wall();
    if (now - p->start < PROGRESS_AFTER || now - p->last < PROGRESS_EVERY)
        return;
    p->last = now;
    double share = p->end > 0.0 ? 100.0 * t / p->end : 100.0;
    int w = fprintf(p->out, "\rspringsim: t = %.1f of %.6g s (%.0f %%)", t, p->end,
                    share > 100.0 ? 100.0 : share);
    if (w > 0 && w - 1 < p->width) /* a shorter line: blank what the last one left */
        fprintf(p->out, "%*s", p->width - (w - 1), "");
    if (w > 0 && w - 1 > p->width)
        p->width = w - 1;
    fflush(p->out);
}

void progress_end(struct progress *p)
{
    if (!p->out || p->width == 0)
        return;
    fprintf(p->out, "\r%*s\r", p->width, "");
    fflush(p->out);
    p->width = 0;
}
