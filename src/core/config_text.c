/* config_text.c: the words made from a row of the settings table: what every error
 * says is expected ("0 < dt <= 0.05"), and --help's argument and line with the range and
 * default. */
#include "config.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

/* A bound as a range states it. */
static void bound_text(double v, char *buf, size_t len)
{
    snprintf(buf, len, v == 0x1p64 ? "2^64" : "%g", v);
    char *e = strstr(buf, "e+");
    if (e) /* 1e6, not 1e+06 */
        memmove(e + 1, e + 2 + (e[2] == '0'), strlen(e + 2 + (e[2] == '0')) + 1);
}

void config_expected(int key, char *buf, size_t len)
{
    const struct config_option *o = &config_options[key];
    char lo[32], hi[32];
    bound_text(o->lo, lo, sizeof lo);
    bound_text(o->hi, hi, sizeof hi);
    const char *gt = o->lo_open ? ">" : ">=", *lt = o->lo_open ? "<" : "<=";
    switch (o->kind) {
    case CONFIG_CHOICE: {
        size_t used = 0;
        buf[0] = '\0';
        for (int i = 0; i < o->choices && used < len; i++)
            used += (size_t)snprintf(buf + used, len - used, "%s%s",
                                     i == 0 ? "" : i == o->choices - 1 ? " or " : ", ",
                                     o->choice_name(i));
        return;
    }
    case CONFIG_WHOLE:
        snprintf(buf, len, "%s %s %s %s %s", lo, lt, o->symbol, o->hi_open ? "<" : "<=", hi);
        return;
    case CONFIG_NUMBER:
        if (isfinite(o->hi))
            snprintf(buf, len, "%s %s %s <= %s", lo, lt, o->symbol, hi);
        else
            snprintf(buf, len, "%s %s %s %s", o->symbol, gt, lo, o->unit);
        return;
    case CONFIG_LIST: {
        const char *each = o->per == CONFIG_PER_SPRING ? "N+1" : "one per mass";
        if (isfinite(o->lo) && isfinite(o->hi))
            snprintf(buf, len, "%s <= %s <= %s %s: one value, or %s", lo, o->symbol, hi,
                     o->unit, each);
        else if (isfinite(o->lo))
            snprintf(buf, len, "%s %s %s %s: one value, or %s", o->symbol, gt, lo, o->unit,
                     each);
        else
            snprintf(buf, len, "%s in %s: one value, or %s", o->symbol, o->unit, each);
        return;
    }
    case CONFIG_FLAG:
        snprintf(buf, len, "true or false");
        return;
    case CONFIG_TEXT:
    case CONFIG_MODE:
        snprintf(buf, len, "%s", o->expect ? o->expect : "nothing");
        return;
    }
}

void config_arg(int key, char *buf, size_t len)
{
    const struct config_option *o = &config_options[key];
    buf[0] = '\0';
    if (o->kind != CONFIG_CHOICE) {
        snprintf(buf, len, "%s", o->arg ? o->arg : "");
        return;
    }
    size_t used = 0;
    for (int i = 0; i < o->choices && used < len; i++)
        used += (size_t)snprintf(buf + used, len - used, "%s%s", i ? "|" : "", o->choice_name(i));
}

void config_help(int key, char *buf, size_t len)
{
    const struct config_option *o = &config_options[key];
    char range[160], def[64] = "";
    config_expected(key, range, sizeof range);
    if (o->def_text)
        snprintf(def, sizeof def, "default %s", o->def_text);
    else if (o->kind == CONFIG_CHOICE)
        snprintf(def, sizeof def, "default %s", o->choice_name((int)o->def));
    else if (o->kind == CONFIG_WHOLE || o->kind == CONFIG_NUMBER || o->kind == CONFIG_LIST)
        if (isfinite(o->def))
            snprintf(def, sizeof def, "default %g", o->def);
    switch (o->kind) {
    case CONFIG_WHOLE:
    case CONFIG_NUMBER:
        snprintf(buf, len, "%s (%s%s%s)", o->help, range, def[0] ? "; " : "", def);
        return;
    case CONFIG_LIST:
        if (isfinite(o->lo) && isfinite(o->hi)) {
            char lo[32], hi[32];
            bound_text(o->lo, lo, sizeof lo);
            bound_text(o->hi, hi, sizeof hi);
            snprintf(buf, len, "%s (%s to %s %s; one value or %s; %s)", o->help, lo, hi,
                     o->unit, o->per == CONFIG_PER_SPRING ? "N+1" : "N", def);
        } else
            snprintf(buf, len, "%s (%s; one value or %s; %s)", o->help, o->unit,
                     o->per == CONFIG_PER_SPRING ? "N+1" : "N", def);
        return;
    default:
        snprintf(buf, len, "%s%s%s%s", o->help, def[0] ? " (" : "", def, def[0] ? ")" : "");
        return;
    }
}
