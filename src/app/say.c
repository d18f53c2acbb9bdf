/* say.c: the status message, the one line every part of the app says what happened on,
 * the digits its times are given with, numbers kept to a width, a spring's name, and what
 * cubic springs add to a warning. */
#include "app.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

unsigned app_say(struct app *app, enum app_said said, const char *fmt, ...)
{
    char line[sizeof app->message];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(line, sizeof line, fmt, ap);
    va_end(ap);
    /* Whatever went into it, the status line gets no control byte. */
    config_escape(line, strlen(line), sizeof line, app->message, sizeof app->message);
    app->said = said;
    app->says++;
    return APP_CHANGED_MESSAGE;
}

/* The bytes of a path a message shows at most: the status line holds the reason too. */
#define PATH_SHOWN 80

/* n, moved back to the start of the UTF-8 character byte n is in. */
static size_t char_start(const char *s, size_t n)
{
    while (n > 0 && ((unsigned char)s[n] & 0xc0) == 0x80)
        n--;
    return n;
}

const char *app_path_shown(const char *path, char *buf, size_t len)
{
    size_t n = strlen(path);
    if (n <= PATH_SHOWN) {
        snprintf(buf, len, "%s", path);
        return buf;
    }
    size_t head = char_start(path, 30), tail = char_start(path, n - (PATH_SHOWN - 36));
    snprintf(buf, len, "%.*s...%s", (int)head, path, path + tail);
    return buf;
}

const char *app_key(const struct app *app, int a)
{
    const char *name = app->name_of ? app->name_of(a) : NULL;
    return name ? name : "";
}

const char *app_key_hint(const struct app *app, int a, const char *what, char *buf,
                         size_t len)
{
    const char *key = app_key(app, a);
    if (app->keys && *key)
        snprintf(buf, len, " (%s%s%s)", key, what ? " " : "", what ? what : "");
    else if (len)
        buf[0] = '\0';
    return buf;
}

void app_quiet(struct app *app)
{
    app->message[0] = '\0';
    app->said = SAID_NOTE;
}

int app_time_decimals(double dt)
{
    int d = 2;
    while (d < 6 && fabs(dt * pow(10.0, d) - round(dt * pow(10.0, d))) > 1e-6)
        d++;
    return d;
}

const char *app_fixed(double v, int decimals, char *buf, size_t len)
{
    if (!isfinite(v))
        snprintf(buf, len, "%s", isnan(v) ? "undefined" : v > 0 ? "overflow" : "-overflow");
    else if (fabs(v) < 1e6)
        snprintf(buf, len, "%.*f", decimals, v + 0.0);
    else
        snprintf(buf, len, "%.*e", decimals > 3 ? 3 : decimals, v);
    return buf;
}

void app_spring_name(const struct model *m, int j, char *buf, size_t len)
{
    /* Numbered from 1 as in the --spring list; what it joins says which one it is. */
    char left[16], right[16];
    if (j == 0)
        snprintf(left, sizeof left, "wall");
    else
        snprintf(left, sizeof left, "%d", j);
    if (j == m->n)
        snprintf(right, sizeof right, "%s", m->boundary == BOUNDARY_MOTOR ? "motor" : "wall");
    else
        snprintf(right, sizeof right, "%d", j + 1);
    snprintf(buf, len, "spring %d (%s–%s)", j + 1, left, right);
}

/* What a chain with cubic springs adds to the warning in line: a stability warning holds
 * for the chain linearised at rest, and swings stiffen hardening springs, lowering the
 * limit; a softening spring's force turns over past some stretch. */
void app_say_nonlinear(const struct model *m, char *line, size_t len)
{
    int j = 0;
    size_t used = strlen(line);
    double s = m->cubic ? model_turnover(m, &j) : INFINITY;
    if (used && limits_linearised_note(m)[0])
        snprintf(line + used, len - used, "%s", limits_linearised_note(m));
    else if (!used && isfinite(s)) {
        char name[48];
        app_spring_name(m, j, name, sizeof name);
        snprintf(line, len, "%s softens: its force turns over at a stretch of %.3g m, and "
                 "past it the chain runs away", name, s);
    }
}
