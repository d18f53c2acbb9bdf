/* config_args.c: a configuration written back as the command line that makes it again:
 * every setting of the table (the rows with a preset section) in the table's order, each
 * value read through config_get, numbers with the digits that read back exactly. For
 * --meta's comment line, which says how a CSV was made; the preset and output options are
 * not settings of the run. */
#include "config.h"

#include <stdio.h>
#include <string.h>

/* A text value as a shell reads it back: bare when it is made of safe characters,
 * otherwise in single quotes (control bytes escaped, so the line stays one line). */
static void write_text(FILE *out, const char *s)
{
    if (*s && strspn(s, "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789"
                        "+-_.,:/=@%") == strlen(s)) {
        fputs(s, out);
        return;
    }
    char safe[4 * 1024 + 8];
    config_escape(s, strlen(s), 1024, safe, sizeof safe);
    fputc('\'', out);
    for (const char *p = safe; *p; p++)
        fputs(*p == '\'' ? "'\\''" : (char[]){*p, '\0'}, out);
    fputc('\'', out);
}

static void write_number(FILE *out, double v)
{
    char num[32];
    config_format_exact(v, num, sizeof num);
    fputs(num, out);
}

/* Whether the command line says key of c: a flag when on, the seed when positions are
 * random or it was given, a number whose default is words ("every step") when it is not
 * that default, x0 unless random positions stand for it, start-mode when c starts along a
 * mode (written after x0 and v0, so it wins over them as it did), spring-cubic when some k3
 * is not 0, every other key always. */
static bool said(int key, const struct config *c)
{
    const struct config_option *o = &config_options[key];
    const char *at = (const char *)c + o->offset;
    switch (key) {
    case CFG_SEED:
        return c->random || c->seed_set;
    case CFG_X0:
        return c->x0.count > 0 || !c->random;
    case CFG_START_MODE:
        return c->start_mode > 0;
    case CFG_SPRING_CUBIC:
        return config_in_force(key, c);
    default:
        break;
    }
    if (o->kind == CONFIG_FLAG)
        return *(const bool *)(const void *)at;
    if (o->kind == CONFIG_NUMBER && o->def_text)
        return *(const double *)(const void *)at != o->def;
    return o->kind != CONFIG_MODE;
}

int config_write_args(FILE *out, const struct config *c)
{
    for (int k = 0; k < CFG_KEY_COUNT; k++) {
        const struct config_option *o = &config_options[k];
        if (!o->section || !said(k, c))
            continue;
        fprintf(out, " --%s", o->name);
        if (o->kind == CONFIG_FLAG)
            continue;
        struct config_value v;
        config_get(k, c, NULL, &v);
        fputc(' ', out);
        if (v.count == 0)
            write_text(out, v.str);
        for (int i = 0; i < v.count; i++) {
            if (i)
                fputc(',', out);
            write_number(out, v.v[i]);
        }
    }
    return ferror(out) ? -1 : 0;
}
